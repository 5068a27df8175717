//! Unit tests of the instance: state machine, kinematics, value checks,
//! the state round trip, and the physics options against traction-contact.

use super::*;
use crate::physics::{self, Contact};
use crate::variables::{self, Causality, N_REAL_OUTPUTS, Type, vr};

const N_OUT: usize = N_REAL_OUTPUTS;

/// Position of a Real output among the outputs (table order).
fn out_index(r: u32) -> Option<usize> {
    variables::slot(r)
        .filter(|s| s.causality == Causality::Output && s.value_type == Type::Real)
        .map(|s| s.index)
}

/// Value references of every Real output, in the order of the variable
/// table (FX to TEMPERATURE_RISE, then J1 to J7).
fn all_real_outputs() -> Vec<u32> {
    (vr::FX..=vr::TEMPERATURE_RISE)
        .chain(vr::J1..=vr::J7)
        .collect()
}

struct Capture(Vec<(Status, String)>);
impl Logger for Capture {
    fn log(&mut self, status: Status, _: &str, message: &str) {
        self.0.push((status, message.to_owned()));
    }
}

fn initialized() -> TractionFmu {
    let mut f = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
    f.setup_experiment(None, 0.0, Some(1.0)).unwrap();
    f.enter_initialization_mode().unwrap();
    f.exit_initialization_mode(&mut NullLogger).unwrap();
    f
}

#[test]
fn wrong_guid_is_refused() {
    assert!(
        TractionFmu::instantiate("t", "{nope}")
            .unwrap_err()
            .contains("GUID")
    );
}

#[test]
fn state_machine_allows_and_refuses_per_the_standard() {
    let mut f = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
    // SetReal before initialization is accepted; GetReal is not yet allowed.
    f.set_real(&[vr::LOAD, vr::RX1], &[700.0, 0.03]).unwrap();
    assert!(f.do_step(0.0, 0.1, &mut NullLogger).is_err());
    assert_eq!(f.mode(), Mode::Error);
    f.reset().unwrap();
    assert_eq!(f.mode(), Mode::Instantiated);
    let mut x = [0.0];
    f.enter_initialization_mode().unwrap();
    f.get_real(&[vr::LOAD], &mut x, &mut NullLogger).unwrap();
    assert_eq!(x[0], 500.0, "reset restores the start value");
    f.exit_initialization_mode(&mut NullLogger).unwrap();
    // Fixed parameters cannot change after initialization.
    let e = f.set_real(&[vr::RX1], &[0.05]).unwrap_err();
    assert!(e.message.contains("fixed parameter"), "{e}");
    f.reset().unwrap();
    let mut f = initialized();
    f.do_step(0.0, 0.5, &mut NullLogger).unwrap();
    f.terminate().unwrap();
    assert_eq!(f.mode(), Mode::Terminated);
    f.get_real(&[vr::FX], &mut x, &mut NullLogger).unwrap();
    assert!(f.do_step(0.5, 0.5, &mut NullLogger).is_err());
}

#[test]
fn outputs_follow_kinematics_and_torque_convention() {
    let mut f = initialized();
    // u1 = 600*0.033 = 19.8 m/s, u2 = 270*0.0714 = 19.278 m/s.
    f.set_real(&[vr::OMEGA1, vr::OMEGA2], &[600.0, 270.0])
        .unwrap();
    f.do_step(0.0, 0.01, &mut NullLogger).unwrap();
    let vrs = [
        vr::FX,
        vr::TORQUE1,
        vr::TORQUE2,
        vr::U,
        vr::DU,
        vr::POWER_LOSS,
    ];
    let mut o = [0.0; 6];
    f.get_real(&vrs, &mut o, &mut NullLogger).unwrap();
    let (u1, u2) = (600.0 * 0.033, 270.0 * 0.0714);
    assert!((o[3] - 0.5 * (u1 + u2)).abs() < 1e-12 && (o[4] - (u1 - u2)).abs() < 1e-12);
    assert!(o[0] > 0.0, "body 1 is faster: it drives body 2 forward");
    assert!((o[1] + o[0] * 0.033).abs() < 1e-12 && (o[2] - o[0] * 0.0714).abs() < 1e-12);
    // Power balance: the loss is what the two torques take out of the bodies.
    let p = -(o[1] * 600.0 + o[2] * 270.0);
    assert!(
        (o[5] - p).abs() < 1e-9 * p.abs().max(1.0),
        "{} vs {p}",
        o[5]
    );
    // The contact equals the seam evaluated directly.
    let c = Contact::new(&f.physics_parameters().unwrap()).unwrap();
    let d = c
        .evaluate(&physics::Inputs {
            load: 500.0,
            u: o[3],
            du: o[4],
            dv: 0.0,
            omega: 0.0,
            inlet_temperature_celsius: 40.0,
        })
        .unwrap();
    assert_eq!(d.fx, o[0]);
}

