//! Golden tests of the twin-disc spin kinematics against Tables 2-5 and 2-6 and
//! the J groups against Appendix VI.
//!
//! Inputs (read from `fluids/data` through traction-fluids' `spin_tests` and
//! `main_text_tables`): Table 2-4 (R_y, e), Table 2-2 (C, printed, as input),
//! Tables 2-5 and 2-6 (printed), the Appendix VI traces (`appendix_vi_spin_traces.csv`:
//! J2, J3 printed with m, μ, k, Z, ΔV/U); equations 6 and 7. The tolerances are the
//! reproduction's (`traction_reproduce::tables::spin`).
//! OCR/print corrections (each checked independently):
//! * High-speed machine, k = 1: Table 2-4 prints R_y = 20.6 mm, Table 2-1 prints
//!   22.6 mm for the same upper disc. 22.6 mm is right: it gives Table 2-1's
//!   Re = (1/33 + 1/71.4 + 1/22.6)⁻¹ = 11.29 mm (printed 11.3), the rolling radius
//!   R_y + e = 22.6 + 10.4 = 33.0 mm = R_x of the upper disc, and Table 2-5's
//!   2.46e-3 and 5.12e-3 (20.6 mm would give 2.62e-3 and 5.44e-3; tested below).
//! * Table 2-6, trace 80051402 (TDF-88, 70 °C, k = 1, 6°): the pressure column
//!   prints 1.00 GPa but Z = .00135; figure 2-16 (the same trace's conditions)
//!   states 1.9 GPa, and .713e-3 × 1.90 = .00135. 1.90 GPa is used.

use traction_fluids::SpinTest;
use traction_kinematics::{j2, j3, spin_factor, spin_group, tilted_disc_spin_per_speed};
use traction_reproduce::tables::spin::{C2_HERTZ_C_TOL, C2_TOL};
use traction_tests::data::APPENDIX_VI;
use traction_tests::{Csv, rel_diff};

const GPA: f64 = 1e9;

/// The spin-test conditions of Tables 2-4 and 2-5 (`fluids/data`: Table 2-1
/// radii with Table 2-2's printed C, Table 2-4's e, Table 2-5's printed C'').
fn table_2_5() -> Vec<SpinTest> {
    traction_fluids::spin_tests().expect("Table 2-5 data")
}

/// C'' (1/Pa) of a spin test with Table 2-2's printed C, eq. 6 and 7.
fn c2(t: &SpinTest) -> f64 {
    let w = tilted_disc_spin_per_speed(
        t.spin_deg.to_radians(),
        t.machine.ry1_mm * 1e-3,
        t.e_mm * 1e-3,
    )
    .expect("valid Table 2-4 geometry");
    spin_factor(w, t.machine.c_e12_m_per_pa.value * 1e-12, t.machine.k).expect("valid C and k")
}

#[test]
fn table_2_5_spin_factors() {
    println!("Table 2-5: C'' (1/GPa) computed vs printed");
    for case in table_2_5() {
        let printed = case.spin_factor.c_table_2_5;
        let computed = c2(&case) * GPA;
        let d = rel_diff(computed, printed);
        println!(
            "k={:3} α={:2}°  computed {:.4e}  printed {:.3e}  rel {:.2}%",
            case.machine.k,
            case.spin_deg,
            computed,
            printed,
            100.0 * d
        );
        // C2_TOL: its justification is in its docs.
        assert!(
            d < C2_TOL,
            "k={} α={}: {computed} vs {printed}",
            case.machine.k,
            case.spin_deg,
        );
    }
}

#[test]
fn table_2_4_high_speed_ry_misprint_is_real() {
    // With the 20.6 mm of Table 2-4 (machines.csv's correction) the high-speed
    // k = 1 factors miss Table 2-5 by > 5 %.
    let hs_k1: Vec<SpinTest> = table_2_5()
        .into_iter()
        .filter(|t| t.machine.name == "HS k=1")
        .collect();
    assert_eq!(hs_k1.len(), 2);
    for t in hs_k1 {
        let w =
            tilted_disc_spin_per_speed(t.spin_deg.to_radians(), 20.6e-3, t.e_mm * 1e-3).unwrap();
        let c = spin_factor(w, t.machine.c_e12_m_per_pa.value * 1e-12, 1.0).unwrap() * GPA;
        assert!(rel_diff(c, t.spin_factor.c_table_2_5) > 0.05);
    }
}

