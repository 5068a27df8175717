//! Variables, normalisation (eq. 12) and the design rows of eq. 14 and eq. 15.

use traction_range::Range;

use crate::RegressionError;

/// Valid rolling speed U of a correlation variable.
pub const SPEED_RANGE: Range = Range::POSITIVE.with_unit("m/s");
/// Valid Hertz pressure P0 of a correlation variable (the report's unit).
pub const P0_GPA_RANGE: Range = Range::POSITIVE.with_unit("GPa");
/// Valid inlet temperature θ: above absolute zero.
pub const TEMPERATURE_RANGE: Range = Range::greater_than(-273.15).with_unit("°C");

/// One operating point in the report's correlation variables.
///
/// Units are those of the report's correlations: speed in m/s, the Hertz
/// pressure P0 in **GPa** (the report defines the correlations with P0 in GPa;
/// only the means and the normalisation see it, so the unit cancels in P' but
/// not in the means), the inlet temperature θ in **°C** (θ' depends on the
/// Celsius zero), the aspect ratio k = b/a and the spin parameter
/// Z = ω√(ab)/U (both dimensionless).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Variables {
    /// Rolling speed U (m/s).
    pub speed: f64,
    /// Maximum Hertz pressure P0 (GPa).
    pub p0_gpa: f64,
    /// Fluid inlet temperature θ (°C).
    pub theta_celsius: f64,
    /// Contact aspect ratio k = b/a (dimensionless).
    pub k: f64,
    /// Spin parameter Z = ω√(ab)/U (dimensionless, 0 without spin).
    pub z: f64,
}

impl Variables {
    /// Checks that every variable is finite and in its physical range
    /// (U > 0, P0 > 0, θ > −273.15 °C, k > 0, Z ≥ 0).
    pub fn validate(&self) -> Result<(), RegressionError> {
        let checks: [(&'static str, f64, Range); 5] = [
            ("rolling speed U (m/s)", self.speed, SPEED_RANGE),
            ("Hertz pressure P0 (GPa)", self.p0_gpa, P0_GPA_RANGE),
            (
                "inlet temperature θ (°C)",
                self.theta_celsius,
                TEMPERATURE_RANGE,
            ),
            ("aspect ratio k", self.k, Range::POSITIVE),
            ("spin parameter Z", self.z, Range::NON_NEGATIVE),
        ];
        for (quantity, value, range) in checks {
            range.check(quantity, value)?;
        }
        Ok(())
    }

    /// Arithmetic means of a data set (the barred quantities of eq. 12).
    pub fn mean_of(points: &[Variables]) -> Result<Variables, RegressionError> {
        if points.is_empty() {
            return Err(RegressionError::DataShape {
                what: "means of an empty data set",
                detail: "at least one point is needed".into(),
            });
        }
        let n = points.len() as f64;
        let sum = |f: fn(&Variables) -> f64| points.iter().map(f).sum::<f64>() / n;
        Ok(Variables {
            speed: sum(|p| p.speed),
            p0_gpa: sum(|p| p.p0_gpa),
            theta_celsius: sum(|p| p.theta_celsius),
            k: sum(|p| p.k),
            z: sum(|p| p.z),
        })
    }
}

/// The normalised (primed) variables of eq. 12: X' = (X − X̄)/X̄.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Normalised {
    /// U' = (U − Ū)/Ū.
    pub u: f64,
    /// P' = (P0 − P̄0)/P̄0.
    pub p: f64,
    /// θ' = (θ − θ̄)/θ̄ (θ in °C).
    pub theta: f64,
    /// k' = (k − k̄)/k̄.
    pub k: f64,
    /// Z' = (Z − Z̄)/Z̄ (only used by eq. 15; 0 when Z̄ = 0).
    pub z: f64,
}

impl Normalised {
    /// Eq. 12 with the given means. Z' is set to 0 when Z̄ = 0 (16-term
    /// correlations have no spin term).
    pub fn new(x: &Variables, means: &Variables) -> Normalised {
        let rel = |v: f64, m: f64| (v - m) / m;
        Normalised {
            u: rel(x.speed, means.speed),
            p: rel(x.p0_gpa, means.p0_gpa),
            theta: rel(x.theta_celsius, means.theta_celsius),
            k: rel(x.k, means.k),
            z: if means.z > 0.0 {
                rel(x.z, means.z)
            } else {
                0.0
            },
        }
    }
}

/// Which product of linear factors the correlation expands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum TermSet {
    /// Eq. 14: 16 terms, (1 + k')(1 + P')(1 + T)(1 + U'), k' varying fastest.
    Sixteen,
    /// Eq. 15: 32 terms, (1 + Z')(1 + k')(1 + P')(1 + T)(1 + U'), Z' fastest.
    ThirtyTwo,
}

