//! Gauss–Legendre quadrature of the strip sums across the contact (Y = sin φ):
//! composite (fixed resolution) and adaptive with blended refinement.

use std::f64::consts::{FRAC_PI_2, PI};

use super::kink::MARGIN_CAP;
use super::{ETD_MIN_STEP, Resolution, Scaled, Strip, StripSums, smooth_step};
use crate::quad;

/// Composite Gauss–Legendre over Y = sin φ of a strip functional; returns
/// (J4, J5, J6).
pub(crate) fn contact_integral(
    sc: &Scaled,
    res: &Resolution,
    mut strip_fn: impl FnMut(&Strip) -> StripSums,
) -> (f64, f64, f64) {
    let rule = quad::rule(res.y_points);
    let np = res.y_panels.max(1);
    let width = PI / np as f64;
    let (mut sx, mut sy, mut sxy, mut syx) = (0.0, 0.0, 0.0, 0.0);
    for p in 0..np {
        let mid = -FRAC_PI_2 + (p as f64 + 0.5) * width;
        for &(t, w) in rule {
            let phi = mid + 0.5 * width * t;
            let (y, cphi) = phi.sin_cos();
            let wt = 0.5 * width * w * cphi;
            let st = strip_fn(&sc.strip(y));
            sx += wt * st.ix;
            sy += wt * st.iy;
            sxy += wt * st.ixy;
            syx += wt * y * st.ix;
        }
    }
    let j4 = sx / PI;
    let j5 = sy / PI;
    // J6 = T/(μN√(ab)) = (1/(π√k))∫∫(Zy·(X+ΔX) − k·Zx·Y) dX dY: the torque
    // about the spin pole, so that J7 = J1·J4 + J2·J5 + J3·J6 is the
    // dissipation also for ΔX ≠ 0 (for ΔX = 0 it is the torque about the
    // contact centre, App. IV eq. 16).
    let j6 = (sxy + sc.dx * sy - sc.k * syx) / (PI * sc.k.sqrt());
    (j4, j5, j6)
}

/// Sums (∫Zx, ∫Zy, ∫Zy·X, ∫Zx·Y over strips) of one φ-panel by `rule`;
/// `strip(Y)` gives a strip's (∫Zx, ∫Zy, ∫Zy·X).
pub(crate) fn panel_sums(
    rule: &[(f64, f64)],
    lo: f64,
    hi: f64,
    strip: &mut impl FnMut(f64) -> [f64; 3],
) -> [f64; 4] {
    let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
    let mut acc = [0.0; 4];
    for &(t, w) in rule {
        let (y, cphi) = (mid + half * t).sin_cos();
        let wt = half * w * cphi;
        let st = strip(y);
        acc[0] += wt * st[0];
        acc[1] += wt * st[1];
        acc[2] += wt * st[2];
        acc[3] += wt * y * st[0];
    }
    acc
}

/// (J4, J5, J6) from the contact sums of a contact of aspect ratio `k` with
/// spin-pole offset `dx` (see [`contact_integral`]).
pub(crate) fn to_j(k: f64, dx: f64, s: &[f64; 4]) -> (f64, f64, f64) {
    (
        s[0] / PI,
        s[1] / PI,
        (s[2] + dx * s[1] - k * s[3]) / (PI * k.sqrt()),
    )
}

/// Adaptive composite Gauss–Legendre in φ from the panels between the sorted
/// breakpoints `breaks` (in φ, from −π/2 to π/2): a panel is accepted when
/// its n-point value and the sum over its two halves differ by less than
/// tol·width/π in J4, J5 and J6 (the halves' value is kept); otherwise both
/// halves are refined (blended in between, see below), down to `max_depth`
/// levels.
pub(crate) fn contact_integral_adaptive_at(
    sc: &Scaled,
    breaks: &[f64],
    n: usize,
    tol: f64,
    max_depth: u32,
    mut strip_fn: impl FnMut(&Strip) -> StripSums,
) -> (f64, f64, f64) {
    adaptive_in_phi(breaks, quad::rule(n), tol, max_depth, (sc.k, sc.dx), |y| {
        let st = strip_fn(&sc.strip(y));
        [st.ix, st.iy, st.ixy]
    })
}

/// [`contact_integral_adaptive_at`] for any strip functional `strip(Y)` →
/// (∫Zx, ∫Zy, ∫Zy·X) and panel rule `rule`, on a contact of aspect ratio k
/// with spin-pole offset ΔX (`k_dx`); also the viscoelastic model's.
pub(crate) fn adaptive_in_phi(
    breaks: &[f64],
    rule: &[(f64, f64)],
    tol: f64,
    max_depth: u32,
    (k, dx): (f64, f64),
    mut strip: impl FnMut(f64) -> [f64; 3],
) -> (f64, f64, f64) {
    let mut total = [0.0; 4];
    // (lo, hi, value, depth, weight)
    let mut stack: Vec<(f64, f64, [f64; 4], u32, f64)> = Vec::with_capacity(32);
    for w in breaks.windows(2) {
        let (lo, hi) = (w[0], w[1]);
        if hi > lo {
            let v = panel_sums(rule, lo, hi, &mut strip);
            stack.push((lo, hi, v, 0, 1.0));
        }
    }
    while let Some((lo, hi, coarse, depth, weight)) = stack.pop() {
        let m = 0.5 * (lo + hi);
        let l = panel_sums(rule, lo, m, &mut strip);
        let r = panel_sums(rule, m, hi, &mut strip);
        let fine = [l[0] + r[0], l[1] + r[1], l[2] + r[2], l[3] + r[3]];
        let d = [
            fine[0] - coarse[0],
            fine[1] - coarse[1],
            fine[2] - coarse[2],
            fine[3] - coarse[3],
        ];
        let (e4, e5, e6) = to_j(k, dx, &d);
        let err = e4.abs().max(e5.abs()).max(e6.abs());
        let allowed = tol * (hi - lo) / PI;
        // Share of the refined value: 0 up to BLEND.0·allowed, 1 from
        // BLEND.1·allowed on, a smooth step in between, so that the result is a
        // continuous function of the inputs (no jump where a panel's
        // decision flips).
        let refine = refine_share(err, allowed, depth, max_depth);
        if refine < 1.0 {
            let w = weight * (1.0 - refine);
            for i in 0..4 {
                total[i] += w * fine[i];
            }
        }
        if refine > 0.0 {
            stack.push((lo, m, l, depth + 1, weight * refine));
            stack.push((m, hi, r, depth + 1, weight * refine));
        }
    }
    to_j(k, dx, &total)
}

/// Blend between a panel's value and its refinement: from BLEND.0 to BLEND.1
/// times the allowed change (see `contact_integral_adaptive_at`).
const BLEND: (f64, f64) = (1.0, 2.0);

/// Share of a panel's refined value in the result (the rest is its own
/// value): 0 up to BLEND.0 times the allowed change `allowed`, 1 from
/// BLEND.1 times it, a C¹ smooth step in between (so that a panel's
/// decision adds no jump in the inputs); 0 at `max_depth` or for a NaN
/// change. Shared by the elastic/plastic and viscoelastic panel rules.
///
/// A panel narrower than an ulp of φ (a kink's split pulled to within
/// rounding of a panel's end leaves one) has err = allowed = 0: it is
/// accepted (the quotient would be NaN).
#[inline]
pub(crate) fn refine_share(err: f64, allowed: f64, depth: u32, max_depth: u32) -> f64 {
    if depth >= max_depth || err.is_nan() || err <= BLEND.0 * allowed {
        0.0
    } else {
        smooth_step((err / allowed - BLEND.0) / (BLEND.1 - BLEND.0))
    }
}

