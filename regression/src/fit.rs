//! Least-squares fitting (faer QR), evaluation with the θ' guard, the report's
//! percent error and leave-one-out cross-validation.

use faer::Mat;
use faer::linalg::solvers::SolveLstsq;

use crate::{Model, Normalised, RegressionError, TemperatureForm, Variables};

/// Largest condition number accepted before a fit is declared rank deficient.
pub const MAX_CONDITION: f64 = 1e12;

/// The report's percent error of an estimate e against the actual value a
/// (Appendix III, "PERCENT ERROR" column):
/// `50·(a/e − e/a) = ½·[(a − e)/a + (a − e)/e]·100`,
/// the average of the errors relative to the actual and to the estimated
/// value. Positive when the correlation under-predicts.
///
/// Identified from the printed rows: e.g. III-E point 66 (a = 0.065, our
/// estimate 0.04643) gives 34.28 against the printed 34.291, while the error
/// relative to a gives 28.6 and relative to e 40.0; the printed means of
/// III-A/III-B (−0.5285 %, −0.738 %) are reproduced to the printed digits
/// only with this definition.
pub fn percent_error(actual: f64, estimate: f64) -> f64 {
    50.0 * (actual / estimate - estimate / actual)
}

/// Mean and standard deviation of a set of percent errors, as the report
/// prints them ("THE MEAN OF THE ERROR", "THE STANDARD DEVIATION OF THE
/// ERROR"): the arithmetic mean and the *sample* standard deviation (divisor
/// n − 1), which reproduces III-A's 10.742 (population: 10.669).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ErrorStats {
    /// Arithmetic mean (%).
    pub mean: f64,
    /// Sample standard deviation (%), divisor n − 1 (0 for n = 1).
    pub std_dev: f64,
}

