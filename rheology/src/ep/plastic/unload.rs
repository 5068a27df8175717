//! The end of a plastic segment by elastic unloading. After each step the
//! segment driver's `Strip::step_end` (`mod.rs`) evaluates g = (v·n)·cos s +
//! (3/2)·sin s at the step's end; where it is negative, unloading started
//! inside the step and [`Strip::locate_unload`] finds where: the root of
//! g's cubic Hermite interpolant over the step ([`hermite_root`], with
//! dg/ds from [`Strip::g_rate`]) as the first trial length, then Newton
//! with the exact dg/ds of the integrated state, safeguarded by regula
//! falsi. The strip integration then goes on elastically from there.

use super::super::{PState, Strip};
use super::rules::sin_cos_small;
use super::{Stiff, TURN_PER_STEP};

/// Largest number of iterations (integrations of the step) locating the
/// start of unloading.
const UNLOAD_ITERATIONS: usize = 6;
/// The same for a viscoelastic cap's exit, where ψ(L) makes g steep and
/// curved (sinh of L/Z0): with 6, k = 3.96, J = (0.0353, 84.9, 0),
/// D = 0.0249, Z0 = 0.312 at tol 1e-3 stopped at g = −53 (g rising from
/// 1.3 to far below 0 over one exponential step), the exit 0.28 rad late
/// in σ and the contact 2.2·tol off (docs/decisions/0119). The bracket
/// (regula falsi, Illinois) converges within these.
const UNLOAD_ITERATIONS_VIS: usize = 24;
/// Largest number of Newton steps on the cubic Hermite interpolant of g over
/// a step (its root is the first iterate locating unloading; only scalar
/// arithmetic, no integration).
const HERMITE_ITERATIONS: usize = 8;
/// |g| below which the start of unloading counts as located.
const UNLOAD_G_TOL: f64 = 1e-13;
/// Error in s of the start of unloading accepted per s-step⁴: the Newton
/// iteration of [`Strip::locate_unload`] stops once its next correction
/// |g/g'| is at most this times s_step⁴, as the yield search does
/// (`ROOT_TOL_PER_STEP4` in yield_point.rs): the RK4 steps' error is
/// ≈ 10·s_step⁴ (the tolerance), and the strip sums change by ≈ |Z| times
/// the location error. At tol 1e-3 cases p, b, c take 3.8, 1.5, 1.4 %
/// fewer instructions, the worst error/tol of `cargo xtask ep-sets` is
/// unchanged (docs/decisions/0079).
const UNLOAD_ROOT_PER_STEP4: f64 = 1e-3;

impl Strip {
    /// dg/ds along the plastic flow at a state on the limit: with
    /// g = (a·nx + vy·ny)·cos s + (3/2)·sin s, dn/ds = θ'·(−ny, nx) and
    /// dvy/ds = q2·c·cos s (with a viscous law, minus that of its term).
    #[inline]
    pub(in crate::ep) fn g_rate<const VIS: bool>(&self, sn: f64, cs: f64, nx: f64, ny: f64) -> f64 {
        let vy = self.vy(self.c * sn);
        let th = self.theta_rate(sn, cs, nx, ny);
        let dvn = th * (vy * nx - self.a * ny) + self.q2 * self.c * cs * ny;
        let r = dvn * cs - (self.a * nx + vy * ny) * sn + 1.5 * cs;
        match &self.vis {
            Some(law) if VIS => {
                // d/ds of ψ(L)·N·cos s, L = (3/2)·c·cos s, N = nx² + gy·ny²
                // (dN/ds = 2(gy − 1)·nx·ny·θ').
                let l = 1.5 * self.c * cs;
                let (mu, dpsi) = law.rates(l);
                let psi = mu * l;
                let ngn = nx * nx + self.gy * ny * ny;
                let dngn = 2.0 * (self.gy - 1.0) * nx * ny * th;
                r - (dpsi * (-1.5 * self.c * sn) * ngn * cs + psi * (dngn * cs - ngn * sn))
            }
            _ => r,
        }
    }

