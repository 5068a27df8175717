//! Property tests of the fluid API: never NaN, never a silent extrapolation.
use proptest::prelude::*;
use traction_fluids::{Fluid, Policy, Quantity, Query};

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Any query (including absurd ones) gives an error or a finite positive
    /// value; inside-strict results are never flagged, and every flagged
    /// variable really lies outside the envelope.
    #[test]
    fn finite_or_error_and_flags_are_honest(
        p in -1e9..4e9f64, u in -10.0..120.0f64, t in -20.0..120.0f64, k in -1.0..8.0f64, z in -0.01..0.05f64,
    ) {
        let f = Fluid::santotrac_50().unwrap();
        let q = Query { p0_pa: p, speed_m_s: u, theta_celsius: t, k, z };
        for quantity in [Quantity::Slope, Quantity::Mu, Quantity::SpinMu] {
            if let Ok(e) = f.evaluate(quantity, &q, Policy::Strict) {
                prop_assert!(e.value.is_finite() && e.value > 0.0);
                prop_assert!(!e.is_extrapolated());
            }
            if let Ok(e) = f.evaluate(quantity, &q, Policy::Extrapolate) {
                prop_assert!(e.value.is_finite() && e.value > 0.0);
                prop_assert_eq!(e.is_extrapolated(), !f.correlation(quantity).envelope.outside(&q).is_empty());
            }
        }
    }
}
