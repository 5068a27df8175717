//! Load the toroidal variator FMU from Rust with the `fmi` crate and step it.
//!
//! ```text
//! cargo run -p traction-cli -- fmu build --model variator --out target/fmu/ToroidalVariator.fmu
//! cargo run -p traction-examples --example variator_fmu_import -- target/fmu/ToroidalVariator.fmu
//! ```
//!
//! The input disc turns at 300 rad/s, the rollers are tilted by 0.3 rad and the
//! output disc runs 1 % slower than the geometry's speed ratio: the variator
//! transmits torque from the input to the output disc. Value references are
//! looked up by name in modelDescription.xml; the example checks the power
//! balance (input power = output power + losses) and the efficiency.
use std::process::ExitCode;

use fmi::fmi2::import::Fmi2Import;
use fmi::fmi2::instance::{CoSimulation, Common};
use fmi::traits::{FmiImport, FmiInstance};

fn main() -> ExitCode {
    let Some(path) = std::env::args().nth(1) else {
        eprintln!(
            "usage: variator_fmu_import PATH.fmu (build it with `traction fmu build --model variator`)"
        );
        return ExitCode::from(2);
    };
    match run(&path) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(path: &str) -> Result<(), String> {
    let import: Fmi2Import =
        fmi::import::from_path(path).map_err(|e| format!("loading {path}: {e:?}"))?;
    let md = import.model_description();
    let vr = |name: &str| {
        md.model_variable_by_name(name)
            .map(|v| v.value_reference)
            .map_err(|e| format!("variable `{name}`: {e:?}"))
    };
    let inputs = [vr("omega_in")?, vr("omega_out")?, vr("tilt_angle")?];
    let outputs = [
        vr("speed_ratio")?,
        vr("torque_in")?,
        vr("torque_out")?,
        vr("power_loss")?,
        vr("efficiency")?,
    ];
    let mut fmu = import
        .instantiate_cs("example", false, true)
        .map_err(|e| format!("instantiate: {e:?}"))?;
    println!("{} (FMI {})", md.model_name, Common::get_version(&fmu));
    let (omega_in, tilt) = (300.0, 0.3);
    // The kinematic ratio first (a step with the output at rest), then the
    // output disc at 99 % of it.
    fmu.set_real(&inputs, &[omega_in, 0.0, tilt])
        .map_err(|e| format!("set inputs: {e:?}"))?;
    FmiInstance::enter_initialization_mode(&mut fmu, None, 0.0, Some(0.1))
        .map_err(|e| format!("initialise: {e:?}"))?;
    FmiInstance::exit_initialization_mode(&mut fmu).map_err(|e| format!("initialise: {e:?}"))?;
    let mut out = [0.0; 5];
    fmu.get_real(&outputs, &mut out)
        .map_err(|e| format!("get outputs: {e:?}"))?;
    let omega_out = 0.99 * out[0] * omega_in;
    fmu.set_real(&inputs[1..2], &[omega_out])
        .map_err(|e| format!("set omega_out: {e:?}"))?;
    let h = 1e-3;
    for k in 0..5 {
        fmu.do_step(f64::from(k) * h, h, true)
            .map_err(|e| format!("step {k}: {e:?}"))?;
    }
    fmu.get_real(&outputs, &mut out)
        .map_err(|e| format!("get outputs: {e:?}"))?;
    let [ratio, t_in, t_out, loss, efficiency] = out;
    println!(
        "ratio {ratio:.4}: torque in {t_in:.2} N·m, out {t_out:.2} N·m, loss {loss:.1} W, efficiency {efficiency:.4}"
    );
    // Power balance: the input disc receives t_in·ω_in (negative: it drives),
    // the output disc t_out·ω_out.
    let (p_in, p_out) = (-t_in * omega_in, t_out * omega_out);
    let balance = (p_in - p_out - loss).abs() / p_in.abs();
    println!("input power {p_in:.1} W, output {p_out:.1} W, balance residual {balance:.2e}");
    if !(p_in > 0.0 && p_out > 0.0 && balance < 1e-8 && efficiency > 0.5 && efficiency < 1.0) {
        return Err(format!("unexpected outputs {out:?}"));
    }
    Ok(())
}
