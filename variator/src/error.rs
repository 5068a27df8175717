//! The crate's error type.

use traction_contact::ContactError;
use traction_kinematics::KinematicsError;

/// Why a variator could not be built or evaluated. Every variant names the
/// offending quantity and its valid range; the lower crates' errors are
/// wrapped unchanged as the source of a variant that names the context (show
/// a user the whole chain: `traction_contact::error_chain`).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum VariatorError {
    /// An input of this crate is invalid in combination with another input
    /// (the roller crown radius against the cavity radius, the tilt against
    /// the half-cone angle; the message says what is required).
    #[error("{quantity} = {value} is out of range: must be {valid}")]
    OutOfRange {
        /// Which quantity, with its unit.
        quantity: &'static str,
        /// The value given.
        value: f64,
        /// The valid range, in words.
        valid: &'static str,
    },
    /// An input of this crate is NaN, infinite or outside its valid range
    /// (one of the crate's `*_RANGE` constants or a range of its own; the
    /// message names the quantity, the value and the range).
    #[error(transparent)]
    Range(#[from] traction_range::OutOfRange),
    /// The cavity geometry at the tilt could not be computed.
    #[error("variator kinematics")]
    Kinematics(#[from] KinematicsError),
    /// A disc–roller contact could not be built or evaluated.
    #[error("disc–roller contact")]
    Contact(#[from] ContactError),
    /// The roller torque balance could not be bracketed (the contacts'
    /// traction torques do not change sign over the searched roller speeds).
    #[error(
        "roller torque balance: no roller speed in [{low}, {high}] rad/s balances the two contacts' torques"
    )]
    NoBalance {
        /// Lowest roller speed searched (rad/s).
        low: f64,
        /// Highest roller speed searched (rad/s).
        high: f64,
    },
}

pub(crate) fn check(
    quantity: &'static str,
    value: f64,
    ok: bool,
    valid: &'static str,
) -> Result<f64, VariatorError> {
    if ok && value.is_finite() {
        Ok(value)
    } else {
        Err(VariatorError::OutOfRange {
            quantity,
            value,
            valid,
        })
    }
}