/// First graded panel edge from the spin pole's strip, in φ: POLE_GRADING/|J3|
/// (at tol ≤ 1e-4 the second at POLE_SECOND_EDGE times that distance from
/// it, the further ones at POLE_GRADING_GROWTH times the previous distance).
/// With the former rule (4-point Gauss panels checked against their halves,
/// distances doubling) 4, 8 and 16 gave a worst error/tol of
/// 0.48/0.48/0.50 on 224 cases and 0.35/0.33/0.47 on 600 high-spin ones at
/// +17/+6/+3 % and +10/+8/+9 % instructions (8 was chosen). With the
/// Lobatto–Kronrod panels of [`lobatto_kronrod_in_phi`], against 128-panel
/// references on 1842 cases (`cargo xtask ep-sets` with six seeds), the
/// total strips at tol 1e-2/1e-3/1e-4 are 77.0 k/103.8 k/181.0 k with 3,
/// 81.8 k/101.6 k/183.5 k with 2, 73.9 k/110.7 k/187.8 k with 4 and
/// 70.0 k/134.4 k/212.8 k with 8, the worst error/tol ≤ 0.22 at 1e-2 and
/// 1e-3 for all. Instructions on the bench set at 1e-3: 3 halves the worst
/// case (8: cases a, b, c 1.25 M/949 k/953 k; 3: 503 k/589 k/490 k; 2: a
/// +60 %); on 307 random cases in total 8 is 21 % and 4 % cheaper than 3
/// at 1e-2 and 1e-4 (its strips lie farther from the pole, where they are
/// cheaper) and 3 % dearer at 1e-3 (docs/decisions/0074).
const POLE_GRADING: f64 = 3.0;

/// Growth of the initial panel edges' distance from the spin pole's strip
/// beyond the first (POLE_GRADING/|J3|, the panel that holds the change of
/// the flow pattern; at tol ≤ 1e-4 beyond the second, POLE_SECOND_EDGE).
/// The outer panels only need to be wide enough not to waste strips: the
/// strip sums are smooth there and the adaptive rule halves them where not.
/// Against 128-panel references on 307 high-spin cases (k ∈ {0.5, 1, 2, 5},
/// |J1|, |J2| ≤ 5, J3 ∈ [5, 26]), 157 wide ones
/// (k 0.05–20, |J3| to 316) and 67 (k ∈ {0.2 … 5}, J3 ∈ [0.5, 26]): the
/// worst error/tol at tol = 1e-2, 1e-3, 1e-4 is the same for 2 (before),
/// 4 and 8 on every set, while 4 takes 11–25 % fewer strips than 2 at
/// 1e-2/1e-3 and 7–8 % at 1e-4 (8: a further 0–11 % on the wide set only);
/// 4 keeps some grading for very large |J3| (docs/decisions/0065). With the
/// Lobatto–Kronrod panels and POLE_GRADING = 3, growth 6 takes 10 % fewer
/// strips at 1e-2 but 8 % more at 1e-4 (1842 cases), 3 more at 1e-2 and
/// 1e-3 (first edge 4/|J3|); in instructions over 307 cases 6 and 8
/// differ from 4 by −0.5 % and +2 % (docs/decisions/0074); at 1e-4, 3 for
/// every edge costs 1 % more than 4 and 3 % more than POLE_SECOND_EDGE with
/// 4 beyond it (docs/decisions/0086).
const POLE_GRADING_GROWTH: f64 = 4.0;

/// Distance of the second initial panel edge from the spin pole's strip in
/// units of the first (POLE_GRADING/|J3|) at tol ≤ 1e-4 (`second_edge`):
/// where |J3|/√k is large the panel next to the pole's own holds flow-topology
/// changes (kinks of the strip sums) that its refinements chase. 3 instead
/// of POLE_GRADING_GROWTH (4) at 1e-4: instructions on 307 random cases
/// −2.1 %, on a random batch (k 0.2–5, |J1|, |J2| ≤ 5, |J3| ≤ 26) −3.2 %,
/// worst error/tol of the high-spin and other cases on four seeds of
/// `cargo xtask ep-sets errs` 0.308 / 0.196 → 0.101 / 0.101; 2 and 2.5:
/// +0.9 % and +0.8 % on the 307 cases. At 1e-3 and 1e-2 it costs the bench
/// set's case s +31 % and +66 % (the 307 cases −2.6 % and +1.8 %), so the
/// larger tolerances keep 4 (docs/decisions/0086).
const POLE_SECOND_EDGE: f64 = 3.0;

/// Largest number of initial panel edges: at most MAX_BREAKS/2 − 2 graded
/// edges per side (they reach the contact's edge for any |J3| below
/// [`crate::J_RIGID`]; otherwise the outermost panel would be wider and
/// refined by the adaptive rule).
pub(crate) const MAX_BREAKS: usize = 64;

/// Initial panel edges in φ (Y = sin φ): graded geometrically towards the
/// spin pole's strip Y_p = J1/(√k·J3), where the slip's X component
/// a = a0 − J3·Y vanishes, at φ = [`pole_anchor`]`(Y_p)` (asin Y_p for
/// |Y_p| ≤ [`ANCHOR_Y`]; towards the nearer edge of the contact as Y_p
/// nears and leaves it, so that the edges move continuously as the pole
/// leaves the contact: second differences along J1 across |Y_p| = 1 at
/// tol = 1e-3 are ≤ 0.007·tol, against 0.027·tol when switching to fixed
/// edges there).
///
/// Near that strip the flow pattern changes within |ΔY| ~ 1/|J3|. Starting
/// from the two halves, a coarse panel whose 4- and 8-point values agree by
/// chance was accepted although neither resolved that region: k = 0.5,
/// J = (1.01, −2.51, 7.80) was off by 1.76·tol at tol = 1e-4 (J5), k = 1,
/// J = (1.21, 0.016, 16.5) by 0.94·tol at 1e-3. The edges move continuously
/// with the inputs; one appears or disappears only at the outermost panel,
/// where the integrand is smooth and the change far below tol.
fn initial_breaks(sc: &Scaled, tol: f64, out: &mut [f64; MAX_BREAKS]) -> usize {
    let yp = sc.a0 / sc.j3;
    // J1 = J3 = 0 (the closed form unless gy ≠ 1): the two halves.
    if yp.is_nan() {
        out[..3].copy_from_slice(&[-FRAC_PI_2, 0.0, FRAC_PI_2]);
        return 3;
    }
    // With the pole at (or beyond) an edge and w0 wider than the contact
    // (small |J3|) this is one panel from edge to edge, whose first
    // refinement is the two halves (an empty panel at the edge is skipped).
    let pp = pole_anchor(yp);
    let grading = (second_edge(tol), POLE_GRADING_GROWTH);
    graded_breaks(pp, POLE_GRADING / sc.j3.abs(), grading, out)
}

/// |Y_p| up to which the initial panels' anchor is the spin pole's strip
/// itself, φ = asin Y_p ([`pole_anchor`]). Beyond it asin moves without
/// bound (dφ/dY_p = 1/√(1 − Y_p²)), and every panel with it: at small k
/// and small spin (k = 0.0768, J = (−0.0913, −0.0519, −0.331), Y_p =
/// 0.9966) the panels swept across the strip sums' kinks at 0.014 rad per
/// 1e-4 of J, their decisions flipping from one input to the next, and
/// the second differences along a line 1e-4 apart reached 0.087, 0.103
/// and 0.434·tol at tol 1e-2, 1e-3 and 1e-4; with the anchor continued
/// linearly beyond 0.9 0.0014, 0.0055 and 0.247·tol (0.7: 0.155·tol at
/// 1e-3 on the worst line of another seed) (docs/decisions/0123).
const ANCHOR_Y: f64 = 0.9;

