//! Golden tests of `traction-hertz` against the report's Tables 2-1, 2-2 and
//! 2-3 (section 2-1 and 2-2).
//!
//! Printed values: `fluids/data/machines.csv` (Table 2-1 with Table 2-2's C,
//! upper disc = body 1, lower disc = body 2, flat across; its header lists the
//! two OCR corrections of the upper Ry), `shape_factors.csv` (Table 2-2's A, B)
//! and `load_tests.csv` (Table 2-3), through `traction-fluids`. Tolerances
//! shared with the reproduction: `traction_reproduce::tables::hertz`.
//!
//! Material: steel (AISI-O1), E = 210 GPa, ν = 0.3, `E' = 2/((1−ν²)/E·2)`.
// Functions outside #[test] functions unwrap too: any failure is a test failure.
#![allow(clippy::unwrap_used)]

use traction_fluids::{Machine, load_tests, machine, machines, shape_factor_table};
use traction_hertz::{Body, Geometry, STEEL_POISSON_RATIO, STEEL_YOUNGS_MODULUS, shape_factors};
use traction_reproduce::tables::hertz::{C_TOL, SHAPE_FACTOR_TOL, p0_tolerance};
use traction_tests::rel_diff;

const INF: f64 = f64::INFINITY;

fn geometry(m: &Machine) -> Geometry {
    let [rx1, ry1, rx2] = [m.rx1_mm, m.ry1_mm, m.rx2_mm].map(|r| r * 1e-3);
    Geometry::new(&Body::steel(rx1, ry1), &Body::steel(rx2, INF)).unwrap()
}

#[test]
fn table_2_1_equivalent_radius() {
    let all = machines().unwrap();
    assert_eq!(all.len(), 6);
    for m in &all {
        let g = geometry(m);
        let re_mm = g.re * 1e3;
        let re = m.re_mm.value;
        println!("{}: Re = {re_mm:.4} mm (printed {re})", m.name);
        // Tolerance: half a unit of the last printed digit (the radii are
        // exact inputs, Re is printed rounded).
        assert!(
            (re_mm - re).abs() <= m.re_mm.half_unit(),
            "{}: Re {re_mm} mm vs printed {re}",
            m.name
        );
    }
}

#[test]
fn table_2_1_aspect_ratio() {
    for m in &machines().unwrap() {
        let g = geometry(m);
        let dev = rel_diff(g.k, m.k);
        println!(
            "{}: k = {:.5} (nominal {}), {:+.2} %",
            m.name,
            g.k,
            m.k,
            100.0 * (g.k / m.k - 1.0)
        );
        // The aspect ratio column is a nominal label (Table 2-3 prints it as
        // "1" and "5"): the radii were chosen to approximate it. Exact Hertz
        // theory on the printed radii gives k within 1.8 % of the labels
        // (largest: LS k=2, 2.0355); 2 % bounds that. A wrong curvature
        // convention (e.g. k from Cx/Cy directly, 12 for LS k=5) fails by far.
        assert!(dev < 0.02, "{}: k {} vs nominal {}", m.name, g.k, m.k);
        // Orientation: the ellipse is long across the rolling direction
        // exactly when the toroid's Ry is larger than the relative Rx.
        assert_eq!(g.k > 1.0, g.curvature_x > g.curvature_y, "{}", m.name);
    }
}

#[test]
fn table_2_2_shape_factors() {
    let printed = shape_factor_table().unwrap();
    assert_eq!(printed.len(), 4);
    for p in printed {
        let (k, a_printed, b_printed) = (p.k, p.a.value, p.b.value);
        let (a, b) = shape_factors(k).unwrap();
        println!("k = {k}: A = {a:.5} (printed {a_printed}), B = {b:.5} (printed {b_printed})");
        // Tolerance SHAPE_FACTOR_TOL = 0.4 %. Equations (1), (2) and the Hertz force balance
        // F = (2/3)πabP0 require B = k·A exactly, but the printed pair at
        // k = .5 has B/A = .725/1.46 = 0.4966 (0.69 % from 0.5; same at
        // k = 2): no exact solution can lie closer than ~0.35 % to both
        // printed values. Measured worst: B(.5) = A(2) = 0.7278 vs .725 (0.38 %).
        assert!(rel_diff(a, a_printed) < SHAPE_FACTOR_TOL, "A({k}) = {a}");
        assert!(rel_diff(b, b_printed) < SHAPE_FACTOR_TOL, "B({k}) = {b}");
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
    let shape = shape_factor_table().unwrap();
    for m in &machines().unwrap() {
        let s = shape.iter().find(|s| s.k == m.k).unwrap();
        let (a, b) = (s.a.value, s.b.value);
        // At k = 1 the printed "1.0" is exact in theory (A = B = 1): no rounding.
        let (ua, ub) = if m.k == 1.0 {
            (0.0, 0.0)
        } else {
            (s.a.unit, s.b.unit)
        };
        let re = m.re_mm.value;
        let c = 2.0 * std::f64::consts::PI * a * a * b * re * 1e-3 / e_prime * 1e12;
        let tol = 2.0 * half(a, ua)
            + half(b, ub)
            + m.re_mm.half_unit() / re
            + half(m.c_e12_m_per_pa.value, m.c_e12_m_per_pa.unit);
        println!(
            "{}: C(printed A, B, Re) = {c:.4}e-12 vs {} (tol {:.2} %)",
            m.name,
            m.c_e12_m_per_pa.value,
            100.0 * tol
        );
        assert!(
            rel_diff(c, m.c_e12_m_per_pa.value) <= tol,
            "{}: {c} vs {}",
            m.name,
            m.c_e12_m_per_pa.value
        );
    }
}

#[test]
fn table_2_2_c_exact_on_machine_geometry() {
    for m in &machines().unwrap() {
        let g = geometry(m);
        let c = g.c * 1e12;
        println!(
            "{}: C = {c:.5}e-12 m/Pa (printed {}), {:+.2} %",
            m.name,
            m.c_e12_m_per_pa.value,
            100.0 * (c / m.c_e12_m_per_pa.value - 1.0)
        );
        // Tolerance C_TOL = 1 %. The report computed C from its rounded Table 2-2
        // A, B at the nominal k and the rounded Re (previous test); the exact
        // C at the discs' actual k differs from that by up to 0.95 % (LS k=5:
        // k = 5.054, exact A²B 0.4 % above the printed .511²·2.55, Re 11.54
        // vs 11.5 mm). k = 1 (exact A = B = 1) agrees to 0.1 %.
        assert!(
            rel_diff(c, m.c_e12_m_per_pa.value) < C_TOL,
            "{}: {c} vs {}",
            m.name,
            m.c_e12_m_per_pa.value
        );
        if m.k == 1.0 {
            // Only Re's and C's rounding remain: half a unit of C, 0.3 %.
            assert!(rel_diff(c, m.c_e12_m_per_pa.value) < 0.003, "{}", m.name);
        }
    }
}

#[test]
fn table_2_3_pressure_from_load_and_load_from_pressure() {
    let tests = load_tests().unwrap();
    assert_eq!(tests.len(), 8);
    for t in &tests {
        let (test, mach, p0_gpa, load) = (&t.test, &t.machine, t.p0_gpa.value, t.load_n.value);
        let g = geometry(&machine(mach).unwrap());
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
        let tol = p0_tolerance(t);
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