#[test]
fn skew_angle_and_tilt_geometry_sources() {
    let mut f = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
    f.set_integer(&[vr::SIDE_SLIP_SOURCE, vr::SPIN_SOURCE], &[2, 2])
        .unwrap();
    f.set_real(
        &[vr::TILT_ANGLE, vr::TILT_OFFSET, vr::SKEW_ANGLE],
        &[0.1, 0.0104, 0.01],
    )
    .unwrap();
    f.set_real(&[vr::OMEGA1, vr::OMEGA2], &[600.0, 600.0 * 0.033 / 0.0714])
        .unwrap();
    f.enter_initialization_mode().unwrap();
    let mut log = Capture(Vec::new());
    assert_eq!(f.exit_initialization_mode(&mut log).unwrap(), Status::Ok);
    assert!(log.0.is_empty(), "{:?}", log.0);
    let mut o = [0.0; 5];
    f.get_real(
        &[vr::U, vr::DV, vr::OMEGA, vr::MZ, vr::POWER_LOSS],
        &mut o,
        &mut log,
    )
    .unwrap();
    assert!((o[1] - o[0] * 0.01_f64.tan()).abs() < 1e-12);
    let w = o[0] * 0.1_f64.sin() / (0.0226 * 0.1_f64.cos() + 0.0104);
    assert!((o[2] - w).abs() < 1e-9);
    assert!(o[3] != 0.0, "spin gives a spin moment");
    assert!(o[4] >= 0.0);
    assert!(f.set_integer(&[vr::FLUID], &[9]).is_err());
}

#[test]
fn report_fluid_through_start_up_warns_once_and_stays_finite() {
    let mut f = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
    f.set_integer(&[vr::FLUID], &[1]).unwrap(); // Santotrac 50, clamp (default)
    f.set_real(&[vr::OMEGA1, vr::OMEGA2], &[0.0, 0.0]).unwrap();
    f.enter_initialization_mode().unwrap();
    let mut log = Capture(Vec::new());
    f.exit_initialization_mode(&mut log).unwrap();
    let all = all_real_outputs();
    let mut o = vec![0.0; all.len()];
    for k in 0..200 {
        // Run up from rest with 1 % slip.
        let w1 = f64::from(k) * 3.0;
        f.set_real(&[vr::OMEGA1, vr::OMEGA2], &[w1, 0.99 * w1 * 0.033 / 0.0714])
            .unwrap();
        f.do_step(f64::from(k) * 1e-3, 1e-3, &mut log).unwrap();
        f.get_real(&all, &mut o, &mut log).unwrap();
        assert!(o.iter().all(|x| x.is_finite()));
    }
    assert_eq!(log.0.len(), 1, "{:?}", log.0);
    assert_eq!(log.0[0].0, Status::Warning);
    assert!(o[0] > 0.0 && o[16] > 0.0 && o[17] > 0.0, "fx, m, mu: {o:?}");
    // Strict envelope: the same start-up is an error naming the quantity.
    let mut g = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
    g.set_integer(&[vr::FLUID, vr::ENVELOPE], &[1, 1]).unwrap();
    g.enter_initialization_mode().unwrap();
    let e = g.exit_initialization_mode(&mut log).unwrap_err();
    assert!(e.message.contains("fluid correlation"), "{e}");
}

#[test]
fn state_round_trip_is_bit_exact() {
    let mut f = initialized();
    f.set_real(&[vr::OMEGA1, vr::OMEGA2, vr::LOAD], &[612.3, 270.1, 1234.5])
        .unwrap();
    f.do_step(0.0, 0.1, &mut NullLogger).unwrap();
    let s = f.get_state().unwrap();
    let bytes = TractionFmu::serialize_state(&s);
    let back = TractionFmu::deserialize_state(&bytes).unwrap();
    assert_eq!(TractionFmu::serialize_state(&back), bytes);
    let mut o1 = [0.0; N_OUT];
    let all = all_real_outputs();
    f.do_step(0.1, 0.1, &mut NullLogger).unwrap();
    f.get_real(&all, &mut o1, &mut NullLogger).unwrap();
    f.set_real(&[vr::OMEGA1], &[1.0]).unwrap();
    f.do_step(0.2, 0.1, &mut NullLogger).unwrap();
    f.set_state(&back).unwrap();
    f.do_step(0.1, 0.1, &mut NullLogger).unwrap();
    let mut o2 = [0.0; N_OUT];
    f.get_real(&all, &mut o2, &mut NullLogger).unwrap();
    assert_eq!(o1.map(f64::to_bits), o2.map(f64::to_bits));
    let mut corrupt = bytes.clone();
    corrupt[20] ^= 1;
    assert!(TractionFmu::deserialize_state(&corrupt).is_err());
    assert!(TractionFmu::deserialize_state(&bytes[..10]).is_err());
}

