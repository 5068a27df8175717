//! Kalker's linear creep coefficients C11, C22, C23, C33 (elliptical contact).
//!
//! ## Table and sources
//!
//! The table is Kalker's (J.J. Kalker, *Three-dimensional elastic bodies in
//! rolling contact*, Kluwer 1990, Table E.3; first published in his 1967 thesis),
//! for ν = 0, 0.25, 0.5 and g = a/b or b/a = 0.1, 0.2, …, 1.0, where `a` is the
//! semi-axis in the rolling direction.
//!
//! C11, C22 and C23 were transcribed and cross-checked entry by entry against two
//! public machine-readable copies:
//!
//! 1. the `linrol` routine of CONTACT (E.A.H. Vollebregt & J.J. Kalker;
//!    github.com/eve70a/CONTACT, `src/m_hertz.f90`, commit 6a9d48e, Apache-2.0),
//!    which cites "Table E.3 of Kalker 1990";
//! 2. an older copy of the same routine and a C++ port of it (found by exact-value
//!    search of public code; their repositories could not be resolved with the
//!    search tools).
//!
//! Both copies descend from CONTACT, so they are not independent transcriptions
//! of Kalker's book; the internal checks below are what guards against an error
//! common to both. (The data were re-typed here, not copied as code.)
//!
//! All 180 values agree except one: C23 at a/b = 0.8, ν = 0.25 reads 1.25 in
//! copy 1 and 1.15 in copy 2. 1.25 is used: the ν = 0.25 column of C23 rises by
//! 0.10–0.11 per row (1.03, 1.14, **1.25**, 1.36, 1.47), and 1.15 would make
//! C23(ν = 0.25) smaller than C23(ν = 0) + 0.02 where every other row has a gap of
//! 0.10–0.14. Internal checks in the tests: C11 = C22 at ν = 0 in every row (the
//! longitudinal and lateral problems coincide when ν = 0), both halves of the table
//! agree at a/b = 1, and the asymptotes below meet the g = 0.1 rows within a few
//! per cent.
//!
//! **C33 (spin moment) is not in either public copy.** Its values were entered
//! from Kalker's table as commonly reproduced, and could *not* be cross-checked
//! against a second public source with the tools available; they are checked only
//! by the internal consistency tests (both halves equal at a/b = 1, monotonic in
//! g). C33 is not used by any model of the report. Outside the table C33 returns
//! [`ComplianceError::NoAsymptote`].
//!
//! ## Interpolation (documented scheme)
//!
//! * In g (= a/b for a ≤ b, = b/a for a > b): piecewise linear between the tabulated
//!   rows, separately in each half of the table (at a/b = 1 both halves coincide).
//! * In ν: quadratic Lagrange interpolation through ν = 0, 0.25, 0.5, of **1/C**
//!   for C11, C22, C23 (Kalker's small-a/b asymptote C11 = π²/(4(1−ν)) makes 1/C11
//!   exactly linear in ν) and of **C** for C33 (its 1/C varies by a factor 3.5–4
//!   between ν = 0 and 0.5 at large a/b, and the quadratic in 1/C reversed the order
//!   of the rows a/b = 5 and 10 near ν = 0.07 — found by the property test).
//!   ν outside [0, 0.5] is an error (no asymptote).
//!
//! ## Asymptotes outside the table (Kalker 1990; same formulas in CONTACT)
//!
//! For a/b = g → 0:
//! `C11 = π²/(4(1−ν))`, `C22 = π²/4`,
//! `C23 = π√g/(3(1−ν))·[1 + ν(ln(16/g) − 5)]`.
//!
//! For b/a = g → 0, with `Λ = ln(16/g²)`:
//! `C11 = 2π/((Λ−2ν)g)·[1 + (3 − ln 4)/(Λ−2ν)]`,
//! `C22 = 2π/(((1−ν)Λ+2ν)g)·[1 + (1−ν)(3 − ln 4)/((1−ν)Λ+2ν)]`,
//! `C23 = 2π/(3 g^{3/2}((1−ν)Λ − 2 + 4ν))`.
//!
//! Between g = 0 and the first row g = 0.1 the asymptote is blended into the table
//! so that the result is continuous: `C(g) = C_asym(g)·[1 + (r − 1)·g/0.1]` with
//! `r = C_table(0.1)/C_asym(0.1)`; the correction factor tends to 1 as g → 0, so the
//! documented limit is reached.

use crate::{ComplianceError, Range, Result};

