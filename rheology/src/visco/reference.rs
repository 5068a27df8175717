//! The former viscoelastic integrator, kept as an independent reference for
//! tests and convergence studies ([`crate::reference::viscoelastic`]):
//! uniform steps in s (X = c·sin s), an exponential (Lawson) midpoint step of
//! the relaxation with μ frozen at a predicted midpoint, a return onto the
//! cap, trapezoidal sums; second order in the interior, first order where
//! the cap is active. Test builds add the exact strip integral of the linear
//! Maxwell fluid at zero spin.

use std::f64::consts::{FRAC_PI_2, PI};

use super::Law;
use crate::ep::{Resolution, Scaled, Strip, StripSums, contact_integral, return_map};

/// exp(−x) and (1 − exp(−x))/x, stable for small x.
fn phi1(x: f64) -> (f64, f64) {
    if x < 1e-6 {
        (1.0 - x, 1.0 - 0.5 * x)
    } else {
        let e = (-x).exp();
        (e, (1.0 - e) / x)
    }
}

/// The former integrator: `nsteps` uniform steps in s (X = c·sin s), an
/// exponential (Lawson) midpoint step with μ frozen at a predicted midpoint,
/// return onto the cap, trapezoidal sums.
fn uniform_strip(st: &Strip, law: Law, nsteps: usize) -> StripSums {
    let c = st.c;
    let mut acc = StripSums::default();
    if c <= 0.0 {
        return acc;
    }
    let h = PI / nsteps as f64;
    let (mut zx, mut zy) = (0.0_f64, 0.0_f64);
    let mut s = -FRAC_PI_2;
    let mut prev = (0.0, 0.0, -c);
    let gy = st.gy;
    for i in 0..nsteps {
        let s1 = if i + 1 == nsteps { FRAC_PI_2 } else { s + h };
        let x0 = c * s.sin();
        let x1 = c * s1.sin();
        let dxs = x1 - x0;
        let xm = 0.5 * (x0 + x1);
        let (vx, vy) = (st.a, st.b1 + st.q2 * xm);
        let m0 = law.rates(zx.hypot(zy)).0;
        let (e0x, p0x) = phi1(m0 * 0.5 * dxs);
        let (e0y, p0y) = phi1(gy * m0 * 0.5 * dxs);
        let (pmx, pmy) = (
            zx * e0x + 0.5 * dxs * p0x * vx,
            zy * e0y + 0.5 * dxs * p0y * vy,
        );
        let mm = law.rates(pmx.hypot(pmy)).0;
        let (ex, px) = phi1(mm * dxs);
        let (ey, py) = phi1(gy * mm * dxs);
        let nx = zx * ex + dxs * px * vx;
        let ny = zy * ey + dxs * py * vy;
        let l1 = 1.5 * c * s1.cos().max(0.0);
        (zx, zy) = return_map(nx, ny, l1, gy);
        acc.ix += 0.5 * dxs * (prev.0 + zx);
        acc.iy += 0.5 * dxs * (prev.1 + zy);
        acc.ixy += 0.5 * dxs * (prev.1 * prev.2 + zy * x1);
        prev = (zx, zy, x1);
        s = s1;
    }
    acc
}

/// (J4, J5, J6) of the former scheme: `res` Gauss–Legendre strips in
/// φ, `nsteps` uniform steps per strip.
pub(crate) fn solve(sc: &Scaled, law: Law, res: &Resolution, nsteps: usize) -> (f64, f64, f64) {
    contact_integral(sc, res, |st| uniform_strip(st, law, nsteps.max(1)))
}

#[cfg(test)]
/// Exact strip sums of the linear Maxwell fluid (Z0 = ∞, gy = 1) at zero
/// spin: the rate e = (a, b1) is constant, so from the inlet
/// Z = D·e·(1 − exp(−(X + c)/D)) until |Z| = L at X*, then Z = L·ê to the
/// outlet (the direction does not turn and λ ≥ 0 there: n·e − L′ − L/D grows
/// with X).
pub(crate) fn maxwell_strip(st: &super::VStrip) -> [f64; 3] {
    let (c, d) = (st.c, st.law.d);
    let m = st.a.hypot(st.b1);
    if c <= 0.0 || m == 0.0 {
        return [0.0; 3];
    }
    let (ux, uy) = (st.a / m, st.b1 / m);
    let zabs = |x: f64| d * m * (-(-(x + c) / d).exp_m1());
    let lim = |x: f64| 1.5 * (c * c - x * x).max(0.0).sqrt();
    // Entry: g(X) = |Z| − L, negative after the inlet, positive at X = c.
    let g = |x: f64| zabs(x) - lim(x);
    // Bracket: from the inlet side, the first point with g < 0.
    let mut lo = -c + 1e-300_f64.max(c * 1e-14);
    let mut found = false;
    for i in 1..=200 {
        let x = -c + 2.0 * c * (i as f64 / 200.0).powi(4);
        if g(x) < 0.0 {
            lo = x;
            found = true;
            break;
        }
    }
    let xs = if !found {
        -c
    } else {
        let mut hi = c;
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if g(mid) < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    // ∫_{−c}^{X*} D·m·(1 − e^{−(X+c)/D}) dX and ∫_{−c}^{X*} X·(…) dX.
    let w = xs + c;
    let e = (-w / d).exp();
    let i0 = d * m * (w - d * (1.0 - e));
    // ∫ (X) (1 − e^{−(X+c)/D}) dX from −c to X*: with ξ = X + c,
    // ∫ (ξ − c)(1 − e^{−ξ/D}) dξ.
    let int_xi = w * w / 2.0 - (d * d * (1.0 - e) - d * w * e);
    let int_1 = w - d * (1.0 - e);
    let i1 = d * m * (int_xi - c * int_1);
    // Cap part: ∫_{X*}^{c} L dX = 1.5·[(X√(c²−X²) + c² asin(X/c))/2],
    // ∫ X·L dX = −0.5·(c² − X²)^{3/2}.
    let prim = |x: f64| {
        let r = (c * c - x * x).max(0.0).sqrt();
        0.75 * (x * r + c * c * (x / c).clamp(-1.0, 1.0).asin())
    };
    let l0 = prim(c) - prim(xs);
    let l1 = 0.5 * (c * c - xs * xs).max(0.0).powf(1.5);
    [ux * (i0 + l0), uy * (i0 + l0), uy * (i1 + l1)]
}

/// 4-point Gauss–Legendre rule on [−1, 1].
#[cfg(test)]
const GL4: [(f64, f64); 4] = [
    (-0.861_136_311_594_052_6, 0.347_854_845_137_453_8),
    (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_8),
];

/// Composite 4-point Gauss–Legendre in φ (Y = sin φ) over `panels` equal
/// panels of an exact strip functional.
#[cfg(test)]
pub(crate) fn contact_exact(
    p: &crate::ep::Scaled,
    panels: usize,
    mut f: impl FnMut(f64) -> [f64; 3],
) -> (f64, f64, f64) {
    let width = PI / panels as f64;
    let mut s = [0.0; 4];
    for i in 0..panels {
        let lo = -FRAC_PI_2 + i as f64 * width;
        let v = crate::ep::panel_sums(&GL4, lo, lo + width, &mut f);
        for (a, b) in s.iter_mut().zip(v) {
            *a += b;
        }
    }
    crate::ep::to_j(p.k, p.dx, &s)
}
