//! Golden tests: the correlations of Appendix III-A..III-E refitted from the
//! curated data and compared with the report's printed coefficients, means,
//! per-point estimates and error statistics; the III-F refit (printed values
//! held out) and the leave-one-out comparison of the 1/θ' and linear-θ' forms.
//!
//! Run with `--nocapture` to see the comparison tables.
#![allow(clippy::unwrap_used)] // functions outside #[test] fns unwrap like the tests do

use traction_fluids::{FluidName, Quantity, data_set, listing, printed_result};
use traction_regression::{
    Fit, Model, TemperatureForm, TermSet, Variables, fit, leave_one_out, percent_error,
};
use traction_reproduce::tables::appendix_iii::{ERR_MEAN_TOL, ERR_STD_TOL};
use traction_tests::rel_diff;

struct Case {
    appendix: &'static str,
    fluid: FluidName,
    q: Quantity,
}

const CASES: [Case; 5] = [
    Case {
        appendix: "III-A",
        fluid: FluidName::Santotrac50,
        q: Quantity::Slope,
    },
    Case {
        appendix: "III-B",
        fluid: FluidName::Tdf88,
        q: Quantity::Slope,
    },
    Case {
        appendix: "III-C",
        fluid: FluidName::Santotrac50,
        q: Quantity::Mu,
    },
    Case {
        appendix: "III-D",
        fluid: FluidName::Tdf88,
        q: Quantity::Mu,
    },
    Case {
        appendix: "III-E",
        fluid: FluidName::Santotrac50,
        q: Quantity::SpinMu,
    },
];

fn model(q: Quantity) -> Model {
    if q == Quantity::SpinMu {
        Model::EQ15
    } else {
        Model::EQ14
    }
}

/// Refit with the printed means (to compare like with like).
fn refit_printed_means(
    c: &Case,
) -> (
    Fit,
    traction_fluids::PrintedResult,
    Vec<Variables>,
    Vec<f64>,
) {
    let pr = printed_result(c.appendix).unwrap();
    let (x, y) = data_set(c.fluid, c.q).unwrap();
    let f = fit(model(c.q), &x, &y, Some(pr.means)).unwrap();
    (f, pr, x, y)
}

#[test]
fn data_point_counts_match_appendix_iii_index() {
    // Appendix III index: 73, 105, 53, 94, 193, 152 data points.
    for (c, n) in CASES.iter().zip([73, 105, 53, 94, 193]) {
        let (x, _) = data_set(c.fluid, c.q).unwrap();
        assert_eq!(x.len(), n, "{}", c.appendix);
        assert_eq!(printed_result(c.appendix).unwrap().n, n);
        assert_eq!(listing(c.appendix).unwrap().len(), n);
    }
    let (x, _) = data_set(FluidName::Tdf88, Quantity::SpinMu).unwrap();
    assert_eq!(x.len(), 152);
}

#[test]
fn means_of_the_data_match_the_printed_means() {
    for c in &CASES {
        let pr = printed_result(c.appendix).unwrap();
        let (x, _) = data_set(c.fluid, c.q).unwrap();
        let m = Variables::mean_of(&x).unwrap();
        println!(
            "{}: data means U {:.3} P0 {:.4} θ {:.3} k {:.3} Z {:.6} | printed {:.3} {:.3} {:.3} {:.3} {:.6}",
            c.appendix,
            m.speed,
            m.p0_gpa,
            m.theta_celsius,
            m.k,
            m.z,
            pr.means.speed,
            pr.means.p0_gpa,
            pr.means.theta_celsius,
            pr.means.k,
            pr.means.z
        );
        // Printed to 3 decimals: half a unit of the last digit, 0.0005.
        let half = 0.0005 + 1e-9;
        assert!(
            (m.p0_gpa - pr.means.p0_gpa).abs() <= half,
            "{} P0",
            c.appendix
        );
        assert!(
            (m.theta_celsius - pr.means.theta_celsius).abs() <= half,
            "{} θ",
            c.appendix
        );
        assert!((m.k - pr.means.k).abs() <= half, "{} k", c.appendix);
        if c.appendix == "III-E" {
            // Known difference, unresolved: the curated speeds give 45.933 m/s,
            // the printed mean is 45.953 (a total of 3.9 m/s over 193 points;
            // every SPEED* of the III-E listing agrees with the curated speed to
            // its 2 printed decimals, so no single speed can be corrected).
            assert!((m.speed - 45.933).abs() < 0.0005);
            assert!((m.speed - pr.means.speed).abs() < 0.021);
            // Z̄ from the III-E spin factors: 0.0057800 vs printed 0.005786 (0.1 %,
            // the C'' at k = 5 are only known to ±0.1 % from the 2-decimal SPIN*).
            assert!(rel_diff(m.z, pr.means.z) < 0.002);
        } else {
            assert!((m.speed - pr.means.speed).abs() <= half, "{} U", c.appendix);
        }
    }
}

