//! Unit tests of the thermal model's parts: the flash temperature constants
//! and resistances (`flash.rs`), the Hamrock–Dowson film and the inlet
//! heating factor (`film.rs`), the fixed-point solver (`fixed_point.rs`) and
//! the first step's slope of `ContactThermal` (`contact_thermal.rs`). The
//! thermal contact as a whole is tested in `contact/tests/thermal.rs`.

use std::f64::consts::PI;

use super::*;

/// c∞ by quadrature: the mean over the ellipse of 2√(χ t/π)/K with
/// t = (x + l(y))/v (inner integral exact, outer by the midpoint rule in
/// y = sin φ, which removes the endpoint singularity): an independent
/// evaluation of the closed form.
#[test]
fn high_peclet_constant_is_the_ellipse_mean_of_the_transient_solution() {
    let n = 4000;
    let (mut sum, mut area) = (0.0, 0.0);
    for i in 0..n {
        let phi = -PI / 2.0 + (i as f64 + 0.5) * PI / n as f64;
        let (y, dy) = (phi.sin(), phi.cos());
        let l = (1.0 - y * y).sqrt();
        // ∫_{-l}^{l} √(x + l) dx = (2/3)(2l)^{3/2}
        sum += 2.0 / 3.0 * (2.0 * l).powf(1.5) * dy;
        area += 2.0 * l * dy;
    }
    // T̄ = (2/√π)·mean√s·√(χ/v)·q/K = (2/√π)(mean/√2)·q a/(K√Pe), Pe = v a/(2χ).
    let c = 2.0 / PI.sqrt() * (sum / area) / 2f64.sqrt();
    assert!((c - FLASH_HIGH_PECLET).abs() < 1e-6, "{c}");
    // Band source (strip of uniform length 2a): 4/(3√π) = 0.7523, i.e.
    // Jaeger's 1.064·(q a/K)·√(χ/(V a)) (1.064/√2 = 0.7523).
    assert!((4.0 / (3.0 * PI.sqrt()) - 1.064 / 2f64.sqrt()).abs() < 1e-3);
}

#[test]
fn surface_resistance_limits() {
    let (a, b, k, rc) = (0.5e-3, 2.5e-3, 46.6, 3.7e6);
    // Stationary: 8/(3π) √(ab)/K.
    let r0 = surface_resistance(a, b, [0.0, 0.0], k, rc);
    assert!((r0 - FLASH_STATIONARY * (a * b).sqrt() / k).abs() < 1e-15);
    // Fast along x: c∞ a/(K √Pe), Pe = v a/(2χ); the blend's relative
    // correction is (1/2)(r∞²/(r0² Pe)) ≈ 3e-5 at v = 1000 m/s.
    let v = 1000.0;
    let pe = v * a / (2.0 * k / rc);
    let r = surface_resistance(a, b, [v, 0.0], k, rc);
    let high = FLASH_HIGH_PECLET * a / (k * pe.sqrt());
    assert!((r / high - 1.0).abs() < 1e-4, "{}", r / high);
    // Motion along y uses the half-chord b.
    let ry = surface_resistance(a, b, [0.0, v], k, rc);
    let pey = v * b / (2.0 * k / rc);
    assert!((ry / (FLASH_HIGH_PECLET * b / (k * pey.sqrt())) - 1.0).abs() < 1e-3);
    // Monotone: faster surfaces run cooler.
    let mut last = f64::INFINITY;
    for v in [0.0, 0.01, 0.1, 1.0, 10.0, 100.0] {
        let r = surface_resistance(a, b, [v, 0.0], k, rc);
        assert!(r < last);
        last = r;
    }
}

#[test]
fn hamrock_dowson_scaling() {
    // h ∝ (η₀U)^0.67 α^0.53 N^−0.067 exactly (the formula's powers).
    let h = |u: f64, eta: f64, al: f64, n: f64| {
        hamrock_dowson_central(0.02, 2.3e11, 5.0, n, u, eta, al)
    };
    let h0 = h(20.0, 0.01, 2e-8, 1000.0);
    assert!((h(40.0, 0.01, 2e-8, 1000.0) / h0 - 2f64.powf(0.67)).abs() < 1e-12);
    assert!((h(20.0, 0.02, 2e-8, 1000.0) / h0 - 2f64.powf(0.67)).abs() < 1e-12);
    assert!((h(20.0, 0.01, 4e-8, 1000.0) / h0 - 2f64.powf(0.53)).abs() < 1e-12);
    assert!((h(20.0, 0.01, 2e-8, 2000.0) / h0 - 2f64.powf(-0.067)).abs() < 1e-12);
    assert_eq!(h(0.0, 0.01, 2e-8, 1000.0), 0.0);
    // Order of magnitude of an EHL film at 20 m/s, 10 mPa·s: ~1 µm.
    assert!(h0 > 1e-7 && h0 < 3e-6, "{h0}");
}

