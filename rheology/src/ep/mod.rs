//! Elastic/perfectly plastic strip integrator (Prandtl–Reuss; Appendix IV
//! equation 13 with the side-slip term of Appendix V equations 10–11).
//!
//! Each strip at fixed Y (half-width c = √(1−Y²)) is marched from the inlet
//! X = −c (stress-free) to the outlet X = c in the angle s, X = c·sin s, in
//! which the limit L = (3/2)·c·cos s is smooth:
//!
//! * elastic segments: Z is a polynomial in X (closed form, integrated
//!   exactly); first yield or reloading is the first root of
//!   the quartic |Z(X)|² − L(X)², bracketed exactly between the turning
//!   points of its cubic factor, started by Halley steps on that cubic,
//!   then safeguarded Halley (stopped once its cubic error estimate is
//!   1e-3·s_step⁴ of c);
//! * plastic segments: Z = L·n with the unit vector n rotating at
//!   dn/ds = (2/3)(v·t)·t, t ⟂ n (Prandtl–Reuss consistency; the 1/√(c−X)
//!   singularity of dθ/dX is absorbed by dX/ds = c·cos s; with an
//!   anisotropic stiffness gy ≠ 1 the rate of `Strip::theta_rate`, and v is
//!   then the elastic rate G·v throughout this module). Classical RK4 on
//!   (n, ∫Zx dX, ∫Zy dX, ∫Zy X dX) (a segment whose largest κ·h stays below
//!   the stability margin may use a longer step, see `solve_adaptive`, and
//!   in [`Strip::integrate_etd`] 1.5 times that where κ·h ≤ 0.75 at it;
//!   there a segment stiff for RK4 with no exponential steps takes equal
//!   steps of Butcher's six-stage fifth-order rule, `Strip::rk5`, of the
//!   longer step or else of the s-step where κ·h ≤ 2.8 at them);
//!   steps are sub-divided where the relaxation
//!   rate (2/3)|v| makes RK4 unstable or inaccurate (κ·h > 2, within stiff
//!   segments κ·h > 1.5; sub-steps whose lengths vary continuously with
//!   κ·h, so that the outputs stay smooth in the inputs),
//!   where they exceed 3.5 and the slip direction turns slowly, one step of
//!   the L-stable Rosenbrock method RODAS3 on the lag φ = α − θ takes
//!   their place in [`Strip::integrate_etd`] (blended in, and out as its
//!   error estimate rises; `Strip::rodas3_lag`),
//!   and where they exceed 8 sub-steps per step n follows its quasi-steady
//!   solution θ = α − asin(α'/κ) (blended in from 8 to 9 sub-steps; the
//!   rigid/plastic direction with the first elastic lag; for gy ≠ 1 the root
//!   of dθ/ds = α' of the anisotropic law, and only beyond 4·16·f sub-steps,
//!   f = 1 + |gy − 1|/min(1, gy)), integrated by Simpson's rule; on such
//!   stiff segments the steps are also shortened where the slip direction
//!   α turns fast (|α'|·h ≤ 4·s_step, near a strip's
//!   crossing of vy = 0) and graded from κ·h = 1/2 after yield, where the
//!   lag of n behind v̂ relaxes within ~1/κ; in [`Strip::integrate_etd`]
//!   (used by `evaluate`, not by the fixed-resolution reference) stiff
//!   isotropic segments on which the slip direction turns slowly take
//!   exponential steps instead (ETDRK4 on the Riccati equation of
//!   tan((α − θ)/2), `Strip::etd`), several s-steps long, and where κ·h ≤ 0.8
//!   a step near vy = 0 is the one over which α turns by exactly 4·s_step
//!   (`Strip::turn_step`, closed form) rather than the bound's shorter one;
//! * elastic unloading where g = (v·n)·cos s + (3/2)·sin s turns negative
//!   (v·n < dL/dX), located inside the step on the integrated g (the root
//!   of g's cubic Hermite interpolant over the step as the first trial
//!   length, then Newton with the exact dg/ds, safeguarded by regula falsi).

mod kink;
mod plastic;
mod quadrature;
mod yield_point;

use plastic::ETD_MIN_STEP;

#[cfg(test)]
pub(crate) use quadrature::panel_sums;
pub(crate) use quadrature::{
    MAX_BREAKS, adaptive_in_phi, contact_integral, contact_integral_adaptive_at, etd_step,
    graded_breaks, refine_share, solve, solve_adaptive, to_j,
};

