//! CLI tests of `traction jt` (batch evaluation of the J+T model).
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

mod common;
use common::run;

#[test]
fn zero_spin_row_reproduces_equation_22_and_keeps_columns() {
    let (ok, out, err) = run(
        &["jt", "--input", "-", "--output", "-"],
        "k,J1,J2,J3,dX,note_free\n1,1.5,0,0,0.1,7\n",
    );
    assert!(ok, "{err}");
    let mut lines = out.lines();
    assert_eq!(lines.next().unwrap(), "k,J1,J2,J3,dX,note_free,J4,J5,J6,J7");
    let cells: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(&cells[..6], &["1", "1.5", "0", "0", "0.1", "7"]);
    let j4: f64 = cells[6].parse().unwrap();
    // App. V eq. 22 at S = 1: ψ = (2/π)(π/4 + 1/2) = 0.5 + 1/π (exact; the
    // zero-spin path is the closed form): 1e-12.
    assert!(
        (j4 - (0.5 + 1.0 / std::f64::consts::PI)).abs() < 1e-12,
        "{j4}"
    );
    let j7: f64 = cells[9].parse().unwrap();
    assert!((j7 - 1.5 * j4).abs() < 1e-12);
}

#[test]
fn models_and_spin_rows() {
    let input = "k,J1,J2,J3,D\n1,1,0,2,1e9\n5,0,3.36839582,25.8161723,1e9\n";
    for model in ["elastic-plastic", "rigid-plastic", "viscoelastic"] {
        let (ok, out, err) = run(&["jt", "--model", model, "--tol", "1e-3"], input);
        assert!(ok, "{model}: {err}");
        assert_eq!(out.lines().count(), 3);
        for l in out.lines().skip(1) {
            for c in l.split(',') {
                let v: f64 = c.parse().unwrap();
                assert!(v.is_finite(), "{model}: {l}");
            }
        }
    }
}

#[test]
fn errors_name_row_and_column() {
    let (ok, _, err) = run(&["jt"], "k,J1,J2,J3\n1,1,0,0\n1,x,0,0\n");
    assert!(!ok);
    assert!(err.contains("row 2") && err.contains("`J1`"), "{err}");
    let (ok, _, err) = run(&["jt"], "k,J1,J2,J3\n1,1,0,0\n500,1,0,0\n");
    assert!(!ok);
    assert!(
        err.contains("row 2") && err.contains("aspect ratio"),
        "{err}"
    );
    let (ok, _, err) = run(&["jt"], "k,J1,J3\n1,1,0\n");
    assert!(!ok && err.contains("J2"), "{err}");
    let (ok, _, err) = run(
        &["jt", "--model", "viscoelastic"],
        "k,J1,J2,J3,D\n1,1,0,0,-1\n",
    );
    assert!(
        !ok && err.contains("Deborah") && err.contains("row 1"),
        "{err}"
    );
    let (ok, _, err) = run(&["jt", "--tol", "0"], "k,J1,J2,J3\n1,1,0,0\n");
    assert!(!ok && err.contains("tol"), "{err}");
    let (ok, _, err) = run(&["jt"], "k,J1,J2,J3\n1,inf,0,0\n");
    assert!(!ok && err.contains("J1"), "{err}");
}

#[test]
fn stiffness_ratio_column() {
    // Side slip only with gy: the isotropic model at J2' = gy·J2 (exact
    // reduction, see rheology tests/anisotropy.rs): compare the two rows'
    // J5 to 1e-6 (tol 1e-8); a gy outside [0.1, 10] names the row.
    let (ok, out, err) = run(
        &["jt", "--tol", "1e-8"],
        "k,J1,J2,J3,gy\n2,0,0.7,0,1.6\n2,0,1.12,0,1\n",
    );
    assert!(ok, "{err}");
    let j5: Vec<f64> = out
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(6).unwrap().parse().unwrap())
        .collect();
    assert!((j5[0] - j5[1]).abs() < 1e-6, "{j5:?}");
    let (ok, _, err) = run(&["jt"], "k,J1,J2,J3,gy\n1,1,0,1,1\n1,1,0,1,20\n");
    assert!(
        !ok && err.contains("row 2") && err.contains("stiffness ratio"),
        "{err}"
    );
}

