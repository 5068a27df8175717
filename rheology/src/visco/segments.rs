//! The two kinds of segment along a strip, as right-hand sides of the
//! Rosenbrock step (`rosenbrock.rs`): the trait [`Seg`], implemented by the
//! interior ([`Interior`], state Z) and the cap ([`Cap`], state θ, with its
//! unloading test), their values ([`Eval`]) and Jacobians ([`Jac`]) at a
//! point [`Pt`] of the strip (σ with its sine and cosine), and the Taylor
//! sine and cosine ([`sincos_small`], [`horner`] and their tables) that
//! advance a point and rotate the cap's direction without libm. The strip
//! loop (`strip.rs`) switches between the two kinds.

use super::law::VStrip;

/// Right-hand side at one point: the state's rate and the three quadrature
/// rates d/dσ (∫Zx dX, ∫Zy dX, ∫Zy·X dX).
#[derive(Debug, Clone, Copy)]
pub(super) struct Eval<const N: usize> {
    pub(super) f: [f64; N],
    pub(super) fq: [f64; 3],
}

/// Jacobian blocks at one point: ∂f/∂u, ∂fq/∂u, ∂f/∂σ, ∂fq/∂σ.
#[derive(Debug, Clone, Copy)]
pub(super) struct Jac<const N: usize> {
    pub(super) j: [[f64; N]; N],
    pub(super) gq: [[f64; N]; 3],
    pub(super) t: [f64; N],
    pub(super) tq: [f64; 3],
}

/// A point of a strip: σ with its sine and cosine.
#[derive(Debug, Clone, Copy)]
pub(super) struct Pt {
    pub(super) s: f64,
    pub(super) sn: f64,
    pub(super) cs: f64,
}

impl Pt {
    /// The points σ + d1 and σ + d2 (|d2| ≤ |d1| ≤ 1), by
    /// [`sincos_small2`].
    #[inline]
    pub(super) fn advance2(&self, d1: f64, d2: f64) -> (Self, Self) {
        let ((s1, c1), (s2, c2)) = sincos_small2(d1, d2);
        let rot = |sd: f64, cd: f64, d: f64| Pt {
            s: self.s + d,
            sn: self.sn * cd + self.cs * sd,
            cs: self.cs * cd - self.sn * sd,
        };
        (rot(s1, c1, d1), rot(s2, c2, d2))
    }

    /// The point σ + d (|d| ≤ 1): sine and cosine of d by their Taylor
    /// series ([`sincos_small`]), then the rotation.
    #[inline]
    pub(super) fn advance(&self, d: f64) -> Self {
        let (sd, cd) = sincos_small(d);
        Pt {
            s: self.s + d,
            sn: self.sn * cd + self.cs * sd,
            cs: self.cs * cd - self.sn * sd,
        }
    }
}

/// One of the [`horner`] polynomial pairs.
type Horner = fn(&[f64; 8], &[f64; 8], f64) -> (f64, f64);

/// [`sincos_small`] of d1 and d2 (|d2| ≤ |d1| ≤ 1) with the number of
/// terms of d1 for both: one branch on the tier instead of two.
#[inline]
fn sincos_small2(d1: f64, d2: f64) -> ((f64, f64), (f64, f64)) {
    let ad = d1.abs();
    if ad > 1.0 {
        return (d1.sin_cos(), d2.sin_cos());
    }
    let (x1, x2) = (d1 * d1, d2 * d2);
    let both = |n: Horner| {
        let (s1, c1) = n(&SIN_T, &COS_T, x1);
        let (s2, c2) = n(&SIN_T, &COS_T, x2);
        ((d1 * s1, c1), (d2 * s2, c2))
    };
    if ad < TIERS[0] {
        both(horner::<3>)
    } else if ad < TIERS[1] {
        both(horner::<4>)
    } else if ad < TIERS[2] {
        both(horner::<5>)
    } else if ad < TIERS[3] {
        both(horner::<6>)
    } else {
        both(horner::<7>)
    }
}

