//! The fluid API: m, μ and spin μ of Santotrac 50 and TDF-88 with their data
//! envelopes.

use traction_regression::{Correlation, Fit, Model, TemperatureForm, TermSet, Variables, fit};

use crate::{FluidError, FluidName, printed_result, tests};

/// Which fluid parameter a correlation gives.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Quantity {
    /// Initial traction slope m (zero spin), eq. 14, App. III-A / III-B.
    Slope,
    /// Peak traction coefficient μ (zero spin), eq. 14, App. III-C / III-D.
    Mu,
    /// Peak traction coefficient μ with spin, eq. 15, App. III-E / III-F.
    SpinMu,
}

impl Quantity {
    /// The report's appendix for a fluid.
    pub fn appendix(self, fluid: FluidName) -> &'static str {
        match (self, fluid) {
            (Quantity::Slope, FluidName::Santotrac50) => "III-A",
            (Quantity::Slope, FluidName::Tdf88) => "III-B",
            (Quantity::Mu, FluidName::Santotrac50) => "III-C",
            (Quantity::Mu, FluidName::Tdf88) => "III-D",
            (Quantity::SpinMu, FluidName::Santotrac50) => "III-E",
            (Quantity::SpinMu, FluidName::Tdf88) => "III-F",
        }
    }
    /// 16 terms (eq. 14) or 32 terms (eq. 15).
    pub fn terms(self) -> TermSet {
        match self {
            Quantity::SpinMu => TermSet::ThirtyTwo,
            _ => TermSet::Sixteen,
        }
    }
    fn label(self) -> &'static str {
        match self {
            Quantity::Slope => "slope m",
            Quantity::Mu => "μ",
            Quantity::SpinMu => "spin μ",
        }
    }
}

/// The data set of one appendix's regression: variables and targets, in the
/// listing's order (III-A..III-F, 73/105/53/94/193/152 points).
pub fn data_set(fluid: FluidName, q: Quantity) -> Result<(Vec<Variables>, Vec<f64>), FluidError> {
    let mut x = Vec::new();
    let mut y = Vec::new();
    for t in tests(fluid)? {
        let (used, target) = match q {
            Quantity::Slope => (t.in_slope_fit, t.slope),
            Quantity::Mu => (t.in_mu_fit, Some(t.mu)),
            Quantity::SpinMu => (t.in_spin_fit, Some(t.mu)),
        };
        if !used {
            continue;
        }
        let target = target.ok_or_else(|| FluidError::Data {
            file: "tests csv",
            line: t.listing_row.unwrap_or(0),
            message: format!("test {} is in the slope fit but has no slope", t.test),
        })?;
        x.push(t.variables()?);
        y.push(target);
    }
    Ok((x, y))
}

/// Where a correlation's coefficients come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Source {
    /// Printed in the report (III-A..III-E), with the printed means.
    Printed,
    /// Refitted here from the curated data, with the data's means.
    Refit,
}

/// The box of the data a correlation was fitted to. Inside the box is not a
/// guarantee (the tests are not a full factorial), outside is extrapolation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Envelope {
    /// Hertz pressure P0 range (Pa).
    pub p0_pa: (f64, f64),
    /// Rolling speed range (m/s).
    pub speed_m_s: (f64, f64),
    /// Inlet temperature range (°C).
    pub theta_celsius: (f64, f64),
    /// Aspect ratio range.
    pub k: (f64, f64),
    /// Spin parameter Z = ω√(ab)/U range ((0, 0) for zero-spin correlations).
    pub z: (f64, f64),
}

impl Envelope {
    fn of(points: &[Variables]) -> Envelope {
        let r = |f: fn(&Variables) -> f64| {
            points
                .iter()
                .map(f)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                    (a.min(v), b.max(v))
                })
        };
        let p = r(|v| v.p0_gpa);
        Envelope {
            p0_pa: (p.0 * 1e9, p.1 * 1e9),
            speed_m_s: r(|v| v.speed),
            theta_celsius: r(|v| v.theta_celsius),
            k: r(|v| v.k),
            z: r(|v| v.z),
        }
    }

    /// Names of the query variables outside the box, with value and range.
    pub fn outside(&self, q: &Query) -> Vec<(&'static str, f64, f64, f64)> {
        let mut v = Vec::new();
        let mut chk = |name: &'static str, x: f64, (lo, hi): (f64, f64)| {
            // Relative slack of 1e-9 so that the data's own values are inside.
            let tol = 1e-9 * hi.abs().max(lo.abs());
            if x < lo - tol || x > hi + tol {
                v.push((name, x, lo, hi));
            }
        };
        chk("Hertz pressure P0 (Pa)", q.p0_pa, self.p0_pa);
        chk("rolling speed U (m/s)", q.speed_m_s, self.speed_m_s);
        chk(
            "inlet temperature θ (°C)",
            q.theta_celsius,
            self.theta_celsius,
        );
        chk("aspect ratio k", q.k, self.k);
        chk("spin parameter Z = ω√(ab)/U", q.z, self.z);
        v
    }
}

