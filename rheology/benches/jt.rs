//! Criterion benches of the J+T model: closed forms, elastic/plastic at
//! several accuracies (cost vs accuracy), rigid/plastic, viscoelastic.
#![allow(missing_docs, clippy::unwrap_used)]

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use traction_rheology::{
    Accuracy, Inputs, Model, Resolution, closed, evaluate, map::Map, reference,
};
use traction_testkit::bench_cases::{ELASTIC_PLASTIC, VISCOELASTIC};

fn benches(c: &mut Criterion) {
    c.bench_function("closed/slip_traction eq22", |b| {
        b.iter(|| closed::slip_traction(black_box(1.0), black_box(1.5)))
    });
    c.bench_function("closed/combined_slip eq23", |b| {
        b.iter(|| closed::combined_slip_traction(black_box(0.5), black_box(1.32), black_box(1.516)))
    });
    let cases = [
        (
            "moderate k=1 J=(1.5,0.3,2)",
            Inputs::new(1.0, 1.5, 0.3, 2.0).unwrap(),
        ),
        (
            "high-spin k=5 J=(0,3.37,25.8)",
            Inputs::new(5.0, 0.0, 3.368, 25.816).unwrap(),
        ),
    ];
    // The bench set of the direct solver (the same cases as `cargo xtask
    // prof CASE`, which counts instructions).
    let mut g = c.benchmark_group("elastic_plastic");
    g.sample_size(10);
    for case in &ELASTIC_PLASTIC {
        let [j1, j2, j3] = case.j;
        let inp = Inputs::new(case.k, j1, j2, j3).unwrap();
        let name = case.label;
        let tols: &[f64] = if matches!(case.letter, "m" | "h") {
            &[1e-2, 1e-3, 1e-4, 1e-5]
        } else {
            &[1e-3, 1e-4]
        };
        for &tol in tols {
            let a = Accuracy::new(tol).unwrap();
            g.bench_function(format!("{name} tol={tol:.0e}"), |b| {
                b.iter(|| evaluate(black_box(&inp), Model::ElasticPlastic, a).unwrap())
            });
        }
    }
    g.finish();
    let mut g = c.benchmark_group("rigid_plastic");
    g.sample_size(10);
    let a = Accuracy::new(1e-3).unwrap();
    g.bench_function("k=1 J=(1.5,0.3,2) tol=1e-3", |b| {
        b.iter(|| evaluate(black_box(&cases[0].1), Model::RigidPlastic, a).unwrap())
    });
    g.finish();

    // The viscoelastic model: the same cases as `cargo xtask prof-visco CASE`,
    // and the former fixed-grid scheme at its former resolution for tol = 1e-3
    // (4 panels × 8 points, 633 steps).
    let mut g = c.benchmark_group("viscoelastic");
    g.sample_size(10);
    for case in &VISCOELASTIC {
        let [j1, j2, j3] = case.j;
        let (name, deborah, z0) = (case.label, case.deborah, case.z0);
        let inp = Inputs::new(case.k, j1, j2, j3)
            .unwrap()
            .with_stiffness_ratio(case.gy)
            .unwrap();
        let model = Model::Viscoelastic { deborah, z0 };
        for tol in [1e-3, 1e-4] {
            let a = Accuracy::new(tol).unwrap();
            g.bench_function(format!("{name} tol={tol:.0e}"), |b| {
                b.iter(|| evaluate(black_box(&inp), model, a).unwrap())
            });
        }
        if matches!(case.letter, "m" | "h") {
            let res = Resolution {
                y_panels: 4,
                y_points: 8,
                s_step: 0.1,
            };
            g.bench_function(format!("former {name} tol=1e-3"), |b| {
                b.iter(|| reference::viscoelastic(black_box(&inp), deborah, z0, &res, 633).unwrap())
            });
        }
    }
    g.finish();

    // The interpolation map: warm (cells built; 64 points within ±2 % of the
    // case, cycled) and a cold traction curve (fresh map, 100 slip values at
    // fixed side slip and spin) against the same curve evaluated directly.
    let mut g = c.benchmark_group("map");
    g.sample_size(10);
    for (name, inp) in &cases {
        for tol in [1e-3, 1e-4] {
            let a = Accuracy::new(tol).unwrap();
            let mut map = Map::new(inp.k, 0.0, 1.0, a).unwrap();
            let pts: Vec<Inputs> = (0..64)
                .map(|i| {
                    let f = 1.0 + 0.02 * ((i as f64 * 0.37).sin());
                    let g = 1.0 + 0.02 * ((i as f64 * 0.73).cos());
                    Inputs::new(inp.k, inp.j1 * f + 0.01 * g, inp.j2 * g, inp.j3 * f).unwrap()
                })
                .collect();
            for p in &pts {
                map.evaluate(p).unwrap();
            }
            let s0 = map.stats();
            let mut n = 0usize;
            g.bench_function(format!("warm {name} tol={tol:.0e}"), |b| {
                b.iter(|| {
                    n = (n + 1) & 63;
                    map.evaluate(black_box(&pts[n])).unwrap()
                })
            });
            let s1 = map.stats();
            eprintln!(
                "map warm {name} tol={tol:.0e}: interpolated {} direct {} after warm-up",
                s1.interpolated - s0.interpolated,
                s1.direct - s0.direct
            );
        }
    }
    let a = Accuracy::new(1e-3).unwrap();
    let curve: Vec<Inputs> = (0..100)
        .map(|i| Inputs::new(5.0, 0.08 * i as f64, 0.3, 4.0).unwrap())
        .collect();
    g.bench_function("cold curve k=5 100 points tol=1e-3", |b| {
        b.iter(|| {
            let mut map = Map::new(5.0, 0.0, 1.0, a).unwrap();
            for p in &curve {
                black_box(map.evaluate(p).unwrap());
            }
        })
    });
    g.bench_function("direct curve k=5 100 points tol=1e-3", |b| {
        b.iter(|| {
            for p in &curve {
                black_box(evaluate(p, Model::ElasticPlastic, a).unwrap());
            }
        })
    });
    g.finish();
}

criterion_group!(jt, benches);
criterion_main!(jt);
