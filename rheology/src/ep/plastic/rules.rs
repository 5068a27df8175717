//! The one-step rules of a plastic segment, each advancing a state
//! (`PState`: s, the direction n and the strip sums) by one step h:
//! [`Strip::rk4`], the default step; [`Strip::rk5`], Butcher's fifth-order
//! rule, for equal steps on moderately stiff segments; [`Strip::etd`], the
//! exponential step on stiff isotropic segments whose slip direction turns
//! slowly (with [`phi_functions`]); [`Strip::quasi_steady`], the stiff limit
//! along the direction [`Strip::qs_dir`], and [`blend`], which blends it in.
//! Also the bounds by which the segment driver (`mod.rs`) chooses among
//! them, [`Strip::rates`] ((κ·h, |α'|·h) over a step), and
//! [`sin_cos_small`] for the step's half angle. None of them tests for
//! unloading: the driver's `Strip::step_end` does, after every step.

use super::super::{CS_MIN, PState, Strip, StripSums};

/// Factor on the anisotropic relaxation rate at the step's directions
/// (`Strip::aniso_rate`): the direction moves between them within a step.
const ANISO_RATE_SAFETY: f64 = 1.25;

/// (sin x, cos x) of a (half) step angle: Taylor polynomials for |x| ≤ 1/2,
/// whose truncation error (< x¹⁷/17! ≈ 2e-20 for sin, x¹⁸/18! for cos) is
/// far below the rounding of f64, so the result agrees with the library's
/// sin/cos to within an ulp or two at a third of the cost; larger angles
/// use the library.
#[inline]
pub(super) fn sin_cos_small(x: f64) -> (f64, f64) {
    if x.abs() > 0.5 {
        return x.sin_cos();
    }
    let x2 = x * x;
    // Horner in x²: sin x = x·Σ (−x²)^i/(2i+1)!, cos x = Σ (−x²)^i/(2i)!.
    let s = x
        * (1.0
            - x2 / 6.0
                * (1.0
                    - x2 / 20.0
                        * (1.0
                            - x2 / 42.0
                                * (1.0
                                    - x2 / 72.0
                                        * (1.0
                                            - x2 / 110.0
                                                * (1.0 - x2 / 156.0 * (1.0 - x2 / 210.0)))))));
    let c = 1.0
        - x2 / 2.0
            * (1.0
                - x2 / 12.0
                    * (1.0
                        - x2 / 30.0
                            * (1.0
                                - x2 / 56.0
                                    * (1.0
                                        - x2 / 90.0
                                            * (1.0
                                                - x2 / 132.0
                                                    * (1.0 - x2 / 182.0 * (1.0 - x2 / 240.0)))))));
    (s, c)
}

/// (sin x, cos x) of a small angle: for |x| ≤ 1/16 Taylor polynomials of
/// degree 7 and 8, whose truncation error (< x⁹/9! ≈ 4e-17) is below the
/// rounding of f64 (half the dependent operations of [`sin_cos_small`],
/// on the chain of `Strip::rodas3_lag`, whose lag increments per step are
/// mostly below 1e-2); larger angles as [`sin_cos_small`].
#[inline]
fn sin_cos_lag(x: f64) -> (f64, f64) {
    if x.abs() > 0.0625 {
        return sin_cos_small(x);
    }
    let x2 = x * x;
    let s = x * (1.0 - x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0)));
    let c = 1.0 - x2 / 2.0 * (1.0 - x2 / 12.0 * (1.0 - x2 / 30.0 * (1.0 - x2 / 56.0)));
    (s, c)
}

/// Newton on the anisotropic quasi-steady direction (`qs_dir`): iterations,
/// central-difference step in θ, convergence in θ (rad) and the largest
/// correction from the isotropic guess that is still trusted (rad).
const QS_NEWTON_ITERATIONS: usize = 4;
const QS_DIFF_STEP: f64 = 1e-6;
const QS_NEWTON_TOL: f64 = 1e-12;
const QS_MAX_CORRECTION: f64 = 0.5;

/// RODAS3's coefficients c_ij (stages 2–4) and γ_i (stages 1–2; 0 for 3
/// and 4) in the form of `Strip::rodas3_lag`, with a21 = a32 = a42 = 0,
/// a31 = a41 = 2, a43 = 1, weights (2, 0, 1, 1) and γ = 1/2 (Sandu et al.
/// 1997; Hairer & Wanner, Solving Ordinary Differential Equations II,
/// sect. IV.7). A test checks its third order and R(∞) = 0.
pub(super) const RD3_C21: f64 = 4.0;
pub(super) const RD3_C31: f64 = 1.0;
pub(super) const RD3_C32: f64 = -1.0;
pub(super) const RD3_C41: f64 = 1.0;
pub(super) const RD3_C42: f64 = -1.0;
pub(super) const RD3_C43: f64 = -8.0 / 3.0;
pub(super) const RD3_GAMMA_I: (f64, f64) = (0.5, 1.5);

/// The 3-point Gauss–Legendre rule on [−1, 1]: nodes ±GL3_X = ±√(3/5) and
/// 0, weights GL3_W (outer, middle).
const GL3_X: f64 = 0.774_596_669_241_483_4;
const GL3_W: (f64, f64) = (5.0 / 9.0, 8.0 / 9.0);
/// The quadratic Lagrange basis through τ = 0, 1/2, 1 at the outer node
/// τ = (1 − GL3_X)/2: the weights of the values at τ = 0, 1/2 and 1 (at the
/// other outer node those of τ = 0 and 1 swap).
const GL3_LAGRANGE: [f64; 3] = lagrange3((1.0 - GL3_X) / 2.0);