/// (sin d, cos d) by their Taylor series for |d| ≤ 1 (relative error
/// < 1e-16 up to |d| = 0.43, < 5e-14 at |d| = 1), by libm beyond. The
/// number of terms follows |d| (the cap's direction moves little within a
/// step): cos d to d^(2n) with the next term d^(2n+2)/(2n+2)! < 1e-16 on
/// each tier, sin d to d^(2n+1).
#[inline]
fn sincos_small(d: f64) -> (f64, f64) {
    const S: [f64; 8] = SIN_T;
    const C: [f64; 8] = COS_T;
    let ad = d.abs();
    if ad > 1.0 {
        return d.sin_cos();
    }
    let d2 = d * d;
    let (sv, cv) = if ad < TIERS[0] {
        horner::<3>(&S, &C, d2)
    } else if ad < TIERS[1] {
        horner::<4>(&S, &C, d2)
    } else if ad < TIERS[2] {
        horner::<5>(&S, &C, d2)
    } else if ad < TIERS[3] {
        horner::<6>(&S, &C, d2)
    } else {
        horner::<7>(&S, &C, d2)
    };
    (d * sv, cv)
}

/// The |d| below which [`sincos_small`] and [`sincos_small2`] keep d²
/// up to the power n = 3, 4, 5, 6 (n = 7 beyond): cos d's truncation
/// d^(2n+2)/(2n+2)! < 1e-16 there.
const TIERS: [f64; 4] = [0.037, 0.114, 0.245, 0.436];

/// Taylor coefficients of sin d/d and cos d in d²: (−1)^i/(2i+1)!,
/// (−1)^i/(2i)!.
const SIN_T: [f64; 8] = [
    1.0,
    -1.0 / 6.0,
    1.0 / 120.0,
    -1.0 / 5040.0,
    1.0 / 362_880.0,
    -1.0 / 39_916_800.0,
    1.0 / 6_227_020_800.0,
    -1.0 / 1_307_674_368_000.0,
];
const COS_T: [f64; 8] = [
    1.0,
    -1.0 / 2.0,
    1.0 / 24.0,
    -1.0 / 720.0,
    1.0 / 40_320.0,
    -1.0 / 3_628_800.0,
    1.0 / 479_001_600.0,
    -1.0 / 87_178_291_200.0,
];

/// The polynomials Σ_{i ≤ N} s_i·x^i and Σ_{i ≤ N} c_i·x^i (Horner).
#[inline(always)]
fn horner<const N: usize>(s: &[f64; 8], c: &[f64; 8], x: f64) -> (f64, f64) {
    let mut sv = s[N];
    let mut cv = c[N];
    for i in (0..N).rev() {
        sv = s[i] + x * sv;
        cv = c[i] + x * cv;
    }
    (sv, cv)
}

/// A segment type: the interior (N = 2, u = Z) or the cap (N = 1, u = θ).
pub(super) trait Seg<const N: usize> {
    fn eval(&self, p: Pt, u: &[f64; N]) -> Eval<N>;
    fn eval_jac(&self, p: Pt, u: &[f64; N]) -> (Eval<N>, Jac<N>);
    /// The inverse of W = I/(γh) − J (gi = 1/(γh)).
    fn inverse(&self, gi: f64, j: &[[f64; N]; N]) -> [[f64; N]; N];
    /// Weight of a state error in stress units, for a step from `p`.
    fn weight(&self, p: Pt) -> f64;
    /// The product ∂fq/∂u · s.
    #[inline(always)]
    fn gq_dot(&self, gq: &[[f64; N]; 3], s: &[f64; N]) -> [f64; 3] {
        let mut o = [0.0; 3];
        for (i, row) in gq.iter().enumerate() {
            for k in 0..N {
                o[i] += row[k] * s[k];
            }
        }
        o
    }
}