#[test]
fn error_statistics_reproduce_the_printed_ones() {
    for c in &CASES {
        let (f, pr, _, _) = refit_printed_means(c);
        println!(
            "{}: err mean {:.4} (printed {}) std {:.4} (printed {}) cond {:.3e}",
            c.appendix, f.stats.mean, pr.err_mean, f.stats.std_dev, pr.err_std, f.condition_number
        );
        // ERR_MEAN_TOL, ERR_STD_TOL: justified in their docs; III-A and III-B
        // agree to the printed digits (−0.5283/−0.5285, 10.7424/10.742,
        // −0.7385/−0.738, 13.0742/13.074).
        assert!(
            (f.stats.mean - pr.err_mean).abs() < ERR_MEAN_TOL,
            "{} mean",
            c.appendix
        );
        assert!(
            rel_diff(f.stats.std_dev, pr.err_std) < ERR_STD_TOL,
            "{} std",
            c.appendix
        );
    }
}

#[test]
fn coefficients_reproduce_the_printed_ones() {
    // Maximum relative difference over C1..Cn allowed per appendix, with the
    // coefficients that exceed 1 % named. Justification in each line.
    for c in &CASES {
        let (f, pr, _, _) = refit_printed_means(c);
        let d: Vec<f64> = f
            .correlation
            .coefficients()
            .iter()
            .zip(&pr.coefficients)
            .map(|(a, b)| rel_diff(*a, *b))
            .collect();
        let (imax, dmax) =
            d.iter().enumerate().fold(
                (0, 0.0_f64),
                |(i, m), (j, v)| if *v > m { (j, *v) } else { (i, m) },
            );
        let within_3sd = d.iter().filter(|v| **v <= 0.005).count();
        println!(
            "{}: max rel diff {:.4} at C{}; {} of {} within 0.5 % (3 printed digits)",
            c.appendix,
            dmax,
            imax + 1,
            within_3sd,
            d.len()
        );
        for (j, (a, b)) in f
            .correlation
            .coefficients()
            .iter()
            .zip(&pr.coefficients)
            .enumerate()
        {
            println!(
                "   C{:<2} refit {:>12.4e} printed {:>10.3e} rel {:.4}",
                j + 1,
                a,
                b,
                d[j]
            );
        }
        match c.appendix {
            // III-A, III-B, III-C: condition numbers 1e3..1e4; the refit agrees to
            // a few percent in every coefficient (the remaining difference is the
            // original's arithmetic: same data, same estimates and statistics).
            "III-A" => assert!(dmax < 0.04, "{dmax}"),
            "III-B" => assert!(dmax < 0.04, "{dmax}"),
            "III-C" => assert!(dmax < 0.06, "{dmax}"),
            // III-D: C1-C6, C8-C13 within 9 %; C7 (15 %), C14 (76 %), C15 (570 %)
            // and C16 (14 %) are the P'/θ' and U'·/θ' interaction terms whose
            // columns are dominated by four tests at θ = 47-50 °C, next to
            // θ̄ = 49.489 °C (|1/θ'| up to 97): a 0.1 % change in those points moves
            // them by their own size. C14 and C15 are the two smallest
            // coefficients (|C| < 4 % of C1). Estimates and error statistics
            // still agree (see the other tests).
            "III-D" => {
                for (j, v) in d.iter().enumerate() {
                    if ![6, 13, 14, 15].contains(&j) {
                        assert!(*v < 0.09, "III-D C{} {v}", j + 1);
                    }
                }
                assert!(d[6] < 0.2 && d[15] < 0.2);
            }
            // III-E: the 193×32 design has condition number ~1e4-1e5; coefficients of
            // the high-order U' terms are poorly determined and the printed set
            // is not the least-squares optimum for these data (its RSS is 9.7 %
            // higher than the refit's, and it reproduces the listing's own
            // estimates worse, see `iii_e_estimates_match_the_listing`). Only C1,
            // the value at the means, is held to 1 %.
            "III-E" => assert!(d[0] < 0.01, "{}", d[0]),
            _ => unreachable!(),
        }
    }
}

