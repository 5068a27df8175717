//! Load the traction contact FMU from Rust with the `fmi` crate and step it.
//!
//! ```text
//! cargo run -p traction-cli -- fmu build --out target/fmu
//! cargo run -p traction-examples --example fmu_import -- target/fmu/TractionContact.fmu
//! ```
//!
//! Value references are looked up by variable name in the FMU's
//! modelDescription.xml, as any importer would.
use std::process::ExitCode;

use fmi::fmi2::import::Fmi2Import;
use fmi::fmi2::instance::{CoSimulation, Common};
use fmi::traits::{FmiImport, FmiInstance};

fn main() -> ExitCode {
    let Some(path) = std::env::args().nth(1) else {
        eprintln!("usage: fmu_import PATH.fmu (build it with `traction fmu build`)");
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
    let inputs = [vr("normal_load")?, vr("omega1")?, vr("omega2")?];
    let outputs = [vr("fx")?, vr("traction_coefficient")?, vr("p0")?];
    let mut fmu = import
        .instantiate_cs("example", false, true)
        .map_err(|e| format!("instantiate: {e:?}"))?;
    println!("{} (FMI {})", md.model_name, Common::get_version(&fmu));
    // 700 N; body 1 (radius 33 mm) slightly faster than body 2 (71.4 mm).
    fmu.set_real(&inputs, &[700.0, 600.0, 276.0])
        .map_err(|e| format!("set inputs: {e:?}"))?;
    FmiInstance::enter_initialization_mode(&mut fmu, None, 0.0, Some(0.1))
        .map_err(|e| format!("initialise: {e:?}"))?;
    FmiInstance::exit_initialization_mode(&mut fmu).map_err(|e| format!("initialise: {e:?}"))?;
    let h = 1e-3;
    let mut out = [0.0; 3];
    for k in 0..100 {
        fmu.do_step(f64::from(k) * h, h, true)
            .map_err(|e| format!("step {k}: {e:?}"))?;
        fmu.get_real(&outputs, &mut out)
            .map_err(|e| format!("get outputs: {e:?}"))?;
        if k % 25 == 0 {
            println!(
                "t = {:.3} s: fx = {:.2} N, fx/N = {:.4}, P0 = {:.3} GPa",
                f64::from(k + 1) * h,
                out[0],
                out[1],
                out[2] / 1e9
            );
        }
    }
    if !(out[0] > 0.0 && out[1] > 0.0 && out[1] < 0.1) {
        return Err(format!("unexpected outputs {out:?}"));
    }
    Ok(())
}
