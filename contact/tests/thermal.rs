//! The thermal contact (`Options::thermal`): the fixed point against an
//! independent solve, zero heat, continuity through U = 0, monotonicity and
//! bad input.

use traction_contact::thermal::{self, TEMPERATURE_RELATIVE_TOLERANCE, TEMPERATURE_TOLERANCE};
use traction_contact::{
    Body, ContactError, EnvelopeRule, Evaluation, Film, Fluid, OperatingState, Options, Thermal,
    TractionContact,
};

/// Low-speed machine k = 1 discs of Table 2-1.
fn bodies() -> (Body, Body) {
    (
        Body::steel(25e-3, 12.5e-3),
        Body::steel(25e-3, f64::INFINITY),
    )
}

/// A user fluid with the thermal model: h = 0.5 µm, k_f = 0.11, β_μ given.
fn user_thermal(beta: f64) -> Thermal {
    Thermal {
        film: Film::Thickness(0.5e-6),
        fluid_conductivity: Some(0.11),
        mu_coefficient: Some(beta),
        mu_at_traction_peak: false,
        ..Thermal::default()
    }
}

fn contact(fluid: Fluid, thermal: Option<Thermal>) -> TractionContact {
    let (b1, b2) = bodies();
    TractionContact::new(
        &b1,
        &b2,
        fluid,
        Options {
            thermal,
            ..Options::default()
        },
    )
    .expect("contact")
}

fn state(u: f64, du: f64, dv: f64, w: f64) -> OperatingState {
    OperatingState::builder()
        .load(450.0)
        .rolling_speed(u)
        .slip(du)
        .side_slip(dv)
        .spin(w)
        .inlet_temperature_celsius(70.0)
        .build()
        .expect("state")
}