/// The quadratic Lagrange basis through τ = 0, 1/2, 1, at τ.
const fn lagrange3(t: f64) -> [f64; 3] {
    [
        2.0 * (t - 0.5) * (t - 1.0),
        -4.0 * t * (t - 1.0),
        2.0 * t * (t - 0.5),
    ]
}

impl Strip {
    /// One RK4 step of length h; (c2, s2) = (cos h/2, sin h/2).
    ///
    /// The integrands of the strip sums are Zx·dX/ds = w·nx, Zy·dX/ds = w·ny
    /// and Zy·X·dX/ds = w·X·ny with w = L·dX/ds = (3/2)c²cos²s; the two
    /// midpoint stages share their node quantities.
    #[inline(always)]
    pub(super) fn rk4<const ISO: bool>(&self, p: &PState, h: f64, c2: f64, s2: f64) -> PState {
        crate::counts::count!(rk4);
        let c = self.c;
        let (sm, cm) = (p.sn * c2 + p.cs * s2, p.cs * c2 - p.sn * s2);
        let (s1, c1) = (sm * c2 + cm * s2, (cm * c2 - sm * s2).max(0.0));
        let (x0, xm, x1) = (c * p.sn, c * sm, c * s1);
        let w = 1.5 * c * c;
        let (w0, wm, w1) = (w * p.cs * p.cs, w * cm * cm, w * c1 * c1);
        let k = 2.0 / 3.0;
        let av = k * self.a;
        let (vy0, vym, vy1) = (k * self.vy(x0), k * self.vy(xm), k * self.vy(x1));
        // Anisotropic stiffness: the λ·t·G·n part of `theta_rate` (k·(3/2)·
        // tan s at the three nodes, capped like there).
        // Anisotropic stiffness: tan s at the three nodes (capped, see
        // `theta_rate`).
        let tan = |sn: f64, cs: f64| sn / cs.max(CS_MIN);
        let (t0, tm, t1) = if !self.iso::<ISO>() {
            (tan(p.sn, p.cs), tan(sm, cm), tan(s1, c1))
        } else {
            (0.0, 0.0, 0.0)
        };
        let om = |vy: f64, t: f64, nx: f64, ny: f64| self.flow_rate::<ISO>(vy, av, t, nx, ny);
        let hh = 0.5 * h;
        // Stage 1 at s0.
        let (n1x, n1y) = (p.nx, p.ny);
        let om1 = om(vy0, t0, n1x, n1y);
        // Stage 2 at the midpoint.
        let (n2x, n2y) = (n1x - hh * om1 * n1y, n1y + hh * om1 * n1x);
        let om2 = om(vym, tm, n2x, n2y);
        // Stage 3 at the midpoint.
        let (n3x, n3y) = (n1x - hh * om2 * n2y, n1y + hh * om2 * n2x);
        let om3 = om(vym, tm, n3x, n3y);
        // Stage 4 at s1.
        let (n4x, n4y) = (n1x - h * om3 * n3y, n1y + h * om3 * n3x);
        let om4 = om(vy1, t1, n4x, n4y);
        let h6 = h / 6.0;
        let nx = n1x - h6 * (om1 * n1y + 2.0 * om2 * n2y + 2.0 * om3 * n3y + om4 * n4y);
        let ny = n1y + h6 * (om1 * n1x + 2.0 * om2 * n2x + 2.0 * om3 * n3x + om4 * n4x);
        // Normalised here, before the sums, rather than by
        // `PState::normalised` after them: the same results, but that order
        // costs the bench cases 0.7–1 % more instructions.
        let r = (nx * nx + ny * ny).sqrt();
        let (mx, my) = (2.0 * wm * (n2x + n3x), 2.0 * wm * (n2y + n3y));
        let mut acc = p.acc;
        acc.ix += h6 * (w0 * n1x + mx + w1 * n4x);
        acc.iy += h6 * (w0 * n1y + my + w1 * n4y);
        acc.ixy += h6 * (x0 * w0 * n1y + xm * my + x1 * w1 * n4y);
        PState {
            sn: s1,
            cs: c1,
            nx: nx / r,
            ny: ny / r,
            acc,
        }
    }

