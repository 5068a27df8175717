//! The interpolation map (traction_rheology::map) against the integrator.
#![allow(clippy::unwrap_used, missing_docs)]

use traction_rheology::map::{Budget, Map};
use traction_rheology::{Accuracy, Inputs, Model, OutOfRange, RheologyError, evaluate};
use traction_testkit::XorShift64;

/// The inputs at (J1, J2, J3) with the map's k, ΔX and gy (unvalidated:
/// the map validates).
fn at(map: &Map, j1: f64, j2: f64, j3: f64) -> Inputs {
    let (k, dx, gy) = map.key();
    Inputs {
        k,
        j1,
        j2,
        j3,
        dx,
        gy,
    }
}

/// A random J with a log-uniform magnitude of the scaled rates in
/// [10^-1, 10^(rlog-1)] and a uniformly random direction.
fn random_j(rng: &mut XorShift64, k: f64, rlog: f64) -> (f64, f64, f64) {
    let r = 10f64.powf(-1.0 + rlog * rng.unit());
    let z = 2.0 * rng.unit() - 1.0;
    let p = 2.0 * std::f64::consts::PI * rng.unit();
    let q = (1.0 - z * z).sqrt();
    let (s12, s3) = (1.0 / k.sqrt(), (1.0 + 1.0 / (k * k)).sqrt());
    (r * q * p.cos() / s12, r * q * p.sin() / s12, r * z / s3)
}

fn reference(k: f64, j: (f64, f64, f64), tol: f64) -> [f64; 3] {
    let inp = Inputs::new(k, j.0, j.1, j.2).unwrap();
    let o = evaluate(&inp, Model::ElasticPlastic, Accuracy::new(tol).unwrap()).unwrap();
    [o.j4, o.j5, o.j6]
}

#[test]
fn map_meets_its_accuracy_on_random_points() {
    // Tolerance: the map's accuracy tol = 1e-3 itself, checked against the
    // integrator at 1e-5 (whose own error is ≤ 1e-5, verified in
    // convergence.rs). 150 random points per k over |x| 0.1 … 10⁴ (elastic
    // to nearly rigid/plastic), k from 0.1 to 10. Also the share of points
    // answered by interpolation must be high (≥ 75 %), or the map is useless.
    let tol = 1e-3;
    let mut rng = XorShift64::new(0x5eed_1234_abcd_0001);
    let mut worst = 0.0f64;
    for &k in &[0.1, 1.0, 4.0, 10.0] {
        let mut map = Map::new(k, 0.0, 1.0, Accuracy::new(tol).unwrap()).unwrap();
        for _ in 0..150 {
            let j = random_j(&mut rng, k, 5.0);
            let m = map.evaluate(&at(&map, j.0, j.1, j.2)).unwrap();
            let r = reference(k, j, 1e-5);
            let err = (m.j4 - r[0])
                .abs()
                .max((m.j5 - r[1]).abs())
                .max((m.j6 - r[2]).abs());
            assert!(
                err <= tol,
                "k {k} J {j:?}: map {m:?} ref {r:?} err {err:.2e}"
            );
            worst = worst.max(err);
        }
        let s = map.stats();
        let share = s.interpolated as f64 / (s.interpolated + s.direct) as f64;
        assert!(
            share >= 0.75,
            "k {k}: interpolated share {share:.2} ({s:?})"
        );
    }
    eprintln!("worst map error {worst:.2e} (tol {tol:.0e})");
}

#[test]
fn map_with_offset_and_anisotropy_meets_its_accuracy() {
    // ΔX and gy change the solution but not the symmetries the map folds
    // with (point symmetry and the mirror y → −y hold for any ΔX, gy).
    let tol = 1e-3;
    let (k, dx, gy) = (2.0, 0.2, 0.6);
    let mut map = Map::new(k, dx, gy, Accuracy::new(tol).unwrap()).unwrap();
    let mut rng = XorShift64::new(0x0ff5_e7a1_5070_0002);
    for _ in 0..80 {
        let j = random_j(&mut rng, k, 4.0);
        let m = map.evaluate(&at(&map, j.0, j.1, j.2)).unwrap();
        let inp = Inputs::with_offset(k, j.0, j.1, j.2, dx)
            .unwrap()
            .with_stiffness_ratio(gy)
            .unwrap();
        let r = evaluate(&inp, Model::ElasticPlastic, Accuracy::new(1e-5).unwrap()).unwrap();
        let err = (m.j4 - r.j4)
            .abs()
            .max((m.j5 - r.j5).abs())
            .max((m.j6 - r.j6).abs());
        assert!(err <= tol, "J {j:?}: map {m:?} ref {r:?}");
    }
}