/// Which of Kalker's coefficients.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Coefficient {
    /// Longitudinal creep force: `F_x = −G·ab·C11·ξ`.
    C11,
    /// Lateral creep force: `F_y = −G·ab·(C22·η + C23·√(ab)·φ)`.
    C22,
    /// Lateral force from spin (and spin moment from lateral creep).
    C23,
    /// Spin moment from spin.
    C33,
}

/// The four coefficients at one (a/b, ν).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KalkerCoefficients {
    /// C11 (longitudinal).
    pub c11: f64,
    /// C22 (lateral).
    pub c22: f64,
    /// C23 (lateral–spin coupling).
    pub c23: f64,
    /// C33 (spin); `None` outside the table, where no asymptote is implemented.
    pub c33: Option<f64>,
}

const NU: [f64; 3] = [0.0, 0.25, 0.5];

/// Rows g = 0.1..1.0 for a ≤ b (g = a/b): [C11 ×3 ν, C22 ×3, C23 ×3, C33 ×3].
// 3.14 is Kalker's C22 (a/b = 0.5, ν = 0.5), not π.
#[allow(clippy::approx_constant)]
const TABLE_A_LE_B: [[f64; 12]; 10] = [
    [
        2.51, 3.31, 4.85, 2.51, 2.52, 2.53, 0.334, 0.473, 0.731, 6.42, 8.28, 11.7,
    ],
    [
        2.59, 3.37, 4.81, 2.59, 2.63, 2.66, 0.483, 0.603, 0.809, 3.46, 4.27, 5.66,
    ],
    [
        2.68, 3.44, 4.80, 2.68, 2.75, 2.81, 0.607, 0.715, 0.889, 2.49, 2.96, 3.72,
    ],
    [
        2.78, 3.53, 4.82, 2.78, 2.88, 2.98, 0.720, 0.823, 0.977, 2.02, 2.32, 2.77,
    ],
    [
        2.88, 3.62, 4.83, 2.88, 3.01, 3.14, 0.827, 0.929, 1.07, 1.74, 1.93, 2.22,
    ],
    [
        2.98, 3.72, 4.91, 2.98, 3.14, 3.31, 0.930, 1.03, 1.18, 1.56, 1.68, 1.86,
    ],
    [
        3.09, 3.81, 4.97, 3.09, 3.28, 3.48, 1.03, 1.14, 1.29, 1.43, 1.50, 1.60,
    ],
    [
        3.19, 3.91, 5.05, 3.19, 3.41, 3.65, 1.13, 1.25, 1.40, 1.34, 1.37, 1.42,
    ],
    [
        3.29, 4.01, 5.12, 3.29, 3.54, 3.82, 1.23, 1.36, 1.51, 1.27, 1.27, 1.27,
    ],
    [
        3.40, 4.12, 5.20, 3.40, 3.67, 3.98, 1.33, 1.47, 1.63, 1.21, 1.19, 1.16,
    ],
];

/// Rows g = 0.1..1.0 for a > b (g = b/a), same column layout.
const TABLE_A_GT_B: [[f64; 12]; 10] = [
    [
        10.7, 11.7, 12.9, 10.7, 12.8, 16.0, 12.2, 14.6, 18.0, 0.795, 0.526, 0.228,
    ],
    [
        6.96, 7.78, 8.82, 6.96, 8.14, 9.79, 5.72, 6.63, 7.89, 0.828, 0.601, 0.341,
    ],
    [
        5.57, 6.34, 7.34, 5.57, 6.40, 7.51, 3.79, 4.32, 5.01, 0.868, 0.674, 0.446,
    ],
    [
        4.84, 5.57, 6.57, 4.84, 5.48, 6.31, 2.88, 3.24, 3.70, 0.912, 0.747, 0.549,
    ],
    [
        4.37, 5.10, 6.11, 4.37, 4.90, 5.56, 2.35, 2.62, 2.96, 0.958, 0.819, 0.650,
    ],
    [
        4.06, 4.78, 5.80, 4.06, 4.50, 5.04, 2.01, 2.23, 2.50, 1.01, 0.892, 0.751,
    ],
    [
        3.82, 4.54, 5.58, 3.82, 4.21, 4.67, 1.76, 1.95, 2.18, 1.05, 0.965, 0.852,
    ],
    [
        3.65, 4.36, 5.42, 3.65, 3.99, 4.39, 1.58, 1.75, 1.94, 1.10, 1.04, 0.954,
    ],
    [
        3.51, 4.22, 5.30, 3.51, 3.81, 4.16, 1.44, 1.59, 1.77, 1.16, 1.11, 1.06,
    ],
    [
        3.40, 4.12, 5.20, 3.40, 3.67, 3.98, 1.33, 1.47, 1.63, 1.21, 1.19, 1.16,
    ],
];

