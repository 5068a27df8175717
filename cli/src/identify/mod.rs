//! `traction identify`: calibrate the contact model's parameters on measured
//! traction curves.
//!
//! Input: a CSV with the `traction contact` input columns (`rx1,ry1,rx2,ry2,
//! e1,nu1,e2,nu2,load,u,du,dv,omega,theta`, SI units; the fluid as `fluid` or
//! `m,mu[,mu_spin]`, see `traction contact`) plus the measured traction
//! coefficients `fx_over_n` and/or `fy_over_n` (Fx/N, Fy/N in the sign
//! convention of traction-contact: the force body 1 exerts on body 2, positive
//! slip ΔU gives positive Fx). One or more curves may share the file: every
//! row is one measured point, and every non-empty measured cell one residual
//! r = model − measured. A row may leave the fluid empty when the parameters
//! it would give (`m`, `mu`) are fitted as values.
//!
//! The model is the full dimensional contact (slip, side slip, spin through
//! traction-contact) with [`Fluid::Constant`](traction_contact::Fluid::Constant)
//! per row: the slope m, the peak
//! traction coefficient μ and (optionally) the spin-peak μ_s that scales the
//! forces. A row's *baseline* m, μ, μ_s are its `m,mu,mu_spin` cells or, with
//! a `fluid` column, the named fluid's correlations evaluated at the row's
//! P0, |U|, θ, k (as `traction contact` would, before any compliance
//! correction); a row with both a fluid and `m,mu` cells takes the cells (the
//! values at the inlet, as in `traction contact`). The fitted parameters act on the baselines as listed in
//! [`PARAMETERS`]: `m`, `mu`, `mu_spin` replace the baseline by one value for
//! all rows (one operating condition); `m_factor`, `mu_factor` multiply each
//! row's baseline (several conditions, the fluid's correlation trends kept);
//! `slip_offset`, `side_slip_offset` are zero errors of the measured slip
//! ratios (the model sees ΔU + offset·U).
//!
//! `--thermal`: the thermal contact (traction-contact `Options::thermal`). A
//! row with a `fluid` keeps that report fluid, with its baseline m, μ as the
//! values at the inlet temperature (`Fluid::with_inlet_values`), so its own
//! film and temperature coefficients apply; a row with `m,mu` needs the
//! thermal-property columns of `traction contact --thermal` (at least
//! `film_thickness` or `viscosity,pressure_viscosity`, `fluid_conductivity`
//! and `mu_temperature_coefficient`) unless they are fitted. The thermal
//! parameters `mu_temperature_coefficient`, `m_temperature_coefficient` (one
//! value for all rows, 1/K), `mu_rise_scale` (T* of the second-order term of
//! ln μ in the rise, K) and `film_factor` (a factor on every row's film
//! thickness, i.e. on the film's thermal resistance h/(8k_f)) are fitted only
//! with `--thermal`.
//!
//! The fit is nonlinear least squares (Levenberg–Marquardt,
//! [`traction_regression::nls`]) with a central-difference Jacobian, steps of
//! 1e-3 of max(|value|, scale). The J+T strip integrator is adaptive; its
//! results jump by up to its tolerance when a parameter moves, so the
//! rheology tolerance defaults to 1e-6 here (`--tol`, against 1e-4 in
//! `traction contact`): derivative errors ≈ 1e-6/1e-3 = 0.1 %.
//!
//! Output (`--output`, default stdout): `name,value,stderr`, one row per
//! fitted parameter (stderr `inf` when the data do not determine it). On
//! stderr: the RMS residual, the termination, the condition number and the
//! correlation matrix of the parameters, and a warning for every parameter
//! that is not identifiable (see [`diagnose`]). `--residuals PATH` writes the
//! input rows with the model values and residuals; `--plot DIR` draws
//! `identify-fit.png` (measured and fitted against the slip ratio) and
//! `identify-residuals.png` (residuals), with SVG twins.

mod params;
mod problem;
mod report;

use std::path::PathBuf;
use std::time::Instant;

use clap::Args;
use traction_regression::nls::{self, Parameter};

pub use params::{PARAMETERS, ParameterSpec, Trial};
pub use report::diagnose;

use crate::contact::{ComplianceArg, EnvelopeArg, LimitArg, ModelArg, ModelOptions, ModulusArg};
use crate::error::CliError;
use crate::table::{Table, TableWriter, fmt_f64};
use problem::{Problem, read_points};
use report::{plot, summary, write_residuals};

/// Relative finite-difference step of the Jacobian.
const RELATIVE_STEP: f64 = 1e-3;

