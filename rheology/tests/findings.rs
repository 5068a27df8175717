//! TP 1530 / 78-Lub-10 findings that are quantitative, checked on the
//! converged elastic/plastic model.
#![allow(clippy::unwrap_used)] // test helpers: a failed unwrap is a failed test

use traction_rheology::{Accuracy, Inputs, Model, Outputs, evaluate};

fn ep(k: f64, j1: f64, j3: f64, tol: f64) -> Outputs {
    let inp = Inputs::new(k, j1, 0.0, j3).unwrap();
    evaluate(&inp, Model::ElasticPlastic, Accuracy::new(tol).unwrap()).unwrap()
}

#[test]
fn side_force_reaches_about_75_percent_of_traction() {
    // TP 1530 summary: "Sideways forces due to the spin on the contact can be
    // substantial and may reach 75 percent of the transmitted traction force";
    // fig. 12 plots the maximum side force J5 (in units of μN, i.e. of the
    // peak traction) for spin only against k, larger for small k.
    let mut maxima = Vec::new();
    for &k in &[0.125, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0] {
        let mut m: f64 = 0.0;
        for i in 0..40 {
            let j3 = 0.2 * 1.15_f64.powi(i);
            m = m.max(ep(k, 0.0, j3, 1e-3).j5.abs());
        }
        println!("k = {k}: max |J5| (spin only) = {m:.3}");
        maxima.push(m);
    }
    // Monotone decreasing with k (fig. 12) and ≈ 0.75 at the small-k end:
    // the scan in J3 (15 % steps) resolves the maximum to < 0.01.
    assert!(maxima.windows(2).all(|w| w[0] >= w[1] - 0.01), "{maxima:?}");
    assert!(maxima[0] > 0.6 && maxima[0] < 0.9, "{maxima:?}");
}

#[test]
fn loss_factor_minimum_near_j4_075_under_high_spin() {
    // 78-Lub-10 §9: "When the spin is high the loss factor is a minimum at
    // J4 ≈ .75" (k = 1, fig. 8). Scan J1 at J3 = 8.95 (a spin of fig. 5).
    let j3 = 8.95;
    let mut best = (f64::INFINITY, 0.0, 0.0);
    for i in 1..=60 {
        let j1 = 0.5 * i as f64;
        let o = ep(1.0, j1, j3, 1e-3);
        let lf = o.loss_factor();
        if lf < best.0 {
            best = (lf, o.j4, j1);
        }
    }
    println!(
        "min LF = {:.3} at J4 = {:.3} (J1 = {})",
        best.0, best.1, best.2
    );
    // Read off a figure ("≈ .75"); the scan step in J1 (0.5) moves J4 by
    // ≤ 0.03 near the minimum: accept 0.6..0.9.
    assert!(best.1 > 0.6 && best.1 < 0.9, "{best:?}");
}