/// Smallest cos s at which the anisotropic flow term (3/2)·tan s (= −dL/dX)
/// is evaluated. Near the outlet the shrinking limit drives the stress
/// direction towards the stiffer axis at a rate ∝ tan s (logarithmically
/// singular in s); capping it changes the stress only where
/// cos s < 0.02, whose weight in the strip sums is ∫(3/2)c²cos²s ds
/// < 4e-6·c², so the effect on J4..J6 is below 1e-5 (isotropic: no effect).
pub(super) const CS_MIN: f64 = 0.02;

/// 0 for t ≤ 0, 1 for t ≥ 1, C¹ cubic in between: the blend of every
/// discrete choice of the strips and panels (outputs continuous in the
/// inputs).
#[inline]
pub(super) fn smooth_step(t: f64) -> f64 {
    let t = t.clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// |a| = |a0 − J3·Y| below which a strip is the spin pole's (relative to
/// |a0|; a few ulps of a0). Its slip is then purely lateral and reverses at
/// vy = 0, and its discretised strip sums are not the limit of those at
/// a → 0 (where the slip direction turns by π within ≈ |a/q2| of vy = 0
/// and the plastic steps are set by that turn): with J = (5.05, 0, −8.57)
/// at k = 2.48, tol 1e-4, ∫Zy dX at a = 4.4e-16 (1 ulp of a0) was
/// 4.0e-7 relative below its value at a = 0, which took J4..J6 up and down
/// by up to 1.1e-9 between inputs 5e-10 apart, at random along a line of
/// inputs (tests/continuity.rs; docs/decisions/0089).
const POLE_SNAP: f64 = 8.0 * f64::EPSILON;

/// Largest number of elastic ↔ plastic switches per strip.
const MAX_SWITCH: usize = 16;

/// Discretisation of the contact integral (see [`crate::Accuracy`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Resolution {
    /// Panels in φ, Y = sin φ, over [−π/2, π/2].
    pub y_panels: usize,
    /// Gauss–Legendre points per panel (1..=24).
    pub y_points: usize,
    /// Target step in s (radians) of the plastic segments.
    pub s_step: f64,
}

/// Where a segment on the limit ends before the outlet
/// ([`Strip::limit_segment`]): X and the stress Z there.
pub(crate) type LimitEnd = (f64, (f64, f64));

/// Strip integrals ∫Zx dX, ∫Zy dX, ∫Zy·X dX.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct StripSums {
    pub ix: f64,
    pub iy: f64,
    pub ixy: f64,
}

impl std::ops::AddAssign for StripSums {
    fn add_assign(&mut self, o: Self) {
        self.ix += o.ix;
        self.iy += o.iy;
        self.ixy += o.ixy;
    }
}

/// One strip of half-width c: the elastic stress rate G·v/Ḡx =
/// (a, b1 + q2·X), i.e. the slip velocity v = (a, (b1 + q2·X)/gy) with the
/// lateral-to-longitudinal stiffness ratio gy = Ḡy/Ḡx (1: isotropic).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Strip {
    pub c: f64,
    pub a: f64,
    pub b1: f64,
    pub q2: f64,
    pub gy: f64,
    /// The viscous law of the viscoelastic model, whose stress leaves the
    /// limit (its cap) where the plastic multiplier falls below the viscous
    /// rate ψ(L) (see [`Strip::limit_segment`]); None: elastic/plastic.
    pub vis: Option<crate::visco::Law>,
}

#[derive(Debug, Clone, Copy)]
struct PState {
    sn: f64,
    cs: f64,
    nx: f64,
    ny: f64,
    acc: StripSums,
}

impl PState {
    /// The state at (sn, cs) with the direction (nx, ny) scaled to unit
    /// length (a step's rounding and truncation leave |n| ≠ 1).
    #[inline(always)]
    fn normalised(sn: f64, cs: f64, (nx, ny): (f64, f64), acc: StripSums) -> Self {
        let r = (nx * nx + ny * ny).sqrt();
        PState {
            sn,
            cs,
            nx: nx / r,
            ny: ny / r,
            acc,
        }
    }
}