/// |correlation| above which two parameters are reported as not separately
/// identifiable.
pub const MAX_CORRELATION: f64 = 0.99;

/// A standard error above this fraction of max(|value|, scale) marks a
/// parameter as not determined by the data.
pub const MAX_RELATIVE_STDERR: f64 = 0.5;

/// Arguments of `traction identify`.
#[derive(Debug, Args)]
pub struct IdentifyArgs {
    /// Input CSV (`-` for stdin): the `traction contact` columns plus measured
    /// fx_over_n and/or fy_over_n.
    #[arg(long)]
    pub input: String,
    /// Parameters to fit, comma separated: m, mu, mu_spin, m_factor,
    /// mu_factor, slip_offset, side_slip_offset; with --thermal also
    /// mu_temperature_coefficient, m_temperature_coefficient, mu_rise_scale,
    /// film_factor.
    #[arg(long, value_delimiter = ',', required = true)]
    pub fit: Vec<String>,
    /// Initial values, comma separated `name=value` (default: from the
    /// baselines or the data).
    #[arg(long, value_delimiter = ',')]
    pub start: Vec<String>,
    /// Thermal contact model (traction-contact `thermal`); its parameters
    /// may be fitted too.
    #[arg(long)]
    pub thermal: bool,
    /// Output CSV `name,value,stderr` (`-` for stdout).
    #[arg(long, default_value = "-")]
    pub output: String,
    /// Also write the input rows with the fitted model and residuals
    /// (fx_over_n_model, fy_over_n_model, fx_residual, fy_residual).
    #[arg(long)]
    pub residuals: Option<String>,
    /// Draw identify-fit.png/svg and identify-residuals.png/svg in this
    /// directory (created if missing).
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Largest number of Levenberg–Marquardt iterations.
    #[arg(long, default_value_t = 50)]
    pub max_iterations: usize,
    /// Constitutive model.
    #[arg(long, value_enum, default_value_t = ModelArg::ElasticPlastic)]
    pub model: ModelArg,
    /// Absolute accuracy of J4, J5, J6 (1e-9..0.1); tight by default so that
    /// finite-difference derivatives are smooth.
    #[arg(long, default_value_t = 1e-6)]
    pub tol: f64,
    /// What a report fluid does outside its data envelope (baselines).
    #[arg(long, value_enum, default_value_t = EnvelopeArg::Strict)]
    pub envelope: EnvelopeArg,
    /// Disc-compliance correction (report steel, E = 210 GPa, ν = 0.3).
    #[arg(long, value_enum, default_value_t = ComplianceArg::Off)]
    pub compliance: ComplianceArg,
    /// Rolling-speed floor U_f of the J groups (m/s).
    #[arg(long, default_value_t = traction_contact::DEFAULT_ROLLING_SPEED_FLOOR)]
    pub floor: f64,
}

fn parse_fit_list(args: &IdentifyArgs) -> Result<Vec<&'static ParameterSpec>, CliError> {
    let known = || {
        PARAMETERS
            .iter()
            .map(|p| p.name)
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut specs: Vec<&'static ParameterSpec> = Vec::new();
    for name in args.fit.iter().map(|s| s.trim()) {
        let spec = PARAMETERS.iter().find(|p| p.name == name).ok_or_else(|| {
            CliError::Usage(format!(
                "--fit: unknown parameter `{name}` (known: {})",
                known()
            ))
        })?;
        if spec.thermal && !args.thermal {
            return Err(CliError::Usage(format!(
                "--fit: `{name}` is a parameter of the thermal model: add --thermal"
            )));
        }
        if specs.iter().any(|s| s.name == name) {
            return Err(CliError::Usage(format!(
                "--fit: parameter `{name}` given twice"
            )));
        }
        if let Some(other) = specs.iter().find(|s| spec.excludes.contains(&s.name)) {
            return Err(CliError::Usage(format!(
                "--fit: `{name}` and `{}` cannot be fitted together (one replaces what the other scales)",
                other.name
            )));
        }
        specs.push(spec);
    }
    if specs.is_empty() {
        return Err(CliError::Usage(format!(
            "--fit: no parameter given (known: {})",
            known()
        )));
    }
    Ok(specs)
}

