//! Rigid/plastic model (Wernitz, Magi; Appendix IV equation 14, Appendix V
//! equation 14): the stress everywhere equals the local limit in the
//! direction of the local slip velocity, Z = L·v/|v| with
//! v = (J1/√k − J3·Y, J2/√k + J3·(X+ΔX)/k), L = (3/2)√(1−X²−Y²).
//!
//! The integrand is smooth except near the speed pole: along a strip the
//! direction turns by π across the line vy = 0 (X0 = −b1/q2, the same for
//! every strip) within |X − X0| ≈ ε = |vx|·gy/|q2|, which vanishes on the
//! strip through the pole (Y_p, vx = 0). So
//! * along a strip, Gauss–Legendre panels in s (X = c·sin s) split at the
//!   crossing s0 and graded geometrically (ratio 4) from the turning width ε
//!   outwards: every panel sees a function analytic in a neighbourhood of
//!   its own size, and the strip integral is accurate to ≈ 1e-10;
//! * across strips, adaptive panels in φ (Y = sin φ) split where the strip
//!   sums are not smooth — at the pole strip Y_p (a·log|a| behaviour) and
//!   where the line X = X0 leaves the ellipse (Y = ±√(1 − X0²)).

use std::f64::consts::FRAC_PI_2;

use crate::ep::{Scaled, Strip, StripSums, contact_integral_adaptive_at};
use crate::quad;

/// Gauss–Legendre points per s-panel.
const S_POINTS: usize = 8;
/// Largest number of graded panels on one side of the crossing.
const MAX_GRADED: usize = 60;

/// Adds the Gauss–Legendre sums of the strip between s = p and s = q (either order).
fn panel(st: &Strip, p: f64, q: f64, acc: &mut StripSums) {
    let (mid, half) = (0.5 * (p + q), 0.5 * (p - q).abs());
    let c = st.c;
    for &(t, w) in quad::rule(S_POINTS) {
        let (sn, cs) = (mid + half * t).sin_cos();
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
        let f = half * w * 1.5 * c * c * cs * cs;
        acc.ix += f * nx;
        acc.iy += f * ny;
        acc.ixy += f * ny * x;
    }
}

/// Panels from the crossing s0 towards `end` (either side), graded from
/// the turning width `e` (in s) by factors of 4 (8-point panels: a
/// singularity at ≥ 1.8 half-lengths from the centre, error ≈ 3.3^-16).
fn graded(st: &Strip, s0: f64, end: f64, e: f64, acc: &mut StripSums) {
    let len = (end - s0).abs();
    if len <= 0.0 {
        return;
    }
    let dir = (end - s0).signum();
    // Below 1e-12 of the side the turn is a jump for the quadrature (its
    // weight in the integral is below ~1e-12).
    let mut d = e.max(len * 1e-12);
    let mut prev = 0.0;
    let mut n = 0;
    while d < len && n < MAX_GRADED {
        panel(st, s0 + dir * prev, s0 + dir * d, acc);
        prev = d;
        d *= 4.0;
        n += 1;
    }
    panel(st, s0 + dir * prev, end, acc);
}

/// Rigid/plastic strip integrals ∫Zx dX, ∫Zy dX, ∫Zy·X dX.
pub(crate) fn strip_sums(st: &Strip) -> StripSums {
    let mut acc = StripSums::default();
    let c = st.c;
    if c <= 0.0 {
        return acc;
    }
    let x0 = if st.q2 != 0.0 {
        -st.b1 / st.q2
    } else {
        f64::INFINITY
    };
    if x0.abs() < c {
        let s0 = (x0 / c).asin();
        // Turning width in s: ε/(dX/ds) with ε = |a|·gy/|q2|.
        let e = (st.a.abs() * st.gy / st.q2.abs()) / (c * s0.cos());
        graded(st, s0, -FRAC_PI_2, e, &mut acc);
        graded(st, s0, FRAC_PI_2, e, &mut acc);
    } else {
        // No turn inside the strip: the direction is smooth; two panels.
        panel(st, -FRAC_PI_2, 0.0, &mut acc);
        panel(st, 0.0, FRAC_PI_2, &mut acc);
    }
    acc
}

/// Rigid/plastic (J4, J5, J6) to the absolute accuracy `tol`.
pub(crate) fn solve(sc: &Scaled, tol: f64) -> (f64, f64, f64) {
    let mut breaks = vec![-FRAC_PI_2, FRAC_PI_2];
    if sc.j3 != 0.0 {
        // Pole strip: a = a0 − J3·Y = 0.
        let yp = sc.a0 / sc.j3;
        if yp.abs() < 1.0 {
            breaks.push(yp.asin());
        }
        // The line X = X0 (vy = 0) leaves the ellipse at Y = ±√(1 − X0²).
        let x0 = -sc.b1 / sc.q2;
        if x0.abs() < 1.0 {
            let ye = (1.0 - x0 * x0).sqrt().asin();
            breaks.push(ye);
            breaks.push(-ye);
        }
    }
    breaks.sort_by(f64::total_cmp);
    breaks.dedup();
    contact_integral_adaptive_at(sc, &breaks, 6, tol, 14, strip_sums)
}