impl ErrorStats {
    /// Statistics of a slice of percent errors (empty slice: zeros).
    pub fn of(errors: &[f64]) -> ErrorStats {
        let n = errors.len();
        if n == 0 {
            return ErrorStats {
                mean: 0.0,
                std_dev: 0.0,
            };
        }
        let mean = errors.iter().sum::<f64>() / n as f64;
        let std_dev = if n > 1 {
            (errors.iter().map(|e| (e - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt()
        } else {
            0.0
        };
        ErrorStats { mean, std_dev }
    }
}

/// A correlation ready to evaluate: form, means and coefficients, plus the
/// θ' guard.
///
/// The guard: the inverse form (eq. 14/15) is only evaluated where
/// |1/θ'| ≤ `inv_theta_limit`, the largest |1/θ'| of the data the
/// coefficients were fitted to. Inside the band
/// |θ − θ̄| < θ̄ / `inv_theta_limit` the result would be an unconstrained
/// extrapolation in 1/θ' that grows without bound as θ → θ̄, so
/// [`Correlation::evaluate`] returns [`RegressionError::NearMeanTemperature`].
/// The linear form has no guard.
#[derive(Debug, Clone, PartialEq)]
pub struct Correlation {
    model: Model,
    means: Variables,
    coefficients: Vec<f64>,
    inv_theta_limit: f64,
}

impl Correlation {
    /// A correlation from given coefficients (e.g. the report's printed ones)
    /// and means. `inv_theta_limit` is the largest |1/θ'| to accept (use
    /// [`Correlation::inv_theta_limit_of`] on the data behind the coefficients).
    pub fn new(
        model: Model,
        means: Variables,
        coefficients: Vec<f64>,
        inv_theta_limit: f64,
    ) -> Result<Correlation, RegressionError> {
        if coefficients.len() != model.len() {
            return Err(RegressionError::CoefficientCount {
                expected: model.len(),
                got: coefficients.len(),
            });
        }
        if let Some(&value) = coefficients.iter().find(|c| !c.is_finite()) {
            return Err(RegressionError::NotFinite {
                quantity: "correlation coefficient",
                value,
            });
        }
        check_means(&model, &means)?;
        if inv_theta_limit.is_nan() || inv_theta_limit <= 0.0 {
            return Err(RegressionError::OutOfRange {
                quantity: "|1/θ'| limit",
                value: inv_theta_limit,
                range: "> 0 (may be +inf to disable the guard)",
            });
        }
        Ok(Correlation {
            model,
            means,
            coefficients,
            inv_theta_limit,
        })
    }

    /// Largest |1/θ'| over a data set for the given mean temperature.
    pub fn inv_theta_limit_of(points: &[Variables], mean_theta_celsius: f64) -> f64 {
        points
            .iter()
            .map(|p| (mean_theta_celsius / (p.theta_celsius - mean_theta_celsius)).abs())
            .fold(0.0, f64::max)
    }

    /// The functional form.
    pub fn model(&self) -> Model {
        self.model
    }
    /// The means used in eq. 12.
    pub fn means(&self) -> Variables {
        self.means
    }
    /// Coefficients C1..Cn in the order of eq. 14/15.
    pub fn coefficients(&self) -> &[f64] {
        &self.coefficients
    }
    /// The accepted |1/θ'| limit of the guard.
    pub fn inv_theta_limit(&self) -> f64 {
        self.inv_theta_limit
    }

    /// Half-width (°C) of the guard band around θ̄ (0 for the linear form).
    pub fn guard_band_celsius(&self) -> f64 {
        match self.model.temperature {
            TemperatureForm::Inverse => (self.means.theta_celsius / self.inv_theta_limit).abs(),
            TemperatureForm::Linear => 0.0,
        }
    }

    /// Evaluates the correlation at a point, with input validation and the
    /// θ' guard.
    pub fn evaluate(&self, x: &Variables) -> Result<f64, RegressionError> {
        x.validate()?;
        let n = Normalised::new(x, &self.means);
        if self.model.temperature == TemperatureForm::Inverse {
            let inv = (1.0 / n.theta).abs();
            if inv.is_nan() || inv > self.inv_theta_limit {
                return Err(RegressionError::NearMeanTemperature {
                    theta_celsius: x.theta_celsius,
                    mean_celsius: self.means.theta_celsius,
                    band_celsius: self.guard_band_celsius(),
                    inv_theta: inv,
                    limit: self.inv_theta_limit,
                });
            }
        }
        Ok(self.raw(&n))
    }

    /// The bare sum Σ Cj·termj of normalised variables, without any check (may
    /// be ±inf or NaN at θ' = 0 for the inverse form).
    pub fn raw(&self, n: &Normalised) -> f64 {
        let mut row = [0.0; 32];
        self.model.fill_row(n, &mut row);
        row.iter().zip(&self.coefficients).map(|(r, c)| r * c).sum()
    }
}

fn check_means(model: &Model, means: &Variables) -> Result<(), RegressionError> {
    let positive: [(&'static str, f64); 3] = [
        ("mean speed Ū (m/s)", means.speed),
        ("mean pressure P̄0 (GPa)", means.p0_gpa),
        ("mean aspect ratio k̄", means.k),
    ];
    for (quantity, value) in positive {
        traction_range::Range::POSITIVE.check(quantity, value)?;
    }
    if !means.theta_celsius.is_finite() || means.theta_celsius == 0.0 {
        return Err(RegressionError::OutOfRange {
            quantity: "mean temperature θ̄ (°C)",
            value: means.theta_celsius,
            range: "finite and ≠ 0 °C (eq. 12 divides by it)",
        });
    }
    if model.len() == 32 && !(means.z > 0.0 && means.z.is_finite()) {
        return Err(RegressionError::OutOfRange {
            quantity: "mean spin parameter Z̄",
            value: means.z,
            range: "> 0 for the 32-term eq. 15 (the data must contain spin tests)",
        });
    }
    Ok(())
}

/// The result of a least-squares fit.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// The fitted correlation (means, coefficients, guard).
    pub correlation: Correlation,
    /// Estimates at the data points, in input order.
    pub estimates: Vec<f64>,
    /// The report's percent errors at the data points ([`percent_error`]).
    pub percent_errors: Vec<f64>,
    /// Mean and sample standard deviation of the percent errors.
    pub stats: ErrorStats,
    /// 2-norm condition number σmax/σmin of the design matrix.
    pub condition_number: f64,
    /// Residual sum of squares Σ(a − e)².
    pub residual_sum_of_squares: f64,
}

/// Least-squares fit of `model` to `targets` (slope m or traction coefficient
/// μ) at `points`, by Householder QR of the n × 16 or n × 32 design matrix
/// (faer). `means`: `None` uses the data's own means (eq. 12), `Some` uses
/// given means (e.g. the report's printed ones). For 16 terms Z is ignored.
pub fn fit(
    model: Model,
    points: &[Variables],
    targets: &[f64],
    means: Option<Variables>,
) -> Result<Fit, RegressionError> {
    let n = points.len();
    let p = model.len();
    if targets.len() != n {
        return Err(RegressionError::DataShape {
            what: "points and targets differ in length",
            detail: format!("{n} points, {} targets", targets.len()),
        });
    }
    if n <= p {
        return Err(RegressionError::DataShape {
            what: "too few data points",
            detail: format!("{n} points for {p} coefficients (need more than {p})"),
        });
    }
    for (i, x) in points.iter().enumerate() {
        x.validate()?;
        let t = targets[i];
        if !t.is_finite() || t <= 0.0 {
            return Err(RegressionError::OutOfRange {
                quantity: "fitted quantity (slope m or traction coefficient μ)",
                value: t,
                range: "finite and > 0",
            });
        }
    }
    let mut means = match means {
        Some(m) => m,
        None => Variables::mean_of(points)?,
    };
    if model.len() == 16 {
        means.z = 0.0;
    }
    check_means(&model, &means)?;
    if let Some(i) = points.iter().position(|x| {
        model.temperature == TemperatureForm::Inverse && x.theta_celsius == means.theta_celsius
    }) {
        return Err(RegressionError::DataAtMeanTemperature {
            index: i,
            theta_celsius: points[i].theta_celsius,
        });
    }

    let rows: Vec<Vec<f64>> = points
        .iter()
        .map(|x| model.row(&Normalised::new(x, &means)))
        .collect();
    let a = Mat::from_fn(n, p, |i, j| rows[i][j]);
    let sv = a.singular_values().map_err(|_| RegressionError::Svd)?;
    let smax = sv.first().copied().unwrap_or(0.0);
    let smin = sv.last().copied().unwrap_or(0.0);
    let condition_number = if smin > 0.0 {
        smax / smin
    } else {
        f64::INFINITY
    };
    if condition_number.is_nan() || condition_number > MAX_CONDITION {
        return Err(RegressionError::RankDeficient {
            terms: p,
            condition: condition_number,
        });
    }
    let mut rhs = Mat::from_fn(n, 1, |i, _| targets[i]);
    a.qr().solve_lstsq_in_place(rhs.as_mut());
    let coefficients: Vec<f64> = (0..p).map(|j| rhs[(j, 0)]).collect();

    let inv_theta_limit = match model.temperature {
        TemperatureForm::Inverse => Correlation::inv_theta_limit_of(points, means.theta_celsius),
        TemperatureForm::Linear => f64::INFINITY,
    };
    let correlation = Correlation::new(model, means, coefficients, inv_theta_limit)?;
    let estimates: Vec<f64> = rows
        .iter()
        .map(|r| {
            r.iter()
                .zip(correlation.coefficients())
                .map(|(x, c)| x * c)
                .sum()
        })
        .collect();
    let mut percent_errors = Vec::with_capacity(n);
    for (i, (&a, &e)) in targets.iter().zip(&estimates).enumerate() {
        if e.is_nan() || e <= 0.0 {
            return Err(RegressionError::NonPositiveEstimate {
                index: i,
                estimate: e,
            });
        }
        let pe = percent_error(a, e);
        if !pe.is_finite() {
            return Err(RegressionError::PercentErrorOverflow {
                index: i,
                actual: a,
                estimate: e,
            });
        }
        percent_errors.push(pe);
    }
    let residual_sum_of_squares = targets
        .iter()
        .zip(&estimates)
        .map(|(a, e)| (a - e).powi(2))
        .sum();
    Ok(Fit {
        correlation,
        stats: ErrorStats::of(&percent_errors),
        estimates,
        percent_errors,
        condition_number,
        residual_sum_of_squares,
    })
}

/// Summary of a leave-one-out cross-validation.
#[derive(Debug, Clone, PartialEq)]
pub struct LeaveOneOut {
    /// Held-out percent errors ([`percent_error`] of the prediction made
    /// without the point), in input order; `None` where the held-out
    /// prediction is not positive (percent error undefined).
    pub percent_errors: Vec<Option<f64>>,
    /// Root-mean-square of the defined held-out percent errors (%).
    pub rms_percent: f64,
    /// Largest |held-out percent error| (%).
    pub max_abs_percent: f64,
    /// Root-mean-square of the held-out residuals a − ê (units of the target).
    pub rms_residual: f64,
    /// Number of held-out predictions that were not positive (or whose
    /// percent error overflows); their `percent_errors` entry is `None`.
    pub non_positive: usize,
}

/// Leave-one-out cross-validation: for each point, refit on the others (with
/// the others' own means, as a user of the correlation would) and predict the
/// left-out point with the bare formula (no guard, so the inverse form's
/// blow-ups near θ̄ count against it).
pub fn leave_one_out(
    model: Model,
    points: &[Variables],
    targets: &[f64],
) -> Result<LeaveOneOut, RegressionError> {
    let n = points.len();
    let mut errs = Vec::with_capacity(n);
    let mut sq = 0.0;
    let mut sq_pct = 0.0;
    let mut n_pct = 0usize;
    let mut max_abs: f64 = 0.0;
    let mut non_positive = 0;
    let mut pts = Vec::with_capacity(n - 1);
    let mut tg = Vec::with_capacity(n - 1);
    for i in 0..n {
        pts.clear();
        tg.clear();
        for j in (0..n).filter(|&j| j != i) {
            pts.push(points[j]);
            tg.push(targets[j]);
        }
        let f = fit_lenient(model, &pts, &tg)?;
        let e = f.raw(&Normalised::new(&points[i], &f.means()));
        let a = targets[i];
        sq += (a - e).powi(2);
        let pe = percent_error(a, e);
        if e > 0.0 && e.is_finite() && pe.is_finite() {
            sq_pct += pe * pe;
            n_pct += 1;
            max_abs = max_abs.max(pe.abs());
            errs.push(Some(pe));
        } else {
            non_positive += 1;
            errs.push(None);
        }
    }
    Ok(LeaveOneOut {
        percent_errors: errs,
        rms_percent: if n_pct > 0 {
            (sq_pct / n_pct as f64).sqrt()
        } else {
            0.0
        },
        max_abs_percent: max_abs,
        rms_residual: (sq / n as f64).sqrt(),
        non_positive,
    })
}

/// A fit that tolerates non-positive estimates (used inside cross-validation,
/// where only the coefficients are needed).
fn fit_lenient(
    model: Model,
    points: &[Variables],
    targets: &[f64],
) -> Result<Correlation, RegressionError> {
    match fit(model, points, targets, None) {
        Ok(f) => Ok(f.correlation),
        Err(
            RegressionError::NonPositiveEstimate { .. }
            | RegressionError::PercentErrorOverflow { .. },
        ) => {
            // Refit without the estimate check: same algebra.
            let mut means = Variables::mean_of(points)?;
            if model.len() == 16 {
                means.z = 0.0;
            }
            let p = model.len();
            let a = Mat::from_fn(points.len(), p, |i, j| {
                model.row(&Normalised::new(&points[i], &means))[j]
            });
            let mut rhs = Mat::from_fn(points.len(), 1, |i, _| targets[i]);
            a.qr().solve_lstsq_in_place(rhs.as_mut());
            Correlation::new(
                model,
                means,
                (0..p).map(|j| rhs[(j, 0)]).collect(),
                f64::INFINITY,
            )
        }
        Err(e) => Err(e),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::TermSet;

    /// A full-factorial grid over the report's ranges (θ never at the mean).
    fn grid(spin: bool) -> Vec<Variables> {
        let mut v = Vec::new();
        for &u in &[10.0, 20.0, 50.0, 80.0] {
            for &t in &[30.0, 45.0, 70.0] {
                for &p in &[1.0, 1.45, 1.9] {
                    for &k in &[1.0, 2.0, 5.0] {
                        for &z in if spin {
                            &[0.0, 0.002, 0.01][..]
                        } else {
                            &[0.0][..]
                        } {
                            v.push(Variables {
                                speed: u,
                                p0_gpa: p,
                                theta_celsius: t,
                                k,
                                z,
                            });
                        }
                    }
                }
            }
        }
        v
    }

    #[test]
    fn recovers_known_coefficients_exactly() {
        // Targets generated from chosen coefficients with given means: an
        // exact, noise-free model must come back to rounding (1e-9 relative
        // covers the design's condition number ~1e3 times machine epsilon).
        for (model, spin) in [(Model::EQ14, false), (Model::EQ15, true)] {
            let pts = grid(spin);
            let means = Variables {
                speed: 40.0,
                p0_gpa: 1.4,
                theta_celsius: 52.0,
                k: 2.5,
                z: 0.004,
            };
            let truth: Vec<f64> = (0..model.len())
                .map(|j| {
                    if j == 0 {
                        1.0
                    } else {
                        1e-4 * j as f64 * if j % 2 == 0 { 1.0 } else { -1.0 }
                    }
                })
                .collect();
            let c = Correlation::new(model, means, truth.clone(), f64::INFINITY).unwrap();
            let y: Vec<f64> = pts
                .iter()
                .map(|x| c.raw(&Normalised::new(x, &means)))
                .collect();
            assert!(y.iter().all(|v| *v > 0.0));
            let f = fit(model, &pts, &y, Some(means)).unwrap();
            for (a, b) in f.correlation.coefficients().iter().zip(&truth) {
                assert!((a - b).abs() <= 1e-9 * b.abs(), "{a} vs {b}");
            }
            assert!(f.stats.std_dev < 1e-8);
        }
    }

    #[test]
    fn a_percent_error_beyond_the_float_range_is_an_error() {
        // A target of 1e-320 is positive, so it was accepted, and
        // 50·(a/e − e/a) overflowed: `traction fit` printed a mean error of
        // -inf % and a standard deviation of NaN %.
        let pts = grid(false);
        let mut y: Vec<f64> = (0..pts.len())
            .map(|i| 0.05 + 1e-3 * (i % 7) as f64)
            .collect();
        y[3] = 1e-320;
        let e = fit(Model::EQ14, &pts, &y, None).unwrap_err();
        assert!(
            matches!(e, RegressionError::PercentErrorOverflow { index: 3, .. }),
            "{e}"
        );
        // Cross-validation counts the point as undefined instead.
        let l = leave_one_out(Model::EQ14, &pts, &y).unwrap();
        assert!(l.rms_percent.is_finite() && l.percent_errors[3].is_none());
        y[3] = 0.05;
        assert!(fit(Model::EQ14, &pts, &y, None).is_ok());
    }

    #[test]
    fn percent_error_is_the_mean_of_the_two_relative_errors() {
        // Hand-computed: a = 0.065, e = 0.04643: (a-e)/a = 0.285692,
        // (a-e)/e = 0.399957, mean 0.342825 -> 34.2825 %.
        assert!((percent_error(0.065, 0.04643) - 34.2825).abs() < 1e-3);
        assert_eq!(percent_error(0.1, 0.1), 0.0);
    }

    #[test]
    fn sample_standard_deviation() {
        // mean 2.5, Σ(x-m)² = 5, n-1 = 3 -> sqrt(5/3).
        let s = ErrorStats::of(&[1.0, 2.0, 3.0, 4.0]);
        assert_eq!(s.mean, 2.5);
        assert!((s.std_dev - (5.0_f64 / 3.0).sqrt()).abs() < 1e-15);
    }

    #[test]
    fn guard_refuses_near_mean_temperature_and_linear_form_does_not() {
        let pts = grid(false);
        let y: Vec<f64> = pts
            .iter()
            .map(|x| 0.1 - 0.0003 * x.speed + 0.01 * x.p0_gpa - 0.0002 * x.theta_celsius)
            .collect();
        let f = fit(Model::EQ14, &pts, &y, None).unwrap();
        let mean = f.correlation.means().theta_celsius;
        let band = f.correlation.guard_band_celsius();
        assert!(band > 0.0);
        let mut q = pts[0];
        q.theta_celsius = mean + 0.5 * band;
        assert!(matches!(
            f.correlation.evaluate(&q),
            Err(RegressionError::NearMeanTemperature { .. })
        ));
        q.theta_celsius = mean + 1.01 * band;
        assert!(f.correlation.evaluate(&q).unwrap().is_finite());
        let lin = Model {
            terms: TermSet::Sixteen,
            temperature: TemperatureForm::Linear,
        };
        let g = fit(lin, &pts, &y, None).unwrap();
        q.theta_celsius = mean;
        assert!(g.correlation.evaluate(&q).unwrap().is_finite());
    }

    #[test]
    fn rank_deficient_data_is_an_error() {
        // All points at k = 5: the k' columns vanish.
        let pts: Vec<Variables> = grid(false).into_iter().filter(|x| x.k == 5.0).collect();
        let y = vec![0.08; pts.len()];
        assert!(matches!(
            fit(Model::EQ14, &pts, &y, None),
            Err(RegressionError::RankDeficient { .. })
        ));
    }

    #[test]
    fn bad_input_is_named() {
        let pts = grid(false);
        let mut y = vec![0.08; pts.len()];
        y[3] = f64::NAN;
        assert!(matches!(
            fit(Model::EQ14, &pts, &y, None),
            Err(RegressionError::OutOfRange { .. })
        ));
        assert!(fit(Model::EQ14, &pts[..10], &y[..10], None).is_err());
        assert!(fit(Model::EQ15, &pts, &vec![0.08; pts.len()], None).is_err()); // Z̄ = 0
        let c = Correlation::new(Model::EQ14, pts[0], vec![0.0; 15], 1.0);
        assert!(matches!(c, Err(RegressionError::CoefficientCount { .. })));
    }

    #[test]
    fn term_order_of_eq14_and_eq15() {
        let n14 = Model::EQ14.term_names();
        assert_eq!(n14[0], "1");
        assert_eq!(n14[3], "P'k'");
        assert_eq!(n14[4], "1/θ'");
        assert_eq!(n14[15], "U'P'k'/θ'");
        let n15 = Model::EQ15.term_names();
        assert_eq!(n15[1], "Z'");
        assert_eq!(n15[8], "1/θ'");
        assert_eq!(n15[24], "U'/θ'");
        assert_eq!(n15[25], "U'Z'/θ'"); // the printed eq. 15 has U'/θ' here (typo)
        assert_eq!(n15[31], "U'P'k'Z'/θ'");
    }
}
