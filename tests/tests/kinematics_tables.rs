//! Golden tests of the twin-disc spin kinematics against Tables 2-5 and 2-6 and
//! the J groups against Appendix VI.
//!
//! Inputs: Table 2-4 (R_y, e), Table 2-2 (C, printed, as input), equations 6 and 7.
//! OCR/print corrections (each checked independently):
//! * High-speed machine, k = 1: Table 2-4 prints R_y = 20.6 mm, Table 2-1 prints
//!   22.6 mm for the same upper disc. 22.6 mm is right: it gives Table 2-1's
//!   Re = (1/33 + 1/71.4 + 1/22.6)⁻¹ = 11.29 mm (printed 11.3), the rolling radius
//!   R_y + e = 22.6 + 10.4 = 33.0 mm = R_x of the upper disc, and Table 2-5's
//!   2.46e-3 and 5.12e-3 (20.6 mm would give 2.62e-3 and 5.44e-3; tested below).
//! * Table 2-6, trace 80051402 (TDF-88, 70 °C, k = 1, 6°): the pressure column
//!   prints 1.00 GPa but Z = .00135; figure 2-16 (the same trace's conditions)
//!   states 1.9 GPa, and .713e-3 × 1.90 = .00135. 1.90 GPa is used.

use traction_kinematics::{j2, j3, spin_factor, spin_group, tilted_disc_spin_per_speed};
use traction_tests::rel_diff;

const GPA: f64 = 1e9;

/// Tolerance of the Table 2-5 check with C computed from the radii: 2 %. The
/// report tabulated C at the nominal k with A, B rounded to 3 digits, while the
/// real discs give k = 0.493, 2.036, 5.054, 5.036: C·√k grows by ~1 % for 2 % in
/// k (k = 2: C 1.9457e-13 vs 1.94e-13 printed, √k +0.9 %). Measured worst 1.74 % (k = 2).
const TOL_HERTZ_C: f64 = 0.02;

struct Case {
    k: f64,
    alpha_deg: f64,
    ry_mm: f64,
    e_mm: f64,
    c_table_2_2: f64, // m/Pa
    printed_per_gpa: f64,
}

fn table_2_5() -> Vec<Case> {
    let c = |k, alpha_deg, ry_mm, e_mm, c_table_2_2, printed_per_gpa| Case {
        k,
        alpha_deg,
        ry_mm,
        e_mm,
        c_table_2_2,
        printed_per_gpa,
    };
    vec![
        // low speed machine, 6°
        c(0.5, 6.0, 4.3, 20.7, 0.135e-12, 0.399e-3),
        c(1.0, 6.0, 12.5, 12.5, 0.170e-12, 0.713e-3),
        c(2.0, 6.0, 36.5, -11.5, 0.194e-12, 1.15e-3),
        c(5.0, 6.0, 150.4, -125.0, 0.208e-12, 1.98e-3),
        // high speed machine (R_y = 22.6 mm for k = 1, see module docs)
        c(1.0, 15.0, 22.6, 10.4, 0.307e-12, 2.46e-3),
        c(1.0, 30.0, 22.6, 10.4, 0.307e-12, 5.12e-3),
        c(5.0, 15.0, 270.0, -230.0, 0.376e-12, 7.06e-3),
        c(5.0, 30.0, 270.0, -205.0, 0.376e-12, 14.6e-3),
    ]
}

fn c2(case: &Case) -> f64 {
    let w = tilted_disc_spin_per_speed(
        case.alpha_deg.to_radians(),
        case.ry_mm * 1e-3,
        case.e_mm * 1e-3,
    )
    .expect("valid Table 2-4 geometry");
    spin_factor(w, case.c_table_2_2, case.k).expect("valid C and k")
}

#[test]
fn table_2_5_spin_factors() {
    println!("Table 2-5: C'' (1/GPa) computed vs printed");
    for case in table_2_5() {
        let computed = c2(&case) * GPA;
        let d = rel_diff(computed, case.printed_per_gpa);
        println!(
            "k={:3} α={:2}°  computed {:.4e}  printed {:.3e}  rel {:.2}%",
            case.k,
            case.alpha_deg,
            computed,
            case.printed_per_gpa,
            100.0 * d
        );
        // Tolerance 1 %: the printed C'' has 3 significant digits (±0.5 unit =
        // up to 0.45 % for .113-type values), and the inputs C (3 digits, up to
        // ±0.37 % for .135) and R_y, e (0.1 mm in a ~25 mm rolling radius, ±0.2 %)
        // are themselves rounded. Worst case measured: k = 2, 1.156e-3 vs 1.15e-3 (0.55 %).
        assert!(
            d < 0.01,
            "k={} α={}: {computed} vs {}",
            case.k,
            case.alpha_deg,
            case.printed_per_gpa
        );
    }
}

