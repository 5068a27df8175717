//! Elliptical Hertz contact of two elastic bodies, as used in section 2-1 of the
//! traction report (equations 1 and 2, Tables 2-1 to 2-3).
//!
//! # What it models
//!
//! Two smooth, non-conforming, linear-elastic bodies pressed together by a
//! normal load `F`. Each body has principal radii `rx` (in the rolling
//! direction x) and `ry` (across it): convex positive, concave negative, flat
//! = infinite. The contact is an ellipse with semi-axes `a` (along x) and `b`
//! (across), aspect ratio `k = b/a` (either side of 1), and a semi-ellipsoidal
//! pressure `p = P0 √(1 − x²/a² − y²/b²)`.
//!
//! # Equations
//!
//! Report definitions (Hamrock–Dowson notation):
//!
//! ```text
//! Re = (1/rx1 + 1/rx2 + 1/ry1 + 1/ry2)⁻¹                     equivalent radius
//! E' = 2 / ((1−ν1²)/E1 + (1−ν2²)/E2)                         composite modulus
//! (1) P0 = (1/(2πAB)) · (3 F E'² / Re²)^(1/3)
//! (2) a  = C · P0,      C = 2π A² B Re / E'
//! ```
//!
//! The OCR of the report's `E'` is garbled ("½((1−ν²)/E⁺ + (1−ν²)/E⁻)⁻¹"). The
//! definition above is the one for which equation (1) with `A = B = 1` is the
//! exact Hertz result for a sphere on a flat, and with steel
//! ([`STEEL_YOUNGS_MODULUS`] = 210 GPa, [`STEEL_POISSON_RATIO`] = 0.3,
//! `E' = 230.77 GPa`) it reproduces every `C` of Table 2-2 to its three printed
//! digits. (The printed `C` of the low-speed machine at k = 1, 0.170e-12 m/Pa,
//! brackets `E/(1−ν²)` between 230.3 and 231.7 GPa.)
//!
//! Exact Hertz theory (Johnson, *Contact Mechanics*, §3.5) with the gap
//! `h = ½Cx x² + ½Cy y²`, `Cx = 1/rx1 + 1/rx2`, `Cy = 1/ry1 + 1/ry2`, written
//! with Carlson's symmetric integral `R_D` (see [`elliptic`]) so that it holds
//! for both `a > b` and `a < b` and never cancels near `k = 1`:
//!
//! ```text
//! ½Cx = 2P0/E' · (ab/3) R_D(0, b², a²)       ½Cy = 2P0/E' · (ab/3) R_D(0, a², b²)
//! ⇒  Cx / Cy = R_D(0, k², 1) / R_D(0, 1, k²)          (solved for k)
//! F = (2/3) π a b P0
//! δ = 2P0/E' · ab R_F(0, a², b²)  = 2 P0 b_min K(m) / E'     mutual approach
//! ```
//!
//! Substituting into (1) and (2) shows what the report's shape factors are:
//! **`B = k·A`** and
//!
//! ```text
//! A³ = 2 (R_D(0, k², 1) + R_D(0, 1, k²)) / (3π)
//!    = 2 E(1 − k²)   / (π k²)     for k ≤ 1
//!    = 2 E(1 − 1/k²) / (π k)      for k ≥ 1
//! ```
//!
//! so `A` and `B` depend on `k` only, `A(1) = B(1) = 1`, and `A(k) = B(1/k)`
//! exactly (as Table 2-2 shows). Equivalently `a³ = 3 A³ Re F / E'`.
//! `E(m)`, `K(m)` are the complete elliptic integrals with parameter
//! `m = 1 − (b_min/a_max)²`, the squared eccentricity.
//!
//! The Hamrock–Brewe (1983) curve fits are offered as [`Method::HamrockBrewe`]:
//! with `ρ = C_max/C_min ≥ 1`, `k_major/minor = 1.0339 ρ^0.6360`,
//! `E ≈ 1.0003 + 0.5968/ρ`, `K ≈ 1.5277 + 0.6023 ln ρ`. Their error against
//! the exact solution, measured over `0.05 ≤ k ≤ 20` by this crate's tests, is
//! listed in [`Method::HamrockBrewe`].
//!
//! # Assumptions
//!
//! - Both bodies are linear-elastic, isotropic and homogeneous half-spaces near
//!   the contact (contact small against the radii); frictionless normal contact.
//! - **The principal planes of both bodies are aligned** with x and y (as on the
//!   report's twin-disc machines); crossed-axis contacts are not modelled.
//! - The relative curvature is positive in both directions (no conformal or
//!   line contact); the solver supports `k` in [[`K_MIN`], [`K_MAX`]] and is
//!   tested over 0.05 ≤ k ≤ 20 (the range of traction drives and bearings).
//!
//! # Example
//!
//! The low-speed machine, k = 1 discs of Table 2-1 (upper Rx 25 mm, Ry 12.5
//! mm; lower Rx 25 mm, flat), at the Hertz pressure of test 791119-04:
//!
//! ```
//! use traction_hertz::{Body, solve_p0};
//!
//! let upper = Body::steel(25e-3, 12.5e-3);
//! let lower = Body::steel(25e-3, f64::INFINITY);
//! let c = solve_p0(&upper, &lower, 1.9e9)?;
//! assert!((c.k() - 1.0).abs() < 1e-12);
//! assert!((c.geometry.re - 6.25e-3).abs() < 1e-15);
//! // Table 2-2 prints C = .170e-12 m/Pa; Table 2-3 prints a load of 416 N.
//! assert!((c.geometry.c / 0.170e-12 - 1.0).abs() < 0.003);
//! assert!((c.load / 416.0 - 1.0).abs() < 0.003);
//! # Ok::<(), traction_hertz::HertzError>(())
//! ```
#![forbid(unsafe_code)]