    /// One step of length h of Butcher's six-stage fifth-order rule,
    /// (c4, s4) = (cos h/4, sin h/4): a21 = 1/4; a31 = a32 = 1/8;
    /// (a41, a42, a43) = (0, −1/2, 1); (a51..a54) = (3, 0, 0, 9)/16;
    /// (a61..a65) = (−3, 2, 12, −12, 8)/7; nodes 0, 1/4, 1/4, 1/2, 3/4, 1
    /// and weights (7, 0, 32, 12, 32, 7)/90 (Boole's rule);
    /// its 17 conditions of order 5 (Hairer, Nørsett & Wanner, Solving
    /// Ordinary Differential Equations I, ch. II) are checked by a test, its
    /// fifth order on a plastic segment by another. The strip sums are
    /// integrated with the same stages, as in [`Strip::rk4`]; the stability
    /// function 1 + z + … + z⁵/120 + z⁶/640 bounds the real stability
    /// interval at κ·h = 3.39 (RK4: 2.79).
    #[inline(always)]
    pub(super) fn rk5<const ISO: bool>(&self, p: &PState, h: f64, c4: f64, s4: f64) -> PState {
        crate::counts::count!(rk5);
        // Written stage by stage, each stage's contributions to the later
        // stages, the new direction and the strip sums accumulated as soon
        // as it is known (fewer live values).
        let c = self.c;
        let k = 2.0 / 3.0;
        let av = k * self.a;
        let w = 1.5 * c * c;
        let tan = |sn: f64, cs: f64| {
            if self.iso::<ISO>() {
                0.0
            } else {
                sn / cs.max(CS_MIN)
            }
        };
        // dn/ds = ω·(−ny, nx) at the node (sn, cs).
        let kv = |sn: f64, cs: f64, nx: f64, ny: f64| {
            let om = self.flow_rate::<ISO>(k * self.vy(c * sn), av, tan(sn, cs), nx, ny);
            (-om * ny, om * nx)
        };
        // Strip-sum integrands w·n times the weight wt/90 at the node.
        let mut acc = p.acc;
        let h90 = h / 90.0;
        let mut add = |sn: f64, cs: f64, wt: f64, nx: f64, ny: f64| {
            let f = h90 * wt * w * cs * cs;
            let fy = f * ny;
            acc.ix += f * nx;
            acc.iy += fy;
            acc.ixy += c * sn * fy;
        };
        let rot = |sn: f64, cs: f64| (sn * c4 + cs * s4, cs * c4 - sn * s4);
        let (n1x, n1y) = (p.nx, p.ny);
        // Stage 1 at s0.
        add(p.sn, p.cs, 7.0, n1x, n1y);
        let k1 = kv(p.sn, p.cs, n1x, n1y);
        let mut un = (7.0 * k1.0, 7.0 * k1.1);
        let mut u5 = (3.0 * k1.0, 3.0 * k1.1);
        let mut u6 = (-3.0 * k1.0, -3.0 * k1.1);
        // Stages 2 and 3 at s0 + h/4.
        let (sa, ca) = rot(p.sn, p.cs);
        let q = 0.25 * h;
        let k2 = kv(sa, ca, n1x + q * k1.0, n1y + q * k1.1);
        let e = 0.125 * h;
        let (n3x, n3y) = (n1x + e * (k1.0 + k2.0), n1y + e * (k1.1 + k2.1));
        u6 = (u6.0 + 2.0 * k2.0, u6.1 + 2.0 * k2.1);
        add(sa, ca, 32.0, n3x, n3y);
        let k3 = kv(sa, ca, n3x, n3y);
        un = (un.0 + 32.0 * k3.0, un.1 + 32.0 * k3.1);
        u6 = (u6.0 + 12.0 * k3.0, u6.1 + 12.0 * k3.1);
        // Stage 4 at s0 + h/2.
        let (sm, cm) = rot(sa, ca);
        let (n4x, n4y) = (n1x + h * (k3.0 - 0.5 * k2.0), n1y + h * (k3.1 - 0.5 * k2.1));
        add(sm, cm, 12.0, n4x, n4y);
        let k4 = kv(sm, cm, n4x, n4y);
        un = (un.0 + 12.0 * k4.0, un.1 + 12.0 * k4.1);
        u5 = (u5.0 + 9.0 * k4.0, u5.1 + 9.0 * k4.1);
        u6 = (u6.0 - 12.0 * k4.0, u6.1 - 12.0 * k4.1);
        // Stage 5 at s0 + 3h/4.
        let (sb, cb) = rot(sm, cm);
        let g = h / 16.0;
        let (n5x, n5y) = (n1x + g * u5.0, n1y + g * u5.1);
        add(sb, cb, 32.0, n5x, n5y);
        let k5 = kv(sb, cb, n5x, n5y);
        un = (un.0 + 32.0 * k5.0, un.1 + 32.0 * k5.1);
        // Stage 6 at s0 + h.
        let (s1, c1) = rot(sb, cb);
        let c1 = c1.max(0.0);
        let f = h / 7.0;
        let (n6x, n6y) = (n1x + f * (u6.0 + 8.0 * k5.0), n1y + f * (u6.1 + 8.0 * k5.1));
        add(s1, c1, 7.0, n6x, n6y);
        let k6 = kv(s1, c1, n6x, n6y);
        let nx = n1x + h90 * (un.0 + 7.0 * k6.0);
        let ny = n1y + h90 * (un.1 + 7.0 * k6.1);
        PState::normalised(s1, c1, (nx, ny), acc)
    }

