//! The regime of App. IV figure 14 (regions I–III) and the inverse of the
//! zero-spin traction function ψ.

use std::f64::consts::PI;

use traction_rheology::{Accuracy, Inputs};

use crate::contact::Branch;
use crate::{ContactError, Model, REGIME_TOLERANCE, Regime, TractionContact};

/// Accuracy of the rigid/plastic solution that the regime compares with
/// (at least; the contact's own where finer is not asked for): its error
/// moves the 5 % boundary of region III by at most this over the traction
/// norm of the solution (≈ 0.1–1 where spin matters), i.e. to 5 ± 1 % at
/// worst, while a cold rigid/plastic solution at large |J| costs ≈ 10× less
/// than at 1e-4 (0.12 ms → < 0.01 ms for a contact at rest with spin;
/// docs/decisions/0111).
const REGIME_RIGID_TOL: f64 = 1e-3;

impl TractionContact {
    /// Regions I–III of App. IV figure 14 by the 5 % criterion (crate docs).
    pub(crate) fn classify(&self, k: f64, br: &Branch) -> Result<Regime, ContactError> {
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
            let tol = self.options().accuracy.tol().max(REGIME_RIGID_TOL);
            traction_rheology::evaluate(&inp, Model::RigidPlastic, Accuracy::new(tol)?)?
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

/// Inverse of the zero-spin traction function ψ(S) of App. V eq. 22 for
/// 0 ≤ T: with S = tan φ, πψ = 2φ + sin 2φ (increasing and concave in φ on
/// [0, π/2)), Newton on φ with a bisection safeguard; `f64::INFINITY` for
/// T ≥ 1.
///
/// The start is φ = πT/4 (the exact slope at 0, left of the root) for
/// T ≤ 1/2 and φ = π/2 − (3π(1 − T)/4)^(1/3) (from 2δ − sin 2δ ≈ (2δ)³/6
/// at φ = π/2 − δ, right of the root) above, where the root approaches the
/// flat end and Newton from πT/4 would converge slowly. The iteration stops
/// when the residual is at the rounding of πT or the step below 1e-15 of
/// φ: 1–5 iterations over T ∈ (0, 1). S is then accurate to its
/// conditioning, ≈ (π/4)·S³·ε relative for S ≫ 1.
pub fn inverse_psi(t: f64) -> f64 {
    if t.is_nan() || t <= 0.0 {
        return 0.0;
    }
    if t >= 1.0 {
        return f64::INFINITY;
    }
    let target = PI * t;
    let (mut lo, mut hi) = (0.0_f64, PI / 2.0);
    let mut phi = if t > 0.5 {
        PI / 2.0 - (0.75 * PI * (1.0 - t)).cbrt()
    } else {
        0.25 * target
    };
    for _ in 0..60 {
        let f = 2.0 * phi + (2.0 * phi).sin() - target;
        // At the rounding of the residual Newton's step is noise (and a
        // step onto the bracket's end would send it to bisection).
        if f.abs() <= 4.0 * f64::EPSILON * target {
            break;
        }
        if f > 0.0 {
            hi = phi;
        } else {
            lo = phi;
        }
        let d = 4.0 * phi.cos().powi(2);
        let mut next = phi - f / d;
        if !(next >= lo && next <= hi) {
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