    /// With a viscous law, a band inside the step from `p` to `q` (length
    /// h, g ≥ 0 at both ends) where the stress leaves the cap: where the
    /// cubic Hermite interpolant of g over the step (g and dg/ds at both
    /// ends) dips below 0, the state r at its least value (the step
    /// shortened to t), if g < 0 there: (r, t, g(r)). The start of the band
    /// then lies between p and r ([`Strip::locate_unload`]). A band whose
    /// dip the interpolant does not show is narrower than the step's
    /// resolution of g, and its effect on the strip sums is of that order.
    #[cold]
    #[inline(never)]
    pub(super) fn cap_exit_inside<const ISO: bool>(
        &self,
        p: &PState,
        q: &PState,
        h: f64,
        a_h: f64,
    ) -> Option<(PState, f64, f64)> {
        let law = self.vis.as_ref()?;
        // First without the exponentials: ψ(L) ≤ ψ(3/2) makes
        // B = g_ep − ψ(3/2)·N·cos s (N = nx² + gy·ny²) a lower bound of g;
        // where B's interpolant stays ≥ 0 over the step, so does g's.
        let pm = law.psi_max();
        if pm.is_finite() {
            let bound = |r: &PState| {
                let ngn = r.nx * r.nx + self.gy * r.ny * r.ny;
                // dN/ds = 2(gy − 1)·nx·ny·θ' (0 for an isotropic stiffness).
                let dngn = if self.gy == 1.0 {
                    0.0
                } else {
                    2.0 * (self.gy - 1.0) * r.nx * r.ny * self.theta_rate(r.sn, r.cs, r.nx, r.ny)
                };
                let b = self.g::<false>(r.sn, r.cs, r.nx, r.ny) - pm * ngn * r.cs;
                let db =
                    self.g_rate::<false>(r.sn, r.cs, r.nx, r.ny) - pm * (dngn * r.cs - ngn * r.sn);
                (b, h * db)
            };
            let ((b0, e0), (b1, e1)) = (bound(p), bound(q));
            if b0 >= 0.0 && b1 >= 0.0 && hermite_min(b0, e0, b1, e1).is_none_or(|m| m.1 >= 0.0) {
                return None;
            }
        }
        let g0 = self.g::<true>(p.sn, p.cs, p.nx, p.ny);
        let g1 = self.g::<true>(q.sn, q.cs, q.nx, q.ny);
        let d0 = h * self.g_rate::<true>(p.sn, p.cs, p.nx, p.ny);
        let d1 = h * self.g_rate::<true>(q.sn, q.cs, q.nx, q.ny);
        let (u, gu) = hermite_min(g0.max(0.0), d0, g1.max(0.0), d1)?;
        if gu >= 0.0 {
            return None;
        }
        let t = u * h;
        let (st, ct) = sin_cos_small(0.5 * t);
        let r = self.advance::<ISO>(p, t, ct, st, a_h, Stiff::at(a_h / TURN_PER_STEP), None);
        let gr = self.g::<true>(r.sn, r.cs, r.nx, r.ny);
        (gr < 0.0).then_some((r, t, gr))
    }

    /// The state where unloading begins inside the step of length `h` from
    /// `p` to `q` (g ≥ 0 at its start, g = `g1` < 0 at its end), found on the
    /// integrated g of the step shortened to t: the first t is the root of
    /// the cubic Hermite interpolant of g over the step (g and dg/ds at both
    /// ends, [`Strip::g_rate`]), the next ones Newton steps with the exact
    /// dg/ds of the state reached, each kept inside the bracket (regula
    /// falsi, Illinois, where it would leave it); at most
    /// [`UNLOAD_ITERATIONS`] integrations ([`UNLOAD_ITERATIONS_VIS`] for a
    /// viscoelastic cap's exit) or until |g| < [`UNLOAD_G_TOL`] or
    /// the next Newton correction is below [`UNLOAD_ROOT_PER_STEP4`]·s_step⁴
    /// (s_step = `a_h`/TURN_PER_STEP). Two integrations (|g| ≈ 1e-8, then
    /// round-off) without the last criterion, where regula falsi alone took
    /// 4–5, to the same point.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn locate_unload<const ISO: bool, const VIS: bool>(
        &self,
        p: &PState,
        q: &PState,
        h: f64,
        g1: f64,
        a_h: f64,
    ) -> PState {
        crate::counts::count!(unloadings);
        let g0 = self.g::<VIS>(p.sn, p.cs, p.nx, p.ny).max(0.0);
        let (mut tl, mut gl, mut th, mut gh) = (0.0, g0, h, g1);
        let mut best = *p;
        let mut side = 0i32;
        let s_step = a_h / TURN_PER_STEP;
        let stiff = Stiff::at(s_step);
        let t_tol = UNLOAD_ROOT_PER_STEP4 * (s_step * s_step) * (s_step * s_step);
        let mut newton = hermite_root(
            g0,
            h * self.g_rate::<VIS>(p.sn, p.cs, p.nx, p.ny),
            g1,
            h * self.g_rate::<VIS>(q.sn, q.cs, q.nx, q.ny),
        ) * h;
        let iterations = if VIS {
            UNLOAD_ITERATIONS_VIS
        } else {
            UNLOAD_ITERATIONS
        };
        for _ in 0..iterations {
            let t = if newton > tl && newton < th {
                newton
            } else if gl - gh > 0.0 {
                tl + (th - tl) * gl / (gl - gh)
            } else {
                0.5 * (tl + th)
            };
            let (st, ct) = sin_cos_small(0.5 * t);
            let r = self.advance::<ISO>(p, t, ct, st, a_h, stiff, None);
            let gr = self.g::<VIS>(r.sn, r.cs, r.nx, r.ny);
            best = r;
            if gr.abs() < UNLOAD_G_TOL {
                break;
            }
            let dg = self.g_rate::<VIS>(r.sn, r.cs, r.nx, r.ny);
            if (gr / dg).abs() <= t_tol {
                break;
            }
            if gr < 0.0 {
                th = t;
                gh = gr;
                if side == -1 {
                    gl *= 0.5;
                }
                side = -1;
            } else {
                tl = t;
                gl = gr;
                if side == 1 {
                    gh *= 0.5;
                }
                side = 1;
            }
            newton = t - gr / dg;
        }
        best
    }
}

