//! The dimensional contact (traction-contact) against the report's printed
//! theory and measurements, from dimensional inputs only: disc radii (Tables
//! 2-1, 2-4), steel (E = 210 GPa, ν = 0.3, which reproduces Table 2-2's C),
//! Hertz pressure → load (traction-hertz), speeds in m/s, spin from the tilt
//! angle by eq. 6 and the Hertz √(ab), and the fluid's m, μ of Tables 4-1..4-3.
//!
//! Data: `fluids/data/appendix_vii_a_side_slip.csv`,
//! `appendix_vii_b_combined_slip.csv`, `appendix_vi_spin_traces.csv` (their
//! headers list the OCR corrections). Run with `--nocapture` for the deviation
//! tables. Each bound is justified next to its assertion.

use std::f64::consts::PI;

use traction_contact::{
    Body, Compliance, Direction, DiscMaterial, Fluid, OperatingState, Options, TractionContact,
};
use traction_fluids::{machines, table_4_3};
use traction_tests::data::{APPENDIX_VI, APPENDIX_VII_A, APPENDIX_VII_B};
use traction_tests::{Csv, max_rms};

/// The disc pair of Table 2-1 (`fluids/data/machines.csv`, with its OCR
/// corrections) of machine `prefix` (`LS` low speed, `HS` high speed) at k.
fn disc_pair(prefix: &str, k: f64) -> (Body, Body) {
    let m = machines()
        .expect("Table 2-1 data")
        .into_iter()
        .find(|m| m.name.starts_with(prefix) && m.k == k)
        .unwrap_or_else(|| panic!("no {prefix} disc pair for k = {k}"));
    (
        Body::steel(m.rx1_mm * 1e-3, m.ry1_mm * 1e-3),
        Body::steel(m.rx2_mm * 1e-3, f64::INFINITY),
    )
}

/// Low-speed machine discs of Table 2-1.
fn low_speed(k: f64) -> (Body, Body) {
    disc_pair("LS", k)
}

/// High-speed machine discs of Table 2-1.
fn high_speed(k: f64) -> (Body, Body) {
    disc_pair("HS", k)
}

fn build(bodies: (Body, Body), fluid: Fluid, options: Options) -> TractionContact {
    TractionContact::new(&bodies.0, &bodies.1, fluid, options).expect("contact")
}

/// Table 4-2 / 4-3 pressure (Pa) by aspect ratio (U = 20 m/s, θ = 70 °C).
fn table_4_2_p0(k: f64) -> f64 {
    table_4_3()
        .expect("Table 4-3 data")
        .iter()
        .find(|r| r.k == k)
        .unwrap_or_else(|| panic!("k = {k}"))
        .p0_gpa
        * 1e9
}

