//! One function per report table. Each returns a [`TableResult`] with the
//! tolerance of the corresponding golden test (`tests/tests/*.rs`) and the
//! figures drawn from it ([`Figure`]).
//!
//! Printed values: Tables 2-1..2-5 and 4-3 are transcribed below with their
//! table numbers (the golden tests hold the same numbers); Appendix III from
//! `fluids/data/printed_results.csv` and `appendix_iii_listings.csv` (through
//! `traction-fluids`); Appendices VI, VII-A, VII-B from `fluids/data/*.csv`;
//! Appendix I from `traction-fluids` (`fluids/data/appendix_i_traces.csv`).

use rayon::prelude::*;
use traction_compliance::{Direction, DiscMaterial, convert_slope_same_contact};
use traction_fluids::{FluidName, Quantity, data_set, listing, printed_result};
use traction_hertz::{Body, Geometry, shape_factors};
use traction_kinematics::{j2 as j2_group, spin_factor, tilted_disc_spin_per_speed};
use traction_regression::{Model as RegModel, fit};
use traction_rheology::{Accuracy, Inputs, Model, closed, evaluate};

use crate::data::{APPENDIX_VI, APPENDIX_VII_A, APPENDIX_VII_B, DataTable};
use crate::{Deviation, FigureKind, ReproduceError, Row, TableResult, Tolerance};

const GPA: f64 = 1e9;

/// How a plotted series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// Solid line (computed theory).
    Line,
    /// Open circles (measured, as in the report's figures).
    Circles,
    /// Small crosses (the report's printed theory values).
    Crosses,
}

/// One plotted series.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text.
    pub name: String,
    /// Drawing style.
    pub style: Style,
    /// Colour index (same index = same colour).
    pub color: usize,
    /// (x, y) points.
    pub points: Vec<(f64, f64)>,
}

/// The three series of a theory-vs-report figure: the computed line (black),
/// the report's printed theory (crosses) and the measured points (circles).
fn theory_printed_measured(
    computed: &str,
    line: Vec<(f64, f64)>,
    printed_label: &str,
    printed: Vec<(f64, f64)>,
    measured: Vec<(f64, f64)>,
) -> Vec<Series> {
    vec![
        Series {
            name: computed.into(),
            style: Style::Line,
            color: 0,
            points: line,
        },
        Series {
            name: printed_label.into(),
            style: Style::Crosses,
            color: 2,
            points: printed,
        },
        Series {
            name: "measured".into(),
            style: Style::Circles,
            color: 1,
            points: measured,
        },
    ]
}

/// A figure in the style of the report's.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// File-name stem (e.g. `fig-4-1`).
    pub id: String,
    /// Caption (the report's figure number and conditions).
    pub title: String,
    /// Axis labels.
    pub x_label: String,
    /// Axis labels.
    pub y_label: String,
    /// Series.
    pub series: Vec<Series>,
}

/// A reproduced table with its figures.
#[derive(Debug, Clone, PartialEq)]
pub struct Reproduced {
    /// The table.
    pub table: TableResult,
    /// Its figures (may be empty).
    pub figures: Vec<Figure>,
}

/// A table function.
pub type TableFn = fn() -> Result<Reproduced, ReproduceError>;

