//! Golden tests of `traction-hertz` against the report's Tables 2-1, 2-2 and
//! 2-3 (section 2-1 and 2-2).
//!
//! Geometry: Table 2-1 (mm), upper disc = body 1, lower disc = body 2 (flat
//! across). The low-speed k = 5 upper Ry is missing in the OCR of Table 2-1;
//! it is recovered as 150.4 mm, the Ry that Table 2-4 lists for the low-speed
//! k = 5 toroid. Table 2-1's printed Re = 11.5 mm needs Ry in [144.2, 152.0]
//! mm (Re in [11.45, 11.55)); 150.4 mm gives Re = 11.54 mm.
//!
//! Table 2-4 lists Ry = 20.6 mm for the high-speed k = 1 toroid where Table
//! 2-1 prints 22.6 mm; 22.6 mm is used: it reproduces Table 2-1's Re = 11.3 mm
//! and k ≈ 1, while 20.6 mm would give Re = 10.77 mm and k = 0.94 (see
//! `table_2_4_hs_k1_radius_is_inconsistent`).
//!
//! Material: steel (AISI-O1), E = 210 GPa, ν = 0.3, `E' = 2/((1−ν²)/E·2)`.
// Helpers outside #[test] functions unwrap too: any failure is a test failure.
#![allow(clippy::unwrap_used)]

use traction_hertz::{Body, Geometry, STEEL_POISSON_RATIO, STEEL_YOUNGS_MODULUS, shape_factors};
use traction_tests::rel_diff;

const INF: f64 = f64::INFINITY;

/// One disc pair of Table 2-1 with its printed k (nominal) and Re (mm).
struct Machine {
    name: &'static str,
    /// Upper Rx, upper Ry, lower Rx, lower Ry (mm).
    radii_mm: [f64; 4],
    k_printed: f64,
    re_printed_mm: f64,
    /// Half a unit of the last printed digit of Re (mm).
    re_half_unit_mm: f64,
    /// C printed in Table 2-2 (1e-12 m/Pa).
    c_printed: f64,
}

const MACHINES: [Machine; 6] = [
    Machine {
        name: "LS k=.5",
        radii_mm: [25.0, 4.3, 25.0, INF],
        k_printed: 0.5,
        re_printed_mm: 3.2,
        re_half_unit_mm: 0.05,
        c_printed: 0.135,
    },
    Machine {
        name: "LS k=1",
        radii_mm: [25.0, 12.5, 25.0, INF],
        k_printed: 1.0,
        re_printed_mm: 6.25,
        re_half_unit_mm: 0.005,
        c_printed: 0.170,
    },
    Machine {
        name: "LS k=2",
        radii_mm: [25.0, 36.5, 25.0, INF],
        k_printed: 2.0,
        re_printed_mm: 9.3,
        re_half_unit_mm: 0.05,
        c_printed: 0.194,
    },
    Machine {
        name: "LS k=5",
        radii_mm: [25.0, 150.4, 25.0, INF],
        k_printed: 5.0,
        re_printed_mm: 11.5,
        re_half_unit_mm: 0.05,
        c_printed: 0.208,
    },
    Machine {
        name: "HS k=1",
        radii_mm: [33.0, 22.6, 71.4, INF],
        k_printed: 1.0,
        re_printed_mm: 11.3,
        re_half_unit_mm: 0.05,
        c_printed: 0.307,
    },
    Machine {
        name: "HS k=5",
        radii_mm: [33.0, 270.0, 71.4, INF],
        k_printed: 5.0,
        re_printed_mm: 20.8,
        re_half_unit_mm: 0.05,
        c_printed: 0.376,
    },
];

fn geometry(m: &Machine) -> Geometry {
    let [rx1, ry1, rx2, ry2] = m.radii_mm.map(|r| r * 1e-3);
    Geometry::new(&Body::steel(rx1, ry1), &Body::steel(rx2, ry2)).unwrap()
}

fn machine(name: &str) -> &'static Machine {
    MACHINES.iter().find(|m| m.name == name).unwrap()
}

#[test]
fn table_2_1_equivalent_radius() {
    for m in &MACHINES {
        let g = geometry(m);
        let re_mm = g.re * 1e3;
        println!(
            "{}: Re = {re_mm:.4} mm (printed {})",
            m.name, m.re_printed_mm
        );
        // Tolerance: half a unit of the last printed digit (the radii are
        // exact inputs, Re is printed rounded).
        assert!(
            (re_mm - m.re_printed_mm).abs() <= m.re_half_unit_mm,
            "{}: Re {re_mm} mm vs printed {}",
            m.name,
            m.re_printed_mm
        );
    }
}