#[test]
fn results_do_not_depend_on_the_cache() {
    // Bit-identical results whatever was evaluated before, in any order,
    // after clear(): nodes and cell checks are pure functions of the indices.
    let acc = Accuracy::new(1e-3).unwrap();
    let mut rng = XorShift64::new(0xdead_beef_0000_0003);
    let pts: Vec<_> = (0..40).map(|_| random_j(&mut rng, 3.0, 3.0)).collect();
    let mut a = Map::new(3.0, 0.0, 1.0, acc).unwrap();
    let ra: Vec<_> = pts
        .iter()
        .map(|j| a.evaluate(&at(&a, j.0, j.1, j.2)).unwrap())
        .collect();
    let mut b = Map::new(3.0, 0.0, 1.0, acc).unwrap();
    for (j, expect) in pts.iter().zip(&ra).rev() {
        assert_eq!(b.evaluate(&at(&b, j.0, j.1, j.2)).unwrap(), *expect);
    }
    a.clear();
    for (j, expect) in pts.iter().zip(&ra) {
        assert_eq!(a.evaluate(&at(&a, j.0, j.1, j.2)).unwrap(), *expect);
    }
}

#[test]
fn map_keeps_the_model_symmetries() {
    // −J reverses all forces; the mirror (J1, −J2, −J3) reverses J5, J6.
    // The fold makes both exact (bit-identical up to the sign).
    let mut map = Map::new(1.5, 0.0, 1.0, Accuracy::new(1e-3).unwrap()).unwrap();
    for &(j1, j2, j3) in &[(1.0, 0.5, 3.0), (0.3, -2.0, 8.0), (-4.0, 1.0, -20.0)] {
        let o = map.evaluate(&at(&map, j1, j2, j3)).unwrap();
        let n = map.evaluate(&at(&map, -j1, -j2, -j3)).unwrap();
        let m = map.evaluate(&at(&map, j1, -j2, -j3)).unwrap();
        assert_eq!((n.j4, n.j5, n.j6), (-o.j4, -o.j5, -o.j6));
        assert_eq!((m.j4, m.j5, m.j6), (o.j4, -o.j5, -o.j6));
        assert!(o.j7 >= 0.0 && n.j7 >= 0.0 && m.j7 >= 0.0);
    }
}

#[test]
fn zero_spin_and_extreme_inputs() {
    // J3 = 0: the exact closed form (App. V eq. 23); J = 0: zero; huge J's:
    // the rigid/plastic limit, finite; bad input: errors naming the value.
    let mut map = Map::new(2.0, 0.0, 1.0, Accuracy::new(1e-3).unwrap()).unwrap();
    let o = map.evaluate(&at(&map, 1.5, 0.5, 0.0)).unwrap();
    let (j4, j5) = traction_rheology::closed::combined_slip_traction(2.0, 1.5, 0.5);
    let j6 = traction_rheology::closed::combined_slip_torque(2.0, 1.5, 0.5);
    assert_eq!((o.j4, o.j5, o.j6), (j4, j5, j6));
    assert_eq!(map.evaluate(&at(&map, 0.0, 0.0, 0.0)).unwrap().j4, 0.0);
    for &s in &[1e6, 1e11, 1e99] {
        let o = map.evaluate(&at(&map, 0.3 * s, 0.1 * s, s)).unwrap();
        assert!(o.j4.is_finite() && o.j5.is_finite() && o.j6.is_finite() && o.j7 >= 0.0);
        assert!(o.j4.hypot(o.j5) <= 1.0 + 1e-3);
    }
    assert!(matches!(
        map.evaluate(&at(&map, f64::NAN, 0.0, 1.0)),
        Err(RheologyError::OutOfRange(OutOfRange { quantity: "J1", .. }))
    ));
    // Inputs of another geometry are refused by name.
    assert!(matches!(
        map.evaluate(&Inputs::new(3.0, 1.0, 0.0, 1.0).unwrap()),
        Err(RheologyError::MapKey { name: "k", .. })
    ));
    assert_eq!(
        Map::new(2.0, 0.0, 1.0, Accuracy::new(1e-6).unwrap())
            .unwrap_err()
            .to_string(),
        "map accuracy tol = 1e-6 is out of range: must be in [1e-4, 0.01]"
    );
    assert!(matches!(
        Map::new(500.0, 0.0, 1.0, Accuracy::new(1e-3).unwrap()),
        Err(RheologyError::OutOfRange(OutOfRange {
            quantity: "aspect ratio k",
            ..
        }))
    ));
}

