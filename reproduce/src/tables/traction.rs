//! Appendices VI, VII-A, VII-B: the J+T model's traction curves under spin,
//! side slip and combined slip (figures 4-1..4-16).

use rayon::prelude::*;
use traction_kinematics::j2 as j2_group;
use traction_rheology::{Accuracy, Inputs, Model, closed, evaluate};

use super::{Figure, Reproduced, Series, Style, model_err, row, theory_printed_measured, tol};
use crate::data::{APPENDIX_VI, APPENDIX_VII_A, APPENDIX_VII_B, DataTable};
use crate::{Deviation, FigureKind, ReproduceError, Row, TableResult, Tolerance};

/// Figures of Appendix VI traces: trace id → report figure and caption.
fn vi_figure(trace: &str) -> (&'static str, &'static str) {
    match trace {
        "79072704" => (
            "fig-4-1",
            "Figure 4-1: Santotrac 50, 80 m/s, 1.45 GPa, 73 °C, k = 5, 30° spin",
        ),
        "79100403-U20" => (
            "fig-4-2",
            "Figure 4-2: TDF-88, 20 m/s, 1.0 GPa, 50 °C, k = 5, 15° spin",
        ),
        "79072601" => (
            "fig-4-4",
            "Figure 4-4: Santotrac 50, 20 m/s, 1.22 GPa, 32.5 °C, k = 1 printed (k = 5 discs), 15° spin",
        ),
        "79100403" => (
            "fig-4-6",
            "Figure 4-6: TDF-88, 80 m/s, 1.0 GPa, 50 °C, k = 5, 15° spin",
        ),
        // Traces whose measurements the data file does not hold (held out);
        // their figures are drawn when their rows are added to it.
        "80062306" => (
            "fig-4-3",
            "Figure 4-3: Santotrac 50, 20 m/s, 1.9 GPa, 70 °C, k = 1, 6° spin",
        ),
        "80051402" => (
            "fig-4-5",
            "Figure 4-5: TDF-88, 20 m/s, 1.9 GPa, 70 °C, k = 1, 6° spin",
        ),
        "79111902" => (
            "fig-4-7",
            "Figure 4-7: TDF-88, 30 m/s, 1.45 GPa, 29 °C, k = 1, 6° spin",
        ),
        "80062801" => (
            "fig-4-8",
            "Figure 4-8: Santotrac 50, 20 m/s, 1.0 GPa, 70 °C, k = 5, 6° spin",
        ),
        _ => ("fig-4-x", "Appendix VI trace"),
    }
}

/// Accuracy of the J+T strip integration for Appendix VI, as in the golden test.
pub const VI_TOL: f64 = 1e-3;

/// Appendix VI: largest allowed |J5 − printed J5|. The converged model differs
/// from the printed J5 by up to 0.09 at small J2 for k = 1 (J3 = 2.28), where
/// the report's unpublished program is evidently under-resolved.
pub const VI_MAX_DEV: f64 = 0.1;

/// Appendix VI: allowed RMS of J5 − printed J5 over the 70 points.
pub const VI_RMS_DEV: f64 = 0.04;

/// Appendix VII-A: allowed |J5 − printed J5|. J5 is printed to 3 decimals
/// (±0.0005) from J2 printed to 3 decimals (J2 ±0.0005 moves J5 by ≤ 0.0006).
pub const VII_A_TOL: f64 = 0.0015;

/// Appendix VII-B: allowed |J4 − printed J4| (rows printed as Fx/N: this
/// times μ plus half a unit of the printed third decimal). Printed rounding,
/// J1 printed to 2-3 digits (≤ 0.002 in J4) and the report's own integration
/// plateau at k = 0.5 set A (0.993 printed where eq. 23 gives up to 0.9997).
pub const VII_B_TOL: f64 = 0.0075;