/// Appendix VII-A: side slip only, m and μ of Table 4-2. Zero spin: the contact
/// takes App. V eq. 23's closed form, in which k cancels (S = (π/4)(m/μ)ΔV/U),
/// so the printed theory is reproduced to its printing precision whatever the
/// Hertz k is.
#[test]
fn appendix_vii_a_side_slip_from_dimensional_inputs() {
    let t = Csv::parse("appendix_vii_a_side_slip.csv", APPENDIX_VII_A);
    let u = 20.0;
    let mut dev_thy = Vec::new();
    let mut dev_act = Vec::new();
    println!("VII-A: Fy/N computed vs printed theory and measured");
    println!("  k    rows  max|d thy|  RMS d thy   max|d act|  RMS d act  (Fy/N)");
    for k in [0.5, 1.0, 2.0, 5.0] {
        let bodies = low_speed(k);
        let hz = traction_hertz::solve_p0(&bodies.0, &bodies.1, table_4_2_p0(k)).expect("hertz");
        let (mut dt, mut da) = (Vec::new(), Vec::new());
        for r in t.rows.iter().filter(|r| t.f(r, "k") == k) {
            let (m, mu) = (t.f(r, "m"), t.f(r, "mu"));
            let c = build(bodies, Fluid::constant(m, mu).unwrap(), Options::default());
            // ΔV/U = chart cm × "X factor/cm" (the report's own J2 input).
            let dv = t.f(r, "cm") * t.f(r, "xf") * u;
            let s = OperatingState::new(hz.load, u, 0.0, dv, 0.0, 70.0).unwrap();
            let e = c.evaluate(&s).unwrap();
            // Printed J2 = (3π/8)(m/μ)(ΔV/U)√k with nominal k; ours uses the
            // Hertz k: J2/√k must agree to the printed 3 decimals. The report
            // truncates rather than rounds (0.37171 prints as 0.371), so one
            // unit of the last place: 1e-3/√k (+ margin).
            let j2p = t.f(r, "J2");
            assert!(
                (e.j2 / e.k.sqrt() - j2p / k.sqrt()).abs() < 1.1e-3 / k.sqrt(),
                "J2 {} vs {j2p}",
                e.j2
            );
            let d = e.traction_y - t.f(r, "FyN_thy");
            // Printed Fy/N(thy) has 4 decimals, truncated or rounded: one unit
            // of the last place, 1e-4; the model is the exact closed form.
            assert!(
                d.abs() < 1.05e-4,
                "k = {k}, cm = {}: {}",
                t.f(r, "cm"),
                e.traction_y
            );
            dt.push(d);
            da.push(e.traction_y - t.f(r, "FyN_act"));
        }
        assert_eq!(dt.len(), 16, "VII-A k = {k}: 16 rows printed");
        let (mt, rt) = max_rms(&dt);
        let (ma, ra) = max_rms(&da);
        println!(
            "  {k:<4} {:>4}  {mt:.2e}    {rt:.2e}    {ma:.4}      {ra:.4}",
            dt.len()
        );
        dev_thy.extend(dt);
        dev_act.extend(da);
    }
    let (ma, ra) = max_rms(&dev_act);
    println!(
        "  all  {:>4}  measured: max {ma:.4}, RMS {ra:.4}",
        dev_act.len()
    );
    // Against the measurements: the report quotes ±5 % of the traction force for
    // its measurements (section 2-2) and the theory was fitted to these traces
    // (m, μ from them): RMS within 5 % of μ ≈ 0.0047, max within 0.005.
    assert!(ra < 0.0047 && ma < 0.005, "measured: max {ma}, RMS {ra}");
}