#[test]
fn a_traction_curve_reuses_cells() {
    // A slip sweep at fixed spin (a traction curve, or a co-simulation
    // passing through a region of J space) builds a few cells and then
    // interpolates: ≥ 90 % of 400 points are interpolated, every one within tol.
    let tol = 1e-3;
    let k = 5.0;
    let mut map = Map::new(k, 0.0, 1.0, Accuracy::new(tol).unwrap()).unwrap();
    for n in 0..400 {
        let j1 = 0.02 * n as f64;
        let o = map.evaluate(&at(&map, j1, 0.3, 4.0)).unwrap();
        if n % 20 == 0 {
            let r = reference(k, (j1, 0.3, 4.0), 1e-5);
            assert!((o.j4 - r[0]).abs() <= tol && (o.j6 - r[2]).abs() <= tol);
        }
    }
    let s = map.stats();
    assert!(
        s.interpolated >= 360,
        "only {} of 400 interpolated ({s:?})",
        s.interpolated
    );
}

#[test]
fn rigid_plastic_map_meets_its_accuracy() {
    // The two-dimensional rigid/plastic map against traction_rheology::
    // rigid_plastic at 1e-5 (tolerance: the map's tol = 1e-3), 150 random
    // directions per k; the magnitude of J does not matter (1e99 included, near `J_MAX`).
    let tol = 1e-3;
    let mut rng = XorShift64::new(0x0123_4567_89ab_cdef);
    for &k in &[0.2, 1.0, 5.0] {
        let mut map = Map::new(k, 0.0, 1.0, Accuracy::new(tol).unwrap()).unwrap();
        for n in 0..150 {
            let j = random_j(&mut rng, k, 1.0);
            let s = if n % 10 == 0 { 1e99 } else { 1.0 };
            let m = map
                .rigid_plastic(&at(&map, s * j.0, s * j.1, s * j.2))
                .unwrap();
            let inp = Inputs::new(k, j.0, j.1, j.2).unwrap();
            let r = evaluate(&inp, Model::RigidPlastic, Accuracy::new(1e-5).unwrap()).unwrap();
            let err = (m.j4 - r.j4)
                .abs()
                .max((m.j5 - r.j5).abs())
                .max((m.j6 - r.j6).abs());
            assert!(err <= tol, "k {k} J {j:?}: {m:?} vs {r:?}");
            assert!(m.j7.is_finite() && m.j7 >= 0.0);
        }
        let s = map.stats();
        assert!(s.rigid_interpolated >= 140, "{s:?}");
    }
}

#[test]
fn a_budget_bounds_the_node_evaluations() {
    // Map::with_budget(Budget::DEFAULT): 0.5 node evaluations earned per
    // call, at most 65 spent in one. Scattered points with spin (|J1|, |J2|
    // ≤ 5, J3 in [5, 26], k = 5, each once): the node evaluations and cell
    // checks stay within 0.5 per call — counted, the bound by construction
    // that makes the map cost ≤ 1 + 0.5·7 direct evaluations per call —
    // where the map without budget spends more than 8 per call on the same
    // points; every result within tol of the reference (tol/100), whether
    // interpolated or evaluated directly. The rigid/plastic map alike.
    let (k, tol) = (5.0, 1e-3);
    let acc = Accuracy::new(tol).unwrap();
    let mut rng = XorShift64::new(0x0078_b0d9_e7aa_0001);
    let pts: Vec<_> = (0..60)
        .map(|_| {
            (
                10.0 * rng.unit() - 5.0,
                10.0 * rng.unit() - 5.0,
                5.0 + 21.0 * rng.unit(),
            )
        })
        .collect();
    let mut map = Map::new(k, 0.0, 1.0, acc)
        .unwrap()
        .with_budget(Budget::DEFAULT);
    let mut free = Map::new(k, 0.0, 1.0, acc).unwrap();
    for (n, j) in pts.iter().enumerate() {
        let o = map.evaluate(&at(&map, j.0, j.1, j.2)).unwrap();
        free.evaluate(&at(&free, j.0, j.1, j.2)).unwrap();
        let s = map.stats();
        assert!(
            (s.nodes_computed + s.cells_checked) as f64 <= 0.5 * (n + 1) as f64,
            "{s:?}"
        );
        if n % 3 == 0 {
            let r = reference(k, *j, tol / 100.0);
            for (x, y) in [o.j4, o.j5, o.j6].into_iter().zip(r) {
                assert!((x - y).abs() <= tol, "J {j:?}: {x} vs {y}");
            }
        }
    }
    let s = map.stats();
    assert!(s.over_budget > 40, "{s:?}");
    let f = free.stats();
    assert!(f.nodes_computed + f.cells_checked > 8 * 60, "{f:?}");
    // Rigid/plastic: its own credit.
    let mut map = Map::new(k, 0.0, 1.0, acc)
        .unwrap()
        .with_budget(Budget::DEFAULT);
    for (n, j) in pts.iter().enumerate() {
        let o = map.rigid_plastic(&at(&map, j.0, j.1, j.2)).unwrap();
        let s = map.stats();
        assert!(
            (s.nodes_computed + s.cells_checked) as f64 <= 0.5 * (n + 1) as f64,
            "{s:?}"
        );
        let inp = Inputs::new(k, j.0, j.1, j.2).unwrap();
        let r = evaluate(
            &inp,
            Model::RigidPlastic,
            Accuracy::new(tol / 100.0).unwrap(),
        )
        .unwrap();
        for (x, y) in [(o.j4, r.j4), (o.j5, r.j5), (o.j6, r.j6)] {
            assert!((x - y).abs() <= tol, "J {j:?}: {x} vs {y}");
        }
    }
    assert!(map.stats().rigid_over_budget > 0);
}