/// Appendix VI: spin traces (J1 = 0), both rolling directions; J5 against the
/// printed theory J5 and the measured (Fy/Fz)/μ_spin.
pub fn appendix_vi() -> Result<Reproduced, ReproduceError> {
    let t = DataTable::parse("appendix_vi_spin_traces.csv", APPENDIX_VI)?;
    let c = |n| t.col(n);
    let (ct, ck, cm, cmu, cms, cj3, cdir, cdv, cfy, cj2, cj5) = (
        c("trace")?,
        c("k")?,
        c("m")?,
        c("mu")?,
        c("mu_spin")?,
        c("J3")?,
        c("direction")?,
        c("dV_U")?,
        c("FyFz_exp")?,
        c("J2")?,
        c("J5")?,
    );
    let acc = Accuracy::new(VI_TOL).map_err(|e| model_err("accuracy", e))?;
    let mut rows: Vec<Row> = (0..t.rows.len())
        .into_par_iter()
        .map(|i| {
            let (k, j3, j2, printed) = (
                t.num(i, ck)?,
                t.num(i, cj3)?,
                t.num(i, cj2)?,
                t.num(i, cj5)?,
            );
            let ms = t.num(i, cms)?;
            let inp = Inputs::new(k, 0.0, j2, j3).map_err(|e| model_err("Appendix VI", e))?;
            let o = evaluate(&inp, Model::ElasticPlastic, acc)
                .map_err(|e| model_err("Appendix VI", e))?;
            let mut r = row(
                &format!("{} {}", t.str(i, ct), t.str(i, cdir)),
                format!("{} {} dV/U={}", t.str(i, ct), t.str(i, cdir), t.str(i, cdv)),
                t.num(i, cdv)?,
                o.j5,
                Some(printed),
            );
            r.measured = Some(t.num(i, cfy)? / ms);
            r.tol = Some(VI_MAX_DEV);
            Ok(r)
        })
        .collect::<Result<_, ReproduceError>>()?;
    // Figures: one per trace, Fy/Fz against ΔV/U; the negative rolling direction
    // is plotted at −ΔV/U as the report does (its ΔV/U already carries the sign).
    let mut traces: Vec<String> = Vec::new();
    for i in 0..t.rows.len() {
        let tr = t.str(i, ct).to_string();
        if !traces.contains(&tr) {
            traces.push(tr);
        }
    }
    let mut figures = traces
        .par_iter()
        .map(|tr| {
            let idx: Vec<usize> = (0..t.rows.len()).filter(|&i| t.str(i, ct) == tr).collect();
            let i0 = idx[0];
            let (k, m, mu, ms, j3) = (
                t.num(i0, ck)?,
                t.num(i0, cm)?,
                t.num(i0, cmu)?,
                t.num(i0, cms)?,
                t.num(i0, cj3)?,
            );
            let mut dmax = 0.0_f64;
            for &i in &idx {
                dmax = dmax.max(t.num(i, cdv)?.abs());
            }
            let n = 40;
            let line: Vec<(f64, f64)> = (-n..=n)
                .map(|j| {
                    let dv = dmax * j as f64 / n as f64;
                    let j2 = j2_group(m, mu, k, dv).map_err(|e| model_err("Appendix VI J2", e))?;
                    let inp =
                        Inputs::new(k, 0.0, j2, j3).map_err(|e| model_err("Appendix VI", e))?;
                    let o = evaluate(&inp, Model::ElasticPlastic, acc)
                        .map_err(|e| model_err("Appendix VI", e))?;
                    Ok((dv, o.j5 * ms))
                })
                .collect::<Result<_, ReproduceError>>()?;
            let mut printed = Vec::new();
            let mut measured = Vec::new();
            for &i in &idx {
                let dv = t.num(i, cdv)?;
                printed.push((dv, t.num(i, cj5)? * ms));
                measured.push((dv, t.num(i, cfy)?));
            }
            let (id, title) = vi_figure(tr);
            Ok(Figure {
                id: id.to_string(),
                title: format!(
                    "{title} (trace {tr}, m = {m}, μ = {mu}, μ spin = {ms}, J3 = {j3:.3})"
                ),
                x_label: "side slip ΔV/U".into(),
                y_label: "traction coefficient Fy/Fz".into(),
                series: theory_printed_measured(
                    "J+T elastic/plastic, J5·μ_spin (computed)",
                    line,
                    "printed theory (App. VI)",
                    printed,
                    measured,
                ),
            })
        })
        .collect::<Result<Vec<Figure>, ReproduceError>>()?;
    crate::thermal::attach_appendix_vi(&mut rows)?;
    crate::thermal::appendix_vi_series(&mut figures)?;
    let ct = t.col("trace")?;
    let missing: Vec<String> = ["79111902", "80051402", "80062306", "80062801"]
        .into_iter()
        .filter(|held| !(0..t.rows.len()).any(|i| t.str(i, ct) == *held))
        .map(|held| {
            let (fig, _) = vi_figure(held);
            format!("trace {held} ({fig}): held out, not in the curated data")
        })
        .collect();
    Ok(Reproduced {
        table: TableResult {
            id: "appendix-vi".into(),
            title: "Appendix VI (spin traces)".into(),
            quantity: "side force J5 = Fy/(Fz·μ) under spin and side slip (J1 = 0), J+T elastic/plastic at tol 1e-3; measured J5 = (Fy/Fz)/μ_spin (-)".into(),
            deviation: Deviation::Absolute,
            rows,
            tolerance: Some(Tolerance {
                per_value: format!("{VI_MAX_DEV} absolute"),
                rms: Some(VI_RMS_DEV),
                allowed_exceptions: 0,
                justification: "the converged model differs from the printed J5 by up to 0.09 at small J2 for k = 1 (J3 = 2.28), where the report's unpublished program is evidently under-resolved".into(),
                golden_test: "rheology_appendix::appendix_vi_spin_traces".into(),
            }),
            missing,
            figure: FigureKind::SpinTraces,
        },
        figures,
    })
}

