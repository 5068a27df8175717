//! One step along a strip and the events inside it: Shampine's four-stage
//! Rosenbrock method (order 4 with an embedded order-3 estimate) as
//! [`ros_step`] on either kind of segment ([`Seg`]), its tableau and the
//! closed-form coefficients of the strip sums' increments; the step's cubic
//! Hermite interpolant ([`hermite`], [`hermite_dt`]) and the location of an
//! event on it: a cap entry by [`event_newton`], an unloading by [`event`].
//! The strip loop (`strip.rs`) takes the steps, accepts or repeats them and
//! decides what happens at an event.

use super::segments::{Eval, Jac, Pt, Seg};

// Shampine's parameters of the four-stage Rosenbrock method (order 4,
// embedded order 3; L. F. Shampine, ACM TOMS 8 (1982) 93–113), in the
// form (I/(γh) − J)·U_i = f(σ + α_i h, u + Σ a_ij U_j) + Σ c_ij U_j/h + γ_i·h·f_σ.
const GAM: f64 = 0.5;
const A21: f64 = 2.0;
const A31: f64 = 48.0 / 25.0;
const A32: f64 = 6.0 / 25.0;
const C21: f64 = -8.0;
const C31: f64 = 372.0 / 25.0;
const C32: f64 = 12.0 / 5.0;
const C41: f64 = -112.0 / 125.0;
const C42: f64 = -54.0 / 125.0;
const C43: f64 = -2.0 / 5.0;
const B1: f64 = 19.0 / 9.0;
const B2: f64 = 1.0 / 2.0;
const B3: f64 = 25.0 / 108.0;
const B4: f64 = 125.0 / 108.0;
const E1: f64 = 17.0 / 54.0;
const E2: f64 = 7.0 / 36.0;
const E3: f64 = 0.0;
const E4: f64 = 125.0 / 108.0;
const G1: f64 = 1.0 / 2.0;
const G2: f64 = -3.0 / 2.0;
const G3: f64 = 121.0 / 50.0;
const G4: f64 = 29.0 / 250.0;
const ALPHA2: f64 = 1.0;
const ALPHA3: f64 = 3.0 / 5.0;

/// The strip sums' increments in closed form. Their stages do not enter the
/// right-hand side, so U_q,i = γh·P_i + γ·Σ_j c_ij·U_q,j with
/// P_i = fq_i + γ_i·h·tq + Gq·U_u,i, and Σ_i b_i·U_q,i = h·Σ_i b̃_i·P_i with
/// b̃ = γ·(I − γ·C)⁻ᵀ·b (C = (c_ij), strictly lower): the increment and its
/// error estimate are one combination of the stages' P each (the same
/// numbers as the stage-by-stage recursion, up to round-off).
const fn tilde(b: [f64; 4]) -> [f64; 4] {
    let x4 = GAM * b[3];
    let x3 = GAM * (b[2] + C43 * x4);
    let x2 = GAM * (b[1] + C32 * x3 + C42 * x4);
    let x1 = GAM * (b[0] + C21 * x2 + C31 * x3 + C41 * x4);
    [x1, x2, x3, x4]
}
/// b̃ and ẽ of the increments and of their error estimate.
const QB: [f64; 4] = tilde([B1, B2, B3, B4]);
const QE: [f64; 4] = tilde([E1, E2, E3, E4]);
/// Σ b̃_i·γ_i and Σ ẽ_i·γ_i (the factor of h·tq).
const QBG: f64 = QB[0] * G1 + QB[1] * G2 + QB[2] * G3 + QB[3] * G4;
const QEG: f64 = QE[0] * G1 + QE[1] * G2 + QE[2] * G3 + QE[3] * G4;

/// One Rosenbrock step: new state, quadrature increments, error estimate
/// (max norm of the state error × weight and the quadrature errors).
pub(super) struct Step<const N: usize> {
    /// σ + h.
    pub(super) p1: Pt,
    pub(super) u: [f64; N],
    pub(super) dq: [f64; 3],
    pub(super) err: f64,
}

