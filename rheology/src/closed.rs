//! Closed forms for zero spin (Appendix V equations 22–24, main text equation 8).
//!
//! With J3 = 0 every strip sees a constant elastic rate, the elastic stress
//! grows linearly from the inlet, meets the limit (3/2)√(1−X²−Y²) at
//! ξ* = X*/c = (1−S²)/(1+S²) and then follows the limit to the outlet. The strip
//! integral is c²·F(S), so the contact integral is elementary.

use std::f64::consts::PI;

/// The report's traction function ψ(S) (Appendix V equation 22/23):
/// ψ = (1/π)[π/2 − asin((1−S²)/(1+S²)) + 2S/(1+S²)], evaluated as
/// (2/π)[atan S + S/(1+S²)] (identical for all S, free of cancellation at
/// small S, odd in S).
pub fn psi(s: f64) -> f64 {
    if !s.is_finite() {
        return s.signum();
    }
    (2.0 / PI) * (s.atan() + s / (1.0 + s * s))
}

/// ψ(S)/S, finite at S = 0 (limit 4/π).
fn psi_over_s(s: f64) -> f64 {
    if s.abs() < 1e-8 { 4.0 / PI } else { psi(s) / s }
}

/// Traction J4 for slip only (Appendix V equation 22, main text equation 8):
/// J4 = ψ(S) with S = (2/3)·J1/√k. Odd in J1.
pub fn slip_traction(k: f64, j1: f64) -> f64 {
    psi((2.0 / 3.0) * j1 / k.sqrt())
}

/// (J4, J5) for combined slip and side slip, zero spin (Appendix V
/// equation 23): J4 = (2/3)·J1·ψ/(S√k), J5 = (2/3)·J2·ψ/(S√k) with
/// S = (2/3)·√(J1²+J2²)/√k. The spin-pole offset has no effect here.
pub fn combined_slip_traction(k: f64, j1: f64, j2: f64) -> (f64, f64) {
    let sk = k.sqrt();
    let mag = j1.hypot(j2);
    let s = (2.0 / 3.0) * mag / sk;
    if s.is_infinite() || mag > 1e300 {
        // Rigid/plastic limit (equation 24) without overflow.
        let (a, b) = (
            j1 / mag.max(f64::MIN_POSITIVE),
            j2 / mag.max(f64::MIN_POSITIVE),
        );
        return (a, b);
    }
    let f = (2.0 / 3.0) * psi_over_s(s) / sk;
    (f * j1, f * j2)
}

/// (J4, J5) of the rigid/plastic model without spin (Appendix V equation 24):
/// the traction is the full limit in the direction of the slip vector,
/// J4 = J1/√(J1²+J2²), J5 = J2/√(J1²+J2²); (0, 0) when both are zero.
pub fn rigid_plastic_slip_traction(j1: f64, j2: f64) -> (f64, f64) {
    // Scale first so that J's near f64::MAX do not overflow the hypot.
    let m = j1.abs().max(j2.abs());
    if m == 0.0 {
        return (0.0, 0.0);
    }
    let (a, b) = (j1 / m, j2 / m);
    let h = a.hypot(b);
    (a / h, b / h)
}

/// Spin torque J6 about the contact centre for combined slip and side slip,
/// zero spin (elastic/plastic model, the aligning moment of the side force):
/// J6 = J2/(4k·(1+S²)²) with S = (2/3)·√(J1²+J2²)/√k.
///
/// Derivation: every strip (half-width c) sees the constant elastic rate
/// v = (J1, J2)/√k; Zy = vy·(X + c) up to the yield point X* = c·ξ*,
/// ξ* = (1−S²)/(1+S²), and Zy = L·vy/|v| beyond it. With X = c·ξ,
/// ∫Zy·X dX = c³·vy·[(ξ*+1)²(2ξ*−1)/6 + (1−ξ*²)^{3/2}/(2|v|)]
/// = c³·vy·(2/3)/(1+S²)², and ∫(1−Y²)^{3/2} dY = 3π/8; the Zx·Y part is odd
/// in Y. The elastic limit (S → 0) is (1/4)J2/k, the rigid/plastic limit 0
/// (the lateral traction is then symmetric about X = 0). With a spin-pole
/// offset the torque about the pole adds ΔX·J5/√k (see the crate docs).
pub fn combined_slip_torque(k: f64, j1: f64, j2: f64) -> f64 {
    let s = (2.0 / 3.0) * j1.hypot(j2) / k.sqrt();
    let d = 1.0 + s * s;
    // d = inf for huge slips: the torque is 0 (rigid/plastic limit).
    j2 / (4.0 * k * d * d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn psi_matches_the_printed_form() {
        // The printed form (π/2 − asin((1−S²)/(1+S²)) + 2S/(1+S²))/π, S ≥ 0;
        // the two expressions are algebraically identical: 1e-14.
        for &s in &[0.01_f64, 0.3, 1.0, 1.2527, 3.0, 40.0] {
            let printed =
                (PI / 2.0 - ((1.0 - s * s) / (1.0 + s * s)).asin() + 2.0 * s / (1.0 + s * s)) / PI;
            assert!((psi(s) - printed).abs() < 1e-14, "{s}");
        }
        assert_eq!(psi(0.0), 0.0);
        assert_eq!(psi(f64::INFINITY), 1.0);
    }

    #[test]
    fn small_slip_is_the_elastic_integral() {
        // Elastic limit: Zx = (J1/√k)(X + c), ∫∫ = (J1/√k)·(8/3), so
        // J4 = 8 J1/(3π√k). Relative agreement 1e-6 at J1 = 1e-4 (the
        // next term of ψ is O(S²) ≈ 1e-9).
        let (k, j1) = (2.0_f64, 1e-4_f64);
        let exact = 8.0 * j1 / (3.0 * PI * k.sqrt());
        assert!((slip_traction(k, j1) / exact - 1.0).abs() < 1e-6);
        let (j4, j5) = combined_slip_traction(k, j1, 0.0);
        assert!((j4 / exact - 1.0).abs() < 1e-6 && j5 == 0.0);
    }

    #[test]
    fn small_side_slip_torque_is_the_elastic_integral() {
        // Elastic limit: Zy = (J2/√k)(X + c), ∫∫Zy·X = (J2/√k)·(2/3)·(3π/8),
        // so J6 = J2/(4k); relative agreement 1e-7 at S ≈ 1e-4 (next term
        // −2S², 2e-8).
        let (k, j2) = (2.0_f64, 2e-4_f64);
        let j6 = combined_slip_torque(k, 0.0, j2);
        assert!((j6 / (j2 / (4.0 * k)) - 1.0).abs() < 1e-7, "{j6}");
        assert_eq!(combined_slip_torque(1.0, 1e300, 1e300), 0.0);
    }

    #[test]
    fn rigid_limit_and_huge_inputs_are_finite() {
        let (a, b) = combined_slip_traction(1.0, 1e300, 1e300);
        assert!((a - 0.5_f64.sqrt()).abs() < 1e-12 && (b - 0.5_f64.sqrt()).abs() < 1e-12);
        let (a, b) = rigid_plastic_slip_traction(f64::MAX, f64::MAX);
        assert!((a - 0.5_f64.sqrt()).abs() < 1e-12 && (b - a).abs() < 1e-15);
        assert_eq!(rigid_plastic_slip_traction(0.0, 0.0), (0.0, 0.0));
    }
}