    /// One exponential step of length h (cos/sin of h/2 given) for an
    /// isotropic stiffness, or None where it does not apply (the stress
    /// direction more than π/2 from the slip direction, or v = 0).
    ///
    /// With φ = α − θ the angle of the stress direction n behind the slip
    /// direction v̂ (angle α), dθ/ds = κ·sin φ (κ = (2/3)|v|), and
    /// t = tan(φ/2) obeys the Riccati equation t' = β(1 + t²) − κ·t,
    /// β = α'/2. Cox and Matthews' exponential RK4 (ETDRK4) with the linear
    /// part −κ̄·t frozen at the step's midpoint integrates the relaxation
    /// exactly; the rest, β(1 + t²) − (κ − κ̄)·t, is small and smooth where
    /// the slip direction turns slowly. The strip sums ∫w·n ds and
    /// ∫X·w·n ds (w = (3/2)c²cos²s) take the 3-point Gauss–Legendre rule,
    /// n by its quadratic through the step's start, the mean of the two
    /// midpoint stages and the end, w and X exact at the nodes: over the
    /// long steps this method takes (up to 0.8) Simpson's rule on the
    /// stages, as in [`Strip::rk4`], was off by ≈ h⁵/2880·|(X·w)⁗| per
    /// step, which on nearly fully plastic strips (large side slip, small
    /// spin) left ∫Zy·X dX, a small difference of large parts, 70 % off and
    /// J6 at k = 0.063 off by 0.99·tol at tol 1e-3 (Gauss: ≈
    /// h⁷/2016000·|(X·w)⁽⁶⁾|, 140 times less there).
    #[inline(never)]
    pub(super) fn etd(&self, p: &PState, h: f64, c2: f64, s2: f64) -> Option<PState> {
        crate::counts::count!(exponential);
        let c = self.c;
        let (sm, cm) = (p.sn * c2 + p.cs * s2, p.cs * c2 - p.sn * s2);
        let (s1, c1) = (sm * c2 + cm * s2, (cm * c2 - sm * s2).max(0.0));
        let a = self.a;
        let aq = 0.5 * a * self.q2 * c;
        // (κ, β, v̂) at a node.
        let node = |sn: f64, cs: f64| {
            let vy = self.vy(c * sn);
            let v2 = a * a + vy * vy;
            let r = v2.sqrt();
            ((2.0 / 3.0) * r, aq * cs / v2, a / r, vy / r)
        };
        let (k0, b0, ux0, uy0) = node(p.sn, p.cs);
        let (km, bm, uxm, uym) = node(sm, cm);
        let (k1, b1, ux1, uy1) = node(s1, c1);
        // v ≠ 0 at the nodes, and the slip direction turning by less than
        // π/2 between them (t is measured from it; a segment qualifies only
        // where it turns slowly, so this is a guard).
        if !(k0 > 0.0 && km > 0.0 && k1 > 0.0)
            || ux0 * uxm + uy0 * uym <= 0.0
            || uxm * ux1 + uym * uy1 <= 0.0
        {
            return None;
        }
        let cphi = ux0 * p.nx + uy0 * p.ny;
        if cphi.is_nan() || cphi < 0.0 {
            return None;
        }
        let t0 = (uy0 * p.nx - ux0 * p.ny) / (1.0 + cphi);
        let z = -km * h;
        let e2 = (0.5 * z).exp();
        let e = e2 * e2;
        let (q1, _, _) = phi_functions(0.5 * z, e2);
        let q = 0.5 * h * q1;
        let (f1, f2, f3) = {
            let (p1, p2, p3) = phi_functions(z, e);
            (p1 - 3.0 * p2 + 4.0 * p3, p2 - 2.0 * p3, 4.0 * p3 - p2)
        };
        let nl = |b: f64, k: f64, t: f64| b * (1.0 + t * t) - (k - km) * t;
        let n0 = nl(b0, k0, t0);
        let ta = e2 * t0 + q * n0;
        let na = nl(bm, km, ta);
        let tb = e2 * t0 + q * na;
        let nb = nl(bm, km, tb);
        let tc = e2 * ta + q * (2.0 * nb - n0);
        let nc = nl(b1, k1, tc);
        let t1 = e * t0 + h * (f1 * n0 + 2.0 * f2 * (na + nb) + f3 * nc);
        if !(t1.abs() <= 1.0 && ta.abs() <= 1.0 && tb.abs() <= 1.0 && tc.abs() <= 1.0) {
            return None;
        }
        // n = v̂ rotated by −φ: cos φ = (1 − t²)/(1 + t²), sin φ = 2t/(1 + t²).
        let dir = |t: f64, ux: f64, uy: f64| {
            let d = 1.0 / (1.0 + t * t);
            let (cp, sp) = ((1.0 - t * t) * d, 2.0 * t * d);
            (ux * cp + uy * sp, uy * cp - ux * sp)
        };
        let (nax, nay) = dir(ta, uxm, uym);
        let (nbx, nby) = dir(tb, uxm, uym);
        let (nx, ny) = dir(t1, ux1, uy1);
        // The strip sums: n as the quadratic through the step's start, the
        // midpoint stages' mean and its end, the weights w = (3/2)c²cos²s
        // and X·w exact at the nodes m ∓ (h/2)·GL3_X and m.
        let (nmx, nmy) = (0.5 * (nax + nbx), 0.5 * (nay + nby));
        let hh = 0.5 * h;
        let (sd, cd) = sin_cos_small(hh * GL3_X);
        let (sa, ca) = (sm * cd - cm * sd, cm * cd + sm * sd);
        let (sb, cb) = (sm * cd + cm * sd, cm * cd - sm * sd);
        let [l0, lm, l1] = GL3_LAGRANGE;
        let (n1x, n1y) = (
            l0 * p.nx + lm * nmx + l1 * nx,
            l0 * p.ny + lm * nmy + l1 * ny,
        );
        let (n2x, n2y) = (
            l1 * p.nx + lm * nmx + l0 * nx,
            l1 * p.ny + lm * nmy + l0 * ny,
        );
        let w = 1.5 * c * c * hh;
        let (wa, wm, wb) = (
            GL3_W.0 * w * ca * ca,
            GL3_W.1 * w * cm * cm,
            GL3_W.0 * w * cb * cb,
        );
        let mut acc = p.acc;
        acc.ix += wa * n1x + wm * nmx + wb * n2x;
        acc.iy += wa * n1y + wm * nmy + wb * n2y;
        acc.ixy += c * (wa * sa * n1y + wm * sm * nmy + wb * sb * n2y);
        Some(PState {
            sn: s1,
            cs: c1,
            nx,
            ny,
            acc,
        })
    }