/// Every table the workspace reproduces, in report order.
pub fn catalogue() -> Vec<(&'static str, TableFn)> {
    vec![
        ("table-2-1", || Ok(no_fig(table_2_1()?))),
        ("table-2-2", || Ok(no_fig(table_2_2()?))),
        ("table-2-3", || Ok(no_fig(table_2_3()?))),
        ("table-2-5", || Ok(no_fig(table_2_5()?))),
        ("table-2-5-hertz-c", || Ok(no_fig(table_2_5_hertz_c()?))),
        ("table-4-3", || Ok(no_fig(table_4_3()?))),
        ("appendix-i-js", || Ok(no_fig(appendix_i_js()?))),
        ("appendix-i", appendix_i),
        ("appendix-iii-a", || appendix_iii("III-A")),
        ("appendix-iii-b", || appendix_iii("III-B")),
        ("appendix-iii-c", || appendix_iii("III-C")),
        ("appendix-iii-d", || appendix_iii("III-D")),
        ("appendix-iii-e", || appendix_iii("III-E")),
        ("appendix-iii-f", appendix_iii_f),
        ("appendix-iii-a-coefficients", || {
            Ok(no_fig(appendix_iii_coefficients("III-A")?))
        }),
        ("appendix-iii-b-coefficients", || {
            Ok(no_fig(appendix_iii_coefficients("III-B")?))
        }),
        ("appendix-iii-c-coefficients", || {
            Ok(no_fig(appendix_iii_coefficients("III-C")?))
        }),
        ("appendix-iii-d-coefficients", || {
            Ok(no_fig(appendix_iii_coefficients("III-D")?))
        }),
        ("appendix-iii-e-coefficients", || {
            Ok(no_fig(appendix_iii_coefficients("III-E")?))
        }),
        ("appendix-iii-error-statistics", || {
            Ok(no_fig(appendix_iii_error_statistics()?))
        }),
        ("appendix-vi", appendix_vi),
        ("appendix-vii-a", appendix_vii_a),
        ("appendix-vii-b", appendix_vii_b),
    ]
}

fn no_fig(table: TableResult) -> Reproduced {
    Reproduced {
        table,
        figures: Vec::new(),
    }
}

fn model_err(what: &str, e: impl std::fmt::Display) -> ReproduceError {
    ReproduceError::Model(format!("{what}: {e}"))
}

fn tol(per_value: &str, justification: &str, golden_test: &str) -> Tolerance {
    Tolerance {
        per_value: per_value.to_string(),
        rms: None,
        allowed_exceptions: 0,
        justification: justification.to_string(),
        golden_test: golden_test.to_string(),
    }
}

fn row(series: &str, label: String, x: f64, computed: f64, printed: Option<f64>) -> Row {
    Row {
        series: series.to_string(),
        label,
        x,
        computed,
        printed,
        measured: None,
        tol: None,
        thermal: None,
    }
}

