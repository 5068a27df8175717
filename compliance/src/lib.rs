//! # traction-compliance: disc compliance, Kalker coefficients, slope conversion
//!
//! Models the elastic creep of the discs in series with the elastic fluid film
//! (report Appendix IV = NASA TP 1530, appendices A and B; section 4-2):
//!
//! * (A1) dry creep of the discs: `(ΔU/U)_dry = q·F/(π a b G_s)` ([`dry_creep`]);
//! * (A2) creep of the elastic film: `(ΔU/U)_film = (32/(9π))(h/a)·F/(π a b Ḡ)`
//!   ([`film_creep`]);
//! * (A3) total: the sum ([`total_creep`]);
//! * (B1) compliance-corrected modulus `G_c = Ḡ/(1 − m/m')`
//!   ([`compliance_corrected_modulus`]);
//! * (B2) dry slope `m' = π a b G_s/(q N)` ([`dry_slope_from_load`]) and, with
//!   `N = (2/3)π a b P0`, (B3) `m' = 3 G_s/(2 q P0)` ([`dry_slope`]);
//! * (B4) apparent modulus `Ḡ = (π/4) m P0 h/a` ([`apparent_modulus`]);
//! * (B5)–(B7) conversion of a measured slope `m` (contact a, h, direction q) to
//!   another contact or direction (a*, h*, q*) at the same pressure, assuming
//!   `G_c = G_c*` ([`convert_slope`]):
//!   `m* = m·(h a*)/(h* a) · [1 + (2/3)(m q P0/G_s)(a* h q*/(a q h*) − 1)]⁻¹`.
//!
//! ## Kalker's q
//!
//! The report read q_x, q_y from its figure 19 (lost). Here they follow from
//! Kalker's linear theory ([`kalker`]): Kalker writes the longitudinal creep force
//! as `F = G·ab·C11·ξ` (ξ = ΔU/U) and the lateral one as `F = G·ab·C22·η`
//! (η = ΔV/U). Equating with (A1), `ΔU/U = q F/(π a b G)`, gives
//!
//! `q_x = π / C11`,  `q_y = π / C22`  ([`kalker_q`]),
//!
//! evaluated at a/b = 1/k (the report's k = b/a, a along the rolling direction).
//! The text's values q ≈ 0.4 at k = 0.2 and q ≈ 0.93 at k = 5 (longitudinal) are
//! reproduced by Kalker's ν = 0.25 column: π/7.78 = 0.404 and π/3.37 = 0.932 (tested).
//!
//! ## Material
//!
//! [`DiscMaterial::REPORT_STEEL`]: E = 210 GPa, ν = 0.3 (G_s = 80.77 GPa). The
//! report gives no E or ν; its Table 2-2 gives C = a/P0 = 2πA²B·Re/E'. With
//! k = 1 (A = B = 1), Re = 6.25 mm and C = 0.170e-12 m/Pa this fixes
//! E' = E/(1−ν²) = 2.31e11 Pa (the high-speed machine, Re = 11.3 mm, C = 0.307e-12,
//! gives the same 2.31e11), i.e. E = 210 GPa for the usual steel ν = 0.3.
//!
//! ## Assumptions and sign conventions
//!
//! Linear (small-creep) theory, both discs of the same material, Hertzian
//! pressure. Creep and slope are positive in the direction of the force; the
//! "side" direction is the report's side slip (lateral, y), "longitudinal" the
//! rolling direction (x). SI units throughout (Pa, m, N); m, μ, q, k dimensionless.
//!
//! ## Example
//!
//! Table 4-3, k = 0.5: the side-slip slope 64.06 at P0 = 2.53 GPa becomes the
//! longitudinal slope 66.74 printed in the report:
//!
//! ```
//! use traction_compliance::{DiscMaterial, Direction, convert_slope_same_contact};
//! let m_long = convert_slope_same_contact(
//!     64.06, 0.5, 2.53e9, Direction::Side, Direction::Longitudinal, DiscMaterial::REPORT_STEEL)?;
//! assert!((m_long / 66.74 - 1.0).abs() < 0.01);
//! # Ok::<(), traction_compliance::ComplianceError>(())
//! ```
#![forbid(unsafe_code)]