/// What [`Strip::integrate_rec`] reports along a strip.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Event {
    /// Elastic from x0 (stress z0) to x1: Z is the closed form in between.
    Elastic { x0: f64, z0: (f64, f64), x1: f64 },
    /// On the limit at x with unit direction n (|Z| = L(x)).
    Plastic { x: f64, n: (f64, f64) },
}

enum PlasticEnd {
    Outlet,
    Unload { x: f64, z: (f64, f64) },
}

impl Strip {
    #[inline]
    fn vy(&self, x: f64) -> f64 {
        self.b1 + self.q2 * x
    }

    #[inline]
    pub(crate) fn z_el(&self, x0: f64, z0: (f64, f64), x: f64) -> (f64, f64) {
        let e = x - x0;
        (
            z0.0 + self.a * e,
            z0.1 + (self.b1 + self.q2 * x0) * e + 0.5 * self.q2 * e * e,
        )
    }

    /// Exact integrals of an elastic segment from x0 to x1.
    fn el_sums(&self, x0: f64, z0: (f64, f64), x1: f64) -> StripSums {
        let d = x1 - x0;
        let d2 = d * d;
        let b = self.b1 + self.q2 * x0;
        let ix = z0.0 * d + 0.5 * self.a * d2;
        let iy = z0.1 * d + 0.5 * b * d2 + self.q2 * d2 * d / 6.0;
        let ixy = x0 * iy + 0.5 * z0.1 * d2 + b * d2 * d / 3.0 + self.q2 * d2 * d2 / 8.0;
        StripSums { ix, iy, ixy }
    }

    /// Integrands of the strip sums on the limit with direction n.
    #[inline]
    fn deriv(&self, sn: f64, cs: f64, nx: f64, ny: f64) -> StripSums {
        let x = self.c * sn;
        let dxds = self.c * cs;
        let l = 1.5 * self.c * cs;
        let zx = l * nx;
        let zy = l * ny;
        StripSums {
            ix: zx * dxds,
            iy: zy * dxds,
            ixy: zy * x * dxds,
        }
    }

    /// dθ/ds of the direction n on the limit (Prandtl–Reuss with the elastic
    /// stiffness G = diag(1, gy)): with the elastic rate e = G·v, the plastic
    /// multiplier λ = (n·e − dL/dX)/(n·G·n) and t ⟂ n,
    /// dθ/ds = (2/3)(t·e − λ·t·G·n), t·G·n = (gy − 1)·nx·ny; the isotropic
    /// case is (2/3)(t·e). dL/dX = −(3/2)tan s is capped at cos s ≥
    /// [`CS_MIN`] (see there).
    #[inline]
    pub(crate) fn theta_rate(&self, sn: f64, cs: f64, nx: f64, ny: f64) -> f64 {
        let k = 2.0 / 3.0;
        let t = if self.gy == 1.0 {
            0.0
        } else {
            sn / cs.max(CS_MIN)
        };
        self.flow_rate::<false>(k * self.vy(self.c * sn), k * self.a, t, nx, ny)
    }

    /// Whether the stiffness is isotropic (gy = 1): `ISO = true` asserts it
    /// at compile time (the isotropic instantiation of the plastic stepping,
    /// chosen once per strip), `false` tests it at run time.
    #[inline(always)]
    pub(super) fn iso<const ISO: bool>(&self) -> bool {
        ISO || self.gy == 1.0
    }

    /// `theta_rate` from the scaled rates: vy_k = (2/3)·vy, a_k = (2/3)·a and
    /// t = (2/3)·(3/2)·tan s = tan s (capped; unused for gy = 1).
    #[inline(always)]
    fn flow_rate<const ISO: bool>(&self, vy_k: f64, a_k: f64, t: f64, nx: f64, ny: f64) -> f64 {
        let base = vy_k * nx - a_k * ny;
        if self.iso::<ISO>() {
            base
        } else {
            base - (self.gy - 1.0) * nx * ny * (a_k * nx + vy_k * ny + t)
                / (nx * nx + self.gy * ny * ny)
        }
    }