/// Appendix VII-B: longitudinal slip with imposed side slip, slopes of Table
/// 4-3. ΔU/U from the chart (cm × X factor), ΔV/U from the printed J2 of each
/// set with the report's nominal k (J2 is not printed dimensionally).
#[test]
fn appendix_vii_b_combined_slip_from_dimensional_inputs() {
    let t = Csv::parse("appendix_vii_b_combined_slip.csv", APPENDIX_VII_B);
    let u = 20.0;
    println!("VII-B: Fx/N computed vs printed theory and measured");
    println!("  k    set  J2      rows  max|d thy|  max|d act|  RMS d act  (Fx/N)");
    let mut all_thy = Vec::new();
    let mut all_act = Vec::new();
    for k in [0.5, 1.0, 2.0, 5.0] {
        let bodies = low_speed(k);
        let hz = traction_hertz::solve_p0(&bodies.0, &bodies.1, table_4_2_p0(k)).expect("hertz");
        for set in ["A", "B", "C", "D"] {
            let rows: Vec<_> = t
                .rows
                .iter()
                .filter(|r| t.f(r, "k") == k && t.s(r, "set") == set)
                .collect();
            assert!(!rows.is_empty(), "k = {k} set {set}");
            let (mut dt, mut da) = (Vec::new(), Vec::new());
            let j2 = t.f(rows[0], "J2");
            for r in rows {
                let (m, mu) = (t.f(r, "m"), t.f(r, "mu"));
                let c = build(bodies, Fluid::constant(m, mu).unwrap(), Options::default());
                let du = t.f(r, "cm") * t.f(r, "xf") * u;
                let dv = j2 / (3.0 * PI / 8.0 * (m / mu) * k.sqrt()) * u;
                let s = OperatingState::new(hz.load, u, du, dv, 0.0, 70.0).unwrap();
                let e = c.evaluate(&s).unwrap();
                let thy = t.f(r, "thy");
                let thy_fxn = if t.s(r, "thy_kind") == "J4" {
                    thy * mu
                } else {
                    thy
                };
                let d = e.traction_x - thy_fxn;
                // Printed theory: 3 decimals of J4 or of Fx/N, truncated or
                // rounded (0.08358 prints as 0.083) → one unit of the last
                // place, 1e-3 (of J4: ×μ). Exception, documented in the data file: k = 0.5 set
                // A prints a plateau 0.993 for J4 where eq. 23 gives up to 0.9997;
                // bound 0.0075 in J4 there (printed value, not our error).
                let tol = if k == 0.5 && set == "A" {
                    0.0075 * mu
                } else if t.s(r, "thy_kind") == "J4" {
                    1.05e-3 * mu
                } else {
                    1.05e-3
                };
                assert!(
                    d.abs() < tol,
                    "k = {k} set {set} cm {}: {} vs {thy_fxn}",
                    t.f(r, "cm"),
                    e.traction_x
                );
                dt.push(d);
                da.push(e.traction_x - t.f(r, "FxN_act"));
            }
            let (mt, _) = max_rms(&dt);
            let (ma, ra) = max_rms(&da);
            println!(
                "  {k:<4} {set}    {j2:<7.3} {:>4}  {mt:.2e}    {ma:.4}      {ra:.4}",
                dt.len()
            );
            all_thy.extend(dt);
            all_act.extend(da);
        }
    }
    let (mt, rt) = max_rms(&all_thy);
    let (ma, ra) = max_rms(&all_act);
    println!(
        "  all  {} rows: theory max {mt:.2e} RMS {rt:.2e}; measured max {ma:.4} RMS {ra:.4}",
        all_thy.len()
    );
    // Against the measurements: the k = 0.5 longitudinal traces peak at
    // Fx/N = 0.120, 28 % above the side-slip μ = 0.0935 the theory uses (J4 act
    // up to 1.289), so no isothermal prediction with that μ reaches them (max
    // 0.0265 there); elsewhere the report notes (section 4-2) that thermal
    // effects part theory and test at the larger side slips (up to 0.015, k = 2
    // and 5, set D). Bounds: max 0.03, RMS 0.012 (≈ 12 % of μ).
    assert!(ra < 0.012 && ma < 0.03, "measured: max {ma}, RMS {ra}");
}

/// The compliance option reproduces the slopes of Table 4-3 from those of
/// Table 4-2 (side-slip slope → longitudinal) inside the contact, at the
/// contact's own Hertz k and P0. The compliance crate aims at 1 % and accepts
/// 3 % (the report read q from a lost figure); the longitudinal traction at
/// the VII-B states then follows within the propagated slope error.
#[test]
fn table_4_3_slopes_through_the_compliance_option() {
    let table = table_4_3().expect("Table 4-3 data");
    assert_eq!(table.len(), 4);
    let steel = DiscMaterial::REPORT_STEEL;
    println!("Table 4-3 via Compliance::Discs: m_x computed vs printed");
    for r in table {
        let (k, m_side, mu, m_long) = (r.k, r.m_side, r.mu, r.m_star);
        let bodies = low_speed(k);
        let hz = traction_hertz::solve_p0(&bodies.0, &bodies.1, table_4_2_p0(k)).unwrap();
        let opts = Options {
            compliance: Compliance::Discs {
                material: steel,
                slope_measured_in: Direction::Side,
            },
            ..Options::default()
        };
        let c = build(bodies, Fluid::constant(m_side, mu).unwrap(), opts);
        let s = OperatingState::new(hz.load, 20.0, 0.02, 0.0, 0.0, 70.0).unwrap();
        let e = c.evaluate(&s).unwrap();
        let rel = e.m_used / m_long - 1.0;
        println!(
            "  k = {k}: Hertz k = {:.4}, m_x = {:.2} (printed {m_long}), {:+.2} %",
            e.k,
            e.m_used,
            100.0 * rel
        );
        assert_eq!(e.m_side, m_side);
        // 3 %: the compliance crate's accepted residual for Table 4-3.
        assert!(rel.abs() < 0.03, "k = {k}: {}", e.m_used);
    }
}