// Fixed-size state arrays indexed in parallel (stages, Jacobian rows).
#[allow(clippy::needless_range_loop)]
#[inline(always)]
pub(super) fn ros_step<const N: usize, S: Seg<N>>(
    seg: &S,
    p: Pt,
    h: f64,
    u: &[f64; N],
    ev0: &Eval<N>,
    jac: &Jac<N>,
) -> Step<N> {
    let ih = 1.0 / h;
    // 1/(γh) by a multiplication (exact for γ = 1/2).
    let gi = ih * (1.0 / GAM);
    let wi = seg.inverse(gi, &jac.j);
    let mut th = [0.0; N];
    for k in 0..N {
        th[k] = h * jac.t[k];
    }
    // Stage: r = f + g·h·f_σ + Σ c_j·U_j/h; U = W⁻¹·r.
    let stage = |ev: &Eval<N>, g: f64, cu: [f64; N]| -> [f64; N] {
        let mut r = [0.0; N];
        for k in 0..N {
            r[k] = ev.f[k] + g * th[k] + ih * cu[k];
        }
        let mut uu = [0.0; N];
        for k in 0..N {
            for l in 0..N {
                uu[k] += wi[k][l] * r[l];
            }
        }
        uu
    };
    let u1 = stage(ev0, G1, [0.0; N]);
    let mut y = *u;
    let mut cu = [0.0; N];
    for k in 0..N {
        y[k] += A21 * u1[k];
        cu[k] = C21 * u1[k];
    }
    let (p1, p3) = p.advance2(ALPHA2 * h, ALPHA3 * h);
    let e2 = seg.eval(p1, &y);
    let u2 = stage(&e2, G2, cu);
    let mut y = *u;
    for k in 0..N {
        y[k] += A31 * u1[k] + A32 * u2[k];
        cu[k] = C31 * u1[k] + C32 * u2[k];
    }
    let e3 = seg.eval(p3, &y);
    let u3 = stage(&e3, G3, cu);
    for k in 0..N {
        cu[k] = C41 * u1[k] + C42 * u2[k] + C43 * u3[k];
    }
    let u4 = stage(&e3, G4, cu);
    let mut un = *u;
    let mut err = 0.0_f64;
    let mut sum = 0.0;
    let w = seg.weight(p);
    // Σ b̃_i·U_u,i and Σ ẽ_i·U_u,i for the sums' Gq terms.
    let mut sb = [0.0; N];
    let mut se = [0.0; N];
    for k in 0..N {
        un[k] += B1 * u1[k] + B2 * u2[k] + B3 * u3[k] + B4 * u4[k];
        let e = E1 * u1[k] + E2 * u2[k] + E3 * u3[k] + E4 * u4[k];
        err = err.max((w * e).abs());
        sum += un[k];
        sb[k] = QB[0] * u1[k] + QB[1] * u2[k] + QB[2] * u3[k] + QB[3] * u4[k];
        se[k] = QE[0] * u1[k] + QE[1] * u2[k] + QE[2] * u3[k] + QE[3] * u4[k];
    }
    // The strip sums (stages 3 and 4 evaluate f at the same point).
    let mut dq = [0.0; 3];
    let gb = seg.gq_dot(&jac.gq, &sb);
    let ge = seg.gq_dot(&jac.gq, &se);
    for i in 0..3 {
        let thq = h * jac.tq[i];
        let vb =
            QB[0] * ev0.fq[i] + QB[1] * e2.fq[i] + (QB[2] + QB[3]) * e3.fq[i] + QBG * thq + gb[i];
        let ve =
            QE[0] * ev0.fq[i] + QE[1] * e2.fq[i] + (QE[2] + QE[3]) * e3.fq[i] + QEG * thq + ge[i];
        dq[i] = h * vb;
        err = err.max((h * ve).abs());
        sum += dq[i];
    }
    if !sum.is_finite() || err.is_nan() {
        err = f64::INFINITY;
    }
    Step { p1, u: un, dq, err }
}

/// Cubic Hermite interpolant on [0, 1] (step h) of y with slopes m0, m1 (per σ).
#[inline]
pub(super) fn hermite(y0: f64, m0: f64, y1: f64, m1: f64, h: f64, t: f64) -> f64 {
    let t2 = t * t;
    let t3 = t2 * t;
    (2.0 * t3 - 3.0 * t2 + 1.0) * y0
        + (t3 - 2.0 * t2 + t) * h * m0
        + (-2.0 * t3 + 3.0 * t2) * y1
        + (t3 - t2) * h * m1
}

