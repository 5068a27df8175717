//! Plastic segments of a strip: the stress on the limit, |Z| = L, with its
//! direction n turning at dθ/ds = (2/3)(v·t) (isotropic), integrated by RK4
//! with stiffness and turn control, the quasi-steady limit for large κ, and
//! the location of elastic unloading.
//!
//! The segment driver and the loops that choose the step kinds. A segment
//! starts where the strip integration (`Strip::integrate_with`) finds a
//! yield point and calls [`Strip::plastic`]; that picks the step kind of the
//! whole segment from its (κ·h, |α'|·h) bounds (`Strip::rates`): equal
//! exponential steps ([`Strip::plastic_etd`]) or equal fifth-order steps
//! ([`Strip::plastic_rk5`]), both through [`Strip::equal_steps`], or its own
//! loop of RK4 steps, shortened for the turn of the slip direction
//! ([`Strip::turn_step`]) and graded after yield, each taken by
//! [`Strip::advance`] (one RK4 step, continuous sub-steps
//! [`Strip::sub_steps`], or the quasi-steady step blended in). Every step
//! ends in [`Strip::step_end`], which records the state, and where g turns
//! negative locates the start of unloading (`unload.rs`) and ends the
//! segment there; otherwise the segment ends at the outlet. The one-step
//! rules themselves (RK4, the fifth-order rule, the exponential and the
//! quasi-steady step, the step bounds) are in `rules.rs`.

mod rules;
mod unload;

use std::f64::consts::FRAC_PI_2;

use super::{CS_MIN, Event, PState, PlasticEnd, Strip, StripSums, smooth_step};
use rules::{blend, sin_cos_small};

/// Largest variation of κ within an exponential step, bounded by
/// (2/3)|q2|·c·h (the frozen part of κ is integrated exactly, the variation
/// explicitly). Against 128-panel references on 307 cases
/// (docs/decisions/0068) 0.5 leaves the worst error/tol of every set
/// unchanged at tol 1e-2…1e-4; 1 and 2 moved results by up to 0.14·tol
/// (2: worst error/tol 0.092 → 0.094 on the wide-range set at 1e-2) for no
/// gain on the bench set at 1e-3.
const ETD_KAPPA_VARIATION: f64 = 0.5;

/// Shortest exponential step as a multiple of the s-step: an exponential
/// step costs ≈ 2.3 RK4 steps (≈ 465 instructions with its exp), so
/// shorter ones do not pay (down to 1 s-step: case b +25 % instructions at
/// tol 1e-3).
pub(super) const ETD_MIN_STEP: f64 = 2.5;

