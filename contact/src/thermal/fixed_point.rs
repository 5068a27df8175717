//! The self-consistent temperature rise: the solver of the fixed point
//! `ΔT = q(ΔT)(R_s + R_f)` ([`solve_fixed_point`],
//! [`solve_fixed_point_with_slope`]; f(x) the rise that the dissipation
//! produces at the rise x), bracketed on g(x) = x − f(x) with steps from a
//! local exponential model of f (the first through the start with the
//! caller's slope estimate),
//!
//! ```text
//! f(x) ≈ y₂ e^{s (x − x₂)},  s = (ln y₂ − ln y₁)/(x₂ − x₁)   (through the last two evaluations)
//! next x: the root of t = y₂ e^{s (t − x₂)}                   (exp_model_root, Newton)
//! ```
//!
//! safeguarded by bisection, to [`TEMPERATURE_TOLERANCE`] /
//! [`TEMPERATURE_RELATIVE_TOLERANCE`], with [`MAX_TEMPERATURE_RISE`] as the
//! runaway limit; and the coarser rheology accuracy of the first evaluation
//! with spin (`iteration_accuracy`). The contact's evaluation
//! (`crate::contact`) drives it with the loss of `ContactThermal`
//! (`contact_thermal.rs`) and that model's slope estimate for the first step.

use crate::{Accuracy, ContactError};

/// Accuracy of the fixed point on the temperature rise, K (absolute) — with
/// [`TEMPERATURE_RELATIVE_TOLERANCE`] of the rise, whichever is larger.
pub const TEMPERATURE_TOLERANCE: f64 = 0.01;
/// Relative accuracy of the fixed point on the temperature rise.
pub const TEMPERATURE_RELATIVE_TOLERANCE: f64 = 1e-3;
/// Largest temperature rise the solver accepts, K: beyond it the contact is
/// reported as a thermal runaway (no physical fixed point).
pub const MAX_TEMPERATURE_RISE: f64 = 2000.0;

/// Solve `x = f(x)` for the temperature rise x ≥ 0, where `f(x) ≥ 0` is the
/// rise the contact's dissipation produces with the fluid at inlet + x,
/// starting at `start` (the contact uses the reference peak's rise).
///
/// Bracketed on `g(x) = x − f(x)` (g(0) = −f(0) ≤ 0); steps from a local
/// exponential model of f through the last two evaluations (exact when the
/// loss falls exponentially with temperature), safeguarded by bisection of the
/// bracket. Converged when |g| ≤ max([`TEMPERATURE_TOLERANCE`],
/// [`TEMPERATURE_RELATIVE_TOLERANCE`]·x). Returns (x, evaluations of f).
///
/// Errors: f returns an error (passed on), a non-finite or negative value, no
/// fixed point below [`MAX_TEMPERATURE_RISE`] (runaway), or no convergence in
/// 60 evaluations.
pub fn solve_fixed_point(
    start: f64,
    mut f: impl FnMut(f64) -> Result<f64, ContactError>,
) -> Result<(f64, usize), ContactError> {
    solve_fixed_point_with_slope(start, |x| Ok((f(x)?, 0.0)))
}

