//! The roller torque balance: kinematics linear in the roller speed, and a
//! bracketed root solve (Brent's method) for the roller speed.

use traction_kinematics::ContactKinematics;

use crate::{Result, VariatorError};

/// Contact kinematics as `disc part + ω_r · roller part` (rigid-body velocities
/// are linear in the angular velocities, so this superposition is exact and
/// free of cancellation).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Linear {
    disc: [f64; 4],
    roller: [f64; 4],
}

fn parts(k: &ContactKinematics) -> [f64; 4] {
    [k.rolling_speed, k.slip, k.side_slip, k.spin]
}

impl Linear {
    /// From the kinematics at unit disc speed with the roller at rest
    /// (`disc`), scaled to the disc speed `speed`, and at unit roller speed
    /// with the disc at rest (`roller`).
    pub(crate) fn new(disc: &ContactKinematics, speed: f64, roller: &ContactKinematics) -> Self {
        Linear {
            disc: parts(disc).map(|x| speed * x),
            roller: parts(roller),
        }
    }

    /// (U, ΔU, ΔV, ω) at roller speed `w`.
    pub(crate) fn at(&self, w: f64) -> (f64, f64, f64, f64) {
        let c = |i: usize| self.disc[i] + w * self.roller[i];
        (c(0), c(1), c(2), c(3))
    }

    /// Roller speed at which the slip ΔU vanishes.
    pub(crate) fn zero_slip_speed(&self) -> f64 {
        if self.roller[1] == 0.0 {
            0.0
        } else {
            -self.disc[1] / self.roller[1]
        }
    }
}

/// Most bracket widenings tried before giving up.
const MAX_WIDEN: usize = 80;
/// Most Brent iterations (it needs ~ 10–60 to a few ulps).
const MAX_ITER: usize = 200;
/// The root is accepted when |g| ≤ `G_TOLERANCE` × the torque scale (the sum
/// of the two contacts' torque magnitudes on the roller): the balance then
/// closes to ~1e-12 of the throughput, eight orders below the rheology's own
/// accuracy, and any two solves agree to that level whatever they started
/// from.
pub(crate) const G_TOLERANCE: f64 = 1e-12;

/// One evaluation of the roller torque: `(g, scale)`, the net torque and the
/// sum of the magnitudes of the two contacts' torques.
pub(crate) type Torque = (f64, f64);

/// Whether an evaluation meets the acceptance test of [`G_TOLERANCE`].
fn done((g, scale): Torque) -> bool {
    g == 0.0 || g.abs() <= G_TOLERANCE * scale
}

/// Root of the decreasing roller torque `g(w)`, starting from the zero-slip
/// roller speeds `wa`, `wb` of the two contacts (the root lies between them
/// when the contacts transmit no traction at zero slip; otherwise the bracket
/// is widened). Solved to [`G_TOLERANCE`] or a bracket of a few ulps.
pub(crate) fn balance(g: &mut impl FnMut(f64) -> Result<Torque>, wa: f64, wb: f64) -> Result<f64> {
    let (mut lo, mut hi) = (wa.min(wb), wa.max(wb));
    let elo = g(lo)?;
    if done(elo) {
        return Ok(lo);
    }
    let mut flo = elo.0;
    let mut fhi = if hi == lo {
        flo
    } else {
        let ehi = g(hi)?;
        if done(ehi) {
            return Ok(hi);
        }
        ehi.0
    };
    let scale = lo.abs().max(hi.abs());
    let mut width = (hi - lo).max(1e-6 * scale).max(1e-9);
    let mut widened = 0;
    while !(flo > 0.0 && fhi < 0.0) {
        if widened == MAX_WIDEN {
            return Err(VariatorError::NoBalance { low: lo, high: hi });
        }
        widened += 1;
        if flo < 0.0 {
            hi = lo;
            fhi = flo;
            lo -= width;
            let e = g(lo)?;
            if done(e) {
                return Ok(lo);
            }
            flo = e.0;
        } else {
            lo = hi;
            flo = fhi;
            hi += width;
            let e = g(hi)?;
            if done(e) {
                return Ok(hi);
            }
            fhi = e.0;
        }
        width *= 2.0;
    }
    brent(g, lo, hi, flo, fhi)
}

/// Where the previous root lay: its position `t = (w − wa)/(wb − wa)` between
/// the zero-slip roller speeds of the two contacts (a dimensionless split of
/// the creep, unchanged by a common scaling of the speeds) and the slope
/// dg/dt there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Hint {
    pub(crate) t: f64,
    pub(crate) slope: f64,
}

/// Most secant steps of the warm start before it falls back to the cold bracket.
const MAX_WARM: usize = 8;

