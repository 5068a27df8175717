//! Nonlinear least squares: Levenberg–Marquardt with finite-difference
//! Jacobians, box bounds, and the statistics of the fitted parameters.
//!
//! Finds the parameters x (n of them) that minimise the cost
//! F(x) = ½‖r(x)‖² = ½ Σᵢ rᵢ(x)² of m ≥ n residuals rᵢ computed by a user
//! function, e.g. rᵢ = model(x, tᵢ) − yᵢ.
//!
//! ## Algorithm
//! Each iteration linearises r(x + δ) ≈ r + Jδ, with the Jacobian
//! J = ∂r/∂x by finite differences ([`Difference`]), and takes the damped
//! Gauss–Newton step
//!
//! (JᵀJ + λD) δ = −Jᵀr,
//!
//! solved as the equivalent linear least-squares problem
//! `[J; √(λD)] δ ≈ [−r; 0]` by Householder QR (faer), which avoids squaring
//! the condition number of J. D = diag(dⱼ) is Marquardt's scaling with Moré's
//! safeguard: dⱼ = max over the iterations of ‖J₍:,ⱼ₎‖² (floored at 1e-12 of
//! the largest, so that a parameter the data do not see still gets damped).
//! The step is invariant to the parameters' units.
//!
//! **Bounds.** A trial point is projected on the box [lower, upper]
//! (x + δ clamped component-wise) and the projected step is the one judged.
//!
//! **Damping strategy** (Nielsen 1999, as in Madsen, Nielsen & Tingleff,
//! *Methods for non-linear least squares problems*, 2004, §3.2): the gain
//! ratio ρ = (F(x) − F(x + δ)) / (L(0) − L(δ)) compares the actual reduction
//! with the one predicted by the linear model L(δ) = ½‖r + Jδ‖². A step with
//! ρ > 10⁻⁴ is accepted and λ ← λ·max(⅓, 1 − (2ρ − 1)³), ν ← 2; otherwise
//! (or when r(x + δ) fails or is not finite) it is rejected and λ ← λ·ν,
//! ν ← 2ν. λ starts at [`Options::initial_damping`] (relative to D).
//!
//! **Convergence** ([`Termination`]; MINPACK's tests):
//! * [`Termination::Cost`]: an accepted step whose actual and predicted
//!   relative reductions of the cost are both ≤ [`Options::ftol`];
//! * [`Termination::Step`]: ‖D^½δ‖ ≤ xtol·(‖D^½x‖ + xtol), [`Options::xtol`];
//! * [`Termination::Gradient`]: the largest cosine between r and a column of
//!   J, |Jⱼᵀr| / (‖Jⱼ‖‖r‖), is ≤ [`Options::gtol`];
//! * [`Termination::ZeroResidual`]: r = 0 exactly;
//! * otherwise [`Termination::MaxIterations`], [`Termination::MaxEvaluations`]
//!   or [`Termination::Stalled`] (λ beyond 10¹⁶: no step reduces the cost;
//!   typically the residuals are noisy at the scale of the finite-difference
//!   step). These are reported, not errors: the fit is the best point found.
//!
//! **Finite differences.** Parameter j is stepped by
//! hⱼ = [`Options::relative_step`]·max(|xⱼ|, scaleⱼ), with the parameter's
//! typical magnitude `scale` ([`Parameter::scale`]) so that a parameter near
//! zero (an offset) still gets a step of the right size. Central differences
//! (2n evaluations per Jacobian) by default; one-sided where a bound or a
//! failing evaluation leaves only one side. For residuals computed by an
//! adaptive integration with tolerance ε, the derivative error is of order
//! ε/h: choose ε tight and h large enough (e.g. ε = 10⁻⁶ of the residual
//! scale and h = 10⁻³ of the parameter).
//!
//! ## Statistics
//! At the solution x̂, with J = J(x̂) (recomputed there), m residuals and n
//! parameters, the residual variance is s² = ‖r‖²/(m − n) and the covariance
//! of the parameters is the usual linearised one, C = s²(JᵀJ)⁻¹; the standard
//! errors are √Cⱼⱼ and the correlations Cᵢⱼ/√(CᵢᵢCⱼⱼ). C is computed from the
//! singular value decomposition of the column-scaled Jacobian
//! Jₛ = J·diag(1/‖Jⱼ‖) = UΣVᵀ: C = s² S⁻¹VΣ⁻²VᵀS⁻¹ with S = diag(‖Jⱼ‖).
//! The condition number σmax/σmin of Jₛ measures identifiability
//! independently of the parameters' units. When Jₛ is numerically rank
//! deficient (σᵢ ≤ [`Options::rank_tolerance`]·σmax, or a column of J is
//! zero) or m = n, there is no covariance ([`Fit::covariance`] is `None`);
//! [`Fit::weak_directions`] names the parameter combinations the data do not
//! determine.
//!
//! ## Example
//! The exponential decay y = a·e^(−bt), data generated with a = 2, b = 0.5:
//! ```
//! use traction_regression::nls::{Options, Parameter, levenberg_marquardt};
//! let t: Vec<f64> = (0..20).map(|i| i as f64 * 0.25).collect();
//! let y: Vec<f64> = t.iter().map(|t| 2.0 * (-0.5 * t).exp()).collect();
//! let fit = levenberg_marquardt(
//!     |x: &[f64], r: &mut [f64]| -> Result<(), String> {
//!         for (i, ti) in t.iter().enumerate() {
//!             r[i] = x[0] * (-x[1] * ti).exp() - y[i];
//!         }
//!         Ok(())
//!     },
//!     t.len(),
//!     &[Parameter::new(1.0, 1.0), Parameter::new(1.0, 1.0)],
//!     &Options::default(),
//! )?;
//! assert!((fit.x[0] - 2.0).abs() < 1e-8 && (fit.x[1] - 0.5).abs() < 1e-8);
//! assert!(fit.termination.converged());
//! # Ok::<(), traction_regression::RegressionError>(())
//! ```