fn column(c: Coefficient) -> usize {
    match c {
        Coefficient::C11 => 0,
        Coefficient::C22 => 3,
        Coefficient::C23 => 6,
        Coefficient::C33 => 9,
    }
}

/// A tabulated entry (for tests and documentation): `half` false for a ≤ b,
/// `row` 0..10 for g = 0.1..1.0, `nu_index` 0..3 for ν = 0, 0.25, 0.5.
pub fn table_entry(a_gt_b: bool, row: usize, c: Coefficient, nu_index: usize) -> Option<f64> {
    let t = if a_gt_b { &TABLE_A_GT_B } else { &TABLE_A_LE_B };
    t.get(row)?
        .get(column(c) + nu_index)
        .copied()
        .filter(|_| nu_index < 3)
}

fn interp_nu(values: [f64; 3], nu: f64, reciprocal: bool) -> f64 {
    // Quadratic Lagrange interpolation through ν = 0, 0.25, 0.5, of 1/C or of C.
    let mut sum = 0.0;
    for (i, (nu_i, c_i)) in NU.iter().zip(values).enumerate() {
        let mut l = 1.0;
        for (j, nu_j) in NU.iter().enumerate() {
            if j != i {
                l *= (nu - nu_j) / (nu_i - nu_j);
            }
        }
        sum += l * if reciprocal { 1.0 / c_i } else { c_i };
    }
    if reciprocal { 1.0 / sum } else { sum }
}

fn table_value(a_gt_b: bool, g: f64, c: Coefficient, nu: f64) -> f64 {
    let t = if a_gt_b { &TABLE_A_GT_B } else { &TABLE_A_LE_B };
    let col = column(c);
    let reciprocal = c != Coefficient::C33;
    let at_row = |r: usize| interp_nu([t[r][col], t[r][col + 1], t[r][col + 2]], nu, reciprocal);
    // g in [0.1, 1.0]: rows r (g = 0.1(r+1)).
    let x = (g * 10.0 - 1.0).clamp(0.0, 9.0);
    let r0 = (x.floor() as usize).min(8);
    let w = x - r0 as f64;
    (1.0 - w) * at_row(r0) + w * at_row(r0 + 1)
}

fn asymptote(a_gt_b: bool, g: f64, c: Coefficient, nu: f64) -> Option<f64> {
    use std::f64::consts::PI;
    if !a_gt_b {
        match c {
            Coefficient::C11 => Some(PI * PI / (4.0 * (1.0 - nu))),
            Coefficient::C22 => Some(PI * PI / 4.0),
            Coefficient::C23 => {
                Some(PI * g.sqrt() / (3.0 * (1.0 - nu)) * (1.0 + nu * ((16.0 / g).ln() - 5.0)))
            }
            Coefficient::C33 => None,
        }
    } else {
        let lam = (16.0 / (g * g)).ln();
        let c3 = 3.0 - 4f64.ln();
        match c {
            Coefficient::C11 => {
                let d = lam - 2.0 * nu;
                Some(2.0 * PI / (d * g) * (1.0 + c3 / d))
            }
            Coefficient::C22 => {
                let d = (1.0 - nu) * lam + 2.0 * nu;
                Some(2.0 * PI / (d * g) * (1.0 + (1.0 - nu) * c3 / d))
            }
            Coefficient::C23 => {
                Some(2.0 * PI / (3.0 * g.powf(1.5) * ((1.0 - nu) * lam - 2.0 + 4.0 * nu)))
            }
            Coefficient::C33 => None,
        }
    }
}

fn check_args(a_over_b: f64, nu: f64) -> Result<()> {
    Range::POSITIVE.check("semi-axis ratio a/b", a_over_b)?;
    crate::KALKER_POISSON_RANGE.check("Poisson's ratio ν (Kalker table)", nu)?;
    Ok(())
}

/// One Kalker coefficient at semi-axis ratio `a_over_b` (a along the rolling
/// direction) and Poisson's ratio `nu`.
///
/// Errors: a/b not finite or ≤ 0, ν outside [0, 0.5], or C33 outside the table
/// (g < 0.1), where no asymptote is implemented.
pub fn kalker_coefficient(c: Coefficient, a_over_b: f64, nu: f64) -> Result<f64> {
    check_args(a_over_b, nu)?;
    let a_gt_b = a_over_b > 1.0;
    let g = if a_gt_b { 1.0 / a_over_b } else { a_over_b };
    if g >= 0.1 {
        return Ok(table_value(a_gt_b, g, c, nu));
    }
    let Some(asym) = asymptote(a_gt_b, g, c, nu) else {
        return Err(ComplianceError::NoAsymptote {
            coefficient: "C33",
            a_over_b,
        });
    };
    let asym_edge = asymptote(a_gt_b, 0.1, c, nu).unwrap_or(f64::NAN);
    let r = table_value(a_gt_b, 0.1, c, nu) / asym_edge;
    Ok(asym * (1.0 + (r - 1.0) * g / 0.1))
}