/// Root of the decreasing roller torque `g(w)` (as [`balance`]), started from
/// the previous solution `hint` when there is one: g at the hinted speed, a
/// Newton step with the hinted slope, then secant steps; Brent's method as
/// soon as two evaluations bracket the root. The same acceptance test as the
/// cold solve ([`G_TOLERANCE`]), so both give the root to that tolerance.
/// Falls back to [`balance`] when the steps neither converge nor bracket,
/// or when a step cannot be evaluated.
/// Returns the root and the hint for the next call.
pub(crate) fn balance_warm(
    g: &mut impl FnMut(f64) -> Result<Torque>,
    wa: f64,
    wb: f64,
    hint: Option<Hint>,
) -> Result<(f64, Option<Hint>)> {
    let span = wb - wa;
    let mut seen: Vec<(f64, f64)> = Vec::with_capacity(32);
    let mut rec = |w: f64| -> Result<Torque> {
        let v = g(w)?;
        seen.push((w, v.0));
        Ok(v)
    };
    let root = match hint {
        // A warm step the contacts cannot evaluate (the hinted slope belongs
        // to another operating point: after a load or speed change of many
        // orders the Newton step can land at contact speeds beyond the
        // contact's range) is no error of the point: the cold solve,
        // bracketed from the zero-slip speeds, decides.
        Some(h) if span != 0.0 && span.is_finite() && h.t.is_finite() => {
            warm(&mut rec, wa, span, h).unwrap_or(None)
        }
        _ => None,
    };
    let root = match root {
        Some(w) => w,
        None => balance(&mut rec, wa, wb)?,
    };
    Ok((root, next_hint(&seen, root, wa, span, hint)))
}

/// The warm start proper: None when the steps fail.
fn warm(
    g: &mut impl FnMut(f64) -> Result<Torque>,
    wa: f64,
    span: f64,
    h: Hint,
) -> Result<Option<f64>> {
    let mut w0 = wa + h.t * span;
    let e0 = g(w0)?;
    if done(e0) {
        return Ok(Some(w0));
    }
    let mut g0 = e0.0;
    // dg/dw from the hinted dg/dt; g decreases with w, so the root lies
    // above w0 when g0 > 0.
    let slope = h.slope / span;
    let floor = 1e-9 * span.abs().max(w0.abs());
    let newton = -g0 / slope;
    let mut w1 = if slope < 0.0 && newton.is_finite() {
        w0 + newton
    } else {
        w0 + (1e-3 * span.abs()).max(floor).copysign(g0)
    };
    for _ in 0..MAX_WARM {
        let e1 = g(w1)?;
        if done(e1) {
            return Ok(Some(w1));
        }
        let g1 = e1.0;
        if (g1 > 0.0) != (g0 > 0.0) {
            return brent(g, w0, w1, g0, g1).map(Some);
        }
        // Same side: the secant step if it points onwards (towards the
        // root, in the sense given by the sign of g) and is finite, else
        // twice the last step.
        let secant = -g1 * (w1 - w0) / (g1 - g0);
        let onwards = secant.is_finite() && secant != 0.0 && (secant > 0.0) == (g1 > 0.0);
        let step = if onwards {
            secant
        } else {
            2.0 * (w1 - w0).abs().max(floor).copysign(g1)
        };
        (w0, g0) = (w1, g1);
        w1 += step;
    }
    Ok(None)
}

/// The hint after solving: the root's position, and the slope of the secant
/// through the nearest evaluations either side of the root that lie at least
/// 1e-7 of the bracket from it (the slope of the previous hint if none).
fn next_hint(
    seen: &[(f64, f64)],
    root: f64,
    wa: f64,
    span: f64,
    old: Option<Hint>,
) -> Option<Hint> {
    if span == 0.0 || !span.is_finite() {
        return None;
    }
    let gap = 1e-7 * span.abs();
    let nearest = |side: f64| {
        seen.iter()
            .filter(|(w, v)| (w - root) * side >= gap && v.is_finite())
            .min_by(|a, b| (a.0 - root).abs().total_cmp(&(b.0 - root).abs()))
            .copied()
    };
    let slope = match (nearest(1.0), nearest(-1.0)) {
        (Some((w1, v1)), Some((w0, v0))) => (v1 - v0) / (w1 - w0) * span,
        _ => old.map_or(f64::NAN, |h| h.slope),
    };
    Some(Hint {
        t: (root - wa) / span,
        slope,
    })
}

/// Brent's method on a bracket with f(a), f(b) of opposite signs.
fn brent(
    g: &mut impl FnMut(f64) -> Result<Torque>,
    a0: f64,
    b0: f64,
    fa0: f64,
    fb0: f64,
) -> Result<f64> {
    let (mut a, mut b, mut fa, mut fb) = (a0, b0, fa0, fb0);
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..MAX_ITER {
        if (fb > 0.0) == (fc > 0.0) {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + f64::MIN_POSITIVE;
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            return Ok(b);
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            // Inverse quadratic interpolation or secant.
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                let qa = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
                q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        let eb = g(b)?;
        if done(eb) {
            return Ok(b);
        }
        fb = eb.0;
    }
    Ok(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brent_finds_the_root_of_a_decreasing_function_to_ulps() {
        let mut n = 0;
        let mut g = |w: f64| -> Result<Torque> {
            n += 1;
            Ok(((2.0 - w).powi(3) + 0.1 * (2.0 - w), 0.0))
        };
        let w = balance(&mut g, 0.0, 5.0).unwrap();
        assert!((w - 2.0).abs() <= 4.0 * f64::EPSILON * 2.0, "{w}");
        assert!(n < 80, "{n} evaluations");
    }

    #[test]
    fn bracket_is_widened_when_needed() {
        // Root at 10, starting bracket [1, 1].
        let mut g = |w: f64| -> Result<Torque> { Ok((10.0 - w, 0.0)) };
        let w = balance(&mut g, 1.0, 1.0).unwrap();
        assert!((w - 10.0).abs() < 1e-12);
        let mut flat = |_w: f64| -> Result<Torque> { Ok((1.0, 0.0)) };
        assert!(matches!(
            balance(&mut flat, 0.0, 1.0),
            Err(VariatorError::NoBalance { .. })
        ));
    }
}
