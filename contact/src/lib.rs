//! # traction-contact: the dimensional lubricated rolling traction contact
//!
//! "These two rollers, this fluid, this load, these speeds: what forces, spin
//! moment and losses do I get?" — in one call. The crate composes
//! `traction-hertz` (contact ellipse), the fluid description (user `m`, `μ`, or
//! physical `Ḡ`, `τ̄`, `h`), `traction-compliance` (disc compliance of the slope),
//! `traction-kinematics` (body motion → U, ΔU, ΔV, ω) and `traction-rheology`
//! (the Johnson & Tevaarwerk elastic/plastic model in the J groups). Report
//! sections 3-0, 4-0 to 4-2, Appendix IV (NASA TP 1530) and Appendix V.
//!
//! # Model and equations
//!
//! Built once ([`TractionContact::new`]) from the two bodies (principal radii,
//! E, ν; principal planes aligned, x = rolling direction), the [`Fluid`] and the
//! [`Options`]; the load-independent Hertz geometry (k, Re, E', A, B, C) and
//! Kalker's q_x, q_y are precomputed. Each [`TractionContact::evaluate`] of an
//! [`OperatingState`] (load N, rolling speed U, slip ΔU, side slip ΔV, spin ω,
//! inlet temperature θ) does:
//!
//! ```text
//! Hertz (report eq. 1, 2):   a = (3A³ Re N/E')^(1/3), b = k a, P0 = 3N/(2πab)
//! fluid:                     m, μ (user)   or   App. IV eq. 10 inverted:
//!                            μ = τ̄ π a b / N,   m = (8/3) Ḡ a² b / (N h)
//! compliance (App. IV B7):   m_x, m_y from the measured slope (see Compliance)
//! J groups (App. IV 11, 12): J1 = (3π/8)(m_x/μ)(ΔU/U)√k
//!                            J2 = (3π/8)(m_x/μ)(ΔV/U)√k
//!                            J3 = (3π/8)(m_x/μ)(ω√(ab)/U)√k
//! rheology:                  (J4, J5, J6) = J+T(k, J1, J2, J3; gy = m_y/m_x)
//! forces (App. IV 15, 16):   Fx = μ_f N J4,  Fy = μ_f N J5,  Mz = μ_f N √(ab) J6
//! losses:                    P = Fx ΔU + Fy ΔV + Mz ω  (W)
//!                            J7 = J1 J4 + J2 J5 + J3 J6 = (3π/8)√k m P/(μ² N U)  (App. IV 17)
//! ```
//!
//! `μ_f = μ` except when the user gives a spin-peak traction coefficient
//! ([`Fluid::with_spin_peak`]): then forces are `μ_s N J` with the J groups still
//! built from the zero-spin μ — the report's "J5·MS" prediction of Appendix VI.
//! `J6 = Mz/(μN√(ab))` is the normalisation the rheology crate documents (it shows
//! that App. IV eq. 16's printed prefactor is off by k); the power balance above
//! is tested here in dimensional form.
//!
//! # Sign conventions
//!
//! Those of `traction-kinematics`: body 1 is the report's "+" (upper) body,
//! `ΔU = (v₁ − v₂)·x`, `ΔV = (v₁ − v₂)·y`, `ω = (Ω₁ − Ω₂)·z`, z the normal from
//! body 2 into body 1, `(x, y, z)` right-handed. Fx, Fy and Mz are the traction
//! force and moment that body 1 exerts on body 2 (equal and opposite on body 1):
//! positive slip gives positive Fx, and the loss P ≥ 0 always.
//!
//! **Reversed rolling (U < 0).** The model is solved in the frame that rolls
//! forwards: the lab frame turned by 180° about the normal (x → −x, y → −y), in
//! which U, ΔU and ΔV change sign and ω keeps its sign; the forces are then
//! turned back (Fx, Fy change sign, Mz does not). The reported J1..J7 are those
//! of the forward-rolling frame: `J1 = c_x ΔU/U`, `J2 = c_y ΔV/U` (the signed lab
//! ratios), `J3 = c_x ω√(ab)/|U|`, `J4 = sign(U) Fx/(μ_f N)`,
//! `J5 = sign(U) Fy/(μ_f N)`, `J6 = Mz/(μ_f N √(ab))`, so J7 ≥ 0 always.
//!
//! # Regularisation at U → 0 (start-up, stops)
//!
//! The J groups grow like 1/|U|. With `U_f` = [`Options::rolling_speed_floor`]
//! (default [`DEFAULT_ROLLING_SPEED_FLOOR`] = 1 mm/s):
//!
//! * the J groups use `U_eff = max(|U|, U_f)`: above the floor the model is
//!   evaluated exactly; below it the J's saturate at `c·Δ/U_f`, which for any
//!   relative speed Δ ≫ U_f·μ/m is deep in the rigid/plastic (Coulomb-like)
//!   regime, while at zero relative motion (ΔU = ΔV = ω = 0) all forces are
//!   exactly zero and they grow linearly (stiffly) with Δ — the usual
//!   creep-velocity regularisation of Coulomb friction;
//! * the forward (σ = +1) and reversed (σ = −1) rolling-frame solutions are
//!   blended with `w = ½ + ¾t − ¼t³`, `t = clamp(U/U_f, −1, 1)`:
//!   `F = w F₊ + (1 − w) F₋`. The elastic/plastic solution depends on which side
//!   the inlet is (the sign of J3 in the rolling frame), so without the blend the
//!   forces would jump at U = 0 whenever there is spin. The blend is C¹ in U,
//!   exact (w ∈ {0, 1}) for |U| ≥ U_f, and dissipative (each branch is).
//!
//! # Regime (App. IV figure 14, regions I–III)
//!
//! The figure is lost; the report defines its boundaries as "the values of spin
//! J3 corresponding to a 5 percent increase in the slip" compared with the master
//! curves. [`Regime`] applies that 5 % criterion to the evaluated state:
//!
//! * [`Regime::ElasticWithoutSpin`] (region I): J3 = 0, or the slip magnitude
//!   `S = (2/3)√(J1²+J2²)/√k` is at most 5 % above the slip `S₀` that the zero-spin
//!   closed form (App. V eq. 23, ψ(S₀) = √(J4²+J5²)) needs for the same traction;
//! * [`Regime::RigidPlastic`] (region III): otherwise, if the rigid/plastic
//!   solution at the same J's is within 5 % of the elastic/plastic one,
//!   `|J_ep − J_rp| ≤ 0.05 |J_rp|` over (J4, J5, J6) — a traction-level version
//!   of the criterion, because inverting the rigid/plastic solution for the slip
//!   would cost a root solve of the full model;
//! * [`Regime::ElasticWithSpin`] (region II): otherwise.
//!
//! Region I takes precedence (at large slip without spin both simplifications
//! hold). The master curve is the isotropic one (the report's); with disc
//! compliance (stiffness ratio gy ≠ 1) region I is judged against it too.
//! The classification costs one rigid/plastic evaluation when spin is
//! present; [`Options::classify_regime`] = false skips it ([`Regime::NotClassified`]).
//!
//! # Assumptions
//!
//! Those of the composed crates: Hertzian dry-contact pressure and ellipse,
//! constant film, isothermal J+T model (no thermal correction: the report's
//! predictions omit it too), rigid-body kinematics at the ellipse centre, spin
//! pole offset ΔX = 0, steady state. With compliance on, the slopes along and
//! across rolling differ (Kalker's q_x ≠ q_y): the J groups are formed with
//! m_x and the rheology gets the stiffness ratio gy = m_y/m_x (its
//! anisotropic Prandtl–Reuss law, G = diag(1, gy)), so that spin, which
//! shears the film in both directions, sees each direction's stiffness.
//! Without compliance m_x = m_y and gy = 1.
//!
//! # Example
//!
//! The low-speed machine, k = 1 discs (Table 2-1), Santotrac 50 at the
//! conditions of Table 4-2 (m = 57.6, μ = 0.0956), 0.2 % slip:
//!
//! ```
//! use traction_contact::{Body, Fluid, OperatingState, Options, TractionContact};
//!
//! let upper = Body::steel(25e-3, 12.5e-3);
//! let lower = Body::steel(25e-3, f64::INFINITY);
//! let contact = TractionContact::new(&upper, &lower, Fluid::constant(57.6, 0.0956)?, Options::default())?;
//! let state = OperatingState::new(416.0, 20.0, 0.04, 0.0, 0.0, 70.0)?;
//! let r = contact.evaluate(&state)?;
//! // No spin: App. V eq. 22, Fx/N = μ ψ(S), S = (2/3) J1/√k,
//! // J1 = (3π/8)(m/μ)(ΔU/U)√k, ψ(S) = (2/π)(atan S + S/(1 + S²)).
//! let j1 = 3.0 * std::f64::consts::PI / 8.0 * (57.6 / 0.0956) * (0.04 / 20.0) * r.k.sqrt();
//! let s = 2.0 / 3.0 * j1 / r.k.sqrt();
//! let psi = 2.0 / std::f64::consts::PI * (s.atan() + s / (1.0 + s * s));
//! assert!((r.traction_x / (0.0956 * psi) - 1.0).abs() < 1e-12);
//! assert!((r.p0 / 1.9e9 - 1.0).abs() < 0.01); // Table 2-3: 416 N ↔ 1.9 GPa
//! assert!((r.loss - r.fx * 0.04).abs() < 1e-12);
//! # Ok::<(), traction_contact::ContactError>(())
//! ```
#![forbid(unsafe_code)]

