//! The fluid: user m, μ, physical Ḡ, τ̄, h, or a report fluid's correlations.

use std::sync::{Arc, OnceLock};

use crate::error::ContactError;
use crate::{Range, SLOPE_RANGE, TRACTION_COEFFICIENT_RANGE};

/// The fluid: how the traction slope m and peak traction coefficient μ of the
/// contact are obtained.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Fluid {
    /// User values of the initial traction slope m and the zero-spin peak
    /// traction coefficient μ (both dimensionless, as measured on a disc
    /// machine), optionally the spin-peak μ_s used to scale the forces.
    Constant {
        /// Initial traction slope m = d(F/N)/d(Δ/U) at zero slip.
        slope: f64,
        /// Zero-spin peak traction coefficient μ.
        peak: f64,
        /// Spin-peak traction coefficient μ_s (forces = μ_s N J), if given.
        spin_peak: Option<f64>,
    },
    /// Physical film properties (App. IV eq. 10): mean shear modulus Ḡ (Pa),
    /// mean limiting shear stress τ̄ (Pa) and film thickness h (m); then
    /// μ = τ̄πab/N and m = (8/3)Ḡa²b/(Nh) depend on the load.
    Physical {
        /// Mean elastic shear modulus Ḡ of the film, Pa.
        shear_modulus: f64,
        /// Mean limiting shear stress τ̄ = μN/(πab), Pa.
        limiting_stress: f64,
        /// Film thickness h, m.
        film_thickness: f64,
    },
    /// One of the report's fluids through its correlations (traction-fluids):
    /// m(P0, |U|, θ, k) and μ(P0, |U|, θ, k) at the state, with the data
    /// envelope applied by `envelope`; if `spin_peak`, the forces are scaled
    /// by the spin-peak correlation μ_s(P0, |U|, θ, k, |Z|) (for every Z,
    /// including 0, so that the forces stay continuous in ω).
    Report {
        /// The fluid's correlations (printed coefficients or a refit).
        fluid: Arc<traction_fluids::Fluid>,
        /// What to do outside the data envelope.
        envelope: EnvelopeRule,
        /// Scale the forces by the spin-peak μ_s correlation.
        spin_peak: bool,
        /// User m and μ at the inlet temperature ([`Fluid::with_inlet_values`]):
        /// used instead of the correlations' values, which then supply only
        /// the temperature dependence of the thermal model.
        at_inlet: Option<InletValues>,
    },
}

/// Measured m and μ of a report fluid at the inlet temperature of the state
/// ([`Fluid::with_inlet_values`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InletValues {
    /// Traction slope m at the inlet temperature.
    pub slope: f64,
    /// Peak traction coefficient μ at the inlet temperature.
    pub peak: f64,
}

/// What a report fluid does outside the envelope (box) of its data: P0, |U|,
/// θ, k and, for the spin-peak correlation, |Z| = |ω|√(ab)/|U|.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum EnvelopeRule {
    /// Error naming the quantity, its value and the data range (the fluids
    /// crate's [`traction_fluids::Policy::Strict`]).
    #[default]
    Strict,
    /// Evaluate the correlation outside the data, flagged in
    /// [`Evaluation::outside_envelope`](crate::Evaluation::outside_envelope).
    Extrapolate,
    /// Evaluate at the nearest point of the envelope (each variable clamped to
    /// its data range), flagged in [`Evaluation::outside_envelope`](crate::Evaluation::outside_envelope): bounded
    /// properties for simulators that pass through start-up (U → 0).
    Clamp,
}

/// Which correlation variables were outside the data envelope (report fluids
/// only; all false otherwise).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct OutsideEnvelope {
    /// Hertz pressure P0.
    pub p0: bool,
    /// Rolling speed |U|.
    pub speed: bool,
    /// Inlet temperature θ.
    pub temperature: bool,
    /// Aspect ratio k.
    pub k: bool,
    /// Spin parameter |Z| (spin-peak correlation).
    pub z: bool,
}

