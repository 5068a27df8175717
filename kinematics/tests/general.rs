//! General 3-D contact kinematics: the twin-disc equations (3) and (6) as special
//! cases, the half-toroidal variator against an independent closed form, and
//! property tests of the sign conventions.

use nalgebra::Vector3;
use proptest::prelude::*;
use traction_kinematics::{
    BodyMotion, HalfToroidalVariator, contact_kinematics, j_groups, side_slip_ratio,
    tilted_disc_spin_per_speed,
};

/// The report's rig built in 3-D: contact at the origin, normal +z (into the
/// upper disc), rolling direction +x. The lower (driving) disc of radius
/// `r_lower` turns about an axis parallel to y below the contact. The upper disc
/// is tilted by α about the rolling direction x around the centre of curvature of
/// its crown (at height R_y), whose distance to the upper axis is e; so the upper
/// axis has direction (0, cos α, −sin α) (the sign of α chosen so that α > 0 gives
/// positive spin, as the crate docs define) and passes through (0, 0, R_y + e/cos α).
/// It may also be skewed by β about the normal. The upper disc rolls freely along
/// its own rolling direction (no longitudinal slip in that direction).
fn rig(
    alpha: f64,
    beta: f64,
    ry: f64,
    e: f64,
    r_lower: f64,
    w_lower: f64,
) -> (BodyMotion, BodyMotion) {
    // Lower disc: Ω = (0, w, 0) about an axis through (0, 0, −r_lower); its surface
    // velocity at the contact is (0, w, 0) × (0, 0, r_lower) = w·r_lower·x̂.
    let lower = BodyMotion::rotating(
        Vector3::new(0.0, w_lower, 0.0),
        Vector3::new(0.0, 0.0, -r_lower),
    );
    let v_lower = w_lower * r_lower;
    // Upper disc before skew: axis d = (0, cos α, −sin α) through (0,0,h), h = R_y + e/cos α.
    // Its surface velocity at the origin is Ω_u d × (0,0,−h) = −Ω_u h cos α · x̂.
    // Skew by β about z rotates the whole upper assembly.
    let rot = nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), beta);
    let d = rot * Vector3::new(0.0, alpha.cos(), -alpha.sin());
    let h = ry + e / alpha.cos();
    let upper_dir = rot * Vector3::x(); // the upper disc's own rolling direction
    // Free rolling: upper surface speed along its direction = lower speed component.
    let v_upper = v_lower * upper_dir.dot(&Vector3::x());
    let w_upper = -v_upper / (h * alpha.cos());
    let upper = BodyMotion::rotating(d * w_upper, Vector3::new(0.0, 0.0, h));
    (upper, lower)
}

#[test]
fn twin_disc_equation_6_is_a_special_case() {
    // Low- and high-speed machine geometries of Table 2-4 (R_y = 22.6 mm on the HS
    // k = 1 disc, see tests/tests/kinematics_tables.rs), both signs of e.
    for (ry, e, alpha_deg) in [
        (4.3e-3, 20.7e-3, 6.0),
        (12.5e-3, 12.5e-3, 6.0),
        (36.5e-3, -11.5e-3, 6.0),
        (150.4e-3, -125e-3, 6.0),
        (22.6e-3, 10.4e-3, 15.0),
        (22.6e-3, 10.4e-3, 30.0),
        (270e-3, -230e-3, 15.0),
        (270e-3, -205e-3, 30.0),
    ] {
        let alpha = f64::to_radians(alpha_deg);
        let (upper, lower) = rig(alpha, 0.0, ry, e, 25e-3, 800.0);
        let k = contact_kinematics(&upper, &lower, Vector3::zeros(), Vector3::z(), Vector3::x())
            .unwrap();
        let eq6 = tilted_disc_spin_per_speed(alpha, ry, e).unwrap();
        // Exact identity up to floating-point rounding of a handful of operations.
        assert!((k.spin_per_speed().unwrap() / eq6 - 1.0).abs() < 1e-12);
        assert!(k.slip.abs() < 1e-12 && k.side_slip.abs() < 1e-12 && k.approach.abs() < 1e-12);
        // Upper disc (+) spins positively about the upward normal for α > 0.
        assert!(k.spin > 0.0);
    }
}