#[test]
fn estimates_match_the_printed_listings() {
    for c in &CASES {
        let (f, _, _, _) = refit_printed_means(c);
        let l = listing(c.appendix).unwrap();
        // The listing prints estimates to 3 decimals (μ) or 3 decimals of a
        // slope ~40; OCR damages some (e.g. III-D prints 0.033 for 0.083).
        // Tolerance: μ estimates are printed to 0.001 (half unit 0.0005) plus
        // 0.0002 for the original's arithmetic; slope estimates (~40) are
        // printed to 0.001 but differ from the refit by ~0.02 rms, up to 0.07 (the
        // original's arithmetic, < 2e-3 relative), so 0.1 (0.25 %).
        let tol = if c.q == Quantity::Slope { 0.1 } else { 0.0007 };
        let mut bad = Vec::new();
        let mut sq = 0.0;
        for (r, e) in l.iter().zip(&f.estimates) {
            let d = e - r.estimate;
            if d.abs() > tol {
                bad.push((r.row, r.estimate, *e));
            } else {
                sq += d * d;
            }
        }
        let rms = (sq / (l.len() - bad.len()) as f64).sqrt();
        println!(
            "{}: {} of {} estimates differ (OCR or original arithmetic): {:?}; rms of the rest {:.5}",
            c.appendix,
            bad.len(),
            l.len(),
            bad,
            rms
        );
        // Allowed exceptions per listing (counted from the listing, each an OCR
        // digit error visible as a mismatch with target and percent error, or in
        // III-E the original's less accurate solution at ill-determined points).
        let allowed = match c.appendix {
            "III-A" => 3,
            "III-B" => 1,
            "III-C" => 3,
            "III-D" => 21,
            "III-E" => 12,
            _ => 0,
        };
        assert!(bad.len() <= allowed, "{}: {}", c.appendix, bad.len());
    }
}

