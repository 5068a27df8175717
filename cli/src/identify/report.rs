//! What `traction identify` reports besides the fitted values:
//! identifiability warnings, the summary on stderr, residuals and plots.

use std::fmt::Write as _;

use traction_contact::Evaluation;
use traction_regression::nls::Fit;

use super::problem::Problem;
use super::{MAX_CORRELATION, MAX_RELATIVE_STDERR};
use crate::error::CliError;
use crate::table::{Table, TableWriter, fmt_f64, output_headers};

/// A warning for every parameter that the data do not identify:
/// * the column-scaled Jacobian is rank deficient or nearly so (a singular
///   value ≤ 1e-6 of the largest): the parameters taking part in that
///   direction (|component| ≥ 0.3);
/// * a pair with |correlation| ≥ [`MAX_CORRELATION`];
/// * a standard error above [`MAX_RELATIVE_STDERR`] × max(|value|, scale).
pub fn diagnose(names: &[&str], scales: &[f64], fit: &Fit) -> Vec<String> {
    let mut w = Vec::new();
    for (ratio, v) in fit.weak_directions(1e-6) {
        let involved: Vec<String> = v
            .iter()
            .enumerate()
            .filter(|(_, c)| c.abs() >= 0.3)
            .map(|(j, c)| format!("{} ({c:+.2})", names[j]))
            .collect();
        w.push(format!(
            "not identifiable: the data do not determine the combination of {} \
             (singular value {ratio:.1e} of the largest, column-scaled Jacobian)",
            involved.join(", ")
        ));
    }
    if let (Some(corr), Some(se)) = (fit.correlation(), fit.standard_errors()) {
        let n = names.len();
        for i in 0..n {
            for j in i + 1..n {
                if corr[(i, j)].abs() >= MAX_CORRELATION {
                    w.push(format!(
                        "not identifiable separately: `{}` and `{}` are correlated {:+.4} \
                         (|correlation| ≥ {MAX_CORRELATION}); fix one of them",
                        names[i],
                        names[j],
                        corr[(i, j)]
                    ));
                }
            }
        }
        for j in 0..n {
            let reference = fit.x[j].abs().max(scales[j]);
            if se[j] > MAX_RELATIVE_STDERR * reference {
                w.push(format!(
                    "not identifiable: `{}` = {} has standard error {} (> {:.0} % of max(|value|, {})): \
                     the data do not determine it",
                    names[j],
                    fit.x[j],
                    se[j],
                    MAX_RELATIVE_STDERR * 100.0,
                    scales[j]
                ));
            }
        }
    } else if fit.variance.is_none() {
        w.push(format!(
            "no standard errors: {} residuals for {} parameters (need more residuals than parameters)",
            fit.residuals.len(),
            names.len()
        ));
    }
    w
}

/// The report on stderr: residuals, termination, conditioning, correlation.
pub(super) fn summary(
    table: &Table,
    problem: &Problem,
    fit: &Fit,
    names: &[&str],
    elapsed: f64,
    contact_evaluations: usize,
) -> String {
    let nfx = problem.index.iter().filter(|(_, w)| *w == 0).count();
    let mut s = String::new();
    let _ = writeln!(
        s,
        "identify: {}: {} rows, {} residuals ({nfx} fx_over_n, {} fy_over_n), {} parameters",
        table.source_name,
        problem.points.len(),
        problem.index.len(),
        problem.index.len() - nfx,
        names.len()
    );
    let _ = writeln!(
        s,
        "{}; {} iterations, {} model evaluations ({contact_evaluations} contact evaluations), {elapsed:.2} s",
        fit.termination.describe(),
        fit.iterations,
        fit.evaluations
    );
    let _ = writeln!(
        s,
        "rms residual: {:.6e} (traction coefficient); residual standard deviation s: {}",
        fit.rms,
        fit.variance
            .map_or("undefined".to_string(), |v| format!("{:.6e}", v.sqrt()))
    );
    let _ = writeln!(
        s,
        "condition number of the column-scaled Jacobian: {:.4e}",
        fit.condition_number
    );
    match fit.correlation() {
        Some(c) => {
            let _ = writeln!(s, "correlation matrix:");
            let _ = writeln!(s, ",{}", names.join(","));
            for (i, n) in names.iter().enumerate() {
                let row: Vec<String> = (0..names.len())
                    .map(|j| format!("{:.4}", c[(i, j)]))
                    .collect();
                let _ = writeln!(s, "{n},{}", row.join(","));
            }
        }
        None => {
            let _ = writeln!(s, "correlation matrix: undefined (no covariance)");
        }
    }
    s
}

