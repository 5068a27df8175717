//! `traction curve`: a traction-vs-slip curve of one dimensional contact.
//!
//! The contact (radii, materials, fluid) and the operating state (load or P0,
//! rolling speed, fixed side slip / slip / spin) are given as flags; the slip
//! ratio in the chosen direction (`--direction longitudinal`: ΔU/U, `side`:
//! ΔV/U) is swept linearly from `--from` to `--to` in `--points` points. The
//! output CSV (`-` = stdout) has the columns `slip_ratio,u,du,dv,omega,fx,fy,
//! mz,traction_x,traction_y,loss,a,b,k,p0,m_used,mu_used,J1,J2,J3,J4,J5,J6,J7,
//! regime` in SI units.

use clap::{Args, ValueEnum};
use traction_contact::{Body, Fluid, OperatingState, TractionContact};

use crate::contact::{ModelOptions, report_fluid};
use crate::error::{CliError, chain};
use crate::table::{TableWriter, fmt_f64, radius};
use traction_hertz::Range;

/// Which slip ratio is swept.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SweepDirection {
    /// Longitudinal slip ΔU/U.
    Longitudinal,
    /// Side slip ΔV/U.
    Side,
}

/// Arguments of `traction curve`.
#[derive(Debug, Args)]
pub struct CurveArgs {
    /// Radius of body 1 along the rolling direction x (m; `inf` or 0 = flat).
    #[arg(long)]
    pub rx1: f64,
    /// Radius of body 1 across x (m).
    #[arg(long)]
    pub ry1: f64,
    /// Radius of body 2 along x (m).
    #[arg(long)]
    pub rx2: f64,
    /// Radius of body 2 across x (m).
    #[arg(long, default_value_t = f64::INFINITY)]
    pub ry2: f64,
    /// Young's modulus of both bodies (Pa).
    #[arg(long, default_value_t = 210e9)]
    pub e: f64,
    /// Poisson's ratio of both bodies.
    #[arg(long, default_value_t = 0.3)]
    pub nu: f64,
    /// Normal load (N); or give --p0.
    #[arg(long, conflicts_with = "p0")]
    pub load: Option<f64>,
    /// Maximum Hertz pressure (Pa); the load follows from Hertz theory.
    #[arg(long)]
    pub p0: Option<f64>,
    /// Rolling speed U (m/s).
    #[arg(long)]
    pub u: f64,
    /// Inlet temperature θ (°C).
    #[arg(long, default_value_t = 70.0)]
    pub theta: f64,
    /// Report fluid: santotrac-50 or tdf-88 (else give --m and --mu).
    #[arg(long, conflicts_with_all = ["m", "mu"])]
    pub fluid: Option<String>,
    /// User traction slope m.
    #[arg(long)]
    pub m: Option<f64>,
    /// User peak traction coefficient μ.
    #[arg(long)]
    pub mu: Option<f64>,
    /// Swept slip direction.
    #[arg(long, value_enum, default_value_t = SweepDirection::Longitudinal)]
    pub direction: SweepDirection,
    /// First slip ratio of the sweep.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub from: f64,
    /// Last slip ratio of the sweep.
    #[arg(long, default_value_t = 0.02, allow_negative_numbers = true)]
    pub to: f64,
    /// Number of points (2..=100000).
    #[arg(long, default_value_t = 41)]
    pub points: usize,
    /// Fixed ratio of the other direction (ΔV/U when sweeping longitudinal, ΔU/U when side).
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub other: f64,
    /// Spin ω (rad/s).
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub omega: f64,
    /// Output CSV (`-` for stdout).
    #[arg(long, default_value = "-")]
    pub output: String,
    /// Also plot the curve (Fx/N and Fy/N against the slip ratio) as `curve.png`
    /// and `curve.svg` in this directory (created if missing).
    #[arg(long)]
    pub plot: Option<std::path::PathBuf>,
    /// Model options.
    #[command(flatten)]
    pub model: ModelOptions,
}

const COLUMNS: [&str; 25] = [
    "slip_ratio",
    "u",
    "du",
    "dv",
    "omega",
    "fx",
    "fy",
    "mz",
    "traction_x",
    "traction_y",
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
];

/// Valid number of curve points: at least a segment, at most what a plot or a
/// spreadsheet reads comfortably.
const POINTS_RANGE: Range = Range::closed(2.0, 100_000.0);