pub mod kalker;
pub use kalker::{Coefficient, KalkerCoefficients, kalker_coefficient, kalker_coefficients};

use std::f64::consts::PI;

pub use traction_range::{OutOfRange, Range};

/// Errors of the compliance crate; every variant names the quantity.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ComplianceError {
    /// A quantity is NaN, infinite or outside its valid range (the range and
    /// its message: [`traction_range::Range`]).
    #[error(transparent)]
    OutOfRange(#[from] traction_range::OutOfRange),
    /// A Kalker coefficient was asked for outside the table where no asymptote exists.
    #[error(
        "Kalker coefficient {coefficient} is not available at a/b = {a_over_b}: outside the table (0.1 ≤ a/b ≤ 10) and no asymptote is implemented"
    )]
    NoAsymptote {
        /// Which coefficient.
        coefficient: &'static str,
        /// The a/b asked for.
        a_over_b: f64,
    },
    /// The wet slope is not below the dry slope, so (B1) has no positive solution.
    #[error(
        "wet slope m = {m} must be smaller than the dry slope m' = {m_dry} for a compliance correction (B1)"
    )]
    SlopeNotBelowDry {
        /// Wet slope.
        m: f64,
        /// Dry slope.
        m_dry: f64,
    },
    /// The conversion (B7) gives a non-positive denominator.
    #[error(
        "slope conversion (B7) is singular: 1 + (2/3)(m q P0/G_s)(a* h q*/(a q h*) − 1) = {denominator} ≤ 0 (slope m too large for the disc compliance)"
    )]
    SingularConversion {
        /// The bracket of (B7).
        denominator: f64,
    },
    /// The inputs are each in range, but together overflow (or underflow)
    /// the formula: a result or the term named is infinite, NaN or, for a
    /// slope or modulus, zero (e.g. P0 = 5e-324 Pa, or m = 1e300).
    #[error(
        "{quantity} = {value} is not a finite{positive} number: the inputs are outside the floating-point range of the formula"
    )]
    OutOfFloatRange {
        /// The result or intermediate term, with its formula number.
        quantity: &'static str,
        /// Its value.
        value: f64,
        /// " positive" where the quantity must be > 0, else "".
        positive: &'static str,
    },
}

/// `x` if finite, else [`ComplianceError::OutOfFloatRange`] naming `quantity`.
fn finite(quantity: &'static str, x: f64) -> Result<f64> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(ComplianceError::OutOfFloatRange {
            quantity,
            value: x,
            positive: "",
        })
    }
}

/// `x` if finite and > 0, else [`ComplianceError::OutOfFloatRange`] naming `quantity`.
fn positive(quantity: &'static str, x: f64) -> Result<f64> {
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(ComplianceError::OutOfFloatRange {
            quantity,
            value: x,
            positive: " positive",
        })
    }
}

/// Result alias of this crate.
pub type Result<T> = std::result::Result<T, ComplianceError>;

/// Poisson's ratios of Kalker's table (no asymptote in ν).
pub const KALKER_POISSON_RANGE: Range = Range::closed(0.0, 0.5);

/// Direction of the traction force (and of the measured slope).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// Rolling direction x: longitudinal slip, q = q_x = π/C11.
    Longitudinal,
    /// Lateral direction y: side slip, q = q_y = π/C22.
    Side,
}

/// Isotropic disc material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DiscMaterial {
    /// Young's modulus E (Pa).
    pub youngs_modulus: f64,
    /// Poisson's ratio ν.
    pub poisson_ratio: f64,
}

impl DiscMaterial {
    /// The report's steel as deduced from Table 2-2: E = 210 GPa, ν = 0.3 (see crate docs).
    pub const REPORT_STEEL: DiscMaterial = DiscMaterial {
        youngs_modulus: 210e9,
        poisson_ratio: 0.3,
    };

    /// Checked constructor: E > 0, 0 ≤ ν ≤ 0.5 (Kalker's table range).
    pub fn new(youngs_modulus: f64, poisson_ratio: f64) -> Result<Self> {
        Range::POSITIVE.check("Young's modulus E", youngs_modulus)?;
        KALKER_POISSON_RANGE.check("Poisson's ratio ν", poisson_ratio)?;
        Ok(Self {
            youngs_modulus,
            poisson_ratio,
        })
    }

