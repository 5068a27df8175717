//! # traction-rheology: the Johnson & Tevaarwerk (J+T) traction model
//!
//! Traction, side force, spin torque and losses of a lubricated elliptical
//! rolling contact under slip, side slip and spin, computed by integrating
//! the J+T constitutive law over the Hertzian contact, in the report's
//! dimensionless groups (NASA TP 1530 = report Appendix IV, ASME 78-Lub-10 =
//! Appendix V, main text sections 3-0 and 4-0).
//!
//! ## Dimensionless groups (the report's names)
//! * k = b/a, aspect ratio (a along rolling, b across), X = x/a, Y = y/b.
//! * J1 = Ḡ√(ab)·ΔU/(τ̄hU) = (3π/8)(m/μ)(ΔU/U)√k, slip (App. IV eq. 11).
//! * J2 = Ḡ√(ab)·ΔV/(τ̄hU) = (3π/8)(m/μ)(ΔV/U)√k, side slip (App. V).
//! * J3 = Ḡ√(ab)·ω√(ab)/(τ̄hU) = (3π/8)(m/μ)(ω√(ab)/U)√k, spin (App. IV eq. 12).
//! * ΔX = δ/a, spin-pole offset (App. IV; the report kept it zero).
//! * J4 = Fx/(μN), J5 = Fy/(μN), J6 = T/(μN√(ab)), J7 = J1·J4 + J2·J5 + J3·J6
//!   (App. IV eqs. 15–17, App. V eq. 21), loss factor LF = J7/J4 (App. IV eq. 18).
//!   T is taken about the spin pole (x = −δ); with ΔX = 0 (all the report's
//!   results) that is the contact centre. Only then is J7 the dissipation
//!   for ΔX ≠ 0: the torque about the centre is J6 − ΔX·J5/√k.
//! * Z = τ/τ̄, τ̄ = μN/(πab) (App. IV eq. 10); S = (2/3)J1/√k, ε = J1/J3.
//!
//! ## Equations
//! Along a strip at fixed Y (half-width c = √(1−Y²)), from the stress-free
//! inlet X = −c (App. IV eq. 5) to the outlet X = c (App. IV eq. 13, with the
//! side-slip term of App. V eqs. 10–11):
//!
//! ```text
//!   dZx/dX = J1/√k − J3·Y              − plastic part
//!   dZy/dX = J2/√k + J3·(X + ΔX)/k     − plastic part
//! ```
//!
//! The right-hand side without the plastic part is the elastic rate v. The
//! elastic/perfectly plastic law (App. IV eq. 7, Prandtl–Reuss) keeps
//! |Z| ≤ L = (3/2)√(1−X²−Y²) (App. IV eq. 8 and the text after it; App. V
//! eq. 19 prints 2/3, an OCR slip: only 3/2 makes the mean of L over the
//! ellipse equal to 1, i.e. the peak traction μN). On the limit the stress
//! turns with θ' = (v·t)/L (t ⟂ Z) while v·n ≥ dL/dX, and unloads elastically
//! otherwise. Note the printed F̄ of App. IV eq. 13 keeps |Z| constant on the
//! limit; with a limit that shrinks towards the outlet the consistency
//! condition must include dL/dX, which is what this crate solves.
//!
//! Forces: J4 = (1/π)∫∫Zx dX dY, J5 = (1/π)∫∫Zy dX dY,
//! J6 = (1/(π√k))∫∫(Zy·(X+ΔX) − k·Zx·Y) dX dY, so that
//! J7 = J1·J4 + J2·J5 + J3·J6 = (√k/π)∫∫Z·v dX dY (the dissipation).
//! **J6 prefactor.** App. IV eq. 16 prints (√k/π); with T = ∫(τy·x − τx·y)dA,
//! x = aX, y = bY, dA = ab dX dY, T/(μN√(ab)) has the prefactor 1/(π√k). Only
//! the latter satisfies the power balance J7 = J1·J4 + J2·J5 + J3·J6 =
//! Ḡ(Fx·ΔU + Fy·ΔV + T·ω)/(π τ̄² √(ab) h U) (App. IV eq. 17, App. V eq. 21);
//! they differ by the factor k (equal for k = 1, which is why it went
//! unnoticed). This crate uses 1/(π√k); a test checks the balance.
//!
//! ## Models
//! * [`Model::ElasticPlastic`] (default): Ḡ constant, limit pressure
//!   proportional — the combination the report's printed theory uses: the
//!   zero-spin closed form App. V eq. 22 (main text eq. 8) is exactly the strip
//!   integral of this combination, and App. IV recommends it ("if a better fit
//!   is wanted").
//! * [`Model::RigidPlastic`]: Z = L·v/|v| (App. IV eq. 14, App. V eq. 14), the
//!   limit of the above for J's → ∞ at fixed ratios (ε = J1/J3).
//! * [`Model::Viscoelastic`]: the sinh law (App. V eqs. 3–6) with Deborah
//!   number D = ηU/(Ḡa) and reference stress Z0 = τ0/τ̄, with the limit L kept
//!   as a cap; D → ∞ gives the elastic/plastic model exactly (the viscous
//!   term vanishes), Z0 → ∞ the linear Maxwell fluid (`visco/`).
//! * Other property variations (App. IV eq. 8: G pressure-proportional,
//!   limit constant): [`Model::PropertyVariation`] with [`Properties`], solved by a
//!   Richardson-extrapolated grid scheme ([`props`], ≈ 1e-4, milliseconds).
//! * The stress field Z(X, Y) on a grid (plots, flow pattern):
//!   [`stress_field`].
//! * Many evaluations at one (k, ΔX, gy) — co-simulation steps: [`map::Map`],
//!   a lazily built tricubic interpolation map of the elastic/plastic model
//!   (and of the rigid/plastic one) whose cells are checked against direct
//!   evaluation before use and refined where the model is not smooth
//!   (≈ 0.2 µs per evaluation once built, results within tol).
//! * Closed forms for zero spin: [`closed::slip_traction`] (eq. 22),
//!   [`closed::combined_slip_traction`] (eq. 23) and its aligning moment
//!   [`closed::combined_slip_torque`],
//!   [`closed::rigid_plastic_slip_traction`] (eq. 24).
//!
//! ## Anisotropic stiffness (gy = Ḡy/Ḡx)
//! The report corrects the measured slope for disc compliance separately
//! along and across rolling (Table 4-3, Kalker's C11 ≠ C22), i.e. the film and
//! discs in series act as a stiffness that differs between x and y. With
//! [`Inputs::with_stiffness_ratio`] the elastic law becomes dZ/dX =
//! G·(v − plastic part), G = diag(1, gy), the J's formed with Ḡx; the flow
//! stays associated (plastic strain rate along Z), so on the limit
//! λ = (n·Gv − dL/dX)/(n·G·n) and θ' = (t·Gv − λ·t·G·n)/L (t ⟂ n), which for
//! gy = 1 is the isotropic law. Elastic segments keep their closed forms;
//! the rigid/plastic limit does not depend on gy (Z = L·v/|v|). Checked
//! against the grid scheme with the energy-norm return mapping
//! (tests/anisotropy.rs: agreement ≈ 6e-6) and by the exact reductions for
//! one-directional slip. gy = 1 (the default) is the report's model.
//!
//! ## Assumptions
//! Hertzian pressure and ellipse, constant film thickness, isothermal, no
//! stress in the inlet, no roller compliance beyond what Ḡ absorbs.
//!
//! ## Symmetries (tested)
//! * (J1, J2, J3) → −(J1, J2, J3): (J4, J5, J6) change sign (ΔX = 0 or any ΔX).
//! * Mirror y → −y: (J1, −J2, −J3) gives (J4, −J5, −J6).
//! * Negative rolling direction (App. VI): reversing the discs reverses U and
//!   ω together; in the frame that rolls forwards (x' = −x, y' = −y) the spin
//!   J3 changes sign and ΔV' = ΔV. Mapped back to the lab y-axis with the mirror
//!   above, the report prints it as the same J3 with J2 → −J2: its "negative
//!   rolling direction" tables are J5(0, −J2, J3).
//!
//! ## Kalker's simplified theory (FASTSIM)
//! The elastic/plastic model is Kalker's simplified theory with one
//! flexibility for all directions and an ellipsoidal traction bound. Along the
//! rolling direction FASTSIM integrates dp/dx = (slip)/L_K with the surface
//! traction p, flexibility L_K (m³/N) and creepages; here
//! dτ/dx = (Ḡ/h)·(γ̇·h/U), so
//! * flexibility L_K = h/Ḡ (film thickness over the effective shear modulus);
//! * creepages ξ = ΔU/U, η = ΔV/U, spin creepage φ = ω/U (1/m);
//! * traction bound μ·P(x, y) = (3/2)·μN/(πab)·√(1−x²/a²−y²/b²) = (3/2)τ̄√(…);
//! * J1 = ξ·√(ab)/(L_K τ̄), J2 = η·√(ab)/(L_K τ̄), J3 = φ·ab/(L_K τ̄) with
//!   τ̄ = μN/(πab); conversely ξ = J1·L_K·τ̄/√(ab), φ = J3·L_K·τ̄/(ab);
//! * Fx = J4·μN, Fy = J5·μN, Mz = J6·μN√(ab) (about the spin pole).
//!
//! FASTSIM usually takes three flexibilities L1, L2, L3 fitted to Kalker's
//! linear theory and defines creepage as the rigid slip of body 1 against body
//! 2 with the traction opposing it; to compare, set L1 = L2 = L3 = h/Ḡ and mind
//! the sign (here ΔU > 0 gives J4 > 0, and γ̇y = (ΔV + ω(x+δ))/h).
//!
//! ## Accuracy
//! [`Accuracy`] sets the target absolute error of J4, J5, J6; tests check it
//! against converged solutions and a second, independent grid method
//! ([`reference`](mod@reference): the strip integrator at a fixed resolution, the grid
//! scheme).
//!
//! ## Example
//! ```
//! use traction_rheology::{Accuracy, Inputs, Model, evaluate};
//!
//! // Slip only: the integrator reproduces App. V eq. 22.
//! let inp = Inputs::new(1.0, 1.5, 0.0, 0.0).unwrap();
//! let out = evaluate(&inp, Model::ElasticPlastic, Accuracy::new(1e-6).unwrap()).unwrap();
//! let exact = traction_rheology::closed::slip_traction(1.0, 1.5);
//! assert!((out.j4 - exact).abs() < 1e-6);
//! // Spin adds side force and torque; J7 = J1·J4 + J2·J5 + J3·J6 ≥ 0.
//! let spin = Inputs::new(1.0, 1.5, 0.0, 2.0).unwrap();
//! let o = evaluate(&spin, Model::ElasticPlastic, Accuracy::default()).unwrap();
//! assert!(o.j4 < out.j4 && o.j7 >= 0.0);
//! ```
#![forbid(unsafe_code)]

