//! Callgrind driver for the viscoelastic benches: `prof-visco CASE TOL REPS
//! [old|gauss]` (CASE a letter of the bench set or `k,J1,J2,J3,gy,D,Z0`);
//! instructions per evaluation = (Ir(REPS=3) − Ir(1))/2. `old`
//! runs the former fixed-grid scheme with its former resolution at TOL
//! (`reference::viscoelastic`: 2·⌊max(1, −log10 TOL − 1)⌋ panels of 8
//! points, ⌈20·10^(−log10(TOL)/2)⌉ uniform steps per strip), `gauss` the
//! adaptive solver with the former Gauss–Legendre panel rule
//! (`reference::viscoelastic_gauss_panels`). Built with the feature
//! `step-counts` it also prints the strips and steps per evaluation (see
//! `prof::print_counts`) to stderr.
#![allow(clippy::unwrap_used)]
use crate::arg;
use traction_rheology::{Accuracy, Inputs, Model, Resolution, evaluate, reference};
use traction_testkit::bench_cases::VISCOELASTIC;

/// A bench case by its letter, or `k,J1,J2,J3,gy,D,Z0`: (k, J, gy, D, Z0).
fn visco_case(case: &str) -> Result<(f64, [f64; 3], f64, f64, f64), String> {
    if case.contains(',') {
        let v: Vec<f64> = case
            .split(',')
            .map(|x| x.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|e| format!("case `{case}`: {e}"))?;
        return match v[..] {
            [k, j1, j2, j3, gy, d, z0] => Ok((k, [j1, j2, j3], gy, d, z0)),
            _ => Err(format!("case `{case}`: expected k,J1,J2,J3,gy,D,Z0")),
        };
    }
    VISCOELASTIC
        .iter()
        .find(|c| c.letter == case)
        .map(|c| (c.k, c.j, c.gy, c.deborah, c.z0))
        .ok_or_else(|| format!("unknown case `{case}`"))
}

/// Runs the driver with the command line's arguments after `prof-visco`.
pub fn run(a: &[String]) -> Result<(), String> {
    let case = a.first().map(|s| s.as_str()).unwrap_or("m");
    let tol: f64 = arg(a, 1, "TOL", Some(1e-3))?;
    let reps: usize = arg(a, 2, "REPS", Some(1))?;
    let variant = a.get(3).map(String::as_str);
    if let Some(v) = variant.filter(|v| *v != "old" && *v != "gauss") {
        return Err(format!("unknown variant `{v}` (old, gauss)"));
    }
    let (k, j, gy, deborah, z0) = visco_case(case)?;
    let inp = Inputs::new(k, j[0], j[1], j[2])
        .and_then(|i| i.with_stiffness_ratio(gy))
        .map_err(|e| e.to_string())?;
    let acc = Accuracy::new(tol).map_err(|e| e.to_string())?;
    let lt = -tol.log10();
    let res = Resolution {
        y_panels: ((lt - 1.0).max(1.0) * 2.0) as usize,
        y_points: 8,
        s_step: 0.1,
    };
    let nsteps = (20.0 * 10f64.powf(lt * 0.5)).ceil().clamp(40.0, 20000.0) as usize;
    let eval = |i: &Inputs| match variant {
        Some("old") => reference::viscoelastic(i, deborah, z0, &res, nsteps).unwrap(),
        Some(_) => reference::viscoelastic_gauss_panels(i, deborah, z0, acc).unwrap(),
        None => evaluate(i, Model::Viscoelastic { deborah, z0 }, acc).unwrap(),
    };
    let mut o = eval(&inp);
    for _ in 1..reps {
        o = eval(std::hint::black_box(&inp));
    }
    println!("{:.10} {:.10} {:.10}", o.j4, o.j5, o.j6);
    #[cfg(feature = "step-counts")]
    crate::prof::print_counts(reps, true);
    Ok(())
}
