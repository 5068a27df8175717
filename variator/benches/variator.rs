//! Benchmarks of one variator evaluation (roller torque balance + both
//! contacts), warm: the contacts for the tilt are built and, with the map,
//! its cells filled before timing.
//!
//! The case: the half-toroidal cavity of the tests (r0 = 40 mm, k0 = 0.625,
//! θ0 = 62.5°, r22 = 28 mm, two rollers), m = 40, μ = 0.08, end load 20 kN,
//! ω_in = 300 rad/s, 0.3–1.5 % creep changing at every call, tilt 0.3 rad
//! (both contacts spin).
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
        // The output speed changes at every call (0.3–1.5 % creep), as in a
        // co-simulation: each call solves the balance from the previous root.
        let points: Vec<OperatingPoint> = (0..64)
            .map(|i| {
                let creep = 0.015 - 0.0002 * f64::from(i);
                OperatingPoint::new(300.0, (1.0 - creep) * 300.0 * ratio, tilt, 20e3, 70.0)
                    .expect("point")
            })
            .collect();
        let mut evaluations = 0;
        for p in points
            .iter()
            .cycle()
            .take(if name.ends_with("map") { 2560 } else { 64 })
        {
            evaluations += v.evaluate(p).expect("warm-up").iterations;
        }
        eprintln!(
            "{name}: {} torque evaluations per call (warm-up mean)",
            f64::from(evaluations) / if name.ends_with("map") { 2560.0 } else { 64.0 }
        );
        // Evaluations the maps answered directly (their cells not built
        // yet: they build them within a budget, docs/decisions/0078).
        let direct = |v: &ToroidalVariator| -> u64 {
            v.map_stats()
                .iter()
                .flatten()
                .map(|s| s.direct + s.rigid_direct)
                .sum()
        };
        let before = direct(&v);
        let mut k = 0;
        c.bench_function(name, |b| {
            b.iter(|| {
                k = (k + 1) % points.len();
                v.evaluate(black_box(&points[k]))
            })
        });
        if name.ends_with("map") {
            eprintln!(
                "{name}: {} rheology evaluations answered directly by the maps during the bench",
                direct(&v) - before
            );
        }
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