impl TermSet {
    /// Number of coefficients (16 or 32).
    pub fn len(self) -> usize {
        match self {
            TermSet::Sixteen => 16,
            TermSet::ThirtyTwo => 32,
        }
    }

    /// Always false (a term set has 16 or 32 terms); present for clippy's
    /// `len_without_is_empty`.
    pub fn is_empty(self) -> bool {
        false
    }

    /// From the number of terms (16 or 32).
    pub fn from_count(n: usize) -> Result<TermSet, RegressionError> {
        match n {
            16 => Ok(TermSet::Sixteen),
            32 => Ok(TermSet::ThirtyTwo),
            _ => Err(RegressionError::OutOfRange {
                quantity: "number of terms",
                value: n as f64,
                range: "16 (eq. 14) or 32 (eq. 15)",
            }),
        }
    }
}

/// How the temperature enters each factor.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum TemperatureForm {
    /// The report's factor (A5 + A6/θ'), T = 1/θ': singular at θ = θ̄.
    Inverse,
    /// The well-posed alternative (A5 + A6·θ'), T = θ': a linear temperature
    /// term, finite everywhere.
    Linear,
}

/// A correlation's functional form: term set and temperature factor.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Model {
    /// 16 (eq. 14) or 32 (eq. 15) terms.
    pub terms: TermSet,
    /// 1/θ' (report) or θ' (alternative).
    pub temperature: TemperatureForm,
}

impl Model {
    /// The report's eq. 14.
    pub const EQ14: Model = Model {
        terms: TermSet::Sixteen,
        temperature: TemperatureForm::Inverse,
    };
    /// The report's eq. 15 (term order established by reproducing App. III-E).
    pub const EQ15: Model = Model {
        terms: TermSet::ThirtyTwo,
        temperature: TemperatureForm::Inverse,
    };

    /// Number of coefficients.
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// Always false; see [`TermSet::is_empty`].
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Human-readable term names in coefficient order, e.g. `"U'P'k'/θ'"`;
    /// the constant term is `"1"`.
    pub fn term_names(&self) -> Vec<String> {
        // (bit, name) of the non-temperature factors, printed U' P' k' Z'.
        let (factors, t_bit): (&[(usize, &str)], usize) = match self.terms {
            TermSet::Sixteen => (&[(3, "U'"), (1, "P'"), (0, "k'")], 2),
            TermSet::ThirtyTwo => (&[(4, "U'"), (2, "P'"), (1, "k'"), (0, "Z'")], 3),
        };
        (0..self.len())
            .map(|j| {
                let mut s: String = factors
                    .iter()
                    .filter(|(bit, _)| j >> bit & 1 == 1)
                    .map(|(_, n)| *n)
                    .collect();
                if j >> t_bit & 1 == 1 {
                    match self.temperature {
                        TemperatureForm::Inverse => {
                            if s.is_empty() {
                                s.push('1');
                            }
                            s.push_str("/θ'");
                        }
                        TemperatureForm::Linear => s.push_str("θ'"),
                    }
                }
                if s.is_empty() { "1".to_string() } else { s }
            })
            .collect()
    }

    /// Fills `row` (length [`Model::len`]) with the regressors of one point.
    ///
    /// Term j is the product of the factors whose bit is set in j, the factors
    /// being (k', P', T, U') for eq. 14 and (Z', k', P', T, U') for eq. 15,
    /// T = 1/θ' or θ'. This reproduces the printed order of eq. 14 and the
    /// order of eq. 15 with its typo corrected (C26 = U'Z'/θ', not U'/θ').
    ///
    /// # Panics
    /// Never: a row of the wrong length is filled up to the shorter length.
    pub fn fill_row(&self, x: &Normalised, row: &mut [f64]) {
        let t = match self.temperature {
            TemperatureForm::Inverse => 1.0 / x.theta,
            TemperatureForm::Linear => x.theta,
        };
        let factors: &[f64] = match self.terms {
            TermSet::Sixteen => &[x.k, x.p, t, x.u],
            TermSet::ThirtyTwo => &[x.z, x.k, x.p, t, x.u],
        };
        for (j, out) in row.iter_mut().enumerate().take(self.len()) {
            let mut v = 1.0;
            for (bit, f) in factors.iter().enumerate() {
                if j >> bit & 1 == 1 {
                    v *= f;
                }
            }
            *out = v;
        }
    }

    /// The regressor row as a new vector.
    pub fn row(&self, x: &Normalised) -> Vec<f64> {
        let mut r = vec![0.0; self.len()];
        self.fill_row(x, &mut r);
        r
    }
}
