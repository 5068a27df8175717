//! Carlson's symmetric elliptic integrals and the complete elliptic integrals.
//!
//! The Hertz solution needs the complete elliptic integrals of the first and
//! second kind, `K(m)` and `E(m)` (parameter `m = e²`, the squared eccentricity
//! of the contact ellipse), and two combinations of them that cancel
//! catastrophically near a circular contact when written in `K` and `E`:
//! `K − E` and `E − (1−m)K`. Carlson's symmetric forms give all of them without
//! cancellation (DLMF 19.25.1):
//!
//! ```text
//! K(m)          = R_F(0, 1−m, 1)
//! K(m) − E(m)   = (m/3)       R_D(0, 1−m, 1)
//! E(m) − (1−m)K = (m(1−m)/3)  R_D(0, 1, 1−m)
//! ```
//!
//! `R_F` and `R_D` are evaluated by Carlson's duplication algorithm
//! (B. C. Carlson, "Numerical computation of real or complex elliptic
//! integrals", Numer. Algorithms 10, 1995) with the series truncated at fifth
//! order; the relative error is below a few units of `f64` round-off. The
//! implementation here is written from the published algorithm.

/// Tolerance parameter `r` of Carlson's algorithm: the truncation error of the
/// final series is of order `r`, far below `f64` round-off. (Used through the
/// precomputed stopping constants below.)
#[cfg(test)]
const CARLSON_R: f64 = 1e-16;

/// `(3r)^(-1/6)` for `r` = [`CARLSON_R`] (the R_F stopping constant),
/// precomputed; checked against `powf` in the tests.
const RF_Q_FACTOR: f64 = 386.497_293_934_345_75;

/// `(r/4)^(-1/6)` for `r` = [`CARLSON_R`] (the R_D stopping constant).
const RD_Q_FACTOR: f64 = 584.803_547_642_573;

/// Iteration cap: each duplication step divides the spread of the arguments by
/// 4, so about 30 steps reach round-off from any spread; the cap only guards
/// against non-finite input looping forever.
const MAX_STEPS: usize = 64;

/// Where Carlson's duplication algorithm stops: the mean `A_m`, `4^-m` and
/// the normalised deviations `X = (A₀ − x)·4^-m/A_m`, `Y = (A₀ − y)·4^-m/A_m`
/// of the final series.
struct Duplicated {
    xx: f64,
    yy: f64,
    am: f64,
    pow4: f64,
}

/// The duplication steps shared by [`rf`] and [`rd`], from `(x, y, z)` with
/// the starting mean `a0` (each integral's own) until `4^-m·Q < |A_m|`, where
/// `Q = q_factor·max(|A₀ − x|, |A₀ − y|, |A₀ − z|)`. A step takes
/// `λ = √x√y + √y√z + √z√x` and moves x, y, z and A to `(· + λ)/4`; before it
/// moves, `term(4^-m, √z_m, z_m + λ)` sees the step (R_D sums its terms
/// there).
fn duplicate(
    x: f64,
    y: f64,
    z: f64,
    a0: f64,
    q_factor: f64,
    mut term: impl FnMut(f64, f64, f64),
) -> Duplicated {
    let q = q_factor * (a0 - x).abs().max((a0 - y).abs()).max((a0 - z).abs());
    let (mut xm, mut ym, mut zm, mut am) = (x, y, z, a0);
    let mut pow4 = 1.0; // 4^-m
    for _ in 0..MAX_STEPS {
        if pow4 * q < am.abs() {
            break;
        }
        let (sx, sy, sz) = (xm.sqrt(), ym.sqrt(), zm.sqrt());
        let lambda = sx * sy + sy * sz + sz * sx;
        term(pow4, sz, zm + lambda);
        xm = (xm + lambda) * 0.25;
        ym = (ym + lambda) * 0.25;
        zm = (zm + lambda) * 0.25;
        am = (am + lambda) * 0.25;
        pow4 *= 0.25;
    }
    Duplicated {
        xx: (a0 - x) * pow4 / am,
        yy: (a0 - y) * pow4 / am,
        am,
        pow4,
    }
}