/// The initial panels' anchor in φ for the spin pole's strip at Y_p:
/// asin Y_p for |Y_p| ≤ [`ANCHOR_Y`], beyond it continued with asin's slope
/// there (C¹) up to the contact's edge (±π/2, reached at |Y_p| ≈ 1.097);
/// NaN for NaN.
fn pole_anchor(yp: f64) -> f64 {
    if yp.is_nan() {
        return yp;
    }
    let y = yp.abs();
    let p = if y <= ANCHOR_Y {
        y.asin()
    } else {
        let slope = 1.0 / (1.0 - ANCHOR_Y * ANCHOR_Y).sqrt();
        (ANCHOR_Y.asin() + slope * (y - ANCHOR_Y)).min(FRAC_PI_2)
    };
    p.copysign(yp)
}

/// The second initial edge's distance from the pole's strip in units of the
/// first: POLE_SECOND_EDGE at tol ≤ 1e-4, POLE_GRADING_GROWTH at tol ≥ 1e-3,
/// linear in log10(tol) in between (docs/decisions/0086).
fn second_edge(tol: f64) -> f64 {
    POLE_GRADING_GROWTH + fine_tol(tol) * (POLE_SECOND_EDGE - POLE_GRADING_GROWTH)
}

/// Where the settings chosen for tol 1e-4 (docs/decisions/0086) take over
/// from those of tol ≥ 1e-3: 0 at tol ≥ 1e-3, 1 at tol ≤ 1e-4, linear in
/// log10(tol) in between.
fn fine_tol(tol: f64) -> f64 {
    if tol >= 1e-3 {
        0.0
    } else if tol <= 1e-4 {
        1.0
    } else {
        -3.0 - tol.log10()
    }
}

/// Panel edges in φ from −π/2 to π/2 graded geometrically about φ = `pp`
/// (the spin pole's strip, clamped to the contact): with `(second, growth)`,
/// edges at pp ± w0, pp ± w0·second, pp ± w0·second·growth,
/// pp ± w0·second·growth², … while a panel of at least half the last width is
/// left to the contact's edge, at most MAX_BREAKS/2 − 2 per side. Returns the
/// number of edges written to `out`.
pub(crate) fn graded_breaks(
    pp: f64,
    w0: f64,
    (second, growth): (f64, f64),
    out: &mut [f64; MAX_BREAKS],
) -> usize {
    let side = MAX_BREAKS / 2 - 2;
    // Below the pole (filled from the pole outwards, then reversed).
    let mut n = 1;
    let mut w = w0;
    while pp - w > -FRAC_PI_2 + 0.5 * w && n <= side {
        out[n] = pp - w;
        w *= if n == 1 { second } else { growth };
        n += 1;
    }
    out[1..n].reverse();
    out[0] = -FRAC_PI_2;
    out[n] = pp;
    n += 1;
    let mut w = w0;
    let first = n;
    let lim = n + side;
    while pp + w < FRAC_PI_2 - 0.5 * w && n < lim {
        out[n] = pp + w;
        w *= if n == first { second } else { growth };
        n += 1;
    }
    out[n] = FRAC_PI_2;
    n + 1
}

/// The longest exponential step at `tol` with the s-step `s_step`:
/// [`ETD_STEP`]·√(tol/1e-3), at most [`ETD_STEP_MAX`]; 0 (none) where that
/// is shorter than ETD_MIN_STEP s-steps (below tol ≈ 1e-5).
pub(crate) fn etd_step(tol: f64, s_step: f64) -> f64 {
    let etd_step = (ETD_STEP * (tol / 1e-3).sqrt()).min(ETD_STEP_MAX);
    if etd_step >= ETD_MIN_STEP * s_step {
        etd_step
    } else {
        0.0
    }
}

/// Elastic/plastic (J4, J5, J6) by Lobatto–Kronrod panels in Y
/// ([`lobatto_kronrod_in_phi`]) from the panels of [`initial_breaks`], below
/// tol 4e-4 split at located kinks; the plastic steps `steps`
/// (`crate::plastic_steps`): s-step, or the longer s-step on plastic
/// segments that are non-stiff at it, exponential steps of up to
/// [`etd_step`] on stiff segments where the slip direction turns slowly
/// ([`Strip::integrate_etd`]).
///
/// Without longitudinal slip (J1 = 0, so a = −J3·Y) the strip at −Y is the
/// mirror image of the strip at Y (Zx → −Zx; the stiffness G = diag(1, gy)
/// is symmetric under it): ∫Zx is odd in Y and ∫Zy, ∫Zy·X, ∫Zx·Y are even.
/// The initial panels are then symmetric about Y = 0 (the pole's strip) and
/// the adaptive rule takes the same decisions on mirrored panels, so only
/// Y ≥ 0 is integrated: J4 = 0, J5 and J6 twice the half's, half the cost.
/// The result is the full integration's (bit for bit where compared, e.g.
/// k = 5, J = (0, 3.37, 25.8); rheology/tests/continuity.rs compares J1 = 0
/// with J1 = ±1e-15 within the strip integrator's own sensitivity to such
/// changes), so it stays continuous at J1 = 0.
pub(crate) fn solve_adaptive(
    sc: &Scaled,
    tol: f64,
    (s_step, s_step_smooth, etd_step, _): (f64, f64, f64, bool),
) -> (f64, f64, f64) {
    let mut breaks = [0.0; MAX_BREAKS];
    let nb = initial_breaks(sc, tol, &mut breaks);
    let strip = |y: f64, margin: bool| {
        let s = sc.strip(y);
        let (st, topology, m, amp) = if margin {
            s.integrate_etd_margin(s_step, s_step_smooth, etd_step)
        } else {
            let (st, topology, amp) = s.integrate_etd(s_step, s_step_smooth, etd_step);
            (st, topology, f64::NAN, amp)
        };
        ([st.ix, st.iy, st.ixy], (topology, amp), m)
    };
    let k_dx = (sc.k, sc.dx);
    // The pole's strip in φ (an initial edge; 0 for J1 = J3 = 0).
    let pp = pole_anchor(sc.a0 / sc.j3);
    let pp = if pp.is_nan() { 0.0 } else { pp };
    if sc.a0 == 0.0
        && let Some(i0) = breaks[..nb].iter().position(|&b| b == 0.0)
    {
        let breaks = &breaks[i0..nb];
        let (_, j5, j6) = lobatto_kronrod_in_phi(breaks, tol, MAX_DEPTH, k_dx, pp, strip);
        return (0.0, 2.0 * j5, 2.0 * j6);
    }
    lobatto_kronrod_in_phi(&breaks[..nb], tol, MAX_DEPTH, k_dx, pp, strip)
}

/// Regula falsi points on the kink margin (`Strip::integrate_etd_margin`)
/// per initial panel whose end strips' margins differ in sign; the last one
/// becomes the panel's split (so 2 strips per kink are spent on locating
/// it). On 2000 rows of a random batch at tol 1e-4 (k 0.2–5, |J1|, |J2| ≤ 5,
/// |J3| ≤ 26) 2, 3 and 4 points took 117.3 k, 113.8 k and 115.5 k strips
/// (no splits: 138.3 k); with 3 the split lies a median 0.0006 (90th
/// percentile 0.0037) in φ from the kink. Illinois' halving of the
/// retained end's margin took more (3 points: 117.2 k)
/// (docs/decisions/0094).
const KINK_POINTS: usize = 3;

