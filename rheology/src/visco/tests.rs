//! The viscoelastic solver against exact strip solutions, the exact
//! linear Maxwell contact at zero spin, and the former uniform scheme
//! refined and Richardson-extrapolated (an independent integrator).

use super::segments::Cap;
use super::*;
use crate::{Inputs, Resolution};

/// The cap's plastic steps for the strip error `atol` (the contact's
/// tol = atol/STRIP_TOL).
fn steps_for(atol: f64) -> (f64, f64, f64, bool) {
    crate::plastic_steps(atol / STRIP_TOL)
}

fn strip(c: f64, a: f64, b1: f64, d: f64, atol: f64) -> VStrip {
    VStrip {
        c,
        a,
        b1,
        q2: 0.0,
        gy: 1.0,
        law: Law::new(f64::INFINITY, d),
        steps: steps_for(atol),
    }
}

fn max_dev(a: (f64, f64, f64), b: (f64, f64, f64)) -> f64 {
    (a.0 - b.0)
        .abs()
        .max((a.1 - b.1).abs())
        .max((a.2 - b.2).abs())
}

#[test]
fn strip_matches_the_maxwell_closed_form() {
    // Linear Maxwell fluid, zero spin: relaxation from the inlet, then the
    // cap to the outlet (`reference::maxwell_strip`, exact to round-off).
    // The step error is controlled per step (order-3 estimate of the
    // order-4 solution); these strips cover slow (D = 1) and stiff
    // (D = 0.01) relaxation, early and late cap entry; asserted ≤ atol
    // (measured ≤ 0.39·atol, at atol 1e-6 for D = 1: the state and the sums
    // at a cap entry are the step's cubic Hermite interpolants, O(h⁴) like
    // the order-3 estimate that sets h; ≤ 0.1·atol with the step repeated
    // up to the entry, docs/decisions/0076).
    let mut worst = 0.0_f64;
    for &(c, a, b1, d) in &[
        (0.8, 1.0, 0.3, 1.0),
        (0.8, 3.0, 1.0, 0.1),
        (0.8, 0.2, 0.0, 0.05),
        (0.5, 1.5, 0.0, 0.01),
        (1.0, 10.0, 2.0, 1.0),
        (0.1, -4.0, 2.0, 0.3),
    ] {
        let ex = reference::maxwell_strip(&strip(c, a, b1, d, 1e-3));
        for atol in [1e-3, 1e-4, 1e-6] {
            let v = strip_sums(&strip(c, a, b1, d, atol), atol);
            let e = (0..3).map(|i| (v[i] - ex[i]).abs()).fold(0.0, f64::max);
            worst = worst.max(e / atol);
            assert!(e <= atol, "c {c} a {a} b1 {b1} D {d} atol {atol}: {e:e}");
        }
    }
    println!("worst strip error/atol: {worst:.3}");
}

#[test]
fn maxwell_contact_at_zero_spin_is_exact() {
    // J4, J5, J6 of the linear Maxwell fluid at zero spin from the exact
    // strips, integrated over φ by 64 panels of 4 Gauss points (the
    // integrand is smooth in φ: the difference to 128 panels is asserted
    // < 1e-10), against the solver at tol = 1e-3 and 1e-4.
    let mut worst = 0.0_f64;
    for &(k, j1, j2, d) in &[
        (1.0, 1.5, 0.3, 1.0),
        (0.2, 0.5, -0.2, 0.01),
        (5.0, 3.0, 1.0, 0.1),
        (1.0, 0.3, 2.0, 100.0),
        (2.0, -2.0, 0.5, 0.3),
    ] {
        let inp = Inputs::new(k, j1, j2, 0.0).unwrap();
        let p = Scaled::of(&inp);
        let law = Law::new(f64::INFINITY, d);
        let r = reference::contact_exact(&p, 64, |y| {
            reference::maxwell_strip(&VStrip::new(p.strip(y), law, steps_for(1e-3)))
        });
        let r2 = reference::contact_exact(&p, 128, |y| {
            reference::maxwell_strip(&VStrip::new(p.strip(y), law, steps_for(1e-3)))
        });
        assert!(max_dev(r, r2) < 1e-10, "{r:?} {r2:?}");
        for tol in [1e-3, 1e-4] {
            let v = solve(&p, law, tol);
            let e = max_dev(v, r);
            worst = worst.max(e / tol);
            assert!(e <= tol, "k {k} J1 {j1} J2 {j2} D {d} tol {tol}: {e:e}");
        }
    }
    println!("worst error/tol against the exact Maxwell contact: {worst:.3}");
}

