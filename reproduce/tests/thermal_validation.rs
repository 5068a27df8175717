//! The thermal contact against the report's measurements: regression guard on
//! the RMS deviations (J units, the tables' own normalisation) with one
//! parameter set per fluid (`fluids/data/thermal_properties.csv`).
//!
//! Identification (μ(ΔT) = μ e^(−(ΔT² − ΔT_peak²)/T*²), docs/decisions/0023):
//! Santotrac 50's T* = 480 K on trace 79072704 (both directions) alone;
//! TDF-88's T* = 575 K jointly on trace 79100403 (80 m/s) and the TDF-88
//! peaks of Appendix VII-E. All other traces are predictions (among them
//! Appendix I, VII-A, VII-B and the 64 Santotrac 50 peaks of Appendix VII-E).
//! Margins: 5 % of each measured value (the figures change only when the
//! model or its data change; 5 % leaves room for the rheology's accuracy,
//! 1e-4 in J).
#![allow(clippy::unwrap_used)] // test: a failed unwrap is a failed test

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
    // report's spin-peak method (0.176 on the printed J5).
    assert!(t <= 0.06 && t < sp, "79072704 thermal RMS {t}");
    let idx: Vec<usize> = (0..vi.rows.len())
        .filter(|&i| vi.str(i, ct) == "79072601")
        .collect();
    let pick = |v: &[f64]| idx.iter().map(|&i| v[i]).collect::<Vec<_>>();
    let t = rms(&pick(&pred), &pick(&meas));
    println!("79072601 (k = 5 discs): thermal {t:.4}");
    // Measured 0.1361 (0.250 on the printed k = 1 discs, isothermal 0.132).
    assert!(t < 0.1361 * 1.05, "79072601 thermal RMS {t}");
    let all = rms(&pred, &meas);
    println!("Appendix VI all traces: thermal {all:.4}");
    // Measured 0.0994 (spin-peak 0.182; the goal of halving it, 0.091, is
    // not met: 79100403 and 79072601 hold it, contact README).
    assert!(all < 0.0994 * 1.05, "{all}");
    let a = DataTable::parse("appendix_vii_a_side_slip.csv", APPENDIX_VII_A).unwrap();
    let ma: Vec<f64> = (0..a.rows.len())
        .map(|i| a.num(i, a.col("J5_act").unwrap()).unwrap())
        .collect();
    let ra = rms(&thermal::appendix_vii_a(None).unwrap(), &ma);
    println!("VII-A: thermal {ra:.4}");
    // Measured 0.0111 (isothermal 0.0125): a prediction; the guard (0.0117)
    // lies inside the goal of at most 10 % above the isothermal fit (0.0138).
    assert!(ra < 0.0111 * 1.05, "{ra}");
    let pts = traction_fluids::appendix_i_traces().unwrap();
    let mi: Vec<f64> = pts.iter().map(|p| p.j5).collect();
    let ri = rms(&thermal::appendix_i(None).unwrap(), &mi);
    println!("Appendix I: thermal {ri:.4}");
    // Measured 0.0167 (isothermal 0.0182): the guard (0.0175) lies inside the
    // goal of at most 10 % above the isothermal fit (0.0200).
    assert!(ri < 0.0167 * 1.05, "{ri}");
}