#[test]
fn twin_disc_equation_3_is_a_special_case() {
    for beta_deg in [-3.0_f64, -0.5, 0.25, 1.0, 4.0] {
        let beta = beta_deg.to_radians();
        let (upper, lower) = rig(0.0, beta, 12.5e-3, 12.5e-3, 25e-3, 800.0);
        // Rolling direction = the upper disc's own direction (x rotated by β).
        let t = Vector3::new(beta.cos(), beta.sin(), 0.0);
        let k = contact_kinematics(&upper, &lower, Vector3::zeros(), Vector3::z(), t).unwrap();
        let eq3 = side_slip_ratio(beta).unwrap();
        // ΔV = (v⁺ − v⁻)·(n × t) = v⁻ sin β (the lower surface moves at −β from t),
        // U = v⁻ cos β: ΔV/U = +tan β for a skew β about the upward normal.
        assert!((k.side_slip_ratio().unwrap() - eq3).abs() < 1e-12);
        assert!(k.slip_ratio().unwrap().abs() < 1e-12);
        assert!(k.spin.abs() < 1e-12);
    }
}

/// Independent closed form in the meridian plane (derivation in
/// `traction_kinematics::HalfToroidalVariator` docs): contact radii
/// r_in,out = e0 − r0 cos(θ0 ∓ γ), speed ratio r_in/r_out (with e0 = (1 + k0) r0
/// this is the usual (1 + k0 − cos(θ0 − γ))/(1 + k0 − cos(θ0 + γ)) of the
/// half-toroidal literature, e.g. Carbone, Mangialardi & Mantriota, Mech. Mach.
/// Theory 39 (2004) 921–942), and spin per rolling speed
/// ω/U = cos θ0/(r0 sin θ0) − sin(θ0 ∓ γ)/r_in,out: the inverse apex distance of
/// the roller cone minus that of the disc cone at the contact.
fn closed_form(r0: f64, e0: f64, th: f64, g: f64) -> (f64, f64, f64, f64) {
    let r_in = e0 - r0 * (th - g).cos();
    let r_out = e0 - r0 * (th + g).cos();
    let roller = th.cos() / (r0 * th.sin());
    (
        r_in,
        r_out,
        roller - (th - g).sin() / r_in,
        roller - (th + g).sin() / r_out,
    )
}

#[test]
fn half_toroidal_variator_matches_closed_form() {
    // A half-toroidal variator of automotive size: r0 = 40 mm, k0 = 0.625
    // (e0 = 65 mm), θ0 = 62.5°; input 4000 rpm; tilt from −25° to +25°.
    let (r0, e0, th) = (40e-3, 65e-3, 62.5_f64.to_radians());
    let v = HalfToroidalVariator::new(r0, e0, th).unwrap();
    let w_in = 4000.0 * std::f64::consts::PI / 30.0;
    for i in -25..=25 {
        let g = f64::from(i).to_radians();
        let s = v.state(g, w_in).unwrap();
        let (r_in, r_out, spin_in, spin_out) = closed_form(r0, e0, th, g);
        assert!((s.input_radius / r_in - 1.0).abs() < 1e-12);
        assert!((s.output_radius / r_out - 1.0).abs() < 1e-12);
        assert!((s.speed_ratio / (r_in / r_out) - 1.0).abs() < 1e-12);
        // Rolling speed U = ω_in r_in at both contacts, no gross slip or approach.
        for k in [&s.input, &s.output] {
            assert!((k.rolling_speed / (w_in * r_in) - 1.0).abs() < 1e-12);
            assert!(k.slip.abs() < 1e-9 && k.side_slip.abs() < 1e-9 && k.approach.abs() < 1e-9);
        }
        // Spin: absolute tolerance relative to the roller term (spin can pass through 0).
        let scale = th.cos() / (r0 * th.sin());
        assert!((s.input.spin_per_speed().unwrap() - spin_in).abs() < 1e-12 * scale);
        assert!((s.output.spin_per_speed().unwrap() - spin_out).abs() < 1e-12 * scale);
    }
}