#[test]
fn table_2_1_aspect_ratio() {
    for m in &MACHINES {
        let g = geometry(m);
        let dev = rel_diff(g.k, m.k_printed);
        println!(
            "{}: k = {:.5} (nominal {}), {:+.2} %",
            m.name,
            g.k,
            m.k_printed,
            100.0 * (g.k / m.k_printed - 1.0)
        );
        // The aspect ratio column is a nominal label (Table 2-3 prints it as
        // "1" and "5"): the radii were chosen to approximate it. Exact Hertz
        // theory on the printed radii gives k within 1.8 % of the labels
        // (largest: LS k=2, 2.0355); 2 % bounds that. A wrong curvature
        // convention (e.g. k from Cx/Cy directly, 12 for LS k=5) fails by far.
        assert!(
            dev < 0.02,
            "{}: k {} vs nominal {}",
            m.name,
            g.k,
            m.k_printed
        );
        // Orientation: the ellipse is long across the rolling direction
        // exactly when the toroid's Ry is larger than the relative Rx.
        assert_eq!(g.k > 1.0, g.curvature_x > g.curvature_y, "{}", m.name);
    }
}

/// Table 2-2: (k, A, B) as printed.
const SHAPE_FACTORS: [(f64, f64, f64); 4] = [
    (0.5, 1.46, 0.725),
    (1.0, 1.0, 1.0),
    (2.0, 0.725, 1.46),
    (5.0, 0.511, 2.55),
];

/// Unit of the last printed digit of A and B in Table 2-2 (same order). At
/// k = 1 the printed "1.0" is exact in theory (A = B = 1), so no rounding.
const SHAPE_FACTOR_UNITS: [(f64, f64); 4] =
    [(0.01, 0.001), (0.0, 0.0), (0.001, 0.01), (0.001, 0.01)];

#[test]
fn table_2_2_shape_factors() {
    for (k, a_printed, b_printed) in SHAPE_FACTORS {
        let (a, b) = shape_factors(k).unwrap();
        println!("k = {k}: A = {a:.5} (printed {a_printed}), B = {b:.5} (printed {b_printed})");
        // Tolerance 0.4 %. Equations (1), (2) and the Hertz force balance
        // F = (2/3)πabP0 require B = k·A exactly, but the printed pair at
        // k = .5 has B/A = .725/1.46 = 0.4966 (0.69 % from 0.5; same at
        // k = 2): no exact solution can lie closer than ~0.35 % to both
        // printed values. Measured worst: B(.5) = A(2) = 0.7278 vs .725 (0.38 %).
        assert!(rel_diff(a, a_printed) < 0.004, "A({k}) = {a}");
        assert!(rel_diff(b, b_printed) < 0.004, "B({k}) = {b}");
    }
    // k = 1 is exact: A = B = 1 (sphere-on-flat closed form), to round-off.
    let (a, b) = shape_factors(1.0).unwrap();
    assert!((a - 1.0).abs() < 1e-15 && (b - 1.0).abs() < 1e-15);
}

#[test]
fn table_2_2_c_identifies_the_composite_modulus() {
    // Equation (2), C = 2πA²B·Re/E', evaluated with the report's own printed
    // A, B (Table 2-2) and Re (Table 2-1) and E' = 2/((1−ν²)/E + (1−ν²)/E)
    // for E = 210 GPa, ν = 0.3 (230.77 GPa) reproduces every printed C: this
    // identifies the garbled E' of equation (1). (The OCR's ½(...)⁻¹ would
    // give E'/4 and C four times too large; E/(1−ν²)/2 twice too large.)
    // Tolerance: propagated half-units of the printed inputs and result,
    // 2δA + δB + δRe + δC, each δ = half a unit of the last printed digit
    // divided by the value.
    let e_prime =
        2.0 / (2.0 * (1.0 - STEEL_POISSON_RATIO * STEEL_POISSON_RATIO) / STEEL_YOUNGS_MODULUS);
    let half = |x: f64, unit: f64| 0.5 * unit / x;
    for m in &MACHINES {
        let i = SHAPE_FACTORS
            .iter()
            .position(|s| s.0 == m.k_printed)
            .unwrap();
        let (_, a, b) = SHAPE_FACTORS[i];
        let (ua, ub) = SHAPE_FACTOR_UNITS[i];
        let c = 2.0 * std::f64::consts::PI * a * a * b * m.re_printed_mm * 1e-3 / e_prime * 1e12;
        let tol = 2.0 * half(a, ua)
            + half(b, ub)
            + m.re_half_unit_mm / m.re_printed_mm
            + half(m.c_printed, 0.001);
        println!(
            "{}: C(printed A, B, Re) = {c:.4}e-12 vs {} (tol {:.2} %)",
            m.name,
            m.c_printed,
            100.0 * tol
        );
        assert!(
            rel_diff(c, m.c_printed) <= tol,
            "{}: {c} vs {}",
            m.name,
            m.c_printed
        );
    }
}