impl OutsideEnvelope {
    /// True if any variable was outside.
    pub fn any(&self) -> bool {
        self.p0 || self.speed || self.temperature || self.k || self.z
    }
}

/// A report fluid's correlations, built once per process.
type ReportFluid = OnceLock<Result<Arc<traction_fluids::Fluid>, traction_fluids::FluidError>>;

/// The report fluid that `build` gives, built on first use and shared after
/// it: reading the compiled-in data takes 0.1–0.3 ms for Santotrac 50 and,
/// with the refit of App. III-F, 0.3–0.7 ms for TDF-88, which every contact
/// (and every FMU instance and parameter change) would otherwise pay.
fn report_fluid(
    cell: &'static ReportFluid,
    build: fn() -> Result<traction_fluids::Fluid, traction_fluids::FluidError>,
) -> Result<Arc<traction_fluids::Fluid>, ContactError> {
    Ok(cell.get_or_init(|| build().map(Arc::new)).clone()?)
}

impl Fluid {
    /// Santotrac 50 with the report's printed coefficients (App. III-A, III-C,
    /// III-E), the given envelope rule, forces scaled by μ (no spin peak).
    pub fn santotrac_50(envelope: EnvelopeRule) -> Result<Fluid, ContactError> {
        static FLUID: ReportFluid = OnceLock::new();
        Ok(Fluid::Report {
            fluid: report_fluid(&FLUID, traction_fluids::Fluid::santotrac_50)?,
            envelope,
            spin_peak: false,
            at_inlet: None,
        })
    }

    /// TDF-88 with the report's printed coefficients (App. III-B, III-D; the
    /// spin μ is the fluids crate's refit of III-F).
    pub fn tdf_88(envelope: EnvelopeRule) -> Result<Fluid, ContactError> {
        static FLUID: ReportFluid = OnceLock::new();
        Ok(Fluid::Report {
            fluid: report_fluid(&FLUID, traction_fluids::Fluid::tdf_88)?,
            envelope,
            spin_peak: false,
            at_inlet: None,
        })
    }

    /// User m and μ; checks m in [`SLOPE_RANGE`] and μ in
    /// [`TRACTION_COEFFICIENT_RANGE`].
    pub fn constant(slope: f64, peak: f64) -> Result<Fluid, ContactError> {
        let f = Fluid::Constant {
            slope,
            peak,
            spin_peak: None,
        };
        f.validate()?;
        Ok(f)
    }

    /// Physical Ḡ (Pa), τ̄ (Pa), h (m), each finite and > 0.
    pub fn physical(
        shear_modulus: f64,
        limiting_stress: f64,
        film_thickness: f64,
    ) -> Result<Fluid, ContactError> {
        let f = Fluid::Physical {
            shear_modulus,
            limiting_stress,
            film_thickness,
        };
        f.validate()?;
        Ok(f)
    }

    /// Add the spin-peak traction coefficient μ_s (only for [`Fluid::Constant`]):
    /// forces become μ_s N J while the J groups keep the zero-spin μ (the
    /// report's Appendix VI "J5*MS" column).
    pub fn with_spin_peak(self, spin_peak: f64) -> Result<Fluid, ContactError> {
        match self {
            Fluid::Constant { slope, peak, .. } => {
                let f = Fluid::Constant {
                    slope,
                    peak,
                    spin_peak: Some(spin_peak),
                };
                f.validate()?;
                Ok(f)
            }
            _ => Err(ContactError::OutOfRange {
                quantity: "spin-peak traction coefficient μ_s",
                value: spin_peak,
                valid: "given only with user m and μ (Fluid::Constant; report fluids: use_spin_peak)",
            }),
        }
    }

    /// For a report fluid: scale the forces by its spin-peak μ_s correlation.
    pub fn use_spin_peak(self, on: bool) -> Fluid {
        match self {
            Fluid::Report {
                fluid,
                envelope,
                at_inlet,
                ..
            } => Fluid::Report {
                fluid,
                envelope,
                spin_peak: on,
                at_inlet,
            },
            other => other,
        }
    }

