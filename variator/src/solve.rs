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
    /// From the kinematics with the disc turning and the roller at rest
    /// (`disc`) and with the disc at rest and the roller at unit speed (`roller`).
    pub(crate) fn new(disc: &ContactKinematics, roller: &ContactKinematics) -> Self {
        Linear {
            disc: parts(disc),
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

/// Root of the decreasing roller torque `g(w)`, starting from the zero-slip
/// roller speeds `wa`, `wb` of the two contacts (the root lies between them
/// when the contacts transmit no traction at zero slip; otherwise the bracket
/// is widened). Solved to a bracket of a few ulps (or an exact zero).
pub(crate) fn balance(g: &mut impl FnMut(f64) -> Result<f64>, wa: f64, wb: f64) -> Result<f64> {
    let (mut lo, mut hi) = (wa.min(wb), wa.max(wb));
    let mut flo = g(lo)?;
    if flo == 0.0 {
        return Ok(lo);
    }
    let mut fhi = if hi == lo { flo } else { g(hi)? };
    if fhi == 0.0 {
        return Ok(hi);
    }
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
            flo = g(lo)?;
        } else {
            lo = hi;
            flo = fhi;
            hi += width;
            fhi = g(hi)?;
        }
        if flo == 0.0 {
            return Ok(lo);
        }
        if fhi == 0.0 {
            return Ok(hi);
        }
        width *= 2.0;
    }
    brent(g, lo, hi, flo, fhi)
}

/// Brent's method on a bracket with f(a), f(b) of opposite signs.
fn brent(
    g: &mut impl FnMut(f64) -> Result<f64>,
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
        fb = g(b)?;
    }
    Ok(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brent_finds_the_root_of_a_decreasing_function_to_ulps() {
        let mut n = 0;
        let mut g = |w: f64| -> Result<f64> {
            n += 1;
            Ok((2.0 - w).powi(3) + 0.1 * (2.0 - w))
        };
        let w = balance(&mut g, 0.0, 5.0).unwrap();
        assert!((w - 2.0).abs() <= 4.0 * f64::EPSILON * 2.0, "{w}");
        assert!(n < 80, "{n} evaluations");
    }

    #[test]
    fn bracket_is_widened_when_needed() {
        // Root at 10, starting bracket [1, 1].
        let mut g = |w: f64| -> Result<f64> { Ok(10.0 - w) };
        let w = balance(&mut g, 1.0, 1.0).unwrap();
        assert!((w - 10.0).abs() < 1e-12);
        let mut flat = |_w: f64| -> Result<f64> { Ok(1.0) };
        assert!(matches!(
            balance(&mut flat, 0.0, 1.0),
            Err(VariatorError::NoBalance { .. })
        ));
    }
}
