//! `traction map --k 1 --j1 0:10:101 --j3 0:20:41 --out map.csv`: J4, J5, J6,
//! J7 of the J+T model over a grid of J1, J2, J3 (each a single value or a
//! range `start:stop:count`), evaluated in parallel, written as CSV
//! (`k,J1,J2,J3,J4,J5,J6,J7`, J1 fastest) plus a heat-map PNG of the four
//! outputs when exactly two of J1, J2, J3 vary.

use std::path::PathBuf;

use clap::Args;
use rayon::prelude::*;
use traction_reproduce::plot::{Field, write_heatmaps};
use traction_rheology::{Accuracy, Inputs, Model, evaluate};

use crate::error::CliError;
use crate::jt::JtModel;
use crate::reproduce::{pool, progress};
use crate::table::{TableWriter, fmt_f64};

/// Largest grid accepted (points), to keep a typo from running for hours.
pub const MAX_POINTS: usize = 1_000_000;

/// Arguments of `traction map`.
#[derive(Debug, Args)]
pub struct MapArgs {
    /// Aspect ratio k = b/a (0.01..=100).
    #[arg(long, default_value_t = 1.0)]
    pub k: f64,
    /// Slip J1: a value or `start:stop:count`.
    #[arg(long, default_value = "0")]
    pub j1: String,
    /// Side slip J2: a value or `start:stop:count`.
    #[arg(long, default_value = "0")]
    pub j2: String,
    /// Spin J3: a value or `start:stop:count`.
    #[arg(long, default_value = "0")]
    pub j3: String,
    /// Constitutive model.
    #[arg(long, value_enum, default_value_t = JtModel::ElasticPlastic)]
    pub model: JtModel,
    /// Deborah number D (required for `--model viscoelastic`).
    #[arg(long)]
    pub deborah: Option<f64>,
    /// Sinh reference stress Z0 = τ0/τ̄ for `--model viscoelastic`.
    #[arg(long, default_value_t = 1.0)]
    pub z0: f64,
    /// Target absolute accuracy of J4, J5, J6 (1e-9 ..= 0.1).
    #[arg(long, default_value_t = 1e-4)]
    pub tol: f64,
    /// Output CSV (`-` for stdout).
    #[arg(long)]
    pub out: String,
    /// Heat-map PNG (default: the CSV path with `.png`; none for stdout).
    #[arg(long)]
    pub png: Option<PathBuf>,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub jobs: Option<usize>,
}

/// Parse `v` or `start:stop:count` into the grid values.
pub fn parse_range(name: &str, s: &str) -> Result<Vec<f64>, CliError> {
    let bad = |why: &str| {
        CliError::Usage(format!(
            "--{name} {s:?}: {why} (expected a number or start:stop:count, e.g. 0:10:101)"
        ))
    };
    let num = |t: &str| -> Result<f64, CliError> {
        let v: f64 = t
            .trim()
            .parse()
            .map_err(|_| bad(&format!("`{t}` is not a number")))?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(bad("values must be finite"))
        }
    };
    let parts: Vec<&str> = s.split(':').collect();
    match parts.as_slice() {
        [v] => Ok(vec![num(v)?]),
        [a, b, n] => {
            let (a, b) = (num(a)?, num(b)?);
            let n: usize = n
                .trim()
                .parse()
                .map_err(|_| bad("count must be a whole number"))?;
            match n {
                0 => Err(bad("count must be at least 1")),
                1 => Ok(vec![a]),
                _ if n > MAX_POINTS => Err(bad("count too large")),
                _ => Ok((0..n)
                    .map(|i| a + (b - a) * i as f64 / (n - 1) as f64)
                    .collect()),
            }
        }
        _ => Err(bad("wrong number of `:`-separated parts")),
    }
}