/// Regula falsi points ([`KINK_POINTS`]) for a kink located between two
/// neighbouring nodes of an initial panel (`lobatto_kronrod_in_phi`), on
/// reshaped margins: the unloading side's (< 0), which vanishes like the
/// square root of the distance from the kink, squared and divided by the
/// bracket's margin there; the other side's capped at that margin (it
/// jumps to MARGIN_CAP where a plastic segment vanishes). k = 0.0768,
/// J = (−0.0987, −0.0493, −0.3392), kinks at φ ≈ −0.7927 and 0.7190: 3
/// points on the plain margins split at −0.7861 and 0.6872 (the cap at
/// one end held the bracket), 4 reshaped at −0.7885 and 0.7175. The
/// largest second differences of `cargo xtask ep-sets lines` (small k,
/// small spin, seeds 1 / 7 / 9, tol 1e-4): 3 plain 0.167 / 0.162 / 0.067,
/// 3 reshaped 0.072 / 0.449 / 0.169, 4 reshaped 0.062 / 0.162 / 0.063, 5
/// reshaped 0.045 / 0.162 / 0.062, 5 and 6 with only the cap 0.142 / 0.163
/// / 0.114 and 0.092 / 0.163 / 0.098 (docs/decisions/0130).
const KINK_POINTS_INSIDE: usize = 4;

/// Refinement share of an initial panel from which its kinks between nodes
/// are located: its refinement goes to its pieces by a C¹ step from 0 at
/// this share to 1 at a share of 1 (to its halves otherwise). Locating at
/// every share > 0, the bench case b (whose panels at the pole's strip are
/// refined by shares of 0.06–0.08 at tol 1e-4) cost +33 % instructions; from
/// 0.5 on +0.3 % (docs/decisions/0130).
const PIECES_FROM: f64 = 0.5;

/// Least distance of a regula falsi point (not the split) from either end
/// of its bracket, as a share of the bracket: a safeguard for margins far
/// from linear, where regula falsi keeps one end and creeps towards the
/// kink. On a wide panel at small spin (k = 0.144, J = (2.7e-5, 0.0201,
/// −0.461): the panel [0, π/2] in φ, its margins −0.13 at the pole and 3/2
/// at the edge, steep near the kink at φ = 0.466 and jumping from 0.13 to
/// 0.98 at φ ≈ 0.7 where the plastic segment vanishes) the points without
/// it were 0.12 and 0.23 and the split 0.317; the kink stayed inside a
/// panel whose Lobatto–Kronrod difference was a third of its error, and
/// the result was 1.17·tol off at tol 1e-4. With 0.25 the split is at
/// 0.484 and the result 0.10·tol off. On 28 seeds of the whole-range scan
/// (84 000 cases) the worst error/tol at 1e-4 went from 1.16 to 0.58 (0.2:
/// 0.76, 0.3: 0.66); the random batch's instructions at 1e-4 are the same
/// (−0.05 %) (docs/decisions/0120).
const KINK_STEP_MIN: f64 = 0.25;

/// Band at a panel's ends, in units of its width, within which a located
/// kink's split is pulled to the nearer end (by a C¹ smooth step in the
/// distance): where an unloading band is born at an edge (the pole's
/// strip), its kinks leave it like the square root of the inputs' change,
/// and a split that followed them at once moved the results by up to
/// 0.035·tol within 1e-4 of J3 (k = 1, J = (0.2, 0.1, 3.2); 0.009·tol
/// with 0.1, 0.007·tol with 0.2, 0.021·tol with 0.05). 0.1 costs +0.3 %
/// instructions on a random batch at tol 1e-4, 0.2 +4.5 %
/// (docs/decisions/0094).
const KINK_END_BAND: f64 = 0.1;

/// Tolerances (lo, hi) between which the initial panels' split at a located
/// kink moves in (`kink_share`): split at the kink for tol ≤ lo, none for
/// tol ≥ hi. Splitting at every tol, the instructions on the 307 cases of
/// `cargo xtask ep-sets` change by +11.6 % at tol 1e-3, +8.7 % at 7e-4,
/// +3.9 % at 5e-4, +0.1 % at 4e-4, −3.7 % at 3e-4, −7.3 % at 2e-4 and
/// −15.2 % at 1e-4 (a kink panel at the larger tolerances is settled by one
/// refinement, cheaper than the locating strips and the extra panel); in
/// between the two, at 3.5e-4, a split half-way to the kink costs +13 %
/// (docs/decisions/0094).
const KINK_SPLIT_TOL: (f64, f64) = (3e-4, 4e-4);

/// Where between a split initial panel's end nearer the pole's strip (0)
/// and the located kink (1) that panel is split: 1 at tol ≤
/// KINK_SPLIT_TOL.0, 0 (no split, and no kink margins computed) at tol ≥
/// KINK_SPLIT_TOL.1, linear in log10(tol) in between, so that the result
/// is continuous in tol too (and mirror-symmetric for J1 = 0).
fn kink_share(tol: f64) -> f64 {
    let (lo, hi) = KINK_SPLIT_TOL;
    if tol >= hi {
        0.0
    } else if tol <= lo {
        1.0
    } else {
        (hi / tol).log10() / (hi / lo).log10()
    }
}

/// Deepest refinement of an initial panel in [`solve_adaptive`].
const MAX_DEPTH: u32 = 10;

/// The 5-point Gauss–Lobatto rule (degree 7) on [−1, 1]: nodes ±1, 0,
/// ±√(3/7) ([`LOBATTO_X`]) with weights 1/10 ([`LK_ENDS`].1), 32/45 and
/// 49/90 ([`LOBATTO_W`]). Its nodes hold those of the 3-point rule
/// (Simpson: ±1, 0 with weights 1/3, 4/3, degree 3), and its 9-point
/// Kronrod extension (degree 13) adds the nodes ±0.3410 and ±0.8904
/// ([`LK_ADDED`]). The Kronrod nodes are the real roots that make the
/// 9-point rule exact to degree 13 (computed to 50 digits by Newton on the
/// moment equations; the weights are positive).
const LOBATTO_X: f64 = 0.654_653_670_707_977_2;
/// 5-point Lobatto weights of the nodes 0 and ±√(3/7).
const LOBATTO_W: (f64, f64) = (32.0 / 45.0, 49.0 / 90.0);
/// 9-point Kronrod weights of the Lobatto nodes 0 and ±√(3/7).
const LK_MID: f64 = 0.343_762_087_210_363_07;
const LK_LOBATTO: f64 = 0.283_978_778_048_121_1;
/// The nodes the 9-point Kronrod rule adds to the 5-point Lobatto rule, with
/// their Kronrod weights.
const LK_ADDED: [(f64, f64); 4] = [
    (-0.890_405_527_512_668_8, 0.179_262_699_553_207_36),
    (-0.340_982_265_910_992_97, 0.334_233_739_816_417_7),
    (0.340_982_265_910_992_97, 0.334_233_739_816_417_7),
    (0.890_405_527_512_668_8, 0.179_262_699_553_207_36),
];
/// Weights of the ends ±1: (Kronrod, Lobatto).
const LK_ENDS: (f64, f64) = (0.030_643_738_977_072_31, 0.1);

/// max(|ΔJ4|, |ΔJ5|, |ΔJ6|) of a difference `d` of contact sums.
#[inline]
fn max_abs_j(k: f64, dx: f64, d: &[f64; 4]) -> f64 {
    let (e4, e5, e6) = to_j(k, dx, d);
    e4.abs().max(e5.abs()).max(e6.abs())
}