#[test]
fn table_2_6_spin_groups() {
    let t = table_2_5();
    // The spin test of Table 2-5 with this k and tilt angle.
    let test = |k: f64, spin_deg: f64| {
        t.iter()
            .find(|s| s.machine.k == k && s.spin_deg == spin_deg)
            .expect("a Table 2-5 condition")
    };
    let rows: Vec<_> = traction_fluids::main_text_tables()
        .expect("main-text tables")
        .into_iter()
        .filter(|r| r.table == "2-6")
        .collect();
    assert_eq!(rows.len(), 8);
    println!("Table 2-6: Z = ω√(ab)/U computed vs printed");
    for r in &rows {
        let [_, Some(p0), _, Some(k), Some(spin_deg), Some(printed), ..] = r.values else {
            panic!("{}: incomplete Table 2-6 row", r.trace);
        };
        // 80051402: 1.90 GPa per figure 2-16 (the table prints 1.00; module docs).
        let p0 = if r.trace == "80051402" { 1.90 } else { p0 };
        let z = spin_group(c2(test(k, spin_deg)), p0 * GPA).unwrap();
        let d = rel_diff(z, printed);
        println!(
            "{}: computed {z:.5}  printed {printed}  rel {:.2}%",
            r.trace,
            100.0 * d
        );
        // The printed Z has 1–3 significant digits: accept either rounding to the
        // printed digits (half a unit of the last digit) or the Table 2-5
        // tolerance (Z = C''·P0). Worst measured: 79100403, 7.065e-3 vs 7.1e-3.
        let digits_ok = {
            let s = format!("{printed}");
            let decimals = s.split('.').nth(1).map_or(0, str::len) as i32;
            (z - printed).abs() <= 0.5 * 10f64.powi(-decimals) + 1e-12
        };
        assert!(digits_ok || d < C2_TOL, "{}: {z} vs {printed}", r.trace);
    }
    // The misprinted pressure would give half the printed spin.
    let misprint = rows.iter().find(|r| r.trace == "80051402").unwrap();
    let (p0, printed) = (misprint.values[1].unwrap(), misprint.values[5].unwrap());
    let z_misprint = spin_group(c2(test(1.0, 6.0)), p0 * GPA).unwrap();
    assert!(rel_diff(z_misprint, printed) > 0.4);
}

#[test]
fn appendix_vi_dimensionless_spin_and_side_slip() {
    // Every row of the Appendix VI data (fluids/data): the printed J3 of its
    // trace header from m, μ, k and Z = ω√(ab)/U, and its printed J2 from m,
    // μ, k and ΔV/U. 1e-6 relative: the report's program printed
    // single-precision results (~7 digits).
    let t = Csv::parse("appendix_vi_spin_traces.csv", APPENDIX_VI);
    assert!(t.rows.len() >= 70, "{} rows", t.rows.len());
    for r in &t.rows {
        let (m, mu, k) = (t.f(r, "m"), t.f(r, "mu"), t.f(r, "k"));
        let (trace, printed_j3) = (t.s(r, "trace"), t.f(r, "J3"));
        let j = j3(m, mu, k, t.f(r, "spin")).unwrap();
        assert!(
            rel_diff(j, printed_j3) < 1e-6,
            "{trace}: J3 {j} vs {printed_j3}"
        );
        let printed_j2 = t.f(r, "J2");
        let j = j2(m, mu, k, t.f(r, "dV_U")).unwrap();
        assert!(
            rel_diff(j, printed_j2) < 1e-6,
            "{trace}: J2 {j} vs {printed_j2}"
        );
    }
}

/// Second check of Table 2-5 with C computed by `traction-hertz` (exact Hertz
/// theory, steel E = 210 GPa, ν = 0.3) from the disc radii of Table 2-1 (upper
/// R_x, R_y; lower R_x, flat) instead of Table 2-2's printed C. R_y of the
/// low-speed k = 5 disc is blank in Table 2-1 and taken from Table 2-4 (150.4 mm);
/// the high-speed k = 1 disc uses 22.6 mm (see module docs). k in √k is the
/// computed aspect ratio.
#[test]
fn table_2_5_with_hertz_computed_c() {
    use traction_hertz::{Body, Geometry};
    println!("Table 2-5 with C from traction-hertz");
    for case in table_2_5() {
        let m = &case.machine;
        let printed = case.spin_factor.c_table_2_5;
        let g = Geometry::new(
            &Body::steel(m.rx1_mm * 1e-3, m.ry1_mm * 1e-3),
            &Body::steel(m.rx2_mm * 1e-3, f64::INFINITY),
        )
        .unwrap();
        let w = tilted_disc_spin_per_speed(
            case.spin_deg.to_radians(),
            m.ry1_mm * 1e-3,
            case.e_mm * 1e-3,
        )
        .unwrap();
        let computed = spin_factor(w, g.c, g.k).unwrap() * GPA;
        let d = rel_diff(computed, printed);
        println!(
            "k nominal {:3} (computed {:.3}) α={:2}°: C = {:.4e} (Table 2-2 {:.3e}); C'' {:.4e} vs printed {:.3e}  rel {:.2}%",
            m.k,
            g.k,
            case.spin_deg,
            g.c,
            m.c_e12_m_per_pa.value * 1e-12,
            computed,
            printed,
            100.0 * d
        );
        // C2_HERTZ_C_TOL: its justification is in its docs.
        assert!(
            d < C2_HERTZ_C_TOL,
            "k={} α={}: {computed}",
            m.k,
            case.spin_deg
        );
    }
}