#[test]
fn invalid_values_are_errors_that_name_the_variable() {
    let mut f = initialized();
    let e = f.set_real(&[vr::LOAD], &[f64::NAN]).unwrap_err();
    assert!(e.message.contains("normal_load"));
    assert_eq!(f.mode(), Mode::Error);
    let mut f = initialized();
    assert!(
        f.set_real(&[vr::FX], &[1.0])
            .unwrap_err()
            .message
            .contains("output")
    );
    let mut f = initialized();
    assert!(
        f.set_real(&[9999], &[1.0])
            .unwrap_err()
            .message
            .contains("9999")
    );
    let mut f = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
    f.set_real(&[vr::MU_USER], &[2.0]).unwrap();
    f.enter_initialization_mode().unwrap();
    assert!(
        f.exit_initialization_mode(&mut NullLogger)
            .unwrap_err()
            .message
            .contains("mu_user")
    );
}

/// Body 1 and body 2 of the default parameters (ry2 = 0 is flat).
fn default_bodies(e2: f64, nu2: f64) -> (traction_contact::Body, traction_contact::Body) {
    (
        traction_contact::Body::new(0.033, 0.0226, 2.07e11, 0.3),
        traction_contact::Body::new(0.0714, f64::INFINITY, e2, nu2),
    )
}

/// An instance with the given parameters set before initialization, the
/// operating point of the tests (U ≈ 19.5 m/s, slip, side slip, spin),
/// initialized; returns it with all Real outputs.
fn run(
    reals: &[(u32, f64)],
    ints: &[(u32, i32)],
    bools: &[(u32, bool)],
) -> Result<(TractionFmu, Vec<f64>), FmuError> {
    let mut f = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
    for &(r, x) in reals {
        f.set_real(&[r], &[x])?;
    }
    for &(r, x) in ints {
        f.set_integer(&[r], &[x])?;
    }
    for &(r, x) in bools {
        f.set_boolean(&[r], &[x])?;
    }
    f.set_real(
        &[vr::OMEGA1, vr::OMEGA2, vr::SIDE_SLIP_VELOCITY, vr::SPIN],
        &[600.0, 270.0, 0.05, 20.0],
    )?;
    f.enter_initialization_mode()?;
    f.exit_initialization_mode(&mut NullLogger)?;
    let all = all_real_outputs();
    let mut o = vec![0.0; all.len()];
    f.get_real(&all, &mut o, &mut NullLogger)?;
    Ok((f, o))
}

/// traction-contact with the FMU's default bodies (steel, E = 207 GPa,
/// ν = 0.3) and the user fluid, with options `o`.
fn default_contact(o: traction_contact::Options) -> traction_contact::TractionContact {
    let (b1, b2) = default_bodies(2.07e11, 0.3);
    traction_contact::TractionContact::new(&b1, &b2, user_fluid(), o).unwrap()
}

/// traction-contact evaluated directly at the FMU's operating point
/// (U, dU, dV, omega read back from the FMU's outputs).
fn direct(c: &traction_contact::TractionContact, o: &[f64]) -> traction_contact::Evaluation {
    let i = |r: u32| o[out_index(r).unwrap()];
    let state = traction_contact::OperatingState::new(
        500.0,
        i(vr::U),
        i(vr::DU),
        i(vr::DV),
        i(vr::OMEGA),
        40.0,
    )
    .unwrap();
    c.evaluate(&state).unwrap()
}

/// FMU outputs against a traction-contact evaluation: forces, moment,
/// J1..J7, m, mu and mu_f to 1e-12 relative (the FMU adds no arithmetic
/// to these beyond copying; the bound leaves room for nothing else).
fn assert_matches(o: &[f64], d: &traction_contact::Evaluation) {
    let i = |r: u32| o[out_index(r).unwrap()];
    let pairs = [
        ("fx", i(vr::FX), d.fx),
        ("fy", i(vr::FY), d.fy),
        ("mz", i(vr::MZ), d.mz),
        ("m", i(vr::M_USED), d.m_used),
        ("mu", i(vr::MU_USED), d.mu_used),
        ("mu_force", i(vr::MU_FORCE), d.mu_force),
        ("J1", i(vr::J1), d.j1),
        ("J2", i(vr::J1 + 1), d.j2),
        ("J3", i(vr::J1 + 2), d.j3),
        ("J4", i(vr::J1 + 3), d.j4),
        ("J5", i(vr::J1 + 4), d.j5),
        ("J6", i(vr::J1 + 5), d.j6),
        ("J7", i(vr::J7), d.j7),
    ];
    for (name, fmu, contact) in pairs {
        assert!(
            (fmu - contact).abs() <= 1e-12 * contact.abs(),
            "{name}: FMU {fmu} vs traction-contact {contact}"
        );
    }
}

