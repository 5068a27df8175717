//! The physics seam: the one place where the FMU asks for contact forces.
//!
//! [`Contact::new`] and [`Contact::evaluate`] forward to `traction-contact`,
//! which composes traction-hertz (Hertz contact, report section
//! 2-1), traction-fluids (the Santotrac 50 and TDF-88 correlations,
//! Appendices II, III), traction-compliance (Kalker disc compliance, Appendix
//! IV A, B) and traction-rheology (the Johnson & Tevaarwerk models with slip,
//! side slip and spin, Appendices IV, V). This module only translates the
//! FMU's parameters and inputs into that crate's types and back, so the rest of
//! the FMU does not depend on its API.
//!
//! FMU-level choices made here:
//!
//! * a radius of 0 means a flat profile (`±∞` is accepted too), negative means
//!   concave;
//! * a normal load `N ≤ 0` means the bodies separate: every force, size and J
//!   group is 0 and the regime is [`Regime::Open`];
//! * with the compliance correction on, the user's slope `m` is taken as
//!   measured in side slip (as the report measured it, Table 4-3). The disc
//!   compliance of traction-contact (`Compliance::Discs`) takes *one* disc
//!   material (it assumes both discs alike); the FMU passes the material of
//!   Kalker's combined elastic constants of the two bodies ([`kalker_combined`]):
//!   `1/G = (1/G1 + 1/G2)/2`, `ν/G = (ν1/G1 + ν2/G2)/2`, `E = 2G(1 + ν)`,
//!   with `G_i = E_i/(2(1 + ν_i))`. For identical bodies this is the body
//!   material itself; for dissimilar ones it is the quasi-identical
//!   approximation of Kalker's linear theory (the coupling between normal
//!   and tangential tractions through the difference of the bodies'
//!   `(1 − 2ν)/G` is neglected; it vanishes for identical bodies, the case of
//!   the report's Kalker coefficients);
//! * the rolling-speed floor `U_reg` of traction-contact keeps the forces
//!   finite and continuous through U = 0 and zero at zero relative motion:
//!   the J groups use `max(|U|, U_reg)`, and the forward and reversed rolling
//!   solutions are blended within `|U| < U_reg` (traction-contact's docs);
//! * the fluid correlations use the envelope rule the user chose (default
//!   clamp, so that start-up through U = 0 stays evaluable); the FMU logs a
//!   warning the first time a state lies outside the data.
//!
//! * the viscoelastic model takes the Deborah number `D = ηU/(Ḡa)` and the
//!   sinh reference stress `Z0 = τ0/τ̄` as parameters (`deborah`, `z0`, each
//!   `> 0`, `+∞` allowed): traction-contact takes `D` itself (its
//!   `Options::model`), not the viscosity, so `D` is a constant of the
//!   simulation and does not follow `U` or `a`. `D = ∞` is the
//!   elastic/plastic model exactly, `Z0 = ∞` the linear Maxwell fluid;
//! * with `use_spin_peak` the forces are scaled by the spin-peak traction
//!   coefficient `μ_s` (traction-contact's `Fluid::with_spin_peak` for the
//!   user fluid, `Fluid::use_spin_peak` for the report fluids' correlation)
//!   while the J groups keep the zero-spin `μ`.

use traction_contact::{
    Body, Compliance, ContactError, DEBORAH_RANGE, Direction, DiscMaterial, EnvelopeRule,
    KALKER_POISSON_RANGE, Model, OperatingState, Options, OutOfRange, REFERENCE_STRESS_RANGE,
    ROLLING_SPEED_FLOOR_RANGE, Range, SLOPE_RANGE, TractionContact, thermal,
};

/// Valid `mu_user` and `mu_spin_user`: (0, 1). Narrower on purpose than
/// traction-contact's [`traction_contact::TRACTION_COEFFICIENT_RANGE`]
/// (0, 10]: a lubricated traction contact runs at 0.02..0.15, so a value of 1
/// or more is a unit slip (a percentage) rather than a fluid, and the FMU
/// refuses it by name.
pub const MU_USER_RANGE: Range = Range::open(0.0, 1.0);

/// Valid `rheology_tolerance`: [1e-6, 1e-2]. Narrower on purpose than
/// traction-rheology's [`traction_contact::TOLERANCE_RANGE`] [1e-9, 0.1]: the
/// range the FMU is tested over, with the coarse end at the top of the
/// rheology map's own range (1e-2) and the fine end where a direct evaluation
/// with spin still fits a co-simulation step (the strip integration's work
/// grows as the tolerance falls).
pub const TOLERANCE_RANGE: Range = Range::closed(1e-6, 1e-2);