/// (k, J1, J2, J3, D, Z0, gy, reference panels).
type Case = (f64, f64, f64, f64, f64, f64, f64, usize);

/// The former uniform scheme (`reference::viscoelastic`) with `panels`
/// panels of 8 Gauss points and n, 2n steps per strip, Richardson
/// extrapolated for its first-order cap error.
fn former(inp: &Inputs, d: f64, z0: f64, panels: usize, n: usize) -> (f64, f64, f64) {
    let res = Resolution {
        y_panels: panels,
        y_points: 8,
        s_step: 0.1,
    };
    let a = crate::reference::viscoelastic(inp, d, z0, &res, n).unwrap();
    let b = crate::reference::viscoelastic(inp, d, z0, &res, 2 * n).unwrap();
    (2.0 * b.j4 - a.j4, 2.0 * b.j5 - a.j5, 2.0 * b.j6 - a.j6)
}

#[test]
fn matches_the_former_scheme_refined() {
    // Spread: D 0.01–100, Z0 0.1–∞, k 0.2–5, with and without spin and side
    // slip, gy = 1 and ≠ 1, high spin, and four cases of a random scan that
    // an earlier panel rule or step tolerance got wrong (up to 2.2·tol).
    // The reference (16 panels × 8 points, 32 for k ≈ 4.5–8.6, 64 at high
    // spin; 2000/4000 uniform steps, Richardson) is itself
    // accurate to ≤ 1e-6: against twice the panels and steps it moves by
    // ≤ 7.6e-7 on the first ten cases, and that refined reference agrees
    // with this solver at tol = 1e-8 to ≤ 5.2e-7 (measured once, offline). Asserted:
    // |new − reference| ≤ tol at tol = 1e-3 and 1e-4 (the measured worst
    // error/tol is in the crate README, section Viscoelastic model).
    let cases: [Case; 14] = [
        (1.0, 1.5, 0.3, 2.0, 1.0, 1.0, 1.0, 16),
        (4.5114, 0.1579, -1.8817, -5.6749, 0.1668, 2.503, 1.0, 32),
        (
            8.5173,
            -2.2895,
            -1.7589,
            -5.0226,
            0.0794,
            f64::INFINITY,
            1.0,
            32,
        ),
        (8.6045, 0.2631, -2.8225, -5.6749, 0.1668, 2.503, 1.0, 32),
        (
            0.2753,
            1.7451,
            -0.3493,
            -2.2796,
            10.44,
            f64::INFINITY,
            2.3467,
            16,
        ),
        (1.0, 1.0, 0.0, 0.0, 0.1, 0.1, 1.0, 16),
        (0.5, 2.0, -1.0, 10.0, 0.01, 0.1, 1.0, 16),
        (2.0, 3.0, 0.5, 1.0, 100.0, 0.3, 2.0, 16),
        (0.2, 0.5, 0.2, 0.8, 0.3, f64::INFINITY, 1.0, 16),
        (5.0, 1.0, -0.5, 3.0, 3.0, 2.0, 0.5, 16),
        (1.0, 0.4, 0.1, -1.5, 0.05, 1.0, 1.0, 16),
        (3.0, -2.0, 1.0, 4.0, 1.0, 0.5, 3.0, 16),
        (1.0, 4.0, 2.0, 0.0, 1.0, 1.0, 2.0, 16),
        (5.0, 0.0, 3.368, 25.816, 1.0, 1.0, 1.0, 64),
    ];
    let mut worst = (0.0_f64, String::new());
    for &(k, j1, j2, j3, d, z0, gy, panels) in &cases {
        let inp = Inputs::new(k, j1, j2, j3)
            .unwrap()
            .with_stiffness_ratio(gy)
            .unwrap();
        let r = former(&inp, d, z0, panels, 2000);
        let p = Scaled::of(&inp);
        let law = Law::new(z0, d);
        for tol in [1e-3, 1e-4] {
            let v = solve(&p, law, tol);
            let e = max_dev(v, r);
            let case = format!("k {k} J ({j1}, {j2}, {j3}) D {d} Z0 {z0} gy {gy} tol {tol}");
            if e / tol > worst.0 {
                worst = (e / tol, case.clone());
            }
            assert!(e <= tol, "{case}: {e:e}");
        }
    }
    println!(
        "worst error/tol against the former scheme: {:.3} ({})",
        worst.0, worst.1
    );
}