mod error;

use std::f64::consts::PI;
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};

pub use error::ContactError;
use error::check;
pub use traction_compliance::{Direction, DiscMaterial};
pub use traction_hertz::Body;
use traction_hertz::Geometry;
use traction_kinematics::ContactKinematics;
use traction_rheology::Inputs;
pub use traction_rheology::map::{Map, MapStats};
pub use traction_rheology::{Accuracy, Limit, Model, Modulus, Properties};

/// Accuracy range in which [`Options::map`] applies (the map's range).
const MAP_TOL: (f64, f64) = (1e-4, 1e-2);
/// Default rolling-speed floor U_f of the J groups, m/s (see the crate docs).
pub const DEFAULT_ROLLING_SPEED_FLOOR: f64 = 1e-3;
/// Largest accepted |U|, |ΔU|, |ΔV| (m/s): beyond any machine; keeps every
/// output (including the loss) finite.
pub const MAX_SPEED: f64 = 1e6;
/// Largest accepted |ω| (rad/s).
pub const MAX_SPIN: f64 = 1e9;
/// Largest accepted normal load (N).
pub const MAX_LOAD: f64 = 1e12;
/// Largest accepted traction slope m (dimensionless).
pub const MAX_SLOPE: f64 = 1e6;
/// Largest accepted traction coefficient μ (dimensionless).
pub const MAX_TRACTION_COEFFICIENT: f64 = 10.0;
/// The report's 5 % criterion for the regions of App. IV figure 14.
pub const REGIME_TOLERANCE: f64 = 0.05;

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
    },
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
    /// [`Evaluation::outside_envelope`].
    Extrapolate,
    /// Evaluate at the nearest point of the envelope (each variable clamped to
    /// its data range), flagged in [`Evaluation::outside_envelope`]: bounded
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