/// Run the subcommand.
pub fn run(args: CurveArgs) -> Result<(), CliError> {
    POINTS_RANGE
        .check("--points", args.points as f64)
        .map_err(CliError::model)?;
    for (name, v) in [
        ("--from", args.from),
        ("--to", args.to),
        ("--other", args.other),
    ] {
        Range::FINITE.check(name, v).map_err(CliError::model)?;
    }
    let opts = args.model.options().map_err(CliError::Usage)?;
    let fluid = match (&args.fluid, args.m, args.mu) {
        (Some(name), _, _) => {
            report_fluid(name, args.model.rule(), args.model.spin_peak).map_err(CliError::Usage)?
        }
        (None, Some(m), Some(mu)) => Fluid::constant(m, mu).map_err(CliError::model)?,
        _ => {
            return Err(CliError::Usage(
                "no fluid: give --fluid santotrac-50|tdf-88, or both --m and --mu".into(),
            ));
        }
    };
    let b1 = Body::new(radius(args.rx1), radius(args.ry1), args.e, args.nu);
    let b2 = Body::new(radius(args.rx2), radius(args.ry2), args.e, args.nu);
    let contact = TractionContact::new(&b1, &b2, fluid, opts).map_err(CliError::model)?;
    let load = match (args.load, args.p0) {
        (Some(n), None) => n,
        (None, Some(p0)) => {
            contact
                .geometry()
                .at_p0(p0)
                .map_err(|e| CliError::Usage(format!("--p0: {e}")))?
                .load
        }
        _ => return Err(CliError::Usage("give --load (N) or --p0 (Pa)".into())),
    };
    let mut rows = Vec::with_capacity(args.points);
    let mut fx_curve = Vec::with_capacity(args.points);
    let mut fy_curve = Vec::with_capacity(args.points);
    for i in 0..args.points {
        let t = i as f64 / (args.points - 1) as f64;
        let ratio = args.from + t * (args.to - args.from);
        let (du, dv) = match args.direction {
            SweepDirection::Longitudinal => (ratio * args.u, args.other * args.u),
            SweepDirection::Side => (args.other * args.u, ratio * args.u),
        };
        let state = OperatingState::new(load, args.u, du, dv, args.omega, args.theta)
            .map_err(CliError::model)?;
        let e = contact.evaluate(&state).map_err(|e| {
            CliError::Model(format!(
                "point {} (slip ratio {ratio}): {}",
                i + 1,
                chain(&e)
            ))
        })?;
        let mut cells: Vec<String> = [ratio, args.u, du, dv, args.omega]
            .into_iter()
            .map(fmt_f64)
            .collect();
        cells.extend(
            [
                e.fx,
                e.fy,
                e.mz,
                e.traction_x,
                e.traction_y,
                e.loss,
                e.a,
                e.b,
                e.k,
                e.p0,
            ]
            .into_iter()
            .chain([
                e.m_used, e.mu_used, e.j1, e.j2, e.j3, e.j4, e.j5, e.j6, e.j7,
            ])
            .map(fmt_f64),
        );
        cells.push(e.regime.name().to_string());
        rows.push(cells);
        fx_curve.push((ratio, e.traction_x));
        fy_curve.push((ratio, e.traction_y));
    }
    if let Some(dir) = &args.plot {
        plot_curve(&args, dir, fx_curve, fy_curve)?;
    }
    let headers: Vec<String> = COLUMNS.iter().map(|s| s.to_string()).collect();
    let mut w = TableWriter::create(&args.output, &headers)?;
    for r in &rows {
        w.write_row(r)?;
    }
    w.finish()
}

/// Draw the traction curve with the report-style plotting of `traction reproduce`.
fn plot_curve(
    args: &CurveArgs,
    dir: &std::path::Path,
    fx: Vec<(f64, f64)>,
    fy: Vec<(f64, f64)>,
) -> Result<(), CliError> {
    use traction_reproduce::tables::{Figure, Series, Style};
    std::fs::create_dir_all(dir).map_err(|source| CliError::Io {
        context: format!("creating {}", dir.display()),
        source,
    })?;
    let swept = match args.direction {
        SweepDirection::Longitudinal => "slip ΔU/U",
        SweepDirection::Side => "side slip ΔV/U",
    };
    let fig = Figure {
        id: "curve".into(),
        title: format!(
            "traction curve: U = {} m/s, θ = {} °C, ω = {} rad/s",
            args.u, args.theta, args.omega
        ),
        x_label: swept.into(),
        y_label: "traction coefficient".into(),
        series: vec![
            Series {
                name: "Fx/N".into(),
                style: Style::Line,
                color: 0,
                points: fx,
            },
            Series {
                name: "Fy/N".into(),
                style: Style::Line,
                color: 2,
                points: fy,
            },
        ],
    };
    traction_reproduce::plot::write_figure(&fig, dir).map_err(CliError::model)
}