/// Share of the allowed change ([`lobatto_kronrod_in_phi`]) for a panel
/// whose strips do not all have the same flow topology (a kink of the strip
/// sums inside it, where the two rules can agree by chance). With 1, a
/// panel holding the vanishing of an unloading (k = 0.163,
/// J = (−0.231, −0.204, −0.895)) was accepted at 0.88 of the allowed change
/// and the result was off by 1.08·tol at tol 1e-4 (with 0.7: 0.92·tol,
/// first edge at 8/|J3|); 0.25 takes 12–27 % more strips than 0.5.
const ACCEPT_KINK: f64 = 0.5;

/// ACCEPT_KINK for the refined panels (depth ≥ 1; the initial panels keep
/// ACCEPT_KINK) at tol ≤ 1e-4 (moving with log tol up to 1e-3, where it is
/// ACCEPT_KINK). On the 307 cases of `cargo xtask ep-sets` −2.6 %
/// instructions at 1e-4, on a random batch (k 0.2–5, |J1|, |J2| ≤ 5,
/// |J3| ≤ 26) −3.0 %; worst error/tol at 1e-4 over 62 seeds 0.45 (wide
/// range, the s-steps'), of the batch against tol 1e-6 0.37. 1 instead:
/// the batch's worst 0.51; 0.6: −1.1 % and −1.5 % (docs/decisions/0086).
/// k = 0.163, J = (−0.231, −0.204, −0.895) at 1e-4: 0.022·tol (0.047·tol
/// with 0.5).
const ACCEPT_KINK_REFINED: f64 = 0.7;

/// Least Lobatto–Kronrod estimate of a panel holding a kink, as a share of
/// its Simpson–Lobatto difference (stage 1). Across a kink the rules
/// converge algebraically, so a Lobatto–Kronrod difference far below that
/// share of the Simpson–Lobatto one is the two rules agreeing by chance. At
/// small spin and k (k = 0.1136, J = (−2.92e-5, 0.0333, −0.338)) each half
/// of the contact is one initial panel holding a kink, accepted at tol
/// 5e-4 on a difference 1/710 of its Simpson–Lobatto one and 1/6 of its
/// error: the contact was off by 1.55·tol (0.77·tol at 1e-3). A smooth
/// panel can show such a fall (beside the same kink: 1/1000, with an error
/// below 1e-3 of its allowed change), so the share applies to kink panels
/// only. 0.01 left that case at 0.13·tol at 1e-3, 0.02 at 0.04
/// (docs/decisions/0122).
const KINK_SIMPSON_SHARE: f64 = 0.02;

/// Least estimate of the pair check of a refined panel holding a kink, as
/// a share of the panel's own Lobatto–Kronrod difference: the halves'
/// Lobatto values cannot be trusted to far below that share of it, however
/// well they agree with the panel's Kronrod value (which is off too).
/// Measured on the pair checks of the bench cases h, b, p and of the
/// failing cases of docs/decisions/0122, the halves' actual error was
/// 0.02–0.67 of that difference, about 0.1 in most. k = 0.1065, J = (−2.75e-5, −0.00265, 0.382) at tol 5e-4:
/// the halves' sum agreed with the Kronrod value within 0.99 of the allowed
/// change, both off by about 2 of it, and the contact was off by 0.99·tol;
/// with 0.1 0.05·tol (0.05: 0.90·tol). Case h at tol 1e-3, whose halves
/// were off by 0.79 of the allowed change, is now refined instead: 137 k →
/// 155 k instructions (docs/decisions/0122).
const PAIR_KRONROD_SHARE: f64 = 0.1;

/// Unloading amplitude (`Strip::integrate_etd`) from which a
/// panel's strips that differ in flow topology count fully as a kink
/// ([`Gate`]). A strip's unloading is found at its step ends, so it
/// appears with an amplitude of about 0.01 already (k = 0.073,
/// J = (0.100, −0.097, 0.212): 0.0105), and the weight jumps by
/// smooth_step(0.0105/KINK_AMPLITUDE) there: 0.28 with 0.03, a jump of
/// 0.049·tol in the results at tol 1e-2 (0.115·tol with the former
/// all-or-nothing gate). 0.1 and 0.3 took the worst line of the small-k,
/// small-spin set (`cargo xtask ep-sets lines 4242`) to 0.023·tol at 1e-2
/// but to 0.62 and 0.55·tol at 1e-4 (0.03: 0.43) (docs/decisions/0123).
const KINK_AMPLITUDE: f64 = 0.03;

/// The weight of a panel's kink rules (ACCEPT_KINK, KINK_SIMPSON_SHARE and
/// the pair check) from its strips' flow topologies and unloading
/// amplitudes: 0 where the topologies all agree; where they differ, a C¹
/// step from 0 to 1 as the smaller of the two groups' largest amplitudes
/// (the strips with the first strip's topology, and the others) goes from
/// 0 to KINK_AMPLITUDE; 1 where both groups hold a strip without an
/// unloading (amplitude +∞), e.g. where the strip starts to end elastic.
/// A band of unloading strips born between a panel's strips, or an
/// unloading entering it at an end, reaches a strip with an amplitude near
/// 0, so the rules take hold continuously there instead of at once (a jump
/// in the results, docs/decisions/0123).
#[derive(Default)]
struct Gate {
    /// The first strip's topology.
    first: Option<u32>,
    /// The largest amplitude of the strips with that topology.
    same: f64,
    /// The largest amplitude of the others (None: no other topology).
    other: Option<f64>,
}

impl Gate {
    /// Count a strip's (topology, amplitude).
    #[inline]
    fn add(&mut self, (topology, amplitude): (u32, f64)) {
        match self.first {
            None => {
                self.first = Some(topology);
                self.same = amplitude;
            }
            Some(t) if t == topology => self.same = self.same.max(amplitude),
            Some(_) => {
                self.other = Some(self.other.map_or(amplitude, |o| o.max(amplitude)));
            }
        }
    }

    /// The weight of the kink rules, in [0, 1].
    #[inline]
    fn weight(&self) -> f64 {
        match self.other {
            None => 0.0,
            Some(o) => {
                let a = self.same.min(o);
                if a.is_nan() {
                    1.0
                } else {
                    smooth_step(a / KINK_AMPLITUDE)
                }
            }
        }
    }
}

/// Share of the allowed change up to which an initial panel (depth 0) keeps
/// its 5-point Lobatto value in stage 1. An initial panel has no coarser
/// check: its Simpson and Lobatto values can agree by chance while both are
/// off. k = 0.0887, J = (6.52e7, −1.07e5, −1.06e7) at tol 5e-4 (a fresh
/// seed of the whole-range scan): the panel [−0.476, π/2] was kept at 1.2
/// times the allowed change with its Kronrod value 3.0 times it away, and
/// the contact was 1.76·tol off (0.000 at 4.9e-4 and 5.1e-4, where the two
/// rules did not agree). With 0.3 and 0.1 it is 0.000·tol at 5e-4. On the
/// 307 cases 0.3 costs +2.1 % / +2.7 % instructions at tol 1e-3 / 1e-4 and
/// on the random batch +2.3 % / +5.4 %; 0.1 +4.2 % / +5.1 % and
/// +5.5 % / +9.7 % (docs/decisions/0124).
const INITIAL_STAGE1: f64 = 0.3;