/// Largest number of RK4 sub-steps per step before the quasi-steady branch
/// (isotropic stiffness: κ·h > 2·MAX_SUB, where the lag α'/κ of the stress
/// behind the slip direction and its first correction are tiny). 8 instead
/// of 16: on 157 wide-range cases (k 0.05–20, |J3| to 316) 24–34 % fewer
/// RK4 steps at tol = 1e-2…1e-4 (up to 2.4× on single large-|J| cases),
/// 11–16 % fewer instructions in total, results moved by ≤ 0.052·tol,
/// worst error/tol against the reference
/// unchanged there and on 374 cases with |J| ≤ 26 (docs/decisions/0066);
/// 4: another −30 %, but the worst error/tol at 1e-3 rose 0.32 → 0.35.
const MAX_SUB: usize = 8;
/// The quasi-steady branch is blended in (a C¹ step in κ·h) from MAX_SUB
/// (or the anisotropic count) to this times it stability sub-steps, so
/// that the switch adds no jump in the inputs: switched without the blend,
/// the step's result jumps by up to 1.2e-3 in n
/// (docs/decisions/0082). 1.125: 8 to 9 sub-steps, κ·h from 16 to 18.
const QS_BLEND: f64 = 1.125;
/// The same count's base for an anisotropic stiffness (see `advance`).
const MAX_SUB_ANISO: usize = 16;
/// Largest turn of the slip direction α per step, as a multiple of the
/// s-step: steps (and sub-steps) are shortened to |α'|·h ≤ 4·s_step near a
/// strip's crossing of the line vy = 0, where α turns by up to π within
/// ΔX ≈ |a/q2| (high spin). Without it, strips crossing close to the pole
/// were wrong by up to 0.2 at tol = 1e-2 (k = 0.151, J = (0.358, 0.648,
/// −43.2)). 4 instead of 3 (docs/decisions/0083): at tol 1e-3 cases h, a,
/// b, c −12/−6/−8/−15 % instructions (with KAPPA_H_STIFF), worst error/tol
/// of `cargo xtask ep-sets` over 16 seeds and 11 fresh ones not worse; 5:
/// −17/−12/−15/−20 %, but 0.61·tol at 1e-4 on 4 of the fresh seeds (0.47
/// before), 6: 0.64·tol on the 16.
const TURN_PER_STEP: f64 = 4.0;
/// Newton iterations of `Strip::turn_bound_step`.
const TURN_BOUND_NEWTON: usize = 4;
/// Longest step of `Strip::turn_bound_step` relative to the distance from
/// the crossing of vy = 0 (docs/decisions/0108: 0.5 and 1 took 3–20 %
/// fewer plastic steps at |J3| = 1e4…1e6, for less margin).
const TURN_BOUND_DISTANCE: f64 = 0.25;
/// Largest number of sub-steps per step for the turn of the slip direction.
const MAX_SUB_TURN: f64 = 256.0;
/// RK4 sub-step counts for κ (κ·h/KAPPA_H_STIFF) over which one
/// Rosenbrock step on the lag (`Strip::rodas3_lag`) takes the place of the
/// sub-steps of an isotropic step (a C¹ step in between; `evaluate` only),
/// where the slip direction turns slowly (ROS_SUB_TURN) and the step's
/// error estimate is small (ROS_EST). A Rosenbrock step runs ≈ 1.5–2 RK4
/// sub-steps' instructions, but on a longer chain of dependent operations:
/// in wall time it pays from ≈ 4 sub-steps on (docs/decisions/0114; from 3:
/// the random batch at tol 1e-4 +3 %, k = 0.33, J = (3.3, 2.7, 25.8) at
/// 1e-3 +5 %). The narrow blend keeps the steps that take both few (with
/// (4, 5), k = 1, J = (0.5, 1, 100) at tol 1e-3 had all its 559 such steps
/// in the blend, +30 % time).
const ROS_SUB: (f64, f64) = (3.5, 3.75);
/// The turn's sub-step counts (|α'|·h/a_h) over which the Rosenbrock step
/// is blended out.
const ROS_SUB_TURN: (f64, f64) = (0.8, 1.0);
/// Error estimate of a Rosenbrock step's lag allowed, ROS_EST·s_step⁴ rad
/// (4·tol at the s-step of tol, `Accuracy::s_step`), blended out up to
/// twice that: the estimate is 3–5 times the actual error of the
/// direction, which relaxes within 1/κ, so its effect on the strip sums is
/// far smaller (docs/decisions/0114).
const ROS_EST: f64 = 40.0;
/// Largest κ·h of a step that is limited by the exact turn of the slip
/// direction (`Strip::turn_step`) rather than by the bound |α'|max·h
/// (which makes the steps creep towards vy = 0 in short pieces). Where
/// κ·h is larger RK4 does not resolve a step holding the rate peak of α
/// (docs/decisions/0074: without a limit 1.28·tol at tol 1e-2). Measured
/// (docs/decisions/0075): with 1 the worst error/tol over 4842 cases of
/// `cargo xtask ep-sets` at tol 1e-2/1e-3/1e-4 rises by ≤ 0.04 (wide range
/// 0.147 → 0.184 at 1e-3), with 2 to 0.371 there; 0.5 is no more accurate
/// (tests/convergence.rs 0.34 against 0.30) for the same instructions.
const TURN_EXACT_KAPPA_H: f64 = 1.0;
/// κ·h of the exact-turn step up to which it is taken whole, and from which
/// the bound's step is taken instead; blended in between (see
/// `Strip::plastic`). Switched hard at TURN_EXACT_KAPPA_H, the choice made
/// jumps of 0.042·tol along a random line (`cargo xtask ep-sets lines 3`
/// with TURN_PER_STEP = 4, docs/decisions/0083).
const TURN_EXACT_BLEND: (f64, f64) = (0.8 * TURN_EXACT_KAPPA_H, TURN_EXACT_KAPPA_H);
/// Largest number of steps of a plastic segment (a guard: the turn limit
/// needs at most span/s_step·(1 + π/(4·s_step)) steps).
const MAX_STEPS: usize = 1 << 16;
/// RK4 stability margin on κ·h of non-stiff segments, and the unit of the
/// quasi-steady threshold MAX_SUB·KAPPA_H (the real stability limit is 2.78; at 2 the
/// RK4 amplification of the linearised relaxation is 1/3, positive, so the
/// transient still decays monotonically). Raised from 1.2 without changing
/// the verified accuracy of `evaluate` (rheology/tests/convergence.rs; its
/// worst error/tol: crate README, section Convergence).
const KAPPA_H: f64 = 2.0;
/// RK4's accuracy margin on κ·h of whole non-stiff segments at the longer
/// s-step, at tol 1e-4. A segment non-stiff at the longer step (κ·h ≤
/// KAPPA_H over it) takes equal RK4 steps of about that step only where
/// κ·h ≤ KAPPA_H_SMOOTH·s_step/S_STEP_1E4 there too; otherwise the fewest
/// equal RK4 steps within that margin, at most those of the s-step. The
/// margin falls with the s-step (∝ tol^(1/4)) and is KAPPA_H from tol ≈
/// 7.7e-4 up, where nothing changes.
///
/// RK4 follows a relaxing stress direction poorly at κ·h near 2, and the
/// error it leaves does not fall with the step's tol^(1/4) alone: at k =
/// 0.0654, J = (−0.712, −0.277, −1.692) the strips after a re-yield (κ·h
/// 0.5 → 1.9 along the segment) were off by up to 2e-3 rad, and J6 by
/// 0.73·tol at tol 1e-4 and 0.89–0.94·tol from 3e-5 to 2e-6; now 0.20·tol
/// (docs/decisions/0128). Where the longer s-step is the s-step
/// (`Strip::integrate`) the steps are unchanged.
const KAPPA_H_SMOOTH: f64 = 1.2;
/// The s-step at tol 1e-4, 0.1·(0.1)^(1/4) ([`crate::Accuracy::s_step`]).
const S_STEP_1E4: f64 = 0.056_234_132_519_034_91;
/// Step of the slowest non-stiff segments in `evaluate`, as a multiple of
/// the longer s-step: taken where κ·h ≤ KAPPA_H_LONG at it over the whole
/// segment (and the slip direction turns by ≤ TURN_PER_STEP s-steps per
/// step). On such segments RK4's error in the relaxation of n is small
/// enough for steps 1.5 times longer (docs/decisions/0085: at tol 1e-3
/// cases m, p, s −14/−7/−7 % instructions, worst error/tol of
/// `cargo xtask ep-sets` on 70 seeds unchanged, results moved by
/// ≤ 0.044·tol; 2 raised it to 0.55 at 1e-4). The fixed-resolution
/// reference (`Strip::integrate`) does not use them.
const LONG_FACTOR: f64 = 1.5;
/// κ·h bound of the steps of LONG_FACTOR (see there): with 1 the worst
/// error/tol at tol 1e-4 rose from 0.48 to 0.65 (k = 0.058, J ≈ (−0.36,
/// −0.35, −0.51), whose segments relax at κ ≈ 5–7 throughout), 0.9 left
/// it unchanged; 0.75 keeps a margin for ≤ 1 % fewer instructions.
const KAPPA_H_LONG: f64 = 0.75;

/// κ·h bound up to which a segment that is stiff for RK4 (κ·h > KAPPA_H)
/// and takes no exponential steps is taken in equal steps of the
/// fifth-order rule (`Strip::rk5`, real stability interval 3.39): at the
/// longer s-step where it holds there, else at the s-step where it holds
/// there, instead of RK4 at the s-step with the graded start; in
/// `evaluate` only (docs/decisions/0091: at tol 1e-3 cases a, h −4.4 /
/// −1.9 %, at 1e-2 h, s, a −20 / −14 / −8.9 %, 307 cases −5.5 / −2.9 /
/// −2.0 % at 1e-2 / 1e-3 / 1e-4, worst error/tol of `cargo xtask ep-sets`
/// on 62 seeds unchanged except 0.241 → 0.271 at 1e-4 (others); 2.4 and
/// 3.0–3.2 measured alike, 2.8 keeps a margin below the stability limit).
/// The fixed-resolution reference (`Strip::integrate`) does not use it.
const RK5_KAPPA_H_STIFF: f64 = 2.8;

/// Sub-step counts of the bound over which the anisotropic relaxation rate
/// at the step's directions (`Strip::aniso_rate`) takes over the count in
/// `Strip::advance` (blended in between).
const ANISO_SUB: (f64, f64) = (8.0, 10.0);