pub mod closed;
mod counts;
mod ep;
pub mod field;
pub mod map;
pub mod props;
mod quad;
pub mod reference;
mod rigid;
mod visco;

#[cfg(feature = "step-counts")]
pub use counts::{StepCounts, reset_step_counts, step_counts};
pub use ep::Resolution;
pub use field::{PointState, StressField, stress_field};
pub use props::{Limit, Modulus, Properties};
pub use traction_range::{OutOfRange, Range};

/// Smallest supported aspect ratio k.
pub const K_MIN: f64 = 0.01;
/// Largest supported aspect ratio k.
pub const K_MAX: f64 = 100.0;
/// Smallest supported stiffness ratio gy = Ḡy/Ḡx.
pub const GY_MIN: f64 = 0.1;
/// Largest supported stiffness ratio gy = Ḡy/Ḡx.
pub const GY_MAX: f64 = 10.0;
/// Valid aspect ratios k = b/a: [[`K_MIN`], [`K_MAX`]].
pub const ASPECT_RATIO_RANGE: Range = Range::closed(K_MIN, K_MAX);
/// Valid stiffness ratios gy = Ḡy/Ḡx: [[`GY_MIN`], [`GY_MAX`]].
pub const STIFFNESS_RATIO_RANGE: Range = Range::closed(GY_MIN, GY_MAX);
/// Valid accuracy targets of [`Accuracy::new`] (absolute error of J4, J5, J6).
pub const TOLERANCE_RANGE: Range = Range::closed(1e-9, 0.1);
/// Valid Deborah numbers D = ηU/(Ḡa) of [`Model::Viscoelastic`]: > 0, `inf`
/// being the elastic/plastic limit.
pub const DEBORAH_RANGE: Range = Range::POSITIVE.with_infinity();
/// Valid sinh reference stresses Z0 = τ0/τ̄ of [`Model::Viscoelastic`]: > 0,
/// `inf` being the linear Maxwell fluid.
pub const REFERENCE_STRESS_RANGE: Range = Range::POSITIVE.with_infinity();
/// Above this max(|J1|, |J2|, |J3|) the elastic lag is below 1e-12 of the
/// traction and the elastic/plastic model returns the rigid/plastic solution.
pub const J_RIGID: f64 = 1e12;
/// Largest |J1|, |J2|, |J3| and |ΔX| accepted. Far beyond any physical state
/// (a contact standing still with slip or spin has J's of 1e5–1e12, set by
/// its rolling-speed floor; the extremes of traction-contact's input ranges
/// stay below 1e32; from [`J_RIGID`] on the result is the rigid/plastic
/// limit), and small enough
/// that J7 = J1·J4 + J2·J5 + J3·J6 stays within the floating-point range
/// (at |J3| = 1.7e308 and k = 0.1 it overflowed to infinity).
pub const J_MAX: f64 = 1e100;
/// Valid J1, J2, J3 and ΔX: [−[`J_MAX`], [`J_MAX`]].
pub const J_RANGE: Range = Range::closed(-J_MAX, J_MAX);