#[test]
fn half_toroidal_symmetry_and_zero_spin_design() {
    let (r0, th) = (40e-3, 60_f64.to_radians());
    // Ratio 1 at zero tilt; ratio(−γ) = 1/ratio(γ).
    let v = HalfToroidalVariator::new(r0, 70e-3, th).unwrap();
    assert!((v.state(0.0, 100.0).unwrap().speed_ratio - 1.0).abs() < 1e-12);
    let g = 0.3;
    let p = v.state(g, 100.0).unwrap().speed_ratio;
    let m = v.state(-g, 100.0).unwrap().speed_ratio;
    assert!((p * m - 1.0).abs() < 1e-12);
    // When the roller-cone apex lies on the main axis (e0 = r0/cos θ0) the
    // contacts are spin-free at zero tilt (pure cone rolling).
    let v0 = HalfToroidalVariator::new(r0, r0 / th.cos(), th).unwrap();
    let s = v0.state(0.0, 100.0).unwrap();
    assert!(s.input.spin.abs() < 1e-12 * 100.0 && s.output.spin.abs() < 1e-12 * 100.0);
    // ...but not at other tilts.
    assert!(v0.state(0.2, 100.0).unwrap().input.spin.abs() > 1.0);
}

#[test]
fn half_toroidal_rejects_contacts_past_the_axis() {
    // e0 < r0: at θ0 − γ = 31.4° the input contact radius 30 − 40 cos 31.4° mm < 0.
    let v = HalfToroidalVariator::new(40e-3, 30e-3, 60_f64.to_radians()).unwrap();
    let e = v.state(0.5, 100.0).unwrap_err();
    assert!(e.to_string().contains("contact radius"));
    assert!(HalfToroidalVariator::new(-1.0, 0.1, 1.0).is_err());
}

#[test]
fn speed_pole_is_j1_over_j3() {
    // Tilted rig (LS, k = 1, 6°) with the lower disc 0.5 % faster: ΔU < 0.
    let alpha = 6f64.to_radians();
    let (upper, mut lower) = rig(alpha, 0.0, 12.5e-3, 12.5e-3, 25e-3, 800.0);
    lower.angular_velocity *= 1.005;
    let k =
        contact_kinematics(&upper, &lower, Vector3::zeros(), Vector3::z(), Vector3::x()).unwrap();
    let (a, b) = (0.32e-3, 0.32e-3);
    let eps = k.speed_pole(a, b).unwrap();
    // Hand value: ΔU/U = −0.005·v/(1.0025·v), ω/U from eq. (6), ε = (ΔU/U)/(ω√(ab)/U).
    let du_u = -0.005 / 1.0025;
    let w_u = tilted_disc_spin_per_speed(alpha, 12.5e-3, 12.5e-3).unwrap() / 1.0025;
    // U is the mean speed: the upper spin per U scales with v⁺/U = 1/1.0025.
    let expect = du_u / (w_u * (a * b).sqrt());
    assert!((eps / expect - 1.0).abs() < 1e-9, "{eps} vs {expect}");
    let z = k.spin_group(a, b).unwrap();
    let j = j_groups(40.0, 0.08, 1.0, k.slip_ratio().unwrap(), 0.0, z).unwrap();
    assert!((j.j1 / j.j3 - eps).abs() < 1e-12 * eps.abs());
    // Zero spin: ε undefined, an error naming the spin.
    let (u0, l0) = rig(0.0, 0.0, 12.5e-3, 12.5e-3, 25e-3, 800.0);
    let k0 = contact_kinematics(&u0, &l0, Vector3::zeros(), Vector3::z(), Vector3::x()).unwrap();
    assert!(
        k0.speed_pole(a, b)
            .unwrap_err()
            .to_string()
            .contains("spin")
    );
}

