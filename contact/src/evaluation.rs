//! The result of an evaluation and the regime of App. IV figure 14.

use crate::OutsideEnvelope;

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
    /// Not classified ([`Options::classify_regime`](crate::Options::classify_regime) = false).
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
    /// Mean (mid-plane) temperature rise of the film over the inlet
    /// temperature, K, from the thermal model ([`crate::Options::thermal`]);
    /// 0 when the model is off. `m_used`, `mu_used` are then the values at
    /// the raised temperature.
    pub temperature_rise: f64,
}

impl Evaluation {
    /// Loss factor J7/J4 (App. IV eq. 18); `None` when J4 = 0.
    pub fn loss_factor(&self) -> Option<f64> {
        (self.j4 != 0.0).then(|| self.j7 / self.j4)
    }
}
