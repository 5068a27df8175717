//! `traction contact`: the dimensional traction contact (traction-contact) in
//! batch from CSV.
//!
//! Input columns (SI units): `rx1,ry1,rx2,ry2` (principal radii, m; flat =
//! `inf` or 0), `e1,nu1,e2,nu2` (Pa, -), `load` (N), `u` (rolling speed, m/s),
//! `du` (slip ΔU, m/s), `dv` (side slip ΔV, m/s), `omega` (spin, rad/s),
//! `theta` (inlet temperature, °C), and the fluid: `fluid` (`santotrac-50` or
//! `tdf-88`, the report's correlations) and/or `m,mu` (user slope and peak
//! traction coefficient; optional `mu_spin`). A row that fills only `fluid`
//! uses the correlations; only `m,mu` the user values; both: m and μ are the
//! values at the inlet temperature and the named fluid supplies their
//! temperature dependence and film properties for `--thermal`.
//! Other columns are passed through unchanged.
//!
//! `--thermal`: the thermal contact (traction-contact `thermal`: the film's
//! temperature rise from the contact's own loss, μ and m at the raised
//! temperature, solved self-consistently). Optional columns override the
//! thermal properties per row (empty cell = default): `film_thickness` (m),
//! `viscosity` (inlet η₀, Pa·s) with `pressure_viscosity` (α, 1/Pa) for the
//! Hamrock–Dowson film, `fluid_conductivity` (W/(m·K)), `disc_conductivity`
//! (W/(m·K)), `disc_heat_capacity` (ρc, J/(m³·K)), `mu_temperature_coefficient`
//! and `m_temperature_coefficient` (β = −d ln μ/dθ, −d ln m/dθ, 1/K),
//! `mu_rise_scale` (T* of the second-order term of ln μ in the rise, K). A user
//! fluid (`m,mu` only) needs `mu_temperature_coefficient`,
//! `fluid_conductivity` and a film (`film_thickness`, or `viscosity` and
//! `pressure_viscosity`); the report fluids have their own
//! (traction-fluids `thermal_properties.csv`). Discs default to steel.
//!
//! Output: the input columns followed by `fx,fy,mz,loss,a,b,k,p0,m_used,
//! mu_used,J1,J2,J3,J4,J5,J6,J7,regime,temperature_rise` (N, N, N·m, W, m, m,
//! -, Pa, -, -, the report's dimensionless groups, regime name, K; with
//! `--thermal` m_used and mu_used are at the raised temperature, without it
//! the temperature rise is 0). Every row is evaluated before anything is
//! written; a row that cannot be evaluated stops the command with an error
//! naming the row, the line and the quantity.

use clap::{Args, ValueEnum};
use traction_contact::{
    Accuracy, Body, Compliance, Direction, DiscMaterial, EnvelopeRule, Evaluation, Film, Fluid,
    Limit, Model, Modulus, OperatingState, Options, Properties, Thermal, TractionContact,
};

use crate::error::{CliError, chain};
use crate::table::{Table, TableWriter, fmt_f64, output_headers};

/// Input columns every row needs.
const INPUT_COLUMNS: [&str; 14] = [
    "rx1", "ry1", "rx2", "ry2", "e1", "nu1", "e2", "nu2", "load", "u", "du", "dv", "omega", "theta",
];

/// Output columns appended to the input columns.
pub const OUTPUT_COLUMNS: [&str; 19] = [
    "fx",
    "fy",
    "mz",
    "loss",
    "a",
    "b",
    "k",
    "p0",
    "m_used",
    "mu_used",
    "J1",
    "J2",
    "J3",
    "J4",
    "J5",
    "J6",
    "J7",
    "regime",
    "temperature_rise",
];

