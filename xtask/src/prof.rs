//! Callgrind driver for the elastic/plastic benches: `prof CASE TOL REPS`;
//! instructions per evaluation = (Ir(REPS=3) − Ir(1))/2. CASE is one of the
//! bench set `traction_testkit::bench_cases::ELASTIC_PLASTIC` (the crate's
//! criterion group `elastic_plastic` runs the same) by its letter (`m`
//! moderate, `h` high spin, …); an optional fourth argument GY sets the
//! stiffness ratio gy (default 1).
#![allow(clippy::unwrap_used)]
use crate::arg;
use traction_rheology::{Accuracy, Inputs, Model, evaluate};
use traction_testkit::bench_cases::ELASTIC_PLASTIC;

/// Runs the driver with the command line's arguments after `prof`.
pub fn run(a: &[String]) -> Result<(), String> {
    let case = a.first().map(|s| s.as_str()).unwrap_or("m");
    let tol: f64 = arg(a, 1, "TOL", Some(1e-3))?;
    let reps: usize = arg(a, 2, "REPS", Some(1))?;
    let gy: f64 = arg(a, 3, "GY", Some(1.0))?;
    let c = ELASTIC_PLASTIC
        .iter()
        .find(|c| c.letter == case)
        .ok_or_else(|| format!("unknown case `{case}`"))?;
    let inp = Inputs::new(c.k, c.j[0], c.j[1], c.j[2])
        .and_then(|i| i.with_stiffness_ratio(gy))
        .map_err(|e| e.to_string())?;
    let acc = Accuracy::new(tol).map_err(|e| e.to_string())?;
    let mut o = evaluate(&inp, Model::ElasticPlastic, acc).unwrap();
    for _ in 1..reps {
        o = evaluate(std::hint::black_box(&inp), Model::ElasticPlastic, acc).unwrap();
    }
    println!("{:.10} {:.10} {:.10}", o.j4, o.j5, o.j6);
    Ok(())
}