use faer::Mat;
use faer::linalg::solvers::SolveLstsq;

use crate::RegressionError;

/// Finite-difference scheme of the Jacobian.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Difference {
    /// (r(x + h) − r(x))/h: n evaluations per Jacobian, error O(h).
    Forward,
    /// (r(x + h) − r(x − h))/2h: 2n evaluations per Jacobian, error O(h²).
    #[default]
    Central,
}

/// Options of [`levenberg_marquardt`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Largest number of iterations (Jacobians) (default 200).
    pub max_iterations: usize,
    /// Largest number of residual evaluations, Jacobians included (default 10 000).
    pub max_evaluations: usize,
    /// Relative reduction of the cost below which an accepted step ends the
    /// fit (default 1e-12), in [0, 1).
    pub ftol: f64,
    /// Relative step size below which the fit ends (default 1e-10), in [0, 1).
    pub xtol: f64,
    /// Cosine between the residual and each Jacobian column below which the
    /// fit ends (default 1e-10), in [0, 1).
    pub gtol: f64,
    /// Finite-difference scheme (default central).
    pub difference: Difference,
    /// Finite-difference step relative to max(|x|, scale) (default 1e-6), in
    /// [1e-12, 0.1]. Use about ε^(1/3) (central) or ε^(1/2) (forward) of the
    /// residuals' relative accuracy ε.
    pub relative_step: f64,
    /// Initial damping λ₀, relative to Marquardt's scaling D (default 1e-3), > 0.
    pub initial_damping: f64,
    /// Singular values of the column-scaled Jacobian at or below this
    /// fraction of the largest count as zero (rank deficiency) (default 1e-10),
    /// in [0, 1).
    pub rank_tolerance: f64,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            max_iterations: 200,
            max_evaluations: 10_000,
            ftol: 1e-12,
            xtol: 1e-10,
            gtol: 1e-10,
            difference: Difference::Central,
            relative_step: 1e-6,
            initial_damping: 1e-3,
            rank_tolerance: 1e-10,
        }
    }
}

impl Options {
    fn validate(&self) -> Result<(), RegressionError> {
        let unit = |quantity, v: f64| {
            if (0.0..1.0).contains(&v) {
                Ok(())
            } else {
                Err(RegressionError::OutOfRange {
                    quantity,
                    value: v,
                    range: "in [0, 1)",
                })
            }
        };
        unit("ftol (relative cost reduction)", self.ftol)?;
        unit("xtol (relative step)", self.xtol)?;
        unit("gtol (gradient cosine)", self.gtol)?;
        unit("rank tolerance", self.rank_tolerance)?;
        if !(1e-12..=0.1).contains(&self.relative_step) {
            return Err(RegressionError::OutOfRange {
                quantity: "relative finite-difference step",
                value: self.relative_step,
                range: "in [1e-12, 0.1]",
            });
        }
        if !(self.initial_damping > 0.0 && self.initial_damping.is_finite()) {
            return Err(RegressionError::OutOfRange {
                quantity: "initial damping λ₀",
                value: self.initial_damping,
                range: "finite and > 0",
            });
        }
        if self.max_iterations == 0 || self.max_evaluations == 0 {
            return Err(RegressionError::OutOfRange {
                quantity: "iteration and evaluation limits",
                value: self.max_iterations.min(self.max_evaluations) as f64,
                range: "≥ 1",
            });
        }
        Ok(())
    }
}

/// One fitted parameter: initial value, typical magnitude and bounds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parameter {
    /// Initial value (projected on the bounds).
    pub initial: f64,
    /// Typical magnitude (> 0): the finite-difference step is
    /// `relative_step·max(|x|, scale)`.
    pub scale: f64,
    /// Lower bound (may be −∞).
    pub lower: f64,
    /// Upper bound (may be +∞).
    pub upper: f64,
}

impl Parameter {
    /// An unbounded parameter.
    pub fn new(initial: f64, scale: f64) -> Parameter {
        Parameter {
            initial,
            scale,
            lower: f64::NEG_INFINITY,
            upper: f64::INFINITY,
        }
    }

    /// The same parameter restricted to [lower, upper].
    pub fn bounded(self, lower: f64, upper: f64) -> Parameter {
        Parameter {
            lower,
            upper,
            ..self
        }
    }