    /// For a report fluid: use the user's m and μ at the inlet temperature
    /// instead of the correlations' values (m in [`SLOPE_RANGE`], μ in
    /// [`TRACTION_COEFFICIENT_RANGE`]); the correlations then supply the
    /// temperature dependence of the thermal model only. Other fluids: error.
    pub fn with_inlet_values(self, slope: f64, peak: f64) -> Result<Fluid, ContactError> {
        match self {
            Fluid::Report {
                fluid,
                envelope,
                spin_peak,
                ..
            } => {
                let f = Fluid::Report {
                    fluid,
                    envelope,
                    spin_peak,
                    at_inlet: Some(InletValues { slope, peak }),
                };
                f.validate()?;
                Ok(f)
            }
            _ => Err(ContactError::OutOfRange {
                quantity: "inlet values m, μ of a report fluid",
                value: slope,
                valid: "given only for a report fluid (Fluid::Report)",
            }),
        }
    }

    pub(crate) fn validate(&self) -> Result<(), ContactError> {
        match *self {
            Fluid::Constant {
                slope,
                peak,
                spin_peak,
            } => {
                SLOPE_RANGE.check("traction slope m", slope)?;
                TRACTION_COEFFICIENT_RANGE.check("peak traction coefficient μ", peak)?;
                if let Some(s) = spin_peak {
                    TRACTION_COEFFICIENT_RANGE.check("spin-peak traction coefficient μ_s", s)?;
                }
            }
            Fluid::Physical {
                shear_modulus,
                limiting_stress,
                film_thickness,
            } => {
                let pa = Range::POSITIVE.with_unit("Pa");
                pa.check("fluid shear modulus Ḡ", shear_modulus)?;
                pa.check("limiting shear stress τ̄", limiting_stress)?;
                Range::POSITIVE
                    .with_unit("m")
                    .check("film thickness h", film_thickness)?;
            }
            Fluid::Report { at_inlet, .. } => {
                if let Some(v) = at_inlet {
                    Fluid::constant(v.slope, v.peak)?;
                }
            }
        }
        Ok(())
    }
}

/// Evaluate one correlation under the envelope rule, recording the flags.
pub(crate) fn correlate(
    c: &traction_fluids::FluidCorrelation,
    q: traction_fluids::Query,
    rule: EnvelopeRule,
    flags: &mut OutsideEnvelope,
) -> Result<f64, ContactError> {
    let e = &c.envelope;
    let out = |x: f64, (lo, hi): (f64, f64)| {
        let tol = 1e-9 * hi.abs().max(lo.abs());
        x < lo - tol || x > hi + tol
    };
    let o = [
        out(q.p0_pa, e.p0_pa),
        out(q.speed_m_s, e.speed_m_s),
        out(q.theta_celsius, e.theta_celsius),
        out(q.k, e.k),
        out(q.z, e.z),
    ];
    let value = match rule {
        EnvelopeRule::Strict => c.evaluate(&q, traction_fluids::Policy::Strict)?.value,
        EnvelopeRule::Extrapolate => c.evaluate(&q, traction_fluids::Policy::Extrapolate)?.value,
        EnvelopeRule::Clamp => {
            let cl = |x: f64, (lo, hi): (f64, f64)| x.clamp(lo.min(hi), hi.max(lo));
            let qc = traction_fluids::Query {
                p0_pa: cl(q.p0_pa, e.p0_pa),
                speed_m_s: cl(q.speed_m_s, e.speed_m_s),
                theta_celsius: cl(q.theta_celsius, e.theta_celsius),
                k: cl(q.k, e.k),
                z: cl(q.z, e.z),
            };
            c.evaluate(&qc, traction_fluids::Policy::Strict)?.value
        }
    };
    flags.p0 |= o[0];
    flags.speed |= o[1];
    flags.temperature |= o[2];
    flags.k |= o[3];
    flags.z |= o[4];
    Ok(value)
}
