//! # traction-regression: the report's traction-data correlations
//!
//! Models the empirical correlations of section 3-1 of the report (NASA
//! CR, Tevaarwerk, "Traction drive … fluids"): the initial traction slope m or
//! the peak traction coefficient μ of a traction fluid as a product of linear
//! trends in pressure, speed, temperature, aspect ratio (and spin).
//!
//! ## Equations
//! * Eq. 12, normalisation by the data-set means (barred quantities):
//!   U' = (U − Ū)/Ū, P' = (P0 − P̄0)/P̄0, θ' = (θ − θ̄)/θ̄, k' = (k − k̄)/k̄,
//!   and for spin Z' = (Z − Z̄)/Z̄ with Z = ω√(ab)/U.
//! * Eq. 13/14, 16 terms: μ = (A1 + A2P')(A3 + A4U')(A5 + A6/θ')(A7 + A8k')
//!   expanded as C1 + C2k' + C3P' + C4P'k' + C5/θ' + C6k'/θ' + C7P'/θ' +
//!   C8k'P'/θ' + C9U' + C10U'k' + C11U'P' + C12U'P'k' + C13U'/θ' + C14k'U'/θ' +
//!   C15P'U'/θ' + C16k'P'U'/θ'.
//! * Eq. 15, 32 terms: the same with a factor (1 + Z'), Z' varying fastest:
//!   C1 + C2Z' + C3k' + C4k'Z' + C5P' + … + C25U'/θ' + **C26U'Z'/θ'** + C27k'U'/θ' + … +
//!   C32U'k'P'Z'/θ'. The printed eq. 15 reads "C26*(U'/θ')" (a duplicate of
//!   C25); the order used here (bit j of the term index selects Z', k', P', 1/θ',
//!   U') is the one that reproduces Appendix III-E's per-point estimates (RMS
//!   difference 0.0007 against the listing's 3-decimal estimates) and error
//!   statistics (−0.460 %/9.873 % against the printed −0.458 %/9.870 %).
//!   See [`Model::term_names`].
//!
//! Coefficients are found by least squares (Householder QR of the design
//! matrix, [faer]); the fit reports the 2-norm condition number of the design
//! matrix, the per-point estimates, the report's percent error
//! ([`percent_error`]: 50·(a/e − e/a)) and its mean and sample standard
//! deviation ([`ErrorStats`]).
//!
//! Nonlinear least squares (Levenberg–Marquardt on faer, finite-difference
//! Jacobians, standard errors and correlations of the parameters) is in
//! [`nls`]; the `traction identify` command calibrates the contact model with it.
//!
//! ## Assumptions and units
//! Variables are the report's: U in m/s, P0 in **GPa** (the report defines the
//! correlations with P0 in GPa), θ in **°C** (θ' depends on the Celsius zero),
//! k and Z dimensionless. No physical unit conversion happens in this crate.
//!
//! ## The θ' singularity
//! The factor A5 + A6/θ' is infinite at θ = θ̄. A [`Correlation`] only
//! evaluates the inverse form where |1/θ'| does not exceed the largest value
//! met in its data ([`Correlation::inv_theta_limit`]); inside that band it
//! returns [`RegressionError::NearMeanTemperature`]. The alternative
//! [`TemperatureForm::Linear`] (factor A5 + A6·θ') is finite everywhere and can
//! be compared with the report's form by [`leave_one_out`] cross-validation.
//!
//! ## Example
//! ```
//! use traction_regression::{fit, Model, Variables};
//! // A small synthetic data set generated from a known product law.
//! let mut pts = Vec::new();
//! let mut mu = Vec::new();
//! for &u in &[10.0, 20.0, 30.0] {
//!     for &t in &[30.0, 45.0, 70.0] {
//!         for &p in &[1.0, 1.45, 1.9] {
//!             for &k in &[1.0, 5.0] {
//!                 pts.push(Variables { speed: u, p0_gpa: p, theta_celsius: t, k, z: 0.0 });
//!                 mu.push(0.1 + 0.01 * p - 0.0005 * u - 0.0002 * t - 0.002 * k);
//!             }
//!         }
//!     }
//! }
//! let f = fit(Model::EQ14, &pts, &mu, None).unwrap();
//! assert_eq!(f.correlation.coefficients().len(), 16);
//! assert!(f.condition_number > 1.0);
//! // At the data the estimates are within a few percent of the law.
//! assert!(f.stats.std_dev < 5.0);
//! // Close to the mean temperature the report's form refuses to evaluate.
//! let mut q = pts[0];
//! q.theta_celsius = f.correlation.means().theta_celsius + 0.01;
//! assert!(f.correlation.evaluate(&q).is_err());
//! ```
#![forbid(unsafe_code)]

mod design;
mod error;
mod fit;
pub mod nls;

pub use design::{
    Model, Normalised, P0_GPA_RANGE, SPEED_RANGE, TEMPERATURE_RANGE, TemperatureForm, TermSet,
    Variables,
};
pub use error::RegressionError;
pub use fit::{
    Correlation, ErrorStats, Fit, LeaveOneOut, MAX_CONDITION, fit, leave_one_out, percent_error,
};
pub use traction_range::{OutOfRange, Range};