    fn validate(&self, index: usize) -> Result<(), RegressionError> {
        let bad = |what: &str, v: f64| RegressionError::DataShape {
            what: "parameter",
            detail: format!("parameter {index}: {what} = {v}"),
        };
        if !self.initial.is_finite() {
            return Err(bad("initial value (must be finite)", self.initial));
        }
        if !(self.scale > 0.0 && self.scale.is_finite()) {
            return Err(bad("scale (must be finite and > 0)", self.scale));
        }
        if self.lower.is_nan() || self.upper.is_nan() || self.lower >= self.upper {
            return Err(RegressionError::DataShape {
                what: "parameter",
                detail: format!(
                    "parameter {index}: bounds [{}, {}] must satisfy lower < upper",
                    self.lower, self.upper
                ),
            });
        }
        Ok(())
    }
}

/// Why the iteration stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Termination {
    /// Actual and predicted relative cost reductions ≤ ftol.
    Cost,
    /// Relative step ≤ xtol.
    Step,
    /// Residual orthogonal to the Jacobian's columns within gtol.
    Gradient,
    /// All residuals exactly zero.
    ZeroResidual,
    /// Iteration limit reached.
    MaxIterations,
    /// Evaluation limit reached.
    MaxEvaluations,
    /// No step reduces the cost although the convergence tests are not met
    /// (damping beyond 1e16).
    Stalled,
}

impl Termination {
    /// True for the convergence criteria (cost, step, gradient, zero residual).
    pub fn converged(&self) -> bool {
        matches!(
            self,
            Termination::Cost
                | Termination::Step
                | Termination::Gradient
                | Termination::ZeroResidual
        )
    }

    /// A short description.
    pub fn describe(&self) -> &'static str {
        match self {
            Termination::Cost => "converged: relative reduction of the sum of squares ≤ ftol",
            Termination::Step => "converged: relative step ≤ xtol",
            Termination::Gradient => "converged: gradient (residual–Jacobian cosine) ≤ gtol",
            Termination::ZeroResidual => "converged: zero residual",
            Termination::MaxIterations => "not converged: iteration limit reached",
            Termination::MaxEvaluations => "not converged: evaluation limit reached",
            Termination::Stalled => {
                "not converged: no step reduces the sum of squares (noisy residuals?)"
            }
        }
    }
}

/// The result of [`levenberg_marquardt`].
#[derive(Debug, Clone)]
pub struct Fit {
    /// Fitted parameters.
    pub x: Vec<f64>,
    /// Residuals at `x`.
    pub residuals: Vec<f64>,
    /// Cost ½‖r‖² at `x`.
    pub cost: f64,
    /// Root mean square residual √(‖r‖²/m).
    pub rms: f64,
    /// Residual variance s² = ‖r‖²/(m − n) (`None` when m = n).
    pub variance: Option<f64>,
    /// Iterations (Jacobians evaluated in the loop).
    pub iterations: usize,
    /// Residual evaluations, Jacobians included.
    pub evaluations: usize,
    /// Why the iteration stopped.
    pub termination: Termination,
    /// Jacobian at `x` (m × n).
    pub jacobian: Mat<f64>,
    /// Euclidean norms of the Jacobian's columns at `x`.
    pub column_norms: Vec<f64>,
    /// Singular values of the column-scaled Jacobian, largest first.
    pub singular_values: Vec<f64>,
    /// Right singular vectors of the column-scaled Jacobian (n × n, column i
    /// belongs to `singular_values[i]`).
    pub right_singular_vectors: Mat<f64>,
    /// Condition number σmax/σmin of the column-scaled Jacobian (∞ if singular).
    pub condition_number: f64,
    /// Numerical rank of the Jacobian (columns of zero norm excluded).
    pub rank: usize,
    /// Covariance s²(JᵀJ)⁻¹ (`None` if rank deficient or m = n).
    pub covariance: Option<Mat<f64>>,
}

impl Fit {
    /// Standard errors √Cⱼⱼ (`None` without covariance).
    pub fn standard_errors(&self) -> Option<Vec<f64>> {
        let c = self.covariance.as_ref()?;
        Some((0..c.nrows()).map(|j| c[(j, j)].max(0.0).sqrt()).collect())
    }

    /// Correlation matrix Cᵢⱼ/√(CᵢᵢCⱼⱼ) (`None` without covariance).
    pub fn correlation(&self) -> Option<Mat<f64>> {
        let c = self.covariance.as_ref()?;
        let s = self.standard_errors()?;
        Some(Mat::from_fn(c.nrows(), c.ncols(), |i, j| {
            if i == j {
                1.0
            } else if s[i] > 0.0 && s[j] > 0.0 {
                (c[(i, j)] / (s[i] * s[j])).clamp(-1.0, 1.0)
            } else {
                0.0
            }
        }))
    }