/// The input rows with the model and the residuals appended.
pub(super) fn write_residuals(
    path: &str,
    table: &Table,
    problem: &Problem,
    model: &[Evaluation],
) -> Result<(), CliError> {
    let extra = [
        "fx_over_n_model",
        "fy_over_n_model",
        "fx_residual",
        "fy_residual",
    ];
    let mut w = TableWriter::create(path, &output_headers(table, &extra))?;
    for (i, (p, e)) in problem.points.iter().zip(model).enumerate() {
        let mut cells = table.rows[i].clone();
        cells.push(fmt_f64(e.traction_x));
        cells.push(fmt_f64(e.traction_y));
        cells.push(p.fx.map_or(String::new(), |v| fmt_f64(e.traction_x - v)));
        cells.push(p.fy.map_or(String::new(), |v| fmt_f64(e.traction_y - v)));
        w.write_row(&cells)?;
    }
    w.finish()
}

/// Fit and residual plots against each point's slip ratio (ΔU/U for
/// fx_over_n, ΔV/U for fy_over_n).
pub(super) fn plot(
    dir: &std::path::Path,
    problem: &Problem,
    model: &[Evaluation],
    fit: &Fit,
    names: &[&str],
) -> Result<(), CliError> {
    use traction_reproduce::tables::{Figure, Series, Style};
    std::fs::create_dir_all(dir).map_err(|source| CliError::Io {
        context: format!("creating {}", dir.display()),
        source,
    })?;
    let mut measured: [Vec<(f64, f64)>; 2] = [Vec::new(), Vec::new()];
    let mut fitted: [Vec<(f64, f64)>; 2] = [Vec::new(), Vec::new()];
    let mut resid: [Vec<(f64, f64)>; 2] = [Vec::new(), Vec::new()];
    for &(row, which) in &problem.index {
        let p = &problem.points[row];
        let u = p.state.rolling_speed;
        let (x, y, f) = if which == 0 {
            (p.state.slip / u, p.fx.unwrap_or(0.0), model[row].traction_x)
        } else {
            (
                p.state.side_slip / u,
                p.fy.unwrap_or(0.0),
                model[row].traction_y,
            )
        };
        if x.is_finite() {
            measured[which].push((x, y));
            fitted[which].push((x, f));
            resid[which].push((x, f - y));
        }
    }
    let label = ["Fx/N", "Fy/N"];
    let params: Vec<String> = names
        .iter()
        .zip(&fit.x)
        .map(|(n, v)| format!("{n} = {v:.4}"))
        .collect();
    let mut fit_series = Vec::new();
    let mut res_series = Vec::new();
    for w in 0..2 {
        if measured[w].is_empty() {
            continue;
        }
        fit_series.push(Series {
            name: format!("{} measured", label[w]),
            style: Style::Circles,
            color: 2 * w,
            points: measured[w].clone(),
        });
        fit_series.push(Series {
            name: format!("{} fitted model", label[w]),
            style: Style::Crosses,
            color: 2 * w + 1,
            points: fitted[w].clone(),
        });
        res_series.push(Series {
            name: format!("{} model − measured", label[w]),
            style: Style::Circles,
            color: 2 * w,
            points: resid[w].clone(),
        });
    }
    let x_label = "slip ratio ΔU/U (Fx/N) or ΔV/U (Fy/N)".to_string();
    let figures = [
        Figure {
            id: "identify-fit".into(),
            title: format!("traction identify: {}", params.join(", ")),
            x_label: x_label.clone(),
            y_label: "traction coefficient".into(),
            series: fit_series,
        },
        Figure {
            id: "identify-residuals".into(),
            title: format!("traction identify: residuals, RMS {:.3e}", fit.rms),
            x_label,
            y_label: "residual (model − measured)".into(),
            series: res_series,
        },
    ];
    for f in &figures {
        traction_reproduce::plot::write_figure(f, dir).map_err(CliError::model)?;
    }
    Ok(())
}
