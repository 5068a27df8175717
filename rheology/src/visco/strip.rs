//! One strip from the inlet (σ = 0) to the outlet (σ = π): [`strip_sums`]
//! starts in the interior with [`first_step`], takes Rosenbrock steps
//! (`rosenbrock.rs`) on the current kind of segment ([`Mode`], the
//! segments in `segments.rs`), accepts a step up to [`STEP_ACCEPT`] times
//! the step error and sizes the next one by [`factor`] (at most
//! [`H_MAX`]), goes onto the cap at a located cap entry and back into the
//! interior at a located unloading, leaves a cap entry close to the outlet
//! unfollowed ([`outlet_bound`]), and ends at the outlet with the strip's
//! sums ∫Zx dX, ∫Zy dX, ∫Zy·X dX for the panels across the contact
//! (`mod.rs`). With an isotropic stiffness a cap segment is instead the
//! elastic/plastic model's plastic segment with the cap's end
//! ([`cap_segment`]): on the cap the direction follows the same flow.

use std::f64::consts::PI;

use super::law::VStrip;
use super::rosenbrock::{Step, event, event_newton, hermite, hermite_dt, ros_step};
use super::segments::{Cap, Eval, Interior, Jac, Pt, Seg};

/// Largest number of cap ↔ interior switches per strip (then the stress
/// stays on the cap).
const MAX_SWITCH: usize = 24;
/// A cap that ends within this share of the interior step that entered it
/// counts as empty (`strip_sums_topology`).
const EMPTY_CAP: f64 = 1e-9;
/// Largest number of times per strip an interior step whose entry met an
/// empty cap, or whose interpolated entry the step does not reach
/// ([`ENTRY_GAP`]), is retaken at half its length.
const ENTRY_RETRIES: usize = 8;
/// Largest |(|Z| − L)|/L at the end of the interior step taken up to a cap
/// entry located on a longer step's Hermite interpolant: beyond it the
/// interpolant, not the stress, reached the cap, and the step is retaken
/// at half its length. At k = 0.0206, J = (0, 25.1, 1e4), gy = 0.9,
/// D = 0.0078, Z0 = 0.030 and tol 1e-2 an interior step of 0.47 rad ended
/// at the outlet, its interpolant met the cap at its start where |Z| was
/// 0.63·L, and the stress then stayed on the cap to the outlet: strips
/// off by 20 times their allowed error, 19 000 of them per evaluation
/// (0.7 s) and J6 3.4·tol off (docs/decisions/0132).
const ENTRY_GAP: f64 = 0.01;
/// Steps per strip after which steps are accepted regardless of the error
/// estimate: guarantees termination at extreme inputs (where the tolerance
/// is then not held).
const MAX_STEPS: usize = 1000;

#[derive(Clone, Copy)]
enum Mode {
    Interior([f64; 2]),
    /// On the cap with an anisotropic stiffness (gy ≠ 1): θ and its
    /// direction (cos θ, sin θ).
    Cap(f64, (f64, f64)),
}

/// A step is accepted while its error estimate is at most STEP_ACCEPT times
/// the step error; the step-size factor still aims at 0.9⁴ ≈ 0.66 of it.
/// Most rejected steps had missed by a few tens of per cent (m: 42 of 321
/// attempts rejected with 1, 3 of 272 with 1.5). The contact's error grows
/// less than the limit: worst error/tol over 2500 random cases 0.53 → 0.60
/// at tol 1e-3, 0.46 → 0.55 at 1e-4, against the former scheme refined
/// 0.50 → 0.68 (1.2: 0.57, 0.46, 0.53 for about half the saving;
/// docs/decisions/0077).
const STEP_ACCEPT: f64 = 1.5;

/// Step-size factor from an error ratio (order-3 estimate).
#[inline]
fn factor(err: f64, atol: f64) -> f64 {
    if err == 0.0 {
        4.0
    } else {
        (0.9 * (atol / err).sqrt().sqrt()).clamp(0.2, 4.0)
    }
}