/// An operating point in SI units (temperature in °C).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Query {
    /// Maximum Hertz pressure P0 (Pa).
    pub p0_pa: f64,
    /// Rolling speed U (m/s).
    pub speed_m_s: f64,
    /// Fluid inlet temperature θ (°C).
    pub theta_celsius: f64,
    /// Aspect ratio k = b/a.
    pub k: f64,
    /// Spin parameter Z = ω√(ab)/U (0 for the zero-spin correlations).
    pub z: f64,
}

/// What to do with a query outside the data envelope.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Policy {
    /// Return [`FluidError::OutsideEnvelope`].
    Strict,
    /// Evaluate anyway and list the offending variables in
    /// [`Estimate::extrapolated`].
    Extrapolate,
}

/// A correlation value with its extrapolation flags.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// m or μ (dimensionless).
    pub value: f64,
    /// Variables outside the data envelope (empty inside).
    pub extrapolated: Vec<&'static str>,
}

impl Estimate {
    /// True when any variable lies outside the envelope.
    pub fn is_extrapolated(&self) -> bool {
        !self.extrapolated.is_empty()
    }
}

/// One of a fluid's correlations with its provenance and envelope.
#[derive(Debug, Clone, PartialEq)]
pub struct FluidCorrelation {
    /// Which parameter.
    pub quantity: Quantity,
    /// Printed or refitted coefficients.
    pub source: Source,
    /// The report's appendix of the data set.
    pub appendix: &'static str,
    /// Means, coefficients and θ' guard.
    pub correlation: Correlation,
    /// Box of the data.
    pub envelope: Envelope,
    /// Number of data points.
    pub n: usize,
    label: String,
}

impl FluidCorrelation {
    fn printed(fluid: FluidName, q: Quantity) -> Result<FluidCorrelation, FluidError> {
        let appendix = q.appendix(fluid);
        let pr = printed_result(appendix)?;
        let (x, _) = data_set(fluid, q)?;
        let model = Model {
            terms: q.terms(),
            temperature: TemperatureForm::Inverse,
        };
        let limit = Correlation::inv_theta_limit_of(&x, pr.means.theta_celsius);
        let correlation = Correlation::new(model, pr.means, pr.coefficients, limit)?;
        Ok(FluidCorrelation {
            quantity: q,
            source: Source::Printed,
            appendix,
            correlation,
            envelope: Envelope::of(&x),
            n: x.len(),
            label: format!("{} {} (App. {appendix}, printed)", fluid.label(), q.label()),
        })
    }

    /// Refit of one appendix's data set with the data's own means.
    pub fn refit(
        fluid: FluidName,
        q: Quantity,
        temperature: TemperatureForm,
    ) -> Result<(FluidCorrelation, Fit), FluidError> {
        let appendix = q.appendix(fluid);
        let (x, y) = data_set(fluid, q)?;
        let model = Model {
            terms: q.terms(),
            temperature,
        };
        let f = fit(model, &x, &y, None)?;
        Ok((
            FluidCorrelation {
                quantity: q,
                source: Source::Refit,
                appendix,
                correlation: f.correlation.clone(),
                envelope: Envelope::of(&x),
                n: x.len(),
                label: format!(
                    "{} {} (App. {appendix} data, refit)",
                    fluid.label(),
                    q.label()
                ),
            },
            f,
        ))
    }

