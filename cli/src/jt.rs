//! `traction jt`: the Johnson & Tevaarwerk model in the dimensionless J groups.
//!
//! Input columns `k,J1,J2,J3`, optionally `dX` (spin-pole offset), `gy`
//! (stiffness ratio Ḡy/Ḡx, default 1) and, for `--model viscoelastic`, `D`
//! (Deborah number) and optionally `Z0` (sinh reference stress τ0/τ̄,
//! default 1). Output: the input columns followed by `J4,J5,J6,J7`.
//! `--map` evaluates the elastic/plastic rows through one interpolation map
//! per (k, dX, gy) (traction-rheology `map::Map`): for large batches at few
//! geometries. A group's map may compute [`MAP_NODES_PER_ROW`] node
//! evaluations per row of the group, a budget known before its first cell is
//! built; a group that would need more (scattered points, each opening new
//! cells) or that cannot afford one cell (fewer than 130 rows, e.g. a k per
//! row) is evaluated directly instead. So `--map` costs at most a few direct
//! evaluations per row on any input (docs/decisions/0043, 0126). Rows
//! (or, with `--map`, the groups of one map) are evaluated in parallel on all
//! cores.

use std::collections::HashMap;

use clap::{Args, ValueEnum};
use rayon::prelude::*;
use traction_rheology::map::{Budget, CELL_COST, Map, MapStats};
use traction_rheology::{Accuracy, Inputs, Model, Outputs, RheologyError, evaluate};

use crate::error::CliError;
use crate::table::{Table, TableWriter, fmt_f64, output_headers};

/// `--map`: node evaluations (at tol/10, plus one check per cell) a group's
/// map may spend per row of the group, given to the map as its credit before
/// any cell is built; where it does not cover a cell the group is evaluated
/// directly. A node costs 1.4–7 direct evaluations at tol (bench set,
/// instructions), so a group that exceeds the budget costs at most
/// 1 + 0.5·7 ≈ 4.5 direct evaluations per row, and one within it ≥ 2 rows
/// per node, where the map is about as fast as direct evaluation or faster.
pub const MAP_NODES_PER_ROW: f64 = 0.5;

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

/// The result of one row: its index and outputs.
type RowResult = (usize, Result<Outputs, RheologyError>);