/// Errors of this crate; every variant names the quantity and its valid range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RheologyError {
    /// An input is NaN, infinite or outside its valid range (the message
    /// names the quantity, the value and the range): k
    /// ([`ASPECT_RATIO_RANGE`]), J1, J2, J3, ΔX ([`J_RANGE`]), gy
    /// ([`STIFFNESS_RATIO_RANGE`]), the accuracy ([`TOLERANCE_RANGE`],
    /// [`map::TOLERANCE_RANGE`]), D ([`DEBORAH_RANGE`]), Z0
    /// ([`REFERENCE_STRESS_RANGE`]).
    #[error(transparent)]
    OutOfRange(#[from] OutOfRange),
    /// Inputs given to a [`map::Map`] built for another k, ΔX or gy.
    #[error("{name} = {value} differs from the map's {name} = {map}")]
    MapKey {
        /// Which quantity (k, dX, gy).
        name: &'static str,
        /// The input's value.
        value: f64,
        /// The map's value.
        map: f64,
    },
    /// A stress-field grid size is outside 1..=4000.
    #[error("grid size {0} is outside the supported range 1..=4000")]
    Grid(usize),
}

/// Inputs in the report's dimensionless groups.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inputs {
    /// Aspect ratio k = b/a.
    pub k: f64,
    /// Dimensionless slip J1.
    pub j1: f64,
    /// Dimensionless side slip J2.
    pub j2: f64,
    /// Dimensionless spin J3.
    pub j3: f64,
    /// Dimensionless spin-pole offset ΔX = δ/a (App. IV sign: rate J3(X+ΔX)/k).
    pub dx: f64,
    /// Lateral-to-longitudinal stiffness ratio gy = Ḡy/Ḡx in
    /// [[`GY_MIN`], [`GY_MAX`]] (1 = isotropic, the report's model). The J's
    /// are formed with Ḡx; the elastic rate across rolling is gy times the
    /// slip term (see "Anisotropic stiffness" in the crate docs).
    pub gy: f64,
}

