//! The crate's error type.

/// Why a Hertz contact could not be computed. Every variant names the
/// offending quantity and its valid range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum HertzError {
    /// An input quantity is NaN, infinite where it must be finite, or outside
    /// its valid range (the range and its message: [`traction_range::Range`]).
    #[error(transparent)]
    OutOfRange(#[from] traction_range::OutOfRange),
    /// A radius of curvature is zero or NaN (convex > 0, concave < 0, flat = inf).
    #[error("{quantity} = {value} is out of range: must be {valid}")]
    InvalidInput {
        /// Which quantity (e.g. `rx1 (radius of body 1 along x, m)`).
        quantity: &'static str,
        /// The value given.
        value: f64,
        /// The valid values, in words.
        valid: &'static str,
    },
    /// The relative curvature in one principal direction is not positive: the
    /// surfaces are conformal (a concave radius no larger than the convex one)
    /// or the contact is a line contact (both bodies flat in that direction).
    #[error(
        "relative curvature along {direction} = {value} 1/m (1/r{direction}1 + 1/r{direction}2) \
         must be > 0: conformal or line contact is outside elliptical Hertz theory"
    )]
    NonPositiveCurvature {
        /// `x` (rolling direction) or `y` (across it).
        direction: &'static str,
        /// The relative curvature `1/r1 + 1/r2` in 1/m.
        value: f64,
    },
    /// The curvature ratio gives an ellipse more elongated than the solver
    /// supports (nearly a line contact).
    #[error(
        "curvature ratio Cx/Cy = {ratio} gives an aspect ratio k = b/a outside \
         [{k_min}, {k_max}] (nearly a line contact)"
    )]
    AspectRatioOutOfRange {
        /// The curvature ratio `Cx/Cy`.
        ratio: f64,
        /// Smallest supported k.
        k_min: f64,
        /// Largest supported k.
        k_max: f64,
    },
    /// The aspect ratio given to a shape-factor function is out of range.
    #[error("aspect ratio k = {k} is out of range: must be in [{k_min}, {k_max}]")]
    InvalidAspectRatio {
        /// The value given.
        k: f64,
        /// Smallest supported k.
        k_min: f64,
        /// Largest supported k.
        k_max: f64,
    },
    /// The inputs are each in range, but together give a contact outside
    /// the floating-point range (a semi-axis, the pressure or the load
    /// overflows to infinity or underflows to zero: e.g. a load of 1e308 N,
    /// a modulus of 1e-320 Pa or radii of 1e300 m).
    #[error(
        "{quantity} = {value} is not a finite positive number: the radii, moduli and {given} \
         are outside the floating-point range of the contact"
    )]
    OutOfFloatRange {
        /// The result that overflowed or underflowed, with its unit.
        quantity: &'static str,
        /// Its value (0 or infinite).
        value: f64,
        /// The load or pressure given.
        given: &'static str,
    },
}