/// Largest Simpson–Lobatto difference of a half, in allowed changes, at
/// which the pair check of [`lobatto_kronrod_in_phi`] may keep its Lobatto
/// value (docs/decisions/0080). The pair's agreement can be a chance: k =
/// 0.0646, J = (0, −0.1669, −0.2730) at tol 5e-4 kept a half on a
/// difference of 8.1 allowed changes, and the contact was 0.94·tol off
/// (0.88 at 6e-4, 0.65 at 4e-4); with 4 it is 0.011·tol (0.14 at 6e-4).
/// 20 → 4 costs +3.8 % / +1.1 % instructions on the 307 cases at tol
/// 1e-3 / 1e-4 (bench set the same at 1e-3; b +13 % at 1e-4)
/// (docs/decisions/0125).
const PAIR_STAGE1: f64 = 4.0;

/// The integrand in φ and a strip's (flow topology, unloading amplitude)
/// at a node.
type Node = ([f64; 4], (u32, f64));

/// A panel of [`lobatto_kronrod_in_phi`].
struct Panel {
    /// Its ends in φ.
    lo: f64,
    hi: f64,
    /// The nodes at its ends.
    fl: Node,
    fh: Node,
    /// Its depth of refinement (0: an initial panel, or a piece of one split
    /// at its kinks).
    depth: u32,
    /// The weight of its value in the result.
    weight: f64,
    /// For the halves of a refined panel, the share of the halves' pair that
    /// does not pass the pair check (their interior Lobatto nodes are then
    /// on the stack of nodes already evaluated).
    pair: Option<f64>,
    /// Whether it is a piece of an initial panel split at the kinks its
    /// nodes showed (it is not split at kinks again).
    located: bool,
}

impl Panel {
    /// An initial panel, or a piece of one (`located`), of weight `weight`.
    fn initial(lo: f64, hi: f64, fl: Node, fh: Node, weight: f64, located: bool) -> Self {
        Panel {
            lo,
            hi,
            fl,
            fh,
            depth: 0,
            weight,
            pair: None,
            located,
        }
    }
}

/// The kink between `a` and `b`, whose kink margins `ma` and `mb` differ in
/// sign, by regula falsi on the margins of `node_at` (`points` − 1 located
/// points, kept KINK_STEP_MIN of the bracket from its ends, then the
/// bracket's secant root; with `shaped` on the margins reshaped as in
/// [`KINK_POINTS_INSIDE`]), pulled to the nearer end of the panel `[lo, hi]`
/// within `band` of it (a C¹ smooth step in the distance).
fn locate_kink(
    node_at: &mut impl FnMut(f64, bool) -> (Node, f64),
    (mut a, ma): (f64, f64),
    (mut b, mb): (f64, f64),
    (lo, hi, band): (f64, f64, f64),
    (points, shaped): (usize, bool),
) -> f64 {
    // With `shaped`, the unloading side's margin (< 0), which vanishes like
    // the square root of the distance from the kink, is squared (scaled by
    // the bracket's margin there, so that it is continuous in the inputs).
    let scale = if ma < 0.0 { -ma } else { -mb };
    let shape = |m: f64| {
        if !shaped {
            m
        } else if m < 0.0 {
            -m * m / scale
        } else {
            m.min(scale)
        }
    };
    let (mut ma, mut mb) = (shape(ma), shape(mb));
    let mut x = a;
    for j in 1..points {
        let t = (ma / (ma - mb)).clamp(KINK_STEP_MIN, 1.0 - KINK_STEP_MIN);
        x = a + (b - a) * t;
        let mx = shape(node_at(x, true).1);
        if mx.is_nan() {
            break;
        }
        if (mx > 0.0) == (ma > 0.0) {
            (a, ma) = (x, mx);
        } else {
            (b, mb) = (x, mx);
        }
        if j + 1 == points {
            x = a + (b - a) * ma / (ma - mb);
        }
    }
    let near = if x - lo <= hi - x { lo } else { hi };
    near + smooth_step((x - near).abs() / band) * (x - near)
}

/// The interior nodes of the 5-point Lobatto rule on the panel of midpoint
/// `m` and half-width `hw`: m, m − hw·√(3/7), m + hw·√(3/7).
#[inline(always)]
fn lobatto_nodes(f: &mut impl FnMut(f64) -> Node, m: f64, hw: f64) -> [Node; 3] {
    [f(m), f(m - hw * LOBATTO_X), f(m + hw * LOBATTO_X)]
}

/// The 5-point Lobatto value of a panel of half-width `hw` from the sum of
/// its end values `ends` and its interior nodes ([`lobatto_nodes`]).
#[inline]
fn lobatto5(hw: f64, ends: &[f64; 4], [fm, fa, fb]: &[Node; 3]) -> [f64; 4] {
    std::array::from_fn(|i| {
        hw * (LK_ENDS.1 * ends[i] + LOBATTO_W.1 * (fa.0[i] + fb.0[i]) + LOBATTO_W.0 * fm.0[i])
    })
}

/// The initial panels between `breaks` onto `stack`, each split where a
/// kink (an unloading appearing or vanishing) is located by regula falsi on
/// the kink margins of its ends (KINK_POINTS strips, the last the split; at
/// `split` < 1 the split lies that share of the way from the panel's end
/// nearer the pole's strip `pole` to it; within KINK_END_BAND of a panel's
/// end it is pulled to that end). A split appears or vanishes where a
/// margin changes sign, at a panel's end, where the split then lies: the
/// result stays continuous. At `split` = 0 no margins are computed.
fn initial_panels(
    breaks: &[f64],
    (split, pole): (f64, f64),
    node_at: &mut impl FnMut(f64, bool) -> (Node, f64),
    stack: &mut Vec<Panel>,
) {
    let margins = split > 0.0;
    let mut flo = node_at(breaks[0], margins);
    for w in breaks.windows(2) {
        let fhi = node_at(w[1], margins);
        if w[1] > w[0] {
            if flo.1 * fhi.1 < 0.0 {
                let band = KINK_END_BAND * (w[1] - w[0]);
                let x = locate_kink(
                    node_at,
                    (w[0], flo.1),
                    (w[1], fhi.1),
                    (w[0], w[1], band),
                    (KINK_POINTS, false),
                );
                let end = if w[1] <= pole { w[1] } else { w[0] };
                let x = if split < 1.0 {
                    end + split * (x - end)
                } else {
                    x
                };
                // A split at a panel's end (a margin of exactly 0 there)
                // leaves that panel whole: no empty panel is decided.
                let fx = node_at(x, false).0;
                if x > w[0] {
                    stack.push(Panel::initial(w[0], x, flo.0, fx, 1.0, false));
                }
                if w[1] > x {
                    stack.push(Panel::initial(x, w[1], fx, fhi.0, 1.0, false));
                }
            } else {
                stack.push(Panel::initial(w[0], w[1], flo.0, fhi.0, 1.0, false));
            }
        }
        flo = fhi;
    }
}