    /// Evaluates at a query with the given envelope policy.
    pub fn evaluate(&self, q: &Query, policy: Policy) -> Result<Estimate, FluidError> {
        let vals = [
            ("Hertz pressure P0 (Pa)", q.p0_pa),
            ("rolling speed U (m/s)", q.speed_m_s),
            ("inlet temperature θ (°C)", q.theta_celsius),
            ("aspect ratio k", q.k),
            ("spin parameter Z", q.z),
        ];
        for (quantity, value) in vals {
            traction_range::Range::FINITE.check(quantity, value)?;
        }
        let outside = self.envelope.outside(q);
        if let (Policy::Strict, Some(&(quantity, value, min, max))) = (policy, outside.first()) {
            return Err(FluidError::OutsideEnvelope {
                quantity,
                value,
                min,
                max,
                correlation: self.label.clone(),
            });
        }
        let v = Variables {
            speed: q.speed_m_s,
            p0_gpa: q.p0_pa / 1e9,
            theta_celsius: q.theta_celsius,
            k: q.k,
            z: q.z,
        };
        let value = self.correlation.evaluate(&v)?;
        if value <= 0.0 {
            return Err(FluidError::NonPhysical {
                correlation: self.label.clone(),
                value,
            });
        }
        Ok(Estimate {
            value,
            extrapolated: outside.into_iter().map(|o| o.0).collect(),
        })
    }

    /// A one-line description, e.g. "Santotrac 50 μ (App. III-C, printed)".
    pub fn label(&self) -> &str {
        &self.label
    }
}

/// A traction fluid: its slope m, peak μ and spin peak μ correlations.
#[derive(Debug, Clone, PartialEq)]
pub struct Fluid {
    /// Which fluid.
    pub name: FluidName,
    /// m(P0, U, θ, k).
    pub slope: FluidCorrelation,
    /// μ(P0, U, θ, k).
    pub mu: FluidCorrelation,
    /// μ(P0, U, θ, k, Z) with spin.
    pub spin_mu: FluidCorrelation,
}

impl Fluid {
    /// Santotrac 50 with the report's printed coefficients (III-A, III-C,
    /// III-E) and printed means.
    pub fn santotrac_50() -> Result<Fluid, FluidError> {
        let n = FluidName::Santotrac50;
        Ok(Fluid {
            name: n,
            slope: FluidCorrelation::printed(n, Quantity::Slope)?,
            mu: FluidCorrelation::printed(n, Quantity::Mu)?,
            spin_mu: FluidCorrelation::printed(n, Quantity::SpinMu)?,
        })
    }

    /// TDF-88 with the printed III-B and III-D coefficients; the spin μ is the
    /// **refit** of the III-F data (the printed III-F coefficients are not in
    /// the text available to this project).
    pub fn tdf_88() -> Result<Fluid, FluidError> {
        let n = FluidName::Tdf88;
        Ok(Fluid {
            name: n,
            slope: FluidCorrelation::printed(n, Quantity::Slope)?,
            mu: FluidCorrelation::printed(n, Quantity::Mu)?,
            spin_mu: FluidCorrelation::refit(n, Quantity::SpinMu, TemperatureForm::Inverse)?.0,
        })
    }

    /// All three correlations refitted from the curated data, with the
    /// report's 1/θ' factor ([`TemperatureForm::Inverse`]) or the well-posed
    /// linear θ' factor ([`TemperatureForm::Linear`]).
    pub fn refit(name: FluidName, temperature: TemperatureForm) -> Result<Fluid, FluidError> {
        Ok(Fluid {
            name,
            slope: FluidCorrelation::refit(name, Quantity::Slope, temperature)?.0,
            mu: FluidCorrelation::refit(name, Quantity::Mu, temperature)?.0,
            spin_mu: FluidCorrelation::refit(name, Quantity::SpinMu, temperature)?.0,
        })
    }

    /// The correlation of a quantity.
    pub fn correlation(&self, q: Quantity) -> &FluidCorrelation {
        match q {
            Quantity::Slope => &self.slope,
            Quantity::Mu => &self.mu,
            Quantity::SpinMu => &self.spin_mu,
        }
    }

    /// Evaluates a quantity with an envelope policy.
    pub fn evaluate(
        &self,
        q: Quantity,
        query: &Query,
        policy: Policy,
    ) -> Result<Estimate, FluidError> {
        self.correlation(q).evaluate(query, policy)
    }

    /// Initial traction slope m at P0 (Pa), U (m/s), θ (°C), k; strict envelope.
    pub fn slope_m(
        &self,
        p0_pa: f64,
        speed_m_s: f64,
        theta_celsius: f64,
        k: f64,
    ) -> Result<f64, FluidError> {
        self.strict(Quantity::Slope, p0_pa, speed_m_s, theta_celsius, k, 0.0)
    }

    /// Peak traction coefficient μ without spin; strict envelope.
    pub fn mu(
        &self,
        p0_pa: f64,
        speed_m_s: f64,
        theta_celsius: f64,
        k: f64,
    ) -> Result<f64, FluidError> {
        self.strict(Quantity::Mu, p0_pa, speed_m_s, theta_celsius, k, 0.0)
    }