    /// Shear modulus `G_s = E/(2(1+ν))` (Pa).
    pub fn shear_modulus(&self) -> Result<f64> {
        let m = Self::new(self.youngs_modulus, self.poisson_ratio)?;
        Ok(m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio)))
    }
}

/// Kalker's compliance constant q of (A1) for aspect ratio `k = b/a` and ν:
/// `q_x = π/C11(a/b = 1/k, ν)` (longitudinal), `q_y = π/C22` (side).
pub fn kalker_q(direction: Direction, k: f64, nu: f64) -> Result<f64> {
    Range::POSITIVE.check("aspect ratio k", k)?;
    let c = match direction {
        Direction::Longitudinal => Coefficient::C11,
        Direction::Side => Coefficient::C22,
    };
    Ok(PI / kalker_coefficient(c, 1.0 / k, nu)?)
}

/// (A1) dry creep `q·F/(π a b G_s)` of the discs under traction force `force` (N).
pub fn dry_creep(q: f64, force: f64, a: f64, b: f64, shear_modulus: f64) -> Result<f64> {
    Range::POSITIVE.check("Kalker constant q", q)?;
    Range::FINITE.check("traction force F", force)?;
    Range::POSITIVE.check("semi-axis a", a)?;
    Range::POSITIVE.check("semi-axis b", b)?;
    Range::POSITIVE.check("disc shear modulus G_s", shear_modulus)?;
    finite("dry creep (A1)", q * force / (PI * a * b * shear_modulus))
}

/// (A2) creep of an elastic film of thickness `h` and mean modulus `g_bar`:
/// `(32/(9π))(h/a)·F/(π a b Ḡ)`.
pub fn film_creep(h: f64, force: f64, a: f64, b: f64, g_bar: f64) -> Result<f64> {
    Range::POSITIVE.check("film thickness h", h)?;
    Range::FINITE.check("traction force F", force)?;
    Range::POSITIVE.check("semi-axis a", a)?;
    Range::POSITIVE.check("semi-axis b", b)?;
    Range::POSITIVE.check("fluid shear modulus Ḡ", g_bar)?;
    finite(
        "film creep (A2)",
        32.0 / (9.0 * PI) * (h / a) * force / (PI * a * b * g_bar),
    )
}

/// (A3) total creep of the disc–film–disc sandwich: (A1) + (A2).
pub fn total_creep(
    q: f64,
    shear_modulus: f64,
    h: f64,
    g_bar: f64,
    force: f64,
    a: f64,
    b: f64,
) -> Result<f64> {
    finite(
        "total creep (A3)",
        dry_creep(q, force, a, b, shear_modulus)? + film_creep(h, force, a, b, g_bar)?,
    )
}

/// (B1) compliance-corrected modulus `G_c = Ḡ (1 − m/m')⁻¹`; requires `m < m'`.
pub fn compliance_corrected_modulus(g_bar: f64, m: f64, m_dry: f64) -> Result<f64> {
    Range::POSITIVE.check("apparent modulus Ḡ", g_bar)?;
    Range::POSITIVE.check("wet slope m", m)?;
    Range::POSITIVE.check("dry slope m'", m_dry)?;
    if m >= m_dry {
        return Err(ComplianceError::SlopeNotBelowDry { m, m_dry });
    }
    positive("corrected modulus G_c (B1)", g_bar / (1.0 - m / m_dry))
}

/// (B2) dry slope `m' = π a b G_s/(q N)` for normal load `n` (N).
pub fn dry_slope_from_load(a: f64, b: f64, shear_modulus: f64, q: f64, n: f64) -> Result<f64> {
    Range::POSITIVE.check("semi-axis a", a)?;
    Range::POSITIVE.check("semi-axis b", b)?;
    Range::POSITIVE.check("disc shear modulus G_s", shear_modulus)?;
    Range::POSITIVE.check("Kalker constant q", q)?;
    Range::POSITIVE.check("normal load N", n)?;
    positive("dry slope m' (B2)", PI * a * b * shear_modulus / (q * n))
}