fn user_fluid() -> traction_contact::Fluid {
    traction_contact::Fluid::constant(35.0, 0.075).unwrap()
}

/// The FMU's default options (rheology_map off, tolerance 1e-4).
fn options(model: traction_contact::Model) -> traction_contact::Options {
    traction_contact::Options {
        model,
        rolling_speed_floor: 0.01,
        map: false,
        ..traction_contact::Options::default()
    }
}

#[test]
fn viscoelastic_equals_traction_contact_and_infinite_deborah_is_elastic_plastic() {
    let (d, z0) = (0.5, 0.3);
    let (_, visco) = run(&[(vr::DEBORAH, d), (vr::Z0, z0)], &[(vr::RHEOLOGY, 3)], &[]).unwrap();
    let model = traction_contact::Model::Viscoelastic { deborah: d, z0 };
    let c = default_contact(options(model));
    assert_matches(&visco, &direct(&c, &visco));
    // D = inf through fmi2SetReal: the elastic/plastic model.
    let (_, inf) = run(
        &[(vr::DEBORAH, f64::INFINITY), (vr::Z0, z0)],
        &[(vr::RHEOLOGY, 3)],
        &[],
    )
    .unwrap();
    let (_, ep) = run(&[], &[(vr::RHEOLOGY, 1)], &[]).unwrap();
    assert_eq!(inf, ep);
    let c = default_contact(options(traction_contact::Model::ElasticPlastic));
    assert_matches(&ep, &direct(&c, &ep));
    // A finite D relaxes the stress: less traction than elastic/plastic.
    let fx = out_index(vr::FX).unwrap();
    assert!(visco[fx] < ep[fx] * 0.99, "{} vs {}", visco[fx], ep[fx]);
    // Bad D or Z0: fmi2Error at initialization naming the parameter.
    for (r, x, name) in [
        (vr::DEBORAH, -1.0, "deborah"),
        (vr::DEBORAH, 0.0, "deborah"),
        (vr::DEBORAH, f64::NEG_INFINITY, "deborah"),
        (vr::Z0, -0.3, "z0"),
    ] {
        let e = run(&[(r, x)], &[(vr::RHEOLOGY, 3)], &[]).unwrap_err();
        assert_eq!(e.status, Status::Error);
        assert!(e.message.contains(name), "{e}");
    }
    let mut f = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
    let e = f.set_real(&[vr::DEBORAH], &[f64::NAN]).unwrap_err();
    assert!(e.message.contains("deborah"), "{e}");
}

#[test]
fn rheology_map_and_tolerance_parameters() {
    // rheology_map off (the default): traction-contact without the map,
    // bit-identical; on: within 2·tol = 2e-4 of it in J4..J6 (both are
    // within tol of the converged solution; spin 20 rad/s, side slip);
    // rheology_tolerance
    // reaches the contact (1e-3: same as traction-contact at 1e-3); out
    // of [1e-6, 1e-2] it is refused with a message naming it.
    let ep = traction_contact::Model::ElasticPlastic;
    let contact = |map: bool, tol: f64| {
        default_contact(traction_contact::Options {
            map,
            accuracy: traction_contact::Accuracy::new(tol).unwrap(),
            ..options(ep)
        })
    };
    let (_, off) = run(&[], &[], &[]).unwrap();
    assert_matches(&off, &direct(&contact(false, 1e-4), &off));
    let (_, on) = run(&[], &[], &[(vr::RHEOLOGY_MAP, true)]).unwrap();
    for n in 3..6 {
        let (a, b) = (
            on[out_index(vr::J1 + n).unwrap()],
            off[out_index(vr::J1 + n).unwrap()],
        );
        assert!((a - b).abs() <= 2e-4, "J{}: {a} vs {b}", n + 1);
    }
    assert!(
        on[out_index(vr::J1 + 2).unwrap()].abs() > 0.1,
        "no spin: vacuous"
    );
    let (_, coarse) = run(&[(vr::RHEOLOGY_TOLERANCE, 1e-3)], &[], &[]).unwrap();
    assert_matches(&coarse, &direct(&contact(false, 1e-3), &coarse));
    let (_, coarse_map) = run(
        &[(vr::RHEOLOGY_TOLERANCE, 1e-3)],
        &[],
        &[(vr::RHEOLOGY_MAP, true)],
    )
    .unwrap();
    assert_matches(&coarse_map, &direct(&contact(true, 1e-3), &coarse_map));
    for bad in [1e-8, 0.5] {
        let e = run(&[(vr::RHEOLOGY_TOLERANCE, bad)], &[], &[]).unwrap_err();
        assert!(e.message.contains("rheology_tolerance"), "{e}");
    }
}