impl Inputs {
    /// Validated inputs with ΔX = 0.
    pub fn new(k: f64, j1: f64, j2: f64, j3: f64) -> Result<Self, RheologyError> {
        Self::with_offset(k, j1, j2, j3, 0.0)
    }

    /// Validated inputs with a spin-pole offset ΔX.
    pub fn with_offset(k: f64, j1: f64, j2: f64, j3: f64, dx: f64) -> Result<Self, RheologyError> {
        let inp = Inputs {
            k,
            j1,
            j2,
            j3,
            dx,
            gy: 1.0,
        };
        inp.validate()?;
        Ok(inp)
    }

    /// The same inputs with the stiffness ratio gy = Ḡy/Ḡx (validated).
    pub fn with_stiffness_ratio(self, gy: f64) -> Result<Self, RheologyError> {
        let inp = Inputs { gy, ..self };
        inp.validate()?;
        Ok(inp)
    }

    /// Check k, the J's and ΔX ([`J_RANGE`]) and gy (the fields are public,
    /// so [`evaluate`] checks again).
    pub fn validate(&self) -> Result<(), RheologyError> {
        ASPECT_RATIO_RANGE.check("aspect ratio k", self.k)?;
        for (name, value) in [
            ("J1", self.j1),
            ("J2", self.j2),
            ("J3", self.j3),
            ("dX", self.dx),
        ] {
            J_RANGE.check(name, value)?;
        }
        STIFFNESS_RATIO_RANGE.check("stiffness ratio gy = Gy/Gx", self.gy)?;
        Ok(())
    }
}

