//! Benchmarks of the general contact kinematics and the variator.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use traction_kinematics::{
    BodyMotion, HalfToroidalVariator, Vector3, contact_kinematics, tilted_disc_spin_per_speed,
};

fn bench(c: &mut Criterion) {
    c.bench_function("tilted_disc_eq6", |b| {
        b.iter(|| tilted_disc_spin_per_speed(black_box(0.1), black_box(0.0125), black_box(0.0125)))
    });
    let b1 = BodyMotion::rotating(
        Vector3::new(0.0, -400.0, 20.0),
        Vector3::new(0.0, 0.0, 0.025),
    );
    let b2 = BodyMotion::rotating(Vector3::new(0.0, 196.0, 0.0), Vector3::new(0.0, 0.0, -0.05));
    c.bench_function("contact_kinematics_3d", |b| {
        b.iter(|| {
            contact_kinematics(
                black_box(&b1),
                black_box(&b2),
                Vector3::zeros(),
                Vector3::z(),
                Vector3::x(),
            )
        })
    });
    let v = HalfToroidalVariator::new(40e-3, 65e-3, 62.5_f64.to_radians()).expect("valid geometry");
    c.bench_function("half_toroidal_state", |b| {
        b.iter(|| v.state(black_box(0.2), black_box(420.0)))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