/// The rows `g` (indices into `rows`, in input order) of one (k, dX, gy)
/// group with `--map`, and the counters of the group's map (None where no map
/// was used).
///
/// The group's budget, [`MAP_NODES_PER_ROW`] node evaluations per row, is
/// the map's credit ([`Budget`]) from the start, so no cell is built that it
/// does not cover. A group whose budget cannot build one cell
/// ([`CELL_COST`]) is evaluated directly without a map. Once a row needs a
/// cell beyond the credit, the whole group is evaluated directly: its
/// interpolated rows again, its direct ones kept (they are bit-identical).
/// So the map costs at most its budget plus one direct evaluation per row,
/// and a group either stays on the map or is bit-identical to the run
/// without `--map`, decided by its rows in input order alone.
fn evaluate_group(
    rows: &[(Inputs, Model)],
    g: &[usize],
    acc: Accuracy,
) -> (Vec<RowResult>, Option<MapStats>) {
    let direct = |r: usize| (r, evaluate(&rows[r].0, rows[r].1, acc));
    let credit = MAP_NODES_PER_ROW * g.len() as f64;
    if credit < CELL_COST {
        return (g.par_iter().map(|&r| direct(r)).collect(), None);
    }
    let credit = credit.min(1e9);
    let first = &rows[g[0]].0;
    let map = Map::new(first.k, first.dx, first.gy, acc)
        .and_then(|m| Budget::new(0.0, credit, credit, credit).map(|b| m.with_budget(b)));
    let mut map = match map {
        Ok(map) => map,
        Err(e) => return (g.iter().map(|&r| (r, Err(e.clone()))).collect(), None),
    };
    let mut out = Vec::with_capacity(g.len());
    // Whether a row's value came from direct evaluation (the closed form,
    // large |J|, rejected cells): bit-identical to the run without --map.
    let mut exact = Vec::with_capacity(g.len());
    for &r in g {
        let before = map.stats();
        out.push((r, map.evaluate(&rows[r].0)));
        let after = map.stats();
        if after.over_budget > 0 {
            // This row went direct (over budget); the rows after it follow.
            exact.push(true);
            let mut redo: Vec<usize> = g[out.len()..].to_vec();
            let mut kept = Vec::with_capacity(g.len());
            for (o, e) in out.into_iter().zip(exact) {
                if e {
                    kept.push(o);
                } else {
                    redo.push(o.0);
                }
            }
            kept.par_extend(redo.par_iter().map(|&r| direct(r)));
            return (kept, Some(after));
        }
        exact.push(after.interpolated == before.interpolated);
    }
    let stats = map.stats();
    (out, Some(stats))
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
            .map(|g| evaluate_group(&rows, g, acc).0)
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

#[cfg(test)]
mod tests {
    use super::*;

    fn ep(k: f64, j1: f64, j2: f64, j3: f64) -> (Inputs, Model) {
        (Inputs::new(k, j1, j2, j3).unwrap(), Model::ElasticPlastic)
    }

    fn direct(rows: &[(Inputs, Model)], acc: Accuracy) -> Vec<Outputs> {
        rows.iter()
            .map(|(i, m)| evaluate(i, *m, acc).unwrap())
            .collect()
    }

    /// `rows` as one group through [`evaluate_group`]: the outputs in row
    /// order and the map's counters.
    fn whole_group(rows: &[(Inputs, Model)], acc: Accuracy) -> (Vec<Outputs>, Option<MapStats>) {
        let g: Vec<usize> = (0..rows.len()).collect();
        let (mut out, stats) = evaluate_group(rows, &g, acc);
        out.sort_unstable_by_key(|(r, _)| *r);
        (out.into_iter().map(|(_, o)| o.unwrap()).collect(), stats)
    }

    /// High-spin states scattered over |J1|, |J2| ≤ 5, J3 ∈ [5, 26].
    fn scattered(k: f64, n: usize) -> Vec<(Inputs, Model)> {
        (0..n)
            .map(|n| {
                let t = n as f64;
                let j3 = 15.5 + 10.5 * (0.9 * t).sin();
                ep(k, 5.0 * (1.7 * t).sin(), 5.0 * (2.3 * t).cos(), j3)
            })
            .collect()
    }

    #[test]
    fn a_group_that_cannot_afford_a_cell_builds_none() {
        // A group of fewer than CELL_COST / MAP_NODES_PER_ROW = 130 rows
        // (e.g. one row per k) is evaluated directly without a map. The
        // budget used to be checked only after a row, so each such group
        // built a cell chain first (131 node evaluations at tol/10 for one of
        // these rows; 2000 random rows with a k each took ≈ 290× as long as
        // direct evaluation).
        let acc = Accuracy::new(1e-3).unwrap();
        let rows = scattered(2.0, 129);
        let (out, stats) = whole_group(&rows, acc);
        assert_eq!(stats, None);
        assert_eq!(out, direct(&rows, acc));
        let (out, stats) = whole_group(&rows[7..8], acc);
        assert_eq!(stats, None);
        assert_eq!(out, direct(&rows[7..8], acc));
    }

    #[test]
    fn a_scattered_group_spends_at_most_its_budget() {
        // 400 scattered rows: a budget of 200 node evaluations, three cells.
        // The map stops at the first cell beyond its credit, and the group is
        // then bit-identical to direct evaluation.
        let acc = Accuracy::new(1e-3).unwrap();
        let rows = scattered(2.0, 400);
        let (out, stats) = whole_group(&rows, acc);
        let s = stats.expect("a group of 400 rows has a map");
        assert!(s.over_budget > 0, "{s:?}");
        let spent = (s.nodes_computed + s.cells_checked) as f64;
        assert!(spent <= MAP_NODES_PER_ROW * 400.0, "{s:?}");
        assert_eq!(out, direct(&rows, acc));
    }

    #[test]
    fn a_dense_group_stays_on_its_map() {
        // 600 rows within 2 % of one state need one or two cells: within the
        // budget, interpolated, and within tol of the direct value at tol/100.
        let acc = Accuracy::new(1e-3).unwrap();
        let rows: Vec<_> = (0..600)
            .map(|n| ep(1.0, 1.5 + 5e-5 * f64::from(n), 0.3, 2.0))
            .collect();
        let (out, stats) = whole_group(&rows, acc);
        let s = stats.expect("a group of 600 rows has a map");
        assert_eq!(s.over_budget, 0, "{s:?}");
        assert!(s.interpolated > 500, "{s:?}");
        let fine = direct(&rows, Accuracy::new(1e-5).unwrap());
        for (a, b) in out.iter().zip(&fine) {
            let d = [a.j4 - b.j4, a.j5 - b.j5, a.j6 - b.j6];
            assert!(d.iter().all(|d| d.abs() <= 1e-3), "{a:?} vs {b:?}");
        }
    }
}
