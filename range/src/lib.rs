//! # traction-range: the valid range of an input quantity
//!
//! Every crate of the workspace checks its inputs at its API edge. A [`Range`]
//! states the valid values of one quantity once — next to the constant that
//! defines it — and writes its own message, so that the limit and the text that
//! reports it cannot drift apart:
//!
//! ```
//! use traction_range::Range;
//! const POISSON_RATIO: Range = Range::open(-1.0, 0.5);
//! assert!(POISSON_RATIO.check("nu1 (Poisson's ratio of body 1)", 0.3).is_ok());
//! let e = POISSON_RATIO.check("nu1 (Poisson's ratio of body 1)", 0.5).unwrap_err();
//! assert_eq!(
//!     e.to_string(),
//!     "nu1 (Poisson's ratio of body 1) = 0.5 is out of range: must be in (-1, 0.5)"
//! );
//! ```
//!
//! NaN is never in a range; ±∞ is in a range only when [`Range::with_infinity`]
//! allows it (a flat profile as an infinite radius, an infinite Deborah number).
#![forbid(unsafe_code)]

use std::fmt;

/// The valid values of one quantity: an interval with open or closed ends
/// (unbounded ends are ±∞), optionally a unit for the message.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    min: f64,
    max: f64,
    min_open: bool,
    max_open: bool,
    infinity: bool,
    unit: &'static str,
}

impl Range {
    /// Every finite value.
    pub const FINITE: Range = Range::open(f64::NEG_INFINITY, f64::INFINITY);
    /// Finite and > 0.
    pub const POSITIVE: Range = Range::open(0.0, f64::INFINITY);
    /// Finite and ≥ 0.
    pub const NON_NEGATIVE: Range = Range::at_least(0.0);

    /// The closed interval [min, max].
    pub const fn closed(min: f64, max: f64) -> Range {
        Range {
            min,
            max,
            min_open: false,
            max_open: false,
            infinity: false,
            unit: "",
        }
    }

    /// The open interval (min, max).
    pub const fn open(min: f64, max: f64) -> Range {
        Range {
            min,
            max,
            min_open: true,
            max_open: true,
            infinity: false,
            unit: "",
        }
    }

    /// [min, ∞): finite values ≥ min.
    pub const fn at_least(min: f64) -> Range {
        Range {
            min,
            max: f64::INFINITY,
            min_open: false,
            max_open: true,
            infinity: false,
            unit: "",
        }
    }

    /// (min, ∞): finite values > min.
    pub const fn greater_than(min: f64) -> Range {
        Range::open(min, f64::INFINITY)
    }

    /// The same range with its upper end included: (min, max].
    pub const fn closed_above(self) -> Range {
        Range {
            max_open: false,
            ..self
        }
    }

    /// The same range with the unit named in the message (e.g. `"Pa"`).
    pub const fn with_unit(self, unit: &'static str) -> Range {
        Range { unit, ..self }
    }

    /// The same range that also accepts +∞ when it is unbounded above (and −∞
    /// when it is unbounded below).
    pub const fn with_infinity(self) -> Range {
        Range {
            infinity: true,
            ..self
        }
    }

    /// Smallest valid value (or the open lower end).
    pub const fn min(&self) -> f64 {
        self.min
    }

    /// Largest valid value (or the open upper end).
    pub const fn max(&self) -> f64 {
        self.max
    }

    /// Whether `value` is valid.
    #[inline]
    pub fn contains(&self, value: f64) -> bool {
        if value.is_nan() {
            return false;
        }
        if value.is_infinite() {
            return self.infinity
                && ((value > 0.0 && self.max == f64::INFINITY)
                    || (value < 0.0 && self.min == f64::NEG_INFINITY));
        }
        let above = if self.min_open {
            value > self.min
        } else {
            value >= self.min
        };
        let below = if self.max_open {
            value < self.max
        } else {
            value <= self.max
        };
        above && below
    }

    /// `value` if it is valid, otherwise an error naming `quantity`, the value and
    /// this range.
    #[inline]
    pub fn check(&self, quantity: &'static str, value: f64) -> Result<f64, OutOfRange> {
        if self.contains(value) {
            Ok(value)
        } else {
            Err(OutOfRange {
                quantity,
                value,
                range: *self,
            })
        }
    }
}

/// A number as the messages print it: plain for 1e-3 ≤ |v| < 1e5, else in
/// exponent form (`1e-9`, `2.5e6`).
struct Num(f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        if v == 0.0 || v.is_infinite() || (1e-3..1e5).contains(&v.abs()) {
            write!(f, "{v}")
        } else {
            write!(f, "{v:e}")
        }
    }
}