    /// The unloading margin on the limit: g = (v·n)·cos s + (3/2)·sin s
    /// = cos s·(n·e − dL/dX), ≥ 0 while the plastic multiplier is; with a
    /// viscous law the stress stays on its cap while n·e − dL/dX ≥
    /// ψ(L)·n·G·n, so g − ψ(L)·(nx² + gy·ny²)·cos s.
    /// (`VIS = false`: the elastic/plastic model's, without the viscous
    /// term, checked at compile time.)
    #[inline]
    fn g<const VIS: bool>(&self, sn: f64, cs: f64, nx: f64, ny: f64) -> f64 {
        let g = (self.a * nx + self.vy(self.c * sn) * ny) * cs + 1.5 * sn;
        match &self.vis {
            Some(law) if VIS => {
                let ngn = nx * nx + self.gy * ny * ny;
                g - law.psi(1.5 * self.c * cs) * ngn * cs
            }
            _ => g,
        }
    }

    /// `g` where only its sign is needed (a step's end): with a viscous law
    /// ψ(L) ≤ ψ(3/2) decides g ≥ 0 without ψ(L) (an exponential) wherever
    /// that bound leaves g ≥ 0, and the value returned is then the
    /// elastic/plastic g (≥ 0 too); otherwise `g` itself.
    #[inline]
    fn g_sign<const VIS: bool>(&self, sn: f64, cs: f64, nx: f64, ny: f64) -> f64 {
        if VIS && let Some(law) = &self.vis {
            let g = self.g::<false>(sn, cs, nx, ny);
            let ngn = nx * nx + self.gy * ny * ny;
            if g - law.psi_max() * ngn * cs >= 0.0 {
                return g;
            }
        }
        self.g::<VIS>(sn, cs, nx, ny)
    }

    /// The stress on the limit from (sn, cs) with the unit direction n, to
    /// the outlet (None) or to where it leaves the limit (X and Z there):
    /// the plastic segments of the strip integration with the steps `steps`
    /// (s-step, longer s-step, exponential step, exact turn; see
    /// `integrate_with`), and its sums ∫Zx dX, ∫Zy dX, ∫Zy·X dX. With a
    /// viscous law ([`Strip::vis`]) this is the viscoelastic model's cap: on
    /// it the viscous and the plastic strain rates are both along Z, so the
    /// direction follows the same flow, and only the end differs (`g`).
    pub(crate) fn limit_segment(
        &self,
        sn: f64,
        cs: f64,
        n: (f64, f64),
        allow_unload: bool,
        steps: (f64, f64, f64, bool),
    ) -> (StripSums, Option<LimitEnd>) {
        let mut acc = StripSums::default();
        let end = if self.gy == 1.0 {
            self.plastic::<true, true>(sn, cs, n, &mut acc, allow_unload, steps, &mut |_| {})
        } else {
            self.plastic::<false, true>(sn, cs, n, &mut acc, allow_unload, steps, &mut |_| {})
        };
        match end {
            PlasticEnd::Outlet => (acc, None),
            PlasticEnd::Unload { x, z } => (acc, Some((x, z))),
        }
    }

    /// Integrate the strip from the inlet to the outlet.
    pub(crate) fn integrate(&self, s_step: f64, s_step_smooth: f64) -> StripSums {
        self.integrate_rec(s_step, s_step_smooth, &mut |_| {})
    }

    /// [`Strip::integrate`] with exponential steps of at most `etd_step`
    /// on the stiff isotropic plastic segments where the slip direction
    /// turns slowly (see `Strip::plastic`), RK4 as in [`Strip::integrate`]
    /// elsewhere, steps near vy = 0 set by the exact turn of the slip
    /// direction where κ·h is small (`Strip::turn_step`); and the strip's
    /// flow topology: twice the number of unloadings, plus 1 where it ends
    /// elastic (the strip sums have a kink in Y where it changes: a plastic
    /// segment or an unloading appears or vanishes); and its unloading
    /// amplitude: the smallest |g'(s_u)|·ℓ/6 over its unloadings (s_u where
    /// one starts, ℓ the shorter of the plastic segment before it and the
    /// elastic segment after it, in s; the magnitude of the kink margin's
    /// unloading term, see `ep::kink`), which vanishes where an unloading
    /// appears or vanishes (up to its detection at step ends, where it
    /// appears at ≈ 0.01, see `quadrature::KINK_AMPLITUDE`); +∞ without
    /// unloading.
    pub(crate) fn integrate_etd(
        &self,
        s_step: f64,
        s_step_smooth: f64,
        etd_step: f64,
    ) -> (StripSums, u32, f64) {
        self.integrate_with((s_step, s_step_smooth, etd_step, true), &mut |_| {})
    }