/// Results in the report's dimensionless groups.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outputs {
    /// Traction along the rolling direction J4 = Fx/(μN).
    pub j4: f64,
    /// Side force J5 = Fy/(μN).
    pub j5: f64,
    /// Spin torque J6 = T/(μN√(ab)).
    pub j6: f64,
    /// Losses J7 = J1·J4 + J2·J5 + J3·J6.
    pub j7: f64,
}

impl Outputs {
    /// Loss factor LF = J7/J4 (App. IV eq. 18); infinite when J4 = 0 and J7 > 0.
    pub fn loss_factor(&self) -> f64 {
        self.j7 / self.j4
    }
}

/// Which constitutive model to integrate.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[non_exhaustive]
pub enum Model {
    /// Elastic/perfectly plastic (Prandtl–Reuss), Ḡ constant, limit
    /// (3/2)√(1−X²−Y²) — the report's printed theory.
    #[default]
    ElasticPlastic,
    /// Rigid/plastic (Ḡ → ∞): Z = L·v/|v|.
    RigidPlastic,
    /// Elastic/perfectly plastic with any of App. IV's property variations
    /// ([`Properties`]): the default combination is [`Model::ElasticPlastic`];
    /// the others use a Richardson-extrapolated grid scheme whose error is
    /// ≈ 1e-4 (cells per strip 400/800 for tol ≥ 1e-4, 1600/3200 below; see
    /// [`props`]) and cost milliseconds per evaluation.
    PropertyVariation(Properties),
    /// Viscoelastic sinh law with the limit as a cap.
    Viscoelastic {
        /// Deborah number D = ηU/(Ḡa) (> 0, `inf` allowed).
        deborah: f64,
        /// Sinh reference stress Z0 = τ0/τ̄ (> 0, `inf` = Maxwell fluid).
        z0: f64,
    },
}

/// Accuracy request: the target absolute error of J4, J5 and J6.
///
/// Meaning: the result is within `tol` of the converged solution of the same
/// model (verified in rheology/tests/convergence.rs for tol = 1e-2, 1e-3,
/// 1e-4 against a 128-panel, h = 0.004 reference; the cases and the worst
/// observed error/tol are stated in the crate README, section Convergence).
/// The elastic/plastic
/// integrator is fourth order in the s-step and, in Y, spectrally convergent
/// except across strips where the flow pattern changes (second order there),
/// which the adaptive panel halving of [`evaluate`] localises. Below tol
/// 1e-4 the same rules hold, with the stiff plastic steps' RK4 margin
/// falling as √tol and their quasi-steady steps starting at a fixed κ
/// (docs/decisions/0129; before, the strips' error stayed near 1e-5 at
/// high spin and small k, up to 12·tol at 1e-6). A whole-range scan of
/// 30 000 cases at tol 3e-5 / 1e-5 / 5e-6 against tol 2.5e-7 measured
/// worst 0.58 / 0.65 / 0.31·tol; tests cover cases to tol 1e-6. Such
/// tolerances cost more than the former rules: +15 % at 1e-5, +49 % at
/// 1e-6 on the 307 cases of `cargo xtask ep-sets bits`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Accuracy {
    tol: f64,
}

impl Default for Accuracy {
    /// 1e-4, the CLI default.
    fn default() -> Self {
        Accuracy { tol: 1e-4 }
    }
}

impl Accuracy {
    /// An accuracy target in [`TOLERANCE_RANGE`].
    pub fn new(tol: f64) -> Result<Self, RheologyError> {
        TOLERANCE_RANGE.check("accuracy tol", tol)?;
        Ok(Accuracy { tol })
    }

    /// The target absolute error.
    pub fn tol(&self) -> f64 {
        self.tol
    }

    /// Target step in s of the plastic segments: 0.1·(tol/1e-3)^(1/4)
    /// (RK4 is fourth order), clamped to [0.002, 0.3].
    pub fn s_step(&self) -> f64 {
        (0.1 * (self.tol / 1e-3).powf(0.25)).clamp(0.002, 0.3)
    }

