//! `traction contact`: the dimensional traction contact (traction-contact) in
//! batch from CSV.
//!
//! Input columns (SI units): `rx1,ry1,rx2,ry2` (principal radii, m; flat =
//! `inf` or 0), `e1,nu1,e2,nu2` (Pa, -), `load` (N), `u` (rolling speed, m/s),
//! `du` (slip ΔU, m/s), `dv` (side slip ΔV, m/s), `omega` (spin, rad/s),
//! `theta` (inlet temperature, °C), and the fluid: either `fluid`
//! (`santotrac-50` or `tdf-88`, the report's correlations) or `m,mu` (user
//! slope and peak traction coefficient; optional `mu_spin`). A table may have
//! both a `fluid` and `m,mu` columns as long as each row fills one of them.
//! Other columns are passed through unchanged.
//!
//! Output: the input columns followed by `fx,fy,mz,loss,a,b,k,p0,m_used,
//! mu_used,J1,J2,J3,J4,J5,J6,J7,regime` (N, N, N·m, W, m, m, -, Pa, -, -, the
//! report's dimensionless groups, regime name). Every row is evaluated before
//! anything is written; a row that cannot be evaluated stops the command with
//! an error naming the row, the line and the quantity.

use clap::{Args, ValueEnum};
use traction_contact::{
    Accuracy, Body, Compliance, Direction, DiscMaterial, EnvelopeRule, Evaluation, Fluid, Limit,
    Model, Modulus, OperatingState, Options, Properties, TractionContact,
};

use crate::error::CliError;
use crate::table::{Table, TableWriter, fmt_f64, output_headers};

/// Input columns every row needs.
const INPUT_COLUMNS: [&str; 14] = [
    "rx1", "ry1", "rx2", "ry2", "e1", "nu1", "e2", "nu2", "load", "u", "du", "dv", "omega", "theta",
];

/// Output columns appended to the input columns.
pub const OUTPUT_COLUMNS: [&str; 18] = [
    "fx", "fy", "mz", "loss", "a", "b", "k", "p0", "m_used", "mu_used", "J1", "J2", "J3", "J4",
    "J5", "J6", "J7", "regime",
];

/// Constitutive model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ModelArg {
    /// Elastic/perfectly plastic J+T (the report's).
    ElasticPlastic,
    /// Rigid/plastic limit.
    RigidPlastic,
}

/// Envelope rule of the report fluids' correlations.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum EnvelopeArg {
    /// Error outside the data envelope.
    Strict,
    /// Extrapolate the correlation (flagged on stderr).
    Extrapolate,
    /// Clamp the query to the envelope (flagged on stderr).
    Clamp,
}

/// Disc-compliance correction of the slope.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ComplianceArg {
    /// No correction.
    Off,
    /// The slope was measured in side slip (the report's technique); steel discs.
    Side,
    /// The slope was measured in longitudinal slip; steel discs.
    Longitudinal,
}

/// Distribution of the shear modulus over the contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ModulusArg {
    /// Ḡ constant (the report's).
    Constant,
    /// Proportional to the Hertz pressure.
    Pressure,
}

/// Distribution of the limiting shear stress over the contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum LimitArg {
    /// Proportional to the Hertz pressure (the report's).
    Pressure,
    /// τ̄ constant.
    Constant,
}