/// RK4 margin on κ·h of the steps that `Strip::advance` takes whole on
/// stiff segments (sub-steps beyond it). 1.5 rather than KAPPA_H: with the
/// longer turn-limited steps of TURN_PER_STEP = 4 it keeps the worst
/// error/tol of the wide-range sets where it was (docs/decisions/0083:
/// 0.165 / 0.441 at tol 1e-3 / 1e-4 on 16 seeds, against 0.317 / 0.541 with
/// KAPPA_H), for +8 % instructions on the random sets at 1e-3 and ≤ 0.2 %
/// on the bench set at 1e-3 and 1e-4 (case a at 1e-2 +14 %).
const KAPPA_H_STIFF: f64 = 1.5;

/// The stiff steps' settings at an s-step ([`Stiff::at`]).
#[derive(Debug, Clone, Copy)]
pub(super) struct Stiff {
    /// RK4 margin on κ·h of a sub-step.
    kh: f64,
    /// Factor on the quasi-steady threshold (MAX_SUB·KAPPA_H, and the
    /// anisotropic one).
    qs: f64,
}

impl Stiff {
    /// The settings at the s-step `s_step`: at tol ≥ 1e-4 the RK4 margin
    /// KAPPA_H_STIFF and the quasi-steady threshold MAX_SUB·KAPPA_H; below,
    /// with r = s_step/S_STEP_1E4 (∝ tol^(1/4)), the margin
    /// KAPPA_H_STIFF·r² (∝ √tol: 0.47 at tol 1e-5, 0.15 at 1e-6; applied
    /// through [`Stiff::sub_steps`]) and the threshold divided by r (the
    /// quasi-steady steps start at the same κ, not at the same κ·h).
    ///
    /// Neither error falls with the s-step alone. RK4 sub-steps follow the
    /// relaxation of the stress direction after a yield, or after the slip
    /// direction turns where a strip crosses vy = 0, with an error of about
    /// (κ·h)^2.6 (measured at tol 1e-6 with margins 1.5 … 0.15); the
    /// quasi-steady direction neglects terms of order 1/κ. With both fixed,
    /// k = 0.0633, J = (0, −115.84, 87.68) was off by 0.70 / 4.4 /
    /// 12.1·tol at tol 1e-5 / 2e-6 / 1e-6 (now 0.09 / 0.03 / 0.03), and
    /// k = 0.0789, J = (−215.6, 1.63, −548.9) by 0.72 / 1.85 / 2.10·tol
    /// (now 0.17 / 0.03 / 0.01); a margin ∝ r left error/tol growing as tol
    /// falls (k = 0.0748, J = (0, −28.57, 27.16): 1.22 at 1e-5, 1.99 at
    /// 1e-6). Nothing changes at tol ≥ 1e-4 (docs/decisions/0129).
    #[inline(always)]
    fn at(s_step: f64) -> Self {
        let r = (s_step / S_STEP_1E4).min(1.0);
        Stiff {
            kh: KAPPA_H_STIFF * (r * r),
            qs: 1.0 / r,
        }
    }

    /// The RK4 sub-step count for κ of a step of κ·h = `kh` (real, see
    /// `Strip::sub_steps`): kh/KAPPA_H_STIFF, and at least min(kh,
    /// KAPPA_H)/margin. The small margin serves the relaxation transient,
    /// which the graded start after a yield takes in steps of κ·h ≤
    /// KAPPA_H; on the longer steps the flow has relaxed, and their count
    /// only has to stay continuous in kh. With the margin on every step, at
    /// tol 1e-7 k = 1, J = (0, 0, 1e4) took 4.6 s instead of 0.24–0.29 s, with
    /// results within 4e-10 of each other (docs/decisions/0129).
    #[inline(always)]
    fn sub_steps(&self, kh: f64) -> f64 {
        (kh / KAPPA_H_STIFF).max(kh.min(KAPPA_H) / self.kh)
    }
}

/// Relative slack of the κ·h test of a whole segment (round-off of the bound).
const KAPPA_H_SLACK: f64 = 1e-12;
/// κ·h of the first step after yield on stiff segments (doubled per step).
const GRADED_KAPPA_H: f64 = 0.5;
/// Steps after yield over which the graded start applies (the cap has
/// long exceeded the regular step by then).
const GRADED_STEPS: usize = 40;
/// Floor of the relaxation rate κ in the graded start (v = 0 at the yield point).
const RATE_FLOOR: f64 = 1e-300;
/// Unloading is only looked for while cos s exceeds this (at the outlet
/// L = 0 and g = (3/2)·sin s > 0 anyway).
const OUTLET_CS: f64 = 1e-12;

