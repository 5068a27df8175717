//! `traction field`: the elastic/plastic stress field Z = τ/τ̄ of one case on a
//! grid over the contact (CSV for plots of the flow pattern).
//!
//! Output columns `X,Y,Zx,Zy,state` (X = x/a along rolling, Y = y/b across,
//! cell centres of an nx × ny grid over [−1, 1]², state `outside`, `elastic`
//! or `plastic`; Z = 0 outside the contact ellipse). `--png PATH` also draws
//! heat maps of Zx, Zy, |Z|/L and the state.

use std::path::PathBuf;

use clap::Args;
use traction_reproduce::plot::{Field, write_heatmaps};
use traction_rheology::{Accuracy, Inputs, PointState, stress_field};

use crate::error::CliError;
use crate::table::{TableWriter, fmt_f64};

/// Arguments of `traction field`.
#[derive(Debug, Args)]
pub struct FieldArgs {
    /// Aspect ratio k = b/a (0.01..100).
    #[arg(long)]
    pub k: f64,
    /// Slip J1.
    #[arg(long = "j1", default_value_t = 0.0, allow_hyphen_values = true)]
    pub j1: f64,
    /// Side slip J2.
    #[arg(long = "j2", default_value_t = 0.0, allow_hyphen_values = true)]
    pub j2: f64,
    /// Spin J3.
    #[arg(long = "j3", default_value_t = 0.0, allow_hyphen_values = true)]
    pub j3: f64,
    /// Spin-pole offset ΔX.
    #[arg(long = "dx", default_value_t = 0.0, allow_hyphen_values = true)]
    pub dx: f64,
    /// Stiffness ratio gy = Ḡy/Ḡx (0.1..10).
    #[arg(long, default_value_t = 1.0)]
    pub gy: f64,
    /// Grid points along X (1..4000).
    #[arg(long, default_value_t = 101)]
    pub nx: usize,
    /// Grid points along Y (1..4000).
    #[arg(long, default_value_t = 101)]
    pub ny: usize,
    /// Accuracy of the strip integration (1e-9..0.1).
    #[arg(long, default_value_t = 1e-4)]
    pub tol: f64,
    /// Output CSV (`-` for stdout).
    #[arg(long, default_value = "-")]
    pub output: String,
    /// Also draw heat maps (Zx, Zy, |Z|/L, state) to this PNG.
    #[arg(long)]
    pub png: Option<PathBuf>,
}

/// Run the subcommand.
pub fn run(args: FieldArgs) -> Result<(), CliError> {
    let acc = Accuracy::new(args.tol).map_err(|e| CliError::Usage(format!("--tol: {e}")))?;
    let inp = Inputs::with_offset(args.k, args.j1, args.j2, args.j3, args.dx)
        .and_then(|i| i.with_stiffness_ratio(args.gy))
        .map_err(CliError::model)?;
    let f = stress_field(&inp, args.nx, args.ny, acc).map_err(CliError::model)?;
    let headers: Vec<String> = ["X", "Y", "Zx", "Zy", "state"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    let mut w = TableWriter::create(&args.output, &headers)?;
    for (j, &y) in f.y.iter().enumerate() {
        for (i, &x) in f.x.iter().enumerate() {
            let Some((zx, zy, s)) = f.at(i, j) else {
                continue;
            };
            let state = match s {
                PointState::Outside => "outside",
                PointState::Elastic => "elastic",
                PointState::Plastic => "plastic",
            };
            w.write_row(&[
                fmt_f64(x),
                fmt_f64(y),
                fmt_f64(zx),
                fmt_f64(zy),
                state.to_string(),
            ])?;
        }
    }
    w.finish()?;
    if let Some(png) = &args.png {
        // |Z|/L: 1 on the limit; state: 0 outside, 0.5 elastic, 1 plastic.
        let n = f.zx.len();
        let (mut ratio, mut state) = (vec![0.0; n], vec![0.0; n]);
        for q in 0..n {
            let (x, y) = (f.x[q % f.x.len()], f.y[q / f.x.len()]);
            let l = 1.5 * (1.0 - x * x - y * y).max(0.0).sqrt();
            match f.state[q] {
                PointState::Outside => {}
                s => {
                    ratio[q] = if l > 0.0 {
                        f.zx[q].hypot(f.zy[q]) / l
                    } else {
                        1.0
                    };
                    state[q] = if s == PointState::Plastic { 1.0 } else { 0.5 };
                }
            }
        }
        let fields = [
            ("Zx", f.zx.clone()),
            ("Zy", f.zy.clone()),
            ("|Z|/L", ratio),
            ("state (0 outside, 0.5 elastic, 1 plastic)", state),
        ]
        .map(|(name, values)| Field {
            name: name.to_string(),
            values,
        });
        write_heatmaps(
            png,
            &format!(
                "J+T stress field, k = {}, J = ({}, {}, {}), gy = {}",
                args.k, args.j1, args.j2, args.j3, args.gy
            ),
            "X = x/a (rolling)",
            "Y = y/b",
            &f.x,
            &f.y,
            &fields,
        )
        .map_err(CliError::model)?;
        eprintln!("heat map: {}", png.display());
    }
    Ok(())
}