/// Interior of the cap: state Z.
pub(super) struct Interior<'a>(pub(super) &'a VStrip);
/// On the cap with an anisotropic stiffness (gy ≠ 1; isotropic caps are the
/// elastic/plastic model's plastic segments, `strip.rs`): state θ,
/// Z = L·(cos θ, sin θ); n(θ) is evaluated by
/// rotating n(θ0) of the step's start by θ − θ0. Only such differences
/// enter, so θ is counted from the direction at the cap entry (θ = 0 there,
/// n0 = Z/|Z|).
pub(super) struct Cap<'a> {
    st: &'a VStrip,
    th0: f64,
    n0: (f64, f64),
}

impl Seg<2> for Interior<'_> {
    #[inline]
    fn eval(&self, p: Pt, u: &[f64; 2]) -> Eval<2> {
        let st = self.0;
        let x = -st.c * p.cs;
        let xp = st.c * p.sn;
        let (zx, zy) = (u[0], u[1]);
        let (mu, _) = st.law.rates((zx * zx + zy * zy).sqrt());
        Eval {
            f: [
                xp * (st.a - mu * zx),
                xp * (st.b1 + st.q2 * x - st.gy * mu * zy),
            ],
            fq: [xp * zx, xp * zy, xp * zy * x],
        }
    }

    #[inline]
    fn eval_jac(&self, p: Pt, u: &[f64; 2]) -> (Eval<2>, Jac<2>) {
        let st = self.0;
        let x = -st.c * p.cs;
        let xp = st.c * p.sn;
        let xpp = st.c * p.cs;
        let (zx, zy) = (u[0], u[1]);
        let r = (zx * zx + zy * zy).sqrt();
        let (mu, dpsi) = st.law.rates(r);
        let (nx, ny) = if r > 0.0 {
            let ir = 1.0 / r;
            (zx * ir, zy * ir)
        } else {
            (0.0, 0.0)
        };
        let (gx, gyv) = (st.a - mu * zx, st.b1 + st.q2 * x - st.gy * mu * zy);
        let ev = Eval {
            f: [xp * gx, xp * gyv],
            fq: [xp * zx, xp * zy, xp * zy * x],
        };
        // ∂(μ·Z)/∂Z = μ·I + (ψ′ − μ)·n·nᵀ, then G and −X′.
        let w = dpsi - mu;
        let m = [
            [mu + w * nx * nx, w * nx * ny],
            [w * nx * ny, mu + w * ny * ny],
        ];
        let j = [
            [-xp * m[0][0], -xp * m[0][1]],
            [-xp * st.gy * m[1][0], -xp * st.gy * m[1][1]],
        ];
        // ∂f/∂σ: X″·(e − μGZ) + X′·(0, q2·X′).
        let t = [xpp * gx, xpp * gyv + xp * xp * st.q2];
        let gq = [[xp, 0.0], [0.0, xp], [0.0, xp * x]];
        let tq = [xpp * zx, xpp * zy, xpp * zy * x + xp * zy * xp];
        (ev, Jac { j, gq, t, tq })
    }

    #[inline]
    fn inverse(&self, gi: f64, j: &[[f64; 2]; 2]) -> [[f64; 2]; 2] {
        let (a, b, c, d) = (gi - j[0][0], -j[0][1], -j[1][0], gi - j[1][1]);
        let id = 1.0 / (a * d - b * c);
        [[d * id, -b * id], [-c * id, a * id]]
    }

    fn weight(&self, _p: Pt) -> f64 {
        1.0
    }

    /// ∂fq/∂Z = [[X′, 0], [0, X′], [0, X′·X]]: its zeros skipped.
    #[inline(always)]
    fn gq_dot(&self, gq: &[[f64; 2]; 3], s: &[f64; 2]) -> [f64; 3] {
        [gq[0][0] * s[0], gq[1][1] * s[1], gq[2][1] * s[1]]
    }
}