/// Disc pairs of Table 2-1: name, upper Rx, upper Ry, lower Rx (mm; lower Ry
/// flat), nominal k, printed Re (mm), half a unit of its last digit, printed C
/// of Table 2-2 (1e-12 m/Pa). The LS k = 5 upper Ry is blank in the OCR of
/// Table 2-1 and taken from Table 2-4 (150.4 mm), as in the golden test.
/// One Table 2-1 row (see [`MACHINES`]).
type Machine = (&'static str, f64, f64, f64, f64, f64, f64, f64);

const MACHINES: [Machine; 6] = [
    ("LS k=.5", 25.0, 4.3, 25.0, 0.5, 3.2, 0.05, 0.135),
    ("LS k=1", 25.0, 12.5, 25.0, 1.0, 6.25, 0.005, 0.170),
    ("LS k=2", 25.0, 36.5, 25.0, 2.0, 9.3, 0.05, 0.194),
    ("LS k=5", 25.0, 150.4, 25.0, 5.0, 11.5, 0.05, 0.208),
    ("HS k=1", 33.0, 22.6, 71.4, 1.0, 11.3, 0.05, 0.307),
    ("HS k=5", 33.0, 270.0, 71.4, 5.0, 20.8, 0.05, 0.376),
];

fn geometry(rx1_mm: f64, ry1_mm: f64, rx2_mm: f64) -> Result<Geometry, ReproduceError> {
    Geometry::new(
        &Body::steel(rx1_mm * 1e-3, ry1_mm * 1e-3),
        &Body::steel(rx2_mm * 1e-3, f64::INFINITY),
    )
    .map_err(|e| model_err("Hertz geometry", e))
}

/// Table 2-1: equivalent radius Re (mm) from the disc radii (absolute, mm).
pub fn table_2_1() -> Result<TableResult, ReproduceError> {
    let mut rows = Vec::new();
    for (name, rx1, ry1, rx2, _, re, half, _) in MACHINES {
        let g = geometry(rx1, ry1, rx2)?;
        let mut r = row("Re", format!("Re {name}"), f64::NAN, g.re * 1e3, Some(re));
        r.tol = Some(half + 1e-12);
        rows.push(r);
    }
    Ok(TableResult {
        id: "table-2-1".into(),
        title: "Table 2-1 (Re)".into(),
        quantity: "equivalent radius Re = 1/(Cx + Cy) of the disc pairs, mm".into(),
        deviation: Deviation::Absolute,
        rows,
        tolerance: Some(tol(
            "half a unit of the printed last digit",
            "the radii are exact inputs, Re is printed rounded",
            "hertz_tables::table_2_1_equivalent_radius",
        )),
        missing: vec![],
        figure: FigureKind::None,
    })
}

/// Table 2-2: shape factors A, B (0.4 %) and C on the machine geometry (1 %).
pub fn table_2_2() -> Result<TableResult, ReproduceError> {
    // Table 2-2 as printed: (k, A, B).
    const AB: [(f64, f64, f64); 4] = [
        (0.5, 1.46, 0.725),
        (1.0, 1.0, 1.0),
        (2.0, 0.725, 1.46),
        (5.0, 0.511, 2.55),
    ];
    let mut rows = Vec::new();
    for (k, a, b) in AB {
        let (ca, cb) = shape_factors(k).map_err(|e| model_err("Table 2-2 shape factors", e))?;
        for (name, c, p) in [("A", ca, a), ("B", cb, b)] {
            let mut r = row(name, format!("{name}(k={k})"), k, c, Some(p));
            r.tol = Some(0.004);
            rows.push(r);
        }
    }
    for (name, rx1, ry1, rx2, _, _, _, c) in MACHINES {
        let g = geometry(rx1, ry1, rx2)?;
        let mut r = row("C", format!("C {name}"), g.k, g.c * 1e12, Some(c));
        r.tol = Some(0.01);
        rows.push(r);
    }
    Ok(TableResult {
        id: "table-2-2".into(),
        title: "Table 2-2 (A, B, C)".into(),
        quantity: "Hertz shape factors A, B at the nominal k (-) and C = 2πA²B·Re/E' on the disc radii (1e-12 m/Pa)".into(),
        deviation: Deviation::Relative,
        rows,
        tolerance: Some(tol(
            "A, B 0.4 %; C 1 %",
            "the printed A, B violate B = kA by 0.69 % at k = 0.5 and 2, so no exact solution lies closer than ~0.35 % to both; the report computed C from rounded A, B at the nominal k while the discs' exact k differ by up to 1.8 % (C up to 0.95 %)",
            "hertz_tables::table_2_2_shape_factors, table_2_2_c_exact_on_machine_geometry",
        )),
        missing: vec![],
        figure: FigureKind::None,
    })
}

/// Table 2-3: P0 (GPa) from the printed dead-weight load, relative.
pub fn table_2_3() -> Result<TableResult, ReproduceError> {
    // Table 2-3: test, machine index into MACHINES, printed P0 (GPa), load (N),
    // significant digits of the printed load.
    const TESTS: [(&str, usize, f64, f64, i32); 8] = [
        ("790531-01", 5, 1.45, 5000.0, 1),
        ("790126-03", 5, 1.0, 1500.0, 2),
        ("790329-04", 4, 1.9, 1400.0, 2),
        ("790311-06", 4, 1.0, 200.0, 1),
        ("791119-04", 1, 1.9, 416.0, 3),
        ("791130-06", 1, 1.45, 185.0, 3),
        ("791130-04", 3, 1.0, 460.0, 2),
        ("791103-11", 3, 1.45, 1400.0, 2),
    ];
    let mut rows = Vec::new();
    for (test, mi, p0, load, digits) in TESTS {
        let (name, rx1, ry1, rx2, ..) = MACHINES[mi];
        let g = geometry(rx1, ry1, rx2)?;
        let c = g
            .at_load(load)
            .map_err(|e| model_err("Table 2-3 load", e))?;
        let half_unit_load = 0.5 * 10f64.powi(load.log10().floor() as i32 + 1 - digits);
        let mut r = row(
            name,
            format!("{test} ({name}, {load} N)"),
            load,
            c.p0 / GPA,
            Some(p0),
        );
        r.tol = Some(half_unit_load / load / 3.0 + 0.005 / p0);
        rows.push(r);
    }
    Ok(TableResult {
        id: "table-2-3".into(),
        title: "Table 2-3 (P0)".into(),
        quantity: "maximum Hertz pressure P0 from the printed load, GPa".into(),
        deviation: Deviation::Relative,
        rows,
        tolerance: Some(tol(
            "per row: (half unit of the load's last digit)/load/3 + 0.005 GPa/P0 (0.4..3.7 %)",
            "the printed loads are rounded dead weights and P0 ∝ F^(1/3); P0 is printed to 3 digits",
            "hertz_tables::table_2_3_pressure_from_load_and_load_from_pressure",
        )),
        missing: vec![],
        figure: FigureKind::None,
    })
}

/// Table 2-5 rows: (k, α°, Ry mm, e mm, C of Table 2-2 (m/Pa), printed C''
/// (1/GPa), disc radii (upper Rx, upper Ry, lower Rx) mm). High-speed k = 1
/// uses Ry = 22.6 mm (Table 2-4 prints 20.6; see the golden test).
/// One Table 2-5 row (see [`TABLE_2_5`]).
type SpinRow = (f64, f64, f64, f64, f64, f64, (f64, f64, f64));

const TABLE_2_5: [SpinRow; 8] = [
    (0.5, 6.0, 4.3, 20.7, 0.135e-12, 0.399e-3, (25.0, 4.3, 25.0)),
    (
        1.0,
        6.0,
        12.5,
        12.5,
        0.170e-12,
        0.713e-3,
        (25.0, 12.5, 25.0),
    ),
    (
        2.0,
        6.0,
        36.5,
        -11.5,
        0.194e-12,
        1.15e-3,
        (25.0, 36.5, 25.0),
    ),
    (
        5.0,
        6.0,
        150.4,
        -125.0,
        0.208e-12,
        1.98e-3,
        (25.0, 150.4, 25.0),
    ),
    (
        1.0,
        15.0,
        22.6,
        10.4,
        0.307e-12,
        2.46e-3,
        (33.0, 22.6, 71.4),
    ),
    (
        1.0,
        30.0,
        22.6,
        10.4,
        0.307e-12,
        5.12e-3,
        (33.0, 22.6, 71.4),
    ),
    (
        5.0,
        15.0,
        270.0,
        -230.0,
        0.376e-12,
        7.06e-3,
        (33.0, 270.0, 71.4),
    ),
    (
        5.0,
        30.0,
        270.0,
        -205.0,
        0.376e-12,
        14.6e-3,
        (33.0, 270.0, 71.4),
    ),
];

fn table_2_5_impl(hertz_c: bool) -> Result<TableResult, ReproduceError> {
    let mut rows = Vec::new();
    for (k, alpha, ry, e, c, printed, (rx1, ry1, rx2)) in TABLE_2_5 {
        let w = tilted_disc_spin_per_speed(alpha.to_radians(), ry * 1e-3, e * 1e-3)
            .map_err(|e| model_err("Table 2-5 spin", e))?;
        let (c, kk) = if hertz_c {
            let g = geometry(rx1, ry1, rx2)?;
            (g.c, g.k)
        } else {
            (c, k)
        };
        let c2 = spin_factor(w, c, kk).map_err(|e| model_err("Table 2-5 C''", e))? * GPA;
        let mut r = row(
            "C''",
            format!("k={k} alpha={alpha}"),
            k,
            c2 * 1e3,
            Some(printed * 1e3),
        );
        r.tol = Some(if hertz_c { 0.02 } else { 0.01 });
        rows.push(r);
    }
    let (id, title, quantity, t) = if hertz_c {
        (
            "table-2-5-hertz-c",
            "Table 2-5 (C'' with C from traction-hertz)",
            "spin factor C'' = ω√(ab)/(U·P0), eq. 7, with C and k computed from the disc radii, 1e-3/GPa",
            tol(
                "2 %",
                "the report tabulated C at the nominal k with rounded A, B; the discs' real k (0.493..5.054) move C·√k by up to 1.74 %",
                "kinematics_tables::table_2_5_with_hertz_computed_c",
            ),
        )
    } else {
        (
            "table-2-5",
            "Table 2-5 (C'')",
            "spin factor C'' = ω√(ab)/(U·P0), eq. 7, with Table 2-2's printed C, 1e-3/GPa",
            tol(
                "1 %",
                "C'' printed to 3 digits (±0.45 %), inputs C (±0.37 %) and Ry, e (±0.2 %) rounded",
                "kinematics_tables::table_2_5_spin_factors",
            ),
        )
    };
    Ok(TableResult {
        id: id.into(),
        title: title.into(),
        quantity: quantity.into(),
        deviation: Deviation::Relative,
        rows,
        tolerance: Some(t),
        missing: vec![],
        figure: FigureKind::None,
    })
}

/// Table 2-5 with Table 2-2's printed C (1 %).
pub fn table_2_5() -> Result<TableResult, ReproduceError> {
    table_2_5_impl(false)
}

/// Table 2-5 with C computed by traction-hertz from the radii (2 %).
pub fn table_2_5_hertz_c() -> Result<TableResult, ReproduceError> {
    table_2_5_impl(true)
}

/// Table 4-3 from Table 4-2: longitudinal slope m* from the side-slip slope.
pub fn table_4_3() -> Result<TableResult, ReproduceError> {
    // (k, P0 GPa, side-slip m of Table 4-2, printed m* of Table 4-3, tolerance)
    const ROWS: [(f64, f64, f64, f64, f64); 4] = [
        (0.5, 2.53, 64.06, 66.74, 0.015),
        (1.0, 1.96, 57.60, 65.19, 0.015),
        (2.0, 1.45, 54.40, 62.78, 0.015),
        (5.0, 1.22, 52.40, 61.10, 0.03),
    ];
    let mut rows = Vec::new();
    for (k, p0, m, printed, t) in ROWS {
        let ms = convert_slope_same_contact(
            m,
            k,
            p0 * GPA,
            Direction::Side,
            Direction::Longitudinal,
            DiscMaterial::REPORT_STEEL,
        )
        .map_err(|e| model_err("Table 4-3 slope conversion", e))?;
        let mut r = row("m*", format!("k={k}"), k, ms, Some(printed));
        r.tol = Some(t);
        rows.push(r);
    }
    Ok(TableResult {
        id: "table-4-3".into(),
        title: "Table 4-3 (m*)".into(),
        quantity: "longitudinal traction slope m* from Table 4-2's side-slip m via B7, Kalker q at ν = 0.3, E = 210 GPa (-)".into(),
        deviation: Deviation::Relative,
        rows,
        tolerance: Some(tol(
            "1.5 % (k = 5: 3 %)",
            "the report read q from a lost figure; at k = 5 its q is Kalker's ν = 0.25 value (text quotes q_x ≈ 0.93), with it the row reproduces to −0.46 %",
            "compliance_tables::table_4_3_from_table_4_2",
        )),
        missing: vec![],
        figure: FigureKind::None,
    })
}

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

fn appendix_iii_case(appendix: &str) -> Result<(FluidName, Quantity), ReproduceError> {
    Ok(match appendix {
        "III-A" => (FluidName::Santotrac50, Quantity::Slope),
        "III-B" => (FluidName::Tdf88, Quantity::Slope),
        "III-C" => (FluidName::Santotrac50, Quantity::Mu),
        "III-D" => (FluidName::Tdf88, Quantity::Mu),
        "III-E" => (FluidName::Santotrac50, Quantity::SpinMu),
        "III-F" => (FluidName::Tdf88, Quantity::SpinMu),
        other => return Err(ReproduceError::Data(format!("no appendix {other}"))),
    })
}

fn reg_model(q: Quantity) -> RegModel {
    if q == Quantity::SpinMu {
        RegModel::EQ15
    } else {
        RegModel::EQ14
    }
}

fn parity_figure(id: &str, title: String, target: &str, pts: Vec<(f64, f64)>) -> Figure {
    let (lo, hi) = pts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
            (l.min(p.0).min(p.1), h.max(p.0).max(p.1))
        });
    Figure {
        id: id.to_string(),
        title,
        x_label: format!("measured {target}"),
        y_label: format!("correlation estimate of {target}"),
        series: vec![
            Series {
                name: "estimate = measured".into(),
                style: Style::Line,
                color: 0,
                points: vec![(lo, lo), (hi, hi)],
            },
            Series {
                name: "refit (workspace)".into(),
                style: Style::Circles,
                color: 1,
                points: pts,
            },
        ],
    }
}