    /// Parameter combinations the data (almost) do not determine: for each
    /// singular value of the column-scaled Jacobian with σᵢ/σmax ≤
    /// `threshold`, the pair (σᵢ/σmax, vᵢ) with vᵢ the unit right singular
    /// vector (components in the column-scaled parameters, so comparable
    /// across units; a large |vᵢⱼ| means parameter j takes part). A parameter
    /// with a zero Jacobian column appears as (0, eⱼ).
    pub fn weak_directions(&self, threshold: f64) -> Vec<(f64, Vec<f64>)> {
        let n = self.x.len();
        let mut out = Vec::new();
        for (j, &c) in self.column_norms.iter().enumerate() {
            if c == 0.0 {
                out.push((
                    0.0,
                    (0..n).map(|i| if i == j { 1.0 } else { 0.0 }).collect(),
                ));
            }
        }
        let smax = self.singular_values.first().copied().unwrap_or(0.0);
        for (i, &s) in self.singular_values.iter().enumerate() {
            let ratio = if smax > 0.0 { s / smax } else { 0.0 };
            if ratio <= threshold {
                out.push((
                    ratio,
                    (0..n)
                        .map(|j| {
                            if self.column_norms[j] == 0.0 {
                                0.0
                            } else {
                                self.right_singular_vectors[(j, i)]
                            }
                        })
                        .collect(),
                ));
            }
        }
        out
    }
}

/// Counts evaluations and checks the residuals.
struct Counted<F> {
    f: F,
    m: usize,
    evaluations: usize,
    max: usize,
}

impl<F, E> Counted<F>
where
    F: FnMut(&[f64], &mut [f64]) -> Result<(), E>,
    E: std::fmt::Display,
{
    /// Residuals at x: `Err(message)` when the function fails or returns a
    /// non-finite residual.
    fn eval(&mut self, x: &[f64]) -> Result<Vec<f64>, String> {
        self.evaluations += 1;
        let mut r = vec![0.0; self.m];
        (self.f)(x, &mut r).map_err(|e| e.to_string())?;
        if let Some(i) = r.iter().position(|v| !v.is_finite()) {
            return Err(format!("residual {i} is {} (not finite)", r[i]));
        }
        Ok(r)
    }

    fn exhausted(&self) -> bool {
        self.evaluations >= self.max
    }
}

fn norm2(v: &[f64]) -> f64 {
    v.iter().map(|a| a * a).sum()
}

/// Finite-difference Jacobian at x (residuals r0 there).
fn jacobian<F, E>(
    f: &mut Counted<F>,
    x: &[f64],
    r0: &[f64],
    params: &[Parameter],
    options: &Options,
) -> Result<Mat<f64>, RegressionError>
where
    F: FnMut(&[f64], &mut [f64]) -> Result<(), E>,
    E: std::fmt::Display,
{
    let (m, n) = (r0.len(), x.len());
    let mut jac = Mat::<f64>::zeros(m, n);
    let mut xp = x.to_vec();
    for j in 0..n {
        let h = options.relative_step * x[j].abs().max(params[j].scale);
        let mut side = |sign: f64| -> Option<(f64, Vec<f64>)> {
            let v = x[j] + sign * h;
            if v < params[j].lower || v > params[j].upper {
                return None;
            }
            xp[j] = v;
            let r = f.eval(&xp).ok();
            xp[j] = x[j];
            // The step actually taken (x + h rounded).
            r.map(|r| (v - x[j], r))
        };
        let plus = side(1.0);
        let minus = match (options.difference, &plus) {
            (Difference::Forward, Some(_)) => None,
            _ => side(-1.0),
        };
        let column: Vec<f64> = match (plus, minus) {
            (Some((hp, rp)), Some((hm, rm))) => {
                (0..m).map(|i| (rp[i] - rm[i]) / (hp - hm)).collect()
            }
            (Some((h1, r1)), None) | (None, Some((h1, r1))) => {
                (0..m).map(|i| (r1[i] - r0[i]) / h1).collect()
            }
            (None, None) => {
                return Err(RegressionError::Residual {
                    message: format!(
                        "for the finite-difference Jacobian of parameter {j} at {}: neither x ± h (h = {h:e}) \
                         can be evaluated within the bounds",
                        x[j]
                    ),
                });
            }
        };
        for (i, v) in column.into_iter().enumerate() {
            jac[(i, j)] = v;
        }
    }
    Ok(jac)
}

fn column_norms(jac: &Mat<f64>) -> Vec<f64> {
    (0..jac.ncols())
        .map(|j| {
            (0..jac.nrows())
                .map(|i| jac[(i, j)].powi(2))
                .sum::<f64>()
                .sqrt()
        })
        .collect()
}