/// The root of g(x) = x − rise(x) on [0, 1000] K by plain bisection (60
/// halvings: 1e-15 K), the independent solve the fixed point is checked
/// against.
fn bisect_fixed_point(mut rise: impl FnMut(f64) -> f64) -> f64 {
    let (mut lo, mut hi) = (0.0, 1000.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if mid - rise(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The converged rise satisfies ΔT = (R_s + R_f)·P/(πab) with P evaluated by
/// an isothermal contact at μ(ΔT) (an independent evaluation), and equals the
/// root found by plain bisection on that isothermal contact.
#[test]
fn fixed_point_matches_an_independent_solve() {
    let (m, mu, beta) = (57.6, 0.0956, 0.01);
    let th = user_thermal(beta);
    let c = contact(Fluid::constant(m, mu).unwrap(), Some(th));
    let s = state(20.0, 0.0, 0.2, 0.0);
    let e = c.evaluate(&s).unwrap();
    assert!(e.temperature_rise > 1.0, "{}", e.temperature_rise);
    // μ used is the inlet μ at the raised temperature.
    assert!((e.mu_used / (mu * (-beta * e.temperature_rise).exp()) - 1.0).abs() < 1e-12);
    // Independent: the rise the isothermal contact's loss produces at μ(ΔT).
    let rise = |dt: f64| -> f64 {
        let iso = contact(Fluid::constant(m, mu * (-beta * dt).exp()).unwrap(), None);
        let r: Evaluation = iso.evaluate(&s).unwrap();
        let rs = thermal::surfaces_resistance(
            r.a,
            r.b,
            20.0,
            0.0,
            0.2,
            th.disc_conductivity,
            th.disc_heat_capacity,
        );
        let rf = 0.5e-6 / (8.0 * 0.11);
        (rs + rf) * r.loss / (std::f64::consts::PI * r.a * r.b)
    };
    let dt = e.temperature_rise;
    // Tolerance: the solver's own (0.01 K or 1e-3 relative) plus the
    // iteration accuracy of the rheology (10× coarser: ≤ 1e-3 in J5 here, the
    // closed form at zero spin is exact, so no extra).
    let tol = TEMPERATURE_TOLERANCE.max(TEMPERATURE_RELATIVE_TOLERANCE * dt);
    assert!((rise(dt) - dt).abs() <= tol, "{} vs {dt}", rise(dt));
    // The fixed point's slope g'(x) = 1 − rise'(x) ≥ 1, so |Δx| ≤ |g| ≤ tol.
    let root = bisect_fixed_point(rise);
    assert!((root - dt).abs() <= tol, "{root} vs {dt}");
}

#[test]
fn zero_heat_zero_rise_and_zero_force_at_any_speed() {
    let c = contact(
        Fluid::constant(57.6, 0.0956).unwrap(),
        Some(user_thermal(0.01)),
    );
    for u in [-5.0, -1e-4, 0.0, 1e-4, 5.0] {
        let e = c.evaluate(&state(u, 0.0, 0.0, 0.0)).unwrap();
        assert_eq!(e.temperature_rise, 0.0);
        assert_eq!([e.fx, e.fy, e.mz, e.loss], [0.0; 4]);
    }
    // Off by default: no rise, and the same numbers as without the field.
    let iso = contact(Fluid::constant(57.6, 0.0956).unwrap(), None);
    let e = iso.evaluate(&state(20.0, 0.02, 0.1, 30.0)).unwrap();
    assert_eq!(e.temperature_rise, 0.0);
}

/// Forces stay continuous through U = 0 with slip, side slip and spin, the
/// thermal model on (the U_f blend of the crate docs; the rise is continuous
/// because the surfaces' speeds U ± ΔU/2 are).
#[test]
fn continuous_through_zero_rolling_speed() {
    let c = contact(
        Fluid::constant(57.6, 0.0956).unwrap(),
        Some(user_thermal(0.01)),
    );
    let uf = traction_contact::DEFAULT_ROLLING_SPEED_FLOOR;
    let n = 40;
    let mut last: Option<Evaluation> = None;
    for i in -n..=n {
        let u = 2.0 * uf * i as f64 / n as f64;
        let e = c.evaluate(&state(u, 0.01, 0.005, 0.5)).unwrap();
        assert!(e.fx.is_finite() && e.temperature_rise.is_finite());
        if let Some(p) = last {
            // Step 1e-4 m/s: the blend's slope is ≤ 1.5/U_f in weight, times
            // |F₊ − F₋| ≤ 2μN: ≤ 0.3 μN per step; bound 0.3·μN.
            let bound = 0.3 * 0.0956 * 450.0;
            assert!((e.fx - p.fx).abs() <= bound, "fx jump at U = {u}");
            assert!((e.fy - p.fy).abs() <= bound, "fy jump at U = {u}");
            // The rise moves by far less than a kelvin per step.
            assert!((e.temperature_rise - p.temperature_rise).abs() < 1.0);
        }
        last = Some(e);
    }
}

#[test]
fn rise_grows_with_slip_and_traction_falls_below_isothermal() {
    let th = user_thermal(0.01);
    let c = contact(Fluid::constant(57.6, 0.0956).unwrap(), Some(th));
    let iso = contact(Fluid::constant(57.6, 0.0956).unwrap(), None);
    let mut last = 0.0;
    for dv in [0.01, 0.05, 0.1, 0.2, 0.4] {
        let s = state(20.0, 0.0, dv, 0.0);
        let e = c.evaluate(&s).unwrap();
        assert!(e.temperature_rise > last, "{dv}");
        last = e.temperature_rise;
        assert!(e.fy < iso.evaluate(&s).unwrap().fy);
    }
}

#[test]
fn report_fluid_with_inlet_values_and_spin() {
    let (b1, b2) = (
        Body::steel(33e-3, 270e-3),
        Body::steel(71.4e-3, f64::INFINITY),
    );
    let fluid = Fluid::santotrac_50(EnvelopeRule::Clamp)
        .unwrap()
        .with_inlet_values(35.0, 0.075)
        .unwrap();
    let c = TractionContact::new(
        &b1,
        &b2,
        fluid,
        Options {
            thermal: Some(Thermal::default()),
            ..Options::default()
        },
    )
    .unwrap();
    let s = OperatingState::builder()
        .load(4620.0)
        .rolling_speed(80.0)
        .side_slip(0.5)
        .spin(1300.0)
        .inlet_temperature_celsius(73.0)
        .build()
        .unwrap();
    let e = c.evaluate(&s).unwrap();
    // Heating under 30° spin at 80 m/s: tens of kelvin, μ below the inlet value.
    assert!(e.temperature_rise > 10.0 && e.temperature_rise < 500.0);
    assert!(e.mu_used < 0.075 && e.fy.is_finite());
}

/// The second-order law μ(ΔT) = μ e^(−ΔT²/T*²) (β_μ = 0, no reference
/// peak): the converged rise equals the root found by bisection on an
/// isothermal contact at μ(ΔT), as for the first-order law above.
#[test]
fn second_order_law_matches_an_independent_solve() {
    let (m, mu, scale) = (57.6, 0.0956, 60.0);
    let th = Thermal {
        mu_rise_scale: Some(scale),
        ..user_thermal(0.0)
    };
    let c = contact(Fluid::constant(m, mu).unwrap(), Some(th));
    let s = state(20.0, 0.0, 0.2, 0.0);
    let e = c.evaluate(&s).unwrap();
    let dt = e.temperature_rise;
    assert!(dt > 10.0, "{dt}");
    let factor = |dt: f64| (-(dt / scale).powi(2)).exp();
    assert!((e.mu_used / (mu * factor(dt)) - 1.0).abs() < 1e-12);
    let rise = |dt: f64| -> f64 {
        let iso = contact(Fluid::constant(m, mu * factor(dt)).unwrap(), None);
        let r: Evaluation = iso.evaluate(&s).unwrap();
        let rs = thermal::surfaces_resistance(
            r.a,
            r.b,
            20.0,
            0.0,
            0.2,
            th.disc_conductivity,
            th.disc_heat_capacity,
        );
        (rs + 0.5e-6 / (8.0 * 0.11)) * r.loss / (std::f64::consts::PI * r.a * r.b)
    };
    // Tolerance: the solver's own (closed form at zero spin, exact).
    let tol = TEMPERATURE_TOLERANCE.max(TEMPERATURE_RELATIVE_TOLERANCE * dt);
    let root = bisect_fixed_point(rise);
    assert!((root - dt).abs() <= tol, "{root} vs {dt}");
    // T* = ∞ is no second-order term: the isothermal contact (β_μ = 0).
    let none = contact(
        Fluid::constant(m, mu).unwrap(),
        Some(Thermal {
            mu_rise_scale: Some(f64::INFINITY),
            ..th
        }),
    );
    let iso = contact(Fluid::constant(m, mu).unwrap(), None);
    assert_eq!(none.evaluate(&s).unwrap().fy, iso.evaluate(&s).unwrap().fy);
}

fn msg(e: ContactError) -> String {
    e.to_string()
}

#[test]
fn bad_thermal_input_names_the_quantity() {
    let (b1, b2) = bodies();
    let build = |fluid: Fluid, th: Thermal| {
        TractionContact::new(
            &b1,
            &b2,
            fluid,
            Options {
                thermal: Some(th),
                ..Options::default()
            },
        )
    };
    let f = || Fluid::constant(57.6, 0.0956).unwrap();
    let base = user_thermal(0.01);
    let cases: Vec<(Thermal, &str)> = vec![
        (
            Thermal {
                disc_conductivity: -1.0,
                ..base
            },
            "disc thermal conductivity",
        ),
        (
            Thermal {
                disc_heat_capacity: f64::NAN,
                ..base
            },
            "disc volumetric heat capacity",
        ),
        (
            Thermal {
                fluid_conductivity: Some(0.0),
                ..base
            },
            "fluid thermal conductivity",
        ),
        (
            Thermal {
                film: Film::Thickness(f64::INFINITY),
                ..base
            },
            "film thickness",
        ),
        (
            Thermal {
                film: Film::HamrockDowson {
                    viscosity: -0.01,
                    pressure_viscosity: 2e-8,
                },
                ..base
            },
            "inlet viscosity",
        ),
        (
            Thermal {
                mu_coefficient: Some(5.0),
                ..base
            },
            "temperature coefficient β_μ",
        ),
        (
            Thermal {
                mu_coefficient: None,
                ..base
            },
            "temperature coefficient β_μ",
        ),
        (
            Thermal {
                film: Film::FromFluid,
                ..base
            },
            "film thickness",
        ),
        (
            Thermal {
                mu_rise_scale: Some(0.0),
                ..base
            },
            "temperature scale T*",
        ),
        (
            Thermal {
                mu_rise_scale: Some(f64::NAN),
                ..base
            },
            "temperature scale T*",
        ),
    ];
    for (th, name) in cases {
        let e = build(f(), th).unwrap_err();
        assert!(msg(e.clone()).contains(name), "{name}: {e}");
    }
    // The spin-peak μ_s is the report's empirical thermal correction: not both.
    let e = build(f().with_spin_peak(0.05).unwrap(), base).unwrap_err();
    assert!(msg(e).contains("spin-peak"));
}

/// The inlet-heated film (`Film::FromFluidInletHeated`): the report fluid's
/// Hamrock–Dowson film times Gupta et al.'s factor at its own η₀(θ), β_η and
/// k_f (L = 19.65 at 80 m/s, 73 °C for the data file's 30.3 / 5.0 mPa·s and
/// 0.11 W/(m·K), evaluated by hand: `thermal::inlet_heating_factor`'s unit
/// test); a thinner film conducts its heat out at a lower rise; β_η = 0 is
/// the isothermal inlet exactly.
#[test]
fn inlet_heated_film_of_a_report_fluid() {
    let fluid = Fluid::tdf_88(EnvelopeRule::Clamp)
        .and_then(|f| f.with_inlet_values(33.3, 0.051))
        .unwrap();
    let with = |film: Film| Thermal {
        film,
        ..Thermal::default()
    };
    let c = contact(fluid.clone(), Some(with(Film::FromFluidInletHeated)));
    let s = OperatingState::builder()
        .load(450.0)
        .rolling_speed(80.0)
        .side_slip(0.4)
        .inlet_temperature_celsius(73.0)
        .build()
        .unwrap();
    let g = c.geometry();
    let h = |film: Film| thermal::film_thickness(&with(film), g, Some(&fluid), &s).unwrap();
    let (iso, heated) = (h(Film::FromFluid), h(Film::FromFluidInletHeated));
    let p0 = g.at_load(450.0).unwrap().p0;
    let phi = thermal::inlet_heating_factor(19.651855606961732, p0 / g.e_prime, 0.0).unwrap();
    assert!(
        (heated / iso / phi - 1.0).abs() < 1e-9,
        "{heated} {iso} {phi}"
    );
    assert!(phi > 0.2 && phi < 0.4, "{phi}");
    let hd = Film::HamrockDowson {
        viscosity: 0.011248191075924476,
        pressure_viscosity: 3.0e-8,
    };
    assert!((h(hd) / iso - 1.0).abs() < 1e-12);
    let off = Film::HamrockDowsonInletHeated {
        viscosity: 0.011248191075924476,
        pressure_viscosity: 3.0e-8,
        viscosity_temperature: 0.0,
    };
    assert_eq!(h(off), h(hd));
    let rise = |film: Film| {
        contact(fluid.clone(), Some(with(film)))
            .evaluate(&s)
            .unwrap()
            .temperature_rise
    };
    let (r_iso, r_heated) = (rise(Film::FromFluid), rise(Film::FromFluidInletHeated));
    assert!(r_heated < r_iso && r_heated > 0.0, "{r_heated} {r_iso}");
}

/// Bad input of the inlet-heated films names the quantity: a user fluid has
/// no η₀(θ) of its own, β_η outside [0, 1] 1/K, and the factor beyond its
/// slide-to-roll range (|ΔU|/U ≤ 2), which the contact clamps to it.
#[test]
fn inlet_heated_film_bad_input() {
    let (b1, b2) = bodies();
    let build = |fluid: Fluid, film: Film| {
        TractionContact::new(
            &b1,
            &b2,
            fluid,
            Options {
                thermal: Some(Thermal {
                    film,
                    ..user_thermal(0.01)
                }),
                ..Options::default()
            },
        )
    };
    let f = || Fluid::constant(57.6, 0.0956).unwrap();
    let e = build(f(), Film::FromFluidInletHeated).unwrap_err();
    assert!(msg(e.clone()).contains("film thickness"), "{e}");
    let bad = Film::HamrockDowsonInletHeated {
        viscosity: 0.01,
        pressure_viscosity: 2e-8,
        viscosity_temperature: -0.01,
    };
    let e = build(f(), bad).unwrap_err();
    assert!(msg(e.clone()).contains("temperature–viscosity"), "{e}");
    let good = Film::HamrockDowsonInletHeated {
        viscosity: 0.01,
        pressure_viscosity: 2e-8,
        viscosity_temperature: 0.03,
    };
    let c = build(f(), good).unwrap();
    assert!(c.evaluate(&state(20.0, 0.2, 0.0, 0.0)).is_ok());
    // Beyond the factor's slide-to-roll range the contact takes it at 2
    // (no error for a state starting from rest with slip): the film at
    // |ΔU|/U = 2.5 is the one at 2, and a state at U = 1 mm/s with 0.5 m/s
    // of slip (ratio 500) evaluates.
    let th = Thermal {
        film: good,
        ..user_thermal(0.01)
    };
    let h = |s: &OperatingState| thermal::film_thickness(&th, c.geometry(), Some(&f()), s).unwrap();
    let (h2, h25) = (
        h(&state(20.0, 40.0, 0.0, 0.0)),
        h(&state(20.0, 50.0, 0.0, 0.0)),
    );
    assert!(h2 > 0.0 && h2 == h25, "{h2} {h25}");
    assert!(h(&state(20.0, 30.0, 0.0, 0.0)) > h2);
    assert!(c.evaluate(&state(20.0, 50.0, 0.0, 0.0)).is_ok());
    assert!(c.evaluate(&state(1e-3, 0.5, 0.0, 0.0)).is_ok());
    let e = thermal::inlet_heating_factor(1.0, 0.006, 2.5).unwrap_err();
    assert!(
        traction_contact::error_chain(&e).contains("slide-to-roll"),
        "{e}"
    );
}

#[test]
fn a_temperature_law_outside_the_float_range_is_a_thermal_error() {
    // μ(ΔT) = μ·e^(−β_μ(ΔT − ΔT_peak) − …) with β_μ = −0.5/K: the heating
    // runs away, and on its way to the largest accepted rise (2000 K) the
    // factor reaches e^1000, beyond the float range: that gave μ = ∞ and NaN
    // forces (reported as an internal error); now a thermal error at that
    // rise. Where the fixed point stays low, the same law is solved.
    let c = contact(
        Fluid::constant(40.0, 0.06).unwrap(),
        Some(user_thermal(-0.5)),
    );
    let e = c.evaluate(&state(20.0, 2.0, 0.0, 0.0)).unwrap_err();
    let msg = traction_contact::error_chain(&e);
    assert!(matches!(e, ContactError::Thermal { .. }), "{msg}");
    assert!(msg.contains("temperature law of m or μ"), "{msg}");
    let ok = c.evaluate(&state(20.0, 0.05, 0.0, 0.0)).unwrap();
    assert!(
        ok.temperature_rise > 0.0 && ok.temperature_rise < 10.0,
        "{ok:?}"
    );

    // A fluid's μ measured at a traction peak that would heat the film by
    // 3.5e7 K (U = 2.5e5 m/s on a 0.1 N, 28 µm contact) has no unheated μ
    // (the factor back to it overflowed): a thermal error naming the peak.
    let b1 = Body::new(2.037e-2, -5.47e-3, 3.0e11, 0.3725);
    let b2 = Body::new(5.47e-3, 6.889e-4, 3.1e10, 0.2084);
    let c = TractionContact::new(
        &b1,
        &b2,
        Fluid::santotrac_50(EnvelopeRule::Clamp).unwrap(),
        Options {
            thermal: Some(Thermal::default()),
            ..Options::default()
        },
    )
    .unwrap();
    let st = OperatingState::new(0.0989, -2.544e5, 5.088e5, 0.0, -2.905e6, -29.2).unwrap();
    let e = c.evaluate(&st).unwrap_err();
    let msg = traction_contact::error_chain(&e);
    assert!(matches!(e, ContactError::Thermal { .. }), "{msg}");
    assert!(msg.contains("traction peak"), "{msg}");
}