/// Appendix III-A..III-E: refit with the printed means; per-point estimates
/// against the listing's printed estimates and the measured targets (absolute).
pub fn appendix_iii(appendix: &str) -> Result<Reproduced, ReproduceError> {
    let (fluid, q) = appendix_iii_case(appendix)?;
    let pr = printed_result(appendix).map_err(|e| model_err(appendix, e))?;
    let (x, y) = data_set(fluid, q).map_err(|e| model_err(appendix, e))?;
    let f = fit(reg_model(q), &x, &y, Some(pr.means)).map_err(|e| model_err(appendix, e))?;
    let l = listing(appendix).map_err(|e| model_err(appendix, e))?;
    if l.len() != f.estimates.len() {
        return Err(ReproduceError::Data(format!(
            "{appendix}: listing has {} rows, data set {}",
            l.len(),
            f.estimates.len()
        )));
    }
    let slope = q == Quantity::Slope;
    let t = if slope { 0.1 } else { 0.0007 };
    let allowed = match appendix {
        "III-A" => 3,
        "III-B" => 1,
        "III-C" => 3,
        "III-D" => 21,
        _ => 12,
    };
    let mut rows = Vec::new();
    for ((lr, e), a) in l.iter().zip(&f.estimates).zip(&y) {
        let mut r = row(
            appendix,
            format!("{} {}", lr.row, lr.test),
            *a,
            *e,
            Some(lr.estimate),
        );
        r.measured = Some(*a);
        r.tol = Some(t);
        rows.push(r);
    }
    let target = if slope {
        "slope m"
    } else {
        "traction coefficient μ"
    };
    let pts = rows
        .iter()
        .filter_map(|r| r.measured.map(|m| (m, r.computed)))
        .collect();
    let id = format!("appendix-{}", appendix.to_lowercase());
    let fig = parity_figure(
        &format!("{id}-parity"),
        format!(
            "Appendix {appendix}: {} {target} correlation (eq. {}), {} points; refit err. mean {:.3} % (printed {}), std {:.3} % (printed {})",
            fluid.label(),
            if q == Quantity::SpinMu { 15 } else { 14 },
            y.len(),
            f.stats.mean,
            pr.err_mean,
            f.stats.std_dev,
            pr.err_std
        ),
        target,
        pts,
    );
    Ok(Reproduced {
        table: TableResult {
            id,
            title: format!("Appendix {appendix} (estimates)"),
            quantity: format!(
                "{} {target}: per-point estimate of the refit (printed means) vs the listing's printed EST. and the measured target",
                fluid.label()
            ),
            deviation: Deviation::Absolute,
            rows,
            tolerance: Some(Tolerance {
                per_value: format!("{t} absolute"),
                rms: None,
                allowed_exceptions: allowed,
                justification: format!(
                    "estimates printed to 3 decimals; {allowed} printed estimates carry OCR digit errors or the original's less accurate solution (III-D, III-E ill-conditioned)"
                ),
                golden_test: "regression_appendix_iii::estimates_match_the_printed_listings".into(),
            }),
            missing: vec![],
            figure: FigureKind::Parity,
        },
        figures: vec![fig],
    })
}

