//! `traction fit`: fit the report's 16- or 32-term correlations (eq. 14/15)
//! to a curated data set (`--fluid`) or to the user's own (`--data FILE.csv`).
//!
//! Output (`--format text`, default): the coefficients with their terms, the
//! means, the number of points, the percent-error mean and standard deviation
//! as the report defines them, and the condition number of the design matrix.
//! `--format csv`: exactly two columns `name,value`, rows `C1`..`Cn`, `mean_U`
//! (m/s), `mean_P0` (GPa, the correlations' unit), `mean_theta` (°C), `mean_k`,
//! `mean_Z` (32 terms only), `n`, `err_mean`, `err_std` (percent).
//!
//! `--data` columns: `speed` (m/s), `p0` (Pa) or `p0_gpa` (GPa),
//! `theta_celsius` (°C), `k`, `z` (= ω√(ab)/U, needed for 32 terms), and the
//! target column named by `--target` (`slope` or `mu`).

use clap::{Args, ValueEnum};
use traction_fluids::{FluidName, Quantity, data_set, printed_result};
use traction_regression::{Fit, Model, TemperatureForm, TermSet, Variables, fit};

use crate::error::CliError;
use crate::table::{Table, TableWriter, fmt_f64};

/// A fluid of the report.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FluidArg {
    /// Santotrac 50.
    #[value(name = "santotrac-50")]
    Santotrac50,
    /// TDF-88.
    #[value(name = "tdf-88")]
    Tdf88,
}

impl From<FluidArg> for FluidName {
    fn from(f: FluidArg) -> FluidName {
        match f {
            FluidArg::Santotrac50 => FluidName::Santotrac50,
            FluidArg::Tdf88 => FluidName::Tdf88,
        }
    }
}

/// The fitted quantity.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TargetArg {
    /// Initial traction slope m.
    Slope,
    /// Peak traction coefficient μ.
    Mu,
}

/// Output format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FormatArg {
    /// Human-readable report.
    Text,
    /// `name,value` rows.
    Csv,
}

/// Which means normalise the variables (eq. 12).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MeansArg {
    /// The data set's own means.
    Data,
    /// The means printed in the report's appendix (III-A..III-E only).
    Printed,
}

/// The temperature factor.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TemperatureArg {
    /// The report's 1/θ' (singular at θ = θ̄).
    Inverse,
    /// The well-posed linear θ' alternative.
    Linear,
}

impl From<TemperatureArg> for TemperatureForm {
    fn from(t: TemperatureArg) -> TemperatureForm {
        match t {
            TemperatureArg::Inverse => TemperatureForm::Inverse,
            TemperatureArg::Linear => TemperatureForm::Linear,
        }
    }
}

/// Arguments of `traction fit`.
#[derive(Debug, Args)]
pub struct FitArgs {
    /// Curated data set of this fluid (App. III-A..F); ignored with `--data`.
    #[arg(long, value_enum, default_value_t = FluidArg::Santotrac50)]
    pub fluid: FluidArg,
    /// Fitted quantity.
    #[arg(long, value_enum, default_value_t = TargetArg::Mu)]
    pub target: TargetArg,
    /// 16 (eq. 14, zero spin) or 32 (eq. 15, spin and zero-spin tests, App. III-E/F).
    #[arg(long, default_value_t = 16)]
    pub terms: usize,
    /// The user's own data CSV instead of the curated set (`-` for stdin).
    #[arg(long)]
    pub data: Option<String>,
    /// Means used in the normalisation.
    #[arg(long, value_enum, default_value_t = MeansArg::Data)]
    pub means: MeansArg,
    /// Temperature factor: 1/θ' (report) or θ'.
    #[arg(long, value_enum, default_value_t = TemperatureArg::Inverse)]
    pub temperature: TemperatureArg,
    /// Output format.
    #[arg(long, value_enum, default_value_t = FormatArg::Text)]
    pub format: FormatArg,
    /// Output (`-` for stdout).
    #[arg(long, default_value = "-")]
    pub output: String,
}

/// Reads a user data file.
fn read_data(
    path: &str,
    target: TargetArg,
    terms: TermSet,
) -> Result<(Vec<Variables>, Vec<f64>), CliError> {
    let t = Table::read(path)?;
    let tcol = match target {
        TargetArg::Slope => "slope",
        TargetArg::Mu => "mu",
    };
    t.require(&["speed", "theta_celsius", "k", tcol])?;
    if terms == TermSet::ThirtyTwo {
        t.require(&["z"])?;
    }
    if !t.has("p0") && !t.has("p0_gpa") {
        return Err(CliError::MissingColumn {
            source_name: t.source_name.clone(),
            column: "p0 or p0_gpa".into(),
            expected: format!("speed,p0|p0_gpa,theta_celsius,k,z,{tcol}"),
        });
    }
    let mut x = Vec::with_capacity(t.len());
    let mut y = Vec::with_capacity(t.len());
    for row in 0..t.len() {
        let p0_gpa = match t.opt_f64(row, "p0_gpa")? {
            Some(v) => v,
            None => t.f64(row, "p0")? / 1e9,
        };
        let v = Variables {
            speed: t.f64(row, "speed")?,
            p0_gpa,
            theta_celsius: t.f64(row, "theta_celsius")?,
            k: t.f64(row, "k")?,
            z: t.opt_f64(row, "z")?.unwrap_or(0.0),
        };
        v.validate().map_err(|e| t.row_error(row, e))?;
        x.push(v);
        y.push(t.f64(row, tcol)?);
    }
    Ok((x, y))
}

