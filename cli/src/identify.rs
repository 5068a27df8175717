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
//! traction-contact) with [`Fluid::Constant`] per row: the slope m, the peak
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
//! value for all rows, 1/K) and `film_factor` (a factor on every row's film
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

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use clap::Args;
use rayon::prelude::*;
use traction_contact::{
    Body, Compliance, Evaluation, Film, Fluid, OperatingState, Options, Thermal, TractionContact,
};
use traction_regression::nls::{self, Fit, Parameter};

use crate::contact::{
    ComplianceArg, EnvelopeArg, LimitArg, ModelArg, ModelOptions, ModulusArg, report_fluid,
    thermal_columns,
};
use crate::error::{CliError, chain};
use crate::table::{Table, TableWriter, fmt_f64, output_headers};

/// Input columns every row needs (as `traction contact`).
const INPUT_COLUMNS: [&str; 14] = [
    "rx1", "ry1", "rx2", "ry2", "e1", "nu1", "e2", "nu2", "load", "u", "du", "dv", "omega", "theta",
];

/// Measured columns (at least one must be present).
const MEASURED: [&str; 2] = ["fx_over_n", "fy_over_n"];

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
    /// mu_temperature_coefficient, m_temperature_coefficient, film_factor.
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

/// The values every row's model is built from, set by the fitted parameters.
#[derive(Debug, Clone)]
pub struct Trial {
    /// Slope m for all rows (replaces the baseline).
    pub m: Option<f64>,
    /// Peak μ for all rows (replaces the baseline).
    pub mu: Option<f64>,
    /// Spin-peak μ_s scaling the forces, all rows.
    pub mu_spin: Option<f64>,
    /// Factor on each row's baseline m.
    pub m_factor: f64,
    /// Factor on each row's baseline μ (and μ_s).
    pub mu_factor: f64,
    /// Zero offset of ΔU/U.
    pub slip_offset: f64,
    /// Zero offset of ΔV/U.
    pub side_slip_offset: f64,
    /// Contact options.
    pub options: Options,
    /// β_μ for all rows, 1/K (thermal; replaces the row's value).
    pub mu_temperature_coefficient: Option<f64>,
    /// β_m for all rows, 1/K (thermal; replaces the row's value).
    pub m_temperature_coefficient: Option<f64>,
    /// Factor on every row's film thickness (thermal).
    pub film_factor: f64,
}

/// What the initial value of a parameter is taken from.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Initial {
    /// Mean baseline m, else an estimate from the data's initial slope.
    Slope,
    /// Mean baseline μ, else 1.05 × the largest measured |F/N|.
    Peak,
    /// Mean baseline μ_s, else as [`Initial::Peak`].
    SpinPeak,
    /// A fixed value.
    Value(f64),
}

/// A named parameter of the calibration and how it maps onto the model.
#[derive(Debug, Clone, Copy)]
pub struct ParameterSpec {
    /// Name used in `--fit`, `--start` and the output.
    pub name: &'static str,
    /// What it is (with unit).
    pub description: &'static str,
    /// Typical magnitude: finite-difference step and identifiability floor.
    pub scale: f64,
    /// Lower bound.
    pub lower: f64,
    /// Upper bound.
    pub upper: f64,
    /// Parameters that cannot be fitted together with this one.
    pub excludes: &'static [&'static str],
    /// A parameter of the thermal model (fitted only with `--thermal`).
    pub thermal: bool,
    initial: Initial,
    apply: fn(&mut Trial, f64),
}

