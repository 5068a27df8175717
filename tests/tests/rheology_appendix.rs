//! Golden tests of the J+T model (traction-rheology) against the report's
//! printed theory: Appendix VII-A (side slip), VII-B (slip + side slip), both
//! zero spin (App. V eqs. 22–23), and Appendix VI (spin + side slip, J1 = 0).
//!
//! Data: `fluids/data/appendix_vi_spin_traces.csv`,
//! `appendix_vii_a_side_slip.csv`, `appendix_vii_b_combined_slip.csv` (header
//! comments list the OCR corrections). Deviations are printed (run with
//! `--nocapture`) and bounded below with the reason for each bound.
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

use traction_reproduce::tables::traction::{VI_MAX_DEV, VI_RMS_DEV, VI_TOL, VII_A_TOL, VII_B_TOL};
use traction_rheology::{Accuracy, Inputs, Model, evaluate};
use traction_tests::data::{APPENDIX_VI, APPENDIX_VII_A, APPENDIX_VII_B};
use traction_tests::{Csv, cell as num, max_rms};

#[test]
fn appendix_vii_a_side_slip_theory() {
    let t = Csv::parse("appendix_vii_a_side_slip.csv", APPENDIX_VII_A);
    let rows = &t.rows;
    let (ck, cj2, cj5) = (t.idx("k"), t.idx("J2"), t.idx("J5_thy"));
    assert_eq!(rows.len(), 64);
    let mut by_k: Vec<(f64, Vec<f64>)> = Vec::new();
    for r in rows {
        let (k, j2, printed) = (num(r, ck), num(r, cj2), num(r, cj5));
        let inp = Inputs::new(k, 0.0, j2, 0.0).unwrap();
        let o = evaluate(&inp, Model::ElasticPlastic, Accuracy::new(1e-9).unwrap()).unwrap();
        let d = o.j5 - printed;
        match by_k.iter_mut().find(|(kk, _)| *kk == k) {
            Some((_, v)) => v.push(d),
            None => by_k.push((k, vec![d])),
        }
        // Printed to 3 decimals (±0.0005) from J2 that is itself printed to
        // 3 decimals (J2 ±0.0005 moves J5 by ≤ 0.0005·dJ5/dJ2 ≤ 0.0006):
        // bound VII_A_TOL = 0.0015 covers both with margin; observed max below.
        assert!(d.abs() < VII_A_TOL, "k={k} J2={j2}: {} vs {printed}", o.j5);
    }
    for (k, v) in &by_k {
        let (m, rms) = max_rms(v);
        println!(
            "VII-A k={k}: {} rows, max |dJ5| = {m:.5}, RMS = {rms:.5}",
            v.len()
        );
    }
}

#[test]
fn appendix_vii_b_combined_slip_theory() {
    let t = Csv::parse("appendix_vii_b_combined_slip.csv", APPENDIX_VII_B);
    let rows = &t.rows;
    let (ck, cmu, cset, cj1, ckind, cthy, cj2) = (
        t.idx("k"),
        t.idx("mu"),
        t.idx("set"),
        t.idx("J1"),
        t.idx("thy_kind"),
        t.idx("thy"),
        t.idx("J2"),
    );
    let mut groups: Vec<(String, Vec<f64>)> = Vec::new();
    for r in rows {
        let (k, mu, j1, j2, thy) = (
            num(r, ck),
            num(r, cmu),
            num(r, cj1),
            num(r, cj2),
            num(r, cthy),
        );
        if j1 == 0.0 {
            continue;
        }
        let inp = Inputs::new(k, j1, j2, 0.0).unwrap();
        let o = evaluate(&inp, Model::ElasticPlastic, Accuracy::new(1e-9).unwrap()).unwrap();
        // Compare in the printed quantity: J4 (3 decimals) or Fx/N (3 decimals
        // = J4·mu, i.e. J4 to ±0.0005/mu ≈ ±0.0055).
        let (computed, half_ulp) = if r[ckind] == "J4" {
            (o.j4, 0.0005)
        } else {
            (o.j4 * mu, 0.0005)
        };
        let d = computed - thy;
        let key = format!("k={k} set {} ({})", r[cset], r[ckind]);
        match groups.iter_mut().find(|(g, _)| *g == key) {
            Some((_, v)) => v.push(d),
            None => groups.push((key.clone(), vec![d])),
        }
        // Bound: printed rounding (half_ulp) + J1 printed to 2-3 significant
        // digits (≤ 0.5 % of J1; dJ4/dJ1·ΔJ1 ≤ 0.002 in J4) + the report's own
        // integration plateau at k = 0.5 set A (0.993 printed where eq. 23
        // gives up to 0.9997, 0.007). Overall bound VII_B_TOL = 0.0075 in
        // J4 units, VII_B_TOL·mu for Fx/N.
        let bound = if r[ckind] == "J4" {
            VII_B_TOL
        } else {
            VII_B_TOL * mu + half_ulp
        };
        assert!(
            d.abs() <= bound,
            "{key} J1={j1}: computed {computed} printed {thy}"
        );
    }
    for (g, v) in &groups {
        let (m, rms) = max_rms(v);
        println!(
            "VII-B {g}: {} rows, max |d| = {m:.5}, RMS = {rms:.5}",
            v.len()
        );
    }
}

#[test]
fn appendix_vi_spin_traces() {
    let t = Csv::parse("appendix_vi_spin_traces.csv", APPENDIX_VI);
    let rows = &t.rows;
    let (ct, ck, cj3, cdir, cj2, cj5) = (
        t.idx("trace"),
        t.idx("k"),
        t.idx("J3"),
        t.idx("direction"),
        t.idx("J2"),
        t.idx("J5"),
    );
    assert_eq!(rows.len(), 70);
    let acc = Accuracy::new(VI_TOL).unwrap();
    let mut groups: Vec<(String, Vec<f64>)> = Vec::new();
    let mut all = Vec::new();
    for r in rows {
        let (k, j3, j2, printed) = (num(r, ck), num(r, cj3), num(r, cj2), num(r, cj5));
        // The report prints the negative rolling direction as J2 → −J2 at the
        // same J3 (see the crate docs); the printed J2 already carries the sign.
        let o = evaluate(
            &Inputs::new(k, 0.0, j2, j3).unwrap(),
            Model::ElasticPlastic,
            acc,
        )
        .unwrap();
        let d = o.j5 - printed;
        let key = format!("{} {}", r[ct], r[cdir]);
        match groups.iter_mut().find(|(g, _)| *g == key) {
            Some((_, v)) => v.push(d),
            None => groups.push((key.clone(), vec![d])),
        }
        all.push(d);
    }
    for (g, v) in &groups {
        let (m, rms) = max_rms(v);
        println!(
            "App. VI {g}: {} rows, max |dJ5| = {m:.4}, RMS = {rms:.4}",
            v.len()
        );
    }
    let (m, rms) = max_rms(&all);
    println!("App. VI all: max |dJ5| = {m:.4}, RMS = {rms:.4}");
    // The converged model (checked against an independent grid scheme in
    // rheology_grid.rs) differs from the printed J5 by up to 0.09 at small J2
    // for k = 1 (J3 = 2.28), where the printed values lie between the elastic
    // bound −J3/(4k) and the converged solution; the report's program is
    // unpublished and evidently under-resolved there. Bounds: max 0.1, RMS 0.04
    // (observed values are printed above and in the crate README).
    assert!(m < VI_MAX_DEV && rms < VI_RMS_DEV, "max {m} rms {rms}");
}