#[test]
fn percent_error_definition_reproduces_printed_rows() {
    // III-E prints percent errors to 3 decimals: recompute them from the
    // printed target and our estimate; the median |difference| must be small
    // (< 0.1 %-point) with the report's definition, and larger with the naive
    // alternatives (checked to show the test can fail).
    let c = &CASES[4];
    let (f, _, _, y) = refit_printed_means(c);
    let l = listing("III-E").unwrap();
    let med = |g: &dyn Fn(f64, f64) -> f64| {
        let mut v: Vec<f64> = y
            .iter()
            .zip(&f.estimates)
            .zip(&l)
            .map(|((a, e), r)| (g(*a, *e) - r.percent_error).abs())
            .collect();
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let ours = med(&|a, e| percent_error(a, e));
    let rel_a = med(&|a, e| 100.0 * (a - e) / a);
    let rel_e = med(&|a, e| 100.0 * (a - e) / e);
    println!(
        "median |Δ percent error|: report {ours:.4}, rel. actual {rel_a:.4}, rel. estimate {rel_e:.4}"
    );
    assert!(ours < 0.1);
    assert!(ours < rel_a && ours < rel_e);
}

/// Median over the coefficients of |c / printed − 1|.
fn median_rel_diff(c: &[f64], printed: &[f64]) -> f64 {
    let mut d: Vec<f64> = c
        .iter()
        .zip(printed)
        .map(|(a, p)| rel_diff(*a, *p))
        .collect();
    d.sort_by(f64::total_cmp);
    d[d.len() / 2]
}

#[test]
fn iii_e_printed_coefficients_reproduce_the_reports_estimates_not_the_least_squares_fit() {
    // Why the III-E coefficients are not reproduced: fitting the eq. 15 design
    // (curated inputs, printed means) to the report's OWN per-point estimates
    // (listing EST column) gives back the printed coefficients, so the printed
    // set, its transcription, the term order of eq. 15 and the curated inputs
    // are consistent with each other; the least-squares fit to the listed μ is
    // a different set with the same estimates to ~0.0007 (cond(A) ≈ 1e4: the
    // data do not determine the high-order terms). The report's program did
    // not return the least-squares optimum of its listed data (its RSS is
    // larger, 8.8e-3 vs 8.03e-3); single precision does not explain it (an f32
    // normal-equation solve, checked offline, gives the f64 optimum). Measured:
    // median |Δc/c| 0.05 (fit to EST) vs 0.26 (fit to μ).
    let c = &CASES[4];
    let (f, pr, x, _) = refit_printed_means(c);
    let est: Vec<f64> = listing(c.appendix)
        .unwrap()
        .iter()
        .map(|r| r.estimate)
        .collect();
    let g = fit(model(c.q), &x, &est, Some(pr.means)).unwrap();
    let to_est = median_rel_diff(g.correlation.coefficients(), &pr.coefficients);
    let to_mu = median_rel_diff(f.correlation.coefficients(), &pr.coefficients);
    println!(
        "III-E median |dc/c| vs printed: fit to printed EST {to_est:.3}, fit to mu {to_mu:.3}"
    );
    // Tolerance: the EST column is printed to 0.001 (≈1 % of μ) and 12 of its
    // rows carry OCR digit errors; at cond(A) ≈ 1e4 that moves the weakly
    // determined coefficients by tens of percent, the median by ~5 %: 0.10.
    assert!(to_est < 0.10, "{to_est}");
    // And the least-squares set is clearly another one (measured 0.26).
    assert!(to_mu > 2.0 * to_est, "{to_mu} vs {to_est}");
}

#[test]
fn iii_f_refit_and_leave_one_out() {
    // III-F's printed results are held out: this test records the refit and
    // checks only properties that do not depend on them.
    let (x, y) = data_set(FluidName::Tdf88, Quantity::SpinMu).unwrap();
    let f = fit(Model::EQ15, &x, &y, None).unwrap();
    let m = f.correlation.means();
    println!(
        "III-F refit: n {} means U {:.3} P0 {:.4} θ {:.3} k {:.4} Z {:.6}; err mean {:.4} std {:.4}; cond {:.3e}",
        x.len(),
        m.speed,
        m.p0_gpa,
        m.theta_celsius,
        m.k,
        m.z,
        f.stats.mean,
        f.stats.std_dev,
        f.condition_number
    );
    for (j, c) in f.correlation.coefficients().iter().enumerate() {
        println!("   C{} {:.4e}", j + 1, c);
    }
    assert_eq!(x.len(), 152);
    // A least-squares fit with a constant term has zero mean residual; the
    // percent-error mean is close to zero (it is not exactly zero because the
    // percent error is non-linear).
    let mean_resid: f64 =
        y.iter().zip(&f.estimates).map(|(a, e)| a - e).sum::<f64>() / y.len() as f64;
    assert!(mean_resid.abs() < 1e-12);
    assert!(f.stats.std_dev < 15.0);
}

#[test]
fn leave_one_out_inverse_vs_linear_temperature() {
    // Side-by-side cross-validation of the report's 1/θ' form and the linear
    // θ' alternative on the same six data sets. Recorded, and the linear form
    // must not be catastrophically worse (it is the recommended well-posed form).
    let sets = [
        ("III-A", FluidName::Santotrac50, Quantity::Slope),
        ("III-B", FluidName::Tdf88, Quantity::Slope),
        ("III-C", FluidName::Santotrac50, Quantity::Mu),
        ("III-D", FluidName::Tdf88, Quantity::Mu),
        ("III-E", FluidName::Santotrac50, Quantity::SpinMu),
        ("III-F", FluidName::Tdf88, Quantity::SpinMu),
    ];
    for (name, fl, q) in sets {
        let (x, y) = data_set(fl, q).unwrap();
        let terms = if q == Quantity::SpinMu {
            TermSet::ThirtyTwo
        } else {
            TermSet::Sixteen
        };
        let inv = Model {
            terms,
            temperature: TemperatureForm::Inverse,
        };
        let lin = Model {
            terms,
            temperature: TemperatureForm::Linear,
        };
        let fi = fit(inv, &x, &y, None).unwrap();
        let fl_ = fit(lin, &x, &y, None).unwrap();
        let li = leave_one_out(inv, &x, &y).unwrap();
        let ll = leave_one_out(lin, &x, &y).unwrap();
        println!(
            "{name}: in-sample std 1/θ' {:.3} θ' {:.3} | LOO rms % 1/θ' {:.3} (max {:.1}, non-positive {}) θ' {:.3} (max {:.1}, non-positive {}) | cond 1/θ' {:.2e} θ' {:.2e}",
            fi.stats.std_dev,
            fl_.stats.std_dev,
            li.rms_percent,
            li.max_abs_percent,
            li.non_positive,
            ll.rms_percent,
            ll.max_abs_percent,
            ll.non_positive,
            fi.condition_number,
            fl_.condition_number
        );
        assert!(ll.rms_percent.is_finite() && li.rms_percent.is_finite());
        assert!(ll.rms_percent < 2.0 * li.rms_percent.max(1.0), "{name}");
    }
}

#[test]
fn iii_e_spin_factors_from_the_listing_beat_table_2_5() {
    // Evidence for the C'' choice at k = 5, 15° and 30°: with Table 2-5's
    // printed factors (7.06e-3, 14.6e-3) the III-E refit reproduces the
    // listing's estimates worse than with the factors read from its SPIN*
    // column (7.556e-3, 14.50e-3).
    use traction_fluids::{spin_factor, tests};
    let pr = printed_result("III-E").unwrap();
    let l = listing("III-E").unwrap();
    let recs: Vec<_> = tests(FluidName::Santotrac50)
        .unwrap()
        .iter()
        .filter(|t| t.in_spin_fit)
        .collect();
    let y: Vec<f64> = recs.iter().map(|t| t.mu).collect();
    let rms_vs_listing = |table: bool| {
        let x: Vec<Variables> = recs
            .iter()
            .map(|t| {
                let mut v = t.variables().unwrap();
                if t.spin_deg > 0.0 && table {
                    v.z = spin_factor(t.k, t.spin_deg).unwrap().unwrap().c_table_2_5 * t.p0_gpa;
                }
                v
            })
            .collect();
        let f = fit(Model::EQ15, &x, &y, Some(pr.means)).unwrap();
        let d: Vec<f64> = f
            .estimates
            .iter()
            .zip(&l)
            .map(|(e, r)| e - r.estimate)
            .collect();
        let mut s: Vec<f64> = d.iter().map(|v| v.abs()).collect();
        s.sort_by(f64::total_cmp);
        (s[s.len() * 9 / 10], f.stats.std_dev)
    };
    let (p90_used, sd_used) = rms_vs_listing(false);
    let (p90_table, sd_table) = rms_vs_listing(true);
    println!(
        "III-E |est − listing| 90th percentile: C'' from SPIN* {p90_used:.5} (std {sd_used:.3}), Table 2-5 {p90_table:.5} (std {sd_table:.3})"
    );
    assert!(p90_used < p90_table);
    assert!((sd_used - 9.870).abs() < (sd_table - 9.870).abs());
}
