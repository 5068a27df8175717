//! One Hertz solve: geometry (root solve for k, elliptic integrals, A, B, C)
//! plus the loaded contact, exact and Hamrock–Brewe.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use traction_hertz::{Body, Geometry, Method};

fn bench(c: &mut Criterion) {
    // Low-speed machine, k = 5 discs (Table 2-1), test 791103-11 load.
    let upper = Body::steel(25e-3, 150.4e-3);
    let lower = Body::steel(25e-3, f64::INFINITY);
    c.bench_function("hertz exact solve (LS k=5, 1400 N)", |b| {
        b.iter(|| {
            Geometry::new(black_box(&upper), black_box(&lower))
                .and_then(|g| g.at_load(black_box(1400.0)))
        })
    });
    c.bench_function("hertz Hamrock-Brewe solve (LS k=5, 1400 N)", |b| {
        b.iter(|| {
            Geometry::with_method(black_box(&upper), black_box(&lower), Method::HamrockBrewe)
                .and_then(|g| g.at_load(black_box(1400.0)))
        })
    });
    c.bench_function("carlson R_D(0, k², 1), one evaluation", |b| {
        b.iter(|| traction_hertz::elliptic::rd(0.0, black_box(25.5), 1.0))
    });
    let g = Geometry::new(&upper, &lower);
    c.bench_function("hertz at_p0 on a cached geometry", |b| {
        b.iter(|| g.as_ref().map(|g| g.at_p0(black_box(1.45e9))))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