pub mod elliptic;
mod error;

pub use error::HertzError;
pub use traction_range::{OutOfRange, Range};

use std::f64::consts::PI;

/// Young's modulus of the report's AISI-O1 discs assumed here, Pa (common
/// value for tool steel; with [`STEEL_POISSON_RATIO`] it reproduces the `C`
/// values of Table 2-2).
pub const STEEL_YOUNGS_MODULUS: f64 = 210e9;

/// Poisson's ratio of steel assumed here (see [`STEEL_YOUNGS_MODULUS`]).
pub const STEEL_POISSON_RATIO: f64 = 0.3;

/// Smallest aspect ratio `k = b/a` the solver accepts.
pub const K_MIN: f64 = 1e-3;

/// Largest aspect ratio `k = b/a` the solver accepts.
pub const K_MAX: f64 = 1e3;

/// Relative tolerance of the aspect-ratio root solve (the solver reaches a few
/// 1e-16 in practice).
pub const K_TOLERANCE: f64 = 1e-12;

/// One body of the contact: principal radii and elastic constants.
///
/// Radii in m: convex positive, concave negative, flat = `f64::INFINITY`
/// (either sign). `rx` lies in the rolling direction x, `ry` across it; the
/// principal planes of both bodies are assumed aligned.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    /// Principal radius in the rolling direction x, m.
    pub rx: f64,
    /// Principal radius across the rolling direction (y), m.
    pub ry: f64,
    /// Young's modulus, Pa (> 0).
    pub youngs_modulus: f64,
    /// Poisson's ratio, in (−1, 0.5).
    pub poisson_ratio: f64,
}

impl Body {
    /// A body with the given radii (m), Young's modulus (Pa) and Poisson's
    /// ratio. Not validated here; the solvers validate and name bad values.
    pub fn new(rx: f64, ry: f64, youngs_modulus: f64, poisson_ratio: f64) -> Self {
        Body {
            rx,
            ry,
            youngs_modulus,
            poisson_ratio,
        }
    }

    /// A steel body ([`STEEL_YOUNGS_MODULUS`], [`STEEL_POISSON_RATIO`]), as
    /// the report's discs.
    pub fn steel(rx: f64, ry: f64) -> Self {
        Body::new(rx, ry, STEEL_YOUNGS_MODULUS, STEEL_POISSON_RATIO)
    }
}

/// How the ellipticity and elliptic integrals are obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[non_exhaustive]
pub enum Method {
    /// Exact Hertz theory: Carlson's integrals, `k` from a bracketed root
    /// solve to [`K_TOLERANCE`].
    #[default]
    Exact,
    /// Hamrock & Brewe (1983) curve fits for `k`, `E` and `K` (no root
    /// solve). Measured maximum relative error against [`Method::Exact`]
    /// over 0.05 ≤ k ≤ 20 at a fixed load (asserted in the tests with a
    /// small margin): k 7.2 %, a and b 4.8 %, P0 2.3 %, approach 5.4 %.
    /// The largest errors are at the ends of the range (k = 0.05 and 20:
    /// k 7.2 %, P0 2.3 %) and at k = 1, where the fit gives k = 1.0339 and
    /// K = 1.5277 (π/2 − 2.7 %): P0 −2.2 %, approach −5.4 %. At k = 0.2,
    /// 0.5, 2 and 5 all errors are at most 0.5 % (table in the README).
    HamrockBrewe,
}