#[test]
fn rheology_map_builds_its_cells_within_its_budget() {
    // rheology_map on: the contact's map builds its cells within its budget
    // (docs/decisions/0078), so the first evaluation is direct — the same
    // outputs as without the map, to 1e-12 — and after 1000 steps with ω1
    // varying within 0.17 % the steps are interpolated: J4..J6 no longer
    // equal the direct values bit for bit but stay within 2·tol = 2e-4 of
    // them (both within tol of the converged solution). The same call
    // sequence on a second instance gives bit-identical outputs.
    let direct_contact = default_contact(options(traction_contact::Model::ElasticPlastic));
    let all = all_real_outputs();
    let steps = |f: &mut TractionFmu| -> Vec<Vec<f64>> {
        let mut outs = Vec::new();
        for i in 0..1000u32 {
            let w1 = 600.0 + 0.01 * f64::from(i % 100);
            f.set_real(&[vr::OMEGA1], &[w1]).unwrap();
            f.do_step(f64::from(i) * 1e-3, 1e-3, &mut NullLogger)
                .unwrap();
            let mut o = vec![0.0; all.len()];
            f.get_real(&all, &mut o, &mut NullLogger).unwrap();
            outs.push(o);
        }
        outs
    };
    let (mut f, first) = run(&[], &[], &[(vr::RHEOLOGY_MAP, true)]).unwrap();
    assert_matches(&first, &direct(&direct_contact, &first));
    let outs = steps(&mut f);
    let mut interpolated = 0;
    for o in &outs[900..] {
        let d = direct(&direct_contact, o);
        for (n, x) in [(3, d.j4), (4, d.j5), (5, d.j6)] {
            let y = o[out_index(vr::J1 + n).unwrap()];
            assert!((y - x).abs() <= 2e-4, "J{}: {y} vs {x}", n + 1);
            interpolated += usize::from(y != x);
        }
    }
    assert!(
        interpolated >= 250,
        "{interpolated} of 300 values differ from direct"
    );
    let (mut g, _) = run(&[], &[], &[(vr::RHEOLOGY_MAP, true)]).unwrap();
    assert_eq!(steps(&mut g), outs);
}

#[test]
fn spin_peak_equals_traction_contact() {
    // User fluid: forces scaled by mu_spin_user, J groups by mu_user.
    let (_, o) = run(&[(vr::MU_SPIN_USER, 0.06)], &[], &[(vr::SPIN_PEAK, true)]).unwrap();
    let (b1, b2) = default_bodies(2.07e11, 0.3);
    let fluid = user_fluid().with_spin_peak(0.06).unwrap();
    let c = traction_contact::TractionContact::new(
        &b1,
        &b2,
        fluid,
        options(traction_contact::Model::ElasticPlastic),
    )
    .unwrap();
    assert_matches(&o, &direct(&c, &o));
    assert_eq!(o[out_index(vr::MU_FORCE).unwrap()], 0.06);
    assert_eq!(o[out_index(vr::MU_USED).unwrap()], 0.075);
    // Off (default): mu_spin_user is ignored and mu_f = mu.
    let (_, off) = run(&[(vr::MU_SPIN_USER, 0.06)], &[], &[]).unwrap();
    assert_eq!(off[out_index(vr::MU_FORCE).unwrap()], 0.075);
    // TDF-88: its spin-peak correlation.
    let (_, o) = run(&[], &[(vr::FLUID, 2)], &[(vr::SPIN_PEAK, true)]).unwrap();
    let fluid = traction_contact::Fluid::tdf_88(traction_contact::EnvelopeRule::Clamp)
        .unwrap()
        .use_spin_peak(true);
    let c = traction_contact::TractionContact::new(
        &b1,
        &b2,
        fluid,
        options(traction_contact::Model::ElasticPlastic),
    )
    .unwrap();
    let d = direct(&c, &o);
    assert_matches(&o, &d);
    assert!(d.mu_force != d.mu_used, "the correlation is used");
    // Out of range: error naming the parameter.
    let e = run(&[(vr::MU_SPIN_USER, 1.5)], &[], &[(vr::SPIN_PEAK, true)]).unwrap_err();
    assert!(e.message.contains("mu_spin_user"), "{e}");
}