/// Options shared by `traction contact` and `traction curve`.
#[derive(Debug, Args, Clone)]
pub struct ModelOptions {
    /// Constitutive model.
    #[arg(long, value_enum, default_value_t = ModelArg::ElasticPlastic)]
    pub model: ModelArg,
    /// Absolute accuracy of J4, J5, J6 (1e-9..0.1).
    #[arg(long, default_value_t = 1e-4)]
    pub tol: f64,
    /// What a report fluid does outside its data envelope.
    #[arg(long, value_enum, default_value_t = EnvelopeArg::Strict)]
    pub envelope: EnvelopeArg,
    /// Disc-compliance correction (report steel, E = 210 GPa, ν = 0.3).
    #[arg(long, value_enum, default_value_t = ComplianceArg::Off)]
    pub compliance: ComplianceArg,
    /// Report fluids: scale the forces by the spin-peak μ correlation.
    #[arg(long)]
    pub spin_peak: bool,
    /// Rolling-speed floor U_f of the J groups (m/s).
    #[arg(long, default_value_t = traction_contact::DEFAULT_ROLLING_SPEED_FLOOR)]
    pub floor: f64,
    /// Elastic/plastic model: shear modulus over the contact (other than
    /// `constant` uses the grid scheme: milliseconds per row).
    #[arg(long, value_enum, default_value_t = ModulusArg::Constant)]
    pub modulus: ModulusArg,
    /// Elastic/plastic model: limiting shear stress over the contact.
    #[arg(long, value_enum, default_value_t = LimitArg::Pressure)]
    pub limit: LimitArg,
}

impl ModelOptions {
    /// The library options.
    pub fn options(&self) -> Result<Options, String> {
        let accuracy = Accuracy::new(self.tol).map_err(|e| format!("--tol: {e}"))?;
        let compliance = match self.compliance {
            ComplianceArg::Off => Compliance::Off,
            ComplianceArg::Side | ComplianceArg::Longitudinal => Compliance::Discs {
                material: DiscMaterial::REPORT_STEEL,
                slope_measured_in: if self.compliance == ComplianceArg::Side {
                    Direction::Side
                } else {
                    Direction::Longitudinal
                },
            },
        };
        Ok(Options {
            model: match self.model {
                ModelArg::ElasticPlastic => Model::ElasticPlastic,
                ModelArg::RigidPlastic => Model::RigidPlastic,
            },
            accuracy,
            compliance,
            rolling_speed_floor: self.floor,
            classify_regime: true,
            properties: Properties {
                modulus: match self.modulus {
                    ModulusArg::Constant => Modulus::Constant,
                    ModulusArg::Pressure => Modulus::PressureProportional,
                },
                limit: match self.limit {
                    LimitArg::Pressure => Limit::PressureProportional,
                    LimitArg::Constant => Limit::Constant,
                },
            },
            // Rows are independent contacts: a map would be built per row
            // and never reused.
            map: false,
        })
    }

    /// The envelope rule.
    pub fn rule(&self) -> EnvelopeRule {
        match self.envelope {
            EnvelopeArg::Strict => EnvelopeRule::Strict,
            EnvelopeArg::Extrapolate => EnvelopeRule::Extrapolate,
            EnvelopeArg::Clamp => EnvelopeRule::Clamp,
        }
    }
}

/// A report fluid by its CLI name.
pub fn report_fluid(name: &str, rule: EnvelopeRule, spin_peak: bool) -> Result<Fluid, String> {
    let f = match name {
        "santotrac-50" => Fluid::santotrac_50(rule),
        "tdf-88" => Fluid::tdf_88(rule),
        other => {
            return Err(format!(
                "unknown fluid `{other}` (expected santotrac-50 or tdf-88)"
            ));
        }
    };
    Ok(f.map_err(|e| e.to_string())?.use_spin_peak(spin_peak))
}

/// Arguments of `traction contact`.
#[derive(Debug, Args)]
pub struct ContactArgs {
    /// Input CSV (`-` for stdin). Columns rx1,ry1,rx2,ry2 (m), e1,nu1,e2,nu2
    /// (Pa, -), load (N), u, du, dv (m/s), omega (rad/s), theta (°C), and
    /// fluid (santotrac-50 | tdf-88) or m,mu (optional mu_spin).
    #[arg(long, default_value = "-")]
    pub input: String,
    /// Output CSV (`-` for stdout): the input columns followed by
    /// fx,fy,mz,loss,a,b,k,p0,m_used,mu_used,J1..J7,regime.
    #[arg(long, default_value = "-")]
    pub output: String,
    /// Model options.
    #[command(flatten)]
    pub model: ModelOptions,
}

