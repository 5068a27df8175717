//! Model tests: exact references, limits, symmetries, invariants, errors.
#![allow(clippy::unwrap_used)] // functions outside #[test] fns too: a failed unwrap is a failed test

use std::f64::consts::PI;

use proptest::prelude::*;
use traction_rheology::reference::{elastic_plastic, grid as grid_reference};
use traction_rheology::{
    Accuracy, Inputs, Limit, Model, Modulus, OutOfRange, Outputs, Properties, Resolution,
    RheologyError, closed, evaluate,
};

/// The rigid/plastic model through [`evaluate`].
fn rigid_plastic(i: &Inputs, a: Accuracy) -> Result<Outputs, RheologyError> {
    evaluate(i, Model::RigidPlastic, a)
}

/// The viscoelastic model through [`evaluate`].
fn viscoelastic(i: &Inputs, deborah: f64, z0: f64, a: Accuracy) -> Result<Outputs, RheologyError> {
    evaluate(i, Model::Viscoelastic { deborah, z0 }, a)
}

/// A property variation through [`evaluate`].
fn elastic_plastic_with(i: &Inputs, p: Properties, a: Accuracy) -> Result<Outputs, RheologyError> {
    evaluate(i, Model::PropertyVariation(p), a)
}

fn inp(k: f64, j1: f64, j2: f64, j3: f64) -> Inputs {
    Inputs::new(k, j1, j2, j3).unwrap()
}

/// max(|ΔJ4|, |ΔJ5|, |ΔJ6|).
fn dev(a: &Outputs, b: &Outputs) -> f64 {
    (a.j4 - b.j4)
        .abs()
        .max((a.j5 - b.j5).abs())
        .max((a.j6 - b.j6).abs())
}

fn ep(i: &Inputs, tol: f64) -> Outputs {
    evaluate(i, Model::ElasticPlastic, Accuracy::new(tol).unwrap()).unwrap()
}

#[test]
fn integrator_matches_closed_forms_at_zero_spin() {
    // The strip integrator (no closed-form fast path) against App. V eq. 23
    // for k from 0.2 to 10. The strip integral is c²·F exactly, so the only
    // errors are RK4 in s (O(h⁴), ≈ 1e-9 at h = 0.05) and the Y rule
    // (16 Gauss points of cos³φ, ≈ 1e-15): tolerance 1e-6, far above the quadrature error and far below print precision.
    let res = Resolution {
        y_panels: 2,
        y_points: 8,
        s_step: 0.05,
    };
    for &k in &[0.2, 0.5, 1.0, 2.0, 5.0, 10.0] {
        for &j1 in &[0.0, 0.1, 0.7, 1.5, 4.0, 20.0] {
            for &j2 in &[0.0, 0.5, -2.0] {
                let o = elastic_plastic(&inp(k, j1, j2, 0.0), &res).unwrap();
                let (j4, j5) = closed::combined_slip_traction(k, j1, j2);
                assert!(
                    (o.j4 - j4).abs() < 1e-6 && (o.j5 - j5).abs() < 1e-6,
                    "k={k} {j1} {j2}: {o:?} vs {j4} {j5}"
                );
                if j2 == 0.0 {
                    // Slip only: Zy = 0 and Zx even in Y, so no torque.
                    assert!(o.j6.abs() < 1e-6, "zero-spin torque must vanish: {o:?}");
                }
            }
        }
        // Slip only: eq. 22 itself.
        let o = elastic_plastic(&inp(k, 1.3, 0.0, 0.0), &res).unwrap();
        assert!((o.j4 - closed::slip_traction(k, 1.3)).abs() < 1e-6);
    }
}

#[test]
fn pure_spin_small_j3_is_the_elastic_solution() {
    // Pure spin, elastic everywhere except a thin outlet layer: Zy =
    // J3(X²−c²)/(2k) gives J5 = −J3/(4k) and J6 = −J3/(8k)·(1+k²)... checked
    // here only for J5, whose plastic correction is O(J3³) (the outlet layer
    // where |Zy| > L has width O(J3²)): J3 = 1e-3 → relative 1e-5.
    for &k in &[0.3, 1.0, 4.0] {
        let j3 = 1e-3;
        let o = ep(&inp(k, 0.0, 0.0, j3), 1e-6);
        let exact = -j3 / (4.0 * k);
        assert!(
            (o.j5 / exact - 1.0).abs() < 1e-4,
            "k={k}: {} vs {exact}",
            o.j5
        );
    }
}

#[test]
fn symmetries() {
    // Exact symmetries of the ODE (see crate docs); the same discretisation
    // is applied to mirrored strips, so agreement is to round-off (1e-12).
    let a = Accuracy::new(1e-3).unwrap();
    for &(k, j1, j2, j3, dx) in &[
        (1.0, 1.2, 0.3, 2.5, 0.0),
        (0.3, 0.5, -1.0, 7.0, 0.2),
        (4.0, 3.0, 0.0, 1.0, -0.1),
    ] {
        let o = evaluate(
            &Inputs::with_offset(k, j1, j2, j3, dx).unwrap(),
            Model::ElasticPlastic,
            a,
        )
        .unwrap();
        let n = evaluate(
            &Inputs::with_offset(k, -j1, -j2, -j3, dx).unwrap(),
            Model::ElasticPlastic,
            a,
        )
        .unwrap();
        let m = evaluate(
            &Inputs::with_offset(k, j1, -j2, -j3, dx).unwrap(),
            Model::ElasticPlastic,
            a,
        )
        .unwrap();
        for (x, y) in [
            (o.j4, -n.j4),
            (o.j5, -n.j5),
            (o.j6, -n.j6),
            (o.j7, n.j7),
            (o.j4, m.j4),
            (o.j5, -m.j5),
            (o.j6, -m.j6),
        ] {
            assert!((x - y).abs() < 1e-12, "{o:?} {n:?} {m:?}");
        }
    }
}

#[test]
fn reversed_rolling_frame_from_the_mirrored_slips() {
    // Both symmetries above together: (−J1, −J2, J3) gives (−J4, J5, J6) of
    // (J1, −J2, J3), for every model, stiffness ratio and offset. The
    // contact takes its reversed rolling frame below the rolling-speed
    // floor from it (the forward frame itself without side slip), and
    // evaluates that frame directly from −U_f on, so a defect would be a jump
    // in its forces there. The same discretisation of mirrored strips: 1e-12.
    let a = Accuracy::new(1e-3).unwrap();
    let props = Properties {
        modulus: Modulus::PressureProportional,
        limit: Limit::Constant,
    };
    let models = [
        Model::ElasticPlastic,
        Model::RigidPlastic,
        Model::Viscoelastic {
            deborah: 0.5,
            z0: 1.0,
        },
        Model::PropertyVariation(props),
    ];
    for model in models {
        for &(k, j1, j2, j3, dx, gy) in &[
            (2.0, 1.5, 0.3, -4.0, 0.1, 1.7),
            (0.5, 2.0, -1.0, 10.0, 0.0, 1.0),
            (1.55, 1606.0, 0.7, 14499.0, 0.0, 1.0),
        ] {
            if j3 > 100.0_f64 && !matches!(model, Model::ElasticPlastic) {
                continue;
            }
            let at = |j1: f64, j2: f64| {
                let i = Inputs::with_offset(k, j1, j2, j3, dx)
                    .unwrap()
                    .with_stiffness_ratio(gy)
                    .unwrap();
                evaluate(&i, model, a).unwrap()
            };
            let (rev, mir) = (at(-j1, -j2), at(j1, -j2));
            for (x, y) in [(rev.j4, -mir.j4), (rev.j5, mir.j5), (rev.j6, mir.j6)] {
                assert!((x - y).abs() < 1e-12, "{model:?} {rev:?} {mir:?}");
            }
        }
    }
}

