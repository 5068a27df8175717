//! `traction jt`: the Johnson & Tevaarwerk model in the dimensionless J groups.
//!
//! Input columns `k,J1,J2,J3`, optionally `dX` (spin-pole offset), `gy`
//! (stiffness ratio Ḡy/Ḡx, default 1) and, for `--model viscoelastic`, `D`
//! (Deborah number) and optionally `Z0` (sinh reference stress τ0/τ̄,
//! default 1). Output: the input columns followed by `J4,J5,J6,J7`.
//! `--map` evaluates the elastic/plastic rows through one interpolation map
//! per (k, dX, gy) (traction-rheology `map::Map`): for large batches at few
//! geometries. A group whose map would compute more than
//! [`MAP_NODES_PER_ROW`] node evaluations per row (scattered points, each
//! opening new cells) is evaluated directly instead, so `--map` costs at most
//! a few direct evaluations per row on any input (docs/decisions/0043). Rows
//! (or, with `--map`, the groups of one map) are evaluated in parallel on all
//! cores.

use std::collections::HashMap;

use clap::{Args, ValueEnum};
use rayon::prelude::*;
use traction_rheology::map::Map;
use traction_rheology::{Accuracy, Inputs, Model, Outputs, RheologyError, evaluate};

use crate::error::CliError;

/// `--map`: node evaluations (at tol/10, plus one check per cell) a group's
/// map may spend per row of the group; beyond it the group is evaluated
/// directly. A node costs 1.4–7 direct evaluations at tol (bench set,
/// instructions), so a group that exceeds the budget costs at most
/// 1 + 0.5·7 ≈ 4.5 direct evaluations per row, and one within it ≥ 2 rows
/// per node, where the map is about as fast as direct evaluation or faster.
pub const MAP_NODES_PER_ROW: f64 = 0.5;
use crate::table::{Table, TableWriter, fmt_f64, output_headers};

/// Constitutive model selected on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum JtModel {
    /// Elastic/perfectly plastic (Prandtl–Reuss), the report's printed theory.
    ElasticPlastic,
    /// Rigid/plastic (Wernitz, Magi).
    RigidPlastic,
    /// Viscoelastic sinh law with Deborah number `D` (column) and the limit as a cap.
    Viscoelastic,
}

/// Arguments of `traction jt`.
#[derive(Debug, Args)]
pub struct JtArgs {
    /// Input CSV (`-` for stdin) with columns `k,J1,J2,J3[,dX][,gy][,D][,Z0]`.
    #[arg(long, default_value = "-")]
    pub input: String,
    /// Output CSV (`-` for stdout): the input columns followed by J4,J5,J6,J7.
    #[arg(long, default_value = "-")]
    pub output: String,
    /// Constitutive model.
    #[arg(long, value_enum, default_value_t = JtModel::ElasticPlastic)]
    pub model: JtModel,
    /// Target absolute accuracy of J4, J5, J6 (1e-9 ..= 0.1).
    #[arg(long, default_value_t = 1e-4)]
    pub tol: f64,
    /// Elastic/plastic model only: interpolate in one lazily built map per
    /// (k, dX, gy), each cell checked against direct evaluation to tol/4
    /// (tol in 1e-4 ..= 1e-2). Pays off for thousands of rows at few
    /// geometries; a group whose map would need more than 0.5 node
    /// evaluations per row is evaluated directly instead.
    #[arg(long)]
    pub map: bool,
}