fn vec3() -> impl Strategy<Value = Vector3<f64>> {
    (-10.0..10.0f64, -10.0..10.0f64, -10.0..10.0f64).prop_map(|(x, y, z)| Vector3::new(x, y, z))
}

proptest! {
    // Swapping the bodies (and flipping the normal, which keeps n pointing into
    // body 1) reverses ΔU and keeps U; ΔV keeps its sign because s = n × t flips
    // too, and ω = (Ω₁ − Ω₂)·n keeps its sign because both factors flip.
    #[test]
    fn swapping_bodies(w1 in vec3(), w2 in vec3(), p1 in vec3(), p2 in vec3(), n in vec3(), t in vec3()) {
        prop_assume!(n.norm() > 0.1 && n.cross(&t).norm() > 0.1);
        let b1 = BodyMotion::rotating(w1, p1);
        let b2 = BodyMotion::rotating(w2, p2);
        let a = contact_kinematics(&b1, &b2, Vector3::zeros(), n, t).unwrap();
        let b = contact_kinematics(&b2, &b1, Vector3::zeros(), -n, t).unwrap();
        let tol = 1e-9 * (1.0 + a.surface_velocity_1.norm() + a.surface_velocity_2.norm());
        prop_assert!((a.rolling_speed - b.rolling_speed).abs() < tol);
        prop_assert!((a.slip + b.slip).abs() < tol);
        prop_assert!((a.side_slip - b.side_slip).abs() < tol);
        prop_assert!((a.spin - b.spin).abs() < 1e-9 * (1.0 + w1.norm() + w2.norm()));
    }

    // A common rigid motion added to both bodies leaves every relative quantity unchanged.
    #[test]
    fn common_motion_does_not_change_relative_kinematics(
        w1 in vec3(), w2 in vec3(), p1 in vec3(), p2 in vec3(), wc in vec3(), pc in vec3(),
        n in vec3(), t in vec3(),
    ) {
        prop_assume!(n.norm() > 0.1 && n.cross(&t).norm() > 0.1);
        let plain = contact_kinematics(
            &BodyMotion::rotating(w1, p1), &BodyMotion::rotating(w2, p2), Vector3::zeros(), n, t).unwrap();
        // Adding Ω_c about p_c to body i: equivalent to Ω_i + Ω_c with V_i = Ω_c × (p_i − p_c).
        let add = |w: Vector3<f64>, p: Vector3<f64>| BodyMotion {
            angular_velocity: w + wc, axis_point: p, velocity: wc.cross(&(p - pc)) };
        let moved = contact_kinematics(&add(w1, p1), &add(w2, p2), Vector3::zeros(), n, t).unwrap();
        let tol = 1e-9 * (1.0 + w1.norm() + w2.norm() + wc.norm()) * (1.0 + p1.norm() + p2.norm() + pc.norm());
        prop_assert!((plain.slip - moved.slip).abs() < tol);
        prop_assert!((plain.side_slip - moved.side_slip).abs() < tol);
        prop_assert!((plain.spin - moved.spin).abs() < tol);
    }

    // Equation (6): spin grows with the tilt while the rolling radius stays positive.
    #[test]
    fn eq6_monotonic_in_tilt(a1 in 0.0..0.6f64, da in 1e-4..0.3f64, ry in 1e-3..0.3f64, e in 0.0..0.1f64) {
        let w1 = tilted_disc_spin_per_speed(a1, ry, e).unwrap();
        let w2 = tilted_disc_spin_per_speed(a1 + da, ry, e).unwrap();
        prop_assert!(w2 > w1);
    }
}