impl Fluid {
    /// Santotrac 50 with the report's printed coefficients (App. III-A, III-C,
    /// III-E), the given envelope rule, forces scaled by μ (no spin peak).
    pub fn santotrac_50(envelope: EnvelopeRule) -> Result<Fluid, ContactError> {
        Ok(Fluid::Report {
            fluid: Arc::new(traction_fluids::Fluid::santotrac_50()?),
            envelope,
            spin_peak: false,
        })
    }

    /// TDF-88 with the report's printed coefficients (App. III-B, III-D; the
    /// spin μ is the fluids crate's refit of III-F).
    pub fn tdf_88(envelope: EnvelopeRule) -> Result<Fluid, ContactError> {
        Ok(Fluid::Report {
            fluid: Arc::new(traction_fluids::Fluid::tdf_88()?),
            envelope,
            spin_peak: false,
        })
    }

    /// User m and μ; checks 0 < m ≤ [`MAX_SLOPE`], 0 < μ ≤ [`MAX_TRACTION_COEFFICIENT`].
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
                fluid, envelope, ..
            } => Fluid::Report {
                fluid,
                envelope,
                spin_peak: on,
            },
            other => other,
        }
    }

    fn validate(&self) -> Result<(), ContactError> {
        match *self {
            Fluid::Constant {
                slope,
                peak,
                spin_peak,
            } => {
                check(
                    "traction slope m",
                    slope,
                    slope > 0.0 && slope <= MAX_SLOPE,
                    "in (0, 1e6]",
                )?;
                check(
                    "peak traction coefficient μ",
                    peak,
                    peak > 0.0 && peak <= MAX_TRACTION_COEFFICIENT,
                    "in (0, 10]",
                )?;
                if let Some(s) = spin_peak {
                    check(
                        "spin-peak traction coefficient μ_s",
                        s,
                        s > 0.0 && s <= MAX_TRACTION_COEFFICIENT,
                        "in (0, 10]",
                    )?;
                }
            }
            Fluid::Physical {
                shear_modulus,
                limiting_stress,
                film_thickness,
            } => {
                check(
                    "fluid shear modulus Ḡ (Pa)",
                    shear_modulus,
                    shear_modulus > 0.0,
                    "finite and > 0 Pa",
                )?;
                check(
                    "limiting shear stress τ̄ (Pa)",
                    limiting_stress,
                    limiting_stress > 0.0,
                    "finite and > 0 Pa",
                )?;
                check(
                    "film thickness h (m)",
                    film_thickness,
                    film_thickness > 0.0,
                    "finite and > 0 m",
                )?;
            }
            Fluid::Report { .. } => {}
        }
        Ok(())
    }
}

/// Disc-compliance correction of the traction slope (App. IV appendices A, B).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[non_exhaustive]
pub enum Compliance {
    /// No correction: the one slope m scales J1, J2 and J3.
    #[default]
    Off,
    /// The discs are elastic (`material`, both discs alike), with Kalker's
    /// q_x = π/C11, q_y = π/C22 at this contact's k (traction-compliance).
    ///
    /// * [`Fluid::Constant`]: m is the slope *measured* in `slope_measured_in`
    ///   on this contact (the report measured side-slip slopes); the slope of
    ///   the other direction follows from App. IV eq. B7 at the same contact
    ///   and P0 (the Table 4-3 operation).
    /// * [`Fluid::Physical`]: Ḡ is the film's own modulus; each direction's
    ///   slope is the film and the discs in series (App. IV A3):
    ///   1/m_i = 1/m_film + 1/m'_i with the dry slope m'_i = 3G_s/(2 q_i P0) (B3).
    ///   `slope_measured_in` is not used.
    Discs {
        /// Disc material (E, ν; ν within Kalker's table, 0..0.5).
        material: DiscMaterial,
        /// Direction in which the user's slope m was measured.
        slope_measured_in: Direction,
    },
}