/// Smallest sin σ at which the anisotropic flow term L′ = (3/2)·cot σ is
/// evaluated (as the elastic/plastic model's cap on it: the term is
/// logarithmically singular at the outlet, where the stress and its weight
/// vanish; effect below 1e-5).
const SN_MIN: f64 = 0.02;

impl<'a> Cap<'a> {
    /// The cap from θ0 with n0 = (cos θ0, sin θ0) (carried from step to
    /// step by the rotations of [`Cap::n`], not recomputed by libm).
    pub(super) fn new(st: &'a VStrip, th0: f64, n0: (f64, f64)) -> Self {
        Cap { st, th0, n0 }
    }

    /// (cos θ, sin θ).
    #[inline]
    pub(super) fn n(&self, th: f64) -> (f64, f64) {
        if th == self.th0 {
            return self.n0;
        }
        let (sd, cd) = sincos_small(th - self.th0);
        let (c0, s0) = self.n0;
        (c0 * cd - s0 * sd, s0 * cd + c0 * sd)
    }

    /// dθ/dσ = (2/3)·(t·e − (n·e − L′)·(t·G·n)/(n·G·n)) with n = (nx, ny).
    #[inline]
    pub(super) fn rate(&self, sn: f64, cs: f64, nx: f64, ny: f64) -> f64 {
        let st = self.st;
        let x = -st.c * cs;
        let (ex, ey) = (st.a, st.b1 + st.q2 * x);
        let te = ey * nx - ex * ny;
        if st.gy == 1.0 {
            return te / 1.5;
        }
        let ne = ex * nx + ey * ny;
        let lp = 1.5 * cs / sn.max(SN_MIN);
        let ngn = nx * nx + st.gy * ny * ny;
        let tgn = (st.gy - 1.0) * nx * ny;
        (te - (ne - lp) * tgn / ngn) / 1.5
    }

    /// (∂/∂θ, ∂/∂σ) of [`Cap::rate`] for gy ≠ 1, exact: with
    /// dn/dθ = (−ny, nx), d(t·e)/dθ = −n·e, d(n·e)/dθ = t·e,
    /// d(t·G·n)/dθ = (gy − 1)·(nx² − ny²), d(n·G·n)/dθ = 2·t·G·n, and along σ
    /// d(e_y)/dσ = q2·c·sin σ, dL′/dσ = −(3/2)/sin²σ (−(3/2)·sin σ/SN_MIN
    /// where sin σ is capped).
    #[inline]
    pub(super) fn rate_derivatives(&self, sn: f64, cs: f64, nx: f64, ny: f64) -> (f64, f64) {
        let st = self.st;
        let x = -st.c * cs;
        let (ex, ey) = (st.a, st.b1 + st.q2 * x);
        let te = ey * nx - ex * ny;
        let ne = ex * nx + ey * ny;
        let (lp, dlp) = if sn > SN_MIN {
            (1.5 * cs / sn, -1.5 / (sn * sn))
        } else {
            (1.5 * cs / SN_MIN, -1.5 * sn / SN_MIN)
        };
        let ngn = nx * nx + st.gy * ny * ny;
        let tgn = (st.gy - 1.0) * nx * ny;
        let q = tgn / ngn;
        let dq = ((st.gy - 1.0) * (nx * nx - ny * ny) - 2.0 * q * tgn) / ngn;
        let dth = (-ne - te * q - (ne - lp) * dq) / 1.5;
        let dey = st.q2 * st.c * sn;
        let dsg = (dey * nx - (dey * ny - dlp) * q) / 1.5;
        (dth, dsg)
    }

    /// λ̃ = (n·e − L′ − ψ(L)·n·G·n)·sin σ: the stress stays on the cap while
    /// λ̃ ≥ 0.
    #[inline]
    pub(super) fn unload(&self, p: Pt, th: f64) -> f64 {
        let st = self.st;
        let x = -st.c * p.cs;
        let (nx, ny) = self.n(th);
        let ne = st.a * nx + (st.b1 + st.q2 * x) * ny;
        let l = 1.5 * st.c * p.sn.max(0.0);
        let ngn = nx * nx + st.gy * ny * ny;
        ne * p.sn - 1.5 * p.cs - st.law.psi(l) * ngn * p.sn
    }