/// Longest step in σ (the Taylor sine and cosine of [`Pt::advance`] hold
/// for |d| ≤ 1). Reached on the stiff, quasi-static strips of small D
/// (case l: −4 % instructions at tol 1e-3 against the former 0.8; 1.2 and
/// 1.6 no better; docs/decisions/0076).
const H_MAX: f64 = 1.0;

/// The point at σ + h, exactly (0, −1) at the outlet.
#[inline]
fn end_point(p1: Pt, last: bool) -> Pt {
    if last {
        Pt {
            s: PI,
            sn: 0.0,
            cs: -1.0,
        }
    } else {
        p1
    }
}

/// A cap entry in a strip's last step whose remaining strip moves the
/// sums by less than OUTLET_EPS·atol ([`outlet_bound`]) is not followed.
const OUTLET_EPS: f64 = 0.02;

/// A bound on the strip sums' change if a cap entry at σ_e = σ + `he` in
/// the strip's last step from `p` is not followed: beyond it the interior
/// stress, |Z| ≤ 2·max(L_e, |Z_1|) on the step's interpolant (|Z_1| = `r1`
/// at the outlet), against |Z| = L ≤ L_e on the cap, over the rest of the
/// strip ΔX = c·(1 + cos σ_e) (and X·ΔX for ∫Zy·X dX): (2·max(L_e, |Z_1|) +
/// L_e)·ΔX·(1 + c). Out of line (at most once per strip).
#[inline(never)]
fn outlet_bound(st: &VStrip, p: Pt, he: f64, r1: f64) -> f64 {
    let pe = p.advance(he);
    let le = 1.5 * st.c * pe.sn.max(0.0);
    (2.0 * le.max(r1) + le) * st.c * (1.0 + pe.cs) * (1.0 + st.c)
}

/// The first step's bound at a stiff inlet, see [`strip_sums`]: 20 leaves
/// the first step's estimate ≈ atol on case l (10: −3.1 %, 20: −3.7 %,
/// 30: −4.6 %, 50: none of the instructions at tol 1e-3, the first step
/// then rejected again; 20 keeps a margin).
const INLET_K: f64 = 20.0;

/// The first step of a strip (kept out of line: once per strip).
#[inline(never)]
fn first_step(st: &VStrip, atol: f64) -> f64 {
    // At the inlet Z ≈ e·c·σ²/2 against L ≈ (3/2)·c·σ: the first step keeps
    // |Z|/L ≤ 1/2. 0.8·tol^(1/4) (0.14 at 1e-3): the former 0.2·tol^(1/4)
    // had step errors ≈ 0 and took ≈ 2 steps more to reach the strip's
    // step size (6 % of the steps at moderate spin; docs/decisions/0046).
    let ein = (st.a * st.a + (st.b1 - st.q2 * st.c).powi(2)).sqrt();
    let mut h = 0.8 * atol.sqrt().sqrt();
    if ein > 0.0 {
        h = h.min(1.5 / ein);
    }
    // Stiff relaxation at the inlet (small D): there dZ/dσ ≈ c·σ·(e − Z/D′)
    // with D′ = D/max(1, gy) (ψ′(0) = 1/D), a layer of width √(D′/c) in σ
    // whose first step's error estimate grows like e·D′·(h·√(c/D′))⁵/19
    // (measured on case l, D = 0.01): the first step is kept to
    // √(D′/c)·(INLET_K·atol/(|e|·D′))^(1/5), where that estimate is ≈ atol
    // (the powf only where this bounds the step).
    let dr = st.law.d / st.gy.max(1.0);
    let h2 = h * h;
    if dr * dr.sqrt() * INLET_K * atol < h2 * h2 * h * st.c * st.c * st.c.sqrt() * ein {
        h = (dr / st.c).sqrt() * (INLET_K * atol / (ein * dr)).powf(0.2);
    }
    h
}