/// Evaluation options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Constitutive model (default elastic/plastic, the report's).
    pub model: Model,
    /// Accuracy of the rheology integration (absolute, in J4, J5, J6).
    pub accuracy: Accuracy,
    /// Disc-compliance correction of the slope.
    pub compliance: Compliance,
    /// Rolling-speed floor U_f of the J groups, m/s, in [1e-9, 1] (see crate docs).
    pub rolling_speed_floor: f64,
    /// Classify the regime of App. IV figure 14 (costs a rigid/plastic
    /// evaluation when spin is present).
    pub classify_regime: bool,
    /// Distribution of the shear modulus and of the limiting shear stress
    /// over the contact (App. IV eq. 8 and the text after it), for the
    /// elastic/plastic model. The default (Ḡ constant, limit ∝ pressure) is
    /// the report's and uses the fast strip integrator; the others use the
    /// rheology crate's grid scheme (≈ 1e-4, milliseconds per evaluation).
    pub properties: Properties,
    /// Evaluate the elastic/plastic model through a lazily built
    /// interpolation map ([`traction_rheology::map::Map`], one per contact, at
    /// the same accuracy) instead of integrating the strips at every call.
    /// Used when the map applies: the default property distribution, the
    /// accuracy in [1e-4, 1e-2] and gy = 1 (no compliance correction; with it
    /// gy = m_y/m_x changes with the load); otherwise direct. Pays off for
    /// many evaluations in a region of (J1, J2, J3) — a co-simulation near an
    /// operating point: ≈ 0.2 µs instead of 10–700 µs — and costs up to tens of
    /// milliseconds when a new region is first entered. Results depend only
    /// on the inputs (not on the calls before). Default off.
    pub map: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            model: Model::ElasticPlastic,
            accuracy: Accuracy::default(),
            compliance: Compliance::Off,
            rolling_speed_floor: DEFAULT_ROLLING_SPEED_FLOOR,
            classify_regime: true,
            properties: Properties::default(),
            map: false,
        }
    }
}

/// The contact's interpolation map ([`Options::map`]), behind a lock so that
/// [`TractionContact::evaluate`] keeps `&self` and the contact stays `Sync`.
/// A cache: cloning copies it, and it takes no part in equality.
#[derive(Default)]
struct MapCache(Mutex<Option<Map>>);

impl MapCache {
    fn lock(&self) -> MutexGuard<'_, Option<Map>> {
        // A panic while holding the lock cannot leave the map inconsistent
        // (cells are inserted whole), so a poisoned lock is still usable.
        self.0.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

impl Clone for MapCache {
    fn clone(&self) -> Self {
        MapCache(Mutex::new(self.lock().clone()))
    }
}

impl PartialEq for MapCache {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl std::fmt::Debug for MapCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "MapCache({:?})", self.lock().as_ref().map(Map::stats))
    }
}

/// An operating state of the contact (SI units, lab frame, signs as in the crate docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OperatingState {
    /// Normal load N, N (0 = contact open).
    pub load: f64,
    /// Rolling speed U = ½(v₁ + v₂)·x, m/s (either sign).
    pub rolling_speed: f64,
    /// Slip ΔU = (v₁ − v₂)·x, m/s.
    pub slip: f64,
    /// Side slip ΔV = (v₁ − v₂)·y, m/s.
    pub side_slip: f64,
    /// Spin ω = (Ω₁ − Ω₂)·z, rad/s.
    pub spin: f64,
    /// Inlet temperature θ, °C (used by temperature-dependent fluids).
    pub inlet_temperature_celsius: f64,
}

impl OperatingState {
    /// A checked state: 0 ≤ load ≤ [`MAX_LOAD`]; |U|, |ΔU|, |ΔV| ≤ [`MAX_SPEED`];
    /// |ω| ≤ [`MAX_SPIN`]; θ finite and above −273.15 °C.
    pub fn new(
        load: f64,
        rolling_speed: f64,
        slip: f64,
        side_slip: f64,
        spin: f64,
        inlet_temperature_celsius: f64,
    ) -> Result<Self, ContactError> {
        let s = OperatingState {
            load,
            rolling_speed,
            slip,
            side_slip,
            spin,
            inlet_temperature_celsius,
        };
        s.validate()?;
        Ok(s)
    }

    /// The state from the bodies' motion at the contact (traction-kinematics:
    /// U, ΔU, ΔV, ω in the same sign convention as this crate).
    pub fn from_kinematics(
        kinematics: &ContactKinematics,
        load: f64,
        inlet_temperature_celsius: f64,
    ) -> Result<Self, ContactError> {
        OperatingState::new(
            load,
            kinematics.rolling_speed,
            kinematics.slip,
            kinematics.side_slip,
            kinematics.spin,
            inlet_temperature_celsius,
        )
    }

