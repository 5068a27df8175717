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
//!   Below the floor the reversed frame (−J1, −J2, J3) is taken from
//!   (J1, −J2, J3) by the models' symmetries (odd in the slips, symmetric
//!   about the rolling direction), whose (J4, J5, J6) it is as (−J4, J5, J6).
//!   Without side slip that is the forward frame, so the J+T model is
//!   evaluated once.
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
//! present, at the contact's accuracy but no finer than tol 1e-3 (its error
//! then moves the 5 % boundary by at most 1e-3 over |J_rp|, and at large |J|
//! it costs ≈ 10× less than at 1e-4); [`Options::classify_regime`] = false
//! skips it ([`Regime::NotClassified`]).
//!
//! # Assumptions
//!
//! Those of the composed crates: Hertzian dry-contact pressure and ellipse,
//! constant film, isothermal J+T model by default (the report's predictions
//! omit heating too; [`Options::thermal`] adds the film's temperature rise,
//! module [`thermal`]), rigid-body kinematics at the ellipse centre, spin
//! pole offset ΔX = 0, steady state. With compliance on, the slopes along and
//! across rolling differ (Kalker's q_x ≠ q_y): the J groups are formed with
//! m_x and the rheology gets the stiffness ratio gy = m_y/m_x (its
//! anisotropic Prandtl–Reuss law, G = diag(1, gy)), so that spin, which
//! shears the film in both directions, sees each direction's stiffness.
//! Without compliance m_x = m_y and gy = 1.
//!
//! # Thermal model ([`Options::thermal`], off by default)
//!
//! The film's mid-plane temperature rise ΔT from the contact's own loss P
//! (flash temperature of the two moving surfaces + conduction across the
//! film), with μ and m at θ + ΔT, solved self-consistently:
//! `ΔT = (P/(πab))·(R_s + h/(8k_f))`,
//! `μ = μ(θ)e^(−β_μ(ΔT − ΔT_peak) − (ΔT² − ΔT_peak²)/T*²)`, `m = m(θ)e^(−β_mΔT)`.
//! The film h is given or Hamrock–Dowson's, optionally reduced by inlet
//! shear heating ([`Film::HamrockDowsonInletHeated`],
//! [`Film::FromFluidInletHeated`]; not the report fluids' default).
//! Equations, sources and ranges in [`thermal`]; the result's
//! [`Evaluation::temperature_rise`], `m_used`, `mu_used` are at θ + ΔT.
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

mod contact;
mod error;
mod evaluation;
mod fluid;
mod map_cache;
mod options;
mod regime;
mod state;
pub mod thermal;

pub use contact::TractionContact;
pub use error::{ContactError, error_chain};
pub use evaluation::{Evaluation, Regime};
pub use fluid::{EnvelopeRule, Fluid, InletValues, OutsideEnvelope};
pub use options::{Compliance, Options};
pub use regime::inverse_psi;
pub use state::{OperatingState, OperatingStateBuilder};
pub use thermal::{Film, Thermal};
pub use traction_compliance::{Direction, DiscMaterial, KALKER_POISSON_RANGE};
pub use traction_hertz::Body;
pub use traction_kinematics::ANGLE_RANGE;
pub use traction_rheology::map::{Budget, Map, MapStats};
pub use traction_rheology::{
    Accuracy, DEBORAH_RANGE, Limit, Model, Modulus, Properties, REFERENCE_STRESS_RANGE,
    TOLERANCE_RANGE,
};

pub use traction_range::{OutOfRange, Range};

/// Default rolling-speed floor U_f of the J groups, m/s (see the crate docs).
pub const DEFAULT_ROLLING_SPEED_FLOOR: f64 = 1e-3;
/// Valid rolling-speed floors U_f ([`Options::rolling_speed_floor`]).
pub const ROLLING_SPEED_FLOOR_RANGE: Range = Range::closed(1e-9, 1.0).with_unit("m/s");
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
/// Valid normal loads N: [0, [`MAX_LOAD`]] (0: the contact is open).
pub const LOAD_RANGE: Range = Range::closed(0.0, MAX_LOAD).with_unit("N");
/// Valid rolling speed U, slip ΔU and side slip ΔV: |v| ≤ [`MAX_SPEED`].
pub const SPEED_RANGE: Range = Range::closed(-MAX_SPEED, MAX_SPEED).with_unit("m/s");
/// Valid spin ω: |ω| ≤ [`MAX_SPIN`].
pub const SPIN_RANGE: Range = Range::closed(-MAX_SPIN, MAX_SPIN).with_unit("rad/s");
/// Valid inlet temperatures: above absolute zero.
pub const INLET_TEMPERATURE_RANGE: Range = Range::greater_than(-273.15).with_unit("°C");
/// Valid traction slopes m of a user fluid: (0, [`MAX_SLOPE`]].
pub const SLOPE_RANGE: Range = Range::open(0.0, MAX_SLOPE).closed_above();
/// Valid traction coefficients μ, μ_s of a user fluid: (0,
/// [`MAX_TRACTION_COEFFICIENT`]].
pub const TRACTION_COEFFICIENT_RANGE: Range =
    Range::open(0.0, MAX_TRACTION_COEFFICIENT).closed_above();
/// The report's 5 % criterion for the regions of App. IV figure 14.
pub const REGIME_TOLERANCE: f64 = 0.05;
#[cfg(test)]
mod tests;