/// [`solve_fixed_point`] where `f` also returns an estimate of the
/// logarithmic slope d ln f/dx at x (≤ 0 when heating lowers the loss). The
/// first step after the start is the Newton step of the exponential model
/// through the start with that slope (with 0 it is the plain iteration
/// x₁ = f(x₀), as in [`solve_fixed_point`]); an accurate estimate saves one
/// evaluation of f, a poor one only costs the steps it would have taken
/// anyway (the bracket, the log-secant steps and the convergence test are
/// those of [`solve_fixed_point`]). Returns (x, evaluations of f).
pub fn solve_fixed_point_with_slope(
    start: f64,
    mut f: impl FnMut(f64) -> Result<(f64, f64), ContactError>,
) -> Result<(f64, usize), ContactError> {
    let evals = std::cell::Cell::new(0_usize);
    let slope_hint = std::cell::Cell::new(0.0_f64);
    let mut eval = |x: f64| -> Result<f64, ContactError> {
        evals.set(evals.get() + 1);
        let (y, s) = f(x)?;
        slope_hint.set(if s.is_finite() { s } else { 0.0 });
        if !(y.is_finite() && y >= 0.0) {
            return Err(ContactError::Thermal {
                reason: "the dissipation gave a non-finite or negative temperature rise",
                temperature_rise: x,
            });
        }
        Ok(y)
    };
    let tol = |x: f64| TEMPERATURE_TOLERANCE.max(TEMPERATURE_RELATIVE_TOLERANCE * x);
    let x0 = if start.is_finite() {
        start.clamp(0.0, MAX_TEMPERATURE_RISE)
    } else {
        0.0
    };
    let y0 = eval(x0)?;
    if (x0 - y0).abs() <= tol(x0) {
        return Ok((x0, evals.get()));
    }
    // Bracket [lo, hi] with g(lo) < 0 ≤ g(hi): g(0) = −f(0) ≤ 0 always.
    let (mut lo, mut hi) = (0.0_f64, f64::NAN);
    if x0 < y0 {
        lo = x0;
    } else {
        hi = x0;
    }
    // The last two evaluations (x, f(x)), the newest second.
    let mut pts = [(f64::NAN, f64::NAN), (x0, y0)];
    let mut x = exp_model_root(x0, y0, slope_hint.get().min(0.0)).min(MAX_TEMPERATURE_RISE);
    loop {
        let y = eval(x)?;
        let g = x - y;
        if g.abs() <= tol(x) {
            return Ok((x, evals.get()));
        }
        if g < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        pts = [pts[1], (x, y)];
        if evals.get() >= 60 {
            return Err(ContactError::Thermal {
                reason: "the temperature fixed point did not converge in 60 evaluations",
                temperature_rise: x,
            });
        }
        // Local model f ≈ y₂ e^{s (x − x₂)} through the last two points.
        let [(x1, y1), (x2, y2)] = pts;
        let mut next = f64::NAN;
        if y1 > 0.0 && y2 > 0.0 && x1 != x2 {
            let s = (y2.ln() - y1.ln()) / (x2 - x1);
            if s <= 0.0 {
                next = exp_model_root(x2, y2, s);
            }
        }
        if hi.is_nan() {
            // No point above the root yet: the model's root if it lies
            // beyond the last point below it, else (f grows with the
            // temperature) expand until the bracket closes.
            if x >= MAX_TEMPERATURE_RISE {
                return Err(ContactError::Thermal {
                    reason: "thermal runaway: no fixed point below 2000 K",
                    temperature_rise: x,
                });
            }
            x = if next > lo && next < MAX_TEMPERATURE_RISE {
                next
            } else {
                (2.0 * x).max(y).min(MAX_TEMPERATURE_RISE)
            };
            continue;
        }
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        x = next;
    }
}

/// The root of t = y₀ e^{s (t − x₀)} for s ≤ 0 (h(t) = t − y₀ e^{s(t−x₀)} is
/// increasing; the root lies between x₀ and y₀): Newton from x₀; y₀ for s = 0.
fn exp_model_root(x0: f64, y0: f64, s: f64) -> f64 {
    if s == 0.0 || y0 <= 0.0 {
        return y0;
    }
    let mut t = x0;
    for _ in 0..50 {
        let e = y0 * (s * (t - x0)).exp();
        let step = (t - e) / (1.0 - s * e);
        t -= step;
        if step.abs() <= 1e-12 * t.abs().max(1.0) {
            break;
        }
    }
    t
}

/// Accuracy of the first fixed-point evaluation with spin (far from the
/// root): ten times coarser than the contact's, at most 1e-2 (never finer).
pub(crate) fn iteration_accuracy(accuracy: Accuracy) -> Accuracy {
    Accuracy::new((10.0 * accuracy.tol()).min(1e-2).max(accuracy.tol())).unwrap_or(accuracy)
}