/// Evaluate one row.
fn solve_row(
    table: &Table,
    row: usize,
    opts: &Options,
    model: &ModelOptions,
) -> Result<Evaluation, CliError> {
    let v = |c: &str| table.f64(row, c);
    let r = |c: &str| v(c).map(crate::table::radius); // 0 or inf = flat, as in the FMU
    let body1 = Body::new(r("rx1")?, r("ry1")?, v("e1")?, v("nu1")?);
    let body2 = Body::new(r("rx2")?, r("ry2")?, v("e2")?, v("nu2")?);
    let name = if table.has("fluid") {
        Some(table.str(row, "fluid")?.trim().to_string()).filter(|s| !s.is_empty())
    } else {
        None
    };
    let fluid = match name {
        Some(n) => report_fluid(&n, model.rule(), model.spin_peak)
            .map_err(|e| table.cell_error(row, "fluid", e))?,
        None => {
            let (m, mu) = (table.opt_f64(row, "m")?, table.opt_f64(row, "mu")?);
            let (Some(m), Some(mu)) = (m, mu) else {
                return Err(table.cell_error(
                    row,
                    if m.is_none() { "m" } else { "mu" },
                    "no fluid: fill `fluid` (santotrac-50 or tdf-88) or both `m` and `mu`",
                ));
            };
            let f = Fluid::constant(m, mu).map_err(|e| table.row_error(row, e))?;
            match table.opt_f64(row, "mu_spin")? {
                Some(s) => f
                    .with_spin_peak(s)
                    .map_err(|e| table.cell_error(row, "mu_spin", e.to_string()))?,
                None => f,
            }
        }
    };
    let contact =
        TractionContact::new(&body1, &body2, fluid, *opts).map_err(|e| table.row_error(row, e))?;
    let state = OperatingState::new(
        v("load")?,
        v("u")?,
        v("du")?,
        v("dv")?,
        v("omega")?,
        v("theta")?,
    )
    .map_err(|e| table.row_error(row, e))?;
    contact
        .evaluate(&state)
        .map_err(|e| table.row_error(row, e))
}

/// The output cells of one evaluation.
pub fn output_cells(e: &Evaluation) -> Vec<String> {
    let mut v: Vec<String> = [
        e.fx, e.fy, e.mz, e.loss, e.a, e.b, e.k, e.p0, e.m_used, e.mu_used, e.j1, e.j2, e.j3, e.j4,
        e.j5, e.j6, e.j7,
    ]
    .into_iter()
    .map(fmt_f64)
    .collect();
    v.push(e.regime.name().to_string());
    v
}

/// Run the subcommand.
pub fn run(args: ContactArgs) -> Result<(), CliError> {
    let opts = args.model.options().map_err(CliError::Usage)?;
    let table = Table::read(&args.input)?;
    table.require(&INPUT_COLUMNS)?;
    let user_columns = table.has("m") && table.has("mu");
    if !(table.has("fluid") || user_columns) {
        table.require(&["fluid"])?;
    }
    let mut results = Vec::with_capacity(table.len());
    for row in 0..table.len() {
        let e = solve_row(&table, row, &opts, &args.model)?;
        if e.outside_envelope.any() {
            eprintln!(
                "warning: {}: row {}: fluid correlation outside its data envelope ({:?})",
                table.source_name,
                row + 1,
                e.outside_envelope
            );
        }
        results.push(e);
    }
    let mut w = TableWriter::create(&args.output, &output_headers(&table, &OUTPUT_COLUMNS))?;
    for (row, e) in results.iter().enumerate() {
        let mut cells = table.rows[row].clone();
        cells.extend(output_cells(e));
        w.write_row(&cells)?;
    }
    w.finish()
}
