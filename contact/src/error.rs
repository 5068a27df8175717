//! The crate's error type.

use traction_compliance::ComplianceError;
use traction_fluids::FluidError;
use traction_hertz::HertzError;
use traction_kinematics::KinematicsError;
use traction_rheology::RheologyError;

/// Why a traction contact could not be built or evaluated. Every variant names
/// the offending quantity and its valid range; the lower crates' errors are
/// wrapped unchanged.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ContactError {
    /// An input of this crate is NaN, infinite or outside its valid range.
    #[error("{quantity} = {value} is out of range: must be {valid}")]
    OutOfRange {
        /// Which quantity, with its unit (e.g. `load N (normal load, N)`).
        quantity: &'static str,
        /// The value given.
        value: f64,
        /// The valid range, in words.
        valid: &'static str,
    },
    /// The Hertz contact could not be computed (radii, materials, load).
    #[error("Hertz contact: {0}")]
    Hertz(#[from] HertzError),
    /// The traction model rejected its dimensionless inputs.
    #[error("traction model: {0}")]
    Rheology(#[from] RheologyError),
    /// The disc-compliance correction failed (Kalker table range, singular conversion).
    #[error("disc compliance: {0}")]
    Compliance(#[from] ComplianceError),
    /// A report fluid's correlation failed: outside its data envelope under
    /// [`crate::EnvelopeRule::Strict`] (names the quantity, value and data
    /// range), near the report's θ' singularity, or non-physical.
    #[error("fluid correlation: {0}")]
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
    /// The body motion could not be turned into contact kinematics.
    #[error("kinematics: {0}")]
    Kinematics(#[from] KinematicsError),
}

pub(crate) fn check(
    quantity: &'static str,
    value: f64,
    ok: bool,
    valid: &'static str,
) -> Result<f64, ContactError> {
    if ok && value.is_finite() {
        Ok(value)
    } else {
        Err(ContactError::OutOfRange {
            quantity,
            value,
            valid,
        })
    }
}