#[test]
fn large_inputs_terminate_finite() {
    // |J| = 1e9 and 1e13 with a viscous rate too large for the
    // rigid/plastic shortcut (ψ(3/2) ≈ 1e63 and 3e11) are integrated:
    // finite, bounded (0.3 s and 16 ms).
    for &(m, d, z0) in &[(1e9, 0.01, 0.01), (1e13, 1.0, 0.05)] {
        let inp = Inputs::new(1.0, m, -0.5 * m, 2.0 * m).unwrap();
        let o = crate::evaluate(
            &inp,
            crate::Model::Viscoelastic { deborah: d, z0 },
            crate::Accuracy::new(1e-3).unwrap(),
        )
        .unwrap();
        assert!(
            o.j4.is_finite() && o.j5.is_finite() && o.j6.is_finite(),
            "{o:?}"
        );
        assert!(o.j4.hypot(o.j5) <= 1.0 + 1e-6, "{o:?}");
    }
}

#[test]
fn large_deborah_is_the_elastic_plastic_model() {
    // D → ∞: the viscous rate ψ ≤ Z0·sinh(1.5/Z0)/D ≈ 2e-6 at D = 1e6 moves
    // the forces by O(1e-6); asserted |visco − elastic/plastic(1e-6)| ≤
    // tol + 1e-5 at tol = 1e-3, 1e-4 (the cap segments follow the
    // elastic/plastic flow exactly).
    for &(k, j1, j2, j3, gy) in &[
        (1.0, 1.5, 0.3, 2.0, 1.0),
        (5.0, 0.0, 3.368, 25.816, 1.0),
        (0.5, 2.0, -1.0, 10.0, 2.0),
    ] {
        let inp = Inputs::new(k, j1, j2, j3)
            .unwrap()
            .with_stiffness_ratio(gy)
            .unwrap();
        let ep = crate::evaluate(
            &inp,
            crate::Model::ElasticPlastic,
            crate::Accuracy::new(1e-6).unwrap(),
        )
        .unwrap();
        for tol in [1e-3, 1e-4] {
            let v = solve(&Scaled::of(&inp), Law::new(1.0, 1e6), tol);
            let e = max_dev(v, (ep.j4, ep.j5, ep.j6));
            assert!(
                e <= tol + 1e-5,
                "k {k} J ({j1}, {j2}, {j3}) gy {gy} tol {tol}: {e:e}"
            );
        }
    }
}

/// `n` random inputs over the model's working range (k 0.1–10, |J1| ≤ 5,
/// |J2| ≤ 3, |J3| ≤ 30, D 0.01–100, Z0 0.1–10 or ∞, a quarter with gy 0.3–3;
/// log-uniform where the range spans decades) from `seed`, the solver at
/// tol = 1e-3 and 1e-4 against itself at tol = 1e-8 (a convergence check:
/// the independent references are the tests above): the worst error/tol and
/// its case at each tolerance, printed and asserted ≤ 1, with the strips and
/// step attempts taken at that tolerance (the cost, free of machine load).
fn random_scan(seed: u64, n: usize) {
    random_scan_against(seed, n, 1e-8);
}

