//! Callgrind driver for the elastic/plastic benches: `prof CASE TOL REPS`
//! (CASE `m` = moderate k=1 J=(1.5,0.3,2), `h` = high spin k=5
//! J=(0,3.368,25.816)); instructions per evaluation = (Ir(REPS=3) − Ir(1))/2.
#![allow(clippy::unwrap_used)]
use crate::arg;
use traction_rheology::{Accuracy, Inputs, Model, evaluate};

/// Runs the driver with the command line's arguments after `prof`.
pub fn run(a: &[String]) -> Result<(), String> {
    let case = a.first().map(|s| s.as_str()).unwrap_or("m");
    let tol: f64 = arg(a, 1, "TOL", Some(1e-3))?;
    let reps: usize = arg(a, 2, "REPS", Some(1))?;
    let inp = if case == "m" {
        Inputs::new(1.0, 1.5, 0.3, 2.0).unwrap()
    } else {
        Inputs::new(5.0, 0.0, 3.368, 25.816).unwrap()
    };
    let acc = Accuracy::new(tol).map_err(|e| e.to_string())?;
    let mut o = evaluate(&inp, Model::ElasticPlastic, acc).unwrap();
    for _ in 1..reps {
        o = evaluate(std::hint::black_box(&inp), Model::ElasticPlastic, acc).unwrap();
    }
    println!("{:.10} {:.10} {:.10}", o.j4, o.j5, o.j6);
    Ok(())
}