#[test]
fn table_2_4_high_speed_ry_misprint_is_real() {
    // With the 20.6 mm of Table 2-4 the high-speed k = 1 factors miss Table 2-5 by > 5 %.
    for (alpha, printed) in [(15.0_f64, 2.46e-3), (30.0, 5.12e-3)] {
        let w = tilted_disc_spin_per_speed(alpha.to_radians(), 20.6e-3, 10.4e-3).unwrap();
        let c = spin_factor(w, 0.307e-12, 1.0).unwrap() * GPA;
        assert!(rel_diff(c, printed) > 0.05);
    }
}

#[test]
fn table_2_6_spin_groups() {
    // (trace, machine/angle index in table_2_5(), P0 in GPa, printed Z)
    // Traces numbered below 791103-00 ran on the high-speed machine.
    let cases = [
        ("79072704", 7, 1.45, 0.021),
        ("79072601", 4, 1.22, 0.003),
        ("80062306", 1, 1.90, 0.00135),
        ("8006201", 3, 1.00, 0.00198),
        ("79100403", 6, 1.00, 0.0071),
        ("79100403", 6, 1.00, 0.0071),
        ("79111902", 1, 1.45, 0.00103),
        ("80051402", 1, 1.90, 0.00135), // 1.90 GPa per figure 2-16 (table prints 1.00)
    ];
    let t = table_2_5();
    println!("Table 2-6: Z = ω√(ab)/U computed vs printed");
    for (trace, idx, p0, printed) in cases {
        let z = spin_group(c2(&t[idx]), p0 * GPA).unwrap();
        let d = rel_diff(z, printed);
        println!(
            "{trace}: computed {z:.5}  printed {printed}  rel {:.2}%",
            100.0 * d
        );
        // The printed Z has 1–3 significant digits: accept either rounding to the
        // printed digits (half a unit of the last digit) or 1 % (the Table 2-5
        // tolerance, since Z = C''·P0). Worst measured: 79100403, 7.065e-3 vs 7.1e-3.
        let digits_ok = {
            let s = format!("{printed}");
            let decimals = s.split('.').nth(1).map_or(0, str::len) as i32;
            (z - printed).abs() <= 0.5 * 10f64.powi(-decimals) + 1e-12
        };
        assert!(digits_ok || d < 0.01, "{trace}: {z} vs {printed}");
    }
    // The misprinted pressure would give half the printed spin.
    let z_misprint = spin_group(c2(&t[1]), 1.00 * GPA).unwrap();
    assert!(rel_diff(z_misprint, 0.00135) > 0.4);
}

#[test]
fn appendix_vi_dimensionless_spin_and_side_slip() {
    // (m, μ, Z, k, printed J3): Appendix VI headers, printed to 9 digits.
    let cases = [
        (35.0, 0.075, 0.021, 5.0, 25.8161723),
        (33.3, 0.051, 7.1e-3, 5.0, 12.2123202),
        (46.9, 0.081, 7.1e-3, 5.0, 10.8295884),
        (53.5, 0.083, 3e-3, 1.0, 2.27812588),
    ];
    for (m, mu, z, k, printed) in cases {
        let j = j3(m, mu, k, z).unwrap();
        // 1e-6: the report's program printed single-precision results (~7 digits).
        assert!(rel_diff(j, printed) < 1e-6, "J3 {j} vs {printed}");
    }
    // Trace 79072704, DV/U = 2.74e-3 → J2 = 3.36839582.
    let j = j2(35.0, 0.075, 5.0, 2.74e-3).unwrap();
    assert!(rel_diff(j, 3.36839582) < 1e-6);
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
    // (upper rx, upper ry, lower rx) in mm for each row of table_2_5()
    let radii = [
        (25.0, 4.3, 25.0),
        (25.0, 12.5, 25.0),
        (25.0, 36.5, 25.0),
        (25.0, 150.4, 25.0),
        (33.0, 22.6, 71.4),
        (33.0, 22.6, 71.4),
        (33.0, 270.0, 71.4),
        (33.0, 270.0, 71.4),
    ];
    println!("Table 2-5 with C from traction-hertz");
    for (case, (rx1, ry1, rx2)) in table_2_5().iter().zip(radii) {
        let g = Geometry::new(
            &Body::steel(rx1 * 1e-3, ry1 * 1e-3),
            &Body::steel(rx2 * 1e-3, f64::INFINITY),
        )
        .unwrap();
        let w = tilted_disc_spin_per_speed(
            case.alpha_deg.to_radians(),
            case.ry_mm * 1e-3,
            case.e_mm * 1e-3,
        )
        .unwrap();
        let computed = spin_factor(w, g.c, g.k).unwrap() * GPA;
        let d = rel_diff(computed, case.printed_per_gpa);
        println!(
            "k nominal {:3} (computed {:.3}) α={:2}°: C = {:.4e} (Table 2-2 {:.3e}); C'' {:.4e} vs printed {:.3e}  rel {:.2}%",
            case.k,
            g.k,
            case.alpha_deg,
            g.c,
            case.c_table_2_2,
            computed,
            case.printed_per_gpa,
            100.0 * d
        );
        assert!(
            d < TOL_HERTZ_C,
            "k={} α={}: {computed}",
            case.k,
            case.alpha_deg
        );
    }
}