    /// One step of length h of RODAS3 (Sandu et al., Atmospheric
    /// Environment 31 (1997) 3459–3472: four stages, order 3, L-stable and
    /// stiffly accurate, three evaluations) on the lag φ = α − θ of the
    /// stress direction behind the slip direction, dφ/ds = α' − κ·sin φ
    /// (isotropic stiffness; κ = (2/3)|v|, α' = a·q2·c·cos s/|v|², both in
    /// closed form at any s). On a relaxed stiff segment φ stays near
    /// asin(α'/κ), small and slowly varying, so the step follows the turn
    /// of the slip direction exactly and its error is that of φ, not of θ:
    /// on the strip at Y = 0.623 of the state at rest (k = 1, J = (220, 0,
    /// 866)) 1e-7 … 8e-6 rad per step of 0.056, against 1e-5 … 1.5e-4 for
    /// the same method on θ. The new direction is v̂ rotated by −φ; the
    /// strip sums come from Simpson's rule, the lag at the midpoint from
    /// the cubic Hermite interpolant of φ over the step (docs/decisions/0114:
    /// the corrected trapezoidal rule from the ends' values and slopes saves
    /// a square root, but on the strip next to the pole's at J3 = 100,
    /// h = 0.3, its sums were 2e-4 off, Simpson's 5e-5). Returns the new
    /// state and the method's error estimate |U4| of φ (rad; the difference
    /// from its embedded second-order solution), which is 3–5 times the
    /// actual error where measured; ∞ where cos φ0 < 1/2. The caller
    /// excludes the pole's strip (a = 0, where v̂ flips at vy = 0).
    #[inline(always)]
    pub(super) fn rodas3_lag(&self, p: &PState, h: f64, c2: f64, s2: f64) -> (PState, f64) {
        crate::counts::count!(rosenbrock);
        let c = self.c;
        let a = self.a;
        let qc = self.q2 * c;
        let aq = a * qc;
        let k = 2.0 / 3.0;
        let (sm, cm) = (p.sn * c2 + p.cs * s2, p.cs * c2 - p.sn * s2);
        let (s1, c1) = (sm * c2 + cm * s2, (cm * c2 - sm * s2).max(0.0));
        let (x0, x1) = (c * p.sn, c * s1);
        let (vy0, vy1) = (self.vy(x0), self.vy(x1));
        let (m20, m21) = (a * a + vy0 * vy0, a * a + vy1 * vy1);
        // f0 = α' − κ·sin φ0, ∂f/∂φ = −κ·cos φ0 and ∂f/∂s at s0 from
        // κ·(sin φ0, cos φ0) = (2/3)·(v × n, v·n) and 1/|v|², without the
        // square root (the stages' chain of dependent operations starts
        // here; v̂ is needed only from stage 3 on).
        let i20 = 1.0 / m20;
        let (vxn, vdn) = (vy0 * p.nx - a * p.ny, a * p.nx + vy0 * p.ny);
        let al0 = aq * p.cs * i20;
        let f0 = al0 - k * vxn;
        let jac = -k * vdn;
        // dα'/ds and dκ/ds·sin φ0 at fixed φ.
        let dal = -aq * i20 * (p.sn + 2.0 * p.cs * p.cs * vy0 * qc * i20);
        let dks = k * vy0 * qc * p.cs * vxn * i20;
        let th = h * (dal - dks);
        // v̂, α' and κ at s1; sin φ0, cos φ0.
        let (im0, im1) = (1.0 / m20.sqrt(), 1.0 / m21.sqrt());
        let (ux1, uy1) = (a * im1, vy1 * im1);
        let al1 = aq * c1 * im1 * im1;
        let k1 = k * m21 * im1;
        let (sp0, cp0) = (vxn * im0, vdn * im0);
        // The stages as increments of φ from φ0, (1/(γh) − J)·U_i = f_i +
        // Σ c_ij·U_j/h + γ_i·h·∂f/∂s with γ = 1/2: U_i = h·d·(…) + d·Σ c_ij·U_j,
        // d = 1/(2 − h·J) (> 0 where the lag is below π/2).
        let d = 1.0 / (2.0 - h * jac);
        let hd = h * d;
        let u1 = hd * (f0 + RD3_GAMMA_I.0 * th);
        let u2 = hd * (f0 + RD3_GAMMA_I.1 * th) + d * RD3_C21 * u1;
        // sin and cos of φ0 + δ.
        let lag = |dl: f64| {
            let (sd, cd) = sin_cos_lag(dl);
            (sp0 * cd + cp0 * sd, cp0 * cd - sp0 * sd)
        };
        // Stages 3 and 4 at s1 (a31 = 2, a41 = 2, a43 = 1).
        let d3 = 2.0 * u1;
        let f3 = al1 - k1 * lag(d3).0;
        let u3 = hd * f3 + d * (RD3_C31 * u1 + RD3_C32 * u2);
        let d4 = d3 + u3;
        let f4 = al1 - k1 * lag(d4).0;
        let u4 = hd * f4 + d * (RD3_C41 * u1 + RD3_C42 * u2 + RD3_C43 * u3);
        // n = v̂ rotated by −φ.
        let dir = |ux: f64, uy: f64, (sp, cp): (f64, f64)| (ux * cp + uy * sp, uy * cp - ux * sp);
        // Stiffly accurate: φ1 = φ0 + 2·U1 + U3 + U4.
        let (sp1, cp1) = lag(d4 + u4);
        let (nx, ny) = dir(ux1, uy1, (sp1, cp1));
        // The strip sums, F = w·(nx, ny, X·ny), w = (3/2)·c²·cos² s, by
        // Simpson's rule; the lag at the midpoint from the cubic Hermite
        // interpolant of φ (slopes f0 and f(s1, φ1)), v̂ there exact.
        let dm = 0.5 * (d4 + u4) + 0.125 * h * (f0 - (al1 - k1 * sp1));
        let xm = c * sm;
        let vym = self.vy(xm);
        let imm = 1.0 / (a * a + vym * vym).sqrt();
        let (nmx, nmy) = dir(a * imm, vym * imm, lag(dm));
        let w = 1.5 * c * c;
        let (w0, wm, w1) = (w * p.cs * p.cs, 4.0 * w * cm * cm, w * c1 * c1);
        let h6 = h / 6.0;
        let mut acc = p.acc;
        acc.ix += h6 * (w0 * p.nx + wm * nmx + w1 * nx);
        acc.iy += h6 * (w0 * p.ny + wm * nmy + w1 * ny);
        acc.ixy += h6 * (w0 * x0 * p.ny + wm * xm * nmy + w1 * x1 * ny);
        let q = PState {
            sn: s1,
            cs: c1,
            nx,
            ny,
            acc,
        };
        // Relaxed flow only: where the stress direction is more than 60°
        // from the slip's (a stress left behind by a reversal of the slip,
        // which unloads), no estimate (the caller takes RK4 sub-steps).
        let est = if cp0 >= 0.5 { u4.abs() } else { f64::INFINITY };
        (q, est)
    }