/// The kinks between the neighbouring nodes `at` (φ and node, in order)
/// of a panel whose strips differ in whether they unload: at each pair of
/// neighbours of different kind whose kink margins (computed again here)
/// differ in sign, located by regula falsi on reshaped margins
/// ([`KINK_POINTS_INSIDE`]), pulled to the panel's end within
/// KINK_END_BAND of the bracket there. The located points with their nodes,
/// and how many there are.
fn node_kinks(
    at: &[(f64, Node); 9],
    node_at: &mut impl FnMut(f64, bool) -> (Node, f64),
) -> ([(f64, Node); 8], usize) {
    let (lo, hi) = (at[0].0, at[8].0);
    let mut cuts = [(0.0, at[0].1); 8];
    let mut n = 0;
    for p in at.windows(2) {
        let unloads = |v: &Node| v.1.0 >= 2;
        if unloads(&p[0].1) != unloads(&p[1].1) {
            // The two strips again, with their margins: margins at every
            // node would cost more (docs/decisions/0123, 0131).
            let ma = node_at(p[0].0, true).1;
            let mb = node_at(p[1].0, true).1;
            if ma * mb < 0.0 {
                // Pulled to the panel's end within KINK_END_BAND of the
                // bracket (at the end) from it.
                let band = KINK_END_BAND * (p[1].0 - p[0].0);
                let x = locate_kink(
                    node_at,
                    (p[0].0, ma),
                    (p[1].0, mb),
                    (lo, hi, band),
                    (KINK_POINTS_INSIDE, true),
                );
                cuts[n] = (x, node_at(x, false).0);
                n += 1;
            }
        }
    }
    (cuts, n)
}

