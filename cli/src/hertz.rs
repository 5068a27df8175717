//! `traction hertz`: elliptical Hertz contact of two bodies, in batch from CSV.
//!
//! Input columns (SI units): `rx1,ry1,rx2,ry2` (principal radii in m along
//! the rolling direction x and across it; convex > 0, concave < 0, flat =
//! `inf`), `e1,nu1,e2,nu2` (Young's modulus in Pa and Poisson's ratio of each
//! body), and either `load` (N) or `p0` (maximum Hertz pressure, Pa) — a
//! table may have both columns as long as each row fills exactly one. Other
//! columns (labels) are passed through unchanged.
//!
//! Output: the input columns, followed by `a,b,k,p0,load,re,e_prime,shape_a,
//! shape_b,c` (m, m, -, Pa, N, m, Pa, -, -, m/Pa); with `--all-columns` also
//! `p_mean,area,approach,eccentricity_sq,elliptic_k,elliptic_e` (Pa, m², m,
//! -, -, -; `eccentricity_sq` is the elliptic parameter m = e² of K and E).
//! Every row is validated before anything is written; a bad row stops the
//! command with an error naming the row, the line and the column or quantity.

use clap::{Args, ValueEnum};
use traction_hertz::{Body, Contact, Geometry, Method};

use crate::error::CliError;
use crate::table::{Table, TableWriter, fmt_f64, output_headers};

/// Input columns every row needs.
const INPUT_COLUMNS: [&str; 8] = ["rx1", "ry1", "rx2", "ry2", "e1", "nu1", "e2", "nu2"];

/// Output columns appended to the input columns.
const OUTPUT_COLUMNS: [&str; 10] = [
    "a", "b", "k", "p0", "load", "re", "e_prime", "shape_a", "shape_b", "c",
];

/// Extra output columns with `--all-columns`.
const EXTRA_COLUMNS: [&str; 6] = [
    "p_mean",
    "area",
    "approach",
    "eccentricity_sq",
    "elliptic_k",
    "elliptic_e",
];

/// How the ellipticity and elliptic integrals are computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MethodArg {
    /// Exact Hertz theory (complete elliptic integrals, root solve to 1e-12).
    Exact,
    /// Hamrock–Brewe (1983) curve fits: cheaper, errors up to a few percent.
    HamrockBrewe,
}

/// Arguments of `traction hertz`.
#[derive(Debug, Args)]
pub struct HertzArgs {
    /// Input CSV (`-` for stdin). Columns rx1,ry1,rx2,ry2 (m, flat = inf),
    /// e1,nu1,e2,nu2 (Pa, -), and load (N) or p0 (Pa).
    #[arg(long, default_value = "-")]
    pub input: String,
    /// Output CSV (`-` for stdout): the input columns followed by
    /// a,b,k,p0,load,re,e_prime,shape_a,shape_b,c (SI units).
    #[arg(long, default_value = "-")]
    pub output: String,
    /// Solution method.
    #[arg(long, value_enum, default_value_t = MethodArg::Exact)]
    pub method: MethodArg,
    /// Also write p_mean,area,approach,eccentricity_sq,elliptic_k,elliptic_e.
    #[arg(long)]
    pub all_columns: bool,
}

/// Solve one row.
fn solve_row(table: &Table, row: usize, method: Method) -> Result<Contact, CliError> {
    let v = |c: &str| table.f64(row, c);
    let body1 = Body::new(v("rx1")?, v("ry1")?, v("e1")?, v("nu1")?);
    let body2 = Body::new(v("rx2")?, v("ry2")?, v("e2")?, v("nu2")?);
    let load = table.opt_f64(row, "load")?;
    let p0 = table.opt_f64(row, "p0")?;
    let geometry =
        Geometry::with_method(&body1, &body2, method).map_err(|e| table.row_error(row, e))?;
    match (load, p0) {
        (Some(f), None) => geometry
            .at_load(f)
            .map_err(|e| table.cell_error(row, "load", e.to_string())),
        (None, Some(p)) => geometry
            .at_p0(p)
            .map_err(|e| table.cell_error(row, "p0", e.to_string())),
        (Some(_), Some(_)) => Err(table.cell_error(
            row,
            "p0",
            "both `load` and `p0` are given; fill exactly one of them",
        )),
        (None, None) => Err(table.cell_error(
            row,
            "load",
            "neither `load` (N) nor `p0` (Pa) is given; fill exactly one of them",
        )),
    }
}

/// The output cells of one solved row.
fn output_cells(c: &Contact, all_columns: bool) -> Vec<String> {
    let g = &c.geometry;
    let mut v = vec![
        c.a, c.b, g.k, c.p0, c.load, g.re, g.e_prime, g.shape_a, g.shape_b, g.c,
    ];
    if all_columns {
        v.extend([
            c.p_mean,
            c.area,
            c.approach,
            g.eccentricity_sq,
            g.elliptic_k,
            g.elliptic_e,
        ]);
    }
    v.into_iter().map(fmt_f64).collect()
}

/// Run the subcommand.
pub fn run(args: HertzArgs) -> Result<(), CliError> {
    let table = Table::read(&args.input)?;
    table.require(&INPUT_COLUMNS)?;
    if !table.has("load") && !table.has("p0") {
        return Err(CliError::MissingColumn {
            source_name: table.source_name.clone(),
            column: "load or p0".into(),
            expected: format!("{},load|p0", INPUT_COLUMNS.join(",")),
        });
    }
    let method = match args.method {
        MethodArg::Exact => Method::Exact,
        MethodArg::HamrockBrewe => Method::HamrockBrewe,
    };
    // Solve every row before writing anything: a bad row leaves no partial output.
    let mut out = Vec::with_capacity(table.len());
    for row in 0..table.len() {
        let contact = solve_row(&table, row, method)?;
        let mut cells = table.rows[row].clone();
        cells.extend(output_cells(&contact, args.all_columns));
        out.push(cells);
    }
    let mut extra: Vec<&str> = OUTPUT_COLUMNS.to_vec();
    if args.all_columns {
        extra.extend(EXTRA_COLUMNS);
    }
    let mut w = TableWriter::create(&args.output, &output_headers(&table, &extra))?;
    for cells in &out {
        w.write_row(cells)?;
    }
    w.finish()
}