const III: [&str; 5] = ["III-A", "III-B", "III-C", "III-D", "III-E"];

/// Refit of one of III-A..III-E with the printed means, and the printed result.
fn refit_printed_means(
    appendix: &str,
) -> Result<(traction_regression::Fit, traction_fluids::PrintedResult), ReproduceError> {
    let (fluid, q) = appendix_iii_case(appendix)?;
    let pr = printed_result(appendix).map_err(|e| model_err(appendix, e))?;
    let (x, y) = data_set(fluid, q).map_err(|e| model_err(appendix, e))?;
    let f = fit(reg_model(q), &x, &y, Some(pr.means)).map_err(|e| model_err(appendix, e))?;
    Ok((f, pr))
}

/// Per-coefficient tolerance of the golden test (None: reported, not checked).
fn coefficient_tol(appendix: &str, j: usize) -> Option<f64> {
    match appendix {
        "III-A" | "III-B" => Some(0.04),
        "III-C" => Some(0.06),
        // C7 and C16 within 20 %; C14, C15 (|C| < 4 % of C1, columns dominated by
        // four tests next to the mean temperature) not checked.
        "III-D" => match j {
            6 | 15 => Some(0.2),
            13 | 14 => None,
            _ => Some(0.09),
        },
        // III-E: only C1 (the value at the means); the 193 × 32 design is
        // ill-conditioned and the printed set is not the least-squares optimum.
        _ => (j == 0).then_some(0.01),
    }
}