/// Gupta et al.'s (1992) factor against the printed formula evaluated
/// independently of this code (double precision, Python: 19.65 is
/// L of the report fluids' η₀(73 °C) = 11.25 mPa·s, β_η = 0.030028 1/K,
/// k_f = 0.11 W/(m·K) at 80 m/s), its limits and its range.
#[test]
fn inlet_heating_factor_values_limits_and_errors() {
    let l = thermal_loading(0.030028496668020384, 0.011248191075924476, 80.0, 0.11);
    assert!((l / 19.651855606961732 - 1.0).abs() < 1e-14, "{l}");
    for (l, pr, s, want) in [
        (19.651855606961732, 0.0064, 0.0, 0.289755353272615),
        (1.344, 0.006, 0.05, 0.697504858586546),
        (39.2, 0.0064, 0.0, 0.18755929055361922),
    ] {
        let got = inlet_heating_factor(l, pr, s).unwrap();
        assert!((got / want - 1.0).abs() < 1e-12, "{l} {pr} {s}: {got}");
    }
    // No loading, no reduction; less film with more loading or sliding.
    assert_eq!(inlet_heating_factor(0.0, 0.006, 0.0).unwrap(), 1.0);
    let mut last = 1.0;
    for l in [0.1, 1.0, 10.0, 50.0, 100.0] {
        let f = inlet_heating_factor(l, 0.006, 0.0).unwrap();
        assert!(f < last && f > 0.0, "{l}: {f}");
        assert!(inlet_heating_factor(l, 0.006, 0.5).unwrap() < f);
        last = f;
    }
    // Beyond the positive numerator (L ≈ 124 at p_h/E' = 0.01), outside
    // the slide-to-roll and pressure ranges, NaN: errors naming them.
    for (l, pr, s, name) in [
        (130.0, 0.01, 0.0, "thermal loading"),
        (-1.0, 0.006, 0.0, "thermal loading"),
        (f64::NAN, 0.006, 0.0, "thermal loading"),
        (1.0, 0.006, 2.5, "slide-to-roll ratio"),
        (1.0, 0.2, 0.0, "p_h/E'"),
    ] {
        let e = inlet_heating_factor(l, pr, s).unwrap_err().to_string();
        assert!(e.contains(name), "{l} {pr} {s}: {e}");
    }
    assert!(inlet_heating_factor(120.0, 0.01, 0.0).unwrap() > 0.0);
}

/// x = A e^{−b x} has the exact solution x = W(A b)/b (Lambert W).
#[test]
fn fixed_point_matches_lambert_w() {
    for (a, b) in [(50.0, 0.01), (300.0, 0.02), (5.0, 0.5), (1000.0, 0.001)] {
        let (x, n) = solve_fixed_point(0.0, |x| Ok(a * f64::exp(-b * x))).unwrap();
        // Lambert W by Halley iteration (independent of the solver).
        let z: f64 = a * b;
        let mut w = z.ln_1p();
        for _ in 0..100 {
            let e = w.exp();
            let f = w * e - z;
            w -= f / (e * (w + 1.0) - (w + 2.0) * f / (2.0 * w + 2.0));
        }
        let exact = w / b;
        assert!(
            (x - exact).abs() <= TEMPERATURE_TOLERANCE.max(2e-3 * exact),
            "{a} {b}: {x} vs {exact}"
        );
        // Exact model: the exponential step lands on the root at once.
        assert!(n <= 4, "{n} evaluations");
    }
}

#[test]
fn slope_hint_saves_evaluations_not_accuracy() {
    let tol = |x: f64| TEMPERATURE_TOLERANCE.max(TEMPERATURE_RELATIVE_TOLERANCE * x);
    for (a, b) in [(50.0, 0.01), (300.0, 0.02), (5.0, 0.5), (1000.0, 0.001)] {
        let f = |x: f64| a * f64::exp(-b * x);
        let (x0, n0) = solve_fixed_point(10.0, |x| Ok(f(x))).unwrap();
        // The exact slope of an exponential f: the first Newton step of
        // the model is the root, found at the second evaluation.
        let (x1, n1) = solve_fixed_point_with_slope(10.0, |x| Ok((f(x), -b))).unwrap();
        assert_eq!(n1, 2, "{a} {b}: {n1} evaluations (without the slope {n0})");
        // A poor slope (ten times too steep or of the wrong sign) costs
        // evaluations only.
        for s in [-10.0 * b, b] {
            let (x2, _) = solve_fixed_point_with_slope(10.0, |x| Ok((f(x), s))).unwrap();
            assert!(
                (x2 - x0).abs() <= 2.0 * tol(x0),
                "{a} {b} {s}: {x2} vs {x0}"
            );
        }
        // Both within the solver's tolerance of each other (each of the root).
        assert!((x1 - x0).abs() <= 2.0 * tol(x0), "{a} {b}: {x1} vs {x0}");
        // A zero slope is the plain solver, evaluation for evaluation.
        let (x3, n3) = solve_fixed_point_with_slope(10.0, |x| Ok((f(x), 0.0))).unwrap();
        assert_eq!((x3, n3), (x0, n0));
    }
}