impl Strip {
    /// Advance the plastic state by h (cos/sin of h/2 given): one RK4 step,
    /// or sub-steps whose lengths vary continuously with the step's bounds
    /// (`Strip::sub_steps`) where κ·h exceeds the RK4 margin `stiff.kh`
    /// ([`Stiff::at`]) or the slip direction turns by more than `a_h`
    /// within the step (beyond κ·h = MAX_SUB·KAPPA_H·`stiff.qs`: the
    /// quasi-steady direction, blended in up to QS_BLEND times that).
    /// `rates`: the step's (κ·h, |α'|·h) bounds if the caller has them.
    /// Inlined: its call and the state passed through memory cost ≈ 40
    /// instructions per stiff step (bit-identical results; cases a, b, c
    /// −3…−4 % instructions at tol 1e-3).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn advance<const ISO: bool>(
        &self,
        p: &PState,
        h: f64,
        c2: f64,
        s2: f64,
        a_h: f64,
        stiff: Stiff,
        rates: Option<(f64, f64)>,
    ) -> PState {
        let (sm, cm) = (p.sn * c2 + p.cs * s2, p.cs * c2 - p.sn * s2);
        let (s1, c1) = (sm * c2 + cm * s2, (cm * c2 - sm * s2).max(0.0));
        crate::counts::count!(stiff_steps);
        let (kh, ah) = match rates {
            Some(r) => r,
            None => self.rates::<ISO>(p.sn, p.cs, s1, c1, h),
        };
        if kh.is_nan() || (kh <= stiff.kh && ah <= a_h) {
            return self.rk4::<ISO>(p, h, c2, s2);
        }
        // Sub-steps needed for accuracy (`Stiff::sub_steps`) and the turn,
        // as a real number; the quasi-steady branch from κ·h > MAX_SUB·
        // KAPPA_H·stiff.qs.
        let mk = kh / KAPPA_H;
        let (mr_k, mr_a) = (stiff.sub_steps(kh), (ah / a_h).min(MAX_SUB_TURN));
        let mut mr = mr_k.max(mr_a);
        // With gy ≠ 1 the bound holds over every stress direction. Where it
        // asks for more than ANISO_SUB.0 sub-steps, the relaxation rate at
        // the directions the step can take sets their count instead
        // (`Strip::aniso_sub_steps`). The quasi-steady switch keeps the
        // bound.
        if !self.iso::<ISO>() && mr > ANISO_SUB.0 {
            mr = self.aniso_sub_steps(p, (s1, c1, h), (mr_k, mr_a), stiff.kh);
        }
        // With gy ≠ 1 the bound on κ·h (see `rates`) can exceed the actual
        // relaxation rate of θ by up to f = 1 + |gy − 1|/min(1, gy), and the
        // quasi-steady direction is then wrong where the flow is not yet
        // quasi-steady. Measured against converged solutions: switching at
        // 16 gave 20·tol at tol = 1e-3 (gy = 8.7, J ≈ 10), at
        // 16·f still 1.65·tol at 1e-4 (gy = 0.1, k = 0.05, J ≈ 300); at
        // 4·16·f within tol on the anisotropic scan of the crate README
        // (+0–20 % time).
        let max_sub = stiff.qs
            * if self.iso::<ISO>() {
                MAX_SUB as f64
            } else {
                4.0 * MAX_SUB_ANISO as f64 * (1.0 + self.aniso_f())
            };
        if mk <= max_sub {
            return self.sub_steps::<ISO>(p, (h, c2, s2), mr);
        }
        let qs = self.quasi_steady(p, h, c2, s2);
        // Blended from the sub-steps to the quasi-steady step over
        // max_sub < mk < QS_BLEND·max_sub (a C¹ step in mk), so that the
        // switch adds no jump in the inputs.
        let t = (mk / max_sub - 1.0) / (QS_BLEND - 1.0);
        if t >= 1.0 {
            return qs;
        }
        let rk = self.sub_steps::<ISO>(p, (h, c2, s2), mr);
        blend(&rk, &qs, smooth_step(t))
    }

    /// The sub-step count of an anisotropic step (see `advance`): where the
    /// bound's count `mr_k` exceeds the turn's `mr_a`, the relaxation
    /// rate at the directions the step can take (`Strip::aniso_rate`) sets
    /// it, blended in from ANISO_SUB.0 to ANISO_SUB.1 sub-steps of the bound
    /// (a C¹ step; below ANISO_SUB.0 the rate costs more than the sub-steps
    /// it saves). Continuous in the inputs: the count only falls towards
    /// the turn's, where that sets it.
    /// `margin`: the RK4 margin on κ·h of a sub-step (`Stiff::at`).
    #[cold]
    #[inline(never)]
    fn aniso_sub_steps(
        &self,
        p: &PState,
        (s1, c1, h): (f64, f64, f64),
        (mr_k, mr_a): (f64, f64),
        margin: f64,
    ) -> f64 {
        let mr = mr_k.max(mr_a);
        if mr_k <= mr_a || mr_k <= ANISO_SUB.0 {
            return mr;
        }
        let act = self.aniso_rate(p, s1, c1, h) / margin;
        if act >= mr_k {
            return mr;
        }
        let w = smooth_step((mr_k - ANISO_SUB.0) / (ANISO_SUB.1 - ANISO_SUB.0));
        (mr_k - w * (mr_k - act)).max(mr_a).max(1.0)
    }

    /// `p` advanced by h in RK4 sub-steps where the step needs mr > 1 of
    /// them (real: κ·h/`stiff.kh` or the turn's count, see `advance`):
    /// with n = ⌊mr⌋ and f = mr − n, a first sub-step of length
    /// r = lo + f·(h/(n + 1) − lo), lo = f·h/mr, then n equal ones of
    /// (h − r)/n ≤ h/mr (within the margin). The lengths are continuous in
    /// mr: r = 0 where f = 0, and all n + 1 sub-steps are h/(n + 1) as f → 1,
    /// where the next n takes over. The count is ⌈mr⌉ as with equal
    /// sub-steps, whose length jumps where ⌈mr⌉ does (second differences up
    /// to 0.13·tol along lines at tol 1e-3, docs/decisions/0082). r = lo
    /// alone (the n sub-steps at the margin, the remainder first) is
    /// continuous too, but less accurate (worst error/tol of the wide-range
    /// set at 1e-4 0.51 against 0.46). The first sub-step's (sin, cos) of
    /// r/2 = h/2 − n·hs/2 come from rotating h/2 (`c2`, `s2`) back n times
    /// by hs/2 (a few ulps; cheaper than a second `sin_cos_small`: case h
    /// at tol 1e-2 +2.2 % instead of +4.8 % instructions against equal
    /// sub-steps, whose sin/cos were cached across steps).
    #[inline(always)]
    fn sub_steps<const ISO: bool>(
        &self,
        p: &PState,
        (h, c2, s2): (f64, f64, f64),
        mr: f64,
    ) -> PState {
        let n = mr.floor();
        let f = mr - n;
        let lo = h * f / mr;
        let r = lo + f * (h / (n + 1.0) - lo);
        let hs = (h - r) / n;
        let (s2s, c2s) = sin_cos_small(0.5 * hs);
        let mut q = *p;
        if r > 0.0 {
            let (mut s2r, mut c2r) = (s2, c2);
            for _ in 0..n as usize {
                (s2r, c2r) = (s2r * c2s - c2r * s2s, c2r * c2s + s2r * s2s);
            }
            crate::counts::count!(rk4_sub_steps);
            q = self.rk4::<ISO>(&q, r, c2r, s2r);
        }
        for _ in 0..n as usize {
            crate::counts::count!(rk4_sub_steps);
            q = self.rk4::<ISO>(&q, hs, c2s, s2s);
        }
        q
    }

    /// Plastic flow from yield at X = c·sn (with unit direction n) on;
    /// `VIS`: to the end of the viscoelastic cap instead of unloading (the
    /// viscous term of `Strip::g`, `Strip::limit_segment`).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn plastic<const ISO: bool, const VIS: bool>(
        &self,
        sn: f64,
        cs: f64,
        n: (f64, f64),
        acc: &mut StripSums,
        allow_unload: bool,
        (s_step, s_step_smooth, etd_step, exact_turn): (f64, f64, f64, bool),
        rec: &mut impl FnMut(Event),
    ) -> PlasticEnd {
        rec(Event::Plastic { x: self.c * sn, n });
        // s0 = atan2(sn, cs) with cs = √(1 − sn²) ≥ 0 (asin is cheaper).
        let s0 = sn.asin();
        let span = FRAC_PI_2 - s0;
        if span <= 0.0 {
            return PlasticEnd::Outlet;
        }
        // vy is linear in X, so |v| on the segment is largest at one of its
        // ends and the slip direction turns fastest where |vy| is smallest:
        // if κ·h and |α'|·h are within bounds over the whole segment, no step
        // needs the sub-division test of `advance`. Such non-stiff segments
        // may use the longer step `s_step_smooth`, in `evaluate` (`etd_step`
        // > 0) LONG_FACTOR times it where κ·h ≤ KAPPA_H_LONG there.
        let a_h = TURN_PER_STEP * s_step;
        let steps = |st: f64| ceil_count(span / st).max(1);
        let mut nsteps = steps(s_step_smooth);
        let mut h = span / nsteps as f64;
        // The segment's bounds per unit step (`rates` over the segment is
        // ∝ h: times h they equal it up to rounding, and changed none of
        // the results or references of `cargo xtask ep-sets`).
        let (kr, ar) = self.rates_but_tan::<ISO>(sn, cs, 1.0, 0.0, 1.0);
        // With gy ≠ 1, the anisotropic term's part of the bound, f·|tan s|·h
        // (see `rates`), at equal steps of h that end at the outlet: at the
        // segment's start and at the last step's midpoint (cot(h/2) < 2/h;
        // `rules::outlet_tan`), not at the outlet itself.
        let kt = if self.iso::<ISO>() {
            0.0
        } else {
            self.aniso_f()
        };
        let tan0 = sn.abs() / cs.max(CS_MIN);
        let ok = |h: f64, margin: f64| {
            let t = kt * (h * tan0).max((h / CS_MIN).min(2.0));
            (kr * h + t) * (1.0 + KAPPA_H_SLACK) <= margin && ar * h <= a_h
        };
        let mut nonstiff = ok(h, KAPPA_H);
        let margin = KAPPA_H_SMOOTH * (s_step / S_STEP_1E4);
        if nonstiff && margin < KAPPA_H && !ok(h, margin) {
            // Stable for RK4 at the longer step but beyond its accuracy
            // margin: the fewest equal steps within the margin, at most
            // those of the s-step (the count grows one at a time with κ, so
            // the results do not jump where a segment crosses the margin).
            let most = steps(s_step);
            let mut n = ceil_count(span * kr / margin).clamp(nsteps, most);
            while n < most && !ok(span / n as f64, margin) {
                n += 1;
            }
            nsteps = n;
            h = span / nsteps as f64;
        } else if nonstiff && etd_step > 0.0 {
            let nl = steps(LONG_FACTOR * s_step_smooth);
            let hl = span / nl as f64;
            if nl < nsteps && ok(hl, KAPPA_H_LONG) {
                nsteps = nl;
                h = hl;
            }
        }
        // Stiff segments on which the slip direction turns slowly (far from
        // the spin pole's line vy = 0): exponential steps (`Strip::etd`),
        // which integrate the relaxation at the rate κ exactly for a frozen
        // κ, so that the step is set by the variation of κ and α' rather
        // than by κ·h. κ varies by at most (2/3)|q2|·c per unit s
        // (|d|v|/ds| ≤ |dvy/ds|); that variation within a step is treated
        // explicitly and kept ≤ ETD_KAPPA_VARIATION. Only where the step is
        // at least ETD_MIN_STEP s-steps long (an exponential step costs
        // 2–3 RK4 steps).
        if !nonstiff
            && etd_step > 0.0
            && self.iso::<ISO>()
            && let Some((ne, he)) = self.etd_steps(sn, cs, span, s_step, etd_step)
        {
            let steps = (s_step, ne, he);
            return self.plastic_etd::<VIS>(sn, cs, n, acc, allow_unload, steps, rec);
        }
        // Segments that are stiff for RK4 at the longer s-step (κ·h >
        // KAPPA_H) and take no exponential steps, where κ·h ≤
        // RK5_KAPPA_H_STIFF there: equal steps of the fifth-order rule
        // (`Strip::rk5`) at that step, instead of RK4 at the s-step with the
        // graded start and the sub-division test per step; where they are
        // stiff for RK4 at the s-step too, the same at the s-step.
        if !nonstiff && etd_step > 0.0 && ok(h, RK5_KAPPA_H_STIFF) {
            let steps = (s_step, nsteps, h);
            return self.plastic_rk5::<ISO, VIS>(sn, cs, n, acc, allow_unload, steps, rec);
        }
        if !nonstiff {
            nsteps = steps(s_step);
            h = span / nsteps as f64;
            nonstiff = ok(h, KAPPA_H);
            if !nonstiff && etd_step > 0.0 && ok(h, RK5_KAPPA_H_STIFF) {
                let steps = (s_step, nsteps, h);
                return self.plastic_rk5::<ISO, VIS>(sn, cs, n, acc, allow_unload, steps, rec);
            }
        }
        // Segments whose κ·h can exceed ROS_SUB.0·KAPPA_H_STIFF may take
        // Rosenbrock steps in place of RK4 sub-steps: their own
        // instantiation of the stepping loop, so that the loop of the others
        // stays as it was (in the common loop the branch slowed the steps
        // that never take it: docs/decisions/0113, 0114). Isotropic
        // stiffness, in `evaluate` (`etd_step` > 0), not on the pole's strip
        // (a = 0).
        let seg = (sn, cs, n, s0);
        let steps = (h, nsteps, nonstiff, s_step, exact_turn);
        if ISO && !nonstiff && etd_step > 0.0 && self.a != 0.0 && kr * h > ROS_SUB.0 * KAPPA_H_STIFF
        {
            self.stepping::<ISO, VIS, true>(seg, steps, acc, allow_unload, rec)
        } else {
            self.stepping::<ISO, VIS, false>(seg, steps, acc, allow_unload, rec)
        }
    }

    /// The stepping loop of [`Strip::plastic`] from yield at (`sn`, `cs`)
    /// with direction `n` (s0 = its angle) in steps of at most h (`nsteps`
    /// equal ones on a non-stiff segment); `ROS`: a step whose bounds allow
    /// it leaves the loop for `Strip::advance_ros`, which may take a
    /// Rosenbrock step in place of its RK4 sub-steps.
    #[inline(always)]
    fn stepping<const ISO: bool, const VIS: bool, const ROS: bool>(
        &self,
        (sn, cs, n, s0): (f64, f64, (f64, f64), f64),
        (h, nsteps, nonstiff, s_step, exact_turn): (f64, usize, bool, f64, bool),
        acc: &mut StripSums,
        allow_unload: bool,
        rec: &mut impl FnMut(Event),
    ) -> PlasticEnd {
        let a_h = TURN_PER_STEP * s_step;
        let stiff = Stiff::at(s_step);
        let (s2, c2) = sin_cos_small(0.5 * h);
        // sin/cos of the whole step (double angle).
        let sc_h = (2.0 * s2 * c2, (c2 - s2) * (c2 + s2));
        let mut p = PState {
            sn,
            cs,
            nx: n.0,
            ny: n.1,
            acc: StripSums::default(),
        };
        let mut s_cur = s0;
        let mut i = 0;
        // First step of the graded start (stiff segments only).
        let h_first = if nonstiff {
            f64::INFINITY
        } else {
            GRADED_KAPPA_H / ((2.0 / 3.0) * self.a.hypot(self.vy(self.c * sn))).max(RATE_FLOOR)
        };
        // tan of the turn limit (`turn_step`; a_h ≤ 4·0.3 < π/2, the largest
        // s-step).
        let turn_t = if nonstiff || !exact_turn {
            f64::NAN
        } else {
            a_h.tan()
        };
        // The graded cap of step i: h_first·2^(min(i − 1, 30)) (exact).
        let mut h_grade = h_first;
        // With `ROS`, steps that may take a Rosenbrock step in place of RK4
        // sub-steps leave this loop and are taken by `Strip::advance_ros`,
        // outside it (in the loop, that branch slowed the others).
        'segment: loop {
            let ros_step = loop {
                // Non-stiff segments: nsteps equal steps. Otherwise steps of at
                // most h, shortened where the slip direction turns by more than
                // a_h (near the strip's crossing of the spin pole's line vy = 0),
                // so that unloading is checked at that resolution too.
                let (h, c2, s2, last, step_rates, a_h_step) = if nonstiff {
                    i += 1;
                    (h, c2, s2, i == nsteps, None, a_h)
                } else {
                    let rem = FRAC_PI_2 - s_cur;
                    i += 1;
                    let mut hv = if rem <= 1.01 * h || i > MAX_STEPS {
                        rem
                    } else {
                        h
                    };
                    // sin/cos of s_cur + hv (the outlet for the last step).
                    let (s1, c1) = if hv == rem {
                        (1.0, 0.0)
                    } else {
                        let (sh, ch) = if hv == h { sc_h } else { sin_cos_small(hv) };
                        (p.sn * ch + p.cs * sh, p.cs * ch - p.sn * sh)
                    };
                    let (kh, ah) = self.rates::<ISO>(p.sn, p.cs, s1, c1.max(0.0), hv);
                    let h_full = hv;
                    // The turn limit of `advance`'s sub-division for this step
                    // (none for a step set by the exact turn).
                    let mut a_h_step = a_h;
                    if ah > a_h && i <= MAX_STEPS {
                        let hb = hv * (a_h / ah).max(1.0 / MAX_SUB_TURN);
                        // The step to an exact turn of a_h is at least hb (the
                        // bound over-estimates the turn); taken where RK4
                        // resolves it (κ·h ≤ TURN_EXACT_BLEND.0, κ·h ∝ h), the
                        // bound's step from κ·h ≥ TURN_EXACT_BLEND.1, and in
                        // between a step from hb to hx with the turn sub-steps'
                        // limit from a_h to ∞, both by a C¹ step in κ·h, so that
                        // the choice adds no jump in the inputs.
                        let hx = if turn_t.is_nan() {
                            hb
                        } else {
                            self.turn_step(&p, turn_t, s1, hv).clamp(hb, hv)
                        };
                        let (b0, b1) = TURN_EXACT_BLEND;
                        let x = kh * (hx / hv);
                        // Where the bound's step enters, not shorter than the
                        // bound over its own span (`turn_bound_step`; with the
                        // exact turn, in `evaluate`), which is at most hx.
                        let hb = if x > b0 && !turn_t.is_nan() {
                            hb.max(self.turn_bound_step(&p, a_h, hb).min(hx))
                        } else {
                            hb
                        };
                        if hx > hb && x < b1 {
                            let w = 1.0 - smooth_step((x - b0) / (b1 - b0));
                            hv = hb + w * (hx - hb);
                            a_h_step = a_h / (1.0 - w);
                        } else {
                            hv = hb;
                        }
                    }
                    // Graded first steps: the lag of n behind the slip direction
                    // at yield relaxes within ~1/κ, which RK4 at κ·h ≈ 2 resolves
                    // poorly; start at κ·h = GRADED_KAPPA_H and double.
                    if i < GRADED_STEPS {
                        hv = hv.min(h_grade);
                        if i <= 30 {
                            h_grade *= 2.0;
                        }
                    }
                    // The bounds just computed hold for the step unless it was
                    // shortened (`advance` then computes them for the new step).
                    let step_rates = (hv == h_full).then_some((kh, ah));
                    let (s2v, c2v) = if hv == h {
                        (s2, c2)
                    } else {
                        sin_cos_small(0.5 * hv)
                    };
                    if ROS
                        && hv == h_full
                        && kh > ROS_SUB.0 * KAPPA_H_STIFF
                        && ah < ROS_SUB_TURN.1 * a_h_step
                        && kh < QS_BLEND * MAX_SUB as f64 * stiff.qs * KAPPA_H
                    {
                        break Some((hv, c2v, s2v, hv >= rem, kh, ah, a_h_step));
                    }
                    (hv, c2v, s2v, hv >= rem, step_rates, a_h_step)
                };
                let mut q = if nonstiff {
                    self.rk4::<ISO>(&p, h, c2, s2)
                } else {
                    s_cur += h;
                    self.advance::<ISO>(&p, h, c2, s2, a_h_step, stiff, step_rates)
                };
                let step = (h, last, allow_unload, a_h);
                if let Some(end) = self.step_end::<ISO, VIS>(&p, &mut q, step, acc, rec) {
                    return end;
                }
                p = q;
                if last {
                    break None;
                }
            };
            let Some((h, c2, s2, last, kh, ah, a_h_step)) = ros_step else {
                break 'segment;
            };
            s_cur += h;
            let ros_eps = ROS_EST * (s_step * s_step) * (s_step * s_step);
            let mut q = self.advance_ros(&p, (h, c2, s2), (a_h_step, stiff), (kh, ah), ros_eps);
            let step = (h, last, allow_unload, a_h);
            if let Some(end) = self.step_end::<ISO, VIS>(&p, &mut q, step, acc, rec) {
                return end;
            }
            p = q;
            if last {
                break 'segment;
            }
        }
        *acc += p.acc;
        PlasticEnd::Outlet
    }

    /// `Strip::advance` of an isotropic step with its bounds (κ·h, |α'|·h)
    /// where a Rosenbrock step may take the place of its RK4 sub-steps
    /// (`Strip::sub_steps_or_ros`); the quasi-steady blend as there (the
    /// same lines: shared through a helper taking the sub-steps as a
    /// closure, the bench set ran 1.6–3.2 % more instructions, the state at
    /// rest 1.1 %, with bit-identical results).
    #[inline(never)]
    fn advance_ros(
        &self,
        p: &PState,
        (h, c2, s2): (f64, f64, f64),
        (a_h, stiff): (f64, Stiff),
        (kh, ah): (f64, f64),
        eps: f64,
    ) -> PState {
        crate::counts::count!(stiff_steps);
        let mk = kh / KAPPA_H;
        let (mr_k, mr_a) = (stiff.sub_steps(kh), (ah / a_h).min(MAX_SUB_TURN));
        let rk = self.sub_steps_or_ros(p, (h, c2, s2), (mr_k, mr_a), eps);
        let max_sub = MAX_SUB as f64 * stiff.qs;
        if mk <= max_sub {
            return rk;
        }
        let qs = self.quasi_steady(p, h, c2, s2);
        let t = (mk / max_sub - 1.0) / (QS_BLEND - 1.0);
        blend(&rk, &qs, smooth_step(t))
    }

    /// The RK4 sub-steps of an isotropic step (`Strip::sub_steps`), or one
    /// Rosenbrock step on the lag in their place (`Strip::rodas3_lag`),
    /// blended in where the sub-step count for κ rises over ROS_SUB, the
    /// turn's falls below ROS_SUB_TURN and the step's error estimate below
    /// twice `eps` (each a C¹ step).
    #[inline(always)]
    fn sub_steps_or_ros(
        &self,
        p: &PState,
        (h, c2, s2): (f64, f64, f64),
        (mr_k, mr_a): (f64, f64),
        eps: f64,
    ) -> PState {
        let mr = mr_k.max(mr_a);
        let w = smooth_step((mr_k - ROS_SUB.0) / (ROS_SUB.1 - ROS_SUB.0))
            * (1.0 - smooth_step((mr_a - ROS_SUB_TURN.0) / (ROS_SUB_TURN.1 - ROS_SUB_TURN.0)));
        if w <= 0.0 {
            return self.sub_steps::<true>(p, (h, c2, s2), mr);
        }
        let (e, est) = self.rodas3_lag(p, h, c2, s2);
        // NaN (an estimate that cannot be trusted): the sub-steps.
        let w = if est <= 2.0 * eps {
            w * (1.0 - smooth_step(est / eps - 1.0))
        } else {
            0.0
        };
        if w >= 1.0 {
            return e;
        }
        let rk = self.sub_steps::<true>(p, (h, c2, s2), mr);
        if w <= 0.0 {
            return rk;
        }
        blend(&rk, &e, w)
    }

    /// A longer step than `hb`, the bound's step of `plastic`, towards the
    /// crossing of vy = 0 (0 where there is none). Over the whole s-step
    /// the bound is the rate at the crossing, and its step lets the steps
    /// creep towards it in equal short pieces although the rate over each
    /// of them is far smaller (docs/decisions/0108). This step is the
    /// longest over which the same bound (the largest rate of the slip
    /// direction over the step, with cos s ≤ 1, times the step) is `a_h`,
    /// but no longer than TURN_BOUND_DISTANCE times the distance from the
    /// crossing in s, counted with the turn's width w = |a·gy/q2|/(c·cos s_x)
    /// (s_x the crossing's s), since the rate's higher derivatives grow
    /// like powers of 1/that distance. With A = |a·q2·c|/gy and vm the
    /// smallest |vy|/gy over the step, G(h) = h·A − a_h·(a² + vm²) is
    /// increasing and, near the crossing, concave, so Newton's iterates
    /// from h = 0 approach its root from below (TURN_BOUND_NEWTON of them:
    /// measured 0–6 % short of it on the large-|J| cases of the crate
    /// README, |J3| = 1e4…1e6); a fixed number of them keeps the step
    /// continuous in the inputs. Receding from the crossing the bound's step
    /// is that of the step's start already (0 is returned), and where the
    /// cap is not above `hb` neither is the step (0 too).
    #[inline(never)]
    fn turn_bound_step(&self, p: &PState, a_h: f64, hb: f64) -> f64 {
        let (a, q2) = (self.a, self.q2 / self.gy);
        let vy0 = self.vy(self.c * p.sn) / self.gy;
        if vy0 * q2 >= 0.0 {
            return 0.0;
        }
        let x0 = -self.b1 / self.q2;
        let xc = (x0 / self.c).clamp(-1.0, 1.0);
        let sc = xc.asin();
        // cos(asin xc) = √(1 − xc²).
        let w = (a / (q2 * self.c * (1.0 - xc * xc).sqrt().max(CS_MIN))).abs();
        let cap = TURN_BOUND_DISTANCE * (sc - p.sn.asin()).hypot(w);
        if cap <= hb {
            return 0.0;
        }
        let big_a = (a * q2 * self.c).abs();
        let a2 = a * a;
        let mut h = 0.0;
        for _ in 0..TURN_BOUND_NEWTON {
            let (sh, ch) = sin_cos_small(h);
            let sn1 = p.sn * ch + p.cs * sh;
            let cs1 = p.cs * ch - p.sn * sh;
            let vy1 = self.vy(self.c * sn1) / self.gy;
            // The step holds the crossing where vy changes sign (vm = 0).
            let (vm, dvm2) = if (vy0 < 0.0) != (vy1 < 0.0) {
                (0.0, 0.0)
            } else {
                (vy1, 2.0 * vy1 * q2 * self.c * cs1)
            };
            let g = h * big_a - a_h * (a2 + vm * vm);
            let dg = big_a - a_h * dvm2;
            h -= g / dg;
        }
        // (A NaN iterate, which the bounds above exclude, keeps `hb`.)
        if h > 0.0 { h.min(cap) } else { 0.0 }
    }

    /// The step from `p` over which the slip direction v = (a, vy/gy)
    /// turns by exactly atan(`turn_t`), or `h_full` (whose end has sine
    /// `s1`) if it turns by less. tan α = u = vy/(gy·a) is linear in X, so
    /// the end's u1 follows from tan(α1 − α0) = ±turn_t in closed form, and
    /// the step in s from X1 = c·sn1 by one asin.
    #[inline(never)]
    fn turn_step(&self, p: &PState, turn_t: f64, s1: f64, h_full: f64) -> f64 {
        let ga = self.gy * self.a;
        let du = self.q2 / ga;
        let u0 = self.vy(self.c * p.sn) / ga;
        // u1 = (u0 ± t)/(1 ∓ t·u0) in the direction u moves (X grows);
        // a denominator ≤ 0: the turn to α = ±π/2 is less than atan(t).
        let (num, den) = if du > 0.0 {
            (u0 + turn_t, 1.0 - turn_t * u0)
        } else {
            (u0 - turn_t, 1.0 + turn_t * u0)
        };
        if den <= 0.0 || den.is_nan() {
            return h_full;
        }
        let sn1 = p.sn + (num / den - u0) / (du * self.c);
        if sn1 >= s1 || sn1.is_nan() {
            return h_full;
        }
        // sin(s1 − s0) = sn1·cs0 − cs1·sn0.
        let cs1 = (1.0 - sn1 * sn1).max(0.0).sqrt();
        (sn1 * p.cs - cs1 * p.sn).asin()
    }

    /// End of one plastic step from `p` to `q` of length h, shared by the
    /// RK4 and exponential stepping (`(h, last, allow_unload, a_h)`): the
    /// last step ends exactly at the outlet; where unloading starts inside
    /// the step (g < 0 at its end) it is located, the segment's sums up to it
    /// added to `acc` and the end returned; otherwise `q` is recorded and the
    /// segment goes on (None).
    #[inline(always)]
    fn step_end<const ISO: bool, const VIS: bool>(
        &self,
        p: &PState,
        q: &mut PState,
        (h, last, allow_unload, a_h): (f64, bool, bool, f64),
        acc: &mut StripSums,
        rec: &mut impl FnMut(Event),
    ) -> Option<PlasticEnd> {
        if last {
            q.sn = 1.0;
            q.cs = 0.0;
        }
        if allow_unload && q.cs > OUTLET_CS {
            let g1 = self.g_sign::<VIS>(q.sn, q.cs, q.nx, q.ny);
            // With a viscous law the stress can leave the cap and come back
            // within one step (g < 0 on a band between its ends): the dip of
            // g's cubic Hermite interpolant over the step finds such a band.
            let inside = if VIS && g1 >= 0.0 {
                let (p0, q0) = (*p, *q);
                self.cap_exit_inside::<ISO>(&p0, &q0, h, a_h)
            } else {
                None
            };
            if g1 < 0.0 || inside.is_some() {
                // Copies for the out-of-line call, so that p and q need not
                // live in memory on the hot path.
                let (p0, q0, h, g1) = match inside {
                    Some((r, t, gr)) => (*p, r, t, gr),
                    None => (*p, *q, h, g1),
                };
                let best = self.locate_unload::<ISO, VIS>(&p0, &q0, h, g1, a_h);
                *acc += best.acc;
                let l = 1.5 * self.c * best.cs;
                rec(Event::Plastic {
                    x: self.c * best.sn,
                    n: (best.nx, best.ny),
                });
                return Some(PlasticEnd::Unload {
                    x: self.c * best.sn,
                    z: (l * best.nx, l * best.ny),
                });
            }
        }
        rec(Event::Plastic {
            x: self.c * q.sn,
            n: (q.nx, q.ny),
        });
        None
    }

    /// The exponential steps (count, length) of an isotropic plastic segment
    /// from s = atan2(sn, cs) over `span`, if it qualifies (see
    /// [`Strip::plastic`]).
    #[inline(never)]
    fn etd_steps(
        &self,
        sn: f64,
        cs: f64,
        span: f64,
        s_step: f64,
        etd_step: f64,
    ) -> Option<(usize, f64)> {
        let kv = (2.0 / 3.0) * (self.q2 * self.c).abs();
        let he_max = etd_step.min(ETD_KAPPA_VARIATION / kv);
        if he_max < (ETD_MIN_STEP * s_step).min(span) {
            return None;
        }
        let ne = ceil_count(span / he_max).max(1);
        let he = span / ne as f64;
        (self.rates::<true>(sn, cs, 1.0, 0.0, he).1 <= TURN_PER_STEP * s_step).then_some((ne, he))
    }

    /// [`Strip::plastic`] on an isotropic segment by `nsteps` exponential
    /// steps of length h ([`Strip::etd`]; RK4 steps of at most the s-step
    /// where it does not apply), with the same unloading check and
    /// location.
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    fn plastic_etd<const VIS: bool>(
        &self,
        sn: f64,
        cs: f64,
        n: (f64, f64),
        acc: &mut StripSums,
        allow_unload: bool,
        steps: (f64, usize, f64),
        rec: &mut impl FnMut(Event),
    ) -> PlasticEnd {
        let (s_step, _, h) = steps;
        let (a_h, stiff) = (TURN_PER_STEP * s_step, Stiff::at(s_step));
        let (s2, c2) = sin_cos_small(0.5 * h);
        let step = |p: &PState| match self.etd(p, h, c2, s2) {
            Some(q) => q,
            None => {
                // RK4 steps of at most the s-step.
                let m = (h / s_step).ceil().max(1.0);
                let hs = h / m;
                let (s2s, c2s) = sin_cos_small(0.5 * hs);
                let mut q = *p;
                for _ in 0..m as usize {
                    q = self.advance::<true>(&q, hs, c2s, s2s, a_h, stiff, None);
                }
                q
            }
        };
        self.equal_steps::<true, VIS>((sn, cs, n), acc, allow_unload, steps, rec, step)
    }

    /// [`Strip::plastic`] on a segment by `nsteps` steps of length h of the
    /// fifth-order rule ([`Strip::rk5`]; the caller checks κ·h), with the
    /// same unloading check and location.
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    fn plastic_rk5<const ISO: bool, const VIS: bool>(
        &self,
        sn: f64,
        cs: f64,
        n: (f64, f64),
        acc: &mut StripSums,
        allow_unload: bool,
        steps: (f64, usize, f64),
        rec: &mut impl FnMut(Event),
    ) -> PlasticEnd {
        let h = steps.2;
        let (s4, c4) = sin_cos_small(0.25 * h);
        let step = |p: &PState| self.rk5::<ISO>(p, h, c4, s4);
        self.equal_steps::<ISO, VIS>((sn, cs, n), acc, allow_unload, steps, rec, step)
    }

    /// The plastic segment from (sn, cs) with direction n in `nsteps` equal
    /// steps of length h taken by `step` ([`Strip::plastic_etd`],
    /// [`Strip::plastic_rk5`]), each followed by the unloading check and
    /// location of [`Strip::step_end`].
    #[inline(always)]
    fn equal_steps<const ISO: bool, const VIS: bool>(
        &self,
        (sn, cs, n): (f64, f64, (f64, f64)),
        acc: &mut StripSums,
        allow_unload: bool,
        (s_step, nsteps, h): (f64, usize, f64),
        rec: &mut impl FnMut(Event),
        step: impl Fn(&PState) -> PState,
    ) -> PlasticEnd {
        let a_h = TURN_PER_STEP * s_step;
        let mut p = PState {
            sn,
            cs,
            nx: n.0,
            ny: n.1,
            acc: StripSums::default(),
        };
        for i in 1..=nsteps {
            let mut q = step(&p);
            let end = (h, i == nsteps, allow_unload, a_h);
            if let Some(end) = self.step_end::<ISO, VIS>(&p, &mut q, end, acc, rec) {
                return end;
            }
            p = q;
        }
        *acc += p.acc;
        PlasticEnd::Outlet
    }
}

/// ⌈t⌉ as a count for t ≥ 0 (`t.ceil() as usize`, which calls the
/// library's ceil on the baseline x86-64 target; NaN gives 0 as there).
#[inline(always)]
fn ceil_count(t: f64) -> usize {
    let n = t as usize;
    if (n as f64) < t { n + 1 } else { n }
}

#[cfg(test)]
mod tests;
