//! The error type of the crate.

/// Everything that can go wrong when building, fitting or evaluating a
/// correlation. Each variant names the offending quantity and its valid range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RegressionError {
    /// An input variable is NaN, infinite or outside its valid range (the range
    /// and its message: [`traction_range::Range`]).
    #[error(transparent)]
    Range(#[from] traction_range::OutOfRange),
    /// A variable is NaN or infinite.
    #[error("{quantity} must be a finite number, got {value}")]
    NotFinite {
        /// Name of the quantity (with its unit).
        quantity: &'static str,
        /// The value received.
        value: f64,
    },
    /// A variable is outside its valid range.
    #[error("{quantity} = {value} is out of range: {range}")]
    OutOfRange {
        /// Name of the quantity (with its unit).
        quantity: &'static str,
        /// The value received.
        value: f64,
        /// The valid range, in words.
        range: &'static str,
    },
    /// Equation 14/15 divides by θ' = (θ − θ̄)/θ̄; the query is inside the guard
    /// band around the mean temperature θ̄ where 1/θ' exceeds what the fitted data
    /// ever constrained.
    #[error(
        "temperature θ = {theta_celsius} °C is within {band_celsius:.3} °C of the correlation's mean \
         temperature θ̄ = {mean_celsius} °C: the 1/θ' terms of eq. 14/15 are unbounded there \
         (|1/θ'| would be {inv_theta:.1}, the fitted data only reach {limit:.1}); \
         use the linear-θ' correlation or move θ outside the band"
    )]
    NearMeanTemperature {
        /// Query temperature (°C).
        theta_celsius: f64,
        /// Mean temperature θ̄ of the correlation (°C).
        mean_celsius: f64,
        /// Half-width of the guard band (°C).
        band_celsius: f64,
        /// |1/θ'| at the query.
        inv_theta: f64,
        /// Largest |1/θ'| of the fitted data.
        limit: f64,
    },
    /// A data point sits exactly at the mean temperature (θ' = 0), so the
    /// inverse-temperature design matrix cannot be formed.
    #[error("data point {index}: θ = θ̄ = {theta_celsius} °C makes 1/θ' infinite")]
    DataAtMeanTemperature {
        /// Zero-based row index.
        index: usize,
        /// Its temperature (°C).
        theta_celsius: f64,
    },
    /// The number of coefficients does not match the term set.
    #[error("{expected} coefficients expected for this term set, got {got}")]
    CoefficientCount {
        /// Terms of the model.
        expected: usize,
        /// Coefficients supplied.
        got: usize,
    },
    /// Points and targets differ in length, or there are too few points.
    #[error("{what}: {detail}")]
    DataShape {
        /// What is wrong.
        what: &'static str,
        /// Details with the counts.
        detail: String,
    },
    /// The design matrix is rank deficient (some terms are not identifiable
    /// from the data, e.g. all points at one aspect ratio).
    #[error(
        "the design matrix is rank deficient (condition number {condition:.3e} > 1e12): \
         the data do not vary every variable the {terms}-term correlation needs"
    )]
    RankDeficient {
        /// Number of terms.
        terms: usize,
        /// 2-norm condition number σmax/σmin.
        condition: f64,
    },
    /// The singular value decomposition did not converge.
    #[error("singular value decomposition of the design matrix did not converge")]
    Svd,
    /// The residual function of a nonlinear least-squares fit failed where it
    /// must succeed (the initial point, or both sides of a finite-difference
    /// step).
    #[error("residual function failed {message}")]
    Residual {
        /// Where, and the function's own message.
        message: String,
    },
    /// A fitted estimate is not positive, so the report's percent error
    /// 50·(a/e − e/a) is undefined for it.
    #[error("estimate {estimate} at data point {index} is not positive; percent error undefined")]
    NonPositiveEstimate {
        /// Zero-based row index.
        index: usize,
        /// The estimate.
        estimate: f64,
    },
    /// The report's percent error 50·(a/e − e/a) of a data point overflows:
    /// the actual value and the estimate, both positive, differ by a factor
    /// beyond the floating-point range (e.g. a target of 1e-320).
    #[error(
        "percent error at data point {index} is not finite: actual {actual} and estimate {estimate} differ beyond the floating-point range"
    )]
    PercentErrorOverflow {
        /// Zero-based row index.
        index: usize,
        /// The actual (fitted) value.
        actual: f64,
        /// The estimate.
        estimate: f64,
    },
}
