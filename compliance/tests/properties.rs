//! Property tests of the Kalker interpolation and the slope conversion.

use proptest::prelude::*;
use traction_compliance::{
    Coefficient, Direction, DiscMaterial, SlopeContact, convert_slope, convert_slope_same_contact,
    kalker_coefficient,
};

proptest! {
    // Kalker's C11, C22, C23 grow with ν in every tabulated row, and C22, C23 with
    // a/b in every column; C11 grows with a/b for ν ≤ 0.25 only (the ν = 0.5 column
    // itself dips: 4.85, 4.81, 4.80, 4.82 at a/b = 0.1..0.4, below the a/b → 0 limit
    // 4.93). The interpolation must keep those orders.
    #[test]
    fn coefficients_monotonic(lg in -2.5..2.5f64, dlg in 1e-3..0.5f64, nu in 0.0..0.49f64, dnu in 1e-3..0.01f64) {
        let (r1, r2) = (10f64.powf(lg), 10f64.powf(lg + dlg));
        for c in [Coefficient::C11, Coefficient::C22, Coefficient::C23] {
            let a = kalker_coefficient(c, r1, nu).unwrap();
            let b = kalker_coefficient(c, r2, nu).unwrap();
            if c != Coefficient::C11 || nu <= 0.25 {
                prop_assert!(b > a, "{c:?} not increasing in a/b: {r1} {a} {r2} {b}");
            }
            let d = kalker_coefficient(c, r1, (nu + dnu).min(0.5)).unwrap();
            prop_assert!(d >= a, "{c:?} not increasing in ν at a/b = {r1}");
        }
    }

    // C33 decreases with a/b inside the table.
    #[test]
    fn c33_decreasing(lg in -1.0..0.99f64, dlg in 1e-3..0.5f64, nu in 0.0..0.5f64) {
        let r2 = 10f64.powf((lg + dlg).min(1.0));
        let a = kalker_coefficient(Coefficient::C33, 10f64.powf(lg), nu).unwrap();
        let b = kalker_coefficient(Coefficient::C33, r2, nu).unwrap();
        prop_assert!(b <= a);
    }

    // (B7) conserves the compliance-corrected modulus, so converting there and
    // back returns the measured slope.
    #[test]
    fn conversion_round_trip(m in 5.0..120.0f64, k in 0.2..5.0f64, p0 in 0.5e9..3e9f64, nu in 0.0..0.5f64) {
        let mat = DiscMaterial::new(210e9, nu).unwrap();
        let there = convert_slope_same_contact(m, k, p0, Direction::Side, Direction::Longitudinal, mat);
        if let Ok(ms) = there {
            let back = convert_slope_same_contact(ms, k, p0, Direction::Longitudinal, Direction::Side, mat).unwrap();
            prop_assert!((back / m - 1.0).abs() < 1e-10);
        }
    }

    // Same q, a, h on both sides: (B7) is the identity.
    #[test]
    fn identity_conversion(m in 1.0..200.0f64, q in 0.2..1.5f64, p0 in 0.5e9..3e9f64) {
        let c = SlopeContact { slope: m, q, a: 1e-4, h: 1e-7 };
        let ms = convert_slope(c, c, p0, 80e9).unwrap();
        prop_assert!((ms / m - 1.0).abs() < 1e-12);
    }
}