/// Adaptive Lobatto–Kronrod panels in φ (Y = sin φ) from the sorted edges
/// `breaks` (from −π/2 to π/2, one of them `pole`, the spin pole's strip);
/// `strip(Y, margin)` gives a strip's (∫Zx, ∫Zy, ∫Zy·X), its flow topology
/// (any number that changes where the strip sums have a kink in Y) and,
/// with `margin`, its kink margin (`Strip::integrate_etd_margin`; NaN
/// without).
///
/// Below tol 4e-4 ([`KINK_SPLIT_TOL`]) an initial panel whose end strips'
/// margins differ in sign holds a kink where an unloading appears or vanishes: it is located
/// by regula falsi on the margins ([`KINK_POINTS`] strips) and the panel
/// split there (fully at tol ≤ 3e-4, see `kink_share`) into two initial
/// panels, which then need not be refined down to the kink
/// (docs/decisions/0094).
///
/// Its ends' margins do not show an even number of kinks (an unloading band
/// between them). So an initial panel to be refined (by a share of at least
/// [`PIECES_FROM`]) whose nine nodes differ in whether their strips unload
/// is split at each kink between two neighbouring nodes of different kind,
/// located by regula falsi on reshaped margins ([`KINK_POINTS_INSIDE`]),
/// pulled to the panel's end within KINK_END_BAND of the bracket there.
/// Its pieces are decided as initial panels and are not split at kinks
/// again; their refinement is blended with the halves' by `kink_share` and
/// by the refinement share. Refined by halves instead, the panel's halves
/// chased each kink and their decisions flipped between neighbouring
/// inputs (docs/decisions/0130).
///
/// Each panel is decided in two stages,
/// each against the allowed change tol·width/π in J4, J5 and J6
/// (ACCEPT_KINK times that where the panel's strips differ in topology;
/// ACCEPT_KINK_REFINED on refined panels at tol ≤ 1e-4; each kink rule
/// here applies by the weight of [`Gate`]):
///
/// 1. its 5-point Lobatto value is kept when it and the 3-point one
///    (Simpson, on the ends and the midpoint) differ by less than the
///    allowed change (INITIAL_STAGE1 of it for an initial panel; 3 new
///    strips);
/// 2. otherwise (blended in between, see below) its 9-point Kronrod value
///    is kept when it and the 5-point Lobatto value differ by less than
///    the allowed change (4 more strips); otherwise both halves are
///    refined. Where the strips differ in topology, the difference counts
///    as at least KINK_SIMPSON_SHARE of stage 1's.
///
/// Pair check: where a refined panel's strips (its nine and its halves'
/// stage-1 ones) differ in flow topology, the
/// sum of its halves' 5-point Lobatto values (their stage-1 strips) is
/// compared with the panel's 9-point Kronrod value, two rules on different
/// nodes. Where they agree to ACCEPT_KINK times the panel's allowed change,
/// a half keeps its Lobatto value in stage 1 up to PAIR_STAGE1 times its own
/// allowed change (instead of 1): near a kink Simpson's value is far off
/// while the Lobatto values of the halves are not (docs/decisions/0080).
/// Their difference counts as at least PAIR_KRONROD_SHARE of the panel's
/// own Lobatto–Kronrod difference (docs/decisions/0122).
///
/// Every decision is blended (the share of the next step a C¹ step from 1
/// to 2 times the allowed change; the pair check's share multiplies the
/// wider stage 1's), so that a decision adds no jump in the inputs. The
/// kink rules take hold by [`Gate`]'s weight, continuously where an
/// unloading reaches one of the panel's strips (with the jump of its
/// amplitude where the strip integration finds it, see
/// [`KINK_AMPLITUDE`]); where the strips start or stop ending elastic they
/// still take hold at once. All three rules use the panel's
/// ends: neighbouring panels share their end strips and a panel's halves
/// its ends and midpoint, so a panel costs 3 or 7 new strips (the strips at
/// Y = ±1 are empty), 12 with the former rule (4-point Gauss–Legendre
/// checked against its halves, [`adaptive_in_phi`]), whose 8-point value
/// was far more accurate than needed (docs/decisions/0074). Stage 1 settles
/// mostly the halves of refined panels (the initial panels, 3–50 times the
/// allowed change apart in Simpson's value on the bench set, go on to stage
/// 2): a refinement then costs 2 × 3 strips instead of 2 × 7
/// (docs/decisions/0079).
pub(crate) fn lobatto_kronrod_in_phi(
    breaks: &[f64],
    tol: f64,
    max_depth: u32,
    (k, dx): (f64, f64),
    pole: f64,
    mut strip: impl FnMut(f64, bool) -> ([f64; 3], (u32, f64), f64),
) -> (f64, f64, f64) {
    let kink_refined = ACCEPT_KINK + fine_tol(tol) * (ACCEPT_KINK_REFINED - ACCEPT_KINK);
    let split = kink_share(tol);
    // The integrand in φ: cos φ·(∫Zx, ∫Zy, ∫Zy·X, Y·∫Zx), the topology,
    // and with `margin` the strip's kink margin (NaN without; and for the
    // empty strips at Y = ±1).
    let mut node_at = |phi: f64, margin: bool| -> (Node, f64) {
        let (y, cphi) = phi.sin_cos();
        if cphi <= 0.0 || phi.abs() >= FRAC_PI_2 {
            // The empty strip (Y = ±1) has the margin of a strip with no
            // plastic segment (`Strip::integrate_etd_margin`).
            let m = if margin { MARGIN_CAP } else { f64::NAN };
            return (([0.0; 4], (0, f64::INFINITY)), m);
        }
        let (st, t, m) = strip(y, margin);
        (
            (
                [cphi * st[0], cphi * st[1], cphi * st[2], cphi * y * st[0]],
                t,
            ),
            m,
        )
    };
    let mut total = [0.0; 4];
    let mut stack: Vec<Panel> = Vec::with_capacity(32);
    // Interior Lobatto nodes of the halves on `stack` that have them (in
    // the same order: a half's are on top when it is taken).
    let mut known: Vec<[Node; 3]> = Vec::with_capacity(16);
    initial_panels(breaks, (split, pole), &mut node_at, &mut stack);
    while let Some(panel) = stack.pop() {
        let Panel {
            lo,
            hi,
            fl,
            fh,
            depth,
            weight,
            pair,
            located,
        } = panel;
        let mut f = |phi: f64| node_at(phi, false).0;
        let (m, hw) = (0.5 * (lo + hi), 0.5 * (hi - lo));
        // The strips at Y = ±1 (zero width) count as any topology.
        let mut gate = Gate::default();
        for (v, e) in [(fl.1, lo), (fh.1, hi)] {
            if e.abs() < FRAC_PI_2 {
                gate.add(v);
            }
        }
        // Stage 1: the 5-point Lobatto value against the 3-point one
        // (Simpson, on the ends and the midpoint).
        let nodes = match pair {
            Some(_) => known.pop().unwrap_or_else(|| lobatto_nodes(&mut f, m, hw)),
            None => lobatto_nodes(&mut f, m, hw),
        };
        for v in &nodes {
            gate.add(v.1);
        }
        let [fm, fa, fb] = &nodes;
        let ends: [f64; 4] = std::array::from_fn(|i| fl.0[i] + fh.0[i]);
        let l5 = lobatto5(hw, &ends, &nodes);
        let mut d: [f64; 4] =
            std::array::from_fn(|i| l5[i] - hw * ((1.0 / 3.0) * ends[i] + (4.0 / 3.0) * fm.0[i]));
        // The change allowed in this panel, by its kink weight.
        let allowed_with = |w: f64| {
            let share = if depth == 0 {
                ACCEPT_KINK
            } else {
                kink_refined
            };
            (1.0 - w * (1.0 - share)) * tol * (hi - lo) / PI
        };
        let allowed = allowed_with(gate.weight());
        // The share of the panel that goes on to stage 2 (blended like a
        // refinement, whatever the depth); with a passed pair check it is
        // that of the wider stage 1.
        let e1 = max_abs_j(k, dx, &d);
        let stage1 = if depth == 0 {
            INITIAL_STAGE1 * allowed
        } else {
            allowed
        };
        let mut go_on = refine_share(e1, stage1, 0, 1);
        if let Some(split) = pair
            && split < 1.0
            && go_on > 0.0
        {
            go_on *= 1.0 - (1.0 - split) * (1.0 - refine_share(e1, PAIR_STAGE1 * allowed, 0, 1));
        }
        if go_on < 1.0 {
            let w = weight * (1.0 - go_on);
            for i in 0..4 {
                total[i] += w * l5[i];
            }
        }
        if go_on == 0.0 {
            continue;
        }
        let weight = weight * go_on;
        // Stage 2: the 9-point Kronrod value against the 5-point Lobatto one.
        let mut kv: [f64; 4] = std::array::from_fn(|i| {
            LK_ENDS.0 * ends[i] + LK_MID * fm.0[i] + LK_LOBATTO * (fa.0[i] + fb.0[i])
        });
        let added: [Node; 4] = std::array::from_fn(|j| f(m + hw * LK_ADDED[j].0));
        for ((_, wk), v) in LK_ADDED.iter().zip(&added) {
            gate.add(v.1);
            for (s, x) in kv.iter_mut().zip(v.0) {
                *s += wk * x;
            }
        }
        for i in 0..4 {
            kv[i] *= hw;
            d[i] = kv[i] - l5[i];
        }
        let wk = gate.weight();
        let allowed = allowed_with(wk);
        let d2 = max_abs_j(k, dx, &d);
        // Across a kink the difference is trusted only down to a share of
        // stage 1's (KINK_SIMPSON_SHARE).
        let est = d2.max(wk * KINK_SIMPSON_SHARE * e1);
        let refine = refine_share(est, allowed, depth, max_depth);
        if refine < 1.0 {
            let w = weight * (1.0 - refine);
            for i in 0..4 {
                total[i] += w * kv[i];
            }
        }
        // An initial panel to be refined whose nodes differ in whether
        // their strips unload holds kinks its margins at the ends need not
        // show (an unloading band between them): it is split at each kink
        // located between neighbouring nodes (at `split` < 1 by that share
        // of its refinement, the rest halved).
        let mut halves = refine;
        let pieces = split * smooth_step((refine - PIECES_FROM) / (1.0 - PIECES_FROM));
        if pieces > 0.0 && depth == 0 && !located {
            let at = [
                (lo, fl),
                (m + hw * LK_ADDED[0].0, added[0]),
                (m - hw * LOBATTO_X, *fa),
                (m + hw * LK_ADDED[1].0, added[1]),
                (m, *fm),
                (m + hw * LK_ADDED[2].0, added[2]),
                (m + hw * LOBATTO_X, *fb),
                (m + hw * LK_ADDED[3].0, added[3]),
                (hi, fh),
            ];
            let (cuts, n) = node_kinks(&at, &mut node_at);
            if n > 0 {
                let w = weight * refine * pieces;
                let (mut a, mut fa) = (lo, fl);
                for &(x, fx) in cuts[..n].iter().chain(&[(hi, fh)]) {
                    if x > a {
                        stack.push(Panel::initial(a, x, fa, fx, w, true));
                    }
                    (a, fa) = (x, fx);
                }
                halves = refine * (1.0 - pieces);
            }
        }
        if halves > 0.0 {
            let mut f = |phi: f64| node_at(phi, false).0;
            // The halves' stage-1 strips now, for the pair check.
            let q = 0.5 * hw;
            let nl = lobatto_nodes(&mut f, lo + q, q);
            let nr = lobatto_nodes(&mut f, m + q, q);
            for v in nl.iter().chain(&nr) {
                gate.add(v.1);
            }
            let wk = gate.weight();
            let split = if wk > 0.0 {
                let el: [f64; 4] = std::array::from_fn(|i| fl.0[i] + fm.0[i]);
                let er: [f64; 4] = std::array::from_fn(|i| fm.0[i] + fh.0[i]);
                let (vl, vr) = (lobatto5(q, &el, &nl), lobatto5(q, &er, &nr));
                let d: [f64; 4] = std::array::from_fn(|i| vl[i] + vr[i] - kv[i]);
                let allowed = ACCEPT_KINK * tol * (hi - lo) / PI;
                // The halves' values are trusted only down to a share of
                // the panel's own difference (PAIR_KRONROD_SHARE).
                let est = max_abs_j(k, dx, &d).max(PAIR_KRONROD_SHARE * d2);
                1.0 - wk * (1.0 - refine_share(est, allowed, 0, 1))
            } else {
                1.0
            };
            let w = weight * halves;
            known.push(nl);
            known.push(nr);
            for (lo, hi, fl, fh) in [(lo, m, fl, *fm), (m, hi, *fm, fh)] {
                stack.push(Panel {
                    lo,
                    hi,
                    fl,
                    fh,
                    depth: depth + 1,
                    weight: w,
                    pair: Some(split),
                    located: false,
                });
            }
        }
    }
    to_j(k, dx, &total)
}

/// Exponential step (`Strip::etd`) on the stiff, slowly turning plastic
/// segments at tol = 1e-3, ∝ √tol (its error is observed second order in the
/// step where κ·h ≫ 1: at tol = 1e-4 a step ∝ tol^(1/4), like the s-step,
/// moved results by up to 0.13·tol against 0.001·tol for RK4), at most
/// [`ETD_STEP_MAX`]. 0.8 instead of 0.4 (docs/decisions/0049): case s
/// −7 % instructions at tol 1e-3 and −13 % at 1e-4 (where the steps are now
/// ≥ 2.5 s-steps), results moved by ≤ 0.1·tol, the worst error/tol against
/// 128-panel references unchanged over 62 seeds of `cargo xtask ep-sets`.
const ETD_STEP: f64 = 0.8;
/// Longest exponential step.
const ETD_STEP_MAX: f64 = 0.8;

/// Elastic/plastic (J4, J5, J6) by strip integration.
pub(crate) fn solve(sc: &Scaled, res: &Resolution) -> (f64, f64, f64) {
    contact_integral(sc, res, |s| s.integrate(res.s_step, res.s_step))
}