/// Appendix VII-A: side slip, zero spin; J5 against printed and measured J5.
pub fn appendix_vii_a() -> Result<Reproduced, ReproduceError> {
    let t = DataTable::parse("appendix_vii_a_side_slip.csv", APPENDIX_VII_A)?;
    let c = |n| t.col(n);
    let (ck, cm, cmu, cdv, cj2, cact, cthy) = (
        c("k")?,
        c("m")?,
        c("mu")?,
        c("dV_U")?,
        c("J2")?,
        c("J5_act")?,
        c("J5_thy")?,
    );
    let acc = Accuracy::new(1e-9).map_err(|e| model_err("accuracy", e))?;
    let mut rows = Vec::new();
    for i in 0..t.rows.len() {
        let (k, j2) = (t.num(i, ck)?, t.num(i, cj2)?);
        let inp = Inputs::new(k, 0.0, j2, 0.0).map_err(|e| model_err("Appendix VII-A", e))?;
        let o = evaluate(&inp, Model::ElasticPlastic, acc)
            .map_err(|e| model_err("Appendix VII-A", e))?;
        let mut r = row(
            &format!("k={k}"),
            format!("k={k} J2={j2}"),
            t.num(i, cdv)?,
            o.j5,
            Some(t.num(i, cthy)?),
        );
        r.measured = Some(t.num(i, cact)?);
        r.tol = Some(VII_A_TOL);
        rows.push(r);
    }
    let mut figures = Vec::new();
    let mut ks: Vec<f64> = Vec::new();
    for i in 0..t.rows.len() {
        let k = t.num(i, ck)?;
        if !ks.contains(&k) {
            ks.push(k);
        }
    }
    for (n, k) in ks.iter().enumerate() {
        let idx: Vec<usize> = (0..t.rows.len())
            .filter(|&i| t.num(i, ck).ok() == Some(*k))
            .collect();
        let (m, mu) = (t.num(idx[0], cm)?, t.num(idx[0], cmu)?);
        let dmax = idx
            .iter()
            .map(|&i| t.num(i, cdv).unwrap_or(0.0))
            .fold(0.0, f64::max);
        let line = (0..=100)
            .map(|j| {
                let dv = dmax * j as f64 / 100.0;
                let j2 = j2_group(m, mu, *k, dv).map_err(|e| model_err("VII-A J2", e))?;
                Ok((dv, closed::combined_slip_traction(*k, 0.0, j2).1 * mu))
            })
            .collect::<Result<_, ReproduceError>>()?;
        let mut printed = Vec::new();
        let mut measured = Vec::new();
        for &i in &idx {
            let dv = t.num(i, cdv)?;
            printed.push((dv, t.num(i, cthy)? * mu));
            measured.push((dv, t.num(i, cact)? * mu));
        }
        figures.push(Figure {
            id: format!("fig-4-{}", 9 + n),
            title: format!(
                "Figure 4-{}: side slip, Santotrac 50, k = {k} (m = {m}, μ = {mu}), App. VII-A",
                9 + n
            ),
            x_label: "side slip ΔV/U".into(),
            y_label: "traction coefficient Fy/N".into(),
            series: theory_printed_measured(
                "eq. 8 / J+T elastic/plastic (computed)",
                line,
                "printed theory (App. VII-A)",
                printed,
                measured,
            ),
        });
    }
    crate::thermal::attach_appendix_vii_a(&mut rows)?;
    crate::thermal::appendix_vii_a_series(&mut figures)?;
    Ok(Reproduced {
        table: TableResult {
            id: "appendix-vii-a".into(),
            title: "Appendix VII-A (side slip)".into(),
            quantity: "side force J5 = Fy/(N·μ), zero spin, J+T elastic/plastic at tol 1e-9 (-)"
                .into(),
            deviation: Deviation::Absolute,
            rows,
            tolerance: Some(tol(
                &format!("{VII_A_TOL} absolute"),
                "J5 printed to 3 decimals from J2 printed to 3 decimals (J2 ±0.0005 moves J5 ≤ 0.0006)",
                "rheology_appendix::appendix_vii_a_side_slip_theory",
            )),
            missing: vec![],
            figure: FigureKind::SideSlip,
        },
        figures,
    })
}

