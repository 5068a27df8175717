//! `traction fluid`: evaluate the fluids' slope m and peak traction
//! coefficient μ correlations in batch.
//!
//! Input columns (SI units): `p0` (maximum Hertz pressure, Pa), `speed`
//! (rolling speed, m/s), `theta_celsius` (inlet temperature, °C), `k` (aspect
//! ratio b/a), optional `z` (spin parameter ω√(ab)/U; 0 if absent) and optional
//! `fluid` (`santotrac-50` or `tdf-88`, overriding `--fluid`). Other columns
//! pass through.
//!
//! Output: the input columns followed by `m`, `mu` (zero-spin correlations,
//! App. III-A/B and III-C/D), `mu_spin` (eq. 15 at the row's Z, App. III-E/F)
//! and `extrapolated` (the variables outside the data envelope, `;`-separated,
//! empty inside). Without `--extrapolate` a row outside the envelope is an
//! error naming the row and the variable.

use clap::Args;
use traction_fluids::{Fluid, FluidError, FluidName, Policy, Quantity, Query, TemperatureForm};

use crate::error::{CliError, chain};
use crate::fit::{FluidArg, TemperatureArg};
use crate::table::{Table, TableWriter, fmt_f64, output_headers};

/// Arguments of `traction fluid`.
#[derive(Debug, Args)]
pub struct FluidArgs {
    /// Input CSV (`-` for stdin): p0 (Pa), speed (m/s), theta_celsius, k, optional z and fluid.
    #[arg(long, default_value = "-")]
    pub input: String,
    /// Output CSV (`-` for stdout).
    #[arg(long, default_value = "-")]
    pub output: String,
    /// Fluid for rows without a `fluid` column.
    #[arg(long, value_enum, default_value_t = FluidArg::Santotrac50)]
    pub fluid: FluidArg,
    /// Use correlations refitted from the curated data instead of the printed
    /// ones (TDF-88's spin μ is always the refit: III-F is not in the text).
    #[arg(long)]
    pub refit: bool,
    /// Temperature factor of the refit (`linear` implies `--refit`).
    #[arg(long, value_enum, default_value_t = TemperatureArg::Inverse)]
    pub temperature: TemperatureArg,
    /// Evaluate outside the data envelope too, flagging it in `extrapolated`.
    #[arg(long)]
    pub extrapolate: bool,
}

const OUTPUT_COLUMNS: [&str; 4] = ["m", "mu", "mu_spin", "extrapolated"];

fn build(name: FluidName, args: &FluidArgs) -> Result<Fluid, CliError> {
    let t: TemperatureForm = args.temperature.into();
    let r = if args.refit || t == TemperatureForm::Linear {
        Fluid::refit(name, t)
    } else {
        match name {
            FluidName::Santotrac50 => Fluid::santotrac_50(),
            FluidName::Tdf88 => Fluid::tdf_88(),
        }
    };
    r.map_err(|e| CliError::Usage(e.to_string()))
}

/// Run the subcommand.
pub fn run(args: FluidArgs) -> Result<(), CliError> {
    let table = Table::read(&args.input)?;
    table.require(&["p0", "speed", "theta_celsius", "k"])?;
    let s50 = build(FluidName::Santotrac50, &args)?;
    let tdf = build(FluidName::Tdf88, &args)?;
    let default: FluidName = args.fluid.into();
    let policy = if args.extrapolate {
        Policy::Extrapolate
    } else {
        Policy::Strict
    };
    let mut out = Vec::with_capacity(table.len());
    for row in 0..table.len() {
        let name = if table.has("fluid") {
            match table.str(row, "fluid")?.trim() {
                "santotrac-50" => FluidName::Santotrac50,
                "tdf-88" => FluidName::Tdf88,
                "" => default,
                other => {
                    return Err(table.cell_error(
                        row,
                        "fluid",
                        format!("unknown fluid `{other}` (santotrac-50 or tdf-88)"),
                    ));
                }
            }
        } else {
            default
        };
        let fl = if name == FluidName::Santotrac50 {
            &s50
        } else {
            &tdf
        };
        let q = Query {
            p0_pa: table.f64(row, "p0")?,
            speed_m_s: table.f64(row, "speed")?,
            theta_celsius: table.f64(row, "theta_celsius")?,
            k: table.f64(row, "k")?,
            z: table.opt_f64(row, "z")?.unwrap_or(0.0),
        };
        let q0 = Query { z: 0.0, ..q };
        let ev = |quantity: Quantity, q: &Query| {
            fl.evaluate(quantity, q, policy).map_err(|e| {
                let message = match e {
                    // The library names its API; the CLI names its option.
                    FluidError::OutsideEnvelope {
                        quantity,
                        value,
                        min,
                        max,
                        correlation,
                    } => format!(
                        "{quantity} = {value} is outside the data envelope [{min}, {max}] of \
                         {correlation}; use --extrapolate to get a flagged extrapolation"
                    ),
                    e => chain(&e),
                };
                table.row_message(row, format!("{}: {message}", quantity_name(quantity)))
            })
        };
        let m = ev(Quantity::Slope, &q0)?;
        let mu = ev(Quantity::Mu, &q0)?;
        let ms = ev(Quantity::SpinMu, &q)?;
        let mut flags: Vec<String> = Vec::new();
        for (tag, e) in [("m", &m), ("mu", &mu), ("mu_spin", &ms)] {
            for v in &e.extrapolated {
                flags.push(format!("{tag}:{v}"));
            }
        }
        let mut cells = table.rows[row].clone();
        cells.extend([
            fmt_f64(m.value),
            fmt_f64(mu.value),
            fmt_f64(ms.value),
            flags.join(";"),
        ]);
        out.push(cells);
    }
    let mut w = TableWriter::create(&args.output, &output_headers(&table, &OUTPUT_COLUMNS))?;
    for r in out {
        w.write_row(&r)?;
    }
    w.finish()
}

fn quantity_name(q: Quantity) -> &'static str {
    match q {
        Quantity::Slope => "slope m",
        Quantity::Mu => "μ",
        Quantity::SpinMu => "spin μ",
    }
}