#[test]
fn a_budgeted_map_still_builds_a_visited_region() {
    // A traction curve (J1 from 0 to 8 at J2 = 0.3, J3 = 4), passed eight
    // times through a map with the default budget: the first calls are
    // direct (no credit yet), the cells are built as credit accrues, the
    // last pass is interpolated throughout; every value within tol of the
    // reference. The same calls on a second map, and on a clone taken
    // mid-way, give bit-identical results (the credit is part of the map);
    // clear() keeps the credit.
    let (k, tol) = (5.0, 1e-3);
    let acc = Accuracy::new(tol).unwrap();
    let mut map = Map::new(k, 0.0, 1.0, acc)
        .unwrap()
        .with_budget(Budget::DEFAULT);
    assert_eq!(map.credit(), Some([0.0; 2]));
    let curve: Vec<f64> = (0..200).map(|n| 0.04 * n as f64).collect();
    let mut results = Vec::new();
    let mut clone = None;
    let mut before_last = map.stats();
    for pass in 0..8 {
        if pass == 2 {
            clone = Some(map.clone());
        }
        before_last = map.stats();
        for (n, &j1) in curve.iter().enumerate() {
            let o = map.evaluate(&at(&map, j1, 0.3, 4.0)).unwrap();
            if n % 20 == 0 {
                let r = reference(k, (j1, 0.3, 4.0), 1e-5);
                assert!((o.j4 - r[0]).abs() <= tol && (o.j6 - r[2]).abs() <= tol);
            }
            results.push(o);
        }
    }
    let s = map.stats();
    assert_eq!(s.interpolated - before_last.interpolated, 200, "{s:?}");
    assert!(s.over_budget > 0, "{s:?}");
    let mut again = Map::new(k, 0.0, 1.0, acc)
        .unwrap()
        .with_budget(Budget::DEFAULT);
    let mut clone = clone.unwrap();
    for (n, expect) in results.iter().enumerate() {
        let j1 = curve[n % 200];
        assert_eq!(again.evaluate(&at(&again, j1, 0.3, 4.0)).unwrap(), *expect);
        if n >= 400 {
            assert_eq!(clone.evaluate(&at(&clone, j1, 0.3, 4.0)).unwrap(), *expect);
        }
    }
    assert_eq!(again.stats(), map.stats());
    let credit = map.credit();
    map.clear();
    assert_eq!(map.credit(), credit);
}

#[test]
fn budget_out_of_range_is_named() {
    for (args, name) in [
        ((-0.5, 0.0, 130.0, 4.0), "per_call"),
        ((0.5, 0.0, 0.5, 4.0), "cap"),
        ((0.5, 200.0, 130.0, 4.0), "initial"),
        ((0.5, 0.0, 130.0, f64::NAN), "limit"),
    ] {
        let e = Budget::new(args.0, args.1, args.2, args.3).unwrap_err();
        assert!(e.to_string().contains(name), "{e}");
    }
    assert_eq!(Budget::new(0.5, 0.0, 130.0, 65.0).unwrap(), Budget::DEFAULT);
}
