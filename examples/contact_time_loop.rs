//! A contact stepped in a time loop, as a drivetrain model calls it: a driving
//! disc starts from rest and pulls a driven disc with inertia through the
//! traction of the contact (explicit Euler, 1 ms steps). Only the public API of
//! traction-contact is used.
use traction_contact::{Body, ContactError, Fluid, OperatingState, Options, TractionContact};

fn main() -> Result<(), ContactError> {
    let (r1, r2) = (33e-3, 71.4e-3); // rolling radii = the discs' Rx, m
    let contact = TractionContact::new(
        &Body::steel(r1, 270e-3),
        &Body::steel(r2, f64::INFINITY),
        Fluid::constant(35.0, 0.075)?,
        Options::default(),
    )?;
    let load = 700.0; // N
    let inertia2 = 0.005; // driven disc and its load, kg·m²
    let drag2 = 5e-3; // the driven side's drag, N·m per rad/s
    let (dt, steps) = (1e-3, 2000);
    let mut omega2: f64 = 0.0;
    for n in 0..=steps {
        let t = f64::from(n) * dt;
        // The driving disc ramps up to 600 rad/s in 0.5 s and holds.
        let omega1 = 600.0 * (t / 0.5).min(1.0);
        let (u1, u2) = (omega1 * r1, omega2 * r2);
        let state = OperatingState::new(load, 0.5 * (u1 + u2), u1 - u2, 0.0, 0.0, 40.0)?;
        let e = contact.evaluate(&state)?;
        if n % 250 == 0 {
            println!(
                "t = {t:.2} s: u1 = {u1:6.3} m/s, u2 = {u2:6.3} m/s, Fx = {:7.2} N, loss = {:6.2} W",
                e.fx, e.loss
            );
        }
        // Body 1 drags body 2 forward with Fx at radius r2.
        omega2 += dt * (e.fx * r2 - drag2 * omega2) / inertia2;
    }
    // Steady state: the driven disc runs with the small slip that transmits the
    // drag torque (about 1.4 N·m, Fx ≈ 19 N, Fx/N ≈ 0.028 < μ = 0.075).
    let (u1, u2) = (600.0 * r1, omega2 * r2);
    let slip_ratio = (u1 - u2) / (0.5 * (u1 + u2));
    println!("steady slip dU/U = {slip_ratio:.5}");
    assert!(slip_ratio > 0.0 && slip_ratio < 0.01, "{slip_ratio}");
    Ok(())
}