/// Appendix VII-B (longitudinal traces with side slip, low-speed machine,
/// 20 m/s, no spin; a prediction) per aspect ratio, RMS of J4 = (Fx/N)/μ
/// isothermal / thermal: k = 1, 2, 5 (131 points) 0.0585 / 0.0471 — the
/// heating brings down the high-side-slip sets D the report calls thermal
/// (k = 1 0.078 → 0.031, k = 2 0.104 → 0.073) — while k = 0.5 (44 points)
/// is missed by both, 0.194 / 0.218: its measured Fx/N reaches 1.29 μ of
/// the set (0.12 against the side-slip tests' μ = 0.0935, already at
/// J2 = 0.15), above what any model bounded by that μ can give. Margin 5 %.
#[test]
fn appendix_vii_b_per_aspect_ratio() {
    use traction_reproduce::data::{APPENDIX_VII_B, DataTable};
    let t = DataTable::parse("appendix_vii_b_combined_slip.csv", APPENDIX_VII_B).unwrap();
    let isothermal = thermal::appendix_vii_b(Some(
        [thermal::Law {
            mu_coefficient: 0.0,
            mu_rise_scale: 1e12,
            slope_coefficient: 0.0,
            film: traction_contact::Film::FromFluid,
        }; 2],
    ))
    .unwrap();
    let heated = thermal::appendix_vii_b(None).unwrap();
    let (ck, cj4) = (t.col("k").unwrap(), t.col("J4_act").unwrap());
    let split = |keep: &dyn Fn(f64) -> bool| {
        let idx: Vec<usize> = (0..t.rows.len())
            .filter(|&i| keep(t.num(i, ck).unwrap()))
            .collect();
        let pick = |v: &[f64]| idx.iter().map(|&i| v[i]).collect::<Vec<_>>();
        let meas: Vec<f64> = idx.iter().map(|&i| t.num(i, cj4).unwrap()).collect();
        let peak = meas.iter().cloned().fold(0.0, f64::max);
        (
            rms(&pick(&isothermal), &meas),
            rms(&pick(&heated), &meas),
            peak,
        )
    };
    let (iso, th, _) = split(&|k| k >= 1.0);
    println!("VII-B k ≥ 1: isothermal {iso:.4}, thermal {th:.4}");
    assert!(th < 0.0471 * 1.05 && th < iso, "{th} {iso}");
    let (iso, th, peak) = split(&|k| k < 1.0);
    println!("VII-B k = 0.5: isothermal {iso:.4}, thermal {th:.4}, measured J4 up to {peak:.3}");
    assert!(peak > 1.25 && iso > 0.15, "{peak} {iso}");
}