#[test]
fn table_2_2_c_exact_on_machine_geometry() {
    for m in &MACHINES {
        let g = geometry(m);
        let c = g.c * 1e12;
        println!(
            "{}: C = {c:.5}e-12 m/Pa (printed {}), {:+.2} %",
            m.name,
            m.c_printed,
            100.0 * (c / m.c_printed - 1.0)
        );
        // Tolerance 1 %. The report computed C from its rounded Table 2-2
        // A, B at the nominal k and the rounded Re (previous test); the exact
        // C at the discs' actual k differs from that by up to 0.95 % (LS k=5:
        // k = 5.054, exact A²B 0.4 % above the printed .511²·2.55, Re 11.54
        // vs 11.5 mm). k = 1 (exact A = B = 1) agrees to 0.1 %.
        assert!(
            rel_diff(c, m.c_printed) < 0.01,
            "{}: {c} vs {}",
            m.name,
            m.c_printed
        );
        if m.k_printed == 1.0 {
            // Only Re's and C's rounding remain: half a unit of C, 0.3 %.
            assert!(rel_diff(c, m.c_printed) < 0.003, "{}", m.name);
        }
    }
}

/// Table 2-3: test number, machine, P0 (GPa, printed), load (N, printed),
/// significant digits of the printed load (trailing zeros not significant).
const TESTS: [(&str, &str, f64, f64, i32); 8] = [
    ("790531-01", "HS k=5", 1.45, 5000.0, 1),
    ("790126-03", "HS k=5", 1.0, 1500.0, 2),
    ("790329-04", "HS k=1", 1.9, 1400.0, 2),
    ("790311-06", "HS k=1", 1.0, 200.0, 1),
    ("791119-04", "LS k=1", 1.9, 416.0, 3),
    ("791130-06", "LS k=1", 1.45, 185.0, 3),
    ("791130-04", "LS k=5", 1.0, 460.0, 2),
    ("791103-11", "LS k=5", 1.45, 1400.0, 2),
];

#[test]
fn table_2_3_pressure_from_load_and_load_from_pressure() {
    for (test, mach, p0_gpa, load, digits) in TESTS {
        let g = geometry(machine(mach));
        let from_load = g.at_load(load).unwrap();
        let from_p0 = g.at_p0(p0_gpa * 1e9).unwrap();
        let p0 = from_load.p0 / 1e9;
        println!(
            "{test} ({mach}): P0(load {load} N) = {p0:.4} GPa vs {p0_gpa} ({:+.2} %); load(P0) = {:.1} N vs {load} ({:+.2} %)",
            100.0 * (p0 / p0_gpa - 1.0),
            from_p0.load,
            100.0 * (from_p0.load / load - 1.0)
        );
        // Tolerance: the printed loads are rounded dead weights (5000, 1500,
        // 1400, 200 N) and P0 ∝ F^(1/3), so the load's rounding contributes
        // a third of its half-unit; Appendix II prints P0 to 3 digits
        // (1.00, 1.45, 1.90), half a unit 0.005 GPa. Worst: 790531-01, whose
        // 5000 N gives 1.489 GPa (+2.7 %; 4620 N would give 1.45 GPa):
        // within the one-digit rounding of "5000" (tolerance 3.7 %).
        let half_unit_load = 0.5 * 10f64.powi(load.log10().floor() as i32 + 1 - digits);
        let tol = half_unit_load / load / 3.0 + 0.005 / p0_gpa;
        assert!(
            rel_diff(p0, p0_gpa) <= tol,
            "{test}: P0 {p0} GPa vs {p0_gpa} (tol {tol})"
        );
        // The inverse is consistent with the forward solve.
        let back = g.at_load(from_p0.load).unwrap();
        assert!(rel_diff(back.p0, p0_gpa * 1e9) < 1e-13, "{test}");
    }
}

#[test]
fn table_2_4_hs_k1_radius_is_inconsistent() {
    // Why Table 2-1's 22.6 mm is used rather than Table 2-4's 20.6 mm: with
    // 20.6 mm, Re is 10.77 mm, outside the half-unit of the printed 11.3 mm,
    // and k is 0.94, not 1.
    let g = Geometry::new(&Body::steel(33e-3, 20.6e-3), &Body::steel(71.4e-3, INF)).unwrap();
    let re_mm = g.re * 1e3;
    println!(
        "HS k=1 with Ry = 20.6 mm: Re = {re_mm:.4} mm, k = {:.4}",
        g.k
    );
    assert!((re_mm - 11.3).abs() > 0.05 && g.k < 0.96);
}