impl fmt::Display for Range {
    /// `in [a, b]`, `in (a, b)`, `finite and > a`, `finite and ≥ a`,
    /// `finite and < b`, `finite`, or with infinity allowed `> a or +inf` ...,
    /// followed by the unit.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (lo, hi) = (self.min.is_finite(), self.max.is_finite());
        let finite = if self.infinity { "" } else { "finite and " };
        match (lo, hi) {
            (true, true) => write!(
                f,
                "in {}{}, {}{}",
                if self.min_open { '(' } else { '[' },
                Num(self.min),
                Num(self.max),
                if self.max_open { ')' } else { ']' }
            )?,
            (true, false) => write!(
                f,
                "{finite}{} {}",
                if self.min_open { ">" } else { ">=" },
                Num(self.min)
            )?,
            (false, true) => write!(
                f,
                "{finite}{} {}",
                if self.max_open { "<" } else { "<=" },
                Num(self.max)
            )?,
            (false, false) if self.infinity => write!(f, "not NaN")?,
            (false, false) => write!(f, "finite")?,
        }
        if self.infinity && (lo != hi) {
            write!(f, " (inf allowed)")?;
        }
        if !self.unit.is_empty() {
            write!(f, " {}", self.unit)?;
        }
        Ok(())
    }
}

/// A value outside the range of its quantity.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("{quantity} = {} is out of range: must be {range}", Num(*.value))]
pub struct OutOfRange {
    /// Which quantity, with its unit where it has one (e.g.
    /// `e1 (Young's modulus of body 1, Pa)`).
    pub quantity: &'static str,
    /// The value given.
    pub value: f64,
    /// Its valid range.
    pub range: Range,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn contains_honours_open_and_closed_ends_nan_and_infinity() {
        let r = Range::closed(1e-9, 1.0);
        assert!(r.contains(1e-9) && r.contains(1.0) && !r.contains(1.0 + 1e-15));
        assert!(!Range::open(0.0, 1.0).contains(0.0));
        assert!(!Range::POSITIVE.contains(f64::INFINITY));
        assert!(Range::POSITIVE.with_infinity().contains(f64::INFINITY));
        assert!(!Range::POSITIVE.with_infinity().contains(f64::NEG_INFINITY));
        assert!(
            !Range::closed(0.0, 1.0)
                .with_infinity()
                .contains(f64::INFINITY)
        );
        for r in [Range::FINITE, Range::POSITIVE, Range::closed(0.0, 1.0)] {
            assert!(!r.contains(f64::NAN));
        }
        assert!(Range::FINITE.contains(-1e300) && !Range::FINITE.contains(f64::NEG_INFINITY));
    }

    #[test]
    fn values_print_short_in_messages() {
        // The value as the range's ends: plain for 1e-3 ≤ |v| < 1e5, else
        // in exponent form (an f64 near its maximum printed 309 digits).
        let r = Range::closed(-1e100, 1e100);
        let e = |v: f64| r.check("J3", v).unwrap_err().to_string();
        assert_eq!(
            e(1.7e308),
            "J3 = 1.7e308 is out of range: must be in [-1e100, 1e100]"
        );
        assert!(e(f64::NAN).starts_with("J3 = NaN is out of range"));
        let p = |v: f64| Range::POSITIVE.check("x", v).unwrap_err().to_string();
        assert!(p(-2.5).starts_with("x = -2.5 is"), "{}", p(-2.5));
        assert!(p(-5e-324).starts_with("x = -5e-324 is"), "{}", p(-5e-324));
        assert!(p(0.0).starts_with("x = 0 is"), "{}", p(0.0));
    }

    #[test]
    fn messages_state_the_range() {
        let m = |r: Range| r.to_string();
        assert_eq!(
            m(Range::closed(1e-9, 1.0).with_unit("m/s")),
            "in [1e-9, 1] m/s"
        );
        assert_eq!(m(Range::open(-1.0, 0.5)), "in (-1, 0.5)");
        assert_eq!(m(Range::POSITIVE.with_unit("Pa")), "finite and > 0 Pa");
        assert_eq!(m(Range::NON_NEGATIVE), "finite and >= 0");
        assert_eq!(m(Range::FINITE), "finite");
        assert_eq!(m(Range::POSITIVE.with_infinity()), "> 0 (inf allowed)");
        assert_eq!(m(Range::closed(0.0, 2.5e6)), "in [0, 2.5e6]");
        let e = Range::POSITIVE.check("load (N)", -5.0).unwrap_err();
        assert_eq!(
            e.to_string(),
            "load (N) = -5 is out of range: must be finite and > 0"
        );
    }
}
