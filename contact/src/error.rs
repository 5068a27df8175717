//! The crate's error type.

use traction_compliance::ComplianceError;
use traction_fluids::FluidError;
use traction_hertz::HertzError;
use traction_kinematics::KinematicsError;
use traction_rheology::RheologyError;

/// Why a traction contact could not be built or evaluated. Every variant names
/// the offending quantity and its valid range; the lower crates' errors are
/// wrapped unchanged as the [`source`](std::error::Error::source) of a variant
/// whose message names only the context (show a user the whole chain:
/// [`error_chain`]).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ContactError {
    /// An input of this crate is missing, or invalid in combination with
    /// another input (the message says what is required).
    #[error("{quantity} = {value} is out of range: must be {valid}")]
    OutOfRange {
        /// Which quantity, with its unit (e.g. `load N (normal load, N)`).
        quantity: &'static str,
        /// The value given.
        value: f64,
        /// The valid range, in words.
        valid: &'static str,
    },
    /// An input of this crate is NaN, infinite or outside its valid range
    /// (one of the crate's `*_RANGE` constants; the message names the
    /// quantity, the value and the range).
    #[error(transparent)]
    Range(#[from] traction_range::OutOfRange),
    /// The Hertz contact could not be computed (radii, materials, load).
    #[error("Hertz contact")]
    Hertz(#[from] HertzError),
    /// The traction model rejected its dimensionless inputs.
    #[error("traction model")]
    Rheology(#[from] RheologyError),
    /// The disc-compliance correction failed (Kalker table range, singular conversion).
    #[error("disc compliance")]
    Compliance(#[from] ComplianceError),
    /// A report fluid's correlation failed: outside its data envelope under
    /// [`crate::EnvelopeRule::Strict`] (names the quantity, value and data
    /// range), near the report's θ' singularity, or non-physical.
    #[error("fluid correlation")]
    Fluid(#[from] FluidError),
    /// The thermal model's temperature fixed point failed: no convergence,
    /// a runaway (no fixed point below the accepted rise), or a non-finite
    /// dissipation.
    #[error("thermal model: {reason} (temperature rise {temperature_rise} K)")]
    Thermal {
        /// What failed.
        reason: &'static str,
        /// The temperature rise reached, K.
        temperature_rise: f64,
    },
    /// An output came out NaN or infinite for valid inputs: a failure of
    /// the solver, not of the inputs (never expected; the message names the
    /// output, and the state that produced it is worth reporting).
    #[error(
        "{quantity} = {value} is not finite: the traction solver failed at this state (an internal error)"
    )]
    NonFinite {
        /// Which output.
        quantity: &'static str,
        /// Its value (NaN or ±∞).
        value: f64,
    },
    /// The body motion could not be turned into contact kinematics.
    #[error("kinematics")]
    Kinematics(#[from] KinematicsError),
}

/// An error and its sources joined by `": "`, as the workspace's programs show
/// it to a user (the CLI, the FMUs' loggers, the reproduction), e.g. `Hertz
/// contact: rx1 (...) = 0 is out of range: must be ...`.
///
/// Every wrapping error of the workspace names only its context and keeps the
/// cause as its source (docs/decisions/0018), so each message appears once. A
/// source whose text the message already ends with (errors of other libraries
/// that print their cause too) is not repeated.
pub fn error_chain(e: &dyn std::error::Error) -> String {
    let mut text = e.to_string();
    let mut source = e.source();
    while let Some(s) = source {
        let part = s.to_string();
        if !text.ends_with(&part) {
            text.push_str(": ");
            text.push_str(&part);
        }
        source = s.source();
    }
    text
}
