//! `traction kinematics`: contact kinematics in batch from CSV.
//!
//! Two forms, chosen with `--form` (default: detected from the header — a `ry`
//! column means twin disc, a `w1x` column means general):
//!
//! **twin-disc** (report section 2-2, 2-3). Columns: `alpha` (tilt, rad), `ry`
//! (transverse radius R_y, m), `e` (signed centre offset, m). Optional:
//! `beta` (skew, rad) → side-slip ratio (eq. 3); `c` (contact-size factor
//! a/P0, m/Pa) and `k` (b/a) → spin factor C'' (eq. 7, 1/Pa); plus `p0` (Pa) →
//! Z = C''·P0; plus `m`, `mu` → J2 (needs `beta`) and J3.
//! Output columns: `rolling_radius` (m), `omega_per_u` (1/m), `side_slip_ratio`,
//! `c_double_prime` (1/Pa), `z`, `j2`, `j3`; a cell is empty when its optional
//! inputs are absent.
//!
//! **general** (rigid bodies, sign conventions of `traction-kinematics`):
//! columns `w1x,w1y,w1z` (Ω of body 1, rad/s), `p1x,p1y,p1z` (point on its axis,
//! m), optional `v1x,v1y,v1z` (velocity of that point, m/s), the same with `2`,
//! the contact point `cx,cy,cz` (m), the normal `nx,ny,nz` (from body 2 into
//! body 1) and the rolling direction `tx,ty,tz`; optional `a`, `b` (m) for Z and ε.
//! Output: `v1x_s,v1y_s,v1z_s,v2x_s,v2y_s,v2z_s` (surface velocities, m/s), `u`,
//! `du`, `dv` (m/s), `omega` (rad/s), `approach` (m/s), `du_u`, `dv_u`,
//! `omega_per_u` (1/m), `z`, `epsilon` (empty without `a`, `b`; ε empty when ω = 0).
//! A row with zero rolling speed is an error (the ratios to U are undefined).

use clap::{Args, ValueEnum};
use traction_kinematics::{
    BodyMotion, Vector3, contact_kinematics, j2, j3, side_slip_ratio, spin_factor, spin_group,
    tilted_disc_rolling_radius, tilted_disc_spin_per_speed,
};

use crate::error::CliError;
use crate::table::{Table, TableWriter, fmt_f64, output_headers};

/// Which input form.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Form {
    /// The report's tilted/skewed twin-disc rig (equations 3, 6, 7).
    TwinDisc,
    /// Two rigid bodies in 3-D.
    General,
}

/// Arguments of `traction kinematics`.
#[derive(Debug, Args)]
pub struct KinematicsArgs {
    /// Input CSV (`-` for stdin). See `traction kinematics --help` for columns.
    #[arg(long, default_value = "-")]
    pub input: String,
    /// Output CSV (`-` for stdout): input columns followed by the results.
    #[arg(long, default_value = "-")]
    pub output: String,
    /// Input form; detected from the header when omitted.
    #[arg(long, value_enum)]
    pub form: Option<Form>,
}

const TWIN_IN: [&str; 3] = ["alpha", "ry", "e"];
const TWIN_OUT: [&str; 7] = [
    "rolling_radius",
    "omega_per_u",
    "side_slip_ratio",
    "c_double_prime",
    "z",
    "j2",
    "j3",
];
const GEN_IN: [&str; 21] = [
    "w1x", "w1y", "w1z", "p1x", "p1y", "p1z", "w2x", "w2y", "w2z", "p2x", "p2y", "p2z", "cx", "cy",
    "cz", "nx", "ny", "nz", "tx", "ty", "tz",
];
const GEN_OUT: [&str; 16] = [
    "v1x_s",
    "v1y_s",
    "v1z_s",
    "v2x_s",
    "v2y_s",
    "v2z_s",
    "u",
    "du",
    "dv",
    "omega",
    "approach",
    "du_u",
    "dv_u",
    "omega_per_u",
    "z",
    "epsilon",
];

fn opt(v: Option<f64>) -> String {
    v.map(fmt_f64).unwrap_or_default()
}

fn twin_row(t: &Table, row: usize) -> Result<Vec<String>, CliError> {
    let alpha = t.f64(row, "alpha")?;
    let ry = t.f64(row, "ry")?;
    let e = t.f64(row, "e")?;
    let r = tilted_disc_rolling_radius(alpha, ry, e).map_err(|err| t.row_error(row, err))?;
    let w = tilted_disc_spin_per_speed(alpha, ry, e).map_err(|err| t.row_error(row, err))?;
    let dv_u = match t.opt_f64(row, "beta")? {
        Some(beta) => {
            Some(side_slip_ratio(beta).map_err(|err| t.cell_error(row, "beta", err.to_string()))?)
        }
        None => None,
    };
    let (c, k, p0) = (
        t.opt_f64(row, "c")?,
        t.opt_f64(row, "k")?,
        t.opt_f64(row, "p0")?,
    );
    let c2 = match (c, k) {
        (Some(c), Some(k)) => Some(spin_factor(w, c, k).map_err(|err| t.row_error(row, err))?),
        _ => None,
    };
    let z = match (c2, p0) {
        (Some(c2), Some(p0)) => Some(spin_group(c2, p0).map_err(|err| t.row_error(row, err))?),
        _ => None,
    };
    let (m, mu) = (t.opt_f64(row, "m")?, t.opt_f64(row, "mu")?);
    let (mut jj2, mut jj3) = (None, None);
    if let (Some(m), Some(mu), Some(k)) = (m, mu, k) {
        if let Some(dv_u) = dv_u {
            jj2 = Some(j2(m, mu, k, dv_u).map_err(|err| t.row_error(row, err))?);
        }
        if let Some(z) = z {
            jj3 = Some(j3(m, mu, k, z).map_err(|err| t.row_error(row, err))?);
        }
    }
    Ok(vec![
        fmt_f64(r),
        fmt_f64(w),
        opt(dv_u),
        opt(c2),
        opt(z),
        opt(jj2),
        opt(jj3),
    ])
}