/// The stress on the cap from `p` in the direction `n0`: the elastic/plastic
/// model's plastic segment with the cap's end ([`VStrip::limit_strip`]), in
/// its angle s = σ − π/2 (X = −c·cos σ = c·sin s). Returns the strip sums
/// over it and, where the stress leaves the cap before the outlet, the point
/// and the stress there.
#[inline(never)]
fn cap_segment(
    st: &VStrip,
    p: Pt,
    n0: (f64, f64),
    allow_unload: bool,
) -> ([f64; 3], Option<(Pt, [f64; 2])>) {
    let ep = st.limit_strip();
    let (sums, end) = ep.limit_segment(-p.cs, p.sn.max(0.0), n0, allow_unload, st.steps);
    let end = end.map(|(x, z)| {
        let cs = (-x / st.c).clamp(-1.0, 1.0);
        let sn = (1.0 - cs * cs).max(0.0).sqrt();
        (
            Pt {
                s: cs.acos(),
                sn,
                cs,
            },
            [z.0, z.1],
        )
    });
    ([sums.ix, sums.iy, sums.ixy], end)
}

/// The Rosenbrock step from `p` (state `u`, with its rates and Jacobian
/// `(ev0, jac)`) of length h, or shorter: repeated at `factor`'s shorter
/// length (at most 0.9·h) until its error is within STEP_ACCEPT·atol, or
/// taken as it is once the strip has made MAX_STEPS attempts (`steps`
/// counts them). Returns the step and its length.
#[inline(always)]
fn accepted_step<const N: usize, S: Seg<N>>(
    seg: &S,
    p: Pt,
    mut h: f64,
    u: &[f64; N],
    (ev0, jac): (&Eval<N>, &Jac<N>),
    atol: f64,
    steps: &mut usize,
) -> (Step<N>, f64) {
    loop {
        *steps += 1;
        crate::counts::count!(visco_steps);
        let stp = ros_step(seg, p, h, u, ev0, jac);
        if stp.err <= STEP_ACCEPT * atol || *steps > MAX_STEPS {
            return (stp, h);
        }
        h *= factor(stp.err, atol).min(0.9);
    }
}

/// Strip integrals [∫Zx dX, ∫Zy dX, ∫Zy·X dX], step error estimates
/// ≤ [`STEP_ACCEPT`]·atol (step sizes aimed at 0.66·atol).
pub(crate) fn strip_sums(st: &VStrip, atol: f64) -> [f64; 3] {
    strip_sums_topology(st, atol).0
}

/// [`strip_sums`] and the strip's flow topology: its number of cap entries
/// and unloadings (the strip sums have a kink in Y where it changes).
pub(crate) fn strip_sums_topology(st: &VStrip, atol: f64) -> ([f64; 3], u32) {
    let (q, t, _) = strip_sums_with(st, atol, false);
    (q, t)
}

/// [`strip_sums_topology`] and the strip's near-kink margin: the least
/// closest approach of the interior stress to the cap, 1 − |Z|/L at the
/// interior minima of its samples at the interior steps' ends (each the
/// vertex of the parabola through the three samples about it). It goes to
/// 0 where |Z| touches L and a cap entry and exit appear on the strip, so
/// a band of another flow topology lies near in Y where it falls
/// ([`NO_MARGIN`] where the strip has no such minimum). Measured on the
/// strips next to such bands (docs/decisions/0121): about linear in φ
/// there (0.093, 0.050, 0.025 at φ = 0.785, 0.857, 0.894 before a band at
/// 0.926).
pub(crate) fn strip_sums_margin(st: &VStrip, atol: f64) -> ([f64; 3], u32, f64) {
    strip_sums_with(st, atol, true)
}

/// The margin of a strip without an interior minimum of 1 − |Z|/L
/// ([`strip_sums_margin`]).
pub(crate) const NO_MARGIN: f64 = f64::INFINITY;

/// The vertex value of the parabola through (s, d) at three points, where
/// the middle one is the least.
pub(super) fn parabola_min([(s0, d0), (s1, d1), (s2, d2)]: [(f64, f64); 3]) -> f64 {
    let f01 = (d1 - d0) / (s1 - s0);
    let f12 = (d2 - d1) / (s2 - s1);
    let a = (f12 - f01) / (s2 - s0);
    if a.is_nan() || a <= 0.0 {
        return d1;
    }
    let sv = 0.5 * (s0 + s1) - f01 / (2.0 * a);
    let v = d0 + f01 * (sv - s0) + a * (sv - s0) * (sv - s1);
    v.clamp(0.0, d1)
}

