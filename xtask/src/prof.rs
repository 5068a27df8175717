//! Callgrind driver for the elastic/plastic benches: `prof CASE TOL REPS`;
//! instructions per evaluation = (Ir(REPS=3) − Ir(1))/2. CASE is one of the
//! bench set [`CASES`] by its letter (`m` moderate, `h` high spin, …).
#![allow(clippy::unwrap_used)]
use crate::arg;
use traction_rheology::{Accuracy, Inputs, Model, evaluate};

/// The bench set: (letter, k, J1, J2, J3), the same as the crate's criterion
/// bench `elastic_plastic`.
pub const CASES: [(&str, f64, f64, f64, f64); 7] = [
    ("m", 1.0, 1.5, 0.3, 2.0),
    ("h", 5.0, 0.0, 3.368, 25.816),
    ("p", 0.2, 0.11, 0.08, 0.70),
    ("s", 20.0, 0.5, 2.0, 40.0),
    ("a", 0.5, 2.0, -1.0, 10.0),
    ("b", 2.0, -1.0, 3.0, 15.0),
    ("c", 1.0, 0.2, 0.1, 5.0),
];

/// Runs the driver with the command line's arguments after `prof`.
pub fn run(a: &[String]) -> Result<(), String> {
    let case = a.first().map(|s| s.as_str()).unwrap_or("m");
    let tol: f64 = arg(a, 1, "TOL", Some(1e-3))?;
    let reps: usize = arg(a, 2, "REPS", Some(1))?;
    let &(_, k, j1, j2, j3) = CASES
        .iter()
        .find(|c| c.0 == case)
        .ok_or_else(|| format!("unknown case `{case}`"))?;
    let inp = Inputs::new(k, j1, j2, j3).map_err(|e| e.to_string())?;
    let acc = Accuracy::new(tol).map_err(|e| e.to_string())?;
    let mut o = evaluate(&inp, Model::ElasticPlastic, acc).unwrap();
    for _ in 1..reps {
        o = evaluate(std::hint::black_box(&inp), Model::ElasticPlastic, acc).unwrap();
    }
    println!("{:.10} {:.10} {:.10}", o.j4, o.j5, o.j6);
    Ok(())
}