/// Run the subcommand.
pub fn run(args: JtArgs) -> Result<(), CliError> {
    let acc = Accuracy::new(args.tol).map_err(|e| CliError::Usage(format!("--tol: {e}")))?;
    let t = Table::read(&args.input)?;
    let mut need = vec!["k", "J1", "J2", "J3"];
    if args.model == JtModel::Viscoelastic {
        need.push("D");
    }
    t.require(&need)?;
    if args.map && args.model != JtModel::ElasticPlastic {
        return Err(CliError::Usage(
            "--map applies to --model elastic-plastic only".into(),
        ));
    }
    if args.map {
        // The same check as the map's, reported as a usage error up front.
        Map::new(1.0, 0.0, 1.0, acc).map_err(|e| CliError::Usage(format!("--map: {e}")))?;
    }
    // Parse every row first (the first bad row is reported), then evaluate
    // in parallel: rows directly, or `--map` groups (one map per (k, dX, gy),
    // its rows in input order) on all cores. Results depend only on the
    // inputs, so the output does not depend on the thread count.
    let mut rows = Vec::with_capacity(t.len());
    for row in 0..t.len() {
        let k = t.f64(row, "k")?;
        let j1 = t.f64(row, "J1")?;
        let j2 = t.f64(row, "J2")?;
        let j3 = t.f64(row, "J3")?;
        let dx = t.opt_f64(row, "dX")?.unwrap_or(0.0);
        let model = match args.model {
            JtModel::ElasticPlastic => Model::ElasticPlastic,
            JtModel::RigidPlastic => Model::RigidPlastic,
            JtModel::Viscoelastic => Model::Viscoelastic {
                deborah: t.f64(row, "D")?,
                z0: t.opt_f64(row, "Z0")?.unwrap_or(1.0),
            },
        };
        let gy = t.opt_f64(row, "gy")?.unwrap_or(1.0);
        let inp = Inputs::with_offset(k, j1, j2, j3, dx)
            .and_then(|i| i.with_stiffness_ratio(gy))
            .map_err(|e| t.row_error(row, e))?;
        rows.push((inp, model));
    }
    let results: Vec<Result<Outputs, RheologyError>> = if args.map {
        let mut groups: HashMap<[u64; 3], Vec<usize>> = HashMap::new();
        for (row, (inp, _)) in rows.iter().enumerate() {
            let key = [inp.k.to_bits(), inp.dx.to_bits(), inp.gy.to_bits()];
            groups.entry(key).or_default().push(row);
        }
        let groups: Vec<Vec<usize>> = groups.into_values().collect();
        let done: Vec<Vec<(usize, Result<Outputs, RheologyError>)>> = groups
            .par_iter()
            .map(|g| {
                let first = &rows[g[0]].0;
                match Map::new(first.k, first.dx, first.gy, acc) {
                    Ok(mut map) => {
                        // The rows in input order: whether the group exceeds
                        // the budget depends on its rows alone (not on threads).
                        let budget = MAP_NODES_PER_ROW * g.len() as f64;
                        let mut out = Vec::with_capacity(g.len());
                        for &r in g {
                            out.push((r, map.evaluate(&rows[r].0)));
                            let s = map.stats();
                            if (s.nodes_computed + s.cells_checked) as f64 > budget {
                                return g
                                    .par_iter()
                                    .map(|&r| (r, evaluate(&rows[r].0, rows[r].1, acc)))
                                    .collect();
                            }
                        }
                        out
                    }
                    Err(e) => g.iter().map(|&r| (r, Err(e.clone()))).collect(),
                }
            })
            .collect();
        let mut res: Vec<(usize, Result<Outputs, RheologyError>)> =
            done.into_iter().flatten().collect();
        res.sort_unstable_by_key(|(r, _)| *r);
        res.into_iter().map(|(_, o)| o).collect()
    } else {
        rows.par_iter()
            .map(|(inp, model)| evaluate(inp, *model, acc))
            .collect()
    };
    let mut out = Vec::with_capacity(t.len());
    for (row, o) in results.into_iter().enumerate() {
        let o = o.map_err(|e| t.row_error(row, e))?;
        out.push([o.j4, o.j5, o.j6, o.j7]);
    }
    let mut w = TableWriter::create(&args.output, &output_headers(&t, &["J4", "J5", "J6", "J7"]))?;
    for (row, vals) in out.iter().enumerate() {
        let mut cells: Vec<String> = t.rows[row].clone();
        cells.extend(vals.iter().map(|v| fmt_f64(*v)));
        w.write_row(&cells)?;
    }
    w.finish()
}
