//! Golden tests of the disc-compliance slope conversion against Table 4-3
//! (from Table 4-2) and of Kalker's q against the text of Appendix IV (A).
//!
//! Material: the report's steel as deduced from Table 2-2, E = 210 GPa, ν = 0.3,
//! G_s = E/(2(1+ν)) = 80.77 GPa (see `traction_compliance` docs). q_x = π/C11,
//! q_y = π/C22 from Kalker's table at ν = 0.3 and a/b = 1/k. Same contact, so
//! a* = a and h* = h in (B7).
//!
//! Results (computed vs printed m*):
//! k = 0.5: 66.76 vs 66.74 (+0.03 %), k = 1: 64.31 vs 65.19 (−1.35 %),
//! k = 2: 63.06 vs 62.78 (+0.44 %), k = 5: 62.85 vs 61.10 (+2.87 %).
//!
//! Where the residuals come from. Solving (B7) for the q_x − q_y the report must
//! have used gives −0.030, −0.125, −0.205, −0.270 for k = 0.5, 1, 2, 5; Kalker at
//! ν = 0.3 gives −0.030, −0.112, −0.211, −0.315. No single ν reproduces all four:
//! the implied values correspond to ν ≈ 0.30, 0.33, 0.29 and 0.255. They were read
//! from a figure (figure 19 of Appendix IV, lost):
//! * k = 5: the text itself quotes q_x ≈ 0.93 at k = 5, which is Kalker's ν = 0.25
//!   value (π/3.37 = 0.932; ν = 0.3 gives 0.876). The figure evidently plotted the
//!   ν = 0.25 curves; with ν = 0.25 for the q's this row reproduces to −0.46 %.
//! * k = 1: Table 4-2 prints P0 = 1.96 GPa, figure 4-22 1.90 GPa. 1.90 makes the
//!   residual larger (−1.70 %), so the pressure does not explain it; the remaining
//!   −1.35 % is a 11 % larger |q_x − q_y| than Kalker's, i.e. figure reading.

use traction_compliance::{
    Direction, DiscMaterial, SlopeContact, convert_slope, convert_slope_same_contact, kalker_q,
};
use traction_fluids::table_4_3;
use traction_reproduce::tables::compliance::slope_tolerance;
use traction_tests::rel_diff;

const GPA: f64 = 1e9;

#[test]
fn table_4_3_from_table_4_2() {
    println!("Table 4-3: longitudinal slope m* computed vs printed (E = 210 GPa, ν = 0.3)");
    // Tables 4-2 and 4-3 from fluids/data/main_text_tables.csv. Tolerance
    // (shared with the reproduction): 1.5 %, the aim being 1 % (the three rows
    // below k = 5 are within 1.5 %); 3 % at k = 5, where the report's q is
    // Kalker's ν = 0.25 value (see the module docs).
    let rows = table_4_3().unwrap();
    assert_eq!(rows.len(), 4);
    for r in rows {
        let (k, p0, m, printed) = (r.k, r.p0_gpa, r.m_side, r.m_star);
        let tol = slope_tolerance(k);
        let ms = convert_slope_same_contact(
            m,
            k,
            p0 * GPA,
            Direction::Side,
            Direction::Longitudinal,
            DiscMaterial::REPORT_STEEL,
        )
        .unwrap();
        let d = rel_diff(ms, printed);
        println!(
            "k={k:3}: m={m:6.2} → m*={ms:6.2}  printed {printed:6.2}  {:+.2}%",
            100.0 * (ms / printed - 1.0)
        );
        assert!(d < tol, "k = {k}: {ms} vs {printed}");
    }
}

#[test]
fn table_4_3_k5_with_the_reports_own_q() {
    // q at ν = 0.25 (matching the text's q_x = 0.93 at k = 5), G_s of the steel.
    let g_s = DiscMaterial::REPORT_STEEL.shear_modulus().unwrap();
    let qy = kalker_q(Direction::Side, 5.0, 0.25).unwrap();
    let qx = kalker_q(Direction::Longitudinal, 5.0, 0.25).unwrap();
    let c = |slope, q| SlopeContact {
        slope,
        q,
        a: 1.0,
        h: 1.0,
    };
    let ms = convert_slope(c(52.40, qy), c(0.0, qx), 1.22 * GPA, g_s).unwrap();
    // 1 %: the aim; measured −0.46 %.
    assert!(rel_diff(ms, 61.10) < 0.01, "{ms}");
}

#[test]
fn table_4_3_k1_pressure_misprint_does_not_explain_residual() {
    let m = |p0: f64| {
        convert_slope_same_contact(
            57.60,
            1.0,
            p0 * GPA,
            Direction::Side,
            Direction::Longitudinal,
            DiscMaterial::REPORT_STEEL,
        )
        .unwrap()
    };
    // 1.90 GPa moves m* away from 65.19, not towards it.
    assert!((m(1.90) - 65.19).abs() > (m(1.96) - 65.19).abs());
}

#[test]
fn appendix_a_q_values() {
    // "q = 0.4 for k = 0.2 to q = 0.93 for k = 5 (longitudinal creep only)".
    // Printed to 1 and 2 digits; Kalker's ν = 0.25 column gives 0.404 and 0.932.
    let q02 = kalker_q(Direction::Longitudinal, 0.2, 0.25).unwrap();
    let q5 = kalker_q(Direction::Longitudinal, 5.0, 0.25).unwrap();
    // Half a unit of the printed last digit would allow ±0.05 and ±0.005; the
    // match is within 1 %.
    assert!(rel_diff(q02, 0.4) < 0.011, "{q02}");
    assert!(rel_diff(q5, 0.93) < 0.01, "{q5}");
    // At ν = 0.3 the k = 5 value is 0.876, 6 % from the text: the report's
    // figure used ν = 0.25.
    let q5_03 = kalker_q(Direction::Longitudinal, 5.0, 0.3).unwrap();
    assert!(rel_diff(q5_03, 0.93) > 0.05);
}