/// Valid `mu_rise_scale`: [1e-3, 1e6] K. Narrower than traction-contact's
/// [`traction_contact::thermal::RISE_SCALE_RANGE`] (0, ∞]: an FMI Real
/// parameter has a finite default, so "no second-order term" is the default
/// 1e6 K (ΔT²/T*² < 4e-6 below the fixed point's 2000 K runaway limit).
pub const MU_RISE_SCALE_RANGE: Range = Range::closed(1e-3, 1e6).with_unit("K");

/// The fluid whose slope `m` and peak `μ` the contact uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fluid {
    /// Santotrac 50, through the report's correlations (Appendix III-A).
    Santotrac50,
    /// TDF-88, through the report's correlations (Appendix III-B).
    Tdf88,
    /// The user's `m` and `μ` (parameters `m_user`, `mu_user`).
    User,
}

/// What the report fluids' correlations do outside their data.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Envelope {
    /// Error naming the quantity and the data range.
    Strict,
    /// Evaluate the correlation outside the data (flagged).
    Extrapolate,
    /// Evaluate at the nearest point of the data envelope (flagged).
    Clamp,
}

/// The rheological model of the film.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rheology {
    /// Johnson & Tevaarwerk elastic/plastic (default).
    ElasticPlastic,
    /// Rigid/plastic.
    RigidPlastic,
    /// Viscoelastic sinh law with the limit as a cap (parameters
    /// [`Parameters::deborah`], [`Parameters::z0`]).
    Viscoelastic,
}

/// A code that is not one of an enumeration's items (the FMU's
/// Enumeration variables convert with `TryFrom<i32>`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("{0} is not a code of this enumeration")]
pub struct UnknownCode(pub i32);

/// Codes of the Enumeration `Fluid`: 1 Santotrac 50, 2 TDF-88, 3 user.
impl TryFrom<i32> for Fluid {
    type Error = UnknownCode;
    fn try_from(code: i32) -> Result<Self, UnknownCode> {
        match code {
            1 => Ok(Self::Santotrac50),
            2 => Ok(Self::Tdf88),
            3 => Ok(Self::User),
            _ => Err(UnknownCode(code)),
        }
    }
}

/// Codes of the Enumeration `EnvelopeRule`: 1 strict, 2 extrapolate, 3 clamp.
impl TryFrom<i32> for Envelope {
    type Error = UnknownCode;
    fn try_from(code: i32) -> Result<Self, UnknownCode> {
        match code {
            1 => Ok(Self::Strict),
            2 => Ok(Self::Extrapolate),
            3 => Ok(Self::Clamp),
            _ => Err(UnknownCode(code)),
        }
    }
}

/// Codes of the Enumeration `RheologyModel`: 1 elastic/plastic, 2
/// rigid/plastic, 3 viscoelastic.
impl TryFrom<i32> for Rheology {
    type Error = UnknownCode;
    fn try_from(code: i32) -> Result<Self, UnknownCode> {
        match code {
            1 => Ok(Self::ElasticPlastic),
            2 => Ok(Self::RigidPlastic),
            3 => Ok(Self::Viscoelastic),
            _ => Err(UnknownCode(code)),
        }
    }
}

/// The regime of Appendix IV figure 14, plus an open contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Regime {
    /// N ≤ 0: the bodies do not touch.
    Open = 0,
    /// Region I: elastic/plastic analysis without spin suffices.
    ElasticNoSpin = 1,
    /// Region II: elastic/plastic analysis with spin is required.
    ElasticWithSpin = 2,
    /// Region III: rigid/plastic analysis with spin suffices.
    RigidPlastic = 3,
}