/// Optional thermal-property columns (`--thermal`), SI units.
pub const THERMAL_COLUMNS: [&str; 9] = [
    "film_thickness",
    "viscosity",
    "pressure_viscosity",
    "fluid_conductivity",
    "disc_conductivity",
    "disc_heat_capacity",
    "mu_temperature_coefficient",
    "m_temperature_coefficient",
    "mu_rise_scale",
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
    /// Thermal contact: the film's temperature rise from the contact's own
    /// loss, μ and m at that temperature (output column temperature_rise, K).
    #[arg(long)]
    pub thermal: bool,
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
            thermal: self.thermal.then(Thermal::default),
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

/// Warns on stderr when row `row` (0-based) of `table` was evaluated with a
/// report fluid's correlation outside its data envelope (the envelope rule
/// allowed it: extrapolated or clamped).
pub fn warn_outside_envelope(table: &Table, row: usize, e: &Evaluation) {
    if e.outside_envelope.any() {
        eprintln!(
            "warning: {}: row {}: fluid correlation outside its data envelope ({:?})",
            table.source_name,
            row + 1,
            e.outside_envelope
        );
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
    Ok(f.map_err(|e| chain(&e))?.use_spin_peak(spin_peak))
}

/// Arguments of `traction contact`.
#[derive(Debug, Args)]
pub struct ContactArgs {
    /// Input CSV (`-` for stdin). Columns rx1,ry1,rx2,ry2 (m), e1,nu1,e2,nu2
    /// (Pa, -), load (N), u, du, dv (m/s), omega (rad/s), theta (°C), and
    /// fluid (santotrac-50 | tdf-88) and/or m,mu (optional mu_spin); with
    /// --thermal optional film_thickness, viscosity, pressure_viscosity,
    /// fluid_conductivity, disc_conductivity, disc_heat_capacity,
    /// mu_temperature_coefficient, m_temperature_coefficient, mu_rise_scale
    /// (SI).
    #[arg(long, default_value = "-")]
    pub input: String,
    /// Output CSV (`-` for stdout): the input columns followed by
    /// fx,fy,mz,loss,a,b,k,p0,m_used,mu_used,J1..J7,regime,temperature_rise.
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
    let (m, mu) = if table.has("m") && table.has("mu") {
        (table.opt_f64(row, "m")?, table.opt_f64(row, "mu")?)
    } else {
        (None, None)
    };
    let fluid = match (name, m, mu) {
        (Some(n), None, None) => report_fluid(&n, model.rule(), model.spin_peak)
            .map_err(|e| table.cell_error(row, "fluid", e))?,
        // Both: the user's m, μ at the inlet, the fluid's temperature dependence.
        (Some(n), Some(m), Some(mu)) => report_fluid(&n, model.rule(), model.spin_peak)
            .map_err(|e| table.cell_error(row, "fluid", e))?
            .with_inlet_values(m, mu)
            .map_err(|e| table.row_error(row, e))?,
        (_, m, mu) => {
            let (Some(m), Some(mu)) = (m, mu) else {
                return Err(table.cell_error(
                    row,
                    if m.is_none() { "m" } else { "mu" },
                    "no fluid: fill `fluid` (santotrac-50 or tdf-88) and/or both `m` and `mu`",
                ));
            };
            let f = Fluid::constant(m, mu).map_err(|e| table.row_error(row, e))?;
            match table.opt_f64(row, "mu_spin")? {
                Some(s) => f
                    .with_spin_peak(s)
                    .map_err(|e| table.cell_error(row, "mu_spin", chain(&e)))?,
                None => f,
            }
        }
    };
    let mut opts = *opts;
    if let Some(th) = opts.thermal.as_mut() {
        thermal_columns(table, row, th)?;
        // A fluid given by m and mu has no thermal properties of its own:
        // name the columns that supply them (the contact would name its API).
        if !matches!(fluid, Fluid::Report { .. }) {
            let missing = if th.mu_coefficient.is_none() {
                Some((
                    "mu_temperature_coefficient",
                    "β_μ = −d ln μ/dθ, 1/K, in [-1, 1]",
                ))
            } else if th.fluid_conductivity.is_none() {
                Some((
                    "fluid_conductivity",
                    "the film's thermal conductivity, W/(m·K)",
                ))
            } else if matches!(fluid, Fluid::Constant { .. }) && th.film == Film::FromFluid {
                Some((
                    "film_thickness",
                    "m, or both `viscosity` and `pressure_viscosity`",
                ))
            } else {
                None
            };
            if let Some((column, what)) = missing {
                return Err(table.cell_error(
                    row,
                    column,
                    format!(
                        "--thermal with a fluid given by `m` and `mu` needs `{column}` ({what})"
                    ),
                ));
            }
        }
    }
    let contact =
        TractionContact::new(&body1, &body2, fluid, opts).map_err(|e| table.row_error(row, e))?;
    let state = OperatingState::builder()
        .load(v("load")?)
        .rolling_speed(v("u")?)
        .slip(v("du")?)
        .side_slip(v("dv")?)
        .spin(v("omega")?)
        .inlet_temperature_celsius(v("theta")?)
        .build()
        .map_err(|e| table.row_error(row, e))?;
    contact
        .evaluate(&state)
        .map_err(|e| table.row_error(row, e))
}

/// The optional thermal-property columns of a row into `th` (empty or absent
/// cells keep the defaults; checked by the contact, errors name the quantity).
pub(crate) fn thermal_columns(table: &Table, row: usize, th: &mut Thermal) -> Result<(), CliError> {
    let col = |c: &str| table.opt_f64(row, c);
    if let Some(h) = col("film_thickness")? {
        th.film = Film::Thickness(h);
    }
    match (col("viscosity")?, col("pressure_viscosity")?) {
        (Some(viscosity), Some(pressure_viscosity)) => {
            th.film = Film::HamrockDowson {
                viscosity,
                pressure_viscosity,
            };
        }
        (None, None) => {}
        (v, _) => {
            return Err(table.cell_error(
                row,
                if v.is_none() { "viscosity" } else { "pressure_viscosity" },
                "the Hamrock–Dowson film needs both `viscosity` (Pa·s) and `pressure_viscosity` (1/Pa)",
            ));
        }
    }
    if let Some(k) = col("fluid_conductivity")? {
        th.fluid_conductivity = Some(k);
    }
    if let Some(k) = col("disc_conductivity")? {
        th.disc_conductivity = k;
    }
    if let Some(c) = col("disc_heat_capacity")? {
        th.disc_heat_capacity = c;
    }
    if let Some(b) = col("mu_temperature_coefficient")? {
        th.mu_coefficient = Some(b);
    }
    if let Some(b) = col("m_temperature_coefficient")? {
        th.slope_coefficient = Some(b);
    }
    if let Some(t) = col("mu_rise_scale")? {
        th.mu_rise_scale = Some(t);
    }
    Ok(())
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
    v.push(fmt_f64(e.temperature_rise));
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
    if !args.model.thermal {
        let given: Vec<&str> = THERMAL_COLUMNS
            .into_iter()
            .filter(|c| table.has(c))
            .collect();
        if !given.is_empty() {
            eprintln!(
                "warning: {}: thermal-property columns {} are used only with --thermal",
                table.source_name,
                given.join(", ")
            );
        }
    }
    let mut results = Vec::with_capacity(table.len());
    for row in 0..table.len() {
        let e = solve_row(&table, row, &opts, &args.model)?;
        warn_outside_envelope(&table, row, &e);
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
