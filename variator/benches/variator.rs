//! Benchmarks of one variator evaluation (roller torque balance + both
//! contacts), warm: the contacts for the tilt are built and, with the map,
//! its cells filled before timing.
//!
//! The case: the half-toroidal cavity of the tests (r0 = 40 mm, k0 = 0.625,
//! θ0 = 62.5°, r22 = 28 mm, two rollers), m = 40, μ = 0.08, end load 20 kN,
//! ω_in = 300 rad/s, 1 % creep, tilt 0.3 rad (both contacts spin).
#![allow(missing_docs)]

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use traction_contact::{DiscMaterial, Fluid, Options};
use traction_variator::{Cavity, OperatingPoint, ToroidalVariator};

fn variator(options: Options) -> ToroidalVariator {
    let cavity =
        Cavity::half_toroidal(40e-3, 65e-3, 62.5_f64.to_radians(), 28e-3, 2).expect("cavity");
    let steel = DiscMaterial::REPORT_STEEL;
    ToroidalVariator::new(
        cavity,
        steel,
        steel,
        Fluid::constant(40.0, 0.08).expect("fluid"),
        options,
    )
    .expect("variator")
}

fn bench(c: &mut Criterion) {
    let tilt = 0.3;
    for (name, options) in [
        ("variator_evaluate_direct", Options::default()),
        (
            "variator_evaluate_map",
            Options {
                map: true,
                ..Options::default()
            },
        ),
    ] {
        let v = variator(options);
        let ratio = v.speed_ratio(tilt).expect("ratio");
        let p = OperatingPoint::new(300.0, 0.99 * 300.0 * ratio, tilt, 20e3, 70.0).expect("point");
        let r = v.evaluate(&p).expect("warm-up");
        eprintln!("{name}: {} torque evaluations per call", r.iterations);
        c.bench_function(name, |b| b.iter(|| v.evaluate(black_box(&p))));
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