/// Tilt angle (deg), toroid R_y and signed centre offset e (m) of Table 2-4 for
/// each Appendix VI trace; the machine and k of Table 2-6.
fn spin_rig(trace: &str) -> (f64, f64, f64, (Body, Body)) {
    match trace {
        "79072704" => (30.0, 270e-3, -205e-3, high_speed(5.0)),
        "79100403" | "79100403-U20" => (15.0, 270e-3, -230e-3, high_speed(5.0)),
        "79072601" => (15.0, 22.6e-3, 10.4e-3, high_speed(1.0)),
        _ => panic!("trace {trace}"),
    }
}

/// Hertz pressure (Pa) and normal load (N) of each trace as printed in Table
/// 2-6 / Appendix VI. The report specifies tests by P0 (and its Z = C''·P0 uses
/// it); the printed loads are nominal dead weights that differ from the Hertz
/// load at that P0 (printed below).
fn spin_pressure_load(trace: &str) -> (f64, f64) {
    match trace {
        "79072704" => (1.45e9, 5000.0),
        "79100403" | "79100403-U20" => (1.0e9, 1500.0),
        "79072601" => (1.22e9, 3000.0),
        _ => panic!("trace {trace}"),
    }
}

/// Appendix VI: side force under spin and side slip (J1 = 0), four traces, both
/// rolling directions, from the tilt angle (eq. 6) and the Hertz contact.
///
/// Negative rolling direction: the machine runs backwards, so U and ω both
/// change sign (the tilt is fixed); the printed ΔV/U times |U| is the lab side
/// slip ΔV; the printed J5·μ is Fy/N. In the forward-rolling frame this is
/// J5(0, J2, −J3) mapped back — the report's "J5(0, −J2, J3)" of the rheology
/// crate's docs.
#[test]
fn appendix_vi_spin_traces_from_the_tilt_angle() {
    let t = Csv::parse("appendix_vi_spin_traces.csv", APPENDIX_VI);
    let traces = ["79072704", "79100403", "79100403-U20", "79072601"];
    println!("App. VI: dJ5 = (Fy/N)/μ − J5 printed (theory) and − (Fy/Fz)/μ measured");
    println!(
        "  trace         dir  Z tilt   Z prt  J3 ours  J3 prt   max|dJ5 thy| RMS     max|dJ5 act| RMS"
    );
    let mut all_thy = Vec::new();
    let mut all_act = Vec::new();
    let mut all_thy_z = Vec::new();
    for trace in traces {
        let (alpha, ry, e_off, bodies) = spin_rig(trace);
        let w_per_u =
            traction_kinematics::tilted_disc_spin_per_speed(alpha.to_radians(), ry, e_off).unwrap();
        for dir in ["positive", "negative"] {
            let rows: Vec<_> = t
                .rows
                .iter()
                .filter(|r| t.s(r, "trace") == trace && t.s(r, "direction") == dir)
                .collect();
            assert!(rows.len() >= 8, "{trace} {dir}");
            let r0 = rows[0];
            let (m, mu, mu_s) = (t.f(r0, "m"), t.f(r0, "mu"), t.f(r0, "mu_spin"));
            let speed = t.f(r0, "U");
            let sign = if dir == "positive" { 1.0 } else { -1.0 };
            let c = build(bodies, Fluid::constant(m, mu).unwrap(), Options::default());
            let cs = build(
                bodies,
                Fluid::constant(m, mu)
                    .unwrap()
                    .with_spin_peak(mu_s)
                    .unwrap(),
                Options::default(),
            );
            let (p0, n_printed) = spin_pressure_load(trace);
            let hz = c.geometry().at_p0(p0).unwrap();
            let n = hz.load;
            if dir == "positive" {
                println!("  {trace}: P0 {p0:.3e} Pa -> N = {n:.0} N (printed {n_printed} N)");
            }
            let z_tilt = w_per_u * (hz.a * hz.b).sqrt();
            let z_printed = t.f(r0, "spin");
            let (mut dt, mut da, mut dz) = (Vec::new(), Vec::new(), Vec::new());
            let mut j3 = 0.0;
            for r in &rows {
                let dv = t.f(r, "dV_U") * speed;
                let u = sign * speed;
                let s = OperatingState::new(n, u, 0.0, dv, sign * w_per_u * speed, 50.0).unwrap();
                let e = c.evaluate(&s).unwrap();
                let es = cs.evaluate(&s).unwrap();
                j3 = e.j3;
                // J5 in the report's lab sense: Fy/(μN).
                let j5 = e.traction_y / mu;
                dt.push(j5 - t.f(r, "J5"));
                da.push(j5 - t.f(r, "FyFz_exp") / mu);
                // The spin-peak variant scales the forces by μ_s: Fy/N = μ_s J5.
                assert!((es.traction_y - mu_s * j5).abs() < 1e-12);
                // Same with the printed Z (ω = Z U/√(ab)): isolates the model.
                let w = sign * z_printed * speed / (hz.a * hz.b).sqrt();
                let sz = OperatingState::new(n, u, 0.0, dv, w, 50.0).unwrap();
                let ez = c.evaluate(&sz).unwrap();
                // J3 from the printed Z equals the printed J3 (to the nominal
                // vs Hertz k: √k enters J3).
                let j3p = t.f(r, "J3");
                // The report's program ran in single precision (7 digits): 1e-6.
                // (J3 is in the forward-rolling frame: negative for the reversed run.)
                let ratio = ez.j3.abs() / j3p / (ez.k / t.f(r, "k")).sqrt();
                assert!((ratio - 1.0).abs() < 1e-6, "{trace}: J3 {} vs {j3p}", ez.j3);
                dz.push(ez.traction_y / mu - t.f(r, "J5"));
            }
            let (mt, rt) = max_rms(&dt);
            let (ma, ra) = max_rms(&da);
            let (mz, rz) = max_rms(&dz);
            println!(
                "  {trace:<13} {}  {z_tilt:.5}  {z_printed:.5} {j3:>7.3}  {:>7.3}   {mt:.4}  {rt:.4}     {ma:.4}  {ra:.4}   (printed Z: {mz:.4} {rz:.4})",
                &dir[..3],
                t.f(r0, "J3")
            );
            // Spin from the tilt (eq. 6, Table 2-4, Hertz √(ab) at the printed
            // P0): the printed Z has 1-2 significant digits (0.021: ±2.4 %
            // rounding) and our Hertz k (5.054) is not the nominal 5: 3 %.
            assert!(
                (z_tilt / z_printed - 1.0).abs() < 0.03,
                "{trace}: Z {z_tilt}"
            );
            all_thy.extend(dt);
            all_act.extend(da);
            all_thy_z.extend(dz);
        }
    }
    let (mt, rt) = max_rms(&all_thy);
    let (mz, rz) = max_rms(&all_thy_z);
    let (ma, ra) = max_rms(&all_act);
    println!(
        "  all: theory max {mt:.4} RMS {rt:.4}; with printed Z max {mz:.4} RMS {rz:.4}; measured max {ma:.4} RMS {ra:.4}"
    );
    // Against the printed theory: the rheology crate's converged model differs
    // from these under-resolved printed spin results by up to ~0.1 in J5 (RMS
    // ~0.04; tests/tests/rheology_appendix.rs); from the tilt angle the spin
    // differs from the printed Z by < 1 %. Same bounds here.
    assert!(mt < 0.1 && rt < 0.04, "theory: max {mt}, RMS {rt}");
    assert!(
        mz < 0.1 && rz < 0.04,
        "theory (printed Z): max {mz}, RMS {rz}"
    );
    // Against the measurements (isothermal theory vs a thermal reality, report
    // section 4-1: "except for some of the very high spin/high speed results"):
    // bound RMS 0.25 and max 0.6 in J5 — a sanity bound, the table is the result.
    assert!(ra < 0.25 && ma < 0.6, "measured: max {ma}, RMS {ra}");
}

