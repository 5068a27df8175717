//! The error type of the crate.

use traction_regression::RegressionError;

/// Everything that can go wrong when loading the curated data or evaluating a
/// fluid correlation. Each variant names the quantity and its valid range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum FluidError {
    /// The regression layer rejected the input or the fit.
    #[error(transparent)]
    Regression(#[from] RegressionError),
    /// A query variable lies outside the range of the data the correlation
    /// was fitted to (strict policy).
    #[error(
        "{quantity} = {value} is outside the data envelope [{min}, {max}] of {correlation}; \
         use Policy::Extrapolate to get a flagged extrapolation"
    )]
    OutsideEnvelope {
        /// Name of the variable with its unit.
        quantity: &'static str,
        /// The query value.
        value: f64,
        /// Smallest value in the data.
        min: f64,
        /// Largest value in the data.
        max: f64,
        /// Which correlation (e.g. "Santotrac 50 μ, App. III-C").
        correlation: String,
    },
    /// A query variable is NaN or infinite (the range and its message:
    /// [`traction_range::Range`]).
    #[error(transparent)]
    Range(#[from] traction_range::OutOfRange),
    /// The correlation returned a non-positive slope or traction coefficient
    /// (possible far outside the data).
    #[error("{correlation} gives a non-physical value {value} at this point (must be > 0)")]
    NonPhysical {
        /// Which correlation.
        correlation: String,
        /// The value.
        value: f64,
    },
    /// The embedded data failed to parse (a defect of the crate, reported
    /// rather than panicking).
    #[error("embedded data file {file}, line {line}: {message}")]
    Data {
        /// File name in `fluids/data`.
        file: &'static str,
        /// 1-based line.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// No data or printed result for this combination.
    #[error("{0}")]
    Unavailable(String),
}