/// Run the subcommand.
pub fn run(args: MapArgs) -> Result<(), CliError> {
    let acc = Accuracy::new(args.tol).map_err(|e| CliError::Usage(format!("--tol: {e}")))?;
    let model = match args.model {
        JtModel::ElasticPlastic => Model::ElasticPlastic,
        JtModel::RigidPlastic => Model::RigidPlastic,
        JtModel::Viscoelastic => Model::Viscoelastic {
            deborah: args
                .deborah
                .ok_or_else(|| CliError::Usage("--model viscoelastic needs --deborah D".into()))?,
            z0: args.z0,
        },
    };
    let axes = [
        ("J1", parse_range("j1", &args.j1)?),
        ("J2", parse_range("j2", &args.j2)?),
        ("J3", parse_range("j3", &args.j3)?),
    ];
    let n: usize = axes.iter().map(|a| a.1.len()).product();
    if n > MAX_POINTS {
        return Err(CliError::Usage(format!(
            "the grid has {n} points, more than {MAX_POINTS}"
        )));
    }
    // Validate k and the ranges once, before the long run.
    Inputs::new(args.k, axes[0].1[0], axes[1].1[0], axes[2].1[0])
        .map_err(|e| CliError::Usage(e.to_string()))?;
    let (n1, n2) = (axes[0].1.len(), axes[1].1.len());
    let point = |i: usize| {
        (
            axes[0].1[i % n1],
            axes[1].1[(i / n1) % n2],
            axes[2].1[i / (n1 * n2)],
        )
    };
    let pool = pool(args.jobs)?;
    let pb = progress(n as u64, "map");
    let out: Vec<[f64; 4]> = pool.install(|| {
        (0..n)
            .into_par_iter()
            .map(|i| {
                let (j1, j2, j3) = point(i);
                let r = Inputs::new(args.k, j1, j2, j3)
                    .and_then(|inp| evaluate(&inp, model, acc))
                    .map(|o| [o.j4, o.j5, o.j6, o.j7])
                    .map_err(|e| {
                        CliError::Model(format!(
                            "k = {}, J1 = {j1}, J2 = {j2}, J3 = {j3}: {e}",
                            args.k
                        ))
                    });
                pb.inc(1);
                r
            })
            .collect::<Result<_, CliError>>()
    })?;
    pb.finish_and_clear();
    let headers: Vec<String> = ["k", "J1", "J2", "J3", "J4", "J5", "J6", "J7"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    let mut w = TableWriter::create(&args.out, &headers)?;
    for (i, v) in out.iter().enumerate() {
        let (j1, j2, j3) = point(i);
        let mut cells = vec![fmt_f64(args.k), fmt_f64(j1), fmt_f64(j2), fmt_f64(j3)];
        cells.extend(v.iter().map(|x| fmt_f64(*x)));
        w.write_row(&cells)?;
    }
    w.finish()?;
    let png = match (&args.png, args.out.as_str()) {
        (Some(p), _) => Some(p.clone()),
        (None, "-") => None,
        (None, o) => Some(PathBuf::from(o).with_extension("png")),
    };
    let varying: Vec<usize> = (0..3).filter(|&a| axes[a].1.len() > 1).collect();
    if let Some(png) = png {
        if varying.len() != 2 {
            eprintln!(
                "note: no heat map: it needs exactly two of --j1, --j2, --j3 as ranges ({} given)",
                varying.len()
            );
            return Ok(());
        }
        let (ax, ay) = (varying[0], varying[1]);
        let (nx, ny) = (axes[ax].1.len(), axes[ay].1.len());
        // Re-index the grid as row-major over (ay, ax) with the third axis fixed.
        let index = |ix: usize, iy: usize| {
            let mut idx = [0usize; 3];
            idx[ax] = ix;
            idx[ay] = iy;
            idx[0] + n1 * (idx[1] + n2 * idx[2])
        };
        let fields: Vec<Field> = ["J4", "J5", "J6", "J7"]
            .iter()
            .enumerate()
            .map(|(c, name)| Field {
                name: name.to_string(),
                values: (0..nx * ny)
                    .map(|i| out[index(i % nx, i / nx)][c])
                    .collect(),
            })
            .collect();
        let fixed: Vec<String> = (0..3)
            .filter(|a| !varying.contains(a))
            .map(|a| format!("{} = {}", axes[a].0, axes[a].1[0]))
            .collect();
        write_heatmaps(
            &png,
            &format!("J+T {:?}, k = {}, {}", args.model, args.k, fixed.join(", ")),
            axes[ax].0,
            axes[ay].0,
            &axes[ax].1,
            &axes[ay].1,
            &fields,
        )
        .map_err(CliError::model)?;
        eprintln!("heat map: {}", png.display());
    }
    Ok(())
}
