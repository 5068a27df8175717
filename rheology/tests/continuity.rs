//! Continuity of the elastic/plastic outputs in the inputs: across J3 = 0
//! (the zero-spin closed form against the integrator) and along lines in
//! J space (no jumps from discretisation choices).
#![allow(clippy::unwrap_used)] // functions outside #[test] fns too: a failed unwrap is a failed test

mod common;

use traction_rheology::reference::elastic_plastic;
use traction_rheology::{Accuracy, Inputs, Model, Outputs, Resolution, evaluate};

/// max(|ΔJ4|, |ΔJ5|, |ΔJ6|).
fn dev(a: &Outputs, b: &Outputs) -> f64 {
    (a.j4 - b.j4)
        .abs()
        .max((a.j5 - b.j5).abs())
        .max((a.j6 - b.j6).abs())
}

fn ev(i: &Inputs, tol: f64) -> Outputs {
    evaluate(i, Model::ElasticPlastic, Accuracy::new(tol).unwrap()).unwrap()
}

#[test]
fn spin_moment_is_continuous_at_zero_spin() {
    // With side slip and no spin the lateral traction's centre lies behind the
    // contact centre: J6 = J2/(4k(1+S²)²) (closed::combined_slip_torque),
    // plus ΔX·J5/√k about the spin pole. Against (a) the evaluation at
    // J3 = ±1e-9 (the integrator; J6 changes by O(1e-9) there) at tol 1e-6,
    // and (b) the fixed-resolution strip integrator at J3 = 0 itself
    // (independent of the closed form: 40 panels × 8 points, h = 0.01,
    // converged to ≈ 1e-7, see tests/convergence.rs): 2e-6 each.
    let tol = 1e-6;
    let res = Resolution {
        y_panels: 40,
        y_points: 8,
        s_step: 0.01,
    };
    for &k in &[0.05, 0.2, 0.5, 1.0, 3.0, 20.0] {
        for &(j1, j2, dx) in &[
            (0.0, 1.0, 0.0),
            (0.7, -0.4, 0.0),
            (-2.0, 3.0, 0.0),
            (0.3, 0.2, 0.25),
            (5.0, -8.0, -0.1),
        ] {
            let at = |j3: f64| ev(&Inputs::with_offset(k, j1, j2, j3, dx).unwrap(), tol);
            let zero = at(0.0);
            for j3 in [1e-9, -1e-9] {
                let o = at(j3);
                let d = dev(&o, &zero);
                assert!(
                    d < 2e-6,
                    "k={k} J=({j1},{j2},{j3}) dX={dx}: {o:?} vs {zero:?}"
                );
            }
            let r =
                elastic_plastic(&Inputs::with_offset(k, j1, j2, 0.0, dx).unwrap(), &res).unwrap();
            assert!(
                (r.j6 - zero.j6).abs() < 2e-6,
                "k={k} J=({j1},{j2},0) dX={dx}: integrator J6 {} vs {}",
                r.j6,
                zero.j6
            );
        }
    }
    // The figure of the defect report: k = 0.5, J = (0, 1, 0).
    let o = ev(&Inputs::new(0.5, 0.0, 1.0, 0.0).unwrap(), 1e-4);
    assert!((o.j6 - 0.140_14).abs() < 1e-5, "{}", o.j6);
}