/// With a second-order term the loss is not exponential in the rise; the
/// chord slope of the first step makes a loss that follows the law at
/// constant e converge at the second evaluation, on the root found by
/// bisection.
#[test]
fn chord_slope_lands_on_the_root_of_the_second_order_law() {
    let tol = |x: f64| TEMPERATURE_TOLERANCE.max(TEMPERATURE_RELATIVE_TOLERANCE * x);
    let model = ContactThermal {
        beta_mu: 0.0005,
        beta_m: 0.0,
        inv_scale_sq: 1.0 / (480.0 * 480.0),
        rise_per_watt: 1.0,
        reference_rise: 50.0,
    };
    for e in [1.0, 1.5, 2.0] {
        for a in [20.0, 300.0, 600.0, 1500.0] {
            let f = |x: f64| a * model.log_loss_ratio(e, 50.0, x).exp();
            let (x, n) =
                solve_fixed_point_with_slope(50.0, |x| Ok((f(x), model.chord_slope(e, x, f(x)))))
                    .unwrap();
            let (mut lo, mut hi) = (0.0, 2000.0);
            for _ in 0..80 {
                let mid = 0.5 * (lo + hi);
                if mid < f(mid) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            assert!((x - lo).abs() <= tol(lo), "{e} {a}: {x} vs {lo}");
            assert_eq!(n, 2, "{e} {a}: {n} evaluations");
        }
    }
}

/// The slope estimate is exact without spin: e = d ln J7/d ln |J| of the
/// closed form (eq. 23), against a central difference of the closed form.
#[test]
fn log_slope_matches_the_closed_form_without_spin() {
    let model = ContactThermal {
        beta_mu: 0.003,
        beta_m: 0.001,
        inv_scale_sq: 1.0 / (480.0 * 480.0),
        rise_per_watt: 1.0,
        reference_rise: 0.0,
    };
    for ((k, j1, j2), dt) in [
        (1.0, 0.3, 0.1),
        (5.0, 6.2, 10.1),
        (0.5, 2.0, -1.0),
        (2.0, 40.0, 3.0),
    ]
    .into_iter()
    .zip([0.0, 50.0, 200.0, 350.0])
    {
        let j7 = |l: f64| {
            let (j4, j5) = traction_rheology::closed::combined_slip_traction(k, l * j1, l * j2);
            l * (j1 * j4 + j2 * j5)
        };
        let h = 1e-5;
        let e = (j7(1.0 + h).ln() - j7(1.0 - h).ln()) / ((1.0 + h).ln() - (1.0 - h).ln());
        // d ln μ/dΔT of the second-order law at ΔT = dt.
        let dln_mu = -model.beta_mu - 2.0 * dt / (480.0 * 480.0);
        let exact = dln_mu * (2.0 - e) - model.beta_m * e;
        let j = [j1, j2, 0.0, 0.0, 0.0, 0.0, j7(1.0)];
        // Central difference error O(h²) ≈ 1e-10 relative.
        // rise = dt: the local slope (no chord).
        let got = model.log_slope(k, &j, dt, dt);
        assert!(
            (got - exact).abs() <= 1e-8 * exact.abs(),
            "{k} {j1} {j2}: {got} vs {exact}"
        );
    }
}

#[test]
fn fixed_point_zero_heat_and_runaway() {
    assert_eq!(solve_fixed_point(0.0, |_| Ok(0.0)).unwrap().0, 0.0);
    // A rise that grows faster than the temperature: runaway, an error.
    let e = solve_fixed_point(0.0, |x| Ok(10.0 + 2.0 * x)).unwrap_err();
    assert!(e.to_string().contains("runaway"), "{e}");
    // NaN from the model is an error, never a silent NaN.
    assert!(solve_fixed_point(0.0, |_| Ok(f64::NAN)).is_err());
    // Non-exponential but monotone: converges within the tolerance.
    let (x, _) = solve_fixed_point(0.0, |x| Ok(100.0 / (1.0 + 0.05 * x))).unwrap();
    assert!((x - 100.0 / (1.0 + 0.05 * x)).abs() <= TEMPERATURE_TOLERANCE.max(1e-3 * x));
}