    /// Quasi-steady direction (stiff limit): v̂ rotated by −asin(α'/κ).
    #[inline]
    fn qs_dir(&self, sn: f64, cs: f64) -> (f64, f64) {
        let x = self.c * sn;
        // The stiff limit follows the slip velocity v = (a, vy/gy).
        let (vx, vy) = (self.a, self.vy(x) / self.gy);
        // |v| by the square root of the sum of squares (hypot's scaling is
        // needed only where the squares leave the float range: |J| < 1e12
        // here, J_RIGID, so only for |v| < 1e-150).
        let m2 = vx * vx + vy * vy;
        let m = if m2 > 1e-300 { m2.sqrt() } else { vx.hypot(vy) };
        if m == 0.0 || !m.is_finite() {
            return if m.is_finite() {
                (1.0, 0.0)
            } else {
                (vx.signum() * 0.0 + 1.0, 0.0)
            };
        }
        // One division: 1/|v| (the divisions by |v| were a chain of three).
        let im = 1.0 / m;
        let (ux, uy) = (vx * im, vy * im);
        // α' = dα/ds = vx·(dvy/ds)/|v|², κ = (2/3)|v|.
        let alpha_s = ux * self.q2 / self.gy * self.c * cs * im;
        let sd = (-alpha_s * 1.5 * im).clamp(-1.0, 1.0);
        let cd = (1.0 - sd * sd).sqrt();
        let iso = (ux * cd - uy * sd, ux * sd + uy * cd);
        if self.gy == 1.0 {
            return iso;
        }
        // Anisotropic stiffness: the quasi-steady direction solves
        // dθ/ds (theta_rate) = α' — the isotropic formula above only to
        // leading order (its lag is wrong by O(|gy − 1|/|v|), ≈ 1e-3 in J5 at
        // |J| ≈ 250). Newton from the isotropic guess, central-difference
        // derivative; kept only if it converges near the guess.
        let (sn_, cs_) = (sn, cs);
        let f = |th: f64| {
            let (s_, c_) = th.sin_cos();
            self.theta_rate(sn_, cs_, c_, s_) - alpha_s
        };
        let th0 = iso.1.atan2(iso.0);
        let mut th = th0;
        for _ in 0..QS_NEWTON_ITERATIONS {
            let e = QS_DIFF_STEP;
            let d = (f(th + e) - f(th - e)) / (2.0 * e);
            if d == 0.0 || !d.is_finite() {
                return iso;
            }
            let step = f(th) / d;
            th -= step;
            if !th.is_finite() || (th - th0).abs() > QS_MAX_CORRECTION {
                return iso;
            }
            if step.abs() < QS_NEWTON_TOL {
                break;
            }
        }
        let (s_, c_) = th.sin_cos();
        (c_, s_)
    }