/// The parameters `traction identify` can fit.
pub const PARAMETERS: &[ParameterSpec] = &[
    ParameterSpec {
        name: "m",
        description: "traction slope m (-), one value for all rows",
        scale: 10.0,
        lower: 1e-3,
        upper: traction_contact::MAX_SLOPE,
        excludes: &["m_factor"],
        thermal: false,
        initial: Initial::Slope,
        apply: |t, v| t.m = Some(v),
    },
    ParameterSpec {
        name: "mu",
        description: "peak traction coefficient μ (-), one value for all rows",
        scale: 0.01,
        lower: 1e-6,
        upper: traction_contact::MAX_TRACTION_COEFFICIENT,
        excludes: &["mu_factor"],
        thermal: false,
        initial: Initial::Peak,
        apply: |t, v| t.mu = Some(v),
    },
    ParameterSpec {
        name: "mu_spin",
        description: "spin-peak traction coefficient μ_s scaling the forces (-), one value for all rows",
        scale: 0.01,
        lower: 1e-6,
        upper: traction_contact::MAX_TRACTION_COEFFICIENT,
        excludes: &[],
        thermal: false,
        initial: Initial::SpinPeak,
        apply: |t, v| t.mu_spin = Some(v),
    },
    ParameterSpec {
        name: "m_factor",
        description: "factor on each row's baseline slope m (-)",
        scale: 0.1,
        lower: 1e-3,
        upper: 1e3,
        excludes: &["m"],
        thermal: false,
        initial: Initial::Value(1.0),
        apply: |t, v| t.m_factor = v,
    },
    ParameterSpec {
        name: "mu_factor",
        description: "factor on each row's baseline μ and μ_s (-)",
        scale: 0.1,
        lower: 1e-3,
        upper: 1e3,
        excludes: &["mu"],
        thermal: false,
        initial: Initial::Value(1.0),
        apply: |t, v| t.mu_factor = v,
    },
    ParameterSpec {
        name: "slip_offset",
        description: "zero offset of the measured slip ratio ΔU/U (-): the model sees ΔU + offset·U",
        scale: 1e-3,
        lower: -0.5,
        upper: 0.5,
        excludes: &[],
        thermal: false,
        initial: Initial::Value(0.0),
        apply: |t, v| t.slip_offset = v,
    },
    ParameterSpec {
        name: "side_slip_offset",
        description: "zero offset of the measured side slip ratio ΔV/U (-): the model sees ΔV + offset·U",
        scale: 1e-3,
        lower: -0.5,
        upper: 0.5,
        excludes: &[],
        thermal: false,
        initial: Initial::Value(0.0),
        apply: |t, v| t.side_slip_offset = v,
    },
    ParameterSpec {
        name: "mu_temperature_coefficient",
        description: "temperature coefficient β_μ = −d ln μ/dθ of the peak traction coefficient (1/K), one value for all rows",
        scale: 1e-3,
        lower: -traction_contact::thermal::MAX_TEMPERATURE_COEFFICIENT,
        upper: traction_contact::thermal::MAX_TEMPERATURE_COEFFICIENT,
        excludes: &[],
        thermal: true,
        initial: Initial::Value(0.0025),
        apply: |t, v| t.mu_temperature_coefficient = Some(v),
    },
    ParameterSpec {
        name: "m_temperature_coefficient",
        description: "temperature coefficient β_m = −d ln m/dθ of the traction slope (1/K), one value for all rows",
        scale: 1e-3,
        lower: -traction_contact::thermal::MAX_TEMPERATURE_COEFFICIENT,
        upper: traction_contact::thermal::MAX_TEMPERATURE_COEFFICIENT,
        excludes: &[],
        thermal: true,
        initial: Initial::Value(0.0),
        apply: |t, v| t.m_temperature_coefficient = Some(v),
    },
    ParameterSpec {
        name: "film_factor",
        description: "factor on every row's film thickness h, i.e. on the film's thermal resistance h/(8 k_f) (-)",
        scale: 0.1,
        lower: 1e-3,
        upper: 1e3,
        excludes: &[],
        thermal: true,
        initial: Initial::Value(1.0),
        apply: |t, v| t.film_factor = v,
    },
];

/// One measured row.
#[derive(Debug, Clone)]
struct Point {
    body1: Body,
    body2: Body,
    state: OperatingState,
    /// Baseline m, μ, μ_s (None when the row gives no fluid).
    m: Option<f64>,
    mu: Option<f64>,
    mu_spin: Option<f64>,
    fx: Option<f64>,
    fy: Option<f64>,
    /// The row's report fluid (thermal: its own film and coefficients).
    fluid: Option<Fluid>,
    /// The row's thermal model (`--thermal`): defaults and its columns.
    thermal: Option<Thermal>,
}