/// The load-independent part of a contact: curvatures, `k`, `Re`, `E'`, the
/// elliptic integrals and the report's factors `A`, `B`, `C`.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Geometry {
    /// Relative curvature along x, `Cx = 1/rx1 + 1/rx2`, 1/m.
    pub curvature_x: f64,
    /// Relative curvature along y, `Cy = 1/ry1 + 1/ry2`, 1/m.
    pub curvature_y: f64,
    /// The report's equivalent radius `Re = 1/(Cx + Cy)`, m.
    pub re: f64,
    /// The report's composite modulus `E' = 2/((1−ν1²)/E1 + (1−ν2²)/E2)`, Pa.
    pub e_prime: f64,
    /// Aspect ratio `k = b/a` (dimensionless, report's name).
    pub k: f64,
    /// Parameter of the elliptic integrals, `m = e² = 1 − (minor/major)²`,
    /// the squared eccentricity of the ellipse (not the report's traction
    /// slope m).
    pub eccentricity_sq: f64,
    /// Complete elliptic integral of the first kind `K(m)` used.
    pub elliptic_k: f64,
    /// Complete elliptic integral of the second kind `E(m)` used.
    pub elliptic_e: f64,
    /// The report's shape factor `A` (dimensionless), equation (1).
    pub shape_a: f64,
    /// The report's shape factor `B = k·A` (dimensionless), equation (1).
    pub shape_b: f64,
    /// The report's contact-size constant `C = 2πA²B Re/E'` of equation (2),
    /// m/Pa: `a = C·P0`.
    pub c: f64,
    /// The method used.
    pub method: Method,
}

/// A loaded contact: the geometry plus the load-dependent results.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub struct Contact {
    /// The load-independent part (k, Re, E', A, B, C, elliptic integrals).
    pub geometry: Geometry,
    /// Semi-axis along the rolling direction x, m.
    pub a: f64,
    /// Semi-axis across the rolling direction, m.
    pub b: f64,
    /// Maximum (Hertz) pressure P0, Pa.
    pub p0: f64,
    /// Mean pressure `F/(πab) = (2/3) P0`, Pa.
    pub p_mean: f64,
    /// Contact area `πab`, m².
    pub area: f64,
    /// Normal load F, N.
    pub load: f64,
    /// Mutual approach of distant points of the two bodies (total elastic
    /// deflection) δ, m.
    pub approach: f64,
}

impl Contact {
    /// Aspect ratio `k = b/a`.
    pub fn k(&self) -> f64 {
        self.geometry.k
    }
}

fn check_radius(quantity: &'static str, r: f64) -> Result<f64, HertzError> {
    if r.is_nan() || r == 0.0 {
        return Err(HertzError::InvalidInput {
            quantity,
            value: r,
            valid: "non-zero and not NaN (convex > 0, concave < 0, flat = inf)",
        });
    }
    Ok(1.0 / r)
}

/// Valid Young's modulus of a body.
pub const YOUNGS_MODULUS_RANGE: Range = Range::POSITIVE.with_unit("Pa");

/// Valid Poisson's ratio of a body (0.5, incompressible, is excluded: E' would
/// be infinite).
pub const POISSON_RATIO_RANGE: Range = Range::open(-1.0, 0.5);

/// Valid normal load.
pub const LOAD_RANGE: Range = Range::POSITIVE.with_unit("N");

/// Valid maximum Hertz pressure P0.
pub const P0_RANGE: Range = Range::POSITIVE.with_unit("Pa");

fn check_modulus(quantity: &'static str, e: f64) -> Result<(), HertzError> {
    YOUNGS_MODULUS_RANGE.check(quantity, e)?;
    Ok(())
}

fn check_poisson(quantity: &'static str, nu: f64) -> Result<(), HertzError> {
    POISSON_RATIO_RANGE.check(quantity, nu)?;
    Ok(())
}

/// The report's composite modulus `E' = 2/((1−ν1²)/E1 + (1−ν2²)/E2)`, Pa.
///
/// Errors if a modulus is not finite and positive or a Poisson ratio is
/// outside (−1, 0.5).
pub fn composite_modulus(e1: f64, nu1: f64, e2: f64, nu2: f64) -> Result<f64, HertzError> {
    check_modulus("e1 (Young's modulus of body 1, Pa)", e1)?;
    check_poisson("nu1 (Poisson's ratio of body 1)", nu1)?;
    check_modulus("e2 (Young's modulus of body 2, Pa)", e2)?;
    check_poisson("nu2 (Poisson's ratio of body 2)", nu2)?;
    Ok(2.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2))
}