/// Run the subcommand.
pub fn run(args: FitArgs) -> Result<(), CliError> {
    let terms = TermSet::from_count(args.terms).map_err(|e| CliError::Usage(e.to_string()))?;
    if terms == TermSet::ThirtyTwo && args.target == TargetArg::Slope {
        return Err(CliError::Usage(
            "--terms 32 fits the spin traction coefficient (App. III-E/F); the slope was not \
             recorded for spin tests: use --target mu"
                .into(),
        ));
    }
    let fluid: FluidName = args.fluid.into();
    let q = match (terms, args.target) {
        (TermSet::ThirtyTwo, _) => Quantity::SpinMu,
        (_, TargetArg::Slope) => Quantity::Slope,
        _ => Quantity::Mu,
    };
    let (x, y, label) = match &args.data {
        Some(path) => {
            let (x, y) = read_data(path, args.target, terms)?;
            (x, y, format!("user data {path}"))
        }
        None => {
            let (x, y) = data_set(fluid, q).map_err(|e| CliError::Usage(e.to_string()))?;
            (
                x,
                y,
                format!(
                    "{} curated data of App. {}",
                    fluid.label(),
                    q.appendix(fluid)
                ),
            )
        }
    };
    let means = match args.means {
        MeansArg::Data => None,
        MeansArg::Printed => {
            if args.data.is_some() {
                return Err(CliError::Usage(
                    "--means printed applies to the curated data sets only".into(),
                ));
            }
            let p =
                printed_result(q.appendix(fluid)).map_err(|e| CliError::Usage(e.to_string()))?;
            Some(p.means)
        }
    };
    let model = Model {
        terms,
        temperature: args.temperature.into(),
    };
    let f = fit(model, &x, &y, means).map_err(|e| CliError::Usage(format!("{label}: {e}")))?;
    match args.format {
        FormatArg::Csv => write_csv(&args.output, &f, terms),
        FormatArg::Text => write_text(&args.output, &f, model, &label),
    }
}

/// The `name,value` rows.
pub fn csv_rows(f: &Fit, terms: TermSet) -> Vec<(String, String)> {
    let c = &f.correlation;
    let m = c.means();
    let mut rows: Vec<(String, String)> = c
        .coefficients()
        .iter()
        .enumerate()
        .map(|(j, v)| (format!("C{}", j + 1), fmt_f64(*v)))
        .collect();
    rows.push(("mean_U".into(), fmt_f64(m.speed)));
    rows.push(("mean_P0".into(), fmt_f64(m.p0_gpa)));
    rows.push(("mean_theta".into(), fmt_f64(m.theta_celsius)));
    rows.push(("mean_k".into(), fmt_f64(m.k)));
    if terms == TermSet::ThirtyTwo {
        rows.push(("mean_Z".into(), fmt_f64(m.z)));
    }
    rows.push(("n".into(), f.estimates.len().to_string()));
    rows.push(("err_mean".into(), fmt_f64(f.stats.mean)));
    rows.push(("err_std".into(), fmt_f64(f.stats.std_dev)));
    rows
}

fn write_csv(path: &str, f: &Fit, terms: TermSet) -> Result<(), CliError> {
    let mut w = TableWriter::create(path, &["name".to_string(), "value".to_string()])?;
    for (n, v) in csv_rows(f, terms) {
        w.write_row(&[n, v])?;
    }
    w.finish()
}

fn write_text(path: &str, f: &Fit, model: Model, label: &str) -> Result<(), CliError> {
    use std::io::Write;
    let c = &f.correlation;
    let m = c.means();
    let mut s = String::new();
    s.push_str(&format!(
        "{}-term correlation (eq. {}), temperature factor {}, fitted to {label}\n",
        model.len(),
        if model.len() == 16 { 14 } else { 15 },
        match model.temperature {
            TemperatureForm::Inverse => "1/θ'",
            _ => "θ'",
        }
    ));
    s.push_str("coefficients:\n");
    for (j, (v, name)) in c.coefficients().iter().zip(model.term_names()).enumerate() {
        s.push_str(&format!("  C{:<2} {:>14.6e}  {}\n", j + 1, v, name));
    }
    s.push_str(&format!(
        "means: U {:.3} m/s, P0 {:.4} GPa, θ {:.3} °C, k {:.4}",
        m.speed, m.p0_gpa, m.theta_celsius, m.k
    ));
    if model.len() == 32 {
        s.push_str(&format!(", Z {:.6}", m.z));
    }
    s.push('\n');
    s.push_str(&format!(
        "n {}; percent error 50·(a/e − e/a): mean {:.4} %, standard deviation {:.4} % (n − 1)\n",
        f.estimates.len(),
        f.stats.mean,
        f.stats.std_dev
    ));
    s.push_str(&format!(
        "condition number of the design matrix {:.4e}",
        f.condition_number
    ));
    if model.temperature == TemperatureForm::Inverse {
        s.push_str(&format!(
            "; θ' guard: no evaluation within ±{:.3} °C of θ̄",
            c.guard_band_celsius()
        ));
    }
    s.push('\n');
    let io = |source| CliError::Io {
        context: format!("writing {path}"),
        source,
    };
    if path == "-" {
        std::io::stdout().lock().write_all(s.as_bytes()).map_err(io)
    } else {
        std::fs::write(path, s).map_err(io)
    }
}