    /// [`Strip::integrate`], reporting the elastic segments and the plastic
    /// states (at every step end) to `rec`, in order from the inlet.
    pub(crate) fn integrate_rec(
        &self,
        s_step: f64,
        s_step_smooth: f64,
        rec: &mut impl FnMut(Event),
    ) -> StripSums {
        self.integrate_with((s_step, s_step_smooth, 0.0, false), rec)
            .0
    }

    /// The strip from the inlet to the outlet with the plastic steps
    /// (s-step, longer s-step on non-stiff segments, exponential step or 0
    /// for none, whether steps near vy = 0 may be set by the exact turn of
    /// the slip direction, see `Strip::turn_step`).
    fn integrate_with(
        &self,
        steps: (f64, f64, f64, bool),
        rec: &mut impl FnMut(Event),
    ) -> (StripSums, u32, f64) {
        crate::counts::count!(strips);
        let c = self.c;
        let mut acc = StripSums::default();
        let mut amplitude = f64::INFINITY;
        if c <= 0.0 {
            return (acc, 1, amplitude);
        }
        let mut ends_elastic = 0;
        let mut x0 = -c;
        let mut z0 = (0.0, 0.0);
        let mut switches = 0;
        // At an unloading: s there, the plastic segment's length before it
        // and |g'| there.
        let mut unload: Option<(f64, f64, f64)> = None;
        loop {
            let xy = self.find_yield(x0, z0, steps.0);
            if let Some((s_u, plastic, rate)) = unload.take() {
                let elastic = (xy / c).clamp(-1.0, 1.0).asin() - s_u;
                amplitude = amplitude.min(rate * elastic.min(plastic).max(0.0) / 6.0);
            }
            acc += self.el_sums(x0, z0, xy);
            rec(Event::Elastic { x0, z0, x1: xy });
            // c exactly where the crossing is within `OUTLET_GAP` of it.
            if xy >= c {
                ends_elastic = 1;
                break;
            }
            let z = self.z_el(x0, z0, xy);
            // |Z| = L ≤ 1.5·c at the yield point: no overflow or underflow
            // to guard against (hypot's scaling is not needed).
            let m = (z.0 * z.0 + z.1 * z.1).sqrt();
            if m.is_nan() || m <= 0.0 || !m.is_finite() {
                break;
            }
            let sn = (xy / c).clamp(-1.0, 1.0);
            let cs = (1.0 - sn * sn).max(0.0).sqrt();
            let n = (z.0 / m, z.1 / m);
            let allow_unload = switches < MAX_SWITCH;
            let end = if self.gy == 1.0 {
                self.plastic::<true, false>(sn, cs, n, &mut acc, allow_unload, steps, rec)
            } else {
                self.plastic::<false, false>(sn, cs, n, &mut acc, allow_unload, steps, rec)
            };
            match end {
                PlasticEnd::Outlet => break,
                PlasticEnd::Unload { x, z } => {
                    let su = (x / c).clamp(-1.0, 1.0);
                    let cu = (1.0 - su * su).max(0.0).sqrt();
                    let mz = z.0.hypot(z.1);
                    let rate = self.g_rate::<false>(su, cu, z.0 / mz, z.1 / mz).abs();
                    let s_u = su.asin();
                    unload = Some((s_u, s_u - sn.asin(), rate));
                    x0 = x;
                    z0 = z;
                    switches += 1;
                }
            }
        }
        (acc, 2 * switches as u32 + ends_elastic, amplitude)
    }
}

/// Scaled inputs: J1/√k, J2/√k + J3·ΔX/k, J3, J3/k, and the stiffness
/// ratio gy = Ḡy/Ḡx.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Scaled {
    pub a0: f64,
    pub b1: f64,
    pub j3: f64,
    pub q2: f64,
    pub k: f64,
    pub dx: f64,
    pub gy: f64,
}

impl Scaled {
    pub(crate) fn new(k: f64, j1: f64, j2: f64, j3: f64, dx: f64) -> Self {
        let sk = k.sqrt();
        Scaled {
            a0: j1 / sk,
            b1: j2 / sk + j3 * dx / k,
            j3,
            q2: j3 / k,
            k,
            dx,
            gy: 1.0,
        }
    }