/// Geometry, materials, fluid and options of the contact (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parameters {
    /// Body 1 radius of curvature in the rolling (x) direction, m (0 or ±∞: flat).
    pub rx1: f64,
    /// Body 1 radius of curvature across (y), m (0 or ±∞: flat).
    pub ry1: f64,
    /// Body 2 radius of curvature in the rolling (x) direction, m.
    pub rx2: f64,
    /// Body 2 radius of curvature across (y), m.
    pub ry2: f64,
    /// Young's modulus of body 1, Pa.
    pub e1: f64,
    /// Poisson's ratio of body 1 (dimensionless).
    pub nu1: f64,
    /// Young's modulus of body 2, Pa.
    pub e2: f64,
    /// Poisson's ratio of body 2 (dimensionless).
    pub nu2: f64,
    /// Fluid.
    pub fluid: Fluid,
    /// Envelope rule of the report fluids' correlations.
    pub envelope: Envelope,
    /// Initial traction slope m (dimensionless), used when `fluid` is `User`.
    pub m_user: f64,
    /// Peak traction coefficient μ (dimensionless), used when `fluid` is `User`.
    pub mu_user: f64,
    /// Rheological model.
    pub rheology: Rheology,
    /// Deborah number D = ηU/(Ḡa) of the viscoelastic model (dimensionless,
    /// > 0, `+∞` = elastic/plastic); a constant of the simulation.
    pub deborah: f64,
    /// Sinh reference stress Z0 = τ0/τ̄ of the viscoelastic model
    /// (dimensionless, > 0, `+∞` = linear Maxwell fluid).
    pub z0: f64,
    /// Scale the forces by the spin-peak traction coefficient μ_s.
    pub spin_peak: bool,
    /// Spin-peak traction coefficient μ_s (dimensionless), used when `fluid`
    /// is `User` and `spin_peak` is set.
    pub mu_spin_user: f64,
    /// Disc-compliance correction of the slope (Appendix IV A, B).
    pub compliance: bool,
    /// Rolling-speed regularisation U_reg, m/s (in traction-contact's
    /// [`ROLLING_SPEED_FLOOR_RANGE`]).
    pub u_reg: f64,
    /// Absolute accuracy of J4, J5, J6 of the rheology, in [`TOLERANCE_RANGE`].
    pub tolerance: f64,
    /// Interpolation map of the J+T model (traction-contact `Options::map`).
    pub map: bool,
    /// Thermal contact (traction-contact `Options::thermal`).
    pub thermal: bool,
    /// Film thickness h of the thermal model for the user fluid, m.
    pub film_thickness: f64,
    /// Thermal conductivity k_f of the user fluid, W/(m·K).
    pub fluid_conductivity: f64,
    /// Temperature coefficient β_μ of the user fluid's μ, 1/K.
    pub mu_temperature_coefficient: f64,
    /// Temperature coefficient β_m of the user fluid's m, 1/K.
    pub m_temperature_coefficient: f64,
    /// Temperature scale T* of the second-order term of the user fluid's μ
    /// law, K (traction-contact `Thermal::mu_rise_scale`; 1e6 K: the
    /// first-order law to within 4e-6 of μ).
    pub mu_rise_scale: f64,
}

/// One operating state of the contact (SI units).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Inputs {
    /// Normal load N, N (≤ 0: contact open).
    pub load: f64,
    /// Rolling speed U = (u1 + u2)/2, m/s.
    pub u: f64,
    /// Slip ΔU = u1 − u2, m/s.
    pub du: f64,
    /// Side slip ΔV, m/s.
    pub dv: f64,
    /// Spin ω about the contact normal, rad/s.
    pub omega: f64,
    /// Inlet temperature, °C.
    pub inlet_temperature_celsius: f64,
}

/// What the contact gives back (SI units; J groups dimensionless).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Outputs {
    /// Traction force along x on body 2 (from body 1), N.
    pub fx: f64,
    /// Traction force along y on body 2 (from body 1), N.
    pub fy: f64,
    /// Spin moment about the contact normal on body 2, N·m.
    pub mz: f64,
    /// Semi-axis along x, m.
    pub a: f64,
    /// Semi-axis across, m.
    pub b: f64,
    /// Aspect ratio k = b/a (dimensionless; 0 when open).
    pub k: f64,
    /// Maximum Hertz pressure P0, Pa.
    pub p0: f64,
    /// Slope m used (dimensionless).
    pub m: f64,
    /// Zero-spin peak traction coefficient μ used in the J groups (dimensionless).
    pub mu: f64,
    /// Traction coefficient μ_f that scales the forces: μ, or μ_s with the
    /// spin peak (dimensionless).
    pub mu_force: f64,
    /// J1..J7 (dimensionless), `j[0]` is J1.
    pub j: [f64; 7],
    /// Regime.
    pub regime: Option<Regime>,
    /// A report fluid's correlation was used outside its data envelope.
    pub outside_envelope: bool,
    /// Mean film temperature rise over the inlet (thermal model), K; 0
    /// without it.
    pub temperature_rise: f64,
}

