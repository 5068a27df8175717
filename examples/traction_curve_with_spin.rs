//! A traction curve under spin: the traction coefficient Fx/N of a toroid on a
//! disc against the slip ΔU/U, with and without spin (elastic/plastic J+T model,
//! a user fluid with traction slope m = 35 and peak coefficient μ = 0.075).
use traction_contact::{Body, ContactError, Fluid, OperatingState, Options, TractionContact};

fn main() -> Result<(), ContactError> {
    let toroid = Body::steel(33e-3, 270e-3);
    let disc = Body::steel(71.4e-3, f64::INFINITY);
    let contact = TractionContact::new(
        &toroid,
        &disc,
        Fluid::constant(35.0, 0.075)?,
        Options::default(),
    )?;
    let (load, rolling_speed, temperature) = (1500.0, 20.0, 70.0);
    println!("slip dU/U, Fx/N without spin, Fx/N with spin 100 rad/s");
    let mut previous = (0.0, 0.0);
    for i in 0..=10 {
        let slip_ratio = 0.002 * f64::from(i);
        let slip = slip_ratio * rolling_speed;
        let coefficient = |spin: f64| -> Result<f64, ContactError> {
            let state = OperatingState::new(load, rolling_speed, slip, 0.0, spin, temperature)?;
            Ok(contact.evaluate(&state)?.fx / load)
        };
        let (plain, spinning) = (coefficient(0.0)?, coefficient(100.0)?);
        println!("{slip_ratio:.3}, {plain:.5}, {spinning:.5}");
        // The curves rise with slip, stay below μ, and spin lowers the traction.
        assert!(plain >= previous.0 && spinning >= previous.1 - 1e-9);
        assert!(plain < 0.075 && spinning <= plain + 1e-12);
        previous = (plain, spinning);
    }
    Ok(())
}