/// d/dt of [`hermite`].
#[inline]
pub(super) fn hermite_dt(y0: f64, m0: f64, y1: f64, m1: f64, h: f64, t: f64) -> f64 {
    let t2 = t * t;
    (6.0 * t2 - 6.0 * t) * (y0 - y1)
        + (3.0 * t2 - 4.0 * t + 1.0) * h * m0
        + (3.0 * t2 - 2.0 * t) * h * m1
}

/// The root of g on (0, 1) with g(0) = `g0` < 0 < g(1) = `g1` (a cap entry
/// inside a step) by Newton's method with the exact derivative (`gd(t)` =
/// (g, dg/dt)) from t = 1 (g = |H| − L at a cap entry; with |H|² − L² the
/// iterates approached the root from outside the cap except near the
/// outlet, see [`strip_sums`](super::strip::strip_sums)); a step that
/// leaves the bracket is replaced by regula falsi (bisection if that fails
/// too). Ends with the first Newton update below 1e-6, applied (the
/// convergence is quadratic: the bench cases' values are the same to 10
/// digits as with 1e-10, one evaluation fewer per entry), or a bracket narrower than 1e-10. On the
/// bench cases at tol = 1e-3 (with |H|² − L² and 1e-10): 5–9 evaluations
/// per entry on average, against 9.5–12 of [`event`] and 4–13 of Newton
/// from the secant point (13 in the anisotropic case g, whose g has a
/// minimum inside the step; docs/decisions/0048); with |H| − L 4 on case l,
/// where |H|² − L² took 12 (docs/decisions/0076).
// Inlined into `strip_sums`, as it was when both were in one file: called
// from another module it was not (case l +0.6 % instructions at tol 1e-3;
// inlined, the six bench cases −1.1…−1.8 % against the single file).
#[inline]
pub(super) fn event_newton(gd: impl Fn(f64) -> (f64, f64), g0: f64, g1: f64) -> f64 {
    let (mut a, mut fa, mut b, mut fb) = (0.0, g0, 1.0, g1);
    let mut t = 1.0;
    for _ in 0..60 {
        let (v, dv) = gd(t);
        let mut tn = t - v / dv;
        if v == 0.0 || (tn - t).abs() < 1e-6 {
            return tn.clamp(a, b);
        }
        if v < 0.0 {
            (a, fa) = (t, v);
        } else {
            (b, fb) = (t, v);
        }
        if !(tn > a && tn < b) {
            tn = (a * fb - b * fa) / (fb - fa);
            if !(tn > a && tn < b) {
                tn = 0.5 * (a + b);
            }
        }
        if b - a < 1e-10 {
            return b;
        }
        t = tn;
    }
    b
}

/// The root of g on (0, 1] with g(1) > 0 (an event inside a step): a point
/// with g < 0 is searched from t = 1/2 downwards (g(0) may be 0, at the
/// inlet or at an unloading point), then Illinois regula falsi. Returns 0
/// when no such point exists (the event is at the step's start).
pub(super) fn event(g: impl Fn(f64) -> f64, g1: f64) -> f64 {
    let (mut a, mut fa) = (0.0, 0.0);
    let mut t = 0.5;
    let mut found = false;
    for _ in 0..50 {
        let v = g(t);
        if v < 0.0 {
            (a, fa) = (t, v);
            found = true;
            break;
        }
        t *= 0.5;
    }
    if !found {
        return 0.0;
    }
    let (mut b, mut fb) = (1.0, g1);
    // Illinois: halve the retained end's value when the same end is kept
    // twice in a row.
    let mut side = 0;
    for _ in 0..60 {
        let m = (a * fb - b * fa) / (fb - fa);
        let m = if m.is_finite() && m > a && m < b {
            m
        } else {
            0.5 * (a + b)
        };
        let fm = g(m);
        if fm < 0.0 {
            (a, fa) = (m, fm);
            if side == -1 {
                fb *= 0.5;
            }
            side = -1;
        } else {
            (b, fb) = (m, fm);
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        }
        if b - a < 1e-10 {
            break;
        }
    }
    b
}
