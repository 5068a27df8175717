//! The measured rows and the least-squares problem built on them.

use rayon::prelude::*;
use traction_contact::{
    Body, Compliance, Evaluation, Film, Fluid, OperatingState, Thermal, TractionContact,
};

use super::params::{Initial, ParameterSpec, Trial};
use crate::contact::{ModelOptions, report_fluid, thermal_columns, warn_outside_envelope};
use crate::error::{CliError, chain};
use crate::table::Table;

/// Input columns every row needs (as `traction contact`).
const INPUT_COLUMNS: [&str; 14] = [
    "rx1", "ry1", "rx2", "ry2", "e1", "nu1", "e2", "nu2", "load", "u", "du", "dv", "omega", "theta",
];

/// Measured columns (at least one must be present).
const MEASURED: [&str; 2] = ["fx_over_n", "fy_over_n"];

/// One measured row.
#[derive(Debug, Clone)]
pub(super) struct Point {
    body1: Body,
    body2: Body,
    pub(super) state: OperatingState,
    /// Baseline m, μ, μ_s (None when the row gives no fluid).
    m: Option<f64>,
    mu: Option<f64>,
    mu_spin: Option<f64>,
    pub(super) fx: Option<f64>,
    pub(super) fy: Option<f64>,
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
        if let Some(t) = trial.mu_rise_scale {
            th.mu_rise_scale = Some(t);
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
        let fluid = self.fluid.as_ref();
        traction_contact::thermal::film_thickness(th, &g, fluid, &self.state).map_err(|_| {
            "film_factor: the row has no film thickness (film_thickness, or viscosity and pressure_viscosity)"
                .to_string()
        })
    }
}

/// The calibration problem: the rows, the fitted parameters and the fixed
/// part of the trial.
pub(super) struct Problem<'a> {
    pub(super) table: &'a Table,
    pub(super) points: Vec<Point>,
    pub(super) specs: Vec<&'static ParameterSpec>,
    pub(super) base: Trial,
    /// (row, 0 = fx / 1 = fy) of each residual.
    pub(super) index: Vec<(usize, usize)>,
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
    pub(super) fn model(&self, x: &[f64]) -> Result<Vec<Evaluation>, String> {
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

    pub(super) fn residuals(&self, x: &[f64], r: &mut [f64]) -> Result<(), String> {
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

    pub(super) fn initial(&self, spec: &ParameterSpec) -> f64 {
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
/// Read the rows: bodies, state, baselines, measurements.
pub(super) fn read_points(
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
                warn_outside_envelope(table, row, &e);
                // Given m, μ cells override the correlation (as in `traction
                // contact`: the values at the inlet, the fluid supplying the
                // temperature dependence and film of the thermal model).
                (
                    Some(table.opt_f64(row, "m")?.unwrap_or(e.m_used)),
                    Some(table.opt_f64(row, "mu")?.unwrap_or(e.mu_used)),
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