    /// (κ·h, |α'|·h) bounds over a step from s0 to s1: κ = (2/3)|v| is
    /// largest at an end (vy is linear in X), the rotation rate
    /// α' = a·q2·c·cos s/|v|² largest where |vy| is smallest.
    #[inline]
    pub(super) fn rates<const ISO: bool>(
        &self,
        sn0: f64,
        cs0: f64,
        sn1: f64,
        cs1: f64,
        h: f64,
    ) -> (f64, f64) {
        let (kh, ah) = self.rates_but_tan::<ISO>(sn0, cs0, sn1, cs1, h);
        if self.iso::<ISO>() {
            return (kh, ah);
        }
        // The (3/2)·tan s part of the anisotropic bound (tan s largest at
        // s1; see `outlet_tan` for a step that ends near the outlet).
        let tan1 = sn1.abs() / cs1.max(CS_MIN);
        (kh + self.aniso_f() * tan1.min(outlet_tan(sn0, cs0)) * h, ah)
    }

    /// |gy − 1|/min(1, gy): the anisotropic part of the stiffness bound,
    /// relative to the isotropic rate (`rates`).
    #[inline(always)]
    pub(super) fn aniso_f(&self) -> f64 {
        (self.gy - 1.0).abs() / self.gy.min(1.0)
    }

    /// [`Strip::rates`] without the anisotropic bound's tan s term, which
    /// the caller adds (a whole segment counts it at its own nodes).
    #[inline]
    pub(super) fn rates_but_tan<const ISO: bool>(
        &self,
        sn0: f64,
        cs0: f64,
        sn1: f64,
        cs1: f64,
        h: f64,
    ) -> (f64, f64) {
        let (vy0, vy1) = (self.vy(self.c * sn0), self.vy(self.c * sn1));
        let a2 = self.a * self.a;
        let mut kh = (2.0 / 3.0) * (a2 + vy0.abs().max(vy1.abs()).powi(2)).sqrt() * h;
        if !self.iso::<ISO>() {
            // The λ·t·G·n part of `theta_rate` relaxes θ too: bound its rate
            // by |gy − 1|/min(1, gy)·(|e| + (3/2)tan s); here the |e| part.
            kh *= 1.0 + self.aniso_f();
        }
        // The slip direction v = (a, vy/gy) turns at
        // α' = a·(q2/gy)·c·cos s/(a² + (vy/gy)²).
        let (vy0, vy1, q2) = (vy0 / self.gy, vy1 / self.gy, self.q2 / self.gy);
        // Selects rather than branches (the crossing of vy = 0 is not
        // predictable along a strip near the pole).
        let cross = (vy0 < 0.0) != (vy1 < 0.0);
        let vmin = if cross { 0.0 } else { vy0.abs().min(vy1.abs()) };
        let cmax = if cross { 1.0 } else { cs0.max(cs1) };
        let num = (self.a * q2 * self.c).abs() * cmax * h;
        let den = a2 + vmin * vmin;
        // num ≥ 0 and den ≥ 0: num/den is +∞ where den = 0 < num.
        let ah = if num == 0.0 { 0.0 } else { num / den };
        (kh, ah)
    }

    /// A bound of |∂θ'/∂θ|·h over a step from `p` to (sn1, cs1) for an
    /// anisotropic stiffness, at the directions the step can take: the
    /// step's start direction and the slip directions v̂ = (a, vy/gy)/|·| at
    /// its ends (the quasi-steady attractor), times ANISO_RATE_SAFETY. With
    /// E = e·n, P = t·e (scaled by 2/3) and H = nx·ny/(nx² + gy·ny²),
    /// dθ/ds = P − (gy − 1)·H·(E + tan s), so
    /// −∂θ'/∂θ = E + (gy − 1)·(H′·(E + tan s) + H·P); for a fixed direction
    /// it is affine in vy and tan s, so its largest magnitude over the step
    /// is at an end (tan s there capped by `outlet_tan`, as in `rates`).
    #[inline(never)]
    pub(super) fn aniso_rate(&self, p: &PState, sn1: f64, cs1: f64, h: f64) -> f64 {
        let k = 2.0 / 3.0;
        let a_k = k * self.a;
        let g1 = self.gy - 1.0;
        let ends = [
            (k * self.vy(self.c * p.sn), p.sn / p.cs.max(CS_MIN)),
            (
                k * self.vy(self.c * sn1),
                (sn1 / cs1.max(CS_MIN)).min(outlet_tan(p.sn, p.cs)),
            ),
        ];
        let rate = |nx: f64, ny: f64| {
            let nn = 1.0 / (nx * nx + self.gy * ny * ny);
            let hh = nx * ny * nn;
            let hp = ((nx * nx - ny * ny) - 2.0 * g1 * nx * ny * hh) * nn;
            let mut m = 0.0f64;
            for &(vy_k, t) in &ends {
                let e = a_k * nx + vy_k * ny;
                let pp = vy_k * nx - a_k * ny;
                m = m.max((e + g1 * (hp * (e + t) + hh * pp)).abs());
            }
            m
        };
        let slip = |vy_k: f64| {
            let (vx, vy) = (a_k, vy_k / self.gy);
            let r = (vx * vx + vy * vy).sqrt();
            if r > 0.0 {
                (vx / r, vy / r)
            } else {
                (1.0, 0.0)
            }
        };
        let (u0, u1) = (slip(ends[0].0), slip(ends[1].0));
        let m = rate(p.nx, p.ny).max(rate(u0.0, u0.1)).max(rate(u1.0, u1.1));
        ANISO_RATE_SAFETY * m * h
    }