    /// Peak traction coefficient μ with spin parameter Z = ω√(ab)/U; strict envelope.
    pub fn spin_peak_mu(
        &self,
        p0_pa: f64,
        speed_m_s: f64,
        theta_celsius: f64,
        k: f64,
        z: f64,
    ) -> Result<f64, FluidError> {
        self.strict(Quantity::SpinMu, p0_pa, speed_m_s, theta_celsius, k, z)
    }

    /// [`Fluid::evaluate`] with the strict envelope, value only.
    fn strict(
        &self,
        q: Quantity,
        p0_pa: f64,
        speed_m_s: f64,
        theta_celsius: f64,
        k: f64,
        z: f64,
    ) -> Result<f64, FluidError> {
        let query = Query {
            p0_pa,
            speed_m_s,
            theta_celsius,
            k,
            z,
        };
        Ok(self.evaluate(q, &query, Policy::Strict)?.value)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p0_pa: f64, speed_m_s: f64, theta_celsius: f64, k: f64, z: f64) -> Query {
        Query {
            p0_pa,
            speed_m_s,
            theta_celsius,
            k,
            z,
        }
    }

    #[test]
    fn printed_mu_near_a_measured_point() {
        // Test 790531-1: 1.45 GPa, 20 m/s, 32 °C, k = 5, μ = 0.103; III-C prints
        // the estimate 0.096 for it. Printed coefficients (3 digits) give it
        // within 0.002 of 0.096 (coefficient rounding).
        let f = Fluid::santotrac_50().unwrap();
        let mu = f.mu(1.45e9, 20.0, 32.0, 5.0).unwrap();
        assert!((mu - 0.096).abs() < 0.002, "{mu}");
    }

    #[test]
    fn envelope_strict_and_flagged() {
        let f = Fluid::tdf_88().unwrap();
        // TDF-88 speeds: 10..80 m/s in III-B.
        let e = f.evaluate(
            Quantity::Mu,
            &q(1.45e9, 100.0, 70.0, 1.0, 0.0),
            Policy::Strict,
        );
        assert!(matches!(e, Err(FluidError::OutsideEnvelope { .. })));
        if let Ok(v) = f.evaluate(
            Quantity::Mu,
            &q(1.45e9, 100.0, 70.0, 1.0, 0.0),
            Policy::Extrapolate,
        ) {
            assert_eq!(v.extrapolated, vec!["rolling speed U (m/s)"]);
        }
        let nan = f.evaluate(
            Quantity::Mu,
            &q(f64::NAN, 20.0, 70.0, 1.0, 0.0),
            Policy::Extrapolate,
        );
        assert!(matches!(nan, Err(FluidError::Range(_))));
        // Spin μ needs Z in range; the zero-spin correlations have Z = 0 only.
        let z = f.evaluate(
            Quantity::Mu,
            &q(1.45e9, 20.0, 70.0, 1.0, 0.001),
            Policy::Strict,
        );
        assert!(matches!(z, Err(FluidError::OutsideEnvelope { .. })));
        assert_eq!(f.spin_mu.source, Source::Refit);
        assert_eq!(f.mu.source, Source::Printed);
    }

    #[test]
    fn guard_and_linear_alternative() {
        let f = Fluid::santotrac_50().unwrap();
        let theta_bar = f.mu.correlation.means().theta_celsius;
        let near = q(1.45e9, 50.0, theta_bar + 0.1, 1.0, 0.0);
        assert!(matches!(
            f.evaluate(Quantity::Mu, &near, Policy::Strict),
            Err(FluidError::Regression(
                traction_regression::RegressionError::NearMeanTemperature { .. }
            ))
        ));
        let lin = Fluid::refit(FluidName::Santotrac50, TemperatureForm::Linear).unwrap();
        let v = lin.evaluate(Quantity::Mu, &near, Policy::Strict).unwrap();
        assert!(v.value > 0.05 && v.value < 0.12);
    }

    #[test]
    fn envelopes_are_the_data_ranges() {
        let f = Fluid::santotrac_50().unwrap();
        // III-E data: P0 1.00..1.90 GPa, U 10..80 m/s, θ 27..73.5 °C, k 1..5.
        let e = f.spin_mu.envelope;
        assert_eq!(e.p0_pa, (1.0e9, 1.9e9));
        assert_eq!(e.speed_m_s, (10.0, 80.0));
        assert_eq!(e.theta_celsius, (27.0, 73.5));
        assert_eq!(e.k, (1.0, 5.0));
        assert_eq!(f.slope.envelope.z, (0.0, 0.0));
    }
}