#[test]
fn thermal_parameter_equals_traction_contact() {
    // Off (default): temperature_rise is 0 and the contact is isothermal
    // (bit-identical to traction-contact without the thermal model).
    let (b1, b2) = default_bodies(2.07e11, 0.3);
    let ep = traction_contact::Model::ElasticPlastic;
    let (_, off) = run(&[], &[], &[]).unwrap();
    assert_eq!(off[out_index(vr::TEMPERATURE_RISE).unwrap()], 0.0);
    // User fluid: the FMU's film thickness, conductivity and temperature
    // coefficients reach traction-contact's Thermal; forces and the rise
    // equal a direct evaluation (1e-12 relative: the FMU copies them).
    let reals = [
        (vr::FILM_THICKNESS, 0.4e-6),
        (vr::FLUID_CONDUCTIVITY, 0.12),
        (vr::MU_TEMPERATURE_COEFFICIENT, 0.004),
        (vr::M_TEMPERATURE_COEFFICIENT, 0.001),
        (vr::MU_RISE_SCALE, 300.0),
    ];
    let (_, on) = run(&reals, &[], &[(vr::THERMAL, true)]).unwrap();
    let thermal = traction_contact::Thermal {
        film: traction_contact::Film::Thickness(0.4e-6),
        fluid_conductivity: Some(0.12),
        mu_coefficient: Some(0.004),
        slope_coefficient: Some(0.001),
        mu_rise_scale: Some(300.0),
        ..traction_contact::Thermal::default()
    };
    let c = default_contact(traction_contact::Options {
        thermal: Some(thermal),
        ..options(ep)
    });
    let d = direct(&c, &on);
    assert_matches(&on, &d);
    // The default T* = 1e6 K is the first-order law (mu_rise_scale None):
    // ΔT²/T*² < 1e-7 at this rise, so μ and the forces agree to 1e-6.
    let (_, first) = run(&reals[..4], &[], &[(vr::THERMAL, true)]).unwrap();
    let c1 = default_contact(traction_contact::Options {
        thermal: Some(traction_contact::Thermal {
            mu_rise_scale: None,
            ..thermal
        }),
        ..options(ep)
    });
    let d1 = direct(&c1, &first);
    let fy1 = first[out_index(vr::FY).unwrap()];
    assert!(
        (fy1 - d1.fy).abs() <= 1e-6 * d1.fy.abs(),
        "{fy1} vs {}",
        d1.fy
    );
    let rise = on[out_index(vr::TEMPERATURE_RISE).unwrap()];
    assert!(rise > 1.0, "side slip and spin heat the film: {rise} K");
    assert!((rise - d.temperature_rise).abs() <= 1e-12 * rise);
    let fy = |o: &[f64]| o[out_index(vr::FY).unwrap()];
    assert!(
        fy(&on).abs() < fy(&off).abs(),
        "heating lowers the traction"
    );
    // A report fluid: its own property set (Thermal::default()).
    let (_, tdf) = run(&[], &[(vr::FLUID, 2)], &[(vr::THERMAL, true)]).unwrap();
    let fluid = traction_contact::Fluid::tdf_88(traction_contact::EnvelopeRule::Clamp).unwrap();
    let c = traction_contact::TractionContact::new(
        &b1,
        &b2,
        fluid,
        traction_contact::Options {
            thermal: Some(traction_contact::Thermal::default()),
            ..options(ep)
        },
    )
    .unwrap();
    assert_matches(&tdf, &direct(&c, &tdf));
    assert!(tdf[out_index(vr::TEMPERATURE_RISE).unwrap()] > 0.0);
    // Out of range: errors naming the parameter; thermal with the spin
    // peak is refused (the same heating twice).
    let on = [(vr::THERMAL, true)];
    let e = run(&[(vr::FILM_THICKNESS, 0.0)], &[], &on).unwrap_err();
    assert!(e.message.contains("film_thickness"), "{e}");
    let e = run(&[(vr::FLUID_CONDUCTIVITY, f64::NAN)], &[], &on).unwrap_err();
    assert!(e.message.contains("fluid_conductivity"), "{e}");
    let e = run(&[(vr::MU_TEMPERATURE_COEFFICIENT, 2.0)], &[], &on).unwrap_err();
    assert!(e.message.contains("mu_temperature_coefficient"), "{e}");
    let e = run(&[(vr::MU_RISE_SCALE, 0.0)], &[], &on).unwrap_err();
    assert!(e.message.contains("mu_rise_scale"), "{e}");
    // Thermal off: the thermal parameters are not used (not checked).
    assert!(run(&[(vr::FILM_THICKNESS, 0.0)], &[], &[]).is_ok());
    let e = run(&[], &[], &[(vr::THERMAL, true), (vr::SPIN_PEAK, true)]).unwrap_err();
    assert!(e.message.contains("spin-peak"), "{e}");
}