/// Appendix III-A..III-E coefficients C1..Cn: refit (printed means) vs printed (relative).
pub fn appendix_iii_coefficients(appendix: &str) -> Result<TableResult, ReproduceError> {
    let mut rows = Vec::new();
    let mut unchecked = Vec::new();
    {
        let (f, pr) = refit_printed_means(appendix)?;
        for (j, (c, p)) in f
            .correlation
            .coefficients()
            .iter()
            .zip(&pr.coefficients)
            .enumerate()
        {
            let mut r = row(
                appendix,
                format!("{appendix} C{}", j + 1),
                (j + 1) as f64,
                *c,
                Some(*p),
            );
            r.tol = coefficient_tol(appendix, j);
            if r.tol.is_none() {
                unchecked.push(format!("{appendix} C{}", j + 1));
            }
            rows.push(r);
        }
    }
    Ok(TableResult {
        id: format!("appendix-{}-coefficients", appendix.to_lowercase()),
        title: format!("Appendix {appendix} (coefficients)"),
        quantity: "correlation coefficients C1..C16 (eq. 14) / C1..C32 (eq. 15), refit with the printed means vs printed".into(),
        deviation: Deviation::Relative,
        rows,
        tolerance: Some(tol(
            match appendix {
                "III-A" | "III-B" => "4 % relative",
                "III-C" => "6 % relative",
                "III-D" => "9 % relative (C7, C16: 20 %; C14, C15 not checked)",
                _ => "C1 1 % relative (C2..C32 not checked)",
            },
            "condition numbers 1e3..1e5: the refit reproduces the estimates and error statistics, the remaining coefficient differences are the 1980 program's arithmetic; ill-determined coefficients are reported, not checked",
            "regression_appendix_iii::coefficients_reproduce_the_printed_ones",
        )),
        missing: if unchecked.is_empty() {
            vec![]
        } else {
            vec![format!(
                "not checked (ill-determined, reported in the CSV only): {}",
                if unchecked.len() > 6 {
                    format!("C2..C32 ({} coefficients)", unchecked.len())
                } else {
                    unchecked.join(", ")
                }
            )]
        },
        figure: FigureKind::None,
    })
}

