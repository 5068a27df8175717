//! Benchmarks of the Kalker lookup and the slope conversion.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use traction_compliance::{
    Coefficient, Direction, DiscMaterial, convert_slope_same_contact, kalker_coefficient,
};

fn bench(c: &mut Criterion) {
    c.bench_function("kalker_c11_interpolated", |b| {
        b.iter(|| kalker_coefficient(Coefficient::C11, black_box(0.37), black_box(0.28)))
    });
    c.bench_function("kalker_c22_asymptotic", |b| {
        b.iter(|| kalker_coefficient(Coefficient::C22, black_box(23.0), black_box(0.3)))
    });
    c.bench_function("convert_slope_side_to_longitudinal", |b| {
        b.iter(|| {
            convert_slope_same_contact(
                black_box(52.4),
                black_box(5.0),
                black_box(1.22e9),
                Direction::Side,
                Direction::Longitudinal,
                DiscMaterial::REPORT_STEEL,
            )
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