/// Appendix VII-E: the peak traction coefficient falls with side slip (by up
/// to 30 % at 2 %); the isothermal J+T peak does not (it is μ at every side
/// slip), the thermal contact follows it. Relative to the zero-spin,
/// zero-side-slip μ of the same fluid, P0, k; measured RMS (isothermal /
/// thermal): Santotrac 50 (a prediction: its T* comes from 79072704)
/// 0.125 / 0.060 without spin, 0.143 / 0.082 with 6° spin; TDF-88 (its T*
/// identified on these and 79100403) 0.134 / 0.074, 0.110 / 0.060. Margin 5 %.
#[test]
fn appendix_vii_e_peaks_fall_with_side_slip() {
    let peaks = thermal::appendix_vii_e(None).unwrap();
    for (fluid, spin, iso_rms, thermal_rms) in [
        ("Santotrac", false, 0.1251, 0.0604),
        ("Santotrac", true, 0.1430, 0.0815),
        ("TDF", false, 0.1336, 0.0740),
        ("TDF", true, 0.1102, 0.0602),
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

/// Trace 79072601 ran on the high-speed machine's k = 5 discs (its
/// Appendix VI header prints k = 1): the printed load and pressure (3000 N,
/// 1.22 GPa) are those of the k = 5 discs, and the printed m = 53.5, μ =
/// 0.083 are the report's correlations evaluated at k = 1 (so the thermal
/// prediction evaluates them at k = 5). Independent checks against printed
/// values: Hertz on Table 2-1's discs (the k = 5 discs give P0 2.9 % above
/// the printed value, as for trace 79072704's 5000 N → 1.45 GPa on the same
/// discs: 2.7 %; the k = 1 discs give twice the pressure), and the printed
/// correlations at k = 1 against Table 4-1's printed m, μ (3 digits).
#[test]
fn trace_79072601_ran_on_the_k5_discs() {
    use traction_contact::{Body, Fluid, Options, TractionContact};
    let p0_at = |ry: f64, load: f64| {
        let c = TractionContact::new(
            &Body::steel(33e-3, ry),
            &Body::steel(71.4e-3, f64::INFINITY),
            Fluid::constant(50.0, 0.08).unwrap(),
            Options::default(),
        )
        .unwrap();
        c.geometry().at_load(load).unwrap().p0
    };
    let (k5, k1, ref_k5) = (
        p0_at(270e-3, 3000.0),
        p0_at(22.6e-3, 3000.0),
        p0_at(270e-3, 5000.0),
    );
    println!(
        "P0 at 3000 N: k = 5 discs {k5:.4e}, k = 1 discs {k1:.4e}; 5000 N on k = 5: {ref_k5:.4e}"
    );
    assert!(
        (k5 / 1.22e9 - ref_k5 / 1.45e9).abs() < 0.005,
        "{k5} {ref_k5}"
    );
    assert!(k1 > 2.0e9, "{k1}");
    let f = traction_fluids::Fluid::santotrac_50().unwrap();
    let q = traction_fluids::Query {
        p0_pa: 1.22e9,
        speed_m_s: 20.0,
        theta_celsius: 32.5,
        k: 1.0,
        z: 0.0,
    };
    let strict = traction_fluids::Policy::Strict;
    let m = f.slope.evaluate(&q, strict).unwrap().value;
    let mu = f.spin_mu.evaluate(&q, strict).unwrap().value;
    // Table 4-1 prints m = 53.5 and μ = .083 (half a unit of the last digit).
    assert!(
        (m - 53.5).abs() <= 0.05 && (mu - 0.083).abs() <= 0.0005,
        "{m} {mu}"
    );
}

fn vi_trace_rms(law: Option<[thermal::Law; 2]>, trace: &str) -> f64 {
    use traction_reproduce::data::{APPENDIX_VI, DataTable};
    let vi = DataTable::parse("appendix_vi_spin_traces.csv", APPENDIX_VI).unwrap();
    let (ct, cfy, cms) = (
        vi.col("trace").unwrap(),
        vi.col("FyFz_exp").unwrap(),
        vi.col("mu_spin").unwrap(),
    );
    let pred = thermal::appendix_vi(law).unwrap();
    let idx: Vec<usize> = (0..vi.rows.len())
        .filter(|&i| vi.str(i, ct) == trace)
        .collect();
    let meas: Vec<f64> = idx
        .iter()
        .map(|&i| vi.num(i, cfy).unwrap() / vi.num(i, cms).unwrap())
        .collect();
    rms(&idx.iter().map(|&i| pred[i]).collect::<Vec<_>>(), &meas)
}

fn vii_a_rms(law: Option<[thermal::Law; 2]>) -> f64 {
    use traction_reproduce::data::{APPENDIX_VII_A, DataTable};
    let a = DataTable::parse("appendix_vii_a_side_slip.csv", APPENDIX_VII_A).unwrap();
    let ma: Vec<f64> = (0..a.rows.len())
        .map(|i| a.num(i, a.col("J5_act").unwrap()).unwrap())
        .collect();
    rms(&thermal::appendix_vii_a(law).unwrap(), &ma)
}

/// Santotrac 50's T* = 480 K is the identified minimum on trace 79072704
/// (RMS 0.0443; 0.0510 at 440 K, 0.0496 at 520 K). The first-order law
/// (T* = ∞) cannot serve this trace and Appendix VII-A together: β_μ =
/// 0.0008 1/K keeps VII-A within 10 % of the isothermal fit (0.0131 ≤
/// 0.0138) but leaves the trace at 0.194 (goal 0.06);
/// β_μ = 0.0025 1/K fits the trace (0.044) and takes VII-A to 0.033
/// (docs/decisions/0023).
#[test]
fn santotrac_rise_scale_is_the_identified_minimum_and_the_first_order_law_is_not_enough() {
    let law = |b: f64, t: f64| {
        let l = thermal::Law {
            mu_coefficient: b,
            mu_rise_scale: t,
            slope_coefficient: 0.0,
            film: traction_contact::Film::FromFluid,
        };
        // TDF-88 at its own identified value.
        let tdf = thermal::Law {
            mu_coefficient: 0.0,
            mu_rise_scale: 575.0,
            slope_coefficient: 0.0,
            film: traction_contact::Film::FromFluid,
        };
        Some([l, tdf])
    };
    let at = |t: f64| vi_trace_rms(law(0.0, t), "79072704");
    let (lo, best, hi) = (at(440.0), at(480.0), at(520.0));
    println!("79072704 at T* = 440, 480, 520 K: {lo:.4} {best:.4} {hi:.4}");
    assert!(best < lo && best < hi, "{lo} {best} {hi}");
    for (b, trace_above, vii_a_within) in [(0.0008, true, true), (0.0025, false, false)] {
        let l = law(b, f64::INFINITY);
        let (t, a) = (vi_trace_rms(l, "79072704"), vii_a_rms(l));
        println!("first-order β_μ = {b}: 79072704 {t:.4}, VII-A {a:.4}");
        assert_eq!(t > 0.06, trace_above, "{b}: {t}");
        assert_eq!(a <= 0.0138, vii_a_within, "{b}: {a}");
    }
}

/// The data do not support a temperature coefficient of the slope m (β_m,
/// docs/decisions/0025): on both 80 m/s spin traces, the only data heated
/// well beyond their reference peak at small slip, any β_m > 0 makes the
/// prediction worse (β_m = 0.0005 / 0.001 / 0.002 1/K: 79072704 0.056 /
/// 0.069 / 0.097, 79100403 0.127 / 0.129 / 0.133, against 0.044 and 0.126
/// with β_m = 0); a negative one would be unphysical (a fluid's shear
/// modulus falls with temperature).
#[test]
fn a_temperature_coefficient_of_the_slope_makes_the_spin_traces_worse() {
    let law = |beta_m: f64| {
        Some([
            thermal::Law {
                mu_coefficient: 0.0,
                mu_rise_scale: 480.0,
                slope_coefficient: beta_m,
                film: traction_contact::Film::FromFluid,
            },
            thermal::Law {
                mu_coefficient: 0.0,
                mu_rise_scale: 575.0,
                slope_coefficient: beta_m,
                film: traction_contact::Film::FromFluid,
            },
        ])
    };
    let mut last = [0.0; 2];
    for (i, b) in [0.0, 0.0005, 0.001, 0.002].into_iter().enumerate() {
        let now = [
            vi_trace_rms(law(b), "79072704"),
            vi_trace_rms(law(b), "79100403"),
        ];
        println!("β_m = {b}: 79072704 {:.4}, 79100403 {:.4}", now[0], now[1]);
        if i > 0 {
            assert!(
                now[0] > last[0] && now[1] > last[1],
                "{b}: {now:?} {last:?}"
            );
        }
        last = now;
    }
    // β_m = 0.002 1/K (a 40 % softer film at 250 K) leaves 79072704 at
    // more than twice its RMS with β_m = 0.
    assert!(last[0] > 0.09, "{last:?}");
}

/// Inputs of the Appendix VI predictions against the report
/// (docs/decisions/0024). The upper disc rolls free in the side-slip tests
/// (no brake: section 4-2), so the side force is measured at Fx = 0; the
/// prediction imposes ΔU = 0, which is that state because the longitudinal
/// slip −ωy is odd in y and the lateral ΔV + ωx even: Fx vanishes by symmetry
/// (1e-9 of Fy: the strip integration is symmetric in y, so this is exact up
/// to rounding). The spin group of each rig (eq. 6 with Table 2-4's tilt and
/// offset, Hertz on Table 2-1's discs at the printed P0) against the printed
/// Z (App. VI; 79072601: Table 2-5's C''(k = 5, 15°)·1.22 GPa, its discs per
/// docs/decisions/0022): within 2.5 % — the printed 0.021 has two digits
/// (±2.4 %), our Hertz C is 0.8 % above Table 2-2's and k = 5.04.
#[test]
fn appendix_vi_inputs_free_rolling_and_spin() {
    // trace, printed m, μ, U (m/s), printed (or Table 2-5) Z
    for (trace, m, mu, u, z_printed) in [
        ("79072704", 35.0, 0.075, 80.0, 0.021),
        ("79100403", 33.3, 0.051, 80.0, 0.0071),
        ("79100403-U20", 46.9, 0.081, 20.0, 0.0071),
        ("79072601", 53.5, 0.083, 20.0, 7.06e-3 * 1.22),
    ] {
        for (positive, dv_u) in [(true, 0.0), (true, 0.005), (false, -0.005)] {
            let (e, z) = thermal::appendix_vi_state(trace, positive, m, mu, u, dv_u, None).unwrap();
            assert!(
                e.traction_x.abs() <= 1e-9 * e.traction_y.abs(),
                "{trace}: Fx {} Fy {}",
                e.traction_x,
                e.traction_y
            );
            assert!((z / z_printed - 1.0).abs() < 0.025, "{trace}: Z {z}");
        }
    }
}

/// TDF-88 keeps the second-order law although the first-order one fits its
/// identification data better (β_μ = 0.0008 1/K, T* = ∞: joint RMS 0.0766
/// against 0.0852 on trace 79100403 and its VII-E peaks; docs/decisions/
/// 0026): under a constant coefficient the limiting stress survives any
/// temperature, so states of gross sliding have no fixed point below the
/// 2000 K runaway limit (61 of 300 random states from 20 to 120 m/s, up to
/// 50 % slip; 1 of 300 with T* = 575 K, 1 of 300 for Santotrac 50's
/// 480 K). Here three such states: the identified law converges, the
/// first-order one runs away.
#[test]
fn the_second_order_law_bounds_the_rise_where_the_first_order_law_runs_away() {
    use traction_contact::{
        Body, ContactError, EnvelopeRule, Fluid, OperatingState, Options, Thermal, TractionContact,
    };
    // (ry1, load N, U m/s, ΔU m/s, ω rad/s, θ °C, m, μ) on the low-speed
    // machine's discs of Table 2-1 (k = 1, 2, 5).
    let states = [
        (12.5e-3, 10000.0, 50.0, 25.0, 250.0, 70.0, 34.04, 0.080),
        (36.5e-3, 500.0, 80.0, 40.0, 400.0, 70.0, 42.37, 0.080),
        (150.4e-3, 2000.0, 120.0, 60.0, 2400.0, 30.0, 20.52, 0.053),
    ];
    let first_order = Thermal {
        mu_coefficient: Some(0.0008),
        mu_rise_scale: Some(f64::INFINITY),
        ..Thermal::default()
    };
    for (ry, load, u, du, w, theta, m, mu) in states {
        let eval = |th: Thermal| {
            let fluid = Fluid::tdf_88(EnvelopeRule::Clamp)
                .and_then(|f| f.with_inlet_values(m, mu))
                .unwrap();
            let opts = Options {
                thermal: Some(th),
                ..Options::default()
            };
            let c = TractionContact::new(
                &Body::steel(25e-3, ry),
                &Body::steel(25e-3, f64::INFINITY),
                fluid,
                opts,
            )
            .unwrap();
            let s = OperatingState::builder()
                .load(load)
                .rolling_speed(u)
                .slip(du)
                .spin(w)
                .inlet_temperature_celsius(theta)
                .build()
                .unwrap();
            c.evaluate(&s)
        };
        let identified = eval(Thermal::default()).unwrap();
        println!(
            "ry {ry}: rise {:.0} K with T* = 575 K",
            identified.temperature_rise
        );
        assert!(identified.temperature_rise < 1500.0);
        assert!(matches!(
            eval(first_order),
            Err(ContactError::Thermal { .. })
        ));
    }
}

/// Sum of squared deviations of TDF-88's identification data for a law:
/// trace 79100403 (80 m/s, 18 points, J5 in μ_s) and its Appendix VII-E
/// peaks (21 without, 32 with spin, in the zero-side-slip μ₀), the
/// objective on which its T* is identified (docs/decisions/0023).
fn tdf_joint_sum_of_squares(law: Option<[thermal::Law; 2]>) -> f64 {
    let trace = vi_trace_rms(law, "79100403");
    let peaks = thermal::appendix_vii_e(law).unwrap();
    let vii_e: f64 = peaks
        .iter()
        .filter(|p| p.point.fluid.contains("TDF") && !p.is_reference)
        .map(|p| ((p.thermal - p.point.mu) / p.reference_mu).powi(2))
        .sum();
    18.0 * trace * trace + vii_e
}

/// Inlet shear heating of the film (Gupta et al. 1992's reduction factor,
/// `Film::FromFluidInletHeated`; docs/decisions/0027), measured and not
/// adopted. It thins the 80 m/s films far more than the 20 m/s ones
/// (φ_T = 0.19 on 79072704 at 50 °C, 0.29 on 79100403 at 73 °C, 0.70 at
/// 20 m/s, 70 °C), so both T* fall when re-identified by the same
/// procedure: Santotrac 50 150 K on 79072704 (RMS 0.0471 / 0.0444 /
/// 0.0495 at 140 / 150 / 160 K: as good as 480 K without it), TDF-88
/// 235 K jointly on 79100403 and its VII-E peaks (Σr² 0.3085 / 0.2959 /
/// 0.3216 at 200 / 235 / 300 K, against 0.515 at 575 K without it).
/// TDF-88's data fit better (79100403 0.126 → 0.104), but the smaller
/// Santotrac 50 T* over-heats its 20 m/s traces: VII-A 0.0221, beyond the
/// goal 0.0138 (1.1 × isothermal), and App. VI (0.0969) stays above its
/// goal 0.091. Margins: the grid's minima are asserted as minima; the goals
/// are missed by 60 % (VII-A) and 6 % (App. VI), beyond the rheology's
/// accuracy (1e-4 in J).
#[test]
fn inlet_shear_heating_re_identified_misses_the_goals() {
    use traction_contact::Film;
    let law = |s: f64, t: f64| {
        let l = |x: f64| thermal::Law {
            mu_coefficient: 0.0,
            mu_rise_scale: x,
            slope_coefficient: 0.0,
            film: Film::FromFluidInletHeated,
        };
        Some([l(s), l(t)])
    };
    let at = |t: f64| vi_trace_rms(law(t, 235.0), "79072704");
    let (lo, best, hi) = (at(140.0), at(150.0), at(160.0));
    println!("inlet heating, 79072704 at T* = 140, 150, 160 K: {lo:.4} {best:.4} {hi:.4}");
    assert!(best < lo && best < hi && best < 0.06, "{lo} {best} {hi}");
    let joint = |t: f64| tdf_joint_sum_of_squares(law(150.0, t));
    let (lo, best, hi) = (joint(200.0), joint(235.0), joint(300.0));
    println!("inlet heating, TDF-88 joint Σr² at T* = 200, 235, 300 K: {lo:.4} {best:.4} {hi:.4}");
    assert!(best < lo && best < hi, "{lo} {best} {hi}");
    // Without inlet heating the same objective is 0.515 at 575 K.
    let plain = tdf_joint_sum_of_squares(None);
    assert!(best < 0.7 * plain, "{best} {plain}");
    let identified = law(150.0, 235.0);
    let (a, tdf80) = (vii_a_rms(identified), vi_trace_rms(identified, "79100403"));
    println!("inlet heating: VII-A {a:.4}, 79100403 {tdf80:.4}");
    assert!(a > 0.0138 && tdf80 < 0.11, "{a} {tdf80}");
    use traction_reproduce::data::{APPENDIX_VI, DataTable};
    let vi = DataTable::parse("appendix_vi_spin_traces.csv", APPENDIX_VI).unwrap();
    let (cfy, cms) = (vi.col("FyFz_exp").unwrap(), vi.col("mu_spin").unwrap());
    let meas: Vec<f64> = (0..vi.rows.len())
        .map(|i| vi.num(i, cfy).unwrap() / vi.num(i, cms).unwrap())
        .collect();
    let all = rms(&thermal::appendix_vi(identified).unwrap(), &meas);
    println!("inlet heating: App. VI {all:.4}");
    assert!(all > 0.091 && all < 0.0994, "{all}");
}