/// Carlson's symmetric integral of the first kind,
/// `R_F(x, y, z) = ½ ∫₀^∞ dt / √((t+x)(t+y)(t+z))`.
///
/// Domain: `x, y, z ≥ 0`, at most one of them zero. Outside the domain the
/// result is NaN or infinite (this is an internal numeric kernel; the Hertz
/// solver never calls it outside its domain).
///
/// ```
/// use traction_hertz::elliptic::rf;
/// // R_F(0, 1, 1) = π/2 = K(0).
/// assert!((rf(0.0, 1.0, 1.0) - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// ```
pub fn rf(x: f64, y: f64, z: f64) -> f64 {
    if !(x >= 0.0 && y >= 0.0 && z >= 0.0) || [x + y, y + z, z + x].contains(&0.0) {
        return f64::NAN;
    }
    let a0 = (x + y + z) / 3.0;
    let Duplicated { xx, yy, am, .. } = duplicate(x, y, z, a0, RF_Q_FACTOR, |_, _, _| {});
    let zz = -(xx + yy);
    let e2 = xx * yy - zz * zz;
    let e3 = xx * yy * zz;
    (1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0) / am.sqrt()
}

/// Carlson's symmetric integral of the second kind,
/// `R_D(x, y, z) = (3/2) ∫₀^∞ dt / ((t+z) √((t+x)(t+y)(t+z)))`.
///
/// Domain: `x, y ≥ 0` with `x + y > 0`, and `z > 0`. Outside the domain the
/// result is NaN.
///
/// ```
/// use traction_hertz::elliptic::rd;
/// // R_D(0, 1, 1) = 3π/4.
/// assert!((rd(0.0, 1.0, 1.0) - 0.75 * std::f64::consts::PI).abs() < 1e-15);
/// ```
pub fn rd(x: f64, y: f64, z: f64) -> f64 {
    if !(x >= 0.0 && y >= 0.0 && z > 0.0 && x + y > 0.0) {
        return f64::NAN;
    }
    let a0 = (x + y + 3.0 * z) / 5.0;
    let mut sum = 0.0;
    let Duplicated { xx, yy, am, pow4 } =
        duplicate(x, y, z, a0, RD_Q_FACTOR, |pow4, sz, z_plus_lambda| {
            sum += pow4 / (sz * z_plus_lambda);
        });
    let zz = -(xx + yy) / 3.0;
    let xy = xx * yy;
    let z2 = zz * zz;
    let e2 = xy - 6.0 * z2;
    let e3 = (3.0 * xy - 8.0 * z2) * zz;
    let e4 = 3.0 * (xy - z2) * z2;
    let e5 = xy * z2 * zz;
    let series = 1.0 - 3.0 * e2 / 14.0 + e3 / 6.0 + 9.0 * e2 * e2 / 88.0
        - 3.0 * e4 / 22.0
        - 9.0 * e2 * e3 / 52.0
        + 3.0 * e5 / 26.0;
    pow4 * series / (am * am.sqrt()) + 3.0 * sum
}

/// Complete elliptic integral of the first kind `K(m) = ∫₀^{π/2} dθ/√(1 − m sin²θ)`,
/// parameter `m = e²` in `[0, 1)`.
///
/// ```
/// use traction_hertz::elliptic::complete_k;
/// assert!((complete_k(0.5) - 1.854_074_677_301_372).abs() < 1e-14);
/// ```
pub fn complete_k(m: f64) -> f64 {
    rf(0.0, 1.0 - m, 1.0)
}