    /// Check the ranges (the fields are public, so [`TractionContact::evaluate`] checks again).
    pub fn validate(&self) -> Result<(), ContactError> {
        check(
            "load N (normal load, N)",
            self.load,
            self.load >= 0.0 && self.load <= MAX_LOAD,
            "in [0, 1e12] N",
        )?;
        let speed = |q, v: f64| check(q, v, v.abs() <= MAX_SPEED, "finite, |value| ≤ 1e6 m/s");
        speed("rolling speed U (m/s)", self.rolling_speed)?;
        speed("slip ΔU (m/s)", self.slip)?;
        speed("side slip ΔV (m/s)", self.side_slip)?;
        check(
            "spin ω (rad/s)",
            self.spin,
            self.spin.abs() <= MAX_SPIN,
            "finite, |ω| ≤ 1e9 rad/s",
        )?;
        check(
            "inlet temperature θ (°C)",
            self.inlet_temperature_celsius,
            self.inlet_temperature_celsius > -273.15,
            "finite and above −273.15 °C",
        )?;
        Ok(())
    }
}

/// Traction regime of App. IV figure 14 (definition in the crate docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Regime {
    /// Region I: the zero-spin elastic/plastic solution is sufficient.
    ElasticWithoutSpin,
    /// Region II: the full elastic/plastic analysis with spin is needed.
    ElasticWithSpin,
    /// Region III: the rigid/plastic (Coulomb-like) analysis is sufficient.
    RigidPlastic,
    /// Not classified ([`Options::classify_regime`] = false).
    NotClassified,
}

impl Regime {
    /// Short name used in CSV output.
    pub fn name(&self) -> &'static str {
        match self {
            Regime::ElasticWithoutSpin => "elastic-without-spin",
            Regime::ElasticWithSpin => "elastic-with-spin",
            Regime::RigidPlastic => "rigid-plastic",
            Regime::NotClassified => "not-classified",
        }
    }
}

/// Result of one evaluation (SI units; J's in the forward-rolling frame).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Evaluation {
    /// Traction force along x that body 1 exerts on body 2, N.
    pub fx: f64,
    /// Side force along y that body 1 exerts on body 2, N.
    pub fy: f64,
    /// Spin moment about z that body 1 exerts on body 2, N·m.
    pub mz: f64,
    /// Traction coefficient Fx/N (0 when N = 0).
    pub traction_x: f64,
    /// Side-force coefficient Fy/N (0 when N = 0).
    pub traction_y: f64,
    /// Power loss Fx ΔU + Fy ΔV + Mz ω, W (≥ 0).
    pub loss: f64,
    /// Semi-axis along x, m.
    pub a: f64,
    /// Semi-axis across x, m.
    pub b: f64,
    /// Aspect ratio k = b/a.
    pub k: f64,
    /// Maximum Hertz pressure P0, Pa.
    pub p0: f64,
    /// Slope m used for J1 and J3 (longitudinal).
    pub m_used: f64,
    /// Lateral slope m_y; the rheology gets the stiffness ratio gy = m_y/m_x
    /// (equal to `m_used`, gy = 1, without compliance).
    pub m_side: f64,
    /// Zero-spin peak traction coefficient μ used in the J groups.
    pub mu_used: f64,
    /// Traction coefficient that scales the forces (μ, or μ_s if given).
    pub mu_force: f64,
    /// Dimensionless slip J1.
    pub j1: f64,
    /// Dimensionless side slip J2.
    pub j2: f64,
    /// Dimensionless spin J3.
    pub j3: f64,
    /// Traction J4 = Fx/(μ_f N) (forward-rolling frame).
    pub j4: f64,
    /// Side force J5 = Fy/(μ_f N) (forward-rolling frame).
    pub j5: f64,
    /// Spin moment J6 = Mz/(μ_f N √(ab)).
    pub j6: f64,
    /// Losses J7 = J1 J4 + J2 J5 + J3 J6 (≥ 0).
    pub j7: f64,
    /// Regime of App. IV figure 14.
    pub regime: Regime,
    /// Correlation variables outside the fluid's data envelope (report fluids).
    pub outside_envelope: OutsideEnvelope,
}

impl Evaluation {
    /// Loss factor J7/J4 (App. IV eq. 18); `None` when J4 = 0.
    pub fn loss_factor(&self) -> Option<f64> {
        (self.j4 != 0.0).then(|| self.j7 / self.j4)
    }
}

/// The traction contact, built once from the bodies, the fluid and the options.
#[derive(Debug, Clone, PartialEq)]
pub struct TractionContact {
    geometry: Geometry,
    fluid: Fluid,
    options: Options,
    /// Kalker q_x, q_y and the disc shear modulus, when compliance is on.
    discs: Option<(f64, f64, f64)>,
    /// The interpolation map of [`Options::map`] (empty until first used).
    map: MapCache,
}

/// The dimensionless solution of one rolling frame.
#[derive(Debug, Clone, Copy)]
struct Branch {
    j: [f64; 3],
    out: [f64; 3],
}