impl Point {
    /// The model's traction coefficients (Fx/N, Fy/N) under `trial`.
    fn evaluate(&self, trial: &Trial) -> Result<Evaluation, String> {
        let m = match (trial.m, self.m) {
            (Some(v), _) => v,
            (None, Some(b)) => b * trial.m_factor,
            (None, None) => return Err("no slope m: fill `fluid` or `m`, or fit `m`".into()),
        };
        let mu = match (trial.mu, self.mu) {
            (Some(v), _) => v,
            (None, Some(b)) => b * trial.mu_factor,
            (None, None) => return Err("no peak μ: fill `fluid` or `mu`, or fit `mu`".into()),
        };
        let mu_spin = trial.mu_spin.or(self.mu_spin.map(|s| s * trial.mu_factor));
        let mut options = trial.options;
        let fluid = match (self.thermal, &self.fluid) {
            (Some(row), report) => {
                options.thermal = Some(self.thermal_of(row, trial)?);
                match report {
                    Some(f) => f.clone().with_inlet_values(m, mu).map_err(|e| chain(&e))?,
                    None => Fluid::constant(m, mu).map_err(|e| chain(&e))?,
                }
            }
            (None, _) => Fluid::constant(m, mu).map_err(|e| chain(&e))?,
        };
        let fluid = match mu_spin {
            Some(s) => fluid.with_spin_peak(s).map_err(|e| chain(&e))?,
            None => fluid,
        };
        let contact = TractionContact::new(&self.body1, &self.body2, fluid, options)
            .map_err(|e| chain(&e))?;
        let mut state = self.state;
        state.slip += trial.slip_offset * state.rolling_speed;
        state.side_slip += trial.side_slip_offset * state.rolling_speed;
        contact.evaluate(&state).map_err(|e| chain(&e))
    }

    /// The row's thermal model under `trial`: fitted coefficients replace
    /// the row's, the film factor scales its film thickness (a given one, a
    /// Hamrock–Dowson film from given η₀ and α, or the report fluid's own).
    fn thermal_of(&self, row: Thermal, trial: &Trial) -> Result<Thermal, String> {
        let mut th = row;
        if let Some(b) = trial.mu_temperature_coefficient {
            th.mu_coefficient = Some(b);
        }
        if let Some(b) = trial.m_temperature_coefficient {
            th.slope_coefficient = Some(b);
        }
        if trial.film_factor != 1.0 {
            th.film = Film::Thickness(self.film_thickness(&th)? * trial.film_factor);
        }
        Ok(th)
    }

    /// The film thickness the row's thermal model would use, m.
    fn film_thickness(&self, th: &Thermal) -> Result<f64, String> {
        let g =
            traction_hertz::Geometry::new(&self.body1, &self.body2).map_err(|e| e.to_string())?;
        let s = &self.state;
        let hd = |viscosity: f64, alpha: f64| {
            traction_contact::thermal::hamrock_dowson_central(
                1.0 / g.curvature_x,
                g.e_prime,
                g.k,
                s.load,
                s.rolling_speed.abs(),
                viscosity,
                alpha,
            )
        };
        match (th.film, &self.fluid) {
            (Film::Thickness(h), _) => Ok(h),
            (
                Film::HamrockDowson {
                    viscosity,
                    pressure_viscosity,
                },
                _,
            ) => Ok(hd(viscosity, pressure_viscosity)),
            (_, Some(Fluid::Report { fluid, .. })) => {
                let p = traction_fluids::ThermalProperties::of(fluid.name)
                    .map_err(|e| e.to_string())?;
                Ok(hd(
                    p.viscosity(s.inlet_temperature_celsius),
                    p.pressure_viscosity,
                ))
            }
            _ => Err(
                "film_factor: the row has no film thickness (film_thickness, or viscosity and pressure_viscosity)"
                    .into(),
            ),
        }
    }
}