/// Appendix VII-B: longitudinal slip with side slip, zero spin; J4 against the
/// printed theory (J4 or Fx/N, converted to J4) and the measured J4.
pub fn appendix_vii_b() -> Result<Reproduced, ReproduceError> {
    let t = DataTable::parse("appendix_vii_b_combined_slip.csv", APPENDIX_VII_B)?;
    let c = |n| t.col(n);
    let (ck, cm, cmu, cset, cdu, cj1, cact, ckind, cthy, cj2) = (
        c("k")?,
        c("m")?,
        c("mu")?,
        c("set")?,
        c("dU_U")?,
        c("J1")?,
        c("J4_act")?,
        c("thy_kind")?,
        c("thy")?,
        c("J2")?,
    );
    let acc = Accuracy::new(1e-9).map_err(|e| model_err("accuracy", e))?;
    let mut rows = Vec::new();
    for i in 0..t.rows.len() {
        let (k, mu, j1, j2, thy) = (
            t.num(i, ck)?,
            t.num(i, cmu)?,
            t.num(i, cj1)?,
            t.num(i, cj2)?,
            t.num(i, cthy)?,
        );
        let inp = Inputs::new(k, j1, j2, 0.0).map_err(|e| model_err("Appendix VII-B", e))?;
        let o = evaluate(&inp, Model::ElasticPlastic, acc)
            .map_err(|e| model_err("Appendix VII-B", e))?;
        let is_j4 = t.str(i, ckind) == "J4";
        let (printed, tol_row) = if is_j4 {
            (thy, VII_B_TOL)
        } else {
            // Fx/N printed to 3 decimals: bound VII_B_TOL·μ + 0.0005 in Fx/N = VII_B_TOL + 0.0005/μ in J4.
            (thy / mu, VII_B_TOL + 0.0005 / mu)
        };
        let mut r = row(
            &format!("k={k} set {}", t.str(i, cset)),
            format!("k={k} set {} J1={j1} J2={j2}", t.str(i, cset)),
            t.num(i, cdu)?,
            o.j4,
            Some(printed),
        );
        r.measured = Some(t.num(i, cact)?);
        r.tol = Some(tol_row);
        rows.push(r);
    }
    let mut ks: Vec<f64> = Vec::new();
    for i in 0..t.rows.len() {
        let k = t.num(i, ck)?;
        if !ks.contains(&k) {
            ks.push(k);
        }
    }
    let mut figures = Vec::new();
    for (n, k) in ks.iter().enumerate() {
        let idx: Vec<usize> = (0..t.rows.len())
            .filter(|&i| t.num(i, ck).ok() == Some(*k))
            .collect();
        let (m, mu) = (t.num(idx[0], cm)?, t.num(idx[0], cmu)?);
        let mut sets: Vec<String> = Vec::new();
        for &i in &idx {
            let s = t.str(i, cset).to_string();
            if !sets.contains(&s) {
                sets.push(s);
            }
        }
        let mut series = Vec::new();
        for (si, set) in sets.iter().enumerate() {
            let sidx: Vec<usize> = idx
                .iter()
                .copied()
                .filter(|&i| t.str(i, cset) == set)
                .collect();
            let j2 = t.num(sidx[0], cj2)?;
            let dmax = sidx
                .iter()
                .map(|&i| t.num(i, cdu).unwrap_or(0.0))
                .fold(0.0, f64::max);
            // Slip J1 = (3π/8)(m/μ)(ΔU/U)·√k, the same group as J2 (m here is
            // Table 4-3's longitudinal slope, printed in the VII-B header).
            let line = (0..=100)
                .map(|j| {
                    let du = dmax * j as f64 / 100.0;
                    let j1 = j2_group(m, mu, *k, du).map_err(|e| model_err("VII-B J1", e))?;
                    Ok((du, closed::combined_slip_traction(*k, j1, j2).0 * mu))
                })
                .collect::<Result<_, ReproduceError>>()?;
            series.push(Series {
                name: format!("set {set}: J2 = {j2} (computed)"),
                style: Style::Line,
                color: si,
                points: line,
            });
            let mut measured = Vec::new();
            for &i in &sidx {
                measured.push((t.num(i, cdu)?, t.num(i, cact)? * mu));
            }
            series.push(Series {
                name: format!("set {set} measured"),
                style: Style::Circles,
                color: si,
                points: measured,
            });
        }
        figures.push(Figure {
            id: format!("fig-4-{}", 13 + n),
            title: format!(
                "Figure 4-{}: longitudinal slip with side slip, Santotrac 50, k = {k} (m* = {m}, μ = {mu}), App. VII-B",
                13 + n
            ),
            x_label: "slip ΔU/U".into(),
            y_label: "traction coefficient Fx/N".into(),
            series,
        });
    }
    crate::thermal::attach_appendix_vii_b(&mut rows)?;
    crate::thermal::appendix_vii_b_series(&mut figures)?;
    Ok(Reproduced {
        table: TableResult {
            id: "appendix-vii-b".into(),
            title: "Appendix VII-B (slip + side slip)".into(),
            quantity: "longitudinal traction J4 = Fx/(N·μ), zero spin, combined slip and side slip, J+T elastic/plastic at tol 1e-9; printed Fx/N converted to J4 = (Fx/N)/μ (-)".into(),
            deviation: Deviation::Absolute,
            rows,
            tolerance: Some(tol(
                &format!("{VII_B_TOL} in J4 (rows printed as Fx/N: {VII_B_TOL} + 0.0005/μ)"),
                "printed rounding + J1 printed to 2-3 digits (≤ 0.002 in J4) + the report's own integration plateau at k = 0.5 set A (0.993 printed where eq. 23 gives up to 0.9997)",
                "rheology_appendix::appendix_vii_b_combined_slip_theory",
            )),
            missing: vec![],
            figure: FigureKind::CombinedSlip,
        },
        figures,
    })
}

