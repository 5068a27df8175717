//! `traction compliance`: traction-slope conversion between directions
//! (Appendix IV, equations B3 and B7, with Kalker's q).
//!
//! Single conversion (SI units), printing the converted slope alone on stdout:
//!
//! `traction compliance --k 0.5 --p0 2.53e9 --slope 64.06 --from side --to longitudinal`
//!
//! Batch: `--input cases.csv` with columns `k` (b/a), `p0` (Pa), `slope` (the
//! measured m), `from`, `to` (`side` or `longitudinal`), optional `e` (Pa) and
//! `nu` per row (else `--e`/`--nu`). Output: the input columns followed by `q_from`,
//! `q_to` (Kalker's q = π/C11 or π/C22 at a/b = 1/k), `g_s` (Pa), `dry_slope_from`
//! (B3, for the measured direction) and `slope_converted` (B7, same contact).
//!
//! The disc material defaults to the report's steel (E = 210 GPa, ν = 0.3, as
//! deduced from Table 2-2 — see `traction-compliance`).

use clap::{Args, ValueEnum};
use traction_compliance::{
    Direction, DiscMaterial, convert_slope_same_contact, dry_slope, kalker_q,
};

use crate::error::CliError;
use crate::table::{Table, TableWriter, fmt_f64, output_headers};

/// Direction of a traction slope.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum DirectionArg {
    /// Side slip (lateral, y): q = π/C22.
    Side,
    /// Longitudinal slip (rolling direction, x): q = π/C11.
    Longitudinal,
}

impl From<DirectionArg> for Direction {
    fn from(d: DirectionArg) -> Self {
        match d {
            DirectionArg::Side => Direction::Side,
            DirectionArg::Longitudinal => Direction::Longitudinal,
        }
    }
}

/// Arguments of `traction compliance`.
#[derive(Debug, Args)]
pub struct ComplianceArgs {
    /// Input CSV (`-` for stdin) with columns `k,p0,slope,from,to[,e,nu]`.
    #[arg(long, default_value = "-")]
    pub input: String,
    /// Output CSV (`-` for stdout).
    #[arg(long, default_value = "-")]
    pub output: String,
    /// Single conversion: aspect ratio k = b/a.
    #[arg(long)]
    pub k: Option<f64>,
    /// Single conversion: maximum Hertz pressure P0 (Pa).
    #[arg(long)]
    pub p0: Option<f64>,
    /// Single conversion: the measured traction slope m.
    #[arg(long)]
    pub slope: Option<f64>,
    /// Single conversion: direction of the measured slope.
    #[arg(long, value_enum)]
    pub from: Option<DirectionArg>,
    /// Single conversion: direction wanted.
    #[arg(long, value_enum)]
    pub to: Option<DirectionArg>,
    /// Disc Young's modulus E (Pa); default the report's steel, 210 GPa.
    #[arg(long, default_value_t = DiscMaterial::REPORT_STEEL.youngs_modulus)]
    pub e: f64,
    /// Disc Poisson's ratio ν; default the report's steel, 0.3.
    #[arg(long, default_value_t = DiscMaterial::REPORT_STEEL.poisson_ratio)]
    pub nu: f64,
}

fn parse_direction(s: &str) -> Result<Direction, String> {
    match s.to_ascii_lowercase().as_str() {
        "side" => Ok(Direction::Side),
        "longitudinal" => Ok(Direction::Longitudinal),
        _ => Err(format!(
            "`{s}` is not a direction (expected `side` or `longitudinal`)"
        )),
    }
}

/// Run the subcommand.
pub fn run(args: ComplianceArgs) -> Result<(), CliError> {
    let single = [args.k, args.p0, args.slope].iter().any(Option::is_some)
        || args.from.is_some()
        || args.to.is_some();
    if single {
        let (Some(k), Some(p0), Some(m), Some(from), Some(to)) =
            (args.k, args.p0, args.slope, args.from, args.to)
        else {
            return Err(CliError::Usage(
                "a single conversion needs all of --k, --p0, --slope, --from and --to".into(),
            ));
        };
        let material = DiscMaterial::new(args.e, args.nu).map_err(CliError::model)?;
        let ms = convert_slope_same_contact(m, k, p0, from.into(), to.into(), material)
            .map_err(CliError::model)?;
        println!("{}", fmt_f64(ms));
        return Ok(());
    }
    let table = Table::read(&args.input)?;
    table.require(&["k", "p0", "slope", "from", "to"])?;
    let mut out = Vec::with_capacity(table.len());
    for row in 0..table.len() {
        let k = table.f64(row, "k")?;
        let p0 = table.f64(row, "p0")?;
        let m = table.f64(row, "slope")?;
        let from = parse_direction(table.str(row, "from")?)
            .map_err(|msg| table.cell_error(row, "from", msg))?;
        let to = parse_direction(table.str(row, "to")?)
            .map_err(|msg| table.cell_error(row, "to", msg))?;
        let e = table.opt_f64(row, "e")?.unwrap_or(args.e);
        let nu = table.opt_f64(row, "nu")?.unwrap_or(args.nu);
        let re = |err| table.row_error(row, err);
        let material = DiscMaterial::new(e, nu).map_err(re)?;
        let g_s = material.shear_modulus().map_err(re)?;
        let q_from = kalker_q(from, k, nu).map_err(re)?;
        let q_to = kalker_q(to, k, nu).map_err(re)?;
        let m_dry = dry_slope(g_s, q_from, p0).map_err(re)?;
        let ms = convert_slope_same_contact(m, k, p0, from, to, material).map_err(re)?;
        let mut cells = table.rows[row].clone();
        cells.extend([q_from, q_to, g_s, m_dry, ms].map(fmt_f64));
        out.push(cells);
    }
    let extra = ["q_from", "q_to", "g_s", "dry_slope_from", "slope_converted"];
    let mut w = TableWriter::create(&args.output, &output_headers(&table, &extra))?;
    for cells in &out {
        w.write_row(cells)?;
    }
    w.finish()
}