impl TractionContact {
    /// Build the contact: Hertz geometry of the two bodies (errors name bad
    /// radii, materials, conformal contact), k within the rheology's range
    /// [0.01, 100], Kalker's q_x, q_y if compliance is on.
    pub fn new(
        body1: &Body,
        body2: &Body,
        fluid: Fluid,
        options: Options,
    ) -> Result<Self, ContactError> {
        fluid.validate()?;
        check(
            "rolling-speed floor U_f (m/s)",
            options.rolling_speed_floor,
            (1e-9..=1.0).contains(&options.rolling_speed_floor),
            "in [1e-9, 1] m/s",
        )?;
        let geometry = Geometry::new(body1, body2)?;
        let k = geometry.k;
        check(
            "aspect ratio k = b/a of the contact",
            k,
            (traction_rheology::K_MIN..=traction_rheology::K_MAX).contains(&k),
            "in [0.01, 100] (the traction model's range)",
        )?;
        let discs = match options.compliance {
            Compliance::Off => None,
            Compliance::Discs { material, .. } => {
                let gs = material.shear_modulus()?;
                let nu = material.poisson_ratio;
                let qx = traction_compliance::kalker_q(Direction::Longitudinal, k, nu)?;
                let qy = traction_compliance::kalker_q(Direction::Side, k, nu)?;
                Some((qx, qy, gs))
            }
        };
        Ok(TractionContact {
            geometry,
            fluid,
            options,
            discs,
            map: MapCache::default(),
        })
    }

    /// Move the interpolation map out of this contact (None if it has none),
    /// e.g. to hand it to a contact rebuilt with other loads or fluids.
    pub fn take_map(&self) -> Option<Map> {
        self.map.lock().take()
    }

    /// Adopt a map built by another contact. Its values depend only on k and
    /// the accuracy, so it is kept when those match this contact's and
    /// [`Options::map`] is on (returns true); otherwise it is dropped.
    pub fn adopt_map(&self, map: Map) -> bool {
        let ok = self.options.map
            && map.key() == (self.geometry.k, 0.0, 1.0)
            && map.tol() == self.options.accuracy.tol();
        if ok {
            *self.map.lock() = Some(map);
        }
        ok
    }

    /// Counters of the interpolation map ([`Options::map`]); None until the
    /// map is first used.
    pub fn map_stats(&self) -> Option<MapStats> {
        self.map.lock().as_ref().map(Map::stats)
    }

    /// The precomputed Hertz geometry.
    pub fn geometry(&self) -> &Geometry {
        &self.geometry
    }

    /// The fluid.
    pub fn fluid(&self) -> &Fluid {
        &self.fluid
    }

    /// The options.
    pub fn options(&self) -> &Options {
        &self.options
    }

    /// Slopes (m_x, m_y), μ and μ_f at a loaded contact, and the envelope flags.
    fn properties(
        &self,
        a: f64,
        b: f64,
        p0: f64,
        load: f64,
        state: &OperatingState,
    ) -> Result<([f64; 4], OutsideEnvelope), ContactError> {
        let mut flags = OutsideEnvelope::default();
        let (m, mu, mu_f, film) = match &self.fluid {
            Fluid::Constant {
                slope,
                peak,
                spin_peak,
            } => (*slope, *peak, spin_peak.unwrap_or(*peak), None),
            Fluid::Physical {
                shear_modulus,
                limiting_stress,
                film_thickness,
            } => {
                let mu = limiting_stress * PI * a * b / load;
                let m = 8.0 / 3.0 * shear_modulus * a * a * b / (load * film_thickness);
                (m, mu, mu, Some(*film_thickness))
            }
            Fluid::Report {
                fluid,
                envelope,
                spin_peak,
            } => {
                let speed = state.rolling_speed.abs();
                let z =
                    state.spin.abs() * (a * b).sqrt() / speed.max(self.options.rolling_speed_floor);
                let base = traction_fluids::Query {
                    p0_pa: p0,
                    speed_m_s: speed,
                    theta_celsius: state.inlet_temperature_celsius,
                    k: self.geometry.k,
                    z: 0.0,
                };
                let m = correlate(&fluid.slope, base, *envelope, &mut flags)?;
                let mu = correlate(&fluid.mu, base, *envelope, &mut flags)?;
                let mu_f = if *spin_peak {
                    correlate(
                        &fluid.spin_mu,
                        traction_fluids::Query { z, ..base },
                        *envelope,
                        &mut flags,
                    )?
                } else {
                    mu
                };
                (m, mu, mu_f, None)
            }
        };
        let (mx, my) = match (self.discs, self.options.compliance) {
            (
                Some((qx, qy, gs)),
                Compliance::Discs {
                    slope_measured_in, ..
                },
            ) => {
                if film.is_some() {
                    // Film and discs in series (A3 with B3): 1/m = 1/m_film + 1/m'.
                    let dry = |q: f64| 1.5 * gs / (q * p0);
                    (
                        1.0 / (1.0 / m + 1.0 / dry(qx)),
                        1.0 / (1.0 / m + 1.0 / dry(qy)),
                    )
                } else {
                    let c = |slope, q| traction_compliance::SlopeContact {
                        slope,
                        q,
                        a: 1.0,
                        h: 1.0,
                    };
                    match slope_measured_in {
                        Direction::Longitudinal => {
                            let my =
                                traction_compliance::convert_slope(c(m, qx), c(0.0, qy), p0, gs)?;
                            (m, my)
                        }
                        Direction::Side => {
                            let mx =
                                traction_compliance::convert_slope(c(m, qy), c(0.0, qx), p0, gs)?;
                            (mx, m)
                        }
                    }
                }
            }
            _ => (m, m),
        };
        Ok(([mx, my, mu, mu_f], flags))
    }