fn vec3(t: &Table, row: usize, names: [&str; 3]) -> Result<Vector3<f64>, CliError> {
    Ok(Vector3::new(
        t.f64(row, names[0])?,
        t.f64(row, names[1])?,
        t.f64(row, names[2])?,
    ))
}

fn opt_vec3(t: &Table, row: usize, names: [&str; 3]) -> Result<Vector3<f64>, CliError> {
    Ok(Vector3::new(
        t.opt_f64(row, names[0])?.unwrap_or(0.0),
        t.opt_f64(row, names[1])?.unwrap_or(0.0),
        t.opt_f64(row, names[2])?.unwrap_or(0.0),
    ))
}

fn general_row(t: &Table, row: usize) -> Result<Vec<String>, CliError> {
    let body = |i: &str| -> Result<BodyMotion, CliError> {
        let n = |s: &str| format!("{s}{i}");
        let (wx, wy, wz) = (n("w") + "x", n("w") + "y", n("w") + "z");
        let (px, py, pz) = (n("p") + "x", n("p") + "y", n("p") + "z");
        let (vx, vy, vz) = (n("v") + "x", n("v") + "y", n("v") + "z");
        Ok(BodyMotion {
            angular_velocity: vec3(t, row, [&wx, &wy, &wz])?,
            axis_point: vec3(t, row, [&px, &py, &pz])?,
            velocity: opt_vec3(t, row, [&vx, &vy, &vz])?,
        })
    };
    let (b1, b2) = (body("1")?, body("2")?);
    let k = contact_kinematics(
        &b1,
        &b2,
        vec3(t, row, ["cx", "cy", "cz"])?,
        vec3(t, row, ["nx", "ny", "nz"])?,
        vec3(t, row, ["tx", "ty", "tz"])?,
    )
    .map_err(|err| t.row_error(row, err))?;
    let re = |err| t.row_error(row, err);
    let du_u = k.slip_ratio().map_err(re)?;
    let dv_u = k.side_slip_ratio().map_err(re)?;
    let w_u = k.spin_per_speed().map_err(re)?;
    let (z, eps) = match (t.opt_f64(row, "a")?, t.opt_f64(row, "b")?) {
        (Some(a), Some(b)) => {
            let z = k.spin_group(a, b).map_err(re)?;
            let eps = if k.spin == 0.0 {
                None
            } else {
                Some(k.speed_pole(a, b).map_err(re)?)
            };
            (Some(z), eps)
        }
        _ => (None, None),
    };
    let (v1, v2) = (k.surface_velocity_1, k.surface_velocity_2);
    let mut out: Vec<String> = [v1.x, v1.y, v1.z, v2.x, v2.y, v2.z, k.rolling_speed, k.slip]
        .into_iter()
        .map(fmt_f64)
        .collect();
    out.extend([k.side_slip, k.spin, k.approach, du_u, dv_u, w_u].map(fmt_f64));
    out.push(opt(z));
    out.push(opt(eps));
    Ok(out)
}

/// Run the subcommand.
pub fn run(args: KinematicsArgs) -> Result<(), CliError> {
    let table = Table::read(&args.input)?;
    let form = match args.form {
        Some(f) => f,
        None if table.has("ry") => Form::TwinDisc,
        None if table.has("w1x") => Form::General,
        None => {
            return Err(CliError::Usage(format!(
                "{}: cannot tell the form from the header: twin-disc needs columns {}, general needs {} (or pass --form)",
                table.source_name,
                TWIN_IN.join(","),
                GEN_IN.join(",")
            )));
        }
    };
    let (required, extra): (&[&str], &[&str]) = match form {
        Form::TwinDisc => (&TWIN_IN, &TWIN_OUT),
        Form::General => (&GEN_IN, &GEN_OUT),
    };
    table.require(required)?;
    // Compute every row first: a bad row leaves no partial output.
    let mut out = Vec::with_capacity(table.len());
    for row in 0..table.len() {
        let mut cells = table.rows[row].clone();
        cells.extend(match form {
            Form::TwinDisc => twin_row(&table, row)?,
            Form::General => general_row(&table, row)?,
        });
        out.push(cells);
    }
    let mut w = TableWriter::create(&args.output, &output_headers(&table, extra))?;
    for cells in &out {
        w.write_row(cells)?;
    }
    w.finish()
}