/// The calibration problem: the rows, the fitted parameters and the fixed
/// part of the trial.
struct Problem<'a> {
    table: &'a Table,
    points: Vec<Point>,
    specs: Vec<&'static ParameterSpec>,
    base: Trial,
    /// (row, 0 = fx / 1 = fy) of each residual.
    index: Vec<(usize, usize)>,
}

impl Problem<'_> {
    fn trial(&self, x: &[f64]) -> Trial {
        let mut t = self.base.clone();
        for (s, &v) in self.specs.iter().zip(x) {
            (s.apply)(&mut t, v);
        }
        t
    }

    /// Model values at every residual (errors name the row).
    fn model(&self, x: &[f64]) -> Result<Vec<Evaluation>, String> {
        let trial = self.trial(x);
        self.points
            .par_iter()
            .enumerate()
            .map(|(i, p)| {
                p.evaluate(&trial)
                    .map_err(|e| self.table.row_message(i, e).to_string())
            })
            .collect()
    }

    fn residuals(&self, x: &[f64], r: &mut [f64]) -> Result<(), String> {
        let e = self.model(x)?;
        for (k, &(row, which)) in self.index.iter().enumerate() {
            let p = &self.points[row];
            r[k] = if which == 0 {
                e[row].traction_x - p.fx.unwrap_or(0.0)
            } else {
                e[row].traction_y - p.fy.unwrap_or(0.0)
            };
        }
        Ok(())
    }

    fn initial(&self, spec: &ParameterSpec) -> f64 {
        let mean = |v: Vec<Option<f64>>| -> Option<f64> {
            let v: Option<Vec<f64>> = v.into_iter().collect();
            v.filter(|v| !v.is_empty())
                .map(|v| v.iter().sum::<f64>() / v.len() as f64)
        };
        let fmax = self
            .points
            .iter()
            .flat_map(|p| [p.fx, p.fy])
            .flatten()
            .fold(0.0_f64, |a, b| a.max(b.abs()));
        let peak = if fmax > 0.0 { 1.05 * fmax } else { 0.05 };
        match spec.initial {
            Initial::Value(v) => v,
            Initial::Peak => mean(self.points.iter().map(|p| p.mu).collect()).unwrap_or(peak),
            Initial::SpinPeak => mean(self.points.iter().map(|p| p.mu_spin).collect())
                .or(mean(self.points.iter().map(|p| p.mu).collect()))
                .unwrap_or(peak),
            Initial::Slope => {
                mean(self.points.iter().map(|p| p.m).collect()).unwrap_or_else(|| {
                    // Median of |F/N| / |slip ratio| over the points below half
                    // the largest force: the initial slope of the curves.
                    let mut s: Vec<f64> = self
                        .points
                        .iter()
                        .filter_map(|p| {
                            let f = p.fx.unwrap_or(0.0).hypot(p.fy.unwrap_or(0.0));
                            let u = p.state.rolling_speed.abs();
                            let ratio = p.state.slip.hypot(p.state.side_slip) / u;
                            (u > 0.0 && ratio > 0.0 && f > 0.0 && f <= 0.5 * fmax)
                                .then_some(f / ratio)
                        })
                        .collect();
                    s.sort_by(f64::total_cmp);
                    s.get(s.len() / 2).copied().unwrap_or(30.0)
                })
            }
        }
    }
}

