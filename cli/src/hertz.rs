//! `traction hertz`: elliptical Hertz contact of two bodies, in batch from CSV.
//!
//! Input columns (SI units): `rx1,ry1,rx2,ry2` (principal radii in m along
//! the rolling direction x and across it; convex > 0, concave < 0, flat =
//! `inf` or 0 as in the FMU), `e1,nu1,e2,nu2` (Young's modulus in Pa and Poisson's ratio of each
//! body), and either `load` (N) or `p0` (maximum Hertz pressure, Pa) — a
//! table may have both columns as long as each row fills exactly one. Other
//! columns (labels) are passed through unchanged.
//!
//! Output: the input columns, followed by `a,b,k,p0,load,re,e_prime,shape_a,
//! shape_b,c` (m, m, -, Pa, N, m, Pa, -, -, m/Pa); with `--all-columns` also
//! `p_mean,area,approach,eccentricity_sq,elliptic_k,elliptic_e` (Pa, m², m,
//! -, -, -; `eccentricity_sq` is the elliptic parameter m = e² of K and E).
//! Every column name appears once: the input's `load` and `p0` columns are not
//! repeated (the computed `load` and `p0` hold the given value where a row gave
//! it), and any other input column named like a computed one is written as
//! `input_NAME`.
//! Every row is validated before anything is written; a bad row stops the
//! command with an error naming the row, the line and the column or quantity.

use clap::{Args, ValueEnum};
use traction_hertz::{Body, Contact, Geometry, Method};

use crate::error::CliError;
use crate::table::{Table, TableWriter, fmt_f64, radius};

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
    /// Input CSV (`-` for stdin). Columns rx1,ry1,rx2,ry2 (m, flat = inf or 0),
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
    let r = |c: &str| table.f64(row, c).map(radius);
    let body1 = Body::new(r("rx1")?, r("ry1")?, v("e1")?, v("nu1")?);
    let body2 = Body::new(r("rx2")?, r("ry2")?, v("e2")?, v("nu2")?);
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

/// The input columns written before the computed ones (indices and names):
/// `load` and `p0` are carried by the computed columns of the same name, and
/// another input column named like a computed one becomes `input_NAME`.
fn echoed_columns(input: &[String], computed: &[&str]) -> (Vec<usize>, Vec<String>) {
    input
        .iter()
        .enumerate()
        .filter(|(_, h)| !matches!(h.as_str(), "load" | "p0"))
        .map(|(i, h)| {
            if computed.contains(&h.as_str()) {
                (i, format!("input_{h}"))
            } else {
                (i, h.clone())
            }
        })
        .unzip()
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
    let mut extra: Vec<&str> = OUTPUT_COLUMNS.to_vec();
    if args.all_columns {
        extra.extend(EXTRA_COLUMNS);
    }
    let (echo, mut headers) = echoed_columns(&table.headers, &extra);
    headers.extend(extra.iter().map(|s| s.to_string()));
    let mut out = Vec::with_capacity(table.len());
    for row in 0..table.len() {
        let contact = solve_row(&table, row, method)?;
        let mut cells: Vec<String> = echo.iter().map(|&i| table.rows[row][i].clone()).collect();
        cells.extend(output_cells(&contact, args.all_columns));
        out.push(cells);
    }
    let mut w = TableWriter::create(&args.output, &headers)?;
    for cells in &out {
        w.write_row(cells)?;
    }
    w.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_column_name_is_written_twice() {
        let input: Vec<String> = ["rx1", "load", "p0", "a", "label"]
            .map(String::from)
            .to_vec();
        let (idx, names) = echoed_columns(&input, &OUTPUT_COLUMNS);
        assert_eq!(idx, vec![0_usize, 3, 4]);
        assert_eq!(names, ["rx1", "input_a", "label"]);
    }
}