/// Whether the interior step of length `hs` from `p` (stress `z`) ends on
/// the cap, to ENTRY_GAP of L: the check of a cap entry located on the
/// Hermite interpolant of a longer step.
fn entry_holds(
    inter: &Interior,
    p: Pt,
    hs: f64,
    z: &[f64; 2],
    (ev0, jac): (&Eval<2>, &Jac<2>),
) -> bool {
    let e = ros_step(inter, p, hs, z, ev0, jac);
    let r = (e.u[0] * e.u[0] + e.u[1] * e.u[1]).sqrt();
    let l = 1.5 * inter.0.c * e.p1.sn.max(0.0);
    (r - l).abs() <= ENTRY_GAP * l
}

#[allow(clippy::needless_range_loop)]
fn strip_sums_with(st: &VStrip, atol: f64, with_margin: bool) -> ([f64; 3], u32, f64) {
    let mut q = [0.0; 3];
    if st.c <= 0.0 {
        return (q, 0, NO_MARGIN);
    }
    let mut margin = NO_MARGIN;
    // The last interior step ends' (s, 1 − |Z|/L), newest last (with_margin).
    let mut samples: [(f64, f64); 3] = [(f64::NAN, f64::NAN); 3];
    let mut nsamples = 0;
    crate::counts::count!(visco_strips);
    let inter = Interior(st);
    // The largest viscous rate on this strip, ψ((3/2)·c), for
    // Cap::unload_sign (computed at the first cap step).
    let mut psi_c = f64::NAN;
    let mut h = first_step(st, atol);
    let mut p = Pt {
        s: 0.0,
        sn: 0.0,
        cs: 1.0,
    };
    let mut mode = Mode::Interior([0.0, 0.0]);
    let mut switches = 0;
    let mut steps = 0;
    // Interior steps retaken shorter for an entry onto an empty cap.
    let mut retries = 0;
    let lcap = |sn: f64| 1.5 * st.c * sn.max(0.0);
    let add = |q: &mut [f64; 3], d: &[f64; 3]| {
        for i in 0..3 {
            q[i] += d[i];
        }
    };
    while p.s < PI {
        let hmax = PI - p.s;
        h = h.min(H_MAX);
        let last = h >= hmax;
        if last {
            h = hmax;
        }
        match mode {
            Mode::Interior(z) => {
                let (p_start, q_start) = (p, q);
                let (ev0, jac) = inter.eval_jac(p, &z);
                let (stp, h1) = accepted_step(&inter, p, h, &z, (&ev0, &jac), atol, &mut steps);
                let last = last && h1 == hmax;
                let p1 = end_point(stp.p1, last);
                let l1 = lcap(p1.sn);
                let r1 = (stp.u[0] * stp.u[0] + stp.u[1] * stp.u[1]).sqrt();
                if r1 > l1 {
                    // Cap entry inside the step: |H(t)|² − L² changes sign.
                    let ev1 = inter.eval(p1, &stp.u);
                    let g = |t: f64| {
                        let zx = hermite(z[0], ev0.f[0], stp.u[0], ev1.f[0], h1, t);
                        let zy = hermite(z[1], ev0.f[1], stp.u[1], ev1.f[1], h1, t);
                        zx * zx + zy * zy - lcap(p.advance(t * h1).sn).powi(2)
                    };
                    let g0 = z[0] * z[0] + z[1] * z[1] - lcap(p.sn).powi(2);
                    let t = if g0 < 0.0 {
                        // |H| − L and its derivative H·H′/|H| − L′,
                        // L′ = (3/2)·c·cos σ·h. (|H|² − L² is flat where L
                        // vanishes linearly at the outlet: Newton's iterates
                        // from t = 1 left the bracket there, 12 evaluations
                        // per entry on case l against 4 with |H| − L.)
                        let gd = |t: f64| {
                            let zx = hermite(z[0], ev0.f[0], stp.u[0], ev1.f[0], h1, t);
                            let zy = hermite(z[1], ev0.f[1], stp.u[1], ev1.f[1], h1, t);
                            let dx = hermite_dt(z[0], ev0.f[0], stp.u[0], ev1.f[0], h1, t);
                            let dy = hermite_dt(z[1], ev0.f[1], stp.u[1], ev1.f[1], h1, t);
                            let pt = p.advance(t * h1);
                            let r = (zx * zx + zy * zy).sqrt();
                            let dr = if r > 0.0 {
                                (zx * dx + zy * dy) / r
                            } else {
                                0.0
                            };
                            (r - lcap(pt.sn), dr - 1.5 * st.c * pt.cs * h1)
                        };
                        let r0 = (z[0] * z[0] + z[1] * z[1]).sqrt();
                        event_newton(gd, r0 - lcap(p.sn), r1 - l1)
                    } else {
                        // At the inlet (Z = 0 = L) or on the cap's edge.
                        event(g, r1 * r1 - l1 * l1)
                    };
                    // An entry this close to the outlet (the stiff,
                    // quasi-static strips of small D) is not followed.
                    if last
                        && t < 1.0
                        && stp.err <= STEP_ACCEPT * atol
                        && outlet_bound(st, p, t * h1, r1) <= OUTLET_EPS * atol
                    {
                        add(&mut q, &stp.dq);
                        break;
                    }
                    let zs = if stp.err > STEP_ACCEPT * atol {
                        // A step forced through at MAX_STEPS (extreme
                        // inputs, where the tolerance is not held): neither
                        // it nor its interpolant is trusted, the stress
                        // goes onto the cap at the step's start.
                        z
                    } else if t >= 1.0 {
                        add(&mut q, &stp.dq);
                        p = p1;
                        stp.u
                    } else if t > 0.0 {
                        // The state and the sums at the entry from the
                        // step's Hermite interpolants (the sums' slopes are
                        // their integrands fq) instead of the step repeated
                        // up to it: m −4 % time, worst error/tol on 2000
                        // random cases 0.60 / 0.51 → 0.59 / 0.54 at tol
                        // 1e-3 / 1e-4 (docs/decisions/0076).
                        let hs = t * h1;
                        // With gy ≠ 1 the interpolated entry is checked
                        // against the step taken up to it: on a long stiff
                        // step the Hermite interpolant of Z can bulge out
                        // to the cap where the stress stays well inside it
                        // (the step is then retaken at half its length).
                        // With gy = 1 such an entry meets an empty cap,
                        // which retakes the step below.
                        if st.gy != 1.0
                            && retries < ENTRY_RETRIES
                            && !entry_holds(&inter, p, hs, &z, (&ev0, &jac))
                        {
                            p = p_start;
                            q = q_start;
                            mode = Mode::Interior(z);
                            retries += 1;
                            h = 0.5 * h1;
                            continue;
                        }
                        let mut dq = [0.0; 3];
                        for i in 0..3 {
                            dq[i] = hermite(0.0, ev0.fq[i], stp.dq[i], ev1.fq[i], h1, t);
                        }
                        add(&mut q, &dq);
                        p = p.advance(hs);
                        [
                            hermite(z[0], ev0.f[0], stp.u[0], ev1.f[0], h1, t),
                            hermite(z[1], ev0.f[1], stp.u[1], ev1.f[1], h1, t),
                        ]
                    } else {
                        z
                    };
                    // The cap's angle is counted from the entry direction
                    // n0 = Z/|Z| (only angle differences enter the cap's
                    // equations): no atan2 and sin_cos per entry.
                    let rs = (zs[0] * zs[0] + zs[1] * zs[1]).sqrt();
                    let n0 = if rs > 0.0 {
                        (zs[0] / rs, zs[1] / rs)
                    } else {
                        // At the inlet (Z = 0): the direction of (a, b1).
                        let eb = (st.a * st.a + st.b1 * st.b1).sqrt();
                        if eb > 0.0 {
                            (st.a / eb, st.b1 / eb)
                        } else {
                            (1.0, 0.0)
                        }
                    };
                    switches += 1;
                    if st.gy == 1.0 {
                        // The elastic/plastic flow to the outlet or to where
                        // the stress leaves the cap.
                        let (dq, end) = cap_segment(st, p, n0, switches < MAX_SWITCH);
                        // A new interior segment follows an exit.
                        nsamples = 0;
                        add(&mut q, &dq);
                        match end {
                            None => break,
                            // The cap ended where it began: at the entry the
                            // stress cannot stay on the cap, which the
                            // interior step's entry and its direction decide
                            // where the viscous rate nearly balances the
                            // slip (a short step locates them better).
                            Some((pu, _))
                                if pu.s - p.s <= EMPTY_CAP * h1 && retries < ENTRY_RETRIES =>
                            {
                                p = p_start;
                                q = q_start;
                                mode = Mode::Interior(z);
                                switches -= 1;
                                retries += 1;
                                h = 0.5 * h1;
                                continue;
                            }
                            Some((pu, zu)) => {
                                p = pu;
                                mode = Mode::Interior(zu);
                                switches += 1;
                            }
                        }
                    } else {
                        mode = Mode::Cap(0.0, n0);
                        nsamples = 0;
                    }
                } else {
                    add(&mut q, &stp.dq);
                    p = p1;
                    mode = Mode::Interior(stp.u);
                    if with_margin && l1 > 0.0 {
                        samples = [samples[1], samples[2], (p1.s, 1.0 - r1 / l1)];
                        nsamples += 1;
                        if nsamples >= 3
                            && samples[1].1 < samples[0].1
                            && samples[1].1 < samples[2].1
                        {
                            margin = margin.min(parabola_min(samples));
                        }
                    }
                }
                h = h1 * factor(stp.err, atol);
            }
            Mode::Cap(th, n0) => {
                let u = [th];
                let cap = Cap::new(st, th, n0);
                let (ev0, jac) = cap.eval_jac(p, &u);
                let (stp, h1) = accepted_step(&cap, p, h, &u, (&ev0, &jac), atol, &mut steps);
                let last = last && h1 == hmax;
                let p1 = end_point(stp.p1, last);
                let lam1 = if switches < MAX_SWITCH && !last {
                    if psi_c.is_nan() {
                        psi_c = st.law.psi(1.5 * st.c);
                    }
                    cap.unload_sign(p1, stp.u[0], psi_c)
                } else {
                    0.0
                };
                if lam1 < 0.0 {
                    let ev1 = cap.eval(p1, &stp.u);
                    // −λ̃ along the interpolated θ changes sign at unloading.
                    let g = |t: f64| {
                        let th = hermite(th, ev0.f[0], stp.u[0], ev1.f[0], h1, t);
                        -cap.unload(p.advance(t * h1), th)
                    };
                    let t = event(g, -lam1);
                    let ths = if t >= 1.0 {
                        add(&mut q, &stp.dq);
                        p = p1;
                        stp.u[0]
                    } else if t > 0.0 {
                        let hs = t * h1;
                        let e = ros_step(&cap, p, hs, &u, &ev0, &jac);
                        add(&mut q, &e.dq);
                        p = e.p1;
                        e.u[0]
                    } else {
                        th
                    };
                    let l = lcap(p.sn);
                    let (cx, sy) = cap.n(ths);
                    mode = Mode::Interior([l * cx, l * sy]);
                    switches += 1;
                } else {
                    add(&mut q, &stp.dq);
                    p = p1;
                    mode = Mode::Cap(stp.u[0], cap.n(stp.u[0]));
                }
                h = h1 * factor(stp.err, atol);
            }
        }
        if h.is_nan() || h <= 0.0 || h.is_infinite() {
            h = 1e-3;
        }
    }
    // Strips and step attempts, counted for the random scans' cost figures.
    #[cfg(test)]
    COUNT.with(|c| {
        let (a, b) = c.get();
        c.set((a + 1, b + steps));
    });
    (q, switches as u32, margin)
}

#[cfg(test)]
thread_local! {
    /// (strips, step attempts) integrated by [`strip_sums`] on this thread.
    pub(crate) static COUNT: std::cell::Cell<(usize, usize)> = const { std::cell::Cell::new((0, 0)) };
}