/// A warning for every parameter that the data do not identify:
/// * the column-scaled Jacobian is rank deficient or nearly so (a singular
///   value ≤ 1e-6 of the largest): the parameters taking part in that
///   direction (|component| ≥ 0.3);
/// * a pair with |correlation| ≥ [`MAX_CORRELATION`];
/// * a standard error above [`MAX_RELATIVE_STDERR`] × max(|value|, scale).
pub fn diagnose(names: &[&str], scales: &[f64], fit: &Fit) -> Vec<String> {
    let mut w = Vec::new();
    for (ratio, v) in fit.weak_directions(1e-6) {
        let involved: Vec<String> = v
            .iter()
            .enumerate()
            .filter(|(_, c)| c.abs() >= 0.3)
            .map(|(j, c)| format!("{} ({c:+.2})", names[j]))
            .collect();
        w.push(format!(
            "not identifiable: the data do not determine the combination of {} \
             (singular value {ratio:.1e} of the largest, column-scaled Jacobian)",
            involved.join(", ")
        ));
    }
    if let (Some(corr), Some(se)) = (fit.correlation(), fit.standard_errors()) {
        let n = names.len();
        for i in 0..n {
            for j in i + 1..n {
                if corr[(i, j)].abs() >= MAX_CORRELATION {
                    w.push(format!(
                        "not identifiable separately: `{}` and `{}` are correlated {:+.4} \
                         (|correlation| ≥ {MAX_CORRELATION}); fix one of them",
                        names[i],
                        names[j],
                        corr[(i, j)]
                    ));
                }
            }
        }
        for j in 0..n {
            let reference = fit.x[j].abs().max(scales[j]);
            if se[j] > MAX_RELATIVE_STDERR * reference {
                w.push(format!(
                    "not identifiable: `{}` = {} has standard error {} (> {:.0} % of max(|value|, {})): \
                     the data do not determine it",
                    names[j],
                    fit.x[j],
                    se[j],
                    MAX_RELATIVE_STDERR * 100.0,
                    scales[j]
                ));
            }
        }
    } else if fit.variance.is_none() {
        w.push(format!(
            "no standard errors: {} residuals for {} parameters (need more residuals than parameters)",
            fit.residuals.len(),
            names.len()
        ));
    }
    w
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

/// Read the rows: bodies, state, baselines, measurements.
fn read_points(
    table: &Table,
    model: &ModelOptions,
    specs: &[&'static ParameterSpec],
) -> Result<Vec<Point>, CliError> {
    table.require(&INPUT_COLUMNS)?;
    if !MEASURED.iter().any(|c| table.has(c)) {
        return Err(CliError::MissingColumn {
            source_name: table.source_name.clone(),
            column: "fx_over_n or fy_over_n".into(),
            expected:
                "the `traction contact` input columns plus a measured fx_over_n and/or fy_over_n"
                    .into(),
        });
    }
    let fitted = |n: &str| specs.iter().any(|s| s.name == n);
    // Baselines from a report fluid: its correlations at the row's state,
    // without compliance (the correlation's m is the measured slope).
    let mut baseline_opts = model.options().map_err(CliError::Usage)?;
    baseline_opts.compliance = Compliance::Off;
    baseline_opts.classify_regime = false;
    baseline_opts.thermal = None;
    let mut points = Vec::with_capacity(table.len());
    for row in 0..table.len() {
        let v = |c: &str| table.f64(row, c);
        let body1 = Body::new(v("rx1")?, v("ry1")?, v("e1")?, v("nu1")?);
        let body2 = Body::new(v("rx2")?, v("ry2")?, v("e2")?, v("nu2")?);
        let state = OperatingState::new(
            v("load")?,
            v("u")?,
            v("du")?,
            v("dv")?,
            v("omega")?,
            v("theta")?,
        )
        .map_err(|e| table.row_error(row, e))?;
        let name = if table.has("fluid") {
            Some(table.str(row, "fluid")?.trim().to_string()).filter(|s| !s.is_empty())
        } else {
            None
        };
        let mut report = None;
        let (m, mu, mu_spin) = match name {
            Some(n) => {
                let fluid = report_fluid(&n, model.rule(), false)
                    .map_err(|e| table.cell_error(row, "fluid", e))?;
                report = Some(fluid.clone());
                let c = TractionContact::new(&body1, &body2, fluid, baseline_opts)
                    .map_err(|e| table.row_error(row, e))?;
                let mut s = state;
                (s.slip, s.side_slip, s.spin) = (0.0, 0.0, 0.0);
                let e = c.evaluate(&s).map_err(|e| table.row_error(row, e))?;
                if e.outside_envelope.any() {
                    eprintln!(
                        "warning: {}: row {}: fluid correlation outside its data envelope ({:?})",
                        table.source_name,
                        row + 1,
                        e.outside_envelope
                    );
                }
                // Given m, μ cells override the correlation (as in `traction
                // contact`: the values at the inlet, the fluid supplying the
                // temperature dependence and film of the thermal model).
                let given = |c: &str| {
                    if table.has(c) {
                        table.opt_f64(row, c)
                    } else {
                        Ok(None)
                    }
                };
                (
                    Some(given("m")?.unwrap_or(e.m_used)),
                    Some(given("mu")?.unwrap_or(e.mu_used)),
                    None,
                )
            }
            None => {
                let (m, mu) = (table.opt_f64(row, "m")?, table.opt_f64(row, "mu")?);
                for (col, val, param) in [("m", m, "m"), ("mu", mu, "mu")] {
                    if val.is_none() && !fitted(param) {
                        return Err(table.cell_error(
                            row,
                            col,
                            format!(
                                "no fluid: fill `fluid` (santotrac-50 or tdf-88) or `{col}`, or fit `{param}` (--fit)"
                            ),
                        ));
                    }
                }
                (m, mu, table.opt_f64(row, "mu_spin")?)
            }
        };
        let measured = |c: &str| -> Result<Option<f64>, CliError> {
            let v = table.opt_f64(row, c)?;
            match v {
                Some(x) if !x.is_finite() => Err(table.cell_error(
                    row,
                    c,
                    format!("{x} is not a finite traction coefficient"),
                )),
                _ => Ok(v),
            }
        };
        let thermal = match model.options().map_err(CliError::Usage)?.thermal {
            Some(mut th) => {
                thermal_columns(table, row, &mut th)?;
                Some(th)
            }
            None => None,
        };
        points.push(Point {
            body1,
            body2,
            state,
            m,
            mu,
            mu_spin,
            fx: measured("fx_over_n")?,
            fy: measured("fy_over_n")?,
            fluid: report,
            thermal,
        });
    }
    Ok(points)
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

/// The report on stderr: residuals, termination, conditioning, correlation.
fn summary(
    table: &Table,
    problem: &Problem,
    fit: &Fit,
    names: &[&str],
    elapsed: f64,
    contact_evaluations: usize,
) -> String {
    let nfx = problem.index.iter().filter(|(_, w)| *w == 0).count();
    let mut s = String::new();
    let _ = writeln!(
        s,
        "identify: {}: {} rows, {} residuals ({nfx} fx_over_n, {} fy_over_n), {} parameters",
        table.source_name,
        problem.points.len(),
        problem.index.len(),
        problem.index.len() - nfx,
        names.len()
    );
    let _ = writeln!(
        s,
        "{}; {} iterations, {} model evaluations ({contact_evaluations} contact evaluations), {elapsed:.2} s",
        fit.termination.describe(),
        fit.iterations,
        fit.evaluations
    );
    let _ = writeln!(
        s,
        "rms residual: {:.6e} (traction coefficient); residual standard deviation s: {}",
        fit.rms,
        fit.variance
            .map_or("undefined".to_string(), |v| format!("{:.6e}", v.sqrt()))
    );
    let _ = writeln!(
        s,
        "condition number of the column-scaled Jacobian: {:.4e}",
        fit.condition_number
    );
    match fit.correlation() {
        Some(c) => {
            let _ = writeln!(s, "correlation matrix:");
            let _ = writeln!(s, ",{}", names.join(","));
            for (i, n) in names.iter().enumerate() {
                let row: Vec<String> = (0..names.len())
                    .map(|j| format!("{:.4}", c[(i, j)]))
                    .collect();
                let _ = writeln!(s, "{n},{}", row.join(","));
            }
        }
        None => {
            let _ = writeln!(s, "correlation matrix: undefined (no covariance)");
        }
    }
    s
}

/// The input rows with the model and the residuals appended.
fn write_residuals(
    path: &str,
    table: &Table,
    problem: &Problem,
    model: &[Evaluation],
) -> Result<(), CliError> {
    let extra = [
        "fx_over_n_model",
        "fy_over_n_model",
        "fx_residual",
        "fy_residual",
    ];
    let mut w = TableWriter::create(path, &output_headers(table, &extra))?;
    for (i, (p, e)) in problem.points.iter().zip(model).enumerate() {
        let mut cells = table.rows[i].clone();
        cells.push(fmt_f64(e.traction_x));
        cells.push(fmt_f64(e.traction_y));
        cells.push(p.fx.map_or(String::new(), |v| fmt_f64(e.traction_x - v)));
        cells.push(p.fy.map_or(String::new(), |v| fmt_f64(e.traction_y - v)));
        w.write_row(&cells)?;
    }
    w.finish()
}

/// Fit and residual plots against each point's slip ratio (ΔU/U for
/// fx_over_n, ΔV/U for fy_over_n).
fn plot(
    dir: &std::path::Path,
    problem: &Problem,
    model: &[Evaluation],
    fit: &Fit,
    names: &[&str],
) -> Result<(), CliError> {
    use traction_reproduce::tables::{Figure, Series, Style};
    std::fs::create_dir_all(dir).map_err(|source| CliError::Io {
        context: format!("creating {}", dir.display()),
        source,
    })?;
    let mut measured: [Vec<(f64, f64)>; 2] = [Vec::new(), Vec::new()];
    let mut fitted: [Vec<(f64, f64)>; 2] = [Vec::new(), Vec::new()];
    let mut resid: [Vec<(f64, f64)>; 2] = [Vec::new(), Vec::new()];
    for &(row, which) in &problem.index {
        let p = &problem.points[row];
        let u = p.state.rolling_speed;
        let (x, y, f) = if which == 0 {
            (p.state.slip / u, p.fx.unwrap_or(0.0), model[row].traction_x)
        } else {
            (
                p.state.side_slip / u,
                p.fy.unwrap_or(0.0),
                model[row].traction_y,
            )
        };
        if x.is_finite() {
            measured[which].push((x, y));
            fitted[which].push((x, f));
            resid[which].push((x, f - y));
        }
    }
    let label = ["Fx/N", "Fy/N"];
    let params: Vec<String> = names
        .iter()
        .zip(&fit.x)
        .map(|(n, v)| format!("{n} = {v:.4}"))
        .collect();
    let mut fit_series = Vec::new();
    let mut res_series = Vec::new();
    for w in 0..2 {
        if measured[w].is_empty() {
            continue;
        }
        fit_series.push(Series {
            name: format!("{} measured", label[w]),
            style: Style::Circles,
            color: 2 * w,
            points: measured[w].clone(),
        });
        fit_series.push(Series {
            name: format!("{} fitted model", label[w]),
            style: Style::Crosses,
            color: 2 * w + 1,
            points: fitted[w].clone(),
        });
        res_series.push(Series {
            name: format!("{} model − measured", label[w]),
            style: Style::Circles,
            color: 2 * w,
            points: resid[w].clone(),
        });
    }
    let x_label = "slip ratio ΔU/U (Fx/N) or ΔV/U (Fy/N)".to_string();
    let figures = [
        Figure {
            id: "identify-fit".into(),
            title: format!("traction identify: {}", params.join(", ")),
            x_label: x_label.clone(),
            y_label: "traction coefficient".into(),
            series: fit_series,
        },
        Figure {
            id: "identify-residuals".into(),
            title: format!("traction identify: residuals, RMS {:.3e}", fit.rms),
            x_label,
            y_label: "residual (model − measured)".into(),
            series: res_series,
        },
    ];
    for f in &figures {
        traction_reproduce::plot::write_figure(f, dir).map_err(CliError::model)?;
    }
    Ok(())
}