/// Table 4-1: the report took m, μ and the spin-peak μ of the Appendix VI
/// traces from its correlations (section 4-1). The contact's report fluids
/// (printed coefficients; TDF-88 spin μ refitted) at the same dimensional state
/// — Hertz P0 and k, |U|, θ, Z from the tilt angle — against the printed values.
#[test]
fn table_4_1_fluid_properties_through_the_correlations() {
    // trace, Santotrac?, θ (°C), U (m/s), P0 (Pa), printed m, μ, μ_s (Table 4-1;
    // 79100403b's slope is 46.9 in App. VI, 40.9 in the OCR of Table 4-1: the
    // App. VI J3 = 10.8295884 needs 46.9).
    let rows = [
        ("79072704", true, 73.0, 80.0, 1.45e9, 35.0, 0.075, 0.035),
        ("79100403", false, 50.0, 80.0, 1.0e9, 33.3, 0.051, 0.044),
        ("79100403-U20", false, 50.0, 20.0, 1.0e9, 46.9, 0.081, 0.080),
        ("79072601", true, 32.5, 20.0, 1.22e9, 53.5, 0.083, 0.084),
    ];
    // The report evaluated its correlations at the nominal k (5, 1); our Hertz k
    // of the high-speed k = 5 discs is 5.036, just outside the data (k ≤ 5), and
    // the correlations are steep there (Extrapolate gives m = 34.6 instead of
    // 33.2 for 79100403): EnvelopeRule::Clamp evaluates at k = 5, flagged.
    println!("Table 4-1 via the report fluids (EnvelopeRule::Clamp, flags shown)");
    println!("  trace          m ours  m prt   μ ours  μ prt   μs ours μs prt  outside");
    let mut rel = Vec::new();
    for (trace, santo, theta, u, p0, m_p, mu_p, mus_p) in rows {
        let (alpha, ry, e_off, bodies) = spin_rig(trace);
        let rule = traction_contact::EnvelopeRule::Clamp;
        let fluid = if santo {
            Fluid::santotrac_50(rule)
        } else {
            Fluid::tdf_88(rule)
        }
        .unwrap()
        .use_spin_peak(true);
        let c = build(bodies, fluid, Options::default());
        let hz = c.geometry().at_p0(p0).unwrap();
        let w = traction_kinematics::tilted_disc_spin_per_speed(alpha.to_radians(), ry, e_off)
            .unwrap()
            * u;
        let s = OperatingState::new(hz.load, u, 0.0, 0.0, w, theta).unwrap();
        let e = c.evaluate(&s).unwrap();
        println!(
            "  {trace:<13} {:>6.1}  {m_p:>5.1}   {:.4}  {mu_p:.3}   {:.4}  {mus_p:.3}   {:?}",
            e.m_used, e.mu_used, e.mu_force, e.outside_envelope
        );
        for (ours, printed) in [(e.m_used, m_p), (e.mu_used, mu_p), (e.mu_force, mus_p)] {
            assert!(ours.is_finite() && ours > 0.0);
            rel.push(ours / printed - 1.0);
        }
        // The slopes (printed coefficients of III-A/III-B, as the report used)
        // within 1 %: 3 printed digits, Z from the tilt vs the printed Z.
        assert!(
            (e.m_used / m_p - 1.0).abs() < 0.01,
            "{trace}: m {}",
            e.m_used
        );
        if trace != "79072601" {
            // μ (III-C/III-D) within 5 %. 79072601 (θ = 32.5 °C) is the
            // exception: the III-C correlation gives 0.113 against the printed
            // 0.083 — reported, not asserted (the printed μ is not what the
            // printed coefficients give at the printed conditions).
            assert!(
                (e.mu_used / mu_p - 1.0).abs() < 0.05,
                "{trace}: μ {}",
                e.mu_used
            );
        }
        if trace != "79072601" {
            // Spin-peak μ_s within 5 % (Santotrac: printed III-E coefficients;
            // TDF-88: the fluids crate's refit of III-F, whose printed
            // coefficients are lost). 79072601: 0.0884 vs 0.084 (+5.2 %), same
            // trace as the μ anomaly above; reported.
            assert!(
                (e.mu_force / mus_p - 1.0).abs() < 0.05,
                "{trace}: μs {}",
                e.mu_force
            );
        }
    }
    let (mx, rms) = max_rms(&rel);
    println!(
        "  relative deviation: max {:.1} %, RMS {:.1} %",
        100.0 * mx,
        100.0 * rms
    );
}