    /// Whether [`Options::map`] is on and applies (elastic/plastic model,
    /// default properties, accuracy within the map's range); the
    /// elastic/plastic map needs gy = 1 in addition, the rigid/plastic one
    /// (regime classification) does not depend on gy.
    fn map_applies(&self) -> bool {
        self.options.map
            && self.options.model == Model::ElasticPlastic
            && self.options.properties == Properties::default()
            && (MAP_TOL.0..=MAP_TOL.1).contains(&self.options.accuracy.tol())
    }

    /// Run `f` on the contact's map (built empty on first use).
    fn with_map<T>(
        &self,
        f: impl FnOnce(&mut Map) -> Result<T, traction_rheology::RheologyError>,
    ) -> Result<T, ContactError> {
        let mut slot = self.map.lock();
        let map = match slot.as_mut() {
            Some(map) => map,
            None => slot.insert(Map::new(self.geometry.k, 0.0, 1.0, self.options.accuracy)?),
        };
        Ok(f(map)?)
    }

    /// Solve the rheology in one rolling frame.
    fn branch(&self, k: f64, j: [f64; 3], gy: f64) -> Result<Branch, ContactError> {
        if j == [0.0; 3] {
            return Ok(Branch { j, out: [0.0; 3] });
        }
        let inp = Inputs::new(k, j[0], j[1], j[2])?.with_stiffness_ratio(gy)?;
        if self.map_applies() && gy == 1.0 {
            let o = self.with_map(|m| m.evaluate(&inp))?;
            return Ok(Branch {
                j,
                out: [o.j4, o.j5, o.j6],
            });
        }
        let o = match self.options.model {
            Model::ElasticPlastic => traction_rheology::evaluate(
                &inp,
                Model::PropertyVariation(self.options.properties),
                self.options.accuracy,
            )?,
            model => traction_rheology::evaluate(&inp, model, self.options.accuracy)?,
        };
        Ok(Branch {
            j,
            out: [o.j4, o.j5, o.j6],
        })
    }

    /// Evaluate the contact at an operating state.
    ///
    /// Errors name the quantity: a state out of range, a fluid that gives an
    /// invalid slope, a failed compliance conversion. Every returned number is
    /// finite.
    pub fn evaluate(&self, state: &OperatingState) -> Result<Evaluation, ContactError> {
        state.validate()?;
        let k = self.geometry.k;
        if state.load == 0.0 {
            return Ok(self.open(state));
        }
        let hz = self.geometry.at_load(state.load)?;
        let (a, b, p0, n) = (hz.a, hz.b, hz.p0, state.load);
        let ([mx, my, mu, mu_f], outside_envelope) = self.properties(a, b, p0, n, state)?;
        let sqrt_ab = (a * b).sqrt();
        let sk = k.sqrt();
        let cx = 3.0 * PI / 8.0 * (mx / mu) * sk;
        let gy = my / mx;
        let u = state.rolling_speed;
        let uf = self.options.rolling_speed_floor;
        let u_eff = u.abs().max(uf);
        let t = (u / uf).clamp(-1.0, 1.0);
        let w = 0.5 + 0.75 * t - 0.25 * t * t * t;
        let rate = [
            cx * state.slip / u_eff,
            cx * state.side_slip / u_eff,
            cx * state.spin * sqrt_ab / u_eff,
        ];
        // Frame σ: (σ J1, σ J2, J3).
        let frame = |s: f64| [s * rate[0], s * rate[1], rate[2]];
        let fwd = if w > 0.0 {
            Some(self.branch(k, frame(1.0), gy)?)
        } else {
            None
        };
        let rev = if w < 1.0 {
            Some(self.branch(k, frame(-1.0), gy)?)
        } else {
            None
        };
        // Lab-frame dimensionless forces: (σ J4_σ, σ J5_σ, J6_σ), blended.
        let mut lab = [0.0; 3];
        for (br, s, weight) in [(fwd, 1.0, w), (rev, -1.0, 1.0 - w)] {
            if let Some(br) = br {
                lab[0] += weight * s * br.out[0];
                lab[1] += weight * s * br.out[1];
                lab[2] += weight * br.out[2];
            }
        }
        let sigma = if w >= 0.5 { 1.0 } else { -1.0 };
        let dominant = if sigma > 0.0 { fwd } else { rev };
        let fx = mu_f * n * lab[0];
        let fy = mu_f * n * lab[1];
        let mz = mu_f * n * sqrt_ab * lab[2];
        let loss = (fx * state.slip + fy * state.side_slip + mz * state.spin).max(0.0);
        let j = frame(sigma);
        let (j4, j5, j6) = (sigma * lab[0], sigma * lab[1], lab[2]);
        let j7 = (j[0] * j4 + j[1] * j5 + j[2] * j6).max(0.0);
        let regime = match dominant {
            Some(br) if self.options.classify_regime => self.classify(k, &br)?,
            _ if self.options.classify_regime => Regime::ElasticWithoutSpin,
            _ => Regime::NotClassified,
        };
        Ok(Evaluation {
            fx,
            fy,
            mz,
            traction_x: fx / n,
            traction_y: fy / n,
            loss,
            a,
            b,
            k,
            p0,
            m_used: mx,
            m_side: my,
            mu_used: mu,
            mu_force: mu_f,
            j1: j[0],
            j2: j[1],
            j3: j[2],
            j4,
            j5,
            j6,
            j7,
            regime,
            outside_envelope,
        })
    }

