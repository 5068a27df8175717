//! Viscoelastic J+T model (Appendix V equations 1–6, Appendix IV equation 6)
//! in the two-dimensional strip form, with the limiting shear stress kept as
//! a cap.
//!
//! With τ̄ = μN/(πab) as the stress unit, Z0 = τ0/τ̄ (the sinh reference
//! stress of equation 3) and the Deborah number D = ηU/(Ḡa), equations 2–5
//! give along a strip
//!
//!   dZ/dX = v − (Z0/D)·sinh(|Z|/Z0)·Z/|Z|,   |Z| ≤ L = (3/2)√(1−X²−Y²),
//!
//! where v is the elastic rate of the elastic/plastic model. On the cap the
//! flow is Prandtl–Reuss (the radial return below). With a stiffness ratio
//! gy ≠ 1 the right-hand side is G·(v − viscous rate), G = diag(1, gy), and
//! the return onto the cap is the energy-norm closest point. The viscous term vanishes
//! as D → ∞ and the model becomes the elastic/plastic one; for Z0 → ∞ it is
//! the linear Maxwell fluid dZ/dX = v − Z/D.
//!
//! Integration: uniform steps in s (X = c·sin s) with an exponential
//! (Lawson) midpoint step for the stiff relaxation, μ = Z0·sinh(|Z|/Z0)/(D|Z|)
//! frozen at a predicted midpoint, followed by a radial return onto the cap;
//! integrals by the trapezoidal rule. Second order while the cap is inactive.

use std::f64::consts::FRAC_PI_2;

use crate::ep::{Resolution, Scaled, StripSums, contact_integral, return_map};

/// Relaxation rate μ(|Z|) = Z0·sinh(|Z|/Z0)/(D·|Z|) (→ 1/D at Z = 0).
#[inline]
fn mu(ze: f64, z0: f64, d: f64) -> f64 {
    let r = ze / z0;
    let shr = if r < 1e-4 {
        1.0 + r * r / 6.0
    } else {
        r.sinh() / r
    };
    // Cap the argument: beyond ~700 sinh overflows; the rate is then
    // effectively infinite (the stress relaxes within any step).
    if !shr.is_finite() {
        return f64::MAX / 4.0;
    }
    shr / d
}

/// exp(−x) and (1 − exp(−x))/x, stable for small x.
#[inline]
fn phi1(x: f64) -> (f64, f64) {
    if x < 1e-6 {
        (1.0 - x, 1.0 - 0.5 * x)
    } else {
        let e = (-x).exp();
        (e, (1.0 - e) / x)
    }
}

fn strip_sums(st: &crate::ep::Strip, nsteps: usize, z0: f64, d: f64) -> StripSums {
    let c = st.c;
    let mut acc = StripSums::default();
    if c <= 0.0 {
        return acc;
    }
    let h = std::f64::consts::PI / nsteps as f64;
    let (mut zx, mut zy) = (0.0_f64, 0.0_f64);
    let mut s = -FRAC_PI_2;
    let mut prev = (0.0, 0.0, -c); // (zx, zy, x) at the step start
    for i in 0..nsteps {
        let s1 = if i + 1 == nsteps { FRAC_PI_2 } else { s + h };
        let x0 = c * s.sin();
        let x1 = c * s1.sin();
        let dxs = x1 - x0;
        let xm = 0.5 * (x0 + x1);
        // Elastic increment over the step (v is linear in X: exact midpoint).
        let (vx, vy) = (st.a, st.b1 + st.q2 * xm);
        // Predictor: rate at the start, then at the predicted midpoint. The
        // viscous strain rate μ·Z acts through G = diag(1, gy): Zy relaxes
        // at gy·μ.
        let gy = st.gy;
        let m0 = mu(zx.hypot(zy), z0, d);
        let (e0x, p0x) = phi1(m0 * 0.5 * dxs);
        let (e0y, p0y) = phi1(gy * m0 * 0.5 * dxs);
        let (pmx, pmy) = (
            zx * e0x + 0.5 * dxs * p0x * vx,
            zy * e0y + 0.5 * dxs * p0y * vy,
        );
        let mm = mu(pmx.hypot(pmy), z0, d);
        let (ex, px) = phi1(mm * dxs);
        let (ey, py) = phi1(gy * mm * dxs);
        let nx = zx * ex + dxs * px * vx;
        let ny = zy * ey + dxs * py * vy;
        // Return onto the limit (3/2)·c·cos s1 (radial for gy = 1).
        let l1 = 1.5 * c * s1.cos().max(0.0);
        (zx, zy) = return_map(nx, ny, l1, gy);
        // Trapezoidal sums in X.
        acc.ix += 0.5 * dxs * (prev.0 + zx);
        acc.iy += 0.5 * dxs * (prev.1 + zy);
        acc.ixy += 0.5 * dxs * (prev.1 * prev.2 + zy * x1);
        prev = (zx, zy, x1);
        s = s1;
    }
    acc
}

/// Viscoelastic (J4, J5, J6).
pub(crate) fn solve(
    sc: &Scaled,
    res: &Resolution,
    nsteps: usize,
    z0: f64,
    d: f64,
) -> (f64, f64, f64) {
    contact_integral(sc, res, |st| strip_sums(st, nsteps, z0, d))
}
