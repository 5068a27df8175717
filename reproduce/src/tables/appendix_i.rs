//! Appendix I: the reduced traction traces (figure 3-3).

use traction_kinematics::j2 as j2_group;
use traction_rheology::closed;

use super::{Figure, Reproduced, Series, Style, model_err, row, tol};
use crate::{Deviation, FigureKind, ReproduceError, TableResult};

struct TraceI {
    trace: String,
    k: f64,
    m: f64,
    mu: f64,
    dv_u: f64,
    js: f64,
    j5: f64,
}

fn appendix_i_rows() -> Result<Vec<TraceI>, ReproduceError> {
    // The curated copy in traction-fluids (`fluids/data/appendix_i_traces.csv`,
    // with its OCR corrections checked by column consistency).
    let points =
        traction_fluids::appendix_i_traces().map_err(|e| model_err("Appendix I data", e))?;
    Ok(points
        .into_iter()
        .map(|p| TraceI {
            trace: p.trace,
            k: p.k,
            m: p.m,
            mu: p.mu,
            dv_u: p.dv_over_u,
            js: p.js,
            j5: p.j5,
        })
        .collect())
}

/// Appendix I, printed reduced slip JS recomputed from m, μ, ΔV/U (relative).
pub fn appendix_i_js() -> Result<TableResult, ReproduceError> {
    let mut rows = Vec::new();
    for r in appendix_i_rows()? {
        let j2 = j2_group(r.m, r.mu, r.k, r.dv_u).map_err(|e| model_err("Appendix I J2", e))?;
        let mut x = row(
            &r.trace,
            format!("{} dV/U={}", r.trace, r.dv_u),
            r.dv_u,
            j2 / r.k.sqrt(),
            Some(r.js),
        );
        x.tol = Some(1e-6);
        rows.push(x);
    }
    Ok(TableResult {
        id: "appendix-i-js".into(),
        title: "Appendix I (JS)".into(),
        quantity: "reduced slip JS = J2/√k = (3π/8)(m/μ)(ΔV/U) = (3/2)·S of eq. 9 (-)".into(),
        deviation: Deviation::Relative,
        rows,
        tolerance: Some(tol(
            "1e-6 relative",
            "printed to 9 digits by a single-precision program (~7 digits), as the Appendix VI J3 check",
            "kinematics_tables::appendix_vi_dimensionless_spin_and_side_slip (same rule; Appendix I has no golden test of its own)",
        )),
        missing: vec![],
        figure: FigureKind::None,
    })
}

/// Appendix I / figure 3-3: eq. 8 J5 = ψ(S) at the printed reduced slip
/// against the measured reduced side force. The report prints no theory column.
pub fn appendix_i() -> Result<Reproduced, ReproduceError> {
    let data = appendix_i_rows()?;
    let mut rows = Vec::new();
    let mut series: Vec<Series> = Vec::new();
    for r in &data {
        let s = (2.0 / 3.0) * r.js;
        let mut x = row(
            &r.trace,
            format!("{} dV/U={}", r.trace, r.dv_u),
            s,
            closed::psi(s),
            None,
        );
        x.measured = Some(r.j5);
        rows.push(x);
        let n = series.len();
        match series.iter_mut().find(|q| q.name.starts_with(&r.trace)) {
            Some(q) => q.points.push((s, r.j5)),
            None => series.push(Series {
                name: format!("{} (k={}, m={}, μ={})", r.trace, r.k, r.m, r.mu),
                style: Style::Circles,
                color: n + 1,
                points: vec![(s, r.j5)],
            }),
        }
    }
    let smax = rows.iter().map(|r| r.x).fold(0.0, f64::max);
    let curve: Vec<(f64, f64)> = (0..=200)
        .map(|i| {
            let s = smax * i as f64 / 200.0;
            (s, closed::psi(s))
        })
        .collect();
    series.insert(
        0,
        Series {
            name: "eq. 8: J5 = ψ(S) (computed)".into(),
            style: Style::Line,
            color: 0,
            points: curve,
        },
    );
    let fig = Figure {
        id: "fig-3-3".into(),
        title: "Figure 3-3: eight Appendix I traces reduced to J5(S), eq. 8".into(),
        x_label: "S = (π/4)(m/μ)(ΔV/U)".into(),
        y_label: "J5 = Fy/(Fz·μ)".into(),
        series,
    };
    crate::thermal::attach_appendix_i(&mut rows)?;
    Ok(Reproduced {
        table: TableResult {
            id: "appendix-i".into(),
            title: "Appendix I (J5 vs S, fig. 3-3)".into(),
            quantity: "reduced side force J5 = ψ(S), eq. 8, at S = (2/3)·JS, against the measured J5 = (Fy/Fz)/μ (-)".into(),
            deviation: Deviation::Absolute,
            rows,
            tolerance: None,
            missing: vec![
                "printed theory: the report prints no theory J5 in Appendix I (only the measured reduced values); compared with measurements only".into(),
            ],
            figure: FigureKind::ReducedTraces,
        },
        figures: vec![fig],
    })
}