/// Relative curvatures `(Cx, Cy)` in 1/m of two bodies, both checked positive.
pub fn relative_curvatures(body1: &Body, body2: &Body) -> Result<(f64, f64), HertzError> {
    let cx1 = check_radius("rx1 (radius of body 1 along x, m)", body1.rx)?;
    let cy1 = check_radius("ry1 (radius of body 1 across x, m)", body1.ry)?;
    let cx2 = check_radius("rx2 (radius of body 2 along x, m)", body2.rx)?;
    let cy2 = check_radius("ry2 (radius of body 2 across x, m)", body2.ry)?;
    let (cx, cy) = (cx1 + cx2, cy1 + cy2);
    // Radii are non-zero, so the curvatures are finite and never NaN.
    if cx <= 0.0 {
        return Err(HertzError::NonPositiveCurvature {
            direction: "x",
            value: cx,
        });
    }
    if cy <= 0.0 {
        return Err(HertzError::NonPositiveCurvature {
            direction: "y",
            value: cy,
        });
    }
    Ok((cx, cy))
}

/// The curvature ratio `Cx/Cy` that produces aspect ratio `k = b/a`:
/// `R_D(0, k², 1) / R_D(0, 1, k²)` (exact Hertz theory).
///
/// Errors unless `k` is in [[`K_MIN`], [`K_MAX`]].
pub fn curvature_ratio(k: f64) -> Result<f64, HertzError> {
    check_k(k)?;
    Ok(ratio_of_k(k))
}

fn check_k(k: f64) -> Result<(), HertzError> {
    if !(K_MIN..=K_MAX).contains(&k) {
        return Err(HertzError::InvalidAspectRatio {
            k,
            k_min: K_MIN,
            k_max: K_MAX,
        });
    }
    Ok(())
}

fn ratio_of_k(k: f64) -> f64 {
    let k2 = k * k;
    elliptic::rd(0.0, k2, 1.0) / elliptic::rd(0.0, 1.0, k2)
}

/// `g(t) = ln(ratio(e^t)) − ln ρ`, increasing in `t = ln k`.
fn log_ratio_residual(t: f64, ln_rho: f64) -> f64 {
    let k2 = (2.0 * t).exp();
    (elliptic::rd(0.0, k2, 1.0) / elliptic::rd(0.0, 1.0, k2)).ln() - ln_rho
}

/// The exact aspect ratio `k = b/a` for a curvature ratio `Cx/Cy`: the root
/// of `R_D(0, k², 1) / R_D(0, 1, k²) = Cx/Cy`, found to [`K_TOLERANCE`]
/// relative by a bracketed Illinois (modified regula falsi) iteration in
/// `ln k`, with bisection as a safeguard.
///
/// `Cx > Cy` gives `k > 1` (the ellipse is long across the rolling
/// direction). Errors unless the ratio is finite and positive and `k` falls
/// in [[`K_MIN`], [`K_MAX`]].
pub fn aspect_ratio(curvature_ratio: f64) -> Result<f64, HertzError> {
    let rho = curvature_ratio;
    Range::POSITIVE.check("curvature ratio Cx/Cy", rho)?;
    if rho == 1.0 {
        return Ok(1.0);
    }
    // Solve on the k ≥ 1 side; ratio(1/k) = 1/ratio(k) exactly.
    let flip = rho < 1.0;
    let big = if flip { 1.0 / rho } else { rho };
    let ln_rho = big.ln();
    // Bracket: g(0) = −ln ρ < 0; g(ln K_MAX) < 0 means k > K_MAX.
    let (mut lo, mut hi) = (0.0_f64, K_MAX.ln());
    let (mut glo, mut ghi) = (-ln_rho, log_ratio_residual(hi, ln_rho));
    if ghi < 0.0 {
        return Err(HertzError::AspectRatioOutOfRange {
            ratio: rho,
            k_min: K_MIN,
            k_max: K_MAX,
        });
    }
    // Start from the Hamrock–Brewe estimate k ≈ 1.0339 ρ^0.636 to shrink the
    // bracket (only used if it lands inside and has the right sign).
    let guess = (1.0339 * big.powf(0.6360)).ln();
    if guess > lo && guess < hi {
        let g = log_ratio_residual(guess, ln_rho);
        if g < 0.0 {
            (lo, glo) = (guess, g);
        } else {
            (hi, ghi) = (guess, g);
        }
    }
    let mut side = 0_i8; // which end was retained last time (Illinois)
    let mut t = 0.5 * (lo + hi);
    for _ in 0..200 {
        if hi - lo <= 1e-15 * hi.max(1.0) {
            break;
        }
        // Illinois step, falling back to bisection if it is not strictly inside.
        let mut cand = (lo * ghi - hi * glo) / (ghi - glo);
        if !(cand > lo && cand < hi) {
            cand = 0.5 * (lo + hi);
        }
        t = cand;
        let g = log_ratio_residual(t, ln_rho);
        if g == 0.0 {
            break;
        }
        if g < 0.0 {
            (lo, glo) = (t, g);
            if side == -1 {
                ghi *= 0.5;
            }
            side = -1;
        } else {
            (hi, ghi) = (t, g);
            if side == 1 {
                glo *= 0.5;
            }
            side = 1;
        }
        // |g| is the log-ratio residual and dg/d(ln k) ≥ 1.5 over the range,
        // so |g| ≤ 1e-15 means k is within ~1e-15 relative (evaluation noise
        // of g is a few 1e-16).
        if g.abs() <= 1e-15 {
            break;
        }
    }
    let k = t.exp();
    Ok(if flip { 1.0 / k } else { k })
}

