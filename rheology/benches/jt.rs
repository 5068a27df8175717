//! Criterion benches of the J+T model: closed forms, elastic/plastic at
//! several accuracies (cost vs accuracy), rigid/plastic.
#![allow(missing_docs, clippy::unwrap_used)]

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use traction_rheology::{Accuracy, Inputs, Model, closed, evaluate};

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
    let mut g = c.benchmark_group("elastic_plastic");
    g.sample_size(10);
    for (name, inp) in &cases {
        for tol in [1e-2, 1e-3, 1e-4, 1e-5] {
            let a = Accuracy::new(tol).unwrap();
            g.bench_function(format!("{name} tol={tol:.0e}"), |b| {
                b.iter(|| evaluate(black_box(inp), Model::ElasticPlastic, a).unwrap())
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
}

criterion_group!(jt, benches);
criterion_main!(jt);