#[test]
fn spin_moment_has_no_jump_at_zero_spin_at_working_tolerances() {
    // Across J3 = 0 the zero-spin closed form meets the integrator: at each
    // working tolerance the step |Δ| from J3 = 0 to J3 = ±1e-9 is the
    // integrator's error there, and must stay below tol/10 (smooth outputs
    // for finite-difference Jacobians). Worst at small k and large side
    // slip, where the strips are plastic almost from the inlet and the
    // moment ∫Zy·X dX, a small difference of large parts, is weighed by
    // 1/(π√k) in J6: with Simpson's rule for the strip sums over the
    // exponential steps (up to 0.8 rad) the step was 0.985·tol at k = 0.063,
    // J = (0, 3.85, ±1e-9), tol 1e-3 (J6); with the 3-point Gauss rule
    // (`Strip::etd`) ≤ 0.01·tol over this grid (k = 1, J2 = −6, tol 1e-4).
    for tol in [1e-2, 1e-3, 1e-4] {
        for &k in &[0.063, 0.1, 0.3, 1.0] {
            for &(j1, j2) in &[(0.0, 3.85), (0.0, -6.0), (2e-3, 10.0), (0.5, 4.0)] {
                let at = |j3: f64| ev(&Inputs::new(k, j1, j2, j3).unwrap(), tol);
                let zero = at(0.0);
                for j3 in [1e-9, -1e-9] {
                    let o = at(j3);
                    let d = dev(&o, &zero);
                    assert!(
                        d < 0.1 * tol,
                        "tol {tol:e} k={k} J=({j1},{j2},{j3}): step {d:.2e}, {o:?} vs {zero:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn half_contact_without_longitudinal_slip_matches_full_integration() {
    // J1 = 0: `evaluate` integrates only Y ≥ 0 and mirrors (J4 = 0, J5 and J6
    // doubled). At J1 = ±1e-15 the whole contact is integrated, with the same
    // panel decisions (mirrored panels give the same change). The two differ
    // only by round-off and by the strip integrator's discrete choices (step
    // counts, the start of unloading) under a change of J1 by 1e-15: measured
    // ≤ 5e-16 on every case here. Bound tol/100, far above that, while a
    // wrong parity or factor shows as O(0.1). Spin from slip-dominated to
    // high, with ΔX and gy ≠ 1.
    for &(k, j2, j3, dx, gy) in &[
        (5.0, 3.368, 25.816, 0.0, 1.0),
        (1.0, 0.96, 2.28, 0.0, 1.0),
        (0.2, -1.5, 8.0, 0.1, 1.0),
        (2.0, 0.5, -12.0, -0.2, 1.0),
        (1.0, 2.0, 5.0, 0.0, 3.0),
        (0.5, 0.0, 4.0, 0.0, 0.5),
    ] {
        for tol in [1e-3, 1e-4] {
            let at = |j1: f64| {
                let i = Inputs::with_offset(k, j1, j2, j3, dx)
                    .unwrap()
                    .with_stiffness_ratio(gy)
                    .unwrap();
                ev(&i, tol)
            };
            let zero = at(0.0);
            assert_eq!(zero.j4, 0.0);
            for j1 in [1e-15, -1e-15] {
                let o = at(j1);
                let d = dev(&o, &zero);
                println!("k={k} J2={j2} J3={j3} tol={tol:e} J1={j1:e}: {d:.2e}");
                assert!(
                    d < tol / 100.0,
                    "k={k} J=({j1},{j2},{j3}) dX={dx} gy={gy} tol={tol}: {d:e}"
                );
            }
        }
    }
}

#[test]
fn outputs_without_side_slip_are_continuous_at_round_off() {
    // Lines without side slip (J2 = 0, ΔX = 0): the two contacts of a
    // toroidal variator's roller at 1 % creep along the roller speed (J1 and
    // J3 move together), 400 points 4–5e-10 of J1 apart, tol 1e-4. The spin
    // pole's strip (an edge of the initial panels) has a = a0 − J3·Y = 0 up
    // to an ulp of a0 there, and on the second line it stays elastic to the
    // outlet with Z(c) = 0 (a root of the yield quartic at the outlet).
    // Its a left as 0 or ± an ulp at random moved J4..J6 up and down by up
    // to 1.1e-9 (first line; second differences 1.07e-9), and its yield
    // point iterated to either side of the outlet's threshold at random
    // (the Halley search before its outlet test) flipped its flow topology
    // and the panels' decisions with it (second line: 1.8e-6): steps that a
    // root solve on the outputs cannot pass (the variator's roller balance
    // asks for 1e-12 of the torques). A smooth stretch gives |f''|·h² ≈
    // 1e-18 plus the round-off of J4..J6, ≈ 1e-15; measured ≤ 2.2e-15,
    // bound 1e-12 (docs/decisions/0089).
    let lines = [
        (
            2.4832747188477615,
            [5.046280358842363, 0.0, -8.574996126138311],
            [-1.0, 0.0, 0.023],
            4.64e-10,
        ),
        (
            1.9399750125524438,
            [-3.818647161930821, 0.0, -4.971429718088984],
            [-1.0, 0.0, 0.0213],
            4.10e-10,
        ),
    ];
    for (k, p, d, h) in lines {
        let m = common::max_second_difference(k, p, d, h, 400, 1e-4);
        println!("k = {k}, from {p:?}: max |Δ²| = {m:.2e}");
        assert!(m <= 1e-12, "k = {k} {p:?}: {m:.3e}");
    }
}
