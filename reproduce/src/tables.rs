//! One function per report table. Each returns a [`TableResult`] with the
//! tolerance of the corresponding golden test (`tests/tests/*.rs`) and the
//! figures drawn from it ([`Figure`]). One module per table family: [`hertz`]
//! (Tables 2-1..2-3), [`spin`] (2-5), [`compliance`] (4-3), [`appendix_i`](mod@appendix_i),
//! [`appendix_iii`](mod@appendix_iii), [`traction`] (Appendices VI, VII-A, VII-B, VII-E).
//!
//! Printed values come from the curated data in `fluids/data/` (through
//! `traction-fluids`, or [`crate::data`] for Appendices VI, VII-A, VII-B);
//! Table 2-5 is transcribed in [`spin`] with its table number. Tolerances that a
//! golden test shares are public constants or functions of the module that
//! owns the table (e.g. [`hertz::SHAPE_FACTOR_TOL`]).

pub mod appendix_i;
pub mod appendix_iii;
pub mod compliance;
pub mod hertz;
pub mod spin;
pub mod traction;

pub use appendix_i::{appendix_i, appendix_i_js};
pub use appendix_iii::{
    appendix_iii, appendix_iii_coefficients, appendix_iii_error_statistics, appendix_iii_f,
};
pub use compliance::table_4_3;
pub use hertz::{table_2_1, table_2_2, table_2_3};
pub use spin::{table_2_5, table_2_5_hertz_c};
pub use traction::{appendix_vi, appendix_vii_a, appendix_vii_b, appendix_vii_e};

use crate::{ReproduceError, Row, TableResult, Tolerance};

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
        ("appendix-vii-e", appendix_vii_e),
    ]
}

fn no_fig(table: TableResult) -> Reproduced {
    Reproduced {
        table,
        figures: Vec::new(),
    }
}

fn model_err(what: &str, e: impl std::error::Error + Send + Sync + 'static) -> ReproduceError {
    ReproduceError::Model {
        context: what.to_string(),
        source: Box::new(e),
    }
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
