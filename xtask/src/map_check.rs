//! Accuracy and hit rate of `map::Map` on random points:
//! `map-check K TOL N RLOG [DX GY]` (|x| log-uniform in [0.1, 10^(RLOG−1)], reference
//! `evaluate` at TOL/100). Prints the worst error, the error distribution and
//! the map's counters.
#![allow(clippy::unwrap_used)]
use crate::arg;
use std::f64::consts::PI;
use traction_rheology::{Accuracy, Inputs, Model, evaluate, map::Map};
use traction_testkit::XorShift64;

/// Runs the check with the command line's arguments after `map-check`.
pub fn run(a: &[String]) -> Result<(), String> {
    let (k, tol, n, rlog): (f64, f64, usize, f64) = (
        arg(a, 0, "K", None)?,
        arg(a, 1, "TOL", None)?,
        arg(a, 2, "N", None)?,
        arg(a, 3, "RLOG", None)?,
    );
    let (dx, gy): (f64, f64) = (arg(a, 4, "DX", Some(0.0))?, arg(a, 5, "GY", Some(1.0))?);
    let mut map = Map::new(k, dx, gy, Accuracy::new(tol).map_err(|e| e.to_string())?)
        .map_err(|e| e.to_string())?;
    let mut xs = XorShift64::new(0x1234_5678_9abc_def1u64 ^ (k * 1e6) as u64);
    let mut rnd = || xs.unit();
    let (s12, s3) = (1.0 / k.sqrt(), (1.0 + 1.0 / (k * k)).sqrt());
    let acc = Accuracy::new(tol / 100.0).map_err(|e| e.to_string())?;
    let (mut worst, mut hist) = (0.0f64, [0usize; 5]);
    let t0 = std::time::Instant::now();
    for _ in 0..n {
        let r = 10f64.powf(-1.0 + rlog * rnd());
        let z = 2.0 * rnd() - 1.0;
        let p = 2.0 * PI * rnd();
        let q = (1.0 - z * z).sqrt();
        let (j1, j2, j3) = (r * q * p.cos() / s12, r * q * p.sin() / s12, r * z / s3);
        let inp = Inputs::with_offset(k, j1, j2, j3, dx)
            .and_then(|i| i.with_stiffness_ratio(gy))
            .unwrap();
        let m = map.evaluate(&inp).unwrap();
        let o = evaluate(&inp, Model::ElasticPlastic, acc).unwrap();
        let err = (m.j4 - o.j4)
            .abs()
            .max((m.j5 - o.j5).abs())
            .max((m.j6 - o.j6).abs());
        hist[((err / tol * 8.0).floor() as usize).min(4)] += 1;
        if err > worst {
            worst = err;
            if std::env::var("V").is_ok() {
                println!("worst {err:.2e} at J=({j1:.4},{j2:.4},{j3:.4})");
            }
        }
    }
    let s = map.stats();
    println!(
        "k={k} dX={dx} gy={gy} tol={tol:.0e}: worst {:.2}·tol; err/tol in [0,1/8),..,[1/2,inf): {hist:?}; direct {:.1}% ({} of {}); nodes {}, cells {} ({} rejected); {:.1} s",
        worst / tol,
        100.0 * s.direct as f64 / (s.direct + s.interpolated) as f64,
        s.direct,
        s.direct + s.interpolated,
        s.nodes_computed,
        s.cells_checked,
        s.cells_rejected,
        t0.elapsed().as_secs_f64()
    );
    Ok(())
}