/// Appendix III-A..III-E error statistics: mean and standard deviation of the
/// percent error, refit vs printed (absolute, %-points).
pub fn appendix_iii_error_statistics() -> Result<TableResult, ReproduceError> {
    let mut rows = Vec::new();
    for appendix in III {
        let (f, pr) = refit_printed_means(appendix)?;
        let mut m = row(
            appendix,
            format!("{appendix} mean"),
            f64::NAN,
            f.stats.mean,
            Some(pr.err_mean),
        );
        m.tol = Some(0.005);
        let mut s = row(
            appendix,
            format!("{appendix} std"),
            f64::NAN,
            f.stats.std_dev,
            Some(pr.err_std),
        );
        s.tol = Some(1e-3 * pr.err_std.abs());
        rows.extend([m, s]);
    }
    Ok(TableResult {
        id: "appendix-iii-error-statistics".into(),
        title: "Appendix III-A..E (error statistics)".into(),
        quantity: "mean and standard deviation of the report's percent error of the refit, %"
            .into(),
        deviation: Deviation::Absolute,
        rows,
        tolerance: Some(tol(
            "mean 0.005 %-points; std 0.1 % of the printed value",
            "printed to 4-5 digits; III-D, III-E's printed fits are not exactly the least-squares optimum",
            "regression_appendix_iii::error_statistics_reproduce_the_printed_ones",
        )),
        missing: vec![],
        figure: FigureKind::None,
    })
}