/// Complete elliptic integral of the second kind `E(m) = ∫₀^{π/2} √(1 − m sin²θ) dθ`,
/// parameter `m = e²` in `[0, 1]`.
///
/// ```
/// use traction_hertz::elliptic::complete_e;
/// assert!((complete_e(0.5) - 1.350_643_881_047_675_5).abs() < 1e-14);
/// ```
pub fn complete_e(m: f64) -> f64 {
    if m == 1.0 {
        return 1.0;
    }
    let y = 1.0 - m;
    rf(0.0, y, 1.0) - m / 3.0 * rd(0.0, y, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Independent reference: K and E by the arithmetic–geometric mean
    /// (Abramowitz & Stegun 17.6), a different algorithm from Carlson's.
    fn agm_k_e(m: f64) -> (f64, f64) {
        let (mut a, mut b) = (1.0_f64, (1.0 - m).sqrt());
        let mut c2_sum = 0.5 * m; // 2^{n-1} c_n² with c_0² = m, n = 0
        let mut pow2 = 0.5;
        for _ in 0..40 {
            let c = 0.5 * (a - b);
            pow2 *= 2.0;
            c2_sum += pow2 * c * c;
            let an = 0.5 * (a + b);
            b = (a * b).sqrt();
            a = an;
            if c.abs() < 1e-17 {
                break;
            }
        }
        let k = std::f64::consts::FRAC_PI_2 / a;
        (k, k * (1.0 - c2_sum))
    }

    #[test]
    fn stopping_constants() {
        assert!(((3.0 * CARLSON_R).powf(-1.0 / 6.0) / RF_Q_FACTOR - 1.0).abs() < 1e-14);
        assert!(((0.25 * CARLSON_R).powf(-1.0 / 6.0) / RD_Q_FACTOR - 1.0).abs() < 1e-14);
    }

    #[test]
    fn carlson_test_values() {
        // Carlson (1995), section 3 test values, printed to 14 digits: the
        // tolerance 1e-13 relative is the last printed digit.
        let cases = [
            (rf(1.0, 2.0, 0.0), 1.311_028_777_146_1),
            (rf(2.0, 3.0, 4.0), 0.584_082_841_677_15),
            (rd(0.0, 2.0, 1.0), 1.797_210_352_103_4),
            (rd(2.0, 3.0, 4.0), 0.165_105_272_942_61),
        ];
        for (got, want) in cases {
            assert!(((got - want) / want).abs() < 1e-13, "{got} vs {want}");
        }
    }

    #[test]
    fn complete_integrals_match_agm() {
        // Two independent algorithms must agree to round-off: 1e-13 relative
        // allows for the ~40 rounding steps of each.
        for i in 0..=200 {
            let m = 0.999_75 * f64::from(i) / 200.0;
            let (k, e) = agm_k_e(m);
            assert!(((complete_k(m) - k) / k).abs() < 1e-13, "K({m})");
            assert!(((complete_e(m) - e) / e).abs() < 1e-13, "E({m})");
        }
        assert!((complete_e(1.0) - 1.0).abs() < 1e-15);
    }

    #[test]
    fn cancellation_free_identities() {
        // DLMF 19.25.1 against K, E computed by AGM, away from m = 0 where
        // the K − E form itself cancels; 1e-12 relative.
        for &m in &[0.1, 0.5, 0.9, 0.99] {
            let (k, e) = agm_k_e(m);
            let y = 1.0 - m;
            let d1 = m / 3.0 * rd(0.0, y, 1.0);
            let d2 = m * y / 3.0 * rd(0.0, 1.0, y);
            assert!(((d1 - (k - e)) / (k - e)).abs() < 1e-12);
            assert!(((d2 - (e - y * k)) / (e - y * k)).abs() < 1e-12);
        }
    }

    #[test]
    fn outside_domain_is_nan() {
        assert!(rf(-1.0, 1.0, 1.0).is_nan());
        assert!(rf(0.0, 0.0, 1.0).is_nan());
        assert!(rd(1.0, 1.0, 0.0).is_nan());
        assert!(rd(f64::NAN, 1.0, 1.0).is_nan());
    }
}