    /// The scaled inputs of `inp` (its k, J1, J2, J3, ΔX and gy).
    pub(crate) fn of(inp: &crate::Inputs) -> Self {
        Scaled::new(inp.k, inp.j1, inp.j2, inp.j3, inp.dx).with_gy(inp.gy)
    }

    /// With the lateral-to-longitudinal stiffness ratio gy.
    pub(crate) fn with_gy(self, gy: f64) -> Self {
        Scaled { gy, ..self }
    }

    /// The strip at Y: elastic rates (a, gy·(b1 + q2·X)), a = a0 − J3·Y
    /// taken as 0 within [`POLE_SNAP`] of a0 (the spin pole's strip, an
    /// edge of the initial panels at Y = sin(asin(a0/J3)), where the
    /// rounding of Y leaves a = 0 or ± an ulp of a0 at random).
    pub(crate) fn strip(&self, y: f64) -> Strip {
        let a = self.a0 - self.j3 * y;
        Strip {
            c: (1.0 - y * y).max(0.0).sqrt(),
            a: if a.abs() <= POLE_SNAP * self.a0.abs() {
                0.0
            } else {
                a
            },
            b1: self.gy * self.b1,
            q2: self.gy * self.q2,
            gy: self.gy,
            vis: None,
        }
    }
}

/// Return of an elastic trial stress (zx, zy) onto the limit |Z| ≤ L for the
/// stiffness G = diag(1, gy): the closest point in the energy norm
/// (Z − Zt)ᵀG⁻¹(Z − Zt), Z = (zx/(1+μ), zy/(1+gy·μ)) with μ ≥ 0 such that
/// |Z| = L (radial for gy = 1). Used by the grid and viscoelastic schemes.
pub(crate) fn return_map(zx: f64, zy: f64, l: f64, gy: f64) -> (f64, f64) {
    let m = zx.hypot(zy);
    if m <= l {
        return (zx, zy);
    }
    if l <= 0.0 || m == 0.0 {
        return (0.0, 0.0);
    }
    if gy == 1.0 {
        return (zx * l / m, zy * l / m);
    }
    // f(μ) = zx²/(1+μ)² + zy²/(1+gy·μ)² − L² is decreasing and convex, so
    // Newton from μ = 0 increases monotonically to the root.
    let mut mu = 0.0_f64;
    for _ in 0..100 {
        let (dx, dy) = (1.0 + mu, 1.0 + gy * mu);
        let (px, py) = (zx / dx, zy / dy);
        let f = px * px + py * py - l * l;
        let fp = -2.0 * (px * px / dx + gy * py * py / dy);
        if f <= 1e-15 * l * l || fp >= 0.0 {
            break;
        }
        mu -= f / fp;
    }
    let (px, py) = (zx / (1.0 + mu), zy / (1.0 + gy * mu));
    // Put it exactly on the limit (Newton stops within round-off).
    let r = px.hypot(py);
    if r > 0.0 {
        (px * l / r, py * l / r)
    } else {
        (0.0, 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    #[test]
    fn pure_slip_strip_matches_closed_form() {
        // Strip c = 1, Zx = A(X+1) until the limit at ξ* = (1−S²)/(1+S²),
        // S = A/1.5, then Zx = 1.5√(1−X²) (the direction stays fixed):
        // ∫ = A(1+ξ*)²/2 + 1.5·½[π/2 − ξ*√(1−ξ*²) − asin ξ*].
        let a = 1.7_f64;
        let s = a / 1.5;
        let xi = (1.0 - s * s) / (1.0 + s * s);
        let exact = a * (1.0 + xi).powi(2) / 2.0
            + 1.5 * 0.5 * (FRAC_PI_2 - (xi * (1.0 - xi * xi).sqrt() + xi.asin()));
        let st = Strip {
            c: 1.0,
            a,
            b1: 0.0,
            q2: 0.0,
            gy: 1.0,
            vis: None,
        };
        // The yield point is found to round-off; the plastic part is RK4
        // (Simpson) on the smooth 1.5·cos²s: error ≈ 5e-8 at h = 0.1 and
        // O(h⁴), so ≈ 5e-12 at h = 0.01; tolerance 1e-10.
        let r = st.integrate(0.01, 0.01);
        assert!((r.ix - exact).abs() < 1e-10, "{} {}", r.ix, exact);
        assert!(r.iy.abs() < 1e-15);
    }
}