/// The interior local minimum in (0, 1) of the cubic Hermite interpolant
/// with values g0, g1 and derivatives d0, d1 at 0 and 1: where it is taken
/// and its value (None if the interpolant has no local minimum inside).
fn hermite_min(g0: f64, d0: f64, g1: f64, d1: f64) -> Option<(f64, f64)> {
    // G(u) = g0 + d0·u + c2·u² + c3·u³, G'(u) = d0 + 2·c2·u + 3·c3·u².
    let c2 = 3.0 * (g1 - g0) - 2.0 * d0 - d1;
    let c3 = 2.0 * (g0 - g1) + d0 + d1;
    if d0 >= 0.0 && d1 <= 0.0 {
        // Rising from 0 and falling into 1: no interior minimum.
        return None;
    }
    let gu = |u: f64| g0 + u * (d0 + u * (c2 + u * c3));
    // The roots of G', the minimum where G'' = 2·c2 + 6·c3·u > 0.
    let (a, b, c) = (3.0 * c3, 2.0 * c2, d0);
    let u = if a.abs() <= 1e-12 * (b.abs() + c.abs()) {
        -c / b
    } else {
        let disc = b * b - 4.0 * a * c;
        if disc < 0.0 {
            return None;
        }
        let r = disc.sqrt();
        // The root at which G'' = 2·a·u + b > 0 (numerically stable form).
        let q = -0.5 * (b + b.signum() * r);
        let (u1, u2) = (q / a, c / q);
        if 2.0 * a * u1 + b > 0.0 { u1 } else { u2 }
    };
    (u > 0.0 && u < 1.0 && 2.0 * a * u + b > 0.0).then(|| (u, gu(u)))
}

/// Root in (0, 1) of the cubic Hermite interpolant with values g0, g1 and
/// derivatives d0, d1 at 0 and 1 (g0 ≥ 0 > g1): Newton from the
/// regula-falsi point; NaN if an iterate leaves the interval (the caller then
/// starts with regula falsi), the last iterate if it has not settled within
/// [`HERMITE_ITERATIONS`] steps (the caller only uses it as a trial point:
/// the integrated g decides).
fn hermite_root(g0: f64, d0: f64, g1: f64, d1: f64) -> f64 {
    // G(u) = g0 + d0·u + c2·u² + c3·u³.
    let c2 = 3.0 * (g1 - g0) - 2.0 * d0 - d1;
    let c3 = 2.0 * (g0 - g1) + d0 + d1;
    let mut u = g0 / (g0 - g1);
    for _ in 0..HERMITE_ITERATIONS {
        let gu = g0 + u * (d0 + u * (c2 + u * c3));
        let du = d0 + u * (2.0 * c2 + 3.0 * u * c3);
        let step = gu / du;
        u -= step;
        if !(u > 0.0 && u < 1.0) {
            return f64::NAN;
        }
        if step.abs() < 1e-14 {
            return u;
        }
    }
    u
}

#[cfg(test)]
mod tests {
    use super::hermite_min;

    /// The least value of the cubic Hermite interpolant against a dense
    /// scan of the same cubic (exact cubic arithmetic: agreement to
    /// round-off, 1e-12), and None where it has no interior minimum.
    #[test]
    fn hermite_min_is_the_interpolants_least_interior_value() {
        let cubic = |g0: f64, d0: f64, g1: f64, d1: f64, u: f64| {
            let c2 = 3.0 * (g1 - g0) - 2.0 * d0 - d1;
            let c3 = 2.0 * (g0 - g1) + d0 + d1;
            g0 + u * (d0 + u * (c2 + u * c3))
        };
        // (g0, d0, g1, d1): a dip below 0 between positive ends, a shallow
        // dip, a dip near an end, a quadratic (c3 = 0).
        for (g0, d0, g1, d1) in [
            (0.3, -2.0, 0.2, 1.5),
            (1.0, -0.5, 1.0, 0.5),
            (0.05, -0.4, 2.0, 3.0),
            (1.0, -2.0, 1.0, 2.0),
        ] {
            let (u, m) = hermite_min(g0, d0, g1, d1).expect("an interior minimum");
            let scan = (1..10_000)
                .map(|i| cubic(g0, d0, g1, d1, i as f64 / 10_000.0))
                .fold(f64::INFINITY, f64::min);
            assert!((m - cubic(g0, d0, g1, d1, u)).abs() <= 1e-12);
            assert!(m <= scan + 1e-12 && scan - m <= 1e-6, "{m} against {scan}");
        }
        // Rising from the start, falling into the end, or monotone: none.
        for (g0, d0, g1, d1) in [
            (0.1, 1.0, 0.2, -1.0),
            (0.0, 1.0, 1.0, 1.0),
            (1.0, -1.0, 0.0, -1.0),
        ] {
            assert!(hermite_min(g0, d0, g1, d1).is_none());
        }
    }
}