/// The report's shape factors `(A, B)` of equation (1) for aspect ratio `k`
/// (exact theory): `A³ = 2(R_D(0,k²,1) + R_D(0,1,k²))/(3π)`, `B = k·A`.
///
/// ```
/// // Table 2-2 prints A = 1.46, B = .725 for k = .5.
/// let (a, b) = traction_hertz::shape_factors(0.5)?;
/// assert!((a - 1.45558).abs() < 1e-5 && (b - 0.72779).abs() < 1e-5);
/// # Ok::<(), traction_hertz::HertzError>(())
/// ```
pub fn shape_factors(k: f64) -> Result<(f64, f64), HertzError> {
    check_k(k)?;
    let a = shape_a_of_k(k);
    Ok((a, k * a))
}

/// `A(k)`, unchecked (k from the root solve is in range by construction).
fn shape_a_of_k(k: f64) -> f64 {
    let k2 = k * k;
    (2.0 * (elliptic::rd(0.0, k2, 1.0) + elliptic::rd(0.0, 1.0, k2)) / (3.0 * PI)).cbrt()
}

/// Elliptic parameter `m = 1 − (minor/major)²` for aspect ratio `k`.
fn parameter_of_k(k: f64) -> f64 {
    let r = if k <= 1.0 { k } else { 1.0 / k };
    // 1 − r² computed as (1 − r)(1 + r) to keep accuracy near r = 1.
    (1.0 - r) * (1.0 + r)
}

impl Geometry {
    /// The exact geometry of two bodies ([`Method::Exact`]).
    pub fn new(body1: &Body, body2: &Body) -> Result<Geometry, HertzError> {
        Geometry::with_method(body1, body2, Method::Exact)
    }

    /// The geometry of two bodies with the chosen [`Method`].
    pub fn with_method(body1: &Body, body2: &Body, method: Method) -> Result<Geometry, HertzError> {
        let (cx, cy) = relative_curvatures(body1, body2)?;
        let e_prime = composite_modulus(
            body1.youngs_modulus,
            body1.poisson_ratio,
            body2.youngs_modulus,
            body2.poisson_ratio,
        )?;
        let re = 1.0 / (cx + cy);
        let (k, m, ek, ee, shape_a) = match method {
            Method::Exact => {
                let k = aspect_ratio(cx / cy)?;
                let m = parameter_of_k(k);
                let shape_a = shape_a_of_k(k);
                (
                    k,
                    m,
                    elliptic::complete_k(m),
                    elliptic::complete_e(m),
                    shape_a,
                )
            }
            Method::HamrockBrewe => {
                let rho = if cx >= cy { cx / cy } else { cy / cx };
                let major_minor = 1.0339 * rho.powf(0.6360);
                let k = if cx >= cy {
                    major_minor
                } else {
                    1.0 / major_minor
                };
                check_k(k).map_err(|_| HertzError::AspectRatioOutOfRange {
                    ratio: cx / cy,
                    k_min: K_MIN,
                    k_max: K_MAX,
                })?;
                let ee = 1.0003 + 0.5968 / rho;
                let ek = 1.5277 + 0.6023 * rho.ln();
                let m = 1.0 - 1.0 / (major_minor * major_minor);
                // A³ = 2E/(π k²) for k ≤ 1, 2E/(π k) for k ≥ 1.
                let a3 = 2.0 * ee / (PI * k * k.min(1.0));
                (k, m, ek, ee, a3.cbrt())
            }
        };
        let shape_b = k * shape_a;
        let c = 2.0 * PI * shape_a * shape_a * shape_b * re / e_prime;
        Ok(Geometry {
            curvature_x: cx,
            curvature_y: cy,
            re,
            e_prime,
            k,
            eccentricity_sq: m,
            elliptic_k: ek,
            elliptic_e: ee,
            shape_a,
            shape_b,
            c,
            method,
        })
    }

