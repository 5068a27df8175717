//! Rigid/plastic model (Wernitz, Magi; Appendix IV equation 14, Appendix V
//! equation 14): the stress everywhere equals the local limit in the
//! direction of the local slip velocity, Z = L·v/|v| with
//! v = (J1/√k − J3·Y, J2/√k + J3·(X+ΔX)/k), L = (3/2)√(1−X²−Y²).

use std::f64::consts::FRAC_PI_2;

use crate::ep::{Resolution, Scaled, StripSums, contact_integral};
use crate::quad;

/// Rigid/plastic strip integrals, composite Gauss–Legendre in s (X = c·sin s).
///
/// The integrand is smooth except at the speed pole (v = 0), where the
/// direction jumps; panels keep the quadrature error local.
fn strip_sums(st: &crate::ep::Strip, s_panels: usize, s_points: usize) -> StripSums {
    let rule = quad::rule(s_points);
    let width = std::f64::consts::PI / s_panels as f64;
    let mut acc = StripSums::default();
    let c = st.c;
    for p in 0..s_panels {
        let mid = -FRAC_PI_2 + (p as f64 + 0.5) * width;
        for &(t, w) in rule {
            let (sn, cs) = (mid + 0.5 * width * t).sin_cos();
            let x = c * sn;
            // Slip velocity v = (a, (b1 + q2·X)/gy) (the strip holds G·v).
            let (vx, vy) = (st.a, (st.b1 + st.q2 * x) / st.gy);
            let m = vx.hypot(vy);
            if m.is_nan() || m <= 0.0 {
                continue;
            }
            let (nx, ny) = if m.is_finite() {
                (vx / m, vy / m)
            } else {
                let s = vx.abs().max(vy.abs());
                let (a, b) = (vx / s, vy / s);
                let h = a.hypot(b);
                (a / h, b / h)
            };
            // L·dX/ds = (3/2)·c²·cos² s.
            let f = 0.5 * width * w * 1.5 * c * c * cs * cs;
            acc.ix += f * nx;
            acc.iy += f * ny;
            acc.ixy += f * ny * x;
        }
    }
    acc
}

/// Rigid/plastic (J4, J5, J6).
pub(crate) fn solve(sc: &Scaled, res: &Resolution, s_panels: usize) -> (f64, f64, f64) {
    contact_integral(sc, res, |st| strip_sums(st, s_panels, 8))
}