    /// Quasi-steady direction over h (stiff limit), Simpson's rule.
    pub(super) fn quasi_steady(&self, p: &PState, h: f64, c2: f64, s2: f64) -> PState {
        crate::counts::count!(quasi_steady);
        let (sm, cm) = (p.sn * c2 + p.cs * s2, p.cs * c2 - p.sn * s2);
        let (s1, c1) = (sm * c2 + cm * s2, (cm * c2 - sm * s2).max(0.0));
        // Quasi-steady branch, Simpson's rule.
        let n0 = (p.nx, p.ny);
        // On the spin pole's strip (a = 0, `Scaled::strip`) the stress is
        // lateral, n = (0, ±1), from yield on, and dθ/ds = 0 there for any
        // gy (`theta_rate`): n stays. The quasi-steady direction, the slip's,
        // is the same n while vy keeps its sign, but flips with vy at its
        // zero, where the stress must unload instead: with it that strip
        // ended plastic, its ∫Zy off by up to 0.29 at |J3| ≥ 5e2 (κ·h large
        // enough for this branch), and the panels next to it were refined
        // to their last level (37 ms instead of 3 ms at k = 1,
        // J = (0.5, 1, 1e6), tol 1e-3).
        let (nm, n1) = if self.a == 0.0 {
            (n0, n0)
        } else {
            (self.qs_dir(sm, cm), self.qs_dir(s1, c1))
        };
        let a0 = self.deriv(p.sn, p.cs, n0.0, n0.1);
        let am = self.deriv(sm, cm, nm.0, nm.1);
        let a1 = self.deriv(s1, c1, n1.0, n1.1);
        let h6 = h / 6.0;
        let mut acc = p.acc;
        acc.ix += h6 * (a0.ix + 4.0 * am.ix + a1.ix);
        acc.iy += h6 * (a0.iy + 4.0 * am.iy + a1.iy);
        acc.ixy += h6 * (a0.ixy + 4.0 * am.ixy + a1.ixy);
        PState {
            sn: s1,
            cs: c1,
            nx: n1.0,
            ny: n1.1,
            acc,
        }
    }
}

/// (1 − w)·a + w·b of two plastic states at the same s (b's), the direction
/// normalised.
pub(super) fn blend(a: &PState, b: &PState, w: f64) -> PState {
    let v = 1.0 - w;
    let (nx, ny) = (v * a.nx + w * b.nx, v * a.ny + w * b.ny);
    let acc = StripSums {
        ix: v * a.acc.ix + w * b.acc.ix,
        iy: v * a.acc.iy + w * b.acc.iy,
        ixy: v * a.acc.ixy + w * b.acc.ixy,
    };
    PState::normalised(b.sn, b.cs, (nx, ny), acc)
}

/// 1/(j + 3)! for j = 0..12: the Taylor coefficients of φ3.
const PHI3_SERIES: [f64; 12] = [
    1.0 / 6.0,
    1.0 / 24.0,
    1.0 / 120.0,
    1.0 / 720.0,
    1.0 / 5040.0,
    1.0 / 40320.0,
    1.0 / 362880.0,
    1.0 / 3628800.0,
    1.0 / 39916800.0,
    1.0 / 479001600.0,
    1.0 / 6227020800.0,
    1.0 / 87178291200.0,
];

/// φ1, φ2, φ3 of z (φ1 = (eᶻ − 1)/z, φ2 = (φ1 − 1)/z, φ3 = (φ2 − 1/2)/z),
/// given e = eᶻ: the recurrences for |z| ≥ 1/2 (where their cancellation
/// costs at most a few ulps), else φ3's Taylor series Σ zʲ/(j + 3)! to z¹¹
/// (the first omitted term, 0.5¹²/15! ≈ 2e-16, is below φ3's ulp) and
/// φ2 = 1/2 + z·φ3, φ1 = 1 + z·φ2.
#[inline]
pub(super) fn phi_functions(z: f64, e: f64) -> (f64, f64, f64) {
    if z.abs() >= 0.5 {
        let p1 = (e - 1.0) / z;
        let p2 = (p1 - 1.0) / z;
        let p3 = (p2 - 0.5) / z;
        return (p1, p2, p3);
    }
    let mut p3 = 0.0;
    for &c in PHI3_SERIES.iter().rev() {
        p3 = p3 * z + c;
    }
    let p2 = 0.5 + z * p3;
    let p1 = 1.0 + z * p2;
    (p1, p2, p3)
}

/// The largest tan s that the anisotropic term of a step's rate bound
/// (`Strip::rates`) counts on a step from s0 = atan2(sn0, cs0): at least the
/// tan at the midpoint of [s0, π/2], cot((π/2 − s0)/2) = (1 + sin s0)/cos s0
/// (with |sin s0|, and capped like `theta_rate`), rather than at the outlet.
/// The term λ·t·G·n with −dL/dX = (3/2)·tan s drives the direction towards
/// the stiffer axis at a rate that grows without bound at the outlet, but a
/// stage at the outlet moves only the end direction of the strip's last
/// step, whose weight L·dX/ds vanishes there, and beyond the midpoint of
/// what remains of the strip the weight (3/2)c²cos²s of the strip sums is
/// below (3/2)c²·((π/2 − s0)/2)² (docs/decisions/0105).
#[inline(always)]
pub(super) fn outlet_tan(sn0: f64, cs0: f64) -> f64 {
    (1.0 + sn0.abs()) / cs0.max(CS_MIN)
}