#[test]
fn negative_rolling_direction_is_reversed_spin_in_the_rolling_frame() {
    // App. VI prints the negative rolling direction as J5(0, −J2, J3). In the
    // frame rolling forwards (x' = −x, y' = −y) the spin is −J3 and the side
    // slip J2, and the side force is −Fy'. So J5(0, −J2, J3) = −J5(0, J2, −J3):
    // exact mirror symmetry (1e-12). The printed trace 79072704 (k = 5, J3 =
    // 25.8) then has |J5| larger in the negative direction at the same |J2|,
    // as printed (−.3228 vs +.0456 at |J2| = 3.368).
    let a = 1e-3;
    let (k, j2, j3) = (5.0, 3.36839582, 25.8161723);
    let neg = ep(&inp(k, 0.0, -j2, j3), a);
    let frame = ep(&inp(k, 0.0, j2, -j3), a);
    assert!((neg.j5 + frame.j5).abs() < 1e-12);
    let pos = ep(&inp(k, 0.0, j2, j3), a);
    assert!(
        neg.j5 < 0.0 && neg.j5.abs() > pos.j5.abs(),
        "{pos:?} {neg:?}"
    );
}

#[test]
fn large_j_tends_to_rigid_plastic() {
    // Elastic/plastic at λ·(J1, J2, J3) → rigid/plastic (depends on ratios
    // only); the elastic lag is O(1/λ). Observed: difference shrinks at least
    // 5× per decade of λ and is < 2e-3 at λ = 1e4.
    let a = Accuracy::new(1e-4).unwrap();
    for &(k, j1, j2, j3) in &[
        (1.0, 1.0, 0.0, 1.0),
        (0.5, 0.3, 0.2, 1.0),
        (4.0, 2.0, 0.0, 1.0),
    ] {
        let r = rigid_plastic(&inp(k, j1, j2, j3), Accuracy::new(1e-6).unwrap()).unwrap();
        let mut prev = f64::INFINITY;
        for &l in &[1e2, 1e3, 1e4] {
            let o = evaluate(&inp(k, l * j1, l * j2, l * j3), Model::ElasticPlastic, a).unwrap();
            let d = (o.j4 - r.j4)
                .abs()
                .max((o.j5 - r.j5).abs())
                .max((o.j6 - r.j6).abs());
            println!("k={k} λ={l}: |EP − RP| = {d:.2e}");
            assert!(d < prev / 5.0 || d < 1e-4, "λ={l}: {d} (prev {prev})");
            prev = d;
        }
        assert!(prev < 2e-3);
    }
    // Zero spin: eq. 24 exactly.
    let r = rigid_plastic(&inp(2.0, 3.0, 4.0, 0.0), Accuracy::new(1e-6).unwrap()).unwrap();
    assert!(
        (r.j4 - 0.6).abs() < 1e-9 && (r.j5 - 0.8).abs() < 1e-9,
        "{r:?}"
    );
}

#[test]
fn huge_inputs_are_finite_and_rigid() {
    // Up to |J| = J_MAX on every model (at k = 0.1, J6 = O(1/√k) times J3
    // = J_MAX still keeps J7 finite); |(J4, J5)| ≤ 1 + 1e-6 (the rigid/plastic
    // quadrature at tol 1e-2 gives 1 + 8.5e-9 for pure slip at k = 0.1).
    use traction_rheology::J_MAX;
    let mut cases: Vec<(f64, [f64; 3])> = [1e6, 1e9, 1e13, 1e99]
        .iter()
        .map(|&m| (1.0, [m, -0.5 * m, 2.0 * m]))
        .collect();
    cases.extend([
        (0.1, [0.0, 0.0, J_MAX]),
        (0.1, [-J_MAX, 0.0, 0.0]),
        (0.1, [J_MAX, -J_MAX, J_MAX]),
    ]);
    for (k, j) in cases {
        for model in [
            Model::ElasticPlastic,
            Model::RigidPlastic,
            Model::Viscoelastic {
                deborah: 1.0,
                z0: 1.0,
            },
        ] {
            let o = evaluate(
                &inp(k, j[0], j[1], j[2]),
                model,
                Accuracy::new(1e-2).unwrap(),
            )
            .unwrap();
            assert!(
                o.j4.is_finite() && o.j5.is_finite() && o.j6.is_finite() && o.j7.is_finite(),
                "{k} {j:?} {model:?} {o:?}"
            );
            assert!(o.j4.hypot(o.j5) <= 1.0 + 1e-6, "{k} {j:?} {model:?} {o:?}");
        }
    }
}

#[test]
fn errors_name_the_quantity() {
    assert!(matches!(
        Inputs::new(0.001, 1.0, 0.0, 0.0),
        Err(RheologyError::OutOfRange(OutOfRange {
            quantity: "aspect ratio k",
            ..
        }))
    ));
    assert!(matches!(
        Inputs::new(f64::NAN, 1.0, 0.0, 0.0),
        Err(RheologyError::OutOfRange(OutOfRange {
            quantity: "aspect ratio k",
            ..
        }))
    ));
    let e = Inputs::new(1.0, 1.0, f64::INFINITY, 0.0).unwrap_err();
    assert!(e.to_string().contains("J2"), "{e}");
    let e = Inputs::with_offset(1.0, 1.0, 0.0, 0.0, f64::NAN).unwrap_err();
    assert!(e.to_string().contains("dX"));
    let i = inp(1.0, 1.0, 0.0, 0.0);
    let a = Accuracy::default();
    assert!(matches!(
        viscoelastic(&i, -1.0, 1.0, a),
        Err(RheologyError::OutOfRange(e)) if e.quantity.starts_with("Deborah number D")
    ));
    assert!(matches!(
        viscoelastic(&i, 0.0, 1.0, a),
        Err(RheologyError::OutOfRange(e)) if e.quantity.starts_with("Deborah number D")
    ));
    assert!(matches!(
        viscoelastic(&i, 1.0, 0.0, a),
        Err(RheologyError::OutOfRange(e)) if e.quantity.starts_with("reference stress Z0")
    ));
    assert!(matches!(
        Accuracy::new(0.0),
        Err(RheologyError::OutOfRange(OutOfRange {
            quantity: "accuracy tol",
            ..
        }))
    ));
    // Public fields bypass the constructor: evaluate re-validates.
    let bad = Inputs {
        k: 1.0,
        j1: f64::NAN,
        j2: 0.0,
        j3: 0.0,
        dx: 0.0,
        gy: 1.0,
    };
    assert!(evaluate(&bad, Model::ElasticPlastic, a).is_err());
    let bad_gy = Inputs {
        gy: f64::NAN,
        ..Inputs::new(1.0, 1.0, 0.0, 1.0).unwrap()
    };
    assert!(matches!(
        evaluate(&bad_gy, Model::ElasticPlastic, a),
        Err(RheologyError::OutOfRange(e)) if e.quantity.starts_with("stiffness ratio gy")
    ));
    assert!(
        Inputs::new(1.0, 1.0, 0.0, 1.0)
            .unwrap()
            .with_stiffness_ratio(0.05)
            .is_err()
    );
}