#[test]
fn compliance_uses_both_bodies_materials() {
    // Steel on a softer body 2 (E 110 GPa, nu 0.34), compliance on.
    let (e2, nu2) = (1.1e11, 0.34);
    let (_, o) = run(
        &[(vr::E2, e2), (vr::NU2, nu2)],
        &[],
        &[(vr::COMPLIANCE, true)],
    )
    .unwrap();
    // Kalker's combined constants, computed here by hand.
    let (g1, g2) = (2.07e11 / 2.6, e2 / (2.0 * (1.0 + nu2)));
    let g = 1.0 / (0.5 * (1.0 / g1 + 1.0 / g2));
    let nu = 0.5 * g * (0.3 / g1 + nu2 / g2);
    let material = traction_contact::DiscMaterial {
        youngs_modulus: 2.0 * g * (1.0 + nu),
        poisson_ratio: nu,
    };
    let (b1, b2) = default_bodies(e2, nu2);
    let compliant = |material| traction_contact::Options {
        compliance: traction_contact::Compliance::Discs {
            material,
            slope_measured_in: traction_contact::Direction::Side,
        },
        ..options(traction_contact::Model::ElasticPlastic)
    };
    let c = traction_contact::TractionContact::new(&b1, &b2, user_fluid(), compliant(material))
        .unwrap();
    let d = direct(&c, &o);
    assert_matches(&o, &d);
    // Not body 1's material alone (the previous assumption).
    let body1 = traction_contact::DiscMaterial {
        youngs_modulus: 2.07e11,
        poisson_ratio: 0.3,
    };
    let c1 =
        traction_contact::TractionContact::new(&b1, &b2, user_fluid(), compliant(body1)).unwrap();
    let d1 = direct(&c1, &o);
    assert!((d1.m_used - d.m_used).abs() > 1e-3 * d.m_used);
    // Symmetric in the two bodies; identical bodies give their own material.
    let m12 = physics::kalker_combined(2.07e11, 0.3, e2, nu2);
    let m21 = physics::kalker_combined(e2, nu2, 2.07e11, 0.3);
    assert!((m12.youngs_modulus / m21.youngs_modulus - 1.0).abs() < 1e-15);
    assert!((m12.poisson_ratio - m21.poisson_ratio).abs() < 1e-15);
    assert!((m12.youngs_modulus / material.youngs_modulus - 1.0).abs() < 1e-14);
    assert_eq!(physics::kalker_combined(2.07e11, 0.3, 2.07e11, 0.3), body1);
}

#[test]
fn do_step_reports_a_communication_point_that_does_not_continue() {
    let mut log = Capture(Vec::new());
    let mut f = initialized();
    // Continuous steps, also with t = i h computed by the master (a few ulp
    // away from the sum of the steps): no warning.
    let h = 0.1;
    for i in 0..1000 {
        assert_eq!(f.do_step(f64::from(i) * h, h, &mut log), Ok(Status::Ok));
    }
    assert!(log.0.is_empty(), "{:?}", log.0);
    // Forward and backward jumps: the step is taken, with a warning naming
    // both times.
    let t = f.last_successful_time();
    assert_eq!(f.do_step(t + 0.5, h, &mut log), Ok(Status::Warning));
    assert_eq!(log.0.len(), 1);
    assert!(
        log.0[0].1.contains("currentCommunicationPoint"),
        "{:?}",
        log.0
    );
    assert_eq!(f.last_successful_time(), t + 0.5 + h);
    assert_eq!(f.do_step(t + 0.5 + h, h, &mut log), Ok(Status::Ok));
    assert_eq!(f.do_step(1.0, h, &mut log), Ok(Status::Warning));
    assert_eq!(f.mode(), Mode::StepComplete);
    // The first step continues from startTime.
    let mut g = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
    g.setup_experiment(None, 10.0, None).unwrap();
    g.enter_initialization_mode().unwrap();
    g.exit_initialization_mode(&mut NullLogger).unwrap();
    assert_eq!(g.do_step(0.0, h, &mut log), Ok(Status::Warning));
    let mut g = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
    g.setup_experiment(None, 10.0, None).unwrap();
    g.enter_initialization_mode().unwrap();
    g.exit_initialization_mode(&mut NullLogger).unwrap();
    assert_eq!(g.do_step(10.0, h, &mut log), Ok(Status::Ok));
    // A restored state continues from its own time.
    let s = g.get_state().unwrap();
    g.do_step(10.0 + h, h, &mut log).unwrap();
    g.set_state(&s).unwrap();
    assert_eq!(g.do_step(10.0 + h, h, &mut log), Ok(Status::Ok));
}

#[test]
fn blank_instance_name_is_refused() {
    let guid = crate::model_description::guid();
    for name in ["", " ", " \t\n"] {
        let e = TractionFmu::instantiate(name, &guid).unwrap_err();
        assert!(e.contains("blank"), "{e}");
    }
    assert!(TractionFmu::instantiate(" a ", &guid).is_ok());
}

/// Layout of the serialized state (see `snapshot.rs`): magic, mode, two
/// times, Real parameters, inputs, enumerations, booleans, outputs.
fn offset_of_enum(i: usize) -> usize {
    8 + 1 + 16 + 8 * variables::N_REAL_PARAMS + 8 * variables::N_INPUTS + 4 * i
}