/// All four coefficients; C33 is `None` where it has no asymptote.
pub fn kalker_coefficients(a_over_b: f64, nu: f64) -> Result<KalkerCoefficients> {
    Ok(KalkerCoefficients {
        c11: kalker_coefficient(Coefficient::C11, a_over_b, nu)?,
        c22: kalker_coefficient(Coefficient::C22, a_over_b, nu)?,
        c23: kalker_coefficient(Coefficient::C23, a_over_b, nu)?,
        c33: kalker_coefficient(Coefficient::C33, a_over_b, nu).ok(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_table_nodes() {
        for half in [false, true] {
            for row in 0..10 {
                let g = 0.1 * (row + 1) as f64;
                let aob = if half { 1.0 / g } else { g };
                for c in [
                    Coefficient::C11,
                    Coefficient::C22,
                    Coefficient::C23,
                    Coefficient::C33,
                ] {
                    for (i, nu) in NU.iter().enumerate() {
                        let v = kalker_coefficient(c, aob, *nu).unwrap();
                        let t = table_entry(half, row, c, i).unwrap();
                        // Exact node: only floating-point rounding of g = 1/(1/g).
                        assert!(
                            (v / t - 1.0).abs() < 1e-9,
                            "{c:?} half {half} row {row} ν {nu}: {v} vs {t}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn nu_zero_longitudinal_equals_lateral() {
        for half in [false, true] {
            for row in 0..10 {
                assert_eq!(
                    table_entry(half, row, Coefficient::C11, 0),
                    table_entry(half, row, Coefficient::C22, 0)
                );
            }
        }
    }

    #[test]
    fn both_halves_agree_at_circle() {
        for c in [
            Coefficient::C11,
            Coefficient::C22,
            Coefficient::C23,
            Coefficient::C33,
        ] {
            for i in 0..3 {
                assert_eq!(table_entry(false, 9, c, i), table_entry(true, 9, c, i));
            }
        }
    }

    #[test]
    fn asymptotes_meet_the_first_rows() {
        // The asymptotes are leading-order expansions; at g = 0.1 they must agree
        // with the table to within ~6 % (measured: worst C11, a/b = 10, ν = 0.5).
        for half in [false, true] {
            for c in [Coefficient::C11, Coefficient::C22, Coefficient::C23] {
                for (i, nu) in NU.iter().enumerate() {
                    let a = asymptote(half, 0.1, c, *nu).unwrap();
                    let t = table_entry(half, 0, c, i).unwrap();
                    assert!(
                        (a / t - 1.0).abs() < 0.08,
                        "{c:?} half {half} ν {nu}: {a} vs {t}"
                    );
                }
            }
        }
    }

    #[test]
    fn blended_region_is_continuous_and_tends_to_asymptote() {
        for aob in [0.1, 10.0] {
            let inside = kalker_coefficient(Coefficient::C11, aob, 0.3).unwrap();
            let eps = if aob < 1.0 {
                aob * (1.0 - 1e-9)
            } else {
                aob * (1.0 + 1e-9)
            };
            let outside = kalker_coefficient(Coefficient::C11, eps, 0.3).unwrap();
            assert!((inside / outside - 1.0).abs() < 1e-6);
        }
        let g = 1e-4;
        let v = kalker_coefficient(Coefficient::C11, g, 0.3).unwrap();
        let lim = std::f64::consts::PI.powi(2) / (4.0 * 0.7);
        assert!((v / lim - 1.0).abs() < 1e-4);
    }

    #[test]
    fn errors_name_the_quantity() {
        let e = kalker_coefficient(Coefficient::C11, 1.0, 0.6).unwrap_err();
        assert!(e.to_string().contains("Poisson"));
        let e = kalker_coefficient(Coefficient::C11, -1.0, 0.3).unwrap_err();
        assert!(e.to_string().contains("a/b"));
        let e = kalker_coefficient(Coefficient::C33, 0.05, 0.3).unwrap_err();
        assert!(e.to_string().contains("C33"));
        assert!(kalker_coefficients(0.05, 0.3).unwrap().c33.is_none());
    }
}
