//! Support shared by the rheology crate's integration tests.
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

use traction_rheology::{Accuracy, Inputs, Model, evaluate};

/// Largest |second difference| of J4, J5, J6 along `n` points from `p` in
/// steps `h·d`.
pub fn max_second_difference(k: f64, p: [f64; 3], d: [f64; 3], h: f64, n: usize, tol: f64) -> f64 {
    let acc = Accuracy::new(tol).unwrap();
    let v: Vec<[f64; 3]> = (0..n)
        .map(|i| {
            let s = i as f64 * h;
            let inp = Inputs::new(k, p[0] + s * d[0], p[1] + s * d[1], p[2] + s * d[2]).unwrap();
            let o = evaluate(&inp, Model::ElasticPlastic, acc).unwrap();
            [o.j4, o.j5, o.j6]
        })
        .collect();
    let mut m: f64 = 0.0;
    for w in v.windows(3) {
        for ((a, b), c) in w[0].iter().zip(&w[1]).zip(&w[2]) {
            m = m.max((c - 2.0 * b + a).abs());
        }
    }
    m
}
