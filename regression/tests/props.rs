//! Property tests of the correlation algebra.
use proptest::prelude::*;
use traction_regression::{
    Correlation, Model, Normalised, TemperatureForm, TermSet, Variables, percent_error,
};

fn vars() -> impl Strategy<Value = Variables> {
    (
        5.0..90.0f64,
        0.5..2.5f64,
        20.0..90.0f64,
        0.4..6.0f64,
        0.0..0.03f64,
    )
        .prop_map(|(speed, p0_gpa, theta_celsius, k, z)| Variables {
            speed,
            p0_gpa,
            theta_celsius,
            k,
            z,
        })
}

proptest! {
    /// Percent error is antisymmetric and has the sign of a − e.
    #[test]
    fn percent_error_antisymmetric(a in 0.01..100.0f64, e in 0.01..100.0f64) {
        let p = percent_error(a, e);
        prop_assert!((p + percent_error(e, a)).abs() <= 1e-9 * p.abs().max(1.0));
        prop_assert_eq!(p > 0.0, a > e);
    }

    /// At the means every primed variable is 0, so eq. 14/15 in the linear
    /// form reduce to C1, and the normalisation inverts exactly.
    #[test]
    fn at_the_means_only_c1_survives(m in vars(), c in proptest::collection::vec(-1.0..1.0f64, 32)) {
        let mut means = m;
        means.z = m.z.max(1e-4);
        let lin = Model { terms: TermSet::ThirtyTwo, temperature: TemperatureForm::Linear };
        let corr = Correlation::new(lin, means, c.clone(), f64::INFINITY).unwrap();
        let v = corr.evaluate(&means).unwrap();
        prop_assert!((v - c[0]).abs() <= 1e-12);
        let n = Normalised::new(&m, &means);
        prop_assert!((means.speed * (1.0 + n.u) - m.speed).abs() <= 1e-9 * m.speed);
    }

    /// Evaluation never returns NaN or infinity: either a finite value or an
    /// error (the θ' guard included).
    #[test]
    fn evaluate_is_finite_or_error(x in vars(), m in vars(), c in proptest::collection::vec(-1.0..1.0f64, 16)) {
        let corr = Correlation::new(Model::EQ14, m, c, 200.0).unwrap();
        if let Ok(v) = corr.evaluate(&x) { prop_assert!(v.is_finite()); }
    }

    /// The 16-term model is the 32-term model with Z' = 0 and odd (Z')
    /// coefficients dropped: term j of eq. 14 is term 2j of eq. 15.
    #[test]
    fn eq14_embeds_in_eq15(x in vars(), m in vars()) {
        let mut means = m; means.z = 0.01;
        let mut xx = x; xx.z = means.z; // Z' = 0
        let n = Normalised::new(&xx, &means);
        let r14 = Model::EQ14.row(&n);
        let r15 = Model::EQ15.row(&n);
        for j in 0..16 {
            prop_assert!((r14[j] - r15[2 * j]).abs() <= 1e-12 * r14[j].abs().max(1.0));
        }
    }
}