    /// The open contact (N = 0): no forces, no ellipse.
    fn open(&self, _state: &OperatingState) -> Evaluation {
        let (m, mu, mu_f) = match self.fluid {
            Fluid::Constant {
                slope,
                peak,
                spin_peak,
            } => (slope, peak, spin_peak.unwrap_or(peak)),
            // μ = τ̄πab/N and m are undefined at N = 0 (and the report
            // correlations need P0 > 0); reported as 0.
            Fluid::Physical { .. } | Fluid::Report { .. } => (0.0, 0.0, 0.0),
        };
        Evaluation {
            fx: 0.0,
            fy: 0.0,
            mz: 0.0,
            traction_x: 0.0,
            traction_y: 0.0,
            loss: 0.0,
            a: 0.0,
            b: 0.0,
            k: self.geometry.k,
            p0: 0.0,
            m_used: m,
            m_side: m,
            mu_used: mu,
            mu_force: mu_f,
            j1: 0.0,
            j2: 0.0,
            j3: 0.0,
            j4: 0.0,
            j5: 0.0,
            j6: 0.0,
            j7: 0.0,
            regime: if self.options.classify_regime {
                Regime::ElasticWithoutSpin
            } else {
                Regime::NotClassified
            },
            outside_envelope: OutsideEnvelope::default(),
        }
    }

    /// Regions I–III of App. IV figure 14 by the 5 % criterion (crate docs).
    fn classify(&self, k: f64, br: &Branch) -> Result<Regime, ContactError> {
        let [j1, j2, j3] = br.j;
        let [j4, j5, j6] = br.out;
        if j3 == 0.0 {
            return Ok(Regime::ElasticWithoutSpin);
        }
        // Region I: slip increase over the zero-spin master curve ≤ 5 %.
        let s_act = (2.0 / 3.0) * j1.hypot(j2) / k.sqrt();
        let s_need = inverse_psi(j4.hypot(j5));
        if s_act <= (1.0 + REGIME_TOLERANCE) * s_need {
            return Ok(Regime::ElasticWithoutSpin);
        }
        // Region III: the rigid/plastic solution at the same J's within 5 %.
        let rp = if self.map_applies() {
            self.with_map(|m| m.rigid_plastic(&Inputs::new(k, j1, j2, j3)?))?
        } else {
            let inp = Inputs::new(k, j1, j2, j3)?;
            traction_rheology::evaluate(&inp, Model::RigidPlastic, self.options.accuracy)?
        };
        let d = (j4 - rp.j4).hypot(j5 - rp.j5).hypot(j6 - rp.j6);
        let r = rp.j4.hypot(rp.j5).hypot(rp.j6);
        Ok(if d <= REGIME_TOLERANCE * r {
            Regime::RigidPlastic
        } else {
            Regime::ElasticWithSpin
        })
    }
}

/// Evaluate one correlation under the envelope rule, recording the flags.
fn correlate(
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

/// Inverse of the zero-spin traction function ψ(S) of App. V eq. 22 for
/// 0 ≤ T: with S = tan φ, πψ = 2φ + sin 2φ (monotone), Newton on φ with
/// bisection safeguard; `f64::INFINITY` for T ≥ 1.
pub fn inverse_psi(t: f64) -> f64 {
    if t.is_nan() || t <= 0.0 {
        return 0.0;
    }
    if t >= 1.0 {
        return f64::INFINITY;
    }
    let target = PI * t;
    let (mut lo, mut hi) = (0.0_f64, PI / 2.0);
    let mut phi = 0.25 * target; // exact slope at 0: d(2φ+sin2φ)/dφ = 4
    for _ in 0..60 {
        let f = 2.0 * phi + (2.0 * phi).sin() - target;
        if f > 0.0 {
            hi = phi;
        } else {
            lo = phi;
        }
        let d = 4.0 * phi.cos().powi(2);
        let mut next = phi - f / d;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        if (next - phi).abs() <= 1e-15 * phi.max(1e-300) {
            phi = next;
            break;
        }
        phi = next;
    }
    phi.tan()
}

#[cfg(test)]
mod tests;