/// (B3) dry slope `m' = 3 G_s/(2 q P0)`.
pub fn dry_slope(shear_modulus: f64, q: f64, p0: f64) -> Result<f64> {
    Range::POSITIVE.check("disc shear modulus G_s", shear_modulus)?;
    Range::POSITIVE.check("Kalker constant q", q)?;
    Range::POSITIVE.check("Hertz pressure P0", p0)?;
    positive("dry slope m' (B3)", 1.5 * shear_modulus / (q * p0))
}

/// (B4) apparent fluid modulus `Ḡ = (π/4) m P0 h/a` (Pa).
pub fn apparent_modulus(m: f64, p0: f64, h: f64, a: f64) -> Result<f64> {
    Range::POSITIVE.check("traction slope m", m)?;
    Range::POSITIVE.check("Hertz pressure P0", p0)?;
    Range::POSITIVE.check("film thickness h", h)?;
    Range::POSITIVE.check("semi-axis a", a)?;
    positive("apparent modulus Ḡ (B4)", PI / 4.0 * m * p0 * h / a)
}

/// One measured contact for (B7): slope, Kalker q, semi-axis a and film thickness h.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlopeContact {
    /// Traction slope m (dimensionless).
    pub slope: f64,
    /// Kalker constant q for the direction of the measurement.
    pub q: f64,
    /// Semi-axis a along the rolling direction (m).
    pub a: f64,
    /// Film thickness h (m).
    pub h: f64,
}

/// (B7): the slope m* of the target contact (q*, a*, h*) from the measured
/// contact (m, q, a, h) at the same pressure `p0` and disc shear modulus `g_s`.
///
/// `m* = m (h a*)/(h* a) · [1 + (2/3)(m q P0/G_s)(a* h q*/(a q h*) − 1)]⁻¹`.
/// `target.slope` is ignored.
pub fn convert_slope(
    measured: SlopeContact,
    target: SlopeContact,
    p0: f64,
    g_s: f64,
) -> Result<f64> {
    Range::POSITIVE.check("measured slope m", measured.slope)?;
    Range::POSITIVE.check("measured Kalker constant q", measured.q)?;
    Range::POSITIVE.check("measured semi-axis a", measured.a)?;
    Range::POSITIVE.check("measured film thickness h", measured.h)?;
    Range::POSITIVE.check("target Kalker constant q*", target.q)?;
    Range::POSITIVE.check("target semi-axis a*", target.a)?;
    Range::POSITIVE.check("target film thickness h*", target.h)?;
    Range::POSITIVE.check("Hertz pressure P0", p0)?;
    Range::POSITIVE.check("disc shear modulus G_s", g_s)?;
    let (m, q, a, h) = (measured.slope, measured.q, measured.a, measured.h);
    let (qs, as_, hs) = (target.q, target.a, target.h);
    let load_term = finite("m q P0/G_s of (B7)", m * q * p0 / g_s)?;
    let bracket = 1.0 + 2.0 / 3.0 * load_term * (as_ * h * qs / (a * q * hs) - 1.0);
    if bracket <= 0.0 {
        return Err(ComplianceError::SingularConversion {
            denominator: bracket,
        });
    }
    positive(
        "converted slope m* (B7)",
        m * (h * as_) / (hs * a) / bracket,
    )
}