/// Minimise ½‖r(x)‖² by Levenberg–Marquardt (see the module docs).
///
/// `residuals(x, r)` fills the `m` residuals at x; it may fail (return
/// `Err`) or produce non-finite values for some x: such trial points are
/// rejected like a step that increases the cost. It must succeed at the
/// (projected) initial point.
///
/// Errors: invalid options or parameters, m < n, or a residual function that
/// fails at the initial point or at both sides of a finite-difference step
/// ([`RegressionError::Residual`] with its message).
pub fn levenberg_marquardt<F, E>(
    residuals: F,
    m: usize,
    params: &[Parameter],
    options: &Options,
) -> Result<Fit, RegressionError>
where
    F: FnMut(&[f64], &mut [f64]) -> Result<(), E>,
    E: std::fmt::Display,
{
    options.validate()?;
    let n = params.len();
    if n == 0 || m < n {
        return Err(RegressionError::DataShape {
            what: "nonlinear least squares",
            detail: format!("{m} residuals for {n} parameters: need n ≥ 1 and m ≥ n"),
        });
    }
    for (j, p) in params.iter().enumerate() {
        p.validate(j)?;
    }
    let clamp = |j: usize, v: f64| v.clamp(params[j].lower, params[j].upper);
    let mut f = Counted {
        f: residuals,
        m,
        evaluations: 0,
        max: options.max_evaluations,
    };
    let mut x: Vec<f64> = params
        .iter()
        .enumerate()
        .map(|(j, p)| clamp(j, p.initial))
        .collect();
    let mut r = f.eval(&x).map_err(|message| RegressionError::Residual {
        message: format!("at the initial point {x:?}: {message}"),
    })?;
    let mut cost = 0.5 * norm2(&r);
    let mut jac = jacobian(&mut f, &x, &r, params, options)?;
    let mut jac_at_x = true;
    let mut d = vec![0.0_f64; n];
    let update_scaling = |d: &mut [f64], jac: &Mat<f64>| {
        let norms = column_norms(jac);
        for j in 0..n {
            d[j] = d[j].max(norms[j] * norms[j]);
        }
        let dmax = d.iter().copied().fold(0.0, f64::max);
        let floor = if dmax > 0.0 { 1e-12 * dmax } else { 1.0 };
        for v in d.iter_mut() {
            *v = v.max(floor);
        }
    };
    update_scaling(&mut d, &jac);
    let mut lambda = options.initial_damping;
    let mut nu = 2.0;
    let mut iterations = 0;
    let termination = 'outer: loop {
        if cost == 0.0 {
            break Termination::ZeroResidual;
        }
        if iterations >= options.max_iterations {
            break Termination::MaxIterations;
        }
        iterations += 1;
        // Gradient test: cosine between r and each column of J.
        let rnorm = (2.0 * cost).sqrt();
        let norms = column_norms(&jac);
        let mut gmax = 0.0_f64;
        for j in 0..n {
            if norms[j] > 0.0 {
                let g: f64 = (0..m).map(|i| jac[(i, j)] * r[i]).sum();
                gmax = gmax.max(g.abs() / (norms[j] * rnorm));
            }
        }
        if gmax <= options.gtol {
            break Termination::Gradient;
        }
        loop {
            if f.exhausted() {
                break 'outer Termination::MaxEvaluations;
            }
            if lambda > 1e16 {
                break 'outer Termination::Stalled;
            }
            // [J; √(λD)] δ ≈ [−r; 0]
            let a = Mat::from_fn(m + n, n, |i, j| {
                if i < m {
                    jac[(i, j)]
                } else if i - m == j {
                    (lambda * d[j]).sqrt()
                } else {
                    0.0
                }
            });
            let mut rhs = Mat::from_fn(m + n, 1, |i, _| if i < m { -r[i] } else { 0.0 });
            a.qr().solve_lstsq_in_place(rhs.as_mut());
            let x_new: Vec<f64> = (0..n).map(|j| clamp(j, x[j] + rhs[(j, 0)])).collect();
            let step: Vec<f64> = (0..n).map(|j| x_new[j] - x[j]).collect();
            let dstep = (0..n).map(|j| d[j] * step[j] * step[j]).sum::<f64>().sqrt();
            let dx = (0..n).map(|j| d[j] * x[j] * x[j]).sum::<f64>().sqrt();
            let small_step = dstep <= options.xtol * (dx + options.xtol);
            // Predicted cost of the (projected) step: ½‖r + Jδ‖².
            let lin: Vec<f64> = (0..m)
                .map(|i| r[i] + (0..n).map(|j| jac[(i, j)] * step[j]).sum::<f64>())
                .collect();
            let predicted = cost - 0.5 * norm2(&lin);
            let trial = if predicted > 0.0 && dstep > 0.0 {
                f.eval(&x_new).ok()
            } else {
                None
            };
            let accepted = trial.and_then(|r_new| {
                let cost_new = 0.5 * norm2(&r_new);
                let rho = (cost - cost_new) / predicted;
                (rho > 1e-4).then_some((r_new, cost_new, rho))
            });
            match accepted {
                Some((r_new, cost_new, rho)) => {
                    let actual = cost - cost_new;
                    let small_cost =
                        actual <= options.ftol * cost && predicted <= options.ftol * cost;
                    x = x_new;
                    r = r_new;
                    cost = cost_new;
                    jac_at_x = false;
                    lambda *= (1.0 - (2.0 * rho - 1.0).powi(3)).max(1.0 / 3.0);
                    nu = 2.0;
                    if small_cost {
                        break 'outer Termination::Cost;
                    }
                    if small_step {
                        break 'outer Termination::Step;
                    }
                    if f.exhausted() {
                        break 'outer Termination::MaxEvaluations;
                    }
                    jac = jacobian(&mut f, &x, &r, params, options)?;
                    jac_at_x = true;
                    update_scaling(&mut d, &jac);
                    break;
                }
                None => {
                    if small_step {
                        break 'outer Termination::Step;
                    }
                    lambda *= nu;
                    nu *= 2.0;
                }
            }
        }
    };
    if !jac_at_x {
        jac = jacobian(&mut f, &x, &r, params, options)?;
    }
    statistics(
        x,
        r,
        cost,
        jac,
        iterations,
        f.evaluations,
        termination,
        options,
    )
}