/// Why the contact cannot be built or evaluated. Each message names the
/// quantity and its valid range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PhysicsError {
    /// A parameter or input is NaN or outside its valid range (the message
    /// names the variable, its value and the range).
    #[error(transparent)]
    OutOfRange(#[from] OutOfRange),
    /// traction-contact refused the contact or the state (its message and
    /// sources, unchanged).
    #[error(transparent)]
    Contact(#[from] ContactError),
}

/// A radius as traction-hertz takes it: 0 and ±∞ mean flat (∞); NaN is
/// refused (`name` says what the values mean).
fn radius(name: &'static str, r: f64) -> Result<f64, PhysicsError> {
    Range::FINITE.with_infinity().check(name, r)?;
    Ok(if r == 0.0 || r.is_infinite() {
        f64::INFINITY
    } else {
        r
    })
}

/// Kalker's combined elastic constants of two bodies, as one disc material:
/// `1/G = (1/G1 + 1/G2)/2`, `ν/G = (ν1/G1 + ν2/G2)/2`, `E = 2G(1 + ν)`,
/// `G_i = E_i/(2(1 + ν_i))`. Identical bodies give their own material.
pub fn kalker_combined(e1: f64, nu1: f64, e2: f64, nu2: f64) -> DiscMaterial {
    let (g1, g2) = (e1 / (2.0 * (1.0 + nu1)), e2 / (2.0 * (1.0 + nu2)));
    if g1 == g2 && nu1 == nu2 {
        return DiscMaterial {
            youngs_modulus: e1,
            poisson_ratio: nu1,
        };
    }
    let g = 2.0 / (1.0 / g1 + 1.0 / g2);
    let nu = 0.5 * g * (nu1 / g1 + nu2 / g2);
    DiscMaterial {
        youngs_modulus: 2.0 * g * (1.0 + nu),
        poisson_ratio: nu,
    }
}

/// The thermal model of the parameters: the report fluids' own property set
/// (traction-fluids `ThermalProperties`), or the user fluid's film thickness,
/// conductivity and temperature coefficients, checked here against the
/// ranges of traction-contact's `Thermal::validate` so that the error names
/// the FMU parameter.
fn thermal(p: &Parameters) -> Result<Option<traction_contact::Thermal>, PhysicsError> {
    if !p.thermal {
        return Ok(None);
    }
    Ok(Some(match p.fluid {
        Fluid::User => {
            let (h, k) = (p.film_thickness, p.fluid_conductivity);
            thermal::FILM_THICKNESS_RANGE.check("film_thickness", h)?;
            thermal::CONDUCTIVITY_RANGE.check("fluid_conductivity", k)?;
            for (name, b) in [
                ("mu_temperature_coefficient", p.mu_temperature_coefficient),
                ("m_temperature_coefficient", p.m_temperature_coefficient),
            ] {
                thermal::TEMPERATURE_COEFFICIENT_RANGE.check(name, b)?;
            }
            MU_RISE_SCALE_RANGE.check("mu_rise_scale", p.mu_rise_scale)?;
            traction_contact::Thermal {
                film: traction_contact::Film::Thickness(h),
                fluid_conductivity: Some(k),
                mu_coefficient: Some(p.mu_temperature_coefficient),
                slope_coefficient: Some(p.m_temperature_coefficient),
                mu_rise_scale: Some(p.mu_rise_scale),
                ..traction_contact::Thermal::default()
            }
        }
        Fluid::Santotrac50 | Fluid::Tdf88 => traction_contact::Thermal::default(),
    }))
}

/// The contact, built once from its parameters.
#[derive(Debug, Clone)]
pub struct Contact {
    params: Parameters,
    contact: TractionContact,
}

impl Contact {
    /// Move the contact's rheology map out (to keep it across a rebuild).
    pub fn take_map(&self) -> Option<traction_contact::Map> {
        self.contact.take_map()
    }

    /// Adopt the map of a previous contact when k and the tolerance match.
    pub fn adopt_map(&self, map: traction_contact::Map) -> bool {
        self.contact.adopt_map(map)
    }

    /// Validates the parameters and builds the traction-contact model.
    ///
    /// # Errors
    /// A [`PhysicsError`] naming the first invalid parameter.
    pub fn new(p: &Parameters) -> Result<Self, PhysicsError> {
        const R: [&str; 4] = [
            "rx1 (radius in m; 0 or inf: flat, negative: concave)",
            "ry1 (radius in m; 0 or inf: flat, negative: concave)",
            "rx2 (radius in m; 0 or inf: flat, negative: concave)",
            "ry2 (radius in m; 0 or inf: flat, negative: concave)",
        ];
        let b1 = Body::new(radius(R[0], p.rx1)?, radius(R[1], p.ry1)?, p.e1, p.nu1);
        let b2 = Body::new(radius(R[2], p.rx2)?, radius(R[3], p.ry2)?, p.e2, p.nu2);
        ROLLING_SPEED_FLOOR_RANGE.check("rolling_speed_regularisation", p.u_reg)?;
        let envelope = match p.envelope {
            Envelope::Strict => EnvelopeRule::Strict,
            Envelope::Extrapolate => EnvelopeRule::Extrapolate,
            Envelope::Clamp => EnvelopeRule::Clamp,
        };
        let fluid = match p.fluid {
            Fluid::User => {
                SLOPE_RANGE.check("m_user (initial traction slope)", p.m_user)?;
                MU_USER_RANGE.check("mu_user (peak traction coefficient)", p.mu_user)?;
                let f = traction_contact::Fluid::constant(p.m_user, p.mu_user)?;
                if p.spin_peak {
                    MU_USER_RANGE.check(
                        "mu_spin_user (spin-peak traction coefficient)",
                        p.mu_spin_user,
                    )?;
                    f.with_spin_peak(p.mu_spin_user)?
                } else {
                    f
                }
            }
            Fluid::Santotrac50 => {
                traction_contact::Fluid::santotrac_50(envelope)?.use_spin_peak(p.spin_peak)
            }
            Fluid::Tdf88 => traction_contact::Fluid::tdf_88(envelope)?.use_spin_peak(p.spin_peak),
        };
        let model = match p.rheology {
            Rheology::ElasticPlastic => Model::ElasticPlastic,
            Rheology::RigidPlastic => Model::RigidPlastic,
            Rheology::Viscoelastic => {
                DEBORAH_RANGE.check(
                    "deborah (Deborah number D = eta U/(G a); inf: elastic/plastic)",
                    p.deborah,
                )?;
                REFERENCE_STRESS_RANGE.check(
                    "z0 (sinh reference stress Z0 = tau0/tau_bar; inf: linear Maxwell fluid)",
                    p.z0,
                )?;
                if p.deborah == f64::INFINITY {
                    // D = ∞ is the elastic/plastic model exactly (the
                    // rheology crate returns it); naming it so lets
                    // rheology_map apply to it as well.
                    Model::ElasticPlastic
                } else {
                    Model::Viscoelastic {
                        deborah: p.deborah,
                        z0: p.z0,
                    }
                }
            }
        };
        let compliance = if p.compliance {
            let material = kalker_combined(p.e1, p.nu1, p.e2, p.nu2);
            KALKER_POISSON_RANGE.check(
                "nu1, nu2 (compliance_correction: Kalker's combined Poisson's ratio of the two bodies)",
                material.poisson_ratio,
            )?;
            Compliance::Discs {
                material,
                slope_measured_in: Direction::Side,
            }
        } else {
            Compliance::Off
        };
        TOLERANCE_RANGE.check(
            "rheology_tolerance (absolute accuracy of J4, J5, J6)",
            p.tolerance,
        )?;
        let accuracy = traction_contact::Accuracy::new(p.tolerance)
            .map_err(|e| PhysicsError::Contact(e.into()))?;
        let options = Options {
            model,
            accuracy,
            compliance,
            rolling_speed_floor: p.u_reg,
            map: p.map,
            thermal: thermal(p)?,
            ..Options::default()
        };
        let contact = TractionContact::new(&b1, &b2, fluid, options)?;
        Ok(Self {
            params: *p,
            contact,
        })
    }

    /// The parameters the contact was built from.
    pub fn parameters(&self) -> &Parameters {
        &self.params
    }

    /// Evaluates the contact at one operating state.
    ///
    /// # Errors
    /// [`PhysicsError`] when an input is NaN, infinite or out of the model's
    /// range, or a correlation fails (strict envelope).
    pub fn evaluate(&self, i: &Inputs) -> Result<Outputs, PhysicsError> {
        Range::FINITE.check("normal_load (N; <= 0 opens the contact)", i.load)?;
        let state = OperatingState::new(
            i.load.max(0.0),
            i.u,
            i.du,
            i.dv,
            i.omega,
            i.inlet_temperature_celsius,
        )?;
        let r = self.contact.evaluate(&state)?;
        if i.load <= 0.0 {
            return Ok(Outputs {
                m: r.m_used,
                mu: r.mu_used,
                mu_force: r.mu_force,
                regime: Some(Regime::Open),
                ..Outputs::default()
            });
        }
        let regime = match r.regime {
            traction_contact::Regime::ElasticWithSpin => Regime::ElasticWithSpin,
            traction_contact::Regime::RigidPlastic => Regime::RigidPlastic,
            _ => Regime::ElasticNoSpin,
        };
        Ok(Outputs {
            fx: r.fx,
            fy: r.fy,
            mz: r.mz,
            a: r.a,
            b: r.b,
            k: r.k,
            p0: r.p0,
            m: r.m_used,
            mu: r.mu_used,
            mu_force: r.mu_force,
            j: [r.j1, r.j2, r.j3, r.j4, r.j5, r.j6, r.j7],
            regime: Some(regime),
            outside_envelope: r.outside_envelope.any(),
            temperature_rise: r.temperature_rise,
        })
    }
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use super::*;

    /// Complete elliptic integrals K(m), E(m) by the arithmetic-geometric mean
    /// (an independent Hertz reference, not the code traction-hertz uses).
    fn elliptic_ke(m: f64) -> (f64, f64) {
        let (mut a, mut b) = (1.0_f64, (1.0 - m).sqrt());
        let (mut sum, mut pow) = (0.5 * m, 0.5);
        for _ in 0..40 {
            if (a - b).abs() <= 1e-16 * a {
                break;
            }
            let cn = 0.5 * (a - b);
            (a, b) = (0.5 * (a + b), (a * b).sqrt());
            pow *= 2.0;
            sum += pow * cn * cn;
        }
        let k = PI / (2.0 * a);
        (k, k * (1.0 - sum))
    }

    /// Hertz: curvature ratio large/small for the semi-axis ratio κ = minor/major.
    fn curvature_ratio(kappa: f64) -> f64 {
        let (k, e) = elliptic_ke(1.0 - kappa * kappa);
        (e / (kappa * kappa) - k) / (k - e)
    }

    fn steel_twin_disc() -> Parameters {
        // High speed machine, k = 1 discs of Table 2-1 (upper Rx 33, Ry 22.6;
        // lower Rx 71.4, Ry flat), steel.
        Parameters {
            rx1: 0.033,
            ry1: 0.0226,
            rx2: 0.0714,
            ry2: 0.0,
            e1: 2.07e11,
            nu1: 0.3,
            e2: 2.07e11,
            nu2: 0.3,
            fluid: Fluid::User,
            envelope: Envelope::Clamp,
            m_user: 35.0,
            mu_user: 0.075,
            rheology: Rheology::ElasticPlastic,
            deborah: 1.0,
            z0: 1.0,
            spin_peak: false,
            mu_spin_user: 0.075,
            compliance: false,
            u_reg: 0.01,
            tolerance: 1e-4,
            map: true,
            thermal: false,
            film_thickness: 0.5e-6,
            fluid_conductivity: 0.11,
            mu_temperature_coefficient: 0.0025,
            m_temperature_coefficient: 0.0,
            mu_rise_scale: 1e6,
        }
    }

    fn sphere_on_flat(r: f64) -> Parameters {
        Parameters {
            rx1: r,
            ry1: r,
            rx2: 0.0,
            ry2: f64::INFINITY,
            ..steel_twin_disc()
        }
    }

    fn op(load: f64, u: f64, du: f64, dv: f64) -> Inputs {
        Inputs {
            load,
            u,
            du,
            dv,
            omega: 0.0,
            inlet_temperature_celsius: 40.0,
        }
    }

    #[test]
    fn elliptic_integrals_match_tabulated_values() {
        // Abramowitz & Stegun table 17.1: K(0.5) = 1.854074677, E(0.5) = 1.350643881.
        let (k, e) = elliptic_ke(0.5);
        assert!((k - 1.854_074_677_301_372).abs() < 1e-12);
        assert!((e - 1.350_643_881_047_675).abs() < 1e-12);
        let (k0, e0) = elliptic_ke(0.0);
        assert!((k0 - PI / 2.0).abs() < 1e-15 && (e0 - PI / 2.0).abs() < 1e-15);
    }

    #[test]
    fn circular_hertz_matches_closed_form() {
        // Sphere R = 10 mm on a flat, N = 100 N: a³ = 3NR/(4E*), P0 = 3N/(2πa²).
        let p = sphere_on_flat(0.01);
        let c = Contact::new(&p).unwrap();
        let o = c.evaluate(&op(100.0, 1.0, 0.0, 0.0)).unwrap();
        let e_star: f64 = 2.07e11 / (2.0 * (1.0 - 0.09));
        let a = (3.0 * 100.0 * 0.01 / (4.0 * e_star)).cbrt();
        assert!((o.a - a).abs() < 1e-12 * a.max(1.0), "{} vs {a}", o.a);
        assert!((o.b - a).abs() < 1e-12);
        assert!((o.k - 1.0).abs() < 1e-12);
        assert!((o.p0 - 3.0 * 100.0 / (2.0 * PI * a * a)).abs() < 1e-6 * o.p0);
    }

    #[test]
    fn table_2_2_contact_size_factor() {
        // Report Table 2-2: a/P0 = C = 0.307e-12 m/Pa for the k = 1 discs of
        // the high speed machine. The report's E' for steel is not printed
        // exactly; 2 % covers E = 200..210 GPa.
        let c = Contact::new(&steel_twin_disc()).unwrap();
        let o = c.evaluate(&op(500.0, 10.0, 0.0, 0.0)).unwrap();
        let ratio = o.a / o.p0;
        assert!((ratio / 0.307e-12 - 1.0).abs() < 0.02, "C = {ratio:e}");
        assert!((o.k - 1.0).abs() < 0.01, "k = {}", o.k);
    }

    #[test]
    fn elliptical_hertz_obeys_load_balance_and_curvature_relation() {
        // k = 5 discs (upper Rx 33, Ry 270; lower Rx 71.4, flat): the minor axis is
        // along x. Check the two Hertz relations independently of the solver's
        // formulas: N = (2/3)π a b P0, and the curvature ratio equation.
        let p = Parameters {
            ry1: 0.270,
            ..steel_twin_disc()
        };
        let c = Contact::new(&p).unwrap();
        let o = c.evaluate(&op(800.0, 10.0, 0.0, 0.0)).unwrap();
        assert!(o.k > 1.0);
        assert!((2.0 / 3.0 * PI * o.a * o.b * o.p0 / 800.0 - 1.0).abs() < 1e-12);
        let (ca, cb) = (0.5 * (1.0 / 0.033 + 1.0 / 0.0714), 0.5 / 0.270);
        assert!((curvature_ratio(o.a / o.b) / (ca / cb) - 1.0).abs() < 1e-9);
        // Report Table 2-1/2-2 quote k = 5 for these discs.
        assert!((o.k - 5.0).abs() < 0.5, "k = {}", o.k);
        // Swapping x and y swaps a and b.
        let q = Parameters {
            rx1: 0.270,
            ry1: 0.033,
            rx2: 0.0,
            ry2: 0.0714,
            ..p
        };
        let o2 = Contact::new(&q)
            .unwrap()
            .evaluate(&op(800.0, 10.0, 0.0, 0.0))
            .unwrap();
        assert!((o2.a - o.b).abs() < 1e-15 && (o2.b - o.a).abs() < 1e-15);
    }

    /// ψ written as printed in Appendix V (eq. 22, 23).
    fn psi_hand(s: f64) -> f64 {
        (PI / 2.0 - ((1.0 - s * s) / (1.0 + s * s)).asin() + 2.0 * s / (s * s + 1.0)) / PI
    }

    #[test]
    fn traction_matches_hand_calculation() {
        let p = steel_twin_disc();
        let c = Contact::new(&p).unwrap();
        for &(du, dv) in &[
            (0.05, 0.0),
            (0.2, 0.1),
            (-0.02, 0.3),
            (1.0, -1.0),
            (0.0001, 0.0),
        ] {
            let (load, u) = (600.0, 20.0);
            let o = c.evaluate(&op(load, u, du, dv)).unwrap();
            let g = 3.0 * PI / 8.0 * (35.0 / 0.075) * o.k.sqrt();
            let (j1, j2) = (g * du / u, g * dv / u);
            let s = 2.0 / 3.0 * (j1 * j1 + j2 * j2).sqrt() / o.k.sqrt();
            let psi = psi_hand(s);
            let fx = 0.075 * load * psi * j1 / (j1 * j1 + j2 * j2).sqrt();
            let fy = 0.075 * load * psi * j2 / (j1 * j1 + j2 * j2).sqrt();
            assert!((o.fx - fx).abs() <= 1e-9 * load, "fx {} vs {fx}", o.fx);
            assert!((o.fy - fy).abs() <= 1e-9 * load, "fy {} vs {fy}", o.fy);
            assert!((o.j[0] - j1).abs() <= 1e-9 * j1.abs().max(1.0));
            assert!(o.j[6] >= 0.0);
        }
    }

    #[test]
    fn initial_slope_is_m_and_large_slip_gives_mu() {
        let c = Contact::new(&steel_twin_disc()).unwrap();
        let (load, u) = (600.0, 20.0);
        // Small slip: Fx/N = m ΔU/U.
        let du = 1e-6 * u;
        let o = c.evaluate(&op(load, u, du, 0.0)).unwrap();
        assert!((o.fx / load / (35.0 * du / u) - 1.0).abs() < 1e-6);
        // Large slip: Fx → μN.
        let o = c.evaluate(&op(load, u, 10.0 * u, 0.0)).unwrap();
        assert!((o.fx / (0.075 * load) - 1.0).abs() < 1e-4);
    }

    #[test]
    fn zero_rolling_speed_is_continuous_and_zero_relative_motion_gives_zero_force() {
        let c = Contact::new(&steel_twin_disc()).unwrap();
        let f = |u: f64, du: f64| c.evaluate(&op(600.0, u, du, 0.0)).unwrap().fx;
        assert_eq!(f(0.0, 0.0), 0.0);
        assert_eq!(f(20.0, 0.0), 0.0);
        // Continuity through U = 0 at fixed slip, and symmetry in U.
        for &du in &[1e-4, 1e-3, 0.1] {
            let (l, z, r) = (f(-1e-9, du), f(0.0, du), f(1e-9, du));
            assert!((l - z).abs() < 1e-9 && (r - z).abs() < 1e-9);
            assert!((f(-3.0, du) - f(3.0, du)).abs() <= 1e-12 * f(3.0, du).abs());
            // Force follows the slip direction.
            assert!(f(0.0, du) > 0.0 && f(0.0, -du) < 0.0);
            assert_eq!(f(0.0, -du), -f(0.0, du));
        }
        // Hand value at U = 0: U_eff = U_reg.
        let o = c.evaluate(&op(600.0, 0.0, 0.001, 0.0)).unwrap();
        let g = 3.0 * PI / 8.0 * (35.0 / 0.075) * o.k.sqrt();
        let s = 2.0 / 3.0 * g * 0.001 / 0.01 / o.k.sqrt();
        assert!((o.fx - 0.075 * 600.0 * psi_hand(s)).abs() < 1e-9);
    }

    #[test]
    fn small_slip_limit_has_no_cancellation() {
        // As S → 0, J4 → (8/(3π)) J1/√k, i.e. Fx → m N ΔU/U (slope m) exactly;
        // the printed asin form loses digits there, the atan form must not.
        let c = Contact::new(&steel_twin_disc()).unwrap();
        for &du in &[1e-14, 1e-10, 1e-6] {
            let o = c.evaluate(&op(600.0, 20.0, du, 0.0)).unwrap();
            let linear = 35.0 * 600.0 * du / 20.0;
            assert!(
                (o.fx / linear - 1.0).abs() < 1e-9,
                "du {du}: {} vs {linear}",
                o.fx
            );
        }
    }

    #[test]
    fn open_contact_gives_zeros_and_errors_name_the_quantity() {
        // As the FMU logs them: the error with its sources.
        let msg = |e: PhysicsError| traction_contact::error_chain(&e);
        let c = Contact::new(&steel_twin_disc()).unwrap();
        let o = c.evaluate(&op(-5.0, 20.0, 1.0, 1.0)).unwrap();
        assert_eq!((o.fx, o.fy, o.a, o.p0), (0.0, 0.0, 0.0, 0.0));
        assert_eq!(o.regime, Some(Regime::Open));
        let e = c.evaluate(&op(f64::NAN, 20.0, 1.0, 1.0)).unwrap_err();
        assert!(e.to_string().contains("normal_load"), "{e}");
        let bad = Parameters {
            mu_user: 1.5,
            ..steel_twin_disc()
        };
        assert!(
            Contact::new(&bad)
                .unwrap_err()
                .to_string()
                .contains("mu_user")
        );
        let conform = Parameters {
            rx2: -0.033,
            ..steel_twin_disc()
        };
        let e = msg(Contact::new(&conform).unwrap_err());
        assert!(e.contains("curvature"), "{e}");
        for (deborah, z0, name) in [
            (-1.0, 1.0, "deborah"),
            (0.0, 1.0, "deborah"),
            (f64::NAN, 1.0, "deborah"),
            (1.0, -2.0, "z0"),
            (1.0, f64::NAN, "z0"),
        ] {
            let visco = Parameters {
                rheology: Rheology::Viscoelastic,
                deborah,
                z0,
                ..steel_twin_disc()
            };
            let e = Contact::new(&visco).unwrap_err().to_string();
            assert!(e.starts_with(name), "{e}");
        }
        let bad_spin_peak = Parameters {
            spin_peak: true,
            mu_spin_user: -0.1,
            ..steel_twin_disc()
        };
        let e = Contact::new(&bad_spin_peak).unwrap_err().to_string();
        assert!(e.contains("mu_spin_user"), "{e}");
        let auxetic = Parameters {
            compliance: true,
            nu1: -0.5,
            nu2: -0.2,
            ..steel_twin_disc()
        };
        let e = Contact::new(&auxetic).unwrap_err().to_string();
        assert!(e.starts_with("nu1, nu2"), "{e}");
        let e = msg(c.evaluate(&op(600.0, 2e6, 1.0, 0.0)).unwrap_err());
        assert!(e.contains("rolling speed"), "{e}");
    }

    #[test]
    fn report_fluid_and_spin_come_from_traction_contact() {
        // TDF-88 inside its data (Table 2-3: 1.45 GPa, 30 m/s, 70 degC, k = 1):
        // m and mu from the correlations, no envelope flag.
        let p = Parameters {
            fluid: Fluid::Tdf88,
            envelope: Envelope::Strict,
            ..steel_twin_disc()
        };
        let c = Contact::new(&p).unwrap();
        let i = Inputs {
            load: 600.0,
            u: 30.0,
            du: 0.03,
            dv: 0.0,
            omega: 0.0,
            inlet_temperature_celsius: 70.0,
        };
        let o = c.evaluate(&i).unwrap();
        assert!(
            o.m > 1.0 && o.mu > 0.01 && o.mu < 0.2,
            "m {} mu {}",
            o.m,
            o.mu
        );
        // Spin gives a spin moment, dissipates, and keeps J7 >= 0.
        let o = c.evaluate(&Inputs { omega: 40.0, ..i }).unwrap();
        assert!(o.mz != 0.0 && o.j[5] != 0.0);
        assert!(o.fx * i.du + o.mz * 40.0 >= 0.0 && o.j[6] >= 0.0);
    }

    #[test]
    fn rigid_plastic_is_coulomb_in_the_slip_direction() {
        let p = Parameters {
            rheology: Rheology::RigidPlastic,
            ..steel_twin_disc()
        };
        let o = Contact::new(&p)
            .unwrap()
            .evaluate(&op(600.0, 20.0, 0.3, 0.4))
            .unwrap();
        assert!((o.fx - 0.075 * 600.0 * 0.6).abs() < 1e-6 * 45.0, "{}", o.fx);
        assert!((o.fy - 0.075 * 600.0 * 0.8).abs() < 1e-6 * 45.0, "{}", o.fy);
    }
}