/// The J4, J5, J6 cells of each row of `jt` output whose input columns are
/// `k,J1,J2,J3`.
fn j4_j5_j6(out: &str) -> Vec<[f64; 3]> {
    out.lines()
        .skip(1)
        .map(|l| {
            let c: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            [c[4], c[5], c[6]]
        })
        .collect()
}

#[test]
fn map_option_agrees_with_direct_evaluation() {
    // --map: 120 rows of a slip sweep at two spins and two k's; every row
    // within tol = 1e-3 of the direct evaluation at 1e-5 (the map's contract,
    // traction-rheology tests/map.rs; groups this small fall back to direct
    // evaluation, see the next test); --map with another model or a tol
    // outside [1e-4, 1e-2] is a usage error.
    let mut input = String::from("k,J1,J2,J3\n");
    for n in 0..30 {
        for (k, j3) in [(1.0, 2.0), (5.0, 25.8)] {
            input += &format!("{k},{},0.3,{j3}\n", 0.1 * f64::from(n));
            input += &format!("{k},{},-0.3,{}\n", -0.1 * f64::from(n), -j3);
        }
    }
    let (ok, mapped, err) = run(&["jt", "--map", "--tol", "1e-3"], &input);
    assert!(ok, "{err}");
    let (ok, direct, err) = run(&["jt", "--tol", "1e-5"], &input);
    assert!(ok, "{err}");
    let (m, d) = (j4_j5_j6(&mapped), j4_j5_j6(&direct));
    assert_eq!(m.len(), 120);
    for (a, b) in m.iter().zip(&d) {
        for i in 0..3 {
            assert!((a[i] - b[i]).abs() <= 1e-3, "{a:?} vs {b:?}");
        }
    }
    let (ok, _, err) = run(&["jt", "--map", "--model", "rigid-plastic"], &input);
    assert!(!ok && err.contains("--map"), "{err}");
    let (ok, _, err) = run(&["jt", "--map", "--tol", "1e-6"], &input);
    assert!(!ok && err.contains("--map"), "{err}");
}

#[test]
fn map_option_is_used_only_where_it_pays_off() {
    // A dense group: 600 rows of a slip sweep within 2 % of one state at
    // k = 1 need one or two cells (≤ 130 node evaluations, within the budget
    // of 0.5 per row): interpolated (some row differs from the direct value),
    // every row within tol = 1e-3 of the direct evaluation at 1e-5.
    let mut dense = String::from("k,J1,J2,J3\n");
    for n in 0..600 {
        dense += &format!("1,{},0.3,2\n", 1.5 + 5e-5 * f64::from(n));
    }
    let (ok, mapped, err) = run(&["jt", "--map", "--tol", "1e-3"], &dense);
    assert!(ok, "{err}");
    let (ok, direct, err) = run(&["jt", "--tol", "1e-3"], &dense);
    assert!(ok, "{err}");
    let (ok, fine, err) = run(&["jt", "--tol", "1e-5"], &dense);
    assert!(ok, "{err}");
    let (m, d, f) = (j4_j5_j6(&mapped), j4_j5_j6(&direct), j4_j5_j6(&fine));
    assert!(
        m.iter().zip(&d).any(|(a, b)| a != b),
        "the map was not used"
    );
    for (a, b) in m.iter().zip(&f) {
        for i in 0..3 {
            assert!((a[i] - b[i]).abs() <= 1e-3, "{a:?} vs {b:?}");
        }
    }
    // A scattered group: 40 rows over |J1|, |J2| ≤ 5, J3 ∈ [5, 26] at k = 2
    // open a new cell (64 nodes) nearly every row, far beyond the budget: the
    // group is evaluated directly, bit-identical to the run without --map.
    let mut scattered = String::from("k,J1,J2,J3\n");
    for n in 0..40 {
        let t = f64::from(n);
        scattered += &format!(
            "2,{},{},{}\n",
            5.0 * (1.7 * t).sin(),
            5.0 * (2.3 * t).cos(),
            15.5 + 10.5 * (0.9 * t).sin()
        );
    }
    let (ok, mapped, err) = run(&["jt", "--map", "--tol", "1e-3"], &scattered);
    assert!(ok, "{err}");
    let (ok, direct, err) = run(&["jt", "--tol", "1e-3"], &scattered);
    assert!(ok, "{err}");
    assert_eq!(mapped, direct);
}