    /// [`Cap::unload`] where only its sign matters: ψ increases, so with
    /// ψ(L) ≤ `psi_c` = ψ((3/2)·c) the bound (n·e − L′ − ψ_c·n·G·n)·sin σ ≥ 0
    /// already keeps the stress on the cap, without the exponential of ψ(L);
    /// otherwise the exact λ̃.
    #[inline]
    pub(super) fn unload_sign(&self, p: Pt, th: f64, psi_c: f64) -> f64 {
        let st = self.st;
        let x = -st.c * p.cs;
        let (nx, ny) = self.n(th);
        let ne = st.a * nx + (st.b1 + st.q2 * x) * ny;
        let ngn_s = (nx * nx + st.gy * ny * ny) * p.sn;
        let base = ne * p.sn - 1.5 * p.cs;
        let bound = base - psi_c * ngn_s;
        if bound >= 0.0 {
            return bound;
        }
        base - st.law.psi(1.5 * st.c * p.sn.max(0.0)) * ngn_s
    }
}

impl Seg<1> for Cap<'_> {
    #[inline]
    fn eval(&self, p: Pt, u: &[f64; 1]) -> Eval<1> {
        let st = self.st;
        let x = -st.c * p.cs;
        let (nx, ny) = self.n(u[0]);
        let w = 1.5 * st.c * st.c * p.sn * p.sn;
        Eval {
            f: [self.rate(p.sn, p.cs, nx, ny)],
            fq: [w * nx, w * ny, w * ny * x],
        }
    }

    #[inline]
    fn eval_jac(&self, p: Pt, u: &[f64; 1]) -> (Eval<1>, Jac<1>) {
        let st = self.st;
        let (sn, cs) = (p.sn, p.cs);
        let x = -st.c * cs;
        let xp = st.c * sn;
        let th = u[0];
        let (nx, ny) = self.n(th);
        let f = self.rate(sn, cs, nx, ny);
        let (j, t) = if st.gy == 1.0 {
            let ne = st.a * nx + (st.b1 + st.q2 * x) * ny;
            (-ne / 1.5, nx * st.q2 * xp / 1.5)
        } else {
            self.rate_derivatives(sn, cs, nx, ny)
        };
        let w = 1.5 * st.c * st.c * sn * sn;
        let dw = 3.0 * st.c * st.c * sn * cs;
        let ev = Eval {
            f: [f],
            fq: [w * nx, w * ny, w * ny * x],
        };
        let jac = Jac {
            j: [[j]],
            gq: [[-w * ny], [w * nx], [w * nx * x]],
            t: [t],
            tq: [dw * nx, dw * ny, dw * ny * x + w * ny * xp],
        };
        (ev, jac)
    }

    #[inline]
    fn inverse(&self, gi: f64, j: &[[f64; 1]; 1]) -> [[f64; 1]; 1] {
        [[1.0 / (gi - j[0][0])]]
    }

    /// The largest stress the direction carries from σ on: L = (3/2)·c·sin σ
    /// decreases past σ = π/2, so a direction error δθ of a step from there
    /// moves the stress by at most (3/2)·c·sin σ·δθ at and after the step
    /// (times the direction's own error growth, the same for any weight).
    /// Against the constant (3/2)·c: g −14 %, m −3 % instructions at
    /// tol = 1e-3, the worst error/tol on the random scans unchanged
    /// (docs/decisions/0077).
    fn weight(&self, p: Pt) -> f64 {
        if p.cs < 0.0 {
            1.5 * self.st.c * p.sn
        } else {
            1.5 * self.st.c
        }
    }
}
