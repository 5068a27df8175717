//! The thermal contact against the report's measurements: regression guard on
//! the RMS deviations (J units, the tables' own normalisation) with one
//! parameter set per fluid (`fluids/data/thermal_properties.csv`).
//!
//! Identification: Santotrac 50's β_μ = 0.0025 1/K on trace 79072704 (both
//! directions) alone; TDF-88's β_μ = 0 on trace 79100403 (80 m/s) alone. All
//! other traces are predictions. Margins: 5 % of each measured value (the
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
    // Measured 0.1394 (spin-peak 0.182).
    assert!(all < 0.1394 * 1.05, "{all}");
    let a = DataTable::parse("appendix_vii_a_side_slip.csv", APPENDIX_VII_A).unwrap();
    let ma: Vec<f64> = (0..a.rows.len())
        .map(|i| a.num(i, a.col("J5_act").unwrap()).unwrap())
        .collect();
    let ra = rms(&thermal::appendix_vii_a(None).unwrap(), &ma);
    println!("VII-A: thermal {ra:.4}");
    // Measured 0.0329 (isothermal 0.0125): a prediction, guarded from growing.
    assert!(ra < 0.0329 * 1.05, "{ra}");
}