    /// A fixed (non-adaptive) discretisation for this target, for
    /// [`reference::elastic_plastic`]: panels ⌈10·√(1e-3/tol)⌉ of 8 Gauss
    /// points and [`Accuracy::s_step`]. [`evaluate`] uses an adaptive Y
    /// quadrature (Lobatto–Kronrod panels) instead, which is 3–8× cheaper
    /// for moderate spin at the same verified accuracy.
    pub fn resolution(&self) -> Resolution {
        // Calibrated by the convergence study (rheology/tests/convergence.rs):
        // the error is dominated by the Y quadrature across strips where the
        // flow pattern changes (second order in the panel width) and by RK4
        // in s (fourth order): panels ∝ tol^(-1/2), s-step ∝ tol^(1/4).
        let p = (10.0 * (1e-3 / self.tol).sqrt()).ceil();
        let panels = p.clamp(2.0, 400.0) as usize;
        Resolution {
            y_panels: panels,
            y_points: 8,
            s_step: self.s_step(),
        }
    }
}

/// Evaluate a model at the given accuracy.
///
/// Every output is finite for finite inputs. The elastic/plastic model uses
/// the closed forms of App. V eq. 23 and [`closed::combined_slip_torque`]
/// when J3 = 0 and gy = 1 (exact; ΔX only moves the torque's reference
/// point, adding ΔX·J5/√k), and the rigid/plastic solution when
/// max|J| > [`J_RIGID`]. Otherwise it integrates strips with adaptive panels
/// in Y (a 5-point Gauss–Lobatto rule checked against Simpson's rule on
/// its nodes, and where that does not settle the panel against its 9-point
/// Kronrod extension, starting from panels graded towards the spin pole's
/// strip,
/// refinement blended so that the outputs are continuous in the inputs; for
/// J1 = 0 only Y ≥ 0, the strips being mirror images about Y = 0) and the
/// s-step [`Accuracy::s_step`], doubled on
/// plastic segments that stay non-stiff (κ·h below the RK4 stability
/// margin) at the doubled step; stiff segments on which the slip direction
/// turns slowly take exponential steps of up to 0.8·√(tol/1e-3) ≤ 0.8
/// instead (docs/decisions/0068 and 0049).
pub fn evaluate(inp: &Inputs, model: Model, acc: Accuracy) -> Result<Outputs, RheologyError> {
    inp.validate()?;
    let (j4, j5, j6) = match model {
        Model::ElasticPlastic => {
            if inp.j3 == 0.0 && inp.gy == 1.0 {
                let (j4, j5) = closed::combined_slip_traction(inp.k, inp.j1, inp.j2);
                // Torque about the spin pole (crate docs): the centre's
                // aligning moment plus ΔX·J5/√k.
                let j6 = closed::combined_slip_torque(inp.k, inp.j1, inp.j2)
                    + inp.dx * j5 / inp.k.sqrt();
                (j4, j5, j6)
            } else {
                return adaptive(inp, acc.tol);
            }
        }
        Model::RigidPlastic => return rigid_plastic(inp, acc),
        Model::PropertyVariation(props) => return elastic_plastic_with(inp, props, acc),
        Model::Viscoelastic { deborah, z0 } => return viscoelastic(inp, deborah, z0, acc),
    };
    Ok(finish(inp, j4, j5, j6))
}

fn finish(inp: &Inputs, j4: f64, j5: f64, j6: f64) -> Outputs {
    // Large J's with tiny forces: keep J7 finite (the products are bounded by
    // max|J|·O(1); f64 holds them for |J| < 1e300).
    let j7 = inp.j1 * j4 + inp.j2 * j5 + inp.j3 * j6;
    Outputs { j4, j5, j6, j7 }
}

/// Scale J's down when they are so large that the rigid/plastic solution is
/// exact to round-off (only ratios matter there).
fn rigid_scaled(inp: &Inputs) -> ep::Scaled {
    let m = inp.j1.abs().max(inp.j2.abs()).max(inp.j3.abs());
    let f = if m > 1.0 { 1.0 / m } else { 1.0 };
    ep::Scaled::new(inp.k, inp.j1 * f, inp.j2 * f, inp.j3 * f, inp.dx).with_gy(inp.gy)
}

/// Longer s-step factor of [`evaluate`] on non-stiff plastic segments (κ·h
/// below the RK4 margin at the longer step): 2 keeps the worst error/tol of
/// the 13-case convergence test unchanged (3 raised it ≈ 1.8-fold at
/// tol = 1e-4).
const SMOOTH_STEP_FACTOR: f64 = 2.0;

