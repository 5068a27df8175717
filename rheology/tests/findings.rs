//! TP 1530 / 78-Lub-10 findings that are quantitative, checked on the
//! converged elastic/plastic model.
#![allow(clippy::unwrap_used)] // functions outside #[test] fns too: a failed unwrap is a failed test

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

/// Slip J1 at which J4 = target for spin J3 (J4 increases with J1).
fn slip_for(k: f64, j3: f64, target: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, 1.0);
    while ep(k, hi, j3, 1e-3).j4 < target {
        lo = hi;
        hi *= 2.0;
    }
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if ep(k, mid, j3, 1e-3).j4 < target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn figure_14_region_boundaries_and_figure_17_loss_factor() {
    // TP 1530 fig. 14: at J4 = 0.75 the region boundaries are the spins at
    // which the slip rises 5 % above the zero-spin elastic/plastic value
    // (I/II), and at which it comes within 5 % of the rigid/plastic value
    // J1 = ε*·J3 (II/III). The figure is not tabulated; we check the ordering,
    // the report's statement that for spins up to J3 ≈ 1 the losses do not
    // increase (fig. 17), and print the boundaries.
    for &k in &[0.25_f64, 1.0, 4.0] {
        // Zero spin: ψ(S) = 0.75 (eq. 22), J1 = (3/2)·S·√k.
        let (mut lo, mut hi) = (0.0, 10.0);
        for _ in 0..60 {
            let m = 0.5 * (lo + hi);
            if traction_rheology::closed::psi(m) < 0.75 {
                lo = m
            } else {
                hi = m
            }
        }
        let j1_0 = 1.5 * lo * k.sqrt();
        // Rigid/plastic: J4(ε) = 0.75 at J3 = 1.
        let (mut lo, mut hi) = (0.0, 10.0);
        for _ in 0..40 {
            let m = 0.5 * (lo + hi);
            let r = evaluate(
                &Inputs::new(k, m, 0.0, 1.0).unwrap(),
                Model::RigidPlastic,
                Accuracy::new(1e-4).unwrap(),
            )
            .unwrap();
            if r.j4 < 0.75 { lo = m } else { hi = m }
        }
        let eps = lo;
        let mut b1 = None;
        let mut b2 = None;
        let mut j3 = 0.05;
        while j3 < 2000.0 && b2.is_none() {
            let j1 = slip_for(k, j3, 0.75);
            if b1.is_none() && j1 > 1.05 * j1_0 {
                b1 = Some(j3);
            }
            if j1 < 1.05 * eps * j3 {
                b2 = Some(j3);
            }
            j3 *= 1.25;
        }
        let (b1, b2) = (b1.unwrap(), b2.unwrap());
        println!(
            "k = {k}: J1(J3=0) = {j1_0:.3}, eps* = {eps:.4}; region I/II at J3 ≈ {b1:.2}, II/III at J3 ≈ {b2:.1}"
        );
        // Ordering of the regions; the grid in J3 is 25 % steps.
        assert!(b1 < b2, "k={k}: {b1} {b2}");
        // TP 1530 conclusion 4: "the effect of spin is always deleterious to
        // traction efficiency": at J4 = 0.75 the loss factor grows with J3.
        // (Fig. 17's reading "no increase up to J3 ≈ 1" is not confirmed by
        // the converged model: +21 % at J3 = 1 for k = 1, printed below.)
        let lf0 = j1_0; // zero spin: LF = J7/J4 = J1
        let mut prev = lf0;
        for j3 in [0.1, 0.3, 1.0, 3.0] {
            let j1 = slip_for(k, j3, 0.75);
            let lf = ep(k, j1, j3, 1e-4).loss_factor();
            println!(
                "k = {k}: LF(J4 = 0.75) at J3 = {j3}: {lf:.4} ({:+.1} % vs zero spin)",
                100.0 * (lf / lf0 - 1.0)
            );
            // Slip from the bisection is exact to 1e-9; J4 to 1e-3 at the
            // bisection's accuracy: allow 1e-3 relative non-monotonicity.
            assert!(lf >= prev * (1.0 - 1e-3), "k={k} J3={j3}: {lf} < {prev}");
            prev = lf;
        }
    }
}
