//! Fit time of the 193 × 32 problem (App. III-E) and the 73 × 16 problem
//! (III-A), evaluation time of one correlation.
// Benchmark harness, not a user-reachable path: a failure here is a defect to see.
#![allow(clippy::unwrap_used)]
use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use traction_fluids::{Fluid, FluidName, Quantity, data_set};
use traction_regression::{Model, fit};

fn benches(c: &mut Criterion) {
    let (x, y) = data_set(FluidName::Santotrac50, Quantity::SpinMu).unwrap();
    c.bench_function("fit III-E 193x32 (QR + SVD condition number)", |b| {
        b.iter(|| fit(Model::EQ15, black_box(&x), black_box(&y), None).unwrap())
    });
    let (xa, ya) = data_set(FluidName::Santotrac50, Quantity::Slope).unwrap();
    c.bench_function("fit III-A 73x16", |b| {
        b.iter(|| fit(Model::EQ14, black_box(&xa), black_box(&ya), None).unwrap())
    });
    let f = Fluid::santotrac_50().unwrap();
    c.bench_function("evaluate mu (16 terms, checks + envelope)", |b| {
        b.iter(|| {
            f.mu(
                black_box(1.45e9),
                black_box(20.0),
                black_box(70.0),
                black_box(1.0),
            )
            .unwrap()
        })
    });
    c.bench_function("evaluate spin mu (32 terms, checks + envelope)", |b| {
        b.iter(|| {
            f.spin_peak_mu(
                black_box(1.45e9),
                black_box(20.0),
                black_box(70.0),
                black_box(1.0),
                black_box(0.001),
            )
            .unwrap()
        })
    });
}

criterion_group!(g, benches);
criterion_main!(g);