#[allow(clippy::too_many_arguments)]
fn statistics(
    x: Vec<f64>,
    r: Vec<f64>,
    cost: f64,
    jac: Mat<f64>,
    iterations: usize,
    evaluations: usize,
    termination: Termination,
    options: &Options,
) -> Result<Fit, RegressionError> {
    let (m, n) = (jac.nrows(), jac.ncols());
    let norms = column_norms(&jac);
    let scaled = Mat::from_fn(m, n, |i, j| {
        if norms[j] > 0.0 {
            jac[(i, j)] / norms[j]
        } else {
            0.0
        }
    });
    let svd = scaled.thin_svd().map_err(|_| RegressionError::Svd)?;
    let sv: Vec<f64> = (0..n).map(|i| svd.S().column_vector()[i]).collect();
    let v = svd.V().to_owned();
    let smax = sv.first().copied().unwrap_or(0.0);
    let rank = sv
        .iter()
        .filter(|&&s| smax > 0.0 && s > options.rank_tolerance * smax)
        .count();
    let smin = sv.last().copied().unwrap_or(0.0);
    let condition_number = if smin > 0.0 {
        smax / smin
    } else {
        f64::INFINITY
    };
    let ss = 2.0 * cost;
    let variance = (m > n).then(|| ss / (m - n) as f64);
    let covariance = match variance {
        Some(s2) if rank == n && norms.iter().all(|&c| c > 0.0) => {
            Some(Mat::from_fn(n, n, |a, b| {
                let sum: f64 = (0..n)
                    .map(|i| v[(a, i)] * v[(b, i)] / (sv[i] * sv[i]))
                    .sum();
                s2 * sum / (norms[a] * norms[b])
            }))
        }
        _ => None,
    };
    Ok(Fit {
        rms: (ss / m as f64).sqrt(),
        x,
        residuals: r,
        cost,
        variance,
        iterations,
        evaluations,
        termination,
        jacobian: jac,
        column_norms: norms,
        singular_values: sv,
        right_singular_vectors: v,
        condition_number,
        rank,
        covariance,
    })
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    fn fit_fn<F>(f: F, m: usize, p: &[Parameter]) -> Fit
    where
        F: FnMut(&[f64], &mut [f64]) -> Result<(), String>,
    {
        levenberg_marquardt(f, m, p, &Options::default()).unwrap()
    }

    /// NIST StRD nonlinear regression "Misra1a" (lower difficulty):
    /// y = b1·(1 − exp(−b2·x)), 14 points, certified values to 11 digits.
    const MISRA1A_X: [f64; 14] = [
        77.6, 114.9, 141.1, 190.8, 239.9, 289.0, 332.8, 378.4, 434.8, 477.3, 536.8, 593.1, 689.1,
        760.0,
    ];
    const MISRA1A_Y: [f64; 14] = [
        10.07, 14.73, 17.94, 23.93, 29.61, 35.18, 40.02, 44.82, 50.76, 55.05, 61.01, 66.40, 75.47,
        81.78,
    ];

    #[test]
    fn misra1a_certified_values_and_standard_errors() {
        for start in [[500.0, 1e-4], [250.0, 5e-4]] {
            let fit = fit_fn(
                |b, r| {
                    for i in 0..14 {
                        r[i] = b[0] * (1.0 - (-b[1] * MISRA1A_X[i]).exp()) - MISRA1A_Y[i];
                    }
                    Ok(())
                },
                14,
                &[
                    Parameter::new(start[0], 100.0),
                    Parameter::new(start[1], 1e-4),
                ],
            );
            assert!(fit.termination.converged(), "{:?}", fit.termination);
            // Certified: b1 = 2.3894212918E+02 (sd 2.7070075241E+00),
            // b2 = 5.5015643181E-04 (sd 7.2668688436E-06),
            // residual sum of squares 1.2455138894E-01. The optimum is found
            // to ~1e-8 relative (ftol 1e-12 on the cost); the standard errors
            // use a central-difference Jacobian (h = 1e-6 relative): 1e-6.
            let rel = |a: f64, b: f64| (a / b - 1.0).abs();
            assert!(rel(fit.x[0], 2.3894212918e2) < 1e-7, "{}", fit.x[0]);
            assert!(rel(fit.x[1], 5.5015643181e-4) < 1e-7, "{}", fit.x[1]);
            assert!(rel(2.0 * fit.cost, 1.2455138894e-1) < 1e-9);
            let se = fit.standard_errors().unwrap();
            assert!(rel(se[0], 2.7070075241) < 1e-6, "{}", se[0]);
            assert!(rel(se[1], 7.2668688436e-6) < 1e-6, "{}", se[1]);
            assert_eq!(fit.rank, 2);
        }
    }

    #[test]
    fn straight_line_covariance_is_the_closed_form() {
        // y = c0 + c1·t with fixed "noise": the LM optimum is the linear
        // least-squares solution and C = s²(XᵀX)⁻¹ in closed form:
        // Var c1 = s²/Sxx, Var c0 = s²(1/n + t̄²/Sxx), Cov = −t̄ s²/Sxx.
        let t: Vec<f64> = (0..11).map(|i| i as f64).collect();
        let noise = [
            0.1, -0.2, 0.05, 0.3, -0.1, 0.0, -0.25, 0.15, 0.2, -0.05, -0.1,
        ];
        let y: Vec<f64> = t
            .iter()
            .zip(noise)
            .map(|(t, e)| 1.5 + 0.7 * t + e)
            .collect();
        let fit = fit_fn(
            |c, r| {
                for i in 0..t.len() {
                    r[i] = c[0] + c[1] * t[i] - y[i];
                }
                Ok(())
            },
            t.len(),
            &[Parameter::new(0.0, 1.0), Parameter::new(0.0, 1.0)],
        );
        let n = t.len() as f64;
        let tm = t.iter().sum::<f64>() / n;
        let ym = y.iter().sum::<f64>() / n;
        let sxx: f64 = t.iter().map(|t| (t - tm).powi(2)).sum();
        let sxy: f64 = t.iter().zip(&y).map(|(t, y)| (t - tm) * (y - ym)).sum();
        let c1 = sxy / sxx;
        let c0 = ym - c1 * tm;
        let s2: f64 = t
            .iter()
            .zip(&y)
            .map(|(t, y)| (y - c0 - c1 * t).powi(2))
            .sum::<f64>()
            / (n - 2.0);
        // Linear residuals: central differences are exact to rounding.
        assert!((fit.x[0] - c0).abs() < 1e-9 && (fit.x[1] - c1).abs() < 1e-9);
        let c = fit.covariance.as_ref().unwrap();
        assert!((c[(1, 1)] / (s2 / sxx) - 1.0).abs() < 1e-8);
        assert!((c[(0, 0)] / (s2 * (1.0 / n + tm * tm / sxx)) - 1.0).abs() < 1e-8);
        assert!((c[(0, 1)] / (-tm * s2 / sxx) - 1.0).abs() < 1e-8);
        let corr = fit.correlation().unwrap();
        let expect = -tm / (1.0 / n * sxx + tm * tm).sqrt();
        assert!((corr[(0, 1)] - expect).abs() < 1e-8, "{}", corr[(0, 1)]);
        assert!((fit.variance.unwrap() / s2 - 1.0).abs() < 1e-9);
    }

    #[test]
    fn rosenbrock_zero_residual_and_no_covariance_when_m_equals_n() {
        // r = (10(x2 − x1²), 1 − x1): minimum (1, 1), cost 0.
        for fwd in [false, true] {
            let opts = Options {
                difference: if fwd {
                    Difference::Forward
                } else {
                    Difference::Central
                },
                relative_step: if fwd { 1e-8 } else { 1e-6 },
                ..Options::default()
            };
            let fit = levenberg_marquardt(
                |x: &[f64], r: &mut [f64]| -> Result<(), String> {
                    r[0] = 10.0 * (x[1] - x[0] * x[0]);
                    r[1] = 1.0 - x[0];
                    Ok(())
                },
                2,
                &[Parameter::new(-1.2, 1.0), Parameter::new(1.0, 1.0)],
                &opts,
            )
            .unwrap();
            assert!(fit.termination.converged(), "{:?}", fit.termination);
            assert!((fit.x[0] - 1.0).abs() < 1e-6 && (fit.x[1] - 1.0).abs() < 1e-6);
            assert!(fit.cost < 1e-14);
            assert!(fit.covariance.is_none() && fit.variance.is_none());
        }
    }

    #[test]
    fn exponential_fit_matches_the_analytic_covariance() {
        // y = a e^(−b t) + fixed pseudo-noise; covariance checked against
        // s²(JᵀJ)⁻¹ with the analytic Jacobian at the optimum (2×2 inverse).
        let t: Vec<f64> = (0..25).map(|i| 0.2 * i as f64).collect();
        let y: Vec<f64> = t
            .iter()
            .enumerate()
            .map(|(i, t)| 3.0 * (-0.8 * t).exp() + 0.01 * ((i * 7919 % 13) as f64 / 6.0 - 1.0))
            .collect();
        let fit = fit_fn(
            |x, r| {
                for i in 0..t.len() {
                    r[i] = x[0] * (-x[1] * t[i]).exp() - y[i];
                }
                Ok(())
            },
            t.len(),
            &[Parameter::new(1.0, 1.0), Parameter::new(0.1, 1.0)],
        );
        let (a, b) = (fit.x[0], fit.x[1]);
        // Normal equations hold at the optimum (gradient = 0).
        let (mut ja, mut jb, mut saa, mut sab, mut sbb) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for i in 0..t.len() {
            let e = (-b * t[i]).exp();
            let r = a * e - y[i];
            let (da, db) = (e, -a * t[i] * e);
            ja += da * r;
            jb += db * r;
            saa += da * da;
            sab += da * db;
            sbb += db * db;
        }
        assert!(ja.abs() < 1e-9 && jb.abs() < 1e-9, "{ja} {jb}");
        let det = saa * sbb - sab * sab;
        let s2 = fit.variance.unwrap();
        let c = fit.covariance.as_ref().unwrap();
        assert!((c[(0, 0)] / (s2 * sbb / det) - 1.0).abs() < 1e-6);
        assert!((c[(1, 1)] / (s2 * saa / det) - 1.0).abs() < 1e-6);
        assert!((c[(0, 1)] / (-s2 * sab / det) - 1.0).abs() < 1e-6);
    }

    #[test]
    fn rank_deficiency_is_reported_with_its_direction() {
        // y = (a + b) t: only a + b is determined.
        let t: Vec<f64> = (1..8).map(f64::from).collect();
        let fit = fit_fn(
            |x, r| {
                for i in 0..t.len() {
                    r[i] = (x[0] + x[1]) * t[i] - 2.0 * t[i] - 0.01 * (i as f64 - 3.0);
                }
                Ok(())
            },
            t.len(),
            &[Parameter::new(0.5, 1.0), Parameter::new(0.5, 1.0)],
        );
        // Least squares: a + b = 2 + 0.01·Σ(t − 4)t/Σt² = 2 + 0.01·28/140.
        assert!((fit.x[0] + fit.x[1] - 2.002).abs() < 1e-9, "{:?}", fit.x);
        assert!(fit.rank < 2 && fit.covariance.is_none());
        let weak = fit.weak_directions(1e-6);
        assert_eq!(weak.len(), 1);
        let v = &weak[0].1;
        assert!((v[0].abs() - 0.5f64.sqrt()).abs() < 1e-6 && (v[0] + v[1]).abs() < 1e-6);
        // A parameter the residuals do not depend on: zero column.
        let fit = fit_fn(
            |x, r| {
                for i in 0..t.len() {
                    r[i] = x[0] * t[i] - 2.0 * t[i];
                }
                Ok(())
            },
            t.len(),
            &[Parameter::new(0.5, 1.0), Parameter::new(0.5, 1.0)],
        );
        assert_eq!(fit.column_norms[1], 0.0);
        assert!(fit.covariance.is_none());
        assert!(
            fit.weak_directions(1e-6)
                .iter()
                .any(|(s, v)| *s == 0.0 && v[1] == 1.0)
        );
    }

    #[test]
    fn bounds_and_failing_regions() {
        // Optimum of (x − 3)² at 3, bounded to [0, 2]: ends at the bound.
        let fit = fit_fn(
            |x, r| {
                r[0] = x[0] - 3.0;
                r[1] = 0.5 * (x[0] - 3.0);
                Ok(())
            },
            2,
            &[Parameter::new(1.0, 1.0).bounded(0.0, 2.0)],
        );
        assert_eq!(fit.x[0], 2.0);
        // A residual that fails for x < 0.5 (e.g. an unphysical property):
        // steps into that region are rejected, the fit still converges.
        let fit = fit_fn(
            |x, r| {
                if x[0] < 0.5 {
                    return Err(format!("x = {} below 0.5", x[0]));
                }
                r[0] = x[0].ln();
                r[1] = 2.0 * x[0].ln();
                Ok(())
            },
            2,
            &[Parameter::new(20.0, 1.0)],
        );
        assert!((fit.x[0] - 1.0).abs() < 1e-8, "{}", fit.x[0]);
        // Failing at the start is an error naming the message.
        let e = levenberg_marquardt(
            |_x: &[f64], _r: &mut [f64]| Err("no model here"),
            2,
            &[Parameter::new(1.0, 1.0)],
            &Options::default(),
        )
        .unwrap_err();
        assert!(e.to_string().contains("no model here"), "{e}");
    }

    #[test]
    fn bad_inputs_are_errors() {
        let f = |_x: &[f64], r: &mut [f64]| -> Result<(), String> {
            r.fill(1.0);
            Ok(())
        };
        let p = [Parameter::new(1.0, 1.0)];
        assert!(levenberg_marquardt(f, 0, &p, &Options::default()).is_err());
        assert!(levenberg_marquardt(f, 2, &[], &Options::default()).is_err());
        for bad in [
            Parameter::new(f64::NAN, 1.0),
            Parameter::new(1.0, 0.0),
            Parameter::new(1.0, 1.0).bounded(2.0, 1.0),
        ] {
            assert!(levenberg_marquardt(f, 2, &[bad], &Options::default()).is_err());
        }
        for o in [
            Options {
                ftol: 1.0,
                ..Options::default()
            },
            Options {
                relative_step: 0.0,
                ..Options::default()
            },
            Options {
                initial_damping: f64::NAN,
                ..Options::default()
            },
            Options {
                max_iterations: 0,
                ..Options::default()
            },
        ] {
            assert!(levenberg_marquardt(f, 2, &p, &o).is_err());
        }
        // NaN residuals at the start: error, never a NaN fit.
        let e = levenberg_marquardt(
            |_x: &[f64], r: &mut [f64]| -> Result<(), String> {
                r.fill(f64::NAN);
                Ok(())
            },
            2,
            &p,
            &Options::default(),
        )
        .unwrap_err();
        assert!(e.to_string().contains("not finite"), "{e}");
    }
}