/// Convert a slope measured in direction `from` to direction `to` at the same
/// contact (a* = a, h* = h) and pressure, with q from Kalker at the material's ν
/// (the Table 4-3 operation). `k = b/a`, `p0` in Pa.
pub fn convert_slope_same_contact(
    m: f64,
    k: f64,
    p0: f64,
    from: Direction,
    to: Direction,
    material: DiscMaterial,
) -> Result<f64> {
    let g_s = material.shear_modulus()?;
    let q = kalker_q(from, k, material.poisson_ratio)?;
    let qs = kalker_q(to, k, material.poisson_ratio)?;
    let c = |slope, q| SlopeContact {
        slope,
        q,
        a: 1.0,
        h: 1.0,
    };
    convert_slope(c(m, q), c(0.0, qs), p0, g_s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inputs_in_range_that_overflow_a_formula_are_refused() {
        // Each input passes its range, but the result was NaN or infinite:
        // m = 1e300 converted to its own direction gave NaN (inf · 0 in the
        // bracket of B7; the answer would be m itself), P0 = 5e-324 Pa a dry
        // slope of inf, m = 1e300 against another direction a slope of 0.
        let steel = DiscMaterial::REPORT_STEEL;
        let side = Direction::Side;
        let long = Direction::Longitudinal;
        let refused = |r: Result<f64>| matches!(r, Err(ComplianceError::OutOfFloatRange { .. }));
        assert!(refused(convert_slope_same_contact(
            1e300, 2.0, 1.5e9, side, side, steel
        )));
        assert!(refused(convert_slope_same_contact(
            1e300, 2.0, 1.5e9, long, side, steel
        )));
        let gs = steel.shear_modulus().unwrap();
        assert!(refused(dry_slope(gs, 1.0, 5e-324)));
        assert!(refused(dry_slope_from_load(1e-200, 1e-200, gs, 1.0, 1.0)));
        assert!(refused(apparent_modulus(1e300, 1e300, 1.0, 1.0)));
        assert!(refused(dry_creep(1.0, 1e300, 1e-200, 1e-200, gs)));
        // Ordinary inputs are unchanged: the report's Table 4-3 operation.
        let m = convert_slope_same_contact(40.0, 2.0, 1.5e9, long, side, steel).unwrap();
        assert!(m.is_finite() && m > 0.0);
        assert_eq!(
            convert_slope_same_contact(40.0, 2.0, 1.5e9, side, side, steel).unwrap(),
            40.0
        );
    }

    #[test]
    fn b3_is_b2_with_hertz_load() {
        // N = (2/3)π a b P0 turns (B2) into (B3) exactly.
        let (a, b, p0, gs, q) = (2e-4, 3e-4, 1.5e9, 80e9, 0.8);
        let n = 2.0 / 3.0 * PI * a * b * p0;
        let m2 = dry_slope_from_load(a, b, gs, q, n).unwrap();
        let m3 = dry_slope(gs, q, p0).unwrap();
        assert!((m2 / m3 - 1.0).abs() < 1e-12);
    }

    #[test]
    fn b7_preserves_corrected_modulus() {
        // Independent check of (B7): G_c from (B1)+(B4) must be equal for both contacts.
        let (p0, gs) = (1.8e9, 80e9);
        let meas = SlopeContact {
            slope: 55.0,
            q: 0.85,
            a: 3e-4,
            h: 0.4e-6,
        };
        let targ = SlopeContact {
            slope: 0.0,
            q: 0.73,
            a: 2.2e-4,
            h: 0.5e-6,
        };
        let ms = convert_slope(meas, targ, p0, gs).unwrap();
        let gc = |m: f64, c: SlopeContact| {
            let g = apparent_modulus(m, p0, c.h, c.a).unwrap();
            compliance_corrected_modulus(g, m, dry_slope(gs, c.q, p0).unwrap()).unwrap()
        };
        assert!((gc(55.0, meas) / gc(ms, targ) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn a3_is_sum() {
        let t = total_creep(0.8, 80e9, 1e-7, 1e9, 100.0, 2e-4, 3e-4).unwrap();
        let s = dry_creep(0.8, 100.0, 2e-4, 3e-4, 80e9).unwrap()
            + film_creep(1e-7, 100.0, 2e-4, 3e-4, 1e9).unwrap();
        assert_eq!(t, s);
    }

    #[test]
    fn errors() {
        assert!(compliance_corrected_modulus(1e9, 50.0, 40.0).is_err());
        assert!(
            dry_slope(-1.0, 0.8, 1e9)
                .unwrap_err()
                .to_string()
                .contains("G_s")
        );
        assert!(
            DiscMaterial::new(210e9, 0.7)
                .unwrap_err()
                .to_string()
                .contains("Poisson")
        );
        assert!(
            kalker_q(Direction::Side, 0.0, 0.3)
                .unwrap_err()
                .to_string()
                .contains("aspect ratio k")
        );
    }
}