#[test]
fn viscoelastic_limits() {
    // (1) Linear Maxwell fluid (Z0 = ∞) at small stress, zero spin:
    // Zx = D·A·(1 − e^{−(X+c)/D}), A = J1/√k, so per strip
    // ∫Zx dX = D·A·[2c − D(1 − e^{−2c/D})]; the cap is touched only in an
    // outlet layer whose effect is O(|Z|³) ≈ 1e-6 here. The exponential
    // integrator is exact for constant v; the trapezoid sums are O(h²):
    // tolerance 2e-5 relative at the default step count for tol = 1e-5.
    let (k, j1, d) = (1.0, 0.2, 0.05);
    let o = viscoelastic(
        &inp(k, j1, 0.0, 0.0),
        d,
        f64::INFINITY,
        Accuracy::new(1e-5).unwrap(),
    )
    .unwrap();
    let a = j1 / k.sqrt();
    let n = 20000;
    let mut s = 0.0;
    for i in 0..n {
        let phi = -PI / 2.0 + PI * (i as f64 + 0.5) / n as f64;
        let c = phi.cos();
        s += PI / n as f64 * c * d * a * (2.0 * c - d * (1.0 - (-2.0 * c / d).exp()));
    }
    let exact = s / PI;
    assert!((o.j4 / exact - 1.0).abs() < 2e-5, "{} vs {exact}", o.j4);
    // (2) D → ∞: the viscous term vanishes; D = inf is the elastic/plastic
    // model exactly, D = 1e9 within the first-order cap error of the
    // viscoelastic stepping (≈ 3e-3 at tol 1e-4, observed below).
    let i = inp(1.0, 1.0, 0.3, 2.0);
    let e = ep(&i, 1e-5);
    let inf = viscoelastic(&i, f64::INFINITY, 1.0, Accuracy::new(1e-5).unwrap()).unwrap();
    assert!((inf.j4 - e.j4).abs() < 1e-12);
    let big = viscoelastic(&i, 1e9, 1.0, Accuracy::new(1e-4).unwrap()).unwrap();
    let dev = (big.j4 - e.j4)
        .abs()
        .max((big.j5 - e.j5).abs())
        .max((big.j6 - e.j6).abs());
    println!("viscoelastic D=1e9 vs elastic/plastic: {dev:.2e}");
    assert!(dev < 5e-3, "{big:?} {e:?}");
    // (3) Small D: the stress relaxes (Newtonian, J4 ≈ D·A·8/(3π) → 0).
    let small = viscoelastic(
        &inp(1.0, 1.0, 0.0, 0.0),
        1e-3,
        1.0,
        Accuracy::new(1e-3).unwrap(),
    )
    .unwrap();
    assert!(small.j4 > 0.0 && small.j4 < 2e-3, "{small:?}");
}