/// [`random_scan`] against the solver at `tol_ref`.
fn random_scan_against(seed: u64, n: usize, tol_ref: f64) {
    let mut state: u64 = seed;
    let mut uniform = || {
        // xorshift64*.
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        (state.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut worst = [(0.0_f64, String::new()), (0.0, String::new())];
    let mut cnt = [(0usize, 0usize); 2];
    for _ in 0..n {
        let k = 10f64.powf(2.0 * uniform() - 1.0);
        let j1 = 10.0 * uniform() - 5.0;
        let j2 = 6.0 * uniform() - 3.0;
        let j3 = 60.0 * uniform() - 30.0;
        let d = 10f64.powf(4.0 * uniform() - 2.0);
        let z0 = if uniform() < 0.2 {
            f64::INFINITY
        } else {
            10f64.powf(2.0 * uniform() - 1.0)
        };
        let gy = if uniform() < 0.25 {
            0.3 * 10f64.powf(uniform())
        } else {
            1.0
        };
        let inp = Inputs::new(k, j1, j2, j3)
            .unwrap()
            .with_stiffness_ratio(gy)
            .unwrap();
        let p = Scaled::of(&inp);
        let law = Law::new(z0, d);
        let r = solve(&p, law, tol_ref);
        for (i, tol) in [1e-3, 1e-4].into_iter().enumerate() {
            let c0 = super::strip::COUNT.with(|c| c.get());
            let v = solve(&p, law, tol);
            let c1 = super::strip::COUNT.with(|c| c.get());
            cnt[i].0 += c1.0 - c0.0;
            cnt[i].1 += c1.1 - c0.1;
            let e = max_dev(v, r) / tol;
            if e > worst[i].0 {
                worst[i] = (
                    e,
                    format!(
                        "k {k:.4} J ({j1:.4}, {j2:.4}, {j3:.4}) D {d:.4} Z0 {z0:.4} gy {gy:.4}"
                    ),
                );
            }
        }
    }
    for (i, tol) in [1e-3, 1e-4].into_iter().enumerate() {
        println!(
            "seed {seed:#x}, {n} cases, tol {tol:e}: worst error/tol {:.3} ({}) strips {} steps {}",
            worst[i].0, worst[i].1, cnt[i].0, cnt[i].1
        );
        assert!(worst[i].0 <= 1.0);
    }
}

#[test]
#[ignore = "400 random cases at two tolerances against tol = 1e-8, about 20 s: \
            cargo test -p traction-rheology --lib random_scan -- --ignored --nocapture"]
fn random_scan_against_a_tight_tolerance() {
    // This scan found the panels accepted by chance agreement
    // (docs/decisions/0045).
    random_scan(0x9e37_79b9_7f4a_7c15, 400);
}

#[test]
#[ignore = "2100 random cases of two more seeds, about 2 min: \
            cargo test -p traction-rheology --lib random_scan -- --ignored --nocapture"]
fn random_scan_more_seeds() {
    // With the first seed's 400, the 2500 cases of the crate README's
    // worst error/tol (docs/decisions/0077).
    random_scan(0x1234_5678_9abc_def1, 600);
    random_scan(0xdead_beef_cafe_f00d, 1500);
}

#[test]
#[ignore = "2000 random cases of a fourth seed against tol = 1e-7, about 2 min: \
            cargo test -p traction-rheology --release --lib random_scan -- --ignored --nocapture"]
fn random_scan_fourth_seed() {
    // A seed none of the step or panel rules was tuned on
    // (docs/decisions/0076).
    random_scan_against(0x5851_f42d_4c95_7f2d, 2000, 1e-7);
}

#[test]
#[ignore = "2000 random cases of a fifth seed against tol = 1e-7, about 2 min: \
            cargo test -p traction-rheology --release --lib random_scan -- --ignored --nocapture"]
fn random_scan_fifth_seed() {
    // A seed that checked the panel rule of docs/decisions/0084 (none of
    // the rules' constants was chosen on it). Fresh seeds: set
    // TRACTION_SCAN_SEEDS (`traction_testkit::scan_seeds`).
    for seed in traction_testkit::scan_seeds(&[0x2466_b1f6_c6c7_10f2]) {
        random_scan_against(seed, 2000, 1e-7);
    }
}

#[test]
fn half_contact_at_zero_longitudinal_slip_is_continuous() {
    // J1 = 0 integrates Y ≥ 0 only (the strips at ±Y are mirror images);
    // J1 = ±1e-13 integrates the whole contact. A differing panel or step
    // decision would show as a jump of order tol·1e-3 or more; measured
    // ≤ 5e-11 (k = 0.5, gy = 2: the outputs' own slope in J1 times 1e-13
    // is below that), asserted ≤ 1e-9.
    for &(k, j2, j3, d, z0, gy) in &[
        (5.0, 3.368, 25.816, 1.0, 1.0, 1.0),
        (0.5, -1.0, 10.0, 1.0, 0.5, 2.0),
        (2.0, 1.0, 0.0, 0.3, f64::INFINITY, 1.5),
    ] {
        let at = |j1: f64| {
            let inp = Inputs::new(k, j1, j2, j3)
                .unwrap()
                .with_stiffness_ratio(gy)
                .unwrap();
            solve(&Scaled::of(&inp), Law::new(z0, d), 1e-3)
        };
        let v0 = at(0.0);
        assert_eq!(v0.0, 0.0);
        for j1 in [1e-13, -1e-13] {
            let e = max_dev(v0, at(j1));
            assert!(e <= 1e-9, "k {k} J3 {j3} gy {gy} J1 {j1}: {e:e}");
        }
    }
}

/// A line in J space: (k, start J, direction, points, D, Z0, gy).
type Line = (f64, [f64; 3], [f64; 3], usize, f64, f64, f64);

#[test]
fn no_tolerance_driven_jumps() {
    // Second differences of J4, J5, J6 at a spacing of 1e-4 in J (as
    // rheology/tests/smoothness.rs does for the elastic/plastic model): a
    // smooth stretch contributes |f''|·1e-8, a jump of the discretisation
    // (a panel or step decision) its full size. The step sequence along
    // the strips changes discretely with the inputs, so jumps are not
    // excluded by construction; lines through the moderate-spin case, near
    // the spin pole at k = 0.2 (Maxwell fluid), and the anisotropic bench
    // case g at tol = 1e-3: measured ≤ 0.0021·tol, asserted ≤ tol/10.
    let tol = 1e-3;
    let lines: [Line; 3] = [
        (1.0, [1.3, 0.3, 2.0], [1.0, 0.0, 0.0], 400, 1.0, 1.0, 1.0),
        (
            0.2,
            [0.11, 0.08, 0.70],
            [0.3, 0.2, 1.0],
            400,
            0.3,
            f64::INFINITY,
            1.0,
        ),
        (0.5, [2.0, -1.0, 10.0], [0.3, 0.2, 1.0], 300, 1.0, 0.5, 2.0),
    ];
    for (k, p, d, n, de, z0, gy) in lines {
        let v: Vec<(f64, f64, f64)> = (0..n)
            .map(|i| {
                let s = i as f64 * 1e-4;
                let inp = Inputs::new(k, p[0] + s * d[0], p[1] + s * d[1], p[2] + s * d[2])
                    .unwrap()
                    .with_stiffness_ratio(gy)
                    .unwrap();
                solve(&Scaled::of(&inp), Law::new(z0, de), tol)
            })
            .collect();
        let mut m: f64 = 0.0;
        for w in v.windows(3) {
            let d2 = (
                w[2].0 - 2.0 * w[1].0 + w[0].0,
                w[2].1 - 2.0 * w[1].1 + w[0].1,
                w[2].2 - 2.0 * w[1].2 + w[0].2,
            );
            m = m.max(max_dev(d2, (0.0, 0.0, 0.0)));
        }
        println!(
            "k = {k}, from {p:?} along {d:?}: max |Δ²| = {:.4}·tol",
            m / tol
        );
        assert!(m <= 0.1 * tol, "k = {k} {p:?}: {m:.3e}");
    }
}

#[test]
fn cap_rate_derivatives_match_central_differences() {
    // The exact ∂/∂θ and ∂/∂σ of the cap's direction rate (gy ≠ 1) against
    // central differences (step 1e-5: truncation ≈ 1e-10·|f‴|, round-off
    // ≈ 1e-11/1e-5); asserted within 1e-6·(1 + |value|), on both sides of
    // the capped sin σ.
    for &(gy, a, b1, q2) in &[(2.0, 1.3, -0.4, 0.7), (0.4, -2.0, 1.1, -3.0)] {
        let st = VStrip {
            c: 0.8,
            a,
            b1,
            q2,
            gy,
            law: Law::new(1.0, 1.0),
            steps: steps_for(1e-3),
        };
        let cap = Cap::new(&st, 0.0, (1.0, 0.0));
        for &(s, th) in &[
            (0.3_f64, 0.4_f64),
            (1.2, -2.0),
            (2.5, 2.9),
            (3.13, 1.0),
            (0.01, -0.7),
        ] {
            let f = |s: f64, th: f64| cap.rate(s.sin(), s.cos(), th.cos(), th.sin());
            let (dth, dsg) = cap.rate_derivatives(s.sin(), s.cos(), th.cos(), th.sin());
            let d = 1e-5;
            let nth = (f(s, th + d) - f(s, th - d)) / (2.0 * d);
            let nsg = (f(s + d, th) - f(s - d, th)) / (2.0 * d);
            assert!(
                (dth - nth).abs() <= 1e-6 * (1.0 + nth.abs()),
                "θ: {dth} {nth}"
            );
            assert!(
                (dsg - nsg).abs() <= 1e-6 * (1.0 + nsg.abs()),
                "σ: {dsg} {nsg}"
            );
        }
    }
}

#[test]
#[ignore = "the six bench cases against tol = 1e-9, a few seconds: \
            cargo test -p traction-rheology --lib bench_cases -- --ignored --nocapture"]
fn bench_cases_against_a_tight_tolerance() {
    // The cases of `cargo xtask prof-visco` at tol 1e-3 and 1e-4 against
    // the solver at tol = 1e-9 (a convergence check, as the random scans);
    // asserted ≤ tol, the worst error/tol printed.
    for tol in [1e-3, 1e-4] {
        let mut worst = (0.0_f64, "");
        for c in traction_testkit::bench_cases::VISCOELASTIC.iter() {
            let inp = Inputs::new(c.k, c.j[0], c.j[1], c.j[2])
                .unwrap()
                .with_stiffness_ratio(c.gy)
                .unwrap();
            let p = Scaled::of(&inp);
            let law = Law::new(c.z0, c.deborah);
            let e = max_dev(solve(&p, law, tol), solve(&p, law, 1e-9)) / tol;
            if e > worst.0 {
                worst = (e, c.letter);
            }
            assert!(e <= 1.0, "{} tol {tol:e}: {e:.3}", c.letter);
        }
        println!(
            "bench cases, tol {tol:e}: worst error/tol {:.3} ({})",
            worst.0, worst.1
        );
    }
}

#[test]
fn small_k_strip_errors_are_weighed_for_the_spin_torque() {
    // J6 divides the strips' moments by π√k: with the strips' step error at
    // 2·tol alone these small-k cases were off by 1.20·tol (tol 1e-3) and
    // 1.25·tol (tol 1e-2) in J6; with it scaled by √k, 0.25 and 0.14.
    // Against tol 1e-7 (itself within ≈ 1e-7), each within tol/2.
    let cases = [
        (0.114, [-0.0367, -0.00261, -0.0162], 0.84, 1.47, 1e-3),
        (
            0.0935,
            [1.711e-5, 6.196e-6, -0.1269],
            0.415,
            f64::INFINITY,
            1e-2,
        ),
    ];
    for (k, j, d, z0, tol) in cases {
        let p = Scaled::of(&Inputs::new(k, j[0], j[1], j[2]).unwrap());
        let law = Law::new(z0, d);
        let e = max_dev(solve(&p, law, tol), solve(&p, law, 1e-7)) / tol;
        println!("k = {k}, J = {j:?}, D = {d}, Z0 = {z0}: error/tol {e:.3} at tol {tol:e}");
        assert!(e <= 0.5, "{e}");
    }
}

#[test]
fn kink_panels_are_not_accepted_by_their_halves_lobatto_values() {
    // Large side slip at small D: in the middle of the contact the stress
    // rides at the viscous equilibrium below the cap and the strips leave it
    // (entry, unloading, re-entry), towards the edges they stay on it once
    // they reach it; the strip sums have a kink in Y between (φ ≈ 0.66 at
    // k = 1.57). The refined panel holding it had its halves accepted on
    // the sum of their Lobatto values against its Kronrod value (0.81 of
    // the allowed change), both off at the kink: J5 was 1.07·tol off at
    // tol 1e-4 (1.03·tol at k = 9.7). Such panels are now refined: measured
    // 0.026 and 0.013·tol. Bound 0.25·tol, against tol 1e-8.
    for (k, j2, d, z0) in [
        (1.569, 16.122, 0.1682, 0.594),
        (9.727, 34.716, 0.1885, 0.612),
    ] {
        let p = Scaled::of(&Inputs::new(k, 0.0, j2, 0.0).unwrap());
        let law = Law::new(z0, d);
        let r = solve(&p, law, 1e-8);
        for tol in [1e-3, 1e-4] {
            let e = max_dev(solve(&p, law, tol), r) / tol;
            assert!(e < 0.25, "k = {k}, tol {tol:e}: error/tol {e:.3}");
        }
    }
}

#[test]
fn the_initial_panels_slack_keeps_the_sum_of_allowed_changes() {
    // Five initial panels of an integrand smooth but for a steep step in
    // the second: the panels within their allowed change give half of what
    // they leave unused to the panels beyond theirs, in proportion to the
    // excess; the allowed changes' sum grows by exactly that half, and no
    // panel's allowed change shrinks.
    let node = |phi: f64| Node {
        v: [
            phi.cos(),
            (40.0 * (phi + 0.8)).tanh(),
            0.3 * phi * phi,
            (8.0 * phi).sin() * 1e-3,
        ],
        topology: Some(1),
        margin: (),
    };
    let breaks = [-1.5, -1.0, -0.5, 0.1, 0.7, 1.5];
    let mut panels: Vec<Panel<()>> = breaks
        .windows(2)
        .map(|w| {
            let (m, hw) = (0.5 * (w[0] + w[1]), 0.5 * (w[1] - w[0]));
            Panel {
                lo: w[0],
                hi: w[1],
                fl: node(w[0]),
                fh: node(w[1]),
                depth: 0,
                weight: 1.0,
                known: Known::All(Interior {
                    fm: node(m),
                    fb: (node(m - hw * LOB_B), node(m + hw * LOB_B)),
                    fa: (node(m - hw * KRO_A), node(m + hw * KRO_A)),
                }),
                share: 1.0,
            }
        })
        .collect();
    let (k, dx, tol) = (1.0, 0.0, 1e-3);
    let max_abs = |d: &[f64; 4]| {
        let (e4, e5, e6) = to_j(k, dx, d);
        e4.abs().max(e5.abs()).max(e6.abs())
    };
    // Each panel's allowed change and Lobatto–Kronrod difference, here.
    let ae: Vec<(f64, f64)> = panels
        .iter()
        .map(|p| {
            let Known::All(n) = &p.known else {
                unreachable!()
            };
            let (lob, kv) = lobatto_kronrod(0.5 * (p.hi - p.lo), (&p.fl, &p.fh), n);
            let e = max_abs(&std::array::from_fn(|i| kv[i] - lob[i]));
            (ACCEPT * tol * (p.hi - p.lo) / PI, e)
        })
        .collect();
    let slack: f64 = ae.iter().map(|(a, e)| (a - e).max(0.0)).sum();
    let over = ae.iter().filter(|(a, e)| e > a).count();
    assert!(over >= 1 && over < ae.len() && slack > 0.0, "{ae:?}");
    slack_factors(&mut panels, tol, max_abs);
    let mut added = 0.0;
    for (p, (a, e)) in panels.iter().zip(&ae) {
        assert!(p.share >= 1.0);
        if e <= a {
            assert_eq!(p.share, 1.0);
        }
        added += (p.share - 1.0) * a;
    }
    assert!(
        (added - SLACK_SHARE * slack).abs() <= 1e-12 * slack,
        "{added} {slack}"
    );
}

#[test]
fn the_high_spin_bench_case_takes_its_initial_panels() {
    // Case h at tol 1e-3: its panel at the spin pole's strip holds a kink
    // of the strip sums and would be refined three levels for its own
    // share of the tolerance (54 strips); the outer panels' slack settles
    // it in its initial panels (28 strips), within 0.25·tol of tol 1e-9.
    let inp = Inputs::new(5.0, 0.0, 3.368, 25.816).unwrap();
    let p = Scaled::of(&inp);
    let law = Law::new(1.0, 1.0);
    let c0 = super::strip::COUNT.with(|c| c.get());
    let v = solve(&p, law, 1e-3);
    let strips = super::strip::COUNT.with(|c| c.get()).0 - c0.0;
    let e = max_dev(v, solve(&p, law, 1e-9)) / 1e-3;
    assert!(strips <= 30, "{strips} strips");
    assert!(e <= 0.25, "error/tol {e:.3}");
}

#[test]
fn near_band_share_extrapolates_the_margins_between_nodes() {
    // Seven nodes 0.1 apart. Margins falling linearly to 0 at 0.45 (between
    // the nodes at 0.4 and 0.5): the pair (0.3, 0.4) predicts the zero
    // before the next node, so the whole panel is refined.
    let at = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6];
    let inf = f64::INFINITY;
    let falling = |zero: f64| at.map(|x| if x < zero { zero - x } else { inf });
    assert_eq!(super::near_band_share(&at, &falling(0.45)), 1.0);
    // The same slope with its zero far beyond the panel: no share.
    let far = at.map(|x| 2.0 - x);
    assert_eq!(super::near_band_share(&at, &far), 0.0);
    // Margins that turn up again before any zero predict nothing: each
    // falling pair's next node has a finite margin (with 0.05 + (x − 0.3)²,
    // the pair at 0 and 0.1 alone would give 0.104).
    let bowl = at.map(|x| 0.05 + (x - 0.3) * (x - 0.3));
    assert_eq!(super::near_band_share(&at, &bowl), 0.0);
    // Falling towards nodes without a margin (the band), and its mirror.
    let mut edge = bowl;
    edge[5] = inf;
    edge[6] = inf;
    edge[4] = 0.02;
    assert_eq!(super::near_band_share(&at, &edge), 1.0);
    let mut mirrored = edge;
    mirrored.reverse();
    let at_r = at.map(|x| -x);
    let mut at_m = at_r;
    at_m.reverse();
    assert_eq!(super::near_band_share(&at_m, &mirrored), 1.0);
    // Continuous as the predicted zero moves out past the panel's end
    // (0.6, the last node), over one node spacing.
    let mut last = 1.0;
    for j in 0..=200 {
        let zero = 0.6 + 0.15 * j as f64 / 200.0;
        let s = super::near_band_share(&at, &at.map(|x| zero - x));
        assert!(
            (0.0..=1.0).contains(&s) && s <= last && last - s < 0.03,
            "{zero}: {s}"
        );
        last = s;
    }
    assert_eq!(last, 0.0);
}

#[test]
fn parabola_min_is_the_vertex_of_the_samples_parabola() {
    // d = 0.2 + 3·(s − 0.47)², sampled at uneven points about its vertex.
    let d = |s: f64| 0.2 + 3.0 * (s - 0.47) * (s - 0.47);
    let pts = [0.3, 0.5, 0.8].map(|s| (s, d(s)));
    assert!((super::strip::parabola_min(pts) - 0.2).abs() < 1e-14);
    // Never below 0 nor above the least sample.
    let steep = [(0.0, 1.0), (0.1, 0.01), (0.2, 1.0)];
    let v = super::strip::parabola_min(steep);
    assert!((0.0..=0.01).contains(&v));
}