fn offset_of_output(i: usize) -> usize {
    offset_of_enum(variables::N_ENUM_PARAMS) + variables::N_BOOL_PARAMS + 8 * i
}

/// Recomputes the checksum of an edited state, as a forger would.
fn reseal(bytes: &mut [u8]) {
    let n = bytes.len() - 16;
    let sum = crate::model_description::fnv1a_128(&bytes[..n]);
    bytes[n..].copy_from_slice(&sum.to_le_bytes());
}

#[test]
fn deserialized_states_are_checked_like_set_values() {
    let mut f = initialized();
    f.do_step(0.0, 0.1, &mut NullLogger).unwrap();
    let bytes = TractionFmu::serialize_state(&f.get_state().unwrap());
    let fluid = variables::slot(vr::FLUID).unwrap().index;
    assert_eq!(
        i32::from_le_bytes(bytes[offset_of_enum(fluid)..][..4].try_into().unwrap()),
        3,
        "the layout assumed here"
    );
    let fx = out_index(vr::FX).unwrap();
    assert_eq!(
        f64::from_le_bytes(bytes[offset_of_output(fx)..][..8].try_into().unwrap()),
        f.output(vr::FX).unwrap()
    );
    // An edited state with a recomputed checksum: fluid = 99.
    let mut edited = bytes.clone();
    edited[offset_of_enum(fluid)..][..4].copy_from_slice(&99i32.to_le_bytes());
    reseal(&mut edited);
    let e = TractionFmu::deserialize_state(&edited).unwrap_err();
    assert!(e.message.contains("fluid = 99"), "{e}");
    // A NaN output.
    let mut edited = bytes.clone();
    edited[offset_of_output(fx)..][..8].copy_from_slice(&f64::NAN.to_le_bytes());
    reseal(&mut edited);
    let e = TractionFmu::deserialize_state(&edited).unwrap_err();
    assert!(e.message.contains("fx"), "{e}");
    // A NaN parameter (as fmi2SetReal refuses it) and an infinite input.
    let mut edited = bytes.clone();
    let e1 = 8 + 1 + 16 + 8 * variables::slot(vr::E1).unwrap().index;
    edited[e1..][..8].copy_from_slice(&f64::NAN.to_le_bytes());
    reseal(&mut edited);
    let e = TractionFmu::deserialize_state(&edited).unwrap_err();
    assert!(e.message.contains("e1"), "{e}");
    let mut edited = bytes.clone();
    let load =
        8 + 1 + 16 + 8 * (variables::N_REAL_PARAMS + variables::slot(vr::LOAD).unwrap().index);
    edited[load..][..8].copy_from_slice(&f64::INFINITY.to_le_bytes());
    reseal(&mut edited);
    let e = TractionFmu::deserialize_state(&edited).unwrap_err();
    assert!(e.message.contains("normal_load"), "{e}");
    // A regime outside its enumeration.
    let mut edited = bytes.clone();
    let regime = offset_of_output(variables::N_REAL_OUTPUTS);
    edited[regime..][..4].copy_from_slice(&7i32.to_le_bytes());
    reseal(&mut edited);
    let e = TractionFmu::deserialize_state(&edited).unwrap_err();
    assert!(e.message.contains("regime"), "{e}");
    // The untouched bytes still round-trip.
    let back = TractionFmu::deserialize_state(&bytes).unwrap();
    assert_eq!(TractionFmu::serialize_state(&back), bytes);
}

#[test]
fn enumerations_convert_by_their_table_codes() {
    use crate::physics::{Envelope, Fluid, Rheology};
    let converts = |declared: &str, code: i32| match declared {
        "Fluid" => Fluid::try_from(code).is_ok(),
        "EnvelopeRule" => Envelope::try_from(code).is_ok(),
        "RheologyModel" => Rheology::try_from(code).is_ok(),
        "SpinSource" => SpinSource::try_from(code).is_ok(),
        _ => SideSlipSource::try_from(code).is_ok(),
    };
    for declared in [
        "Fluid",
        "EnvelopeRule",
        "RheologyModel",
        "SpinSource",
        "SideSlipSource",
    ] {
        let items = variables::ENUM_TYPES
            .iter()
            .find(|t| t.0 == declared)
            .unwrap()
            .2;
        for &(_, code, _) in items {
            assert!(converts(declared, code), "{declared} {code}");
        }
        for code in [0, items.len() as i32 + 1, -1, 99] {
            assert!(!converts(declared, code), "{declared} {code}");
        }
    }
    assert_eq!(
        crate::physics::Fluid::try_from(99),
        Err(crate::physics::UnknownCode(99))
    );
}
