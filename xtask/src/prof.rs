//! Callgrind driver for the elastic/plastic benches: `prof CASE TOL REPS`;
//! instructions per evaluation = (Ir(REPS=3) − Ir(1))/2. CASE is one of the
//! bench set `traction_testkit::bench_cases::ELASTIC_PLASTIC` (the crate's
//! criterion group `elastic_plastic` runs the same) by its letter (`m`
//! moderate, `h` high spin, …), or any inputs as `k,J1,J2,J3`; an optional
//! fourth argument GY sets the stiffness ratio gy (default 1). Built with
//! the feature `step-counts` it also prints the strips and plastic steps by
//! kind per evaluation (`traction_rheology::StepCounts`) to stderr.
#![allow(clippy::unwrap_used)]
use crate::arg;
use traction_rheology::{Accuracy, Inputs, Model, evaluate};
use traction_testkit::bench_cases::ELASTIC_PLASTIC;

/// (k, [J1, J2, J3]) of a bench case's letter or of `k,J1,J2,J3`.
fn case_inputs(case: &str) -> Result<(f64, [f64; 3]), String> {
    if case.contains(',') {
        let v: Vec<f64> = case
            .split(',')
            .map(|x| x.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|e| format!("case `{case}`: {e}"))?;
        return match v[..] {
            [k, j1, j2, j3] => Ok((k, [j1, j2, j3])),
            _ => Err(format!("case `{case}`: expected k,J1,J2,J3")),
        };
    }
    ELASTIC_PLASTIC
        .iter()
        .find(|c| c.letter == case)
        .map(|c| (c.k, c.j))
        .ok_or_else(|| format!("unknown case `{case}` (m h p s a b c, or k,J1,J2,J3)"))
}

/// Runs the driver with the command line's arguments after `prof`.
pub fn run(a: &[String]) -> Result<(), String> {
    let case = a.first().map(|s| s.as_str()).unwrap_or("m");
    let tol: f64 = arg(a, 1, "TOL", Some(1e-3))?;
    let reps: usize = arg(a, 2, "REPS", Some(1))?;
    let gy: f64 = arg(a, 3, "GY", Some(1.0))?;
    let (k, j) = case_inputs(case)?;
    let inp = Inputs::new(k, j[0], j[1], j[2])
        .and_then(|i| i.with_stiffness_ratio(gy))
        .map_err(|e| e.to_string())?;
    let acc = Accuracy::new(tol).map_err(|e| e.to_string())?;
    let mut o = evaluate(&inp, Model::ElasticPlastic, acc).unwrap();
    for _ in 1..reps {
        o = evaluate(std::hint::black_box(&inp), Model::ElasticPlastic, acc).unwrap();
    }
    println!("{:.10} {:.10} {:.10}", o.j4, o.j5, o.j6);
    #[cfg(feature = "step-counts")]
    print_counts(reps, false);
    Ok(())
}

/// The step counts per evaluation, on stderr: the elastic/plastic strips
/// and their plastic steps by kind; with `visco` the viscoelastic strips
/// and their Rosenbrock step attempts, then the plastic steps of their caps
/// (those with an isotropic stiffness run on the elastic/plastic stepping).
#[cfg(feature = "step-counts")]
pub fn print_counts(reps: usize, visco: bool) {
    let c = traction_rheology::step_counts();
    let r = reps.max(1) as f64;
    let per = |n: u64| n as f64 / r;
    let (head, strips) = if visco {
        let head = format!(
            "{:.0} viscoelastic strips, {:.0} Rosenbrock step attempts; on the caps",
            per(c.visco_strips),
            per(c.visco_steps)
        );
        (head, per(c.visco_strips))
    } else {
        let head = format!(
            "{:.0} strips, {:.1} yield searches",
            per(c.strips),
            per(c.yield_searches)
        );
        (head, per(c.strips))
    };
    eprintln!(
        "per evaluation: {head}: {:.0} stiff steps, {:.0} RK4 steps ({:.0} of them \
         sub-steps), {:.0} fifth-order, {:.0} exponential, {:.0} Rosenbrock, {:.0} \
         quasi-steady, {:.1} unloadings; per strip {:.1} RK4",
        per(c.stiff_steps),
        per(c.rk4),
        per(c.rk4_sub_steps),
        per(c.rk5),
        per(c.exponential),
        per(c.rosenbrock),
        per(c.quasi_steady),
        per(c.unloadings),
        per(c.rk4) / strips.max(1.0),
    );
}