    /// The contact under normal load `F` (N): `a³ = 3A³ Re F/E'`, `b = k a`,
    /// P0 from equation (1).
    ///
    /// Errors unless `F` is finite and > 0.
    pub fn at_load(&self, load: f64) -> Result<Contact, HertzError> {
        LOAD_RANGE.check("load (normal load, N)", load)?;
        let g = self;
        let a = (3.0 * g.shape_a.powi(3) * g.re * load / g.e_prime).cbrt();
        // Equation (1).
        let p0 = (3.0 * load * g.e_prime * g.e_prime / (g.re * g.re)).cbrt()
            / (2.0 * PI * g.shape_a * g.shape_b);
        self.finish(a, p0, load, "load")
    }

    /// The contact at maximum (Hertz) pressure `P0` (Pa) — the inverse
    /// problem; the report specifies every test by P0. `a = C·P0`
    /// (equation 2), `b = k a`, `F = (2/3)π a b P0`.
    ///
    /// Errors unless `P0` is finite and > 0.
    pub fn at_p0(&self, p0: f64) -> Result<Contact, HertzError> {
        P0_RANGE.check("p0 (maximum Hertz pressure, Pa)", p0)?;
        let a = self.c * p0; // equation (2)
        let load = 2.0 / 3.0 * PI * a * (self.k * a) * p0;
        self.finish(a, p0, load, "p0")
    }

    /// The contact from a, P0 and F; errors if a result is 0 or infinite
    /// (`given`: the input, load or P0, named in the message).
    fn finish(
        &self,
        a: f64,
        p0: f64,
        load: f64,
        given: &'static str,
    ) -> Result<Contact, HertzError> {
        let b = self.k * a;
        let minor = a.min(b);
        let c = Contact {
            geometry: *self,
            a,
            b,
            p0,
            p_mean: 2.0 / 3.0 * p0,
            area: PI * a * b,
            load,
            approach: 2.0 * p0 * minor * self.elliptic_k / self.e_prime,
        };
        for (quantity, value) in [
            ("semi-axis a (m)", c.a),
            ("semi-axis b (m)", c.b),
            ("maximum pressure p0 (Pa)", c.p0),
            ("load (N)", c.load),
            ("contact area (m²)", c.area),
            ("approach (m)", c.approach),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(HertzError::OutOfFloatRange {
                    quantity,
                    value,
                    given,
                });
            }
        }
        Ok(c)
    }
}

/// Exact contact of two bodies under normal load `F` (N).
///
/// ```
/// use traction_hertz::{Body, solve_load};
/// // Steel ball of 10 mm radius on a steel flat, 100 N.
/// let ball = Body::steel(10e-3, 10e-3);
/// let flat = Body::steel(f64::INFINITY, f64::INFINITY);
/// let c = solve_load(&ball, &flat, 100.0)?;
/// // Closed form: a = (3FR/(4E*))^(1/3) with E* = E'/2.
/// let a = (3.0 * 100.0 * 10e-3 / (2.0 * c.geometry.e_prime)).cbrt();
/// assert!((c.a / a - 1.0).abs() < 1e-12);
/// # Ok::<(), traction_hertz::HertzError>(())
/// ```
pub fn solve_load(body1: &Body, body2: &Body, load: f64) -> Result<Contact, HertzError> {
    Geometry::new(body1, body2)?.at_load(load)
}

/// Exact contact of two bodies at maximum pressure `P0` (Pa): the load that
/// gives a target P0, with the rest of the contact.
pub fn solve_p0(body1: &Body, body2: &Body, p0: f64) -> Result<Contact, HertzError> {
    Geometry::new(body1, body2)?.at_p0(p0)
}

#[cfg(test)]
mod tests;