/// The plastic steps of [`evaluate`]'s strips at the accuracy `tol`: the
/// s-step [`Accuracy::s_step`], the longer s-step of non-stiff segments,
/// the longest exponential step (0: none) and whether steps near vy = 0 may
/// be set by the exact turn of the slip direction; also the viscoelastic
/// model's cap.
pub(crate) fn plastic_steps(tol: f64) -> (f64, f64, f64, bool) {
    let s_step = Accuracy { tol }.s_step();
    let h = s_step.clamp(1e-4, 0.5);
    let hs = (SMOOTH_STEP_FACTOR * s_step).clamp(h, 1.0);
    (h, hs, ep::etd_step(tol, h), true)
}

fn adaptive(inp: &Inputs, tol: f64) -> Result<Outputs, RheologyError> {
    inp.validate()?;
    let m = inp.j1.abs().max(inp.j2.abs()).max(inp.j3.abs());
    if m > J_RIGID {
        return rigid_plastic(inp, Accuracy { tol: 1e-6 });
    }
    let sc = ep::Scaled::of(inp);
    let (j4, j5, j6) = ep::solve_adaptive(&sc, tol, plastic_steps(tol));
    Ok(finish(inp, j4, j5, j6))
}

/// Rigid/plastic model (App. IV eq. 14 with side slip and ΔX, App. V eq. 14).
///
/// Strips in s split at the crossing of vy = 0 and graded towards it (the
/// direction turns by π there within |vx|·gy/|q2|), adaptive panels in Y
/// split at the pole strip and where vy = 0 leaves the ellipse (see
/// `rigid.rs`): within `tol` of the converged solution; a test checks
/// 1e-6 against an independent nested adaptive Simpson reference.
pub(crate) fn rigid_plastic(inp: &Inputs, acc: Accuracy) -> Result<Outputs, RheologyError> {
    inp.validate()?;
    let sc = rigid_scaled(inp);
    let (j4, j5, j6) = rigid::solve(&sc, acc.tol);
    Ok(finish(inp, j4, j5, j6))
}

/// Viscoelastic J+T model (sinh law, App. V eqs. 3–6) with the limit as a cap.
///
/// `deborah` = D = ηU/(Ḡa) > 0 (`inf` returns the elastic/plastic model),
/// `z0` = τ0/τ̄ > 0 (`inf` = linear Maxwell fluid). Adaptive fourth-order
/// Rosenbrock steps along each strip with the cap entries and unloadings
/// located inside the steps, adaptive Lobatto–Kronrod panels across the
/// contact (`visco/`); within `tol` of the converged solution.
pub(crate) fn viscoelastic(
    inp: &Inputs,
    deborah: f64,
    z0: f64,
    acc: Accuracy,
) -> Result<Outputs, RheologyError> {
    inp.validate()?;
    check_viscoelastic(deborah, z0)?;
    if deborah.is_infinite() {
        return evaluate(inp, Model::ElasticPlastic, acc);
    }
    let law = visco::Law::new(z0, deborah);
    // Huge J with a bounded viscous rate: the stress is on the cap
    // everywhere (the elastic rate exceeds the largest viscous rate
    // ψ(3/2) by more than 1e9), i.e. the rigid/plastic solution.
    let m = inp.j1.abs().max(inp.j2.abs()).max(inp.j3.abs());
    if m > J_RIGID && law.psi_max() < 1e-9 * m {
        return rigid_plastic(inp, Accuracy { tol: 1e-6 });
    }
    let (j4, j5, j6) = visco::solve(&ep::Scaled::of(inp), law, acc.tol);
    Ok(finish(inp, j4, j5, j6))
}

/// Range checks of the viscoelastic parameters D and Z0.
fn check_viscoelastic(deborah: f64, z0: f64) -> Result<(), RheologyError> {
    DEBORAH_RANGE.check("Deborah number D (inf: the elastic/plastic limit)", deborah)?;
    REFERENCE_STRESS_RANGE.check(
        "reference stress Z0 = tau0/tau_bar (inf: a Maxwell fluid)",
        z0,
    )?;
    Ok(())
}

/// Elastic/plastic model with a property variation ([`Model::PropertyVariation`]).
fn elastic_plastic_with(
    inp: &Inputs,
    props: Properties,
    acc: Accuracy,
) -> Result<Outputs, RheologyError> {
    if props == Properties::default() {
        return evaluate(inp, Model::ElasticPlastic, acc);
    }
    let n = if acc.tol >= 1e-4 { 400 } else { 1600 };
    reference::grid(inp, props, n)
}
