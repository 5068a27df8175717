//! The thermal contact against the report's measurements: regression guard on
//! the RMS deviations (J units, the tables' own normalisation) with one
//! parameter set per fluid (`fluids/data/thermal_properties.csv`).
//!
//! Identification: Santotrac 50's β_μ = 0.0025 1/K on trace 79072704 (both
//! directions) alone; TDF-88's β_μ = 0.001 1/K jointly on trace 79100403
//! (80 m/s) and the TDF-88 peaks of Appendix VII-E. All other traces are
//! predictions (among them the 64 Santotrac 50 peaks of Appendix VII-E). Margins: 5 % of each measured value (the
//! figures change only when the model or its data change; 5 % leaves room for
//! the rheology's accuracy, 1e-4 in J).

use traction_reproduce::thermal;

fn rms(pred: &[f64], meas: &[f64]) -> f64 {
    assert_eq!(pred.len(), meas.len());
    let s: f64 = pred.iter().zip(meas).map(|(p, m)| (p - m) * (p - m)).sum();
    (s / pred.len() as f64).sqrt()
}

#[test]
fn thermal_predictions_against_the_measurements() {
    use traction_reproduce::data::{APPENDIX_VI, APPENDIX_VII_A, DataTable};
    let vi = DataTable::parse("appendix_vi_spin_traces.csv", APPENDIX_VI).unwrap();
    let (ct, cfy, cms, cj5) = (
        vi.col("trace").unwrap(),
        vi.col("FyFz_exp").unwrap(),
        vi.col("mu_spin").unwrap(),
        vi.col("J5").unwrap(),
    );
    let meas: Vec<f64> = (0..vi.rows.len())
        .map(|i| vi.num(i, cfy).unwrap() / vi.num(i, cms).unwrap())
        .collect();
    let spin_peak: Vec<f64> = (0..vi.rows.len())
        .map(|i| vi.num(i, cj5).unwrap())
        .collect();
    let pred = thermal::appendix_vi(None).unwrap();
    let idx: Vec<usize> = (0..vi.rows.len())
        .filter(|&i| vi.str(i, ct) == "79072704")
        .collect();
    let pick = |v: &[f64]| idx.iter().map(|&i| v[i]).collect::<Vec<_>>();
    let (t, sp) = (
        rms(&pick(&pred), &pick(&meas)),
        rms(&pick(&spin_peak), &pick(&meas)),
    );
    println!("79072704: thermal {t:.4}, spin-peak (printed J5) {sp:.4}");
    // Measured 0.0443 (identification trace): goal ≤ 0.06 and better than the
    // report's spin-peak method.
    assert!(t <= 0.06 && t < sp, "79072704 thermal RMS {t}");
    let all = rms(&pred, &meas);
    println!("Appendix VI all traces: thermal {all:.4}");
    // Measured 0.1465 (spin-peak 0.182).
    assert!(all < 0.1465 * 1.05, "{all}");
    let a = DataTable::parse("appendix_vii_a_side_slip.csv", APPENDIX_VII_A).unwrap();
    let ma: Vec<f64> = (0..a.rows.len())
        .map(|i| a.num(i, a.col("J5_act").unwrap()).unwrap())
        .collect();
    let ra = rms(&thermal::appendix_vii_a(None).unwrap(), &ma);
    println!("VII-A: thermal {ra:.4}");
    // Measured 0.0329 (isothermal 0.0125): a prediction, guarded from growing.
    assert!(ra < 0.0329 * 1.05, "{ra}");
}

/// Appendix VII-E: the peak traction coefficient falls with side slip (by up
/// to 30 % at 2 %); the isothermal J+T peak does not (it is μ at every side
/// slip), the thermal contact follows it. Relative to the zero-spin,
/// zero-side-slip μ of the same fluid, P0, k; measured RMS (isothermal /
/// thermal): Santotrac 50 (a prediction: its β_μ comes from 79072704)
/// 0.125 / 0.080 without spin, 0.143 / 0.082 with 6° spin; TDF-88 (its β_μ
/// identified on these and 79100403) 0.134 / 0.052, 0.110 / 0.049. Margin 5 %.
#[test]
fn appendix_vii_e_peaks_fall_with_side_slip() {
    let peaks = thermal::appendix_vii_e(None).unwrap();
    for (fluid, spin, iso_rms, thermal_rms) in [
        ("Santotrac", false, 0.1251, 0.0797),
        ("Santotrac", true, 0.1430, 0.0816),
        ("TDF", false, 0.1336, 0.0522),
        ("TDF", true, 0.1102, 0.0486),
    ] {
        let sel: Vec<_> = peaks
            .iter()
            .filter(|p| {
                p.point.fluid.contains(fluid) && (p.point.spin_deg > 0.0) == spin && !p.is_reference
            })
            .collect();
        assert!(sel.len() >= 20, "{fluid} {spin}: {} points", sel.len());
        let meas: Vec<f64> = sel.iter().map(|p| p.point.mu / p.reference_mu).collect();
        let iso = rms(&vec![1.0; sel.len()], &meas);
        let th = rms(
            &sel.iter()
                .map(|p| p.thermal / p.reference_mu)
                .collect::<Vec<_>>(),
            &meas,
        );
        println!("VII-E {fluid} spin {spin}: isothermal {iso:.4}, thermal {th:.4}");
        assert!((iso - iso_rms).abs() < 1e-3, "{iso}");
        assert!(th < thermal_rms * 1.05 && th < 0.7 * iso, "{th}");
    }
}
