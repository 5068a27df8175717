//! Unit tests against exact solutions and exact identities.

use super::*;

const INF: f64 = f64::INFINITY;

fn rel(x: f64, y: f64) -> f64 {
    ((x - y) / y).abs()
}

/// Independent K, E by the arithmetic–geometric mean (A&S 17.6).
fn agm_e(m: f64) -> f64 {
    let (mut a, mut b) = (1.0_f64, (1.0 - m).sqrt());
    let (mut sum, mut pow2) = (0.5 * m, 0.5);
    for _ in 0..40 {
        let c = 0.5 * (a - b);
        pow2 *= 2.0;
        sum += pow2 * c * c;
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    std::f64::consts::FRAC_PI_2 / a * (1.0 - sum)
}

#[test]
fn sphere_on_flat_matches_closed_form() {
    // Closed form (Johnson 4.22/4.23): a = (3FR/4E*)^(1/3), P0 = 3F/(2πa²),
    // δ = a²/R; E* = E'/2. Different steel and aluminium to exercise E'.
    let r = 7.5e-3;
    let ball = Body::new(r, r, 210e9, 0.3);
    let flat = Body::new(INF, -INF, 70e9, 0.33);
    let f = 250.0;
    let c = solve_load(&ball, &flat, f).unwrap();
    let e_star = 1.0 / ((1.0 - 0.09) / 210e9 + (1.0 - 0.33 * 0.33) / 70e9);
    let a = (3.0 * f * r / (4.0 * e_star)).cbrt();
    // Same formula evaluated two ways: only round-off (a few ulp) may differ.
    assert!(rel(c.geometry.e_prime, 2.0 * e_star) < 1e-14);
    assert!(rel(c.a, a) < 1e-13 && rel(c.b, a) < 1e-13);
    assert!(rel(c.p0, 3.0 * f / (2.0 * PI * a * a)) < 1e-13);
    assert!(rel(c.approach, a * a / r) < 1e-13);
    assert!(rel(c.p_mean, f / (PI * a * a)) < 1e-13);
    assert!(rel(c.area, PI * a * a) < 1e-13);
    assert_eq!(c.k(), 1.0);
    assert!(rel(c.geometry.shape_a, 1.0) < 1e-15 && rel(c.geometry.shape_b, 1.0) < 1e-15);
    assert!(rel(c.geometry.elliptic_k, PI / 2.0) < 1e-15);
    assert!(rel(c.geometry.elliptic_e, PI / 2.0) < 1e-15);
}

#[test]
fn crossed_cylinders_equal_sphere_on_flat() {
    // Two equal cylinders crossed at 90° (axes along y and x) touch like a
    // sphere of the same radius on a flat (Johnson §4.2): exact identity.
    let r = 20e-3;
    let c1 = solve_load(&Body::steel(r, INF), &Body::steel(INF, r), 500.0).unwrap();
    let c2 = solve_load(&Body::steel(r, r), &Body::steel(INF, INF), 500.0).unwrap();
    assert!(rel(c1.a, c2.a) < 1e-14 && rel(c1.p0, c2.p0) < 1e-14);
    assert!(rel(c1.approach, c2.approach) < 1e-14);
}

#[test]
fn swapping_bodies_changes_nothing() {
    let b1 = Body::new(30e-3, 200e-3, 200e9, 0.28);
    let b2 = Body::new(70e-3, -400e-3, 110e9, 0.34);
    let c12 = solve_load(&b1, &b2, 800.0).unwrap();
    let c21 = solve_load(&b2, &b1, 800.0).unwrap();
    // Only the order of two floating-point additions differs: 1e-14.
    for (x, y) in [
        (c12.a, c21.a),
        (c12.b, c21.b),
        (c12.p0, c21.p0),
        (c12.approach, c21.approach),
        (c12.geometry.c, c21.geometry.c),
    ] {
        assert!(rel(x, y) < 1e-14, "{x} vs {y}");
    }
}

#[test]
fn swapping_x_and_y_inverts_k() {
    // Turning both bodies by 90° swaps a and b, k → 1/k; P0, δ unchanged;
    // A(k) = B(1/k). Tolerance: the root solves on either side agree to
    // ~1e-15, propagated through cube roots: 1e-13.
    let c = solve_load(
        &Body::steel(25e-3, 36.5e-3),
        &Body::steel(25e-3, INF),
        300.0,
    )
    .unwrap();
    let t = solve_load(
        &Body::steel(36.5e-3, 25e-3),
        &Body::steel(INF, 25e-3),
        300.0,
    )
    .unwrap();
    assert!(rel(c.k(), 1.0 / t.k()) < 1e-13);
    assert!(rel(c.a, t.b) < 1e-13 && rel(c.b, t.a) < 1e-13);
    assert!(rel(c.p0, t.p0) < 1e-13 && rel(c.approach, t.approach) < 1e-13);
    assert!(rel(c.geometry.shape_a, t.geometry.shape_b) < 1e-13);
}

#[test]
fn load_equals_two_thirds_pi_a_b_p0() {
    // at_load gets a from a³ = 3A³ReF/E' and P0 from equation (1); the
    // Hertz force balance F = (2/3)πabP0 ties them. Round-off only: 1e-13.
    for (ry1, f) in [(4.3e-3, 50.0), (12.5e-3, 416.0), (150.4e-3, 1400.0)] {
        let c = solve_load(&Body::steel(25e-3, ry1), &Body::steel(25e-3, INF), f).unwrap();
        assert!(rel(2.0 / 3.0 * PI * c.a * c.b * c.p0, f) < 1e-13);
        // Inverse problem reproduces the load and the contact.
        let back = c.geometry.at_p0(c.p0).unwrap();
        assert!(rel(back.load, f) < 1e-13 && rel(back.a, c.a) < 1e-13);
    }
}

#[test]
fn root_solve_reaches_1e_12() {
    // k → Cx/Cy → k over the whole supported range (log-spaced, both sides
    // of 1) to K_TOLERANCE = 1e-12 relative.
    for i in 0..=600 {
        let k = (K_MIN.ln() + (K_MAX.ln() - K_MIN.ln()) * f64::from(i) / 600.0).exp();
        let rho = curvature_ratio(k).unwrap();
        let back = aspect_ratio(rho).unwrap();
        assert!(rel(back, k) < K_TOLERANCE, "k = {k}: {back}");
    }
}

#[test]
fn shape_factors_equal_the_elliptic_e_forms() {
    // A³ = 2E(1−k²)/(πk²) (k ≤ 1) and 2E(1−1/k²)/(πk) (k ≥ 1) with E by AGM,
    // an independent evaluation; 1e-13 relative.
    for &k in &[0.05, 0.2, 0.5, 0.9, 1.1, 2.0, 5.0, 20.0] {
        let (a, b) = shape_factors(k).unwrap();
        let a3 = if k <= 1.0 {
            2.0 * agm_e(1.0 - k * k) / (PI * k * k)
        } else {
            2.0 * agm_e(1.0 - 1.0 / (k * k)) / (PI * k)
        };
        assert!(rel(a * a * a, a3) < 1e-13, "k = {k}");
        assert!(rel(b, k * a) < 1e-15);
        // A(k) = B(1/k), exactly in theory; round-off here.
        let (a_inv, b_inv) = shape_factors(1.0 / k).unwrap();
        assert!(rel(a, b_inv) < 1e-13 && rel(b, a_inv) < 1e-13);
    }
}

#[test]
fn continuous_through_k_equal_one() {
    // Near equal curvatures nothing cancels (Carlson forms): k, A, K, E
    // approach their k = 1 values linearly in the curvature difference.
    let base = solve_load(&Body::steel(10e-3, 10e-3), &Body::steel(INF, INF), 100.0).unwrap();
    for &eps in &[1e-4, 1e-7, 1e-10, 1e-13] {
        for s in [1.0, -1.0] {
            let c = solve_load(
                &Body::steel(10e-3, 10e-3 * (1.0 + s * eps)),
                &Body::steel(INF, INF),
                100.0,
            )
            .unwrap();
            // dk/d(ratio) ≈ 0.6 at k = 1; bound the change by 1·eps + round-off.
            assert!((c.k() - 1.0).abs() <= eps + 1e-15, "eps {eps}: k {}", c.k());
            assert!((c.k() > 1.0) == (s > 0.0) || eps < 1e-12);
            for (x, y) in [
                (c.a, base.a),
                (c.p0, base.p0),
                (c.approach, base.approach),
                (c.geometry.shape_a, 1.0),
                (c.geometry.elliptic_k, PI / 2.0),
                (c.geometry.elliptic_e, PI / 2.0),
            ] {
                assert!(rel(x, y) <= eps + 1e-14, "eps {eps}: {x} vs {y}");
            }
        }
    }
}

#[test]
fn approach_matches_direct_quadrature() {
    // Displacement at the centre from the pressure by Boussinesq:
    // δ = (1/πE*) ∬ p/r dA = (P0/4E*) ∫₀^{2π} ρ(θ) dθ, ρ(θ) the ellipse radius
    // in direction θ. The integrand is smooth and periodic, so the trapezoid
    // rule converges geometrically: 4000 points give round-off, 1e-12.
    for ry1 in [4.3e-3, 150.4e-3] {
        let c = solve_load(&Body::steel(25e-3, ry1), &Body::steel(25e-3, INF), 700.0).unwrap();
        let n = 4000;
        let mut s = 0.0;
        for i in 0..n {
            let th = 2.0 * PI * f64::from(i) / f64::from(n);
            let (co, si) = (th.cos(), th.sin());
            s += 1.0 / (co * co / (c.a * c.a) + si * si / (c.b * c.b)).sqrt();
        }
        let integral = s * 2.0 * PI / f64::from(n);
        let e_star = c.geometry.e_prime / 2.0;
        assert!(rel(c.approach, c.p0 / (4.0 * e_star) * integral) < 1e-12);
    }
}

#[test]
fn gap_is_reproduced_by_the_pressure() {
    // Hertz condition: the displacement from the pressure must make up the
    // gap ½Cx x² inside the ellipse. Check the x-direction coefficient against
    // Johnson's K/E form with K, E from AGM (independent of R_D):
    // ½Cx = (P0/E*)(b/(e²a²))(K − E) for a the major semi-axis (k < 1).
    let c = solve_load(&Body::steel(25e-3, 4.3e-3), &Body::steel(25e-3, INF), 200.0).unwrap();
    assert!(c.k() < 1.0);
    let m = 1.0 - c.k() * c.k();
    let e = agm_e(m);
    let k_int = elliptic::complete_k(m);
    let e_star = c.geometry.e_prime / 2.0;
    let half_cx = c.p0 / e_star * c.b / (m * c.a * c.a) * (k_int - e);
    // K − E loses ~1 digit to cancellation at m ≈ 0.76: 1e-12.
    assert!(rel(half_cx, 0.5 * c.geometry.curvature_x) < 1e-12);
    let half_cy = c.p0 / e_star * c.b / (m * c.a * c.a) * (e / (c.k() * c.k()) - k_int);
    assert!(rel(half_cy, 0.5 * c.geometry.curvature_y) < 1e-12);
}

fn msg(r: Result<Contact, HertzError>) -> String {
    r.unwrap_err().to_string()
}

#[test]
fn invalid_input_names_quantity_and_range() {
    let s = Body::steel(10e-3, 10e-3);
    let flat = Body::steel(INF, INF);
    let m = msg(solve_load(&s, &flat, -1.0));
    assert!(m.contains("load") && m.contains("> 0"), "{m}");
    assert!(msg(solve_load(&s, &flat, f64::NAN)).contains("load"));
    assert!(msg(solve_load(&s, &flat, 0.0)).contains("load"));
    assert!(msg(solve_p0(&s, &flat, -1e9)).contains("p0"));
    assert!(msg(solve_p0(&s, &flat, f64::INFINITY)).contains("p0"));
    let m = msg(solve_load(&Body::steel(0.0, 1.0), &flat, 1.0));
    assert!(m.contains("rx1") && m.contains("non-zero"), "{m}");
    assert!(msg(solve_load(&Body::steel(1.0, f64::NAN), &flat, 1.0)).contains("ry1"));
    assert!(msg(solve_load(&s, &Body::steel(0.0, 1.0), 1.0)).contains("rx2"));
    assert!(msg(solve_load(&s, &Body::steel(1.0, 0.0), 1.0)).contains("ry2"));
    let m = msg(solve_load(&Body::new(1.0, 1.0, 0.0, 0.3), &flat, 1.0));
    assert!(m.contains("e1") && m.contains("> 0"), "{m}");
    assert!(msg(solve_load(&s, &Body::new(INF, INF, -2e9, 0.3), 1.0)).contains("e2"));
    let m = msg(solve_load(&Body::new(1.0, 1.0, 1e9, 0.5), &flat, 1.0));
    assert!(m.contains("nu1") && m.contains("(-1, 0.5)"), "{m}");
    assert!(msg(solve_load(&s, &Body::new(INF, INF, 1e9, -1.0), 1.0)).contains("nu2"));
    assert!(msg(solve_load(&s, &Body::new(INF, INF, 1e9, f64::NAN), 1.0)).contains("nu2"));
    // Conformal: concave radius equal to (or smaller than) the convex one.
    let m = msg(solve_load(&s, &Body::steel(-10e-3, INF), 1.0));
    assert!(m.contains("along x") && m.contains("> 0"), "{m}");
    assert!(msg(solve_load(&s, &Body::steel(INF, -9e-3), 1.0)).contains("along y"));
    // Line contact: both flat across x.
    let m = msg(solve_load(&Body::steel(10e-3, INF), &flat, 1.0));
    assert!(m.contains("along y") && m.contains("line contact"), "{m}");
    // Nearly a line contact: k beyond K_MAX.
    let m = msg(solve_load(&Body::steel(1e-3, 1e6), &flat, 1.0));
    assert!(m.contains("aspect ratio") && m.contains("1000"), "{m}");
    assert!(shape_factors(0.0).is_err() && curvature_ratio(2e3).is_err());
    assert!(aspect_ratio(f64::NAN).is_err() && aspect_ratio(-1.0).is_err());
}

#[test]
fn hamrock_brewe_error_is_as_documented() {
    // Measured maximum relative error of the Hamrock–Brewe fits against the
    // exact solution over 0.05 ≤ k ≤ 20 (2001 log-spaced k, fixed load).
    // Documented values (Method::HamrockBrewe, README): k 7.3 %, a and b
    // 4.8 %, P0 2.4 %, approach 5.5 %. The bounds below are those values
    // rounded up; the test fails if the fits or the exact path change.
    let mut worst = [0.0_f64; 4];
    for i in 0..=2000 {
        let k = (0.05_f64.ln() + (20.0_f64.ln() - 0.05_f64.ln()) * f64::from(i) / 2000.0).exp();
        let rho = curvature_ratio(k).unwrap();
        let b1 = Body::steel(0.01 / rho, 0.01);
        let b2 = Body::steel(INF, INF);
        let e = Geometry::new(&b1, &b2).unwrap().at_load(100.0).unwrap();
        let h = Geometry::with_method(&b1, &b2, Method::HamrockBrewe)
            .unwrap()
            .at_load(100.0)
            .unwrap();
        let errs = [
            rel(h.k(), e.k()),
            rel(h.a, e.a).max(rel(h.b, e.b)),
            rel(h.p0, e.p0),
            rel(h.approach, e.approach),
        ];
        for (w, x) in worst.iter_mut().zip(errs) {
            *w = w.max(x);
        }
    }
    let bounds = [0.073, 0.048, 0.024, 0.055];
    for (w, b) in worst.iter().zip(bounds) {
        assert!(*w < b, "{worst:?}");
    }
    // And it is a real approximation, not the exact path by accident.
    assert!(worst[0] > 0.01, "{worst:?}");
}

#[test]
fn inputs_in_range_whose_contact_leaves_the_float_range_are_refused() {
    // Each input is finite and positive, so each passes its range, but the
    // contact was returned with a = b = inf or p0 = 0 or inf (`traction
    // hertz` printed inf; the contact crate failed later with "J3 = NaN").
    let steel = |rx, ry| Body::steel(rx, ry);
    let soft = Body::new(0.03, 0.03, 1e-320, 0.3);
    let cases: [(Body, Body, Option<f64>, Option<f64>); 6] = [
        (soft, steel(0.07, INF), Some(500.0), None),
        (soft, steel(0.07, INF), None, Some(1.5e9)),
        (steel(0.03, 0.03), steel(0.07, INF), None, Some(1e308)),
        (
            steel(1e-300, 1e-300),
            steel(1e-300, 1e-300),
            Some(1e-300),
            None,
        ),
        (steel(1e300, 1e300), steel(1e300, 1e300), Some(500.0), None),
        (
            Body::new(0.03, 0.03, 1e-100, 0.3),
            Body::new(0.07, INF, 1e-100, 0.3),
            Some(1e300),
            None,
        ),
    ];
    for (b1, b2, load, p0) in cases {
        let r = match (load, p0) {
            (Some(f), _) => solve_load(&b1, &b2, f),
            (_, Some(p)) => solve_p0(&b1, &b2, p),
            _ => unreachable!(),
        };
        assert!(
            matches!(r, Err(HertzError::OutOfFloatRange { .. })),
            "{b1:?} {b2:?} {load:?} {p0:?}: {r:?}"
        );
    }
    // The extremes of ordinary use stay valid: 1 µN on a 1 mm steel ball
    // and 1 GN on a 1 m roller.
    assert!(solve_load(&steel(1e-3, 1e-3), &steel(INF, INF), 1e-6).is_ok());
    assert!(solve_load(&steel(1.0, 1.0), &steel(INF, INF), 1e9).is_ok());
}