/// Appendix VII-E: the peak longitudinal traction coefficient under side
/// slip (and 6° spin), low-speed machine, 20 m/s, 70 °C, relative to the μ
/// of the same fluid, P0 and k at zero spin and zero side slip. The report
/// prints measurements only; the isothermal J+T peak is μ itself at every
/// side slip and spin (J4 → 1 as ΔU/U grows), so its relative peak is 1, and
/// the thermal contact's is [`crate::thermal::appendix_vii_e`]. The
/// reference rows (zero spin, zero side slip: the model's inputs) and the
/// tests whose P0, k have no zero-spin test are left out.
pub fn appendix_vii_e() -> Result<Reproduced, ReproduceError> {
    let peaks = crate::thermal::appendix_vii_e(None)?;
    let rows = peaks
        .iter()
        .filter(|p| !p.is_reference)
        .map(|p| Row {
            series: format!(
                "{} k={} P0={} GPa",
                p.point.fluid, p.point.k, p.point.p0_gpa
            ),
            label: format!(
                "{} {}° side slip {} %",
                p.point.test, p.point.spin_deg, p.point.side_slip_pct
            ),
            x: p.point.side_slip_pct,
            computed: 1.0,
            printed: None,
            measured: Some(p.point.mu / p.reference_mu),
            tol: None,
            thermal: Some(p.thermal / p.reference_mu),
        })
        .collect();
    Ok(Reproduced {
        table: TableResult {
            id: "appendix-vii-e".into(),
            title: "Appendix VII-E (peak under side slip and spin)".into(),
            quantity: "peak longitudinal traction coefficient relative to the zero-spin, zero-side-slip μ of the same fluid, P0, k: isothermal J+T (1 at every side slip) against measured (-)".into(),
            deviation: Deviation::Absolute,
            rows,
            tolerance: None,
            missing: vec![
                "printed theory: the report prints measured peaks only (no traces, no theory)".into(),
            ],
            figure: FigureKind::None,
        },
        figures: Vec::new(),
    })
}