#[test]
fn property_variations() {
    // (1) The grid scheme for the default combination agrees with the strip
    // integrator: Richardson at 400/800 cells leaves ≈ 1e-5..1e-4 (observed
    // in tests/tests/rheology_grid.rs); tolerance 3e-4.
    for i in [inp(1.0, 1.5, 0.3, 2.0), inp(4.0, 0.5, -0.2, 6.0)] {
        let g = grid_reference(&i, Properties::default(), 400).unwrap();
        let e = ep(&i, 1e-5);
        let d = (g.j4 - e.j4)
            .abs()
            .max((g.j5 - e.j5).abs())
            .max((g.j6 - e.j6).abs());
        assert!(d < 3e-4, "{g:?} {e:?}");
    }
    // (2) Constant limit L = 1, G constant, slip only: per strip
    // ∫Zx dX = 2A·c² if 2cA ≤ 1, else 1/(2A) + (2c − 1/A), A = J1/√k.
    // Exact J4 by a 200 000-point midpoint rule in Y (error < 1e-9).
    let (k, j1) = (1.0_f64, 0.6_f64);
    let a = j1 / k.sqrt();
    let n = 200_000;
    let mut s = 0.0;
    for i in 0..n {
        let y = -1.0 + 2.0 * (i as f64 + 0.5) / n as f64;
        let c = (1.0 - y * y).sqrt();
        let strip = if 2.0 * c * a <= 1.0 {
            2.0 * a * c * c
        } else {
            0.5 / a + (2.0 * c - 1.0 / a)
        };
        s += strip * 2.0 / n as f64;
    }
    let exact = s / PI;
    let props = Properties {
        modulus: Modulus::Constant,
        limit: Limit::Constant,
    };
    let o =
        elastic_plastic_with(&inp(k, j1, 0.0, 0.0), props, Accuracy::new(1e-4).unwrap()).unwrap();
    // First-order grid + Richardson at 400/800 cells: 2e-4.
    assert!((o.j4 - exact).abs() < 2e-4, "{} vs {exact}", o.j4);
    // (3) All four combinations give finite, bounded (|F| ≤ μN plus the
    // grid's 1e-3 slack) and dissipative results with spin.
    for modulus in [Modulus::Constant, Modulus::PressureProportional] {
        for limit in [Limit::PressureProportional, Limit::Constant] {
            let o = elastic_plastic_with(
                &inp(2.0, 1.0, 0.5, 3.0),
                Properties { modulus, limit },
                Accuracy::new(1e-3).unwrap(),
            )
            .unwrap();
            assert!(
                o.j4.is_finite() && o.j4.hypot(o.j5) <= 1.0 + 1e-3 && o.j7 >= 0.0,
                "{modulus:?} {limit:?} {o:?}"
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn losses_are_non_negative_and_forces_bounded(
        k in 0.05f64..20.0, j1 in -30.0f64..30.0, j2 in -30.0f64..30.0, j3 in -60.0f64..60.0, dx in -0.5f64..0.5,
    ) {
        let i = Inputs::with_offset(k, j1, j2, j3, dx).unwrap();
        let o = evaluate(&i, Model::ElasticPlastic, Accuracy::new(1e-2).unwrap()).unwrap();
        // |Z| ≤ L everywhere ⇒ the exact |(J4, J5)| ≤ (1/π)∫∫L = 1; the
        // result is within the requested tol (1e-2) of it (the accuracy
        // contract), so |(J4, J5)| ≤ 1 + tol.
        prop_assert!(o.j4.hypot(o.j5) <= 1.0 + 1e-2, "{:?}", o);
        // Dissipation only: J7 ≥ 0 (discretisation error ≤ 1e-2·(|J|) allowed).
        let scale = j1.abs() + j2.abs() + j3.abs();
        prop_assert!(o.j7 >= -1e-2 * scale, "{:?}", o);
        let r = evaluate(&i, Model::RigidPlastic, Accuracy::new(1e-2).unwrap()).unwrap();
        prop_assert!(r.j7 >= -1e-2 * scale && r.j4.hypot(r.j5) <= 1.0 + 1e-6);
        // The rigid/plastic model dissipates the most for given rates
        // (maximum plastic work, Z = L·v̂ maximises Z·v pointwise).
        prop_assert!(r.j7 >= o.j7 - 2e-2 * scale, "{:?} {:?}", r, o);
    }

    #[test]
    fn anisotropic_stiffness_outputs_are_finite_and_dissipative(
        k in 0.05f64..20.0, j1 in -1e6f64..1e6, j2 in -30.0f64..30.0, j3 in -60.0f64..60.0,
        lg in -1.0f64..1.0, big in proptest::bool::ANY,
    ) {
        // Any gy in [0.1, 10], J's up to 1e6 (rigid/plastic regime): finite,
        // bounded, J7 ≥ 0 within the discretisation slack.
        let j1 = if big { j1 } else { j1 * 3e-5 };
        let i = Inputs::new(k, j1, j2, j3).unwrap().with_stiffness_ratio(10f64.powf(lg)).unwrap();
        let o = evaluate(&i, Model::ElasticPlastic, Accuracy::new(1e-2).unwrap()).unwrap();
        prop_assert!(o.j4.is_finite() && o.j5.is_finite() && o.j6.is_finite() && o.j7.is_finite());
        // Bounded by 1 + tol (the accuracy contract; the quadrature may
        // overshoot the exact bound 1 by less than tol: 4.4e-5 at k = 0.05,
        // J1 = −23.8, J2 = J3 = 0, gy = 2.0, the case in the regression file).
        prop_assert!(o.j4.hypot(o.j5) <= 1.0 + 1e-2, "{:?}", o);
        let scale = j1.abs() + j2.abs() + j3.abs();
        prop_assert!(o.j7 >= -1e-2 * scale, "{:?}", o);
    }

    #[test]
    fn traction_increases_with_slip_at_zero_spin(k in 0.05f64..20.0, j1 in 0.0f64..20.0, dj in 0.01f64..5.0) {
        let a = closed::slip_traction(k, j1);
        let b = closed::slip_traction(k, j1 + dj);
        prop_assert!(b > a && b <= 1.0);
    }
}

#[test]
fn large_spin_at_fine_tolerance_is_finite_and_converged() {
    // |J3| ~ 1e5: the first initial panels are ~1e-5 wide in φ, and where a
    // kink's split fell within rounding of a panel's end it left a panel
    // narrower than an ulp of φ, whose zero change over a zero allowed change
    // was a NaN share (all outputs NaN at tol 1e-4 for 1.1 % of random
    // inputs with |J3| up to 1e5). Each case at tol 1e-4 against tol 1e-5:
    // within 1e-4 (the accuracy contract; observed ≤ 2.1e-7).
    let cases = [
        (1.069100152318923, 0.5, 1.0, 1e5),
        (
            7.190382039281114,
            -0.8931895487244706,
            0.0,
            477300.90420957765,
        ),
        (
            0.7882195063482941,
            0.0708010268127570,
            -0.000920251733574,
            -91759.59602622077,
        ),
        (
            5.0361559022345705,
            18147.81245120198,
            26326.76333916261,
            85930.91227367379,
        ),
    ];
    for (k, j1, j2, j3) in cases {
        let i = inp(k, j1, j2, j3);
        let (a, b) = (ep(&i, 1e-4), ep(&i, 1e-5));
        let d = (a.j4 - b.j4)
            .abs()
            .max((a.j5 - b.j5).abs())
            .max((a.j6 - b.j6).abs());
        println!("k={k} J=({j1},{j2},{j3}): {a:?}, |tol 1e-4 − tol 1e-5| = {d:.1e}");
        assert!(d <= 1e-4, "{a:?} vs {b:?}");
    }
}

#[test]
fn huge_rates_match_the_rigid_plastic_limit() {
    // |J| up to J_RIGID (1e12; the U → 0 of a contact at standstill with
    // slip, where the J's are set by the rolling-speed floor): the elastic
    // zone at the inlet, ≈ 4.5·c/|J|², is shorter than an ulp of X. Its end
    // was taken from the iteration on the yield quartic, which approached it
    // by a third per step from the outlet and stopped on an error estimate
    // valid only near a simple root: the elastic segment ran on to
    // δX = 4e-7·c at |J1| = 1e10, k = 0.07, and J4 was off by 1.4·tol at
    // tol 1e-3 (−1.446 at tol 1e-2, beyond the bound 1); the error grew
    // ∝ |J1| from 1e8. The elastic part of the solution is then O(1/|J|),
    // so at every tol the result is the rigid/plastic one (tol 1e-6) within
    // tol (observed ≤ 0.005·tol).
    for k in [0.0726, 1.0, 5.0] {
        for e in [8.0, 10.0, 11.9] {
            let s = 10f64.powf(e);
            let i = inp(k, -s, -4.7e-4 * s, 1.44e-5 * s);
            let r = rigid_plastic(&i, Accuracy::new(1e-6).unwrap()).unwrap();
            for tol in [1e-2, 1e-3, 1e-4] {
                let o = ep(&i, tol);
                let d = (o.j4 - r.j4)
                    .abs()
                    .max((o.j5 - r.j5).abs())
                    .max((o.j6 - r.j6).abs());
                assert!(d <= tol, "k = {k}, |J1| = 1e{e}, tol {tol}: {o:?} vs {r:?}");
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Every model at tol 1e-5 … 1e-2, J's log-uniform over 1e-6 … 1e8 (or 0)
    /// with either sign: every output finite, |(J4, J5)| ≤ 1 + tol (the
    /// accuracy contract on the exact bound 1).
    #[test]
    fn outputs_finite_and_bounded_over_the_whole_range(
        ltol in -5.0f64..-2.0, lk in -1.3f64..1.3,
        j in proptest::array::uniform3((proptest::bool::ANY, -6.0f64..8.0, proptest::bool::ANY)),
        model in 0u32..4, lde in -3.0f64..3.0, z0 in prop_oneof![Just(f64::INFINITY), 0.2f64..5.0],
    ) {
        let tol = 10f64.powf(ltol);
        let j = j.map(|(zero, e, neg)| if zero { 0.0 } else if neg { -(10f64.powf(e)) } else { 10f64.powf(e) });
        let i = inp(10f64.powf(lk), j[0], j[1], j[2]);
        let model = match model {
            0 | 1 => Model::ElasticPlastic,
            2 => Model::RigidPlastic,
            _ => Model::Viscoelastic { deborah: 10f64.powf(lde), z0 },
        };
        let o = evaluate(&i, model, Accuracy::new(tol).unwrap()).unwrap();
        prop_assert!(o.j4.is_finite() && o.j5.is_finite() && o.j6.is_finite() && o.j7.is_finite(), "{o:?}");
        prop_assert!(o.j4.hypot(o.j5) <= 1.0 + tol, "{o:?}");
    }
}

/// Nested adaptive Simpson (Richardson-corrected), knowing nothing about
/// where the integrand turns: an independent reference for the rigid/plastic
/// solver, whose panels are split and graded at the pole and at vy = 0.
fn adaptive_simpson(f: &dyn Fn(f64) -> [f64; 3], a: f64, b: f64, tol: f64) -> [f64; 3] {
    fn simp(fa: [f64; 3], fm: [f64; 3], fb: [f64; 3], h: f64) -> [f64; 3] {
        [0, 1, 2].map(|i| h / 6.0 * (fa[i] + 4.0 * fm[i] + fb[i]))
    }
    #[allow(clippy::too_many_arguments)]
    fn rec(
        f: &dyn Fn(f64) -> [f64; 3],
        (a, b): (f64, f64),
        (fa, fm, fb): ([f64; 3], [f64; 3], [f64; 3]),
        whole: [f64; 3],
        tol: f64,
        depth: u32,
    ) -> [f64; 3] {
        let m = 0.5 * (a + b);
        let (flm, frm) = (f(0.5 * (a + m)), f(0.5 * (m + b)));
        let l = simp(fa, flm, fm, m - a);
        let r = simp(fm, frm, fb, b - m);
        let err = (0..3)
            .map(|i| (l[i] + r[i] - whole[i]).abs())
            .fold(0.0, f64::max);
        if depth == 0 || err <= 15.0 * tol {
            return [0, 1, 2].map(|i| l[i] + r[i] + (l[i] + r[i] - whole[i]) / 15.0);
        }
        let x = rec(f, (a, m), (fa, flm, fm), l, 0.5 * tol, depth - 1);
        let y = rec(f, (m, b), (fm, frm, fb), r, 0.5 * tol, depth - 1);
        [0, 1, 2].map(|i| x[i] + y[i])
    }
    let (fa, fm, fb) = (f(a), f(0.5 * (a + b)), f(b));
    rec(f, (a, b), (fa, fm, fb), simp(fa, fm, fb, b - a), tol, 40)
}

#[test]
fn rigid_plastic_matches_a_brute_force_reference() {
    // J4..J6 of Z = L·v/|v| by nested adaptive Simpson in (φ, s) (Y = sin φ,
    // X = c·sin s) to 1e-10 / 1e-12, against rigid_plastic at tol = 1e-6:
    // agreement 1e-6. Cases: moderate spin, the spin pole just inside the
    // contact near the axis (k = 0.2 — here uniform panels are off by 1.6e-3
    // at tol = 1e-4 and 2e-4 at 1e-8),
    // pole outside, side slip with the line vy = 0 leaving the ellipse, ΔX.
    use std::f64::consts::{FRAC_PI_2, PI};
    let cases: [(f64, f64, f64, f64, f64); 5] = [
        (1.0, 1.5, 0.3, 2.0, 0.0),
        (0.2, -0.012436, -0.008951, -0.098843, 0.0),
        (5.0, 3.0, 0.5, 1.0, 0.0),
        (2.0, 0.2, 1.1, 1.3, 0.0),
        (1.0, 0.3, 0.1, 1.0, 0.4),
    ];
    for &(k, j1, j2, j3, dx) in &cases {
        let sk = k.sqrt();
        let outer = |phi: f64| -> [f64; 3] {
            let (y, cphi) = phi.sin_cos();
            let c = (1.0 - y * y).max(0.0).sqrt();
            let vx = j1 / sk - j3 * y;
            let inner = |s: f64| -> [f64; 3] {
                let (sn, cs) = s.sin_cos();
                let x = c * sn;
                let vy = j2 / sk + j3 * (x + dx) / k;
                let m = vx.hypot(vy);
                if m == 0.0 {
                    return [0.0; 3];
                }
                let f = 1.5 * c * c * cs * cs;
                [f * vx / m, f * vy / m, f * vy / m * (x + dx)]
            };
            let r = adaptive_simpson(&inner, -FRAC_PI_2, FRAC_PI_2, 1e-12);
            [r[0] * cphi, r[1] * cphi, (r[2] - k * y * r[0]) * cphi]
        };
        let b = adaptive_simpson(&outer, -FRAC_PI_2, FRAC_PI_2, 1e-10);
        let (e4, e5, e6) = (b[0] / PI, b[1] / PI, b[2] / (PI * sk));
        let i = Inputs::with_offset(k, j1, j2, j3, dx).unwrap();
        let r = rigid_plastic(&i, Accuracy::new(1e-6).unwrap()).unwrap();
        let d = (r.j4 - e4)
            .abs()
            .max((r.j5 - e5).abs())
            .max((r.j6 - e6).abs());
        println!("k={k} J=({j1},{j2},{j3}) dX={dx}: |solver − brute| = {d:.1e}");
        assert!(d < 1e-6, "{r:?} vs ({e4}, {e5}, {e6})");
        // The default accuracy (1e-4) holds too.
        let r4 = rigid_plastic(&i, Accuracy::default()).unwrap();
        assert!(
            (r4.j4 - e4)
                .abs()
                .max((r4.j5 - e5).abs())
                .max((r4.j6 - e6).abs())
                < 1e-4
        );
    }
}

/// Uniform numbers in [0, 1) of the random scans, from `seed`.
fn uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut rng = traction_testkit::XorShift64::new(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    move || rng.unit()
}

/// Tolerances of [`wide_range_scan`]: 5e-4 lies between the settings of
/// tol ≥ 1e-3 and those that take over towards 1e-4.
const SCAN_TOLS: [f64; 4] = [1e-2, 1e-3, 5e-4, 1e-4];

/// Worst error/tol at each of SCAN_TOLS (or `traction_testkit::scan_tols`)
/// against tol 1e-6 (a twentieth of the finest tol where that is below 2e-5)
/// over `n` random cases of the whole input range: k 0.063–10, each J 0 (15 %) or of either
/// sign up to 1e12 (a common scale 1 … 1e12 times 1e-6 … 1 each: a contact at
/// U → 0 has J's set by the rolling-speed floor); the viscoelastic model with
/// D 0.01–100 and Z0 ∞ or 0.3–3.3. Prints the worst case per tol.
fn wide_range_scan(viscoelastic: bool, seed: u64, n: usize) -> Vec<f64> {
    let mut r = uniform(seed);
    let tols = traction_testkit::scan_tols(&SCAN_TOLS);
    let tol_ref = tols.iter().fold(1e-6_f64, |r, &t| r.min(t / 20.0));
    let mut worst = vec![(0.0_f64, String::new()); tols.len()];
    for _ in 0..n {
        let k = 10f64.powf(-1.2 + 2.2 * r());
        let big = 10f64.powf(12.0 * r());
        let mut j = [0.0; 3];
        for v in j.iter_mut() {
            *v = if r() < 0.15 {
                0.0
            } else {
                big * 10f64.powf(-6.0 * r()) * if r() < 0.5 { -1.0 } else { 1.0 }
            };
        }
        let i = inp(k, j[0], j[1], j[2]);
        let model = if viscoelastic {
            let deborah = 10f64.powf(-2.0 + 4.0 * r());
            let z0 = if r() < 0.5 {
                f64::INFINITY
            } else {
                0.3 + 3.0 * r()
            };
            Model::Viscoelastic { deborah, z0 }
        } else {
            Model::ElasticPlastic
        };
        let reference = evaluate(&i, model, Accuracy::new(tol_ref).unwrap()).unwrap();
        for (w, &tol) in worst.iter_mut().zip(&tols) {
            let o = evaluate(&i, model, Accuracy::new(tol).unwrap()).unwrap();
            let d = dev(&o, &reference) / tol;
            if d > w.0 {
                *w = (d, format!("k {k:.4} J {j:?} {model:?}"));
            }
        }
    }
    for (w, tol) in worst.iter().zip(&tols) {
        println!(
            "seed {seed}, {n} cases, tol {tol:e}: worst error/tol {:.3} ({})",
            w.0, w.1
        );
    }
    worst.into_iter().map(|w| w.0).collect()
}

#[test]
#[ignore = "15 000 elastic/plastic cases of the whole input range, about 1 min: \
            cargo test -p traction-rheology --release --test model wide_range -- --ignored --nocapture"]
fn wide_range_scan_elastic_plastic() {
    // Seed 30 holds the wide panel of
    // `kink_split_on_a_wide_panel_is_located_near_the_kink` (1.16·tol
    // before its fix; now 0.49).
    let seeds = traction_testkit::scan_seeds(&[2, 3, 4, 5, 30]);
    let worst: Vec<Vec<f64>> = seeds
        .iter()
        .map(|&s| wide_range_scan(false, s, 3000))
        .collect();
    assert!(worst.iter().flatten().all(|&e| e <= 1.0));
}

#[test]
#[ignore = "6000 viscoelastic cases of the whole input range, about 2 min: \
            cargo test -p traction-rheology --release --test model wide_range -- --ignored --nocapture"]
fn wide_range_scan_viscoelastic() {
    let seeds = traction_testkit::scan_seeds(&[2, 3, 4]);
    let worst: Vec<Vec<f64>> = seeds
        .iter()
        .map(|&s| wide_range_scan(true, s, 2000))
        .collect();
    assert!(worst.iter().flatten().all(|&e| e <= 1.0));
}

#[test]
#[ignore = "9000 elastic/plastic cases of large side slip and small spin at small k, a few seconds: \
            cargo test -p traction-rheology --release --test model side_slip -- --ignored --nocapture"]
fn side_slip_at_small_k_scan() {
    // Nearly fully plastic strips (side slip |J2| 3–12, |J1| ≤ 0.05,
    // |J3| ≤ 0.03) at the contract's smallest k (0.063–0.16), where J6 weighs
    // the strips' moment ∫Zy·X dX, a small difference of large parts, by
    // 1/(π√k): tol 1e-3 against tol 1e-6. Worst error/tol 0.023 (0.98 while
    // the exponential steps took Simpson's rule for the strip sums).
    for seed in traction_testkit::scan_seeds(&[1, 2, 3]) {
        let mut r = uniform(seed);
        let tol = 1e-3;
        let mut worst = (0.0_f64, String::new());
        for _ in 0..3000 {
            let k = 10f64.powf(-1.2 + 0.4 * r());
            let mut sign = || if r() < 0.5 { -1.0 } else { 1.0 };
            let (s2, s1, s3) = (sign(), sign(), sign());
            let j2 = s2 * (3.0 + 9.0 * r());
            let j1 = s1 * 0.05 * r() * r();
            let j3 = s3 * 0.03 * r() * r();
            let i = inp(k, j1, j2, j3);
            let reference =
                evaluate(&i, Model::ElasticPlastic, Accuracy::new(1e-6).unwrap()).unwrap();
            let o = evaluate(&i, Model::ElasticPlastic, Accuracy::new(tol).unwrap()).unwrap();
            let d = dev(&o, &reference) / tol;
            if d > worst.0 {
                worst = (d, format!("k {k:.5} J ({j1:.3e}, {j2:.4}, {j3:.3e})"));
            }
        }
        println!("seed {seed}: worst error/tol {:.3} ({})", worst.0, worst.1);
        assert!(worst.0 <= 1.0);
    }
}

#[test]
fn kink_split_on_a_wide_panel_is_located_near_the_kink() {
    // Small spin and side slip at small k: one initial panel across Y spans
    // φ from the pole (≈ 0) to the contact's edge, and an unloading vanishes
    // at φ = 0.466. Its margin is −0.13 at the pole, steep near the kink and
    // 3/2 at the edge, so regula falsi kept the edge and split at 0.317; the
    // panel left holding the kink was accepted at a third of its error and
    // the contact was 1.17·tol off at tol 1e-4 (seed 30 of the whole-range
    // scan). The located points now keep a quarter of their bracket from
    // its ends (docs/decisions/0120). Against tol 1e-7: measured 0.10·tol
    // at 1e-4; 0.5·tol keeps a margin and fails the former rule.
    let i = inp(
        0.1439,
        2.704211520851383e-5,
        0.020058223474608693,
        -0.4607708192021948,
    );
    elastic_plastic_within_share(&i, &[3e-4, 1e-4], 0.5);
}

#[test]
fn whole_segments_of_rk4_steps_keep_tol_after_a_reyield() {
    // Small k, moderate spin: after an unloading the strips near Y ≈ 0.06
    // re-yield and relax on a segment that counted as non-stiff at the
    // longer s-step (κ·h 0.5 → 1.9). RK4 at κ·h near 2 left the stress
    // direction up to 2e-3 rad off, and J6 0.73·tol off at tol 1e-4 and
    // 0.89–0.94·tol from 3e-5 to 2e-6 (seed 1 #211 of `cargo xtask ep-sets
    // errs`). The margin is now 1.2 at tol 1e-4, falling with the s-step
    // (docs/decisions/0128). Against tol 1e-7: measured 0.196 / 0.193 /
    // 0.208·tol at 1e-4 / 3e-5 / 1e-5; 0.3·tol keeps a margin.
    let i = inp(0.0654, -0.712, -0.277, -1.692);
    elastic_plastic_within_share(&i, &[1e-4, 3e-5, 1e-5], 0.3);
}

#[test]
fn stiff_steps_keep_tol_below_1e_4_at_high_spin() {
    // High spin at small k. In the first two cases the strips crossing
    // vy = 0 just before they unload relax their stress direction in RK4
    // sub-steps; with their κ·h margin fixed at 1.5 the first was 0.70 /
    // 4.4 / 12.1·tol off at tol 1e-5 / 2e-6 / 1e-6 and the second 0.90·tol
    // at 1e-5. The third (|J| ≈ 600) takes quasi-steady steps; with their
    // threshold fixed in κ·h it was 0.72 / 1.85 / 2.10·tol off. Below tol
    // 1e-4 the margin now falls as √tol and the threshold stays at a fixed
    // κ (docs/decisions/0129). Against tol 1e-7 (within 1e-9 of tol 3e-9):
    // measured 0.09 / 0.03 / 0.03, 0.24 / 0.11 / 0.09 and 0.17 / 0.03 /
    // 0.01·tol; 0.4·tol keeps a margin and fails the former rules at 1e-5.
    for i in [
        inp(0.0633, 0.0, -115.84, 87.68),
        inp(0.0748, 0.0, -28.570416278855514, 27.163254823676635),
        inp(
            0.0789,
            -215.59948316734247,
            1.63248623129426,
            -548.8921124799836,
        ),
    ] {
        elastic_plastic_within_share(&i, &[1e-5, 2e-6, 1e-6], 0.4);
    }
}

/// Asserts that the elastic/plastic model at `i` is within `share`·tol of
/// its value at tol 1e-7 at each of `tols`.
fn elastic_plastic_within_share(i: &Inputs, tols: &[f64], share: f64) {
    let reference = ep(i, 1e-7);
    for &tol in tols {
        let e = dev(&ep(i, tol), &reference);
        assert!(
            e <= share * tol,
            "tol {tol:e}: error {e:.3e} = {:.2}·tol",
            e / tol
        );
    }
}

#[test]
fn kink_panel_is_not_accepted_far_below_its_simpson_difference() {
    // Small spin at small k: each half of the contact is one initial panel
    // holding a kink, and between tol 2e-3 and 4e-4 (no kink splits) its
    // Lobatto–Kronrod difference was 1/710 of its Simpson–Lobatto one and
    // 1/6 of its error: 0.77, 1.11 and 1.55·tol off at 1e-3, 7e-4 and 5e-4
    // (the whole-range scan, seed 75). Such a difference now counts as at
    // least KINK_SIMPSON_SHARE of stage 1's (docs/decisions/0122). Against
    // tol 1e-7: measured 0.04–0.06·tol; 0.3·tol keeps a margin and fails
    // the former rule at each tol.
    let i = inp(
        0.1136,
        -2.9226656364588072e-5,
        0.03330097672430213,
        -0.3377369983681081,
    );
    elastic_plastic_within_share(&i, &[1e-3, 7e-4, 5e-4], 0.3);
    // The same kind of panel at tol 1e-4 (seed 79): 1.02·tol before, now
    // 0.15.
    let i = inp(0.0936, 0.04076421411538366, 0.0, 0.30965193470936975);
    elastic_plastic_within_share(&i, &[1e-4], 0.4);
}

#[test]
fn initial_panel_is_not_kept_on_a_chance_simpson_agreement() {
    // Very large slip (|J| ≈ 6.5e7, a fresh seed of the whole-range scan):
    // the initial panel [−0.476, π/2] kept its Lobatto value at 1.2 times
    // the allowed change of its Simpson one while its Kronrod value was 3.0
    // times it away: 1.44, 1.76, 1.93 and 1.88·tol off at tol 4.99e-4,
    // 5e-4, 5.01e-4 and 5.05e-4 (0.000 at 4.9e-4 and 5.1e-4, where the two
    // rules did not agree). An initial panel now keeps its Lobatto value
    // only to INITIAL_STAGE1 of the allowed change (docs/decisions/0124).
    // Against tol 1e-7: measured 0.000·tol; 0.1·tol fails the former rule at
    // each tol.
    let i = inp(
        0.0887,
        65195892.77120199,
        -106918.32223609377,
        -10633218.220207531,
    );
    elastic_plastic_within_share(&i, &[4.99e-4, 5e-4, 5.01e-4, 5.05e-4], 0.1);
}

#[test]
fn pair_check_keeps_a_half_only_near_its_own_allowed_change() {
    // Small k and small spin, no slip: a refined kink panel's halves
    // agreed with its Kronrod value by chance, and the half holding the
    // kink kept its Lobatto value on a Simpson–Lobatto difference of 8.1
    // allowed changes: 0.88, 0.94, 0.86 and 0.65·tol off at tol 6e-4,
    // 5e-4, 4.5e-4 and 4e-4 (a fresh seed of the whole-range scan). A half
    // now keeps it only to PAIR_STAGE1 = 4 allowed changes
    // (docs/decisions/0125). Against tol 1e-7: measured 0.14, 0.011, 0.012
    // and 0.013·tol; 0.2·tol fails the former rule at each tol.
    let i = inp(0.0646, 0.0, -0.16693345505696328, -0.27304851212338277);
    elastic_plastic_within_share(&i, &[6e-4, 5e-4, 4.5e-4, 4e-4], 0.2);
}

#[test]
fn pair_check_is_not_passed_far_below_the_panels_own_difference() {
    // A refined kink panel whose halves' Lobatto values agreed with its
    // Kronrod value within 0.99 of the allowed change, both off by 2.5 of
    // it: 0.71 and 0.99·tol off at tol 7e-4 and 5e-4 (the whole-range
    // scan, seed 59). The pair check's difference now counts as at least
    // PAIR_KRONROD_SHARE of the panel's Lobatto–Kronrod difference
    // (docs/decisions/0122). Against tol 1e-7: measured 0.23 and 0.05·tol.
    let i = inp(
        0.1065,
        -2.7472961439279604e-5,
        -0.0026499026826449566,
        0.38179805398827765,
    );
    elastic_plastic_within_share(&i, &[7e-4, 5e-4], 0.4);
}

/// Asserts that the viscoelastic model (D, Z0) at `inputs` is within
/// `share`·tol of its value at tol 1e-6 at each of `tols`.
fn viscoelastic_within_share(inputs: Inputs, (deborah, z0): (f64, f64), tols: &[f64], share: f64) {
    let at = |tol: f64| viscoelastic(&inputs, deborah, z0, Accuracy::new(tol).unwrap()).unwrap();
    let reference = at(1e-6);
    for &tol in tols {
        let o = at(tol);
        let e = dev(&o, &reference);
        assert!(
            e <= share * tol,
            "tol {tol:e}: error {e:.3e} = {:.2}·tol",
            e / tol
        );
    }
}

#[test]
fn viscoelastic_cap_exit_between_two_step_ends_is_found() {
    // Side slip at small D: in the middle of each strip near Y = 0 the
    // viscous rate at the limit exceeds the slip, and the stress leaves the
    // cap for its viscous equilibrium on a band of the strip, then comes
    // back. At tol 1e-3 the caps' exponential steps had both ends of one
    // step on the cap with the band between them: the strips |Y| < 0.28
    // stayed on the cap, J5 0.99999911 against 0.99753253 (2.47·tol). The
    // dip of g's interpolant over the step now finds the band
    // (docs/decisions/0119). Against tol 1e-6 (itself within 1.5e-7 of tol
    // 1e-8): measured 0.01, 0.04 and 0.02·tol at tol 1e-2, 1e-3, 1e-4;
    // 0.25·tol keeps a margin for the reference and for other builds.
    viscoelastic_within_share(
        inp(0.7857, 4.808e-2, 145.66, 0.0),
        (0.0414, 0.411),
        &[1e-2, 1e-3, 1e-4],
        0.25,
    );
}

#[test]
fn viscoelastic_cap_exit_is_located_where_g_falls_steeply() {
    // At small D and Z0, ψ(L) = (Z0/D)·sinh(L/Z0) makes g fall from 1.3 to
    // far below 0 within one exponential cap step. The location of the exit
    // stopped after its 6 integrations at g = −53, 0.28 rad late in σ, and
    // the contact was 2.19·tol off at tol 1e-3 (0.80 at 3e-3); the
    // viscoelastic cap's exit now takes up to 24 (docs/decisions/0119).
    // Against tol 1e-6 (within 1e-7 of tol 1e-8): measured 0.03, 0.05 and
    // 0.14·tol at tol 1e-2, 3e-3 and 1e-3; 0.5·tol keeps a margin.
    viscoelastic_within_share(
        inp(
            3.962426411015227,
            0.03531237724751588,
            84.92099292467957,
            0.0,
        ),
        (0.02489741200914811, 0.312048004215468),
        &[1e-2, 3e-3, 1e-3],
        0.5,
    );
}

/// Large side slip at small D (seeds 32 and 35 of
/// `viscoelastic_side_slip_small_deborah_scan`): a band of another flow
/// topology (cap entry, exit and re-entry; φ 0.926–0.978 and 0.869–0.950)
/// lies between two nodes of the initial panel [π/4, π/2] across Y.
const VISCO_BAND_CASES: [([f64; 4], f64, f64); 2] = [
    (
        [
            0.433194484357755,
            0.0,
            4.236242470946513,
            0.006032789078824766,
        ],
        0.13561007212121673,
        3.20164881059288,
    ),
    (
        [
            0.25999665086735607,
            0.0,
            3.508507368097616,
            0.012862901239536921,
        ],
        0.1303013989447137,
        f64::INFINITY,
    ),
];

#[test]
fn viscoelastic_band_between_panel_nodes_is_predicted_from_strip_margins() {
    // No node saw the band: the contact was 1.14 and 1.05·tol off at tol
    // 1e-4. The strips' closest approaches of |Z| to the cap, extrapolated
    // between nodes, now predict it and refine the panel
    // (docs/decisions/0121). Against tol 1e-6: measured 0.006 and
    // 0.052·tol at 1e-4, 0.016 and 0.032 at 3e-4; 0.25·tol keeps a margin.
    for ([k, j1, j2, j3], deborah, z0) in VISCO_BAND_CASES {
        viscoelastic_within_share(inp(k, j1, j2, j3), (deborah, z0), &[3e-4, 1e-4], 0.25);
    }
}

#[test]
fn viscoelastic_band_refinement_is_continuous_along_a_line() {
    // D through the band cases at tol 1e-4, the band crossing the panels'
    // nodes along the way. Relative steps of 1e-3 (300 points): second
    // differences measured 0.026 and 0.12·tol, against 0.60 and 0.60 while
    // a band was refined only once a node saw it (at that spacing smooth
    // stretches contribute too). The largest left is a jump: at
    // D = 0.1303·(1 − 0.029) in the second case a node of a refined panel
    // enters the band, and the panel's kink rule takes over from the
    // prediction. Through it at relative steps of 3e-5, where smooth
    // stretches contribute ≈ 1e-6·tol, the jump measures 0.085·tol, within
    // the tol/10 asked of every discrete decision (docs/decisions/0121).
    let tol = 1e-4;
    let second_differences = |i: &Inputs, d0: f64, z0: f64, step: f64, n: usize| {
        let v: Vec<Outputs> = (0..n)
            .map(|j| {
                let d = d0 * (1.0 + step * (j as f64 - 0.5 * n as f64));
                viscoelastic(i, d, z0, Accuracy::new(tol).unwrap()).unwrap()
            })
            .collect();
        v.windows(3)
            .map(|w| {
                let d2 = |f: fn(&Outputs) -> f64| (f(&w[2]) - 2.0 * f(&w[1]) + f(&w[0])).abs();
                d2(|o| o.j4).max(d2(|o| o.j5)).max(d2(|o| o.j6))
            })
            .fold(0.0, f64::max)
    };
    for ([k, j1, j2, j3], deborah, z0) in VISCO_BAND_CASES {
        let m = second_differences(&inp(k, j1, j2, j3), deborah, z0, 1e-3, 300);
        assert!(
            m <= 0.2 * tol,
            "D = {deborah}: second difference {:.3}·tol",
            m / tol
        );
    }
    let ([k, j1, j2, j3], deborah, z0) = VISCO_BAND_CASES[1];
    let m = second_differences(&inp(k, j1, j2, j3), deborah * (1.0 - 0.029), z0, 3e-5, 60);
    assert!(m <= 0.1 * tol, "second difference {:.3}·tol", m / tol);
}

#[test]
fn viscoelastic_entry_onto_an_empty_cap_is_retaken_shorter() {
    // High spin with side slip at small D: the viscous rate at the limit
    // nearly balances the slip, so whether the stress can stay on the cap
    // at an entry depends on where the entry is and on the stress direction
    // there. A long interior step (0.42 rad) entered the cap 0.009 rad
    // early, where g = −6: the cap ended where it began, the interior
    // re-entered at once, and after a second such switch the stress stayed
    // inside until 0.29 rad past the true entry. The contact was 4.9·tol
    // off at tol 1e-3 (3.6 at 3e-3, 1.4 at 3e-4). An interior step whose
    // entry meets an empty cap is now retaken at half its length
    // (docs/decisions/0119). Against tol 1e-6: measured 0.01, 0.02, 0.03
    // and 0.02·tol at tol 1e-2, 3e-3, 1e-3 and 3e-4; 0.25·tol keeps a
    // margin.
    viscoelastic_within_share(
        inp(
            9.3339,
            1.1687808460538156,
            982.0784730636004,
            162.03345296215932,
        ),
        (0.011392901478637224, 0.32547113309351133),
        &[1e-2, 3e-3, 1e-3, 3e-4],
        0.25,
    );
}

#[test]
fn viscoelastic_kink_panels_are_refined_at_small_tol() {
    // Large side slip at small D: the strips' flow topology changes at
    // |Y| ≈ 0.62 and 0.82, inside two initial panels across Y whose
    // Lobatto and Kronrod values agreed by chance. The contact was ≈ 1.6e-4
    // off at every tol from 1e-2 to 1e-4 (1.55·tol at 1e-4); an initial
    // panel holding a kink is now refined at tol ≤ 3e-4
    // (docs/decisions/0119). Against tol 1e-6: measured 0.03·tol at 3e-4
    // and 1e-4; 0.25·tol keeps a margin.
    viscoelastic_within_share(
        inp(
            8.048754151971476,
            -0.043618483080038496,
            24.34467381248092,
            0.011115062383883028,
        ),
        (0.11098268084062536, 1.320300433792329),
        &[3e-4, 1e-4],
        0.25,
    );
}

#[test]
fn viscoelastic_halves_are_not_kept_on_a_panel_far_from_resolved() {
    // An initial panel whose Lobatto and Kronrod values were 620 allowed
    // changes apart was refined, and 79 % of it kept on its halves'
    // Lobatto values, which agreed with its Kronrod value within 1.3
    // allowed changes while both were off by about 6: 0.92, 1.33 and
    // 1.48·tol off at tol 1e-4, 7e-5 and 5e-5 (whole-range scan, seed 50).
    // The joint check's difference now counts as at least the halves'
    // expected error (HALVES_LOBATTO_SHARE, docs/decisions/0122). Against
    // tol 1e-6: measured 0.09–0.14·tol; 0.4·tol fails the former rule.
    viscoelastic_within_share(
        inp(8.9608, 0.0, 0.11489424775106839, -6.170431728878041),
        (0.8422532425910502, f64::INFINITY),
        &[1e-4, 7e-5, 5e-5],
        0.4,
    );
}

#[test]
#[ignore = "3000 viscoelastic cases of large side slip and small spin at small D, a few seconds: \
            cargo test -p traction-rheology --release --test model side_slip_small_deborah -- --ignored --nocapture"]
fn viscoelastic_side_slip_small_deborah_scan() {
    // |J2| 3–300, |J1| ≤ 0.05 and |J3| ≤ 0.015 or 0, D 0.01–0.3: in the
    // middle of the contact the stress rides at the viscous equilibrium
    // below the cap, towards the edges it stays on the cap, so the strip
    // sums have kinks in Y. Against tol 1e-6. Worst error/tol 0.25 at 1e-3
    // and 0.47 at 1e-4 on seeds 1 and 2; on seeds 1–60 0.373 and 0.401.
    // Seeds 32, 35 and 41 were 1.14, 1.05 and 1.33·tol off at 1e-4 while
    // a band of another flow topology between two nodes of an initial
    // panel went unseen (docs/decisions/0121). Before the three
    // changes of docs/decisions/0119 (a cap exit between two step ends, an
    // exit located short of converging, initial panels holding a kink
    // accepted by chance) 0.83 and 1.45 here (seed 2; 0.92 before the
    // initial panels' slack of docs/decisions/0117), and on 22 seeds 2.47
    // and 1.55; 1.05 while refined panels holding such a kink were accepted
    // on their halves' Lobatto values (docs/decisions/0104).
    for seed in traction_testkit::scan_seeds(&[1, 2, 32, 35, 41]) {
        let mut r = uniform(seed);
        let mut worst = [(0.0_f64, String::new()), (0.0, String::new())];
        for _ in 0..600 {
            let k = 10f64.powf(-1.2 + 2.2 * r());
            let j2 = if r() < 0.5 { -1.0 } else { 1.0 } * 10f64.powf(0.5 + 2.0 * r());
            let j3 = if r() < 0.5 { 0.0 } else { 0.03 * (r() - 0.5) };
            let j1 = if r() < 0.5 { 0.0 } else { 0.1 * (r() - 0.5) };
            let deborah = 10f64.powf(-2.0 + 1.5 * r());
            let z0 = if r() < 0.5 {
                f64::INFINITY
            } else {
                0.3 + 3.0 * r()
            };
            let model = Model::Viscoelastic { deborah, z0 };
            let i = inp(k, j1, j2, j3);
            let reference = evaluate(&i, model, Accuracy::new(1e-6).unwrap()).unwrap();
            for (w, tol) in worst.iter_mut().zip([1e-3, 1e-4]) {
                let o = evaluate(&i, model, Accuracy::new(tol).unwrap()).unwrap();
                let d = dev(&o, &reference) / tol;
                if d > w.0 {
                    *w = (
                        d,
                        format!(
                            "k {k:.4} J ({j1:.3e}, {j2:.3}, {j3:.3e}) D {deborah:.4} Z0 {z0:.3}"
                        ),
                    );
                }
            }
        }
        for (w, tol) in worst.iter().zip([1e-3, 1e-4]) {
            println!(
                "seed {seed}, tol {tol:e}: worst error/tol {:.3} ({})",
                w.0, w.1
            );
            assert!(w.0 <= 1.0);
        }
    }
}

#[test]
fn j_beyond_their_range_are_refused() {
    // |J| ≤ J_MAX = 1e100: at |J3| = 1.7e308 (k = 0.1) J7 overflowed to
    // infinity. Beyond the range: an error naming the quantity (its end:
    // `huge_inputs_are_finite_and_rigid`).
    use traction_rheology::{J_MAX, J_RANGE};
    assert_eq!(J_RANGE.max(), J_MAX);
    for (j, name) in [
        ([1.1e100, 0.0, 0.0], "J1"),
        ([0.0, -1.7e308, 0.0], "J2"),
        ([0.0, 0.0, 1e101], "J3"),
    ] {
        let e = Inputs::new(0.1, j[0], j[1], j[2]).unwrap_err();
        assert!(e.to_string().contains(name), "{e}");
    }
    assert!(Inputs::with_offset(1.0, 1.0, 0.0, 1.0, 2e100).is_err());
}