fn parse_start(
    args: &IdentifyArgs,
    specs: &[&'static ParameterSpec],
) -> Result<Vec<Option<f64>>, CliError> {
    let mut start = vec![None; specs.len()];
    for item in args
        .start
        .iter()
        .map(|s| s.trim())
        .filter(|s| !s.is_empty())
    {
        let (name, value) = item.split_once('=').ok_or_else(|| {
            CliError::Usage(format!("--start: `{item}` is not of the form name=value"))
        })?;
        let j = specs
            .iter()
            .position(|s| s.name == name.trim())
            .ok_or_else(|| {
                CliError::Usage(format!(
                    "--start: `{}` is not a fitted parameter (--fit)",
                    name.trim()
                ))
            })?;
        let v = crate::table::parse_number(value.trim())
            .map_err(|m| CliError::Usage(format!("--start {name}: {m}")))?;
        let s = specs[j];
        if !(v.is_finite() && v >= s.lower && v <= s.upper) {
            return Err(CliError::Usage(format!(
                "--start {name} = {v} is out of range: {} must be in [{}, {}]",
                s.description, s.lower, s.upper
            )));
        }
        start[j] = Some(v);
    }
    Ok(start)
}

/// Run the subcommand.
pub fn run(args: IdentifyArgs) -> Result<(), CliError> {
    if args.max_iterations == 0 {
        return Err(CliError::Usage(
            "--max-iterations must be at least 1".into(),
        ));
    }
    let specs = parse_fit_list(&args)?;
    let start = parse_start(&args, &specs)?;
    let model = ModelOptions {
        model: args.model,
        tol: args.tol,
        envelope: args.envelope,
        compliance: args.compliance,
        spin_peak: false,
        floor: args.floor,
        modulus: ModulusArg::Constant,
        limit: LimitArg::Pressure,
        thermal: args.thermal,
    };
    let mut options = model.options().map_err(CliError::Usage)?;
    options.classify_regime = false;
    let table = Table::read(&args.input)?;
    let points = read_points(&table, &model, &specs)?;
    let mut index = Vec::new();
    for (i, p) in points.iter().enumerate() {
        if p.fx.is_some() {
            index.push((i, 0));
        }
        if p.fy.is_some() {
            index.push((i, 1));
        }
    }
    if index.len() <= specs.len() {
        return Err(CliError::Usage(format!(
            "{}: {} measured values for {} fitted parameters: need more values than parameters",
            table.source_name,
            index.len(),
            specs.len()
        )));
    }
    let problem = Problem {
        table: &table,
        points,
        specs: specs.clone(),
        base: Trial {
            m: None,
            mu: None,
            mu_spin: None,
            m_factor: 1.0,
            mu_factor: 1.0,
            slip_offset: 0.0,
            side_slip_offset: 0.0,
            options,
            mu_temperature_coefficient: None,
            m_temperature_coefficient: None,
            mu_rise_scale: None,
            film_factor: 1.0,
        },
        index,
    };
    let params: Vec<Parameter> = specs
        .iter()
        .zip(&start)
        .map(|(s, st)| {
            let init = st.unwrap_or_else(|| problem.initial(s));
            Parameter::new(init.clamp(s.lower, s.upper), s.scale).bounded(s.lower, s.upper)
        })
        .collect();
    let nls_options = nls::Options {
        max_iterations: args.max_iterations,
        ftol: 1e-8,
        xtol: 1e-8,
        gtol: 1e-8,
        relative_step: RELATIVE_STEP,
        ..nls::Options::default()
    };
    let t0 = Instant::now();
    let fit = nls::levenberg_marquardt(
        |x: &[f64], r: &mut [f64]| problem.residuals(x, r),
        problem.index.len(),
        &params,
        &nls_options,
    )
    .map_err(CliError::model)?;
    let elapsed = t0.elapsed().as_secs_f64();
    let names: Vec<&str> = specs.iter().map(|s| s.name).collect();
    let scales: Vec<f64> = specs.iter().map(|s| s.scale).collect();
    let se = fit.standard_errors();
    let mut w = TableWriter::create(&args.output, &["name", "value", "stderr"].map(String::from))?;
    for (j, name) in names.iter().enumerate() {
        let e = se.as_ref().map_or(f64::INFINITY, |s| s[j]);
        w.write_row(&[name.to_string(), fmt_f64(fit.x[j]), fmt_f64(e)])?;
    }
    w.finish()?;
    let evaluations = fit.evaluations * problem.points.len();
    eprint!(
        "{}",
        summary(&table, &problem, &fit, &names, elapsed, evaluations)
    );
    for warning in diagnose(&names, &scales, &fit) {
        eprintln!("warning: {warning}");
    }
    if args.residuals.is_some() || args.plot.is_some() {
        let model_values = problem.model(&fit.x).map_err(CliError::Model)?;
        if let Some(path) = &args.residuals {
            write_residuals(path, &table, &problem, &model_values)?;
        }
        if let Some(dir) = &args.plot {
            plot(dir, &problem, &model_values, &fit, &names)?;
        }
    }
    Ok(())
}