/// Appendix III-F: TDF-88 spin refit; its printed values are held out.
pub fn appendix_iii_f() -> Result<Reproduced, ReproduceError> {
    let (fluid, q) = appendix_iii_case("III-F")?;
    let (x, y) = data_set(fluid, q).map_err(|e| model_err("III-F", e))?;
    let f = fit(reg_model(q), &x, &y, None).map_err(|e| model_err("III-F", e))?;
    let rows: Vec<Row> = f
        .estimates
        .iter()
        .zip(&y)
        .enumerate()
        .map(|(i, (e, a))| {
            let mut r = row("III-F", format!("{}", i + 1), *a, *e, None);
            r.measured = Some(*a);
            r
        })
        .collect();
    let pts = rows.iter().map(|r| (r.x, r.computed)).collect();
    let fig = parity_figure(
        "appendix-iii-f-parity",
        format!(
            "Appendix III-F (refit; printed values not available): TDF-88 spin μ, {} points, err. std {:.3} %",
            y.len(),
            f.stats.std_dev
        ),
        "traction coefficient μ",
        pts,
    );
    Ok(Reproduced {
        table: TableResult {
            id: "appendix-iii-f".into(),
            title: "Appendix III-F (refit)".into(),
            quantity: "TDF-88 spin traction coefficient μ: refit estimate (own means) vs the measured target".into(),
            deviation: Deviation::Absolute,
            rows,
            tolerance: None,
            missing: vec![
                "printed values not available: III-F's printed coefficients, means and estimates are held out by the project".into(),
            ],
            figure: FigureKind::Parity,
        },
        figures: vec![fig],
    })
}

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
            "Figure 4-4: Santotrac 50, 20 m/s, 1.22 GPa, 32.5 °C, k = 1, 15° spin",
        ),
        "79100403" => (
            "fig-4-6",
            "Figure 4-6: TDF-88, 80 m/s, 1.0 GPa, 50 °C, k = 5, 15° spin",
        ),
        _ => ("fig-4-x", "Appendix VI trace"),
    }
}

/// Accuracy of the J+T strip integration for Appendix VI, as in the golden test.
const VI_TOL: f64 = 1e-3;

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
            r.tol = Some(0.1);
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
    Ok(Reproduced {
        table: TableResult {
            id: "appendix-vi".into(),
            title: "Appendix VI (spin traces)".into(),
            quantity: "side force J5 = Fy/(Fz·μ) under spin and side slip (J1 = 0), J+T elastic/plastic at tol 1e-3; measured J5 = (Fy/Fz)/μ_spin (-)".into(),
            deviation: Deviation::Absolute,
            rows,
            tolerance: Some(Tolerance {
                per_value: "0.1 absolute".into(),
                rms: Some(0.04),
                allowed_exceptions: 0,
                justification: "the converged model differs from the printed J5 by up to 0.09 at small J2 for k = 1 (J3 = 2.28), where the report's unpublished program is evidently under-resolved".into(),
                golden_test: "rheology_appendix::appendix_vi_spin_traces".into(),
            }),
            missing: vec![
                "traces 79111902, 80051402, 80062306, 80062801 (figures 4-3, 4-5, 4-7, 4-8): held out, not in the curated data".into(),
            ],
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
        r.tol = Some(0.0015);
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
                "0.0015 absolute",
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
            (thy, 0.0075)
        } else {
            // Fx/N printed to 3 decimals: bound 0.0075·μ + 0.0005 in Fx/N = 0.0075 + 0.0005/μ in J4.
            (thy / mu, 0.0075 + 0.0005 / mu)
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
                "0.0075 in J4 (rows printed as Fx/N: 0.0075 + 0.0005/μ)",
                "printed rounding + J1 printed to 2-3 digits (≤ 0.002 in J4) + the report's own integration plateau at k = 0.5 set A (0.993 printed where eq. 23 gives up to 0.9997)",
                "rheology_appendix::appendix_vii_b_combined_slip_theory",
            )),
            missing: vec![],
            figure: FigureKind::CombinedSlip,
        },
        figures,
    })
}
