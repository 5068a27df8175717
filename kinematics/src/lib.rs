//! # traction-kinematics: body motion → rolling, slip, side slip and spin at a contact
//!
//! This crate turns the motion of two rigid bodies into the kinematic inputs of
//! the traction model of the report (Tevaarwerk, NASA CR, sections 2-2 and 2-3;
//! Appendix IV = NASA TP 1530; Appendix V = ASME 78-Lub-10):
//!
//! * **Twin-disc rig** (section 2-2, 2-3):
//!   - side-slip ratio from the skew angle β, equation (3): `ΔV/U = tan β`
//!     ([`side_slip_ratio`]);
//!   - spin per unit rolling speed from the tilt ("spin") angle α, equation (6):
//!     `ω/U = sin α / (R_y cos α + e)` with the signed centre offset `e`
//!     ([`tilted_disc_spin_per_speed`]); `R_y cos α + e` is the rolling radius of
//!     the tilted disc, i.e. the distance from the contact to its axis
//!     ([`tilted_disc_rolling_radius`]);
//!   - the spin grouping `Z = ω√(ab)/U` and the spin factor `C'' = (ω/U)·C·√k`
//!     of equation (7), `Z = C''·P0`, where `a = C·P0` (equation 2)
//!     ([`spin_factor`], [`spin_group`], [`spin_group_from_contact`]).
//! * **General rigid-body contact kinematics** ([`contact_kinematics`]): two bodies,
//!   each with its angular velocity vector, a point on its axis and optionally a
//!   translational velocity of that point, the contact point, the contact normal
//!   and the rolling direction → surface velocities, `U`, `ΔU`, `ΔV`, `ω`, the
//!   slide-to-roll ratios and the speed-pole location `ε = ΔU/(ω√(ab))`.
//!   The twin-disc formulas (3) and (6) are special cases (tested).
//! * **Half-toroidal CVT variator** ([`HalfToroidalVariator`]): contact positions,
//!   rolling speeds and spin at the input and output contacts versus tilt angle.
//! * **Dimensionless groups** J1, J2, J3 (Appendix IV equations 11 and 12,
//!   Appendix V section 6): `J = (3π/8)(m/μ)·ratio·√k` ([`j1`], [`j2`], [`j3`],
//!   [`j_groups`]). The speed-pole location is `ε = J1/J3 = ΔU/(ω√(ab))`.
//!   (Equation (5) of the main text prints `J3 = 3/8 m/μ (ω√(ab)/U)√k` without the
//!   π; equations (9), (11), (12) and the 9-digit J3 values of Appendix VI all
//!   carry it, so the π is used here.)
//!
//! ## Sign conventions (used unchanged by the traction model)
//!
//! Written in the report's terms: body 1 is the report's "+" body (the upper,
//! driven disc of the rig), body 2 the "−" body (the lower, driving disc).
//!
//! * The contact normal `n` points from body 2 into body 1 (upwards on the rig).
//! * The rolling direction `t` (the report's x axis) is given by the caller and
//!   projected onto the tangent plane; the lateral axis is `s = n × t` (the
//!   report's y axis), so `(t, s, n)` = `(x, y, z)` is right-handed.
//! * `U = ½(v₁ + v₂)·t` is the mean rolling speed (positive when both surfaces
//!   move along `+t`), `ΔU = (v₁ − v₂)·t` ("`ΔU = U⁺ − U⁻`"),
//!   `ΔV = (v₁ − v₂)·s`, and the spin `ω = (Ω₁ − Ω₂)·n` is the relative angular
//!   velocity of body 1 with respect to body 2 about the normal (right-hand
//!   rule about `n`).
//! * Slide-to-roll ratios are `ΔU/U` and `ΔV/U`; spin grouping `Z = ω√(ab)/U`.
//! * Twin disc: the report gives no sign for the tilt α or the skew β. Here
//!   α > 0 is the tilt that makes the upper disc's spin about the upward normal
//!   positive (equation 6 then gives ω/U > 0), and β > 0 is a counter-clockwise
//!   turn of the upper assembly seen from above; with `t` along the upper disc's
//!   own rolling direction this gives `ΔV/U = +tan β` (equation 3). Both are
//!   tested as special cases of [`contact_kinematics`].
//!
//! ## Assumptions
//!
//! Rigid bodies (elastic creep belongs to `traction-compliance`), a single
//! contact point (the centre of the Hertz ellipse), steady motion. All inputs and
//! outputs are SI: m, m/s, rad, rad/s, Pa; `k = b/a`, `Z`, `ε`, J1..J3 are
//! dimensionless and keep the report's names.
//!
//! ## Example
//!
//! The report's low-speed machine, k = 1, 6° tilt (Tables 2-2, 2-4, 2-5):
//!
//! ```
//! use traction_kinematics::{spin_factor, tilted_disc_spin_per_speed};
//! let alpha = 6f64.to_radians();
//! let w_per_u = tilted_disc_spin_per_speed(alpha, 12.5e-3, 12.5e-3)?; // 1/m
//! assert!((w_per_u - 4.1932).abs() < 1e-3);
//! // C = 0.170e-12 m/Pa from Table 2-2; C'' printed as .713e-3 GPa⁻¹ in Table 2-5.
//! let c2 = spin_factor(w_per_u, 0.170e-12, 1.0)?; // 1/Pa
//! assert!((c2 * 1e9 - 0.713e-3).abs() < 0.001e-3);
//! # Ok::<(), traction_kinematics::KinematicsError>(())
//! ```
#![forbid(unsafe_code)]

/// The 3-vector type of the public API (re-exported from nalgebra so that users
/// need not depend on it directly).
pub use nalgebra::Vector3;

mod toroidal;
pub use toroidal::{HALF_CONE_ANGLE_RANGE, HalfToroidalVariator, VariatorState};
pub use traction_range::{OutOfRange, Range};

use std::f64::consts::FRAC_PI_2;

/// Errors of the kinematics crate. Every variant names the offending quantity.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum KinematicsError {
    /// An input quantity is NaN, infinite, or outside its valid range (the
    /// range and its message: [`traction_range::Range`]).
    #[error(transparent)]
    Range(#[from] traction_range::OutOfRange),
    /// A quantity derived from the inputs lies outside its valid range.
    #[error("{quantity} = {value} is out of range: {range}")]
    OutOfRange {
        /// Name of the quantity.
        quantity: &'static str,
        /// The value given.
        value: f64,
        /// The valid range, in words.
        range: &'static str,
    },
    /// The tilt makes the rolling radius `R_y cos α + e` of the tilted disc non-positive.
    #[error(
        "rolling radius R_y·cos(α) + e = {radius} m is not positive (tilt α = {alpha} rad, R_y = {ry} m, e = {e} m)"
    )]
    NonPositiveRollingRadius {
        /// The rolling radius `R_y cos α + e` (m).
        radius: f64,
        /// Tilt angle α (rad).
        alpha: f64,
        /// Transverse radius R_y (m).
        ry: f64,
        /// Signed centre offset e (m).
        e: f64,
    },
    /// A ratio to the rolling speed was asked for but the rolling speed is zero.
    #[error("rolling speed U is zero (|U| = {u} m/s): {what} is undefined")]
    ZeroRollingSpeed {
        /// |U| (m/s).
        u: f64,
        /// The ratio that was asked for.
        what: &'static str,
    },
    /// The speed pole was asked for but the spin is zero.
    #[error("spin ω is zero: the speed-pole location ε = ΔU/(ω√(ab)) is undefined")]
    ZeroSpin,
    /// A direction vector is zero, non-finite, or parallel to the normal.
    #[error("{quantity} is degenerate: {reason}")]
    Degenerate {
        /// Name of the vector.
        quantity: &'static str,
        /// Why it cannot be used.
        reason: &'static str,
    },
}

/// Result alias of this crate.
pub type Result<T> = std::result::Result<T, KinematicsError>;

/// Valid skew angle β and tilt angle α: |angle| < π/2.
pub const ANGLE_RANGE: Range = Range::open(-FRAC_PI_2, FRAC_PI_2).with_unit("rad");

fn finite_vec(quantity: &'static str, v: &Vector3<f64>) -> Result<()> {
    for c in v.iter() {
        Range::FINITE.check(quantity, *c)?;
    }
    Ok(())
}

// ---------------------------------------------------------------- twin disc

/// Side-slip ratio `ΔV/U = tan β` from the skew angle β (rad), equation (3).
///
/// Valid for `|β| < π/2`.
pub fn side_slip_ratio(skew_angle: f64) -> Result<f64> {
    ANGLE_RANGE.check("skew angle β", skew_angle)?;
    Ok(skew_angle.tan())
}

/// Rolling radius of the tilted disc, `R_y cos α + e` (m): the distance from the
/// contact point to the tilted axis (denominator of equation 6).
///
/// `ry` is the transverse radius R_y (> 0, m), `e` the signed centre offset (m,
/// negative when the centre of R_y lies above the axis of rotation, figure 2-3a),
/// `alpha` the tilt angle (|α| < π/2). Errors if the radius is not positive.
pub fn tilted_disc_rolling_radius(alpha: f64, ry: f64, e: f64) -> Result<f64> {
    ANGLE_RANGE.check("tilt angle α", alpha)?;
    Range::POSITIVE.check("transverse radius R_y", ry)?;
    Range::FINITE.check("centre offset e", e)?;
    let radius = ry * alpha.cos() + e;
    if radius > 0.0 {
        Ok(radius)
    } else {
        Err(KinematicsError::NonPositiveRollingRadius {
            radius,
            alpha,
            ry,
            e,
        })
    }
}

/// Spin per unit rolling speed of the tilted disc, equation (6):
/// `ω/U = sin α / (R_y cos α + e)` in 1/m. See [`tilted_disc_rolling_radius`].
pub fn tilted_disc_spin_per_speed(alpha: f64, ry: f64, e: f64) -> Result<f64> {
    let r = tilted_disc_rolling_radius(alpha, ry, e)?;
    Ok(alpha.sin() / r)
}

/// Spin factor of equation (7), `C'' = (ω/U)·C·√k` in 1/Pa, so that
/// `ω√(ab)/U = C''·P0`.
///
/// `omega_per_u` is ω/U (1/m), `c` the contact-size factor `C = a/P0` of
/// equation (2) (m/Pa, > 0), `k = b/a` (> 0).
pub fn spin_factor(omega_per_u: f64, c: f64, k: f64) -> Result<f64> {
    Range::FINITE.check("spin per rolling speed ω/U", omega_per_u)?;
    Range::POSITIVE.check("contact-size factor C", c)?;
    Range::POSITIVE.check("aspect ratio k", k)?;
    Ok(omega_per_u * c * k.sqrt())
}

/// Spin grouping `Z = ω√(ab)/U = C''·P0` (equation 7), dimensionless.
///
/// `c_double_prime` in 1/Pa, `p0` the maximum Hertz pressure (Pa, > 0).
pub fn spin_group(c_double_prime: f64, p0: f64) -> Result<f64> {
    Range::FINITE.check("spin factor C''", c_double_prime)?;
    Range::POSITIVE.check("Hertz pressure P0", p0)?;
    Ok(c_double_prime * p0)
}

/// Spin grouping `Z = ω√(ab)/U` from ω/U (1/m) and the semi-axes a, b (m).
pub fn spin_group_from_contact(omega_per_u: f64, a: f64, b: f64) -> Result<f64> {
    Range::FINITE.check("spin per rolling speed ω/U", omega_per_u)?;
    Range::POSITIVE.check("semi-axis a", a)?;
    Range::POSITIVE.check("semi-axis b", b)?;
    Ok(omega_per_u * (a * b).sqrt())
}

// ---------------------------------------------------------------- J groups

fn j_group(m: f64, mu: f64, k: f64, name: &'static str, ratio: f64) -> Result<f64> {
    Range::POSITIVE.check("traction slope m", m)?;
    Range::POSITIVE.check("peak traction coefficient μ", mu)?;
    Range::POSITIVE.check("aspect ratio k", k)?;
    Range::FINITE.check(name, ratio)?;
    Ok(3.0 * std::f64::consts::PI / 8.0 * (m / mu) * ratio * k.sqrt())
}

/// Dimensionless slip `J1 = (3π/8)(m/μ)(ΔU/U)√k` (Appendix IV eq. 11).
pub fn j1(m: f64, mu: f64, k: f64, slip_ratio: f64) -> Result<f64> {
    j_group(m, mu, k, "slide-to-roll ratio ΔU/U", slip_ratio)
}

/// Dimensionless side slip `J2 = (3π/8)(m/μ)(ΔV/U)√k` (Appendix V sec. 6).
pub fn j2(m: f64, mu: f64, k: f64, side_slip_ratio: f64) -> Result<f64> {
    j_group(m, mu, k, "side-slip ratio ΔV/U", side_slip_ratio)
}

/// Dimensionless spin `J3 = (3π/8)(m/μ)(ω√(ab)/U)√k` (Appendix IV eq. 12).
pub fn j3(m: f64, mu: f64, k: f64, z: f64) -> Result<f64> {
    j_group(m, mu, k, "spin grouping ω√(ab)/U", z)
}

/// The three kinematic J groups of one operating point (dimensionless).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JGroups {
    /// J1, dimensionless slip.
    pub j1: f64,
    /// J2, dimensionless side slip.
    pub j2: f64,
    /// J3, dimensionless spin.
    pub j3: f64,
}

/// J1, J2, J3 from the traction slope `m`, peak traction `mu`, aspect ratio `k`,
/// slide-to-roll ratio ΔU/U, side-slip ratio ΔV/U and spin grouping Z = ω√(ab)/U.
pub fn j_groups(
    m: f64,
    mu: f64,
    k: f64,
    slip_ratio: f64,
    side_slip_ratio: f64,
    z: f64,
) -> Result<JGroups> {
    Ok(JGroups {
        j1: j1(m, mu, k, slip_ratio)?,
        j2: j2(m, mu, k, side_slip_ratio)?,
        j3: j3(m, mu, k, z)?,
    })
}

// ---------------------------------------------------------------- general 3-D

/// Motion of one rigid body: angular velocity, a point on its axis, and the
/// translational velocity of that point (zero for a body turning about a fixed axis).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyMotion {
    /// Angular velocity vector Ω (rad/s).
    pub angular_velocity: Vector3<f64>,
    /// A point on the rotation axis (m).
    pub axis_point: Vector3<f64>,
    /// Velocity of `axis_point` (m/s).
    pub velocity: Vector3<f64>,
}

impl BodyMotion {
    /// A body turning with angular velocity `omega` about an axis through `point`.
    pub fn rotating(omega: Vector3<f64>, point: Vector3<f64>) -> Self {
        Self {
            angular_velocity: omega,
            axis_point: point,
            velocity: Vector3::zeros(),
        }
    }

    /// Velocity of the material point of this body at `p`: `V + Ω × (p − A)`.
    pub fn velocity_at(&self, p: &Vector3<f64>) -> Vector3<f64> {
        self.velocity + self.angular_velocity.cross(&(p - self.axis_point))
    }
}

/// Contact frame: point, unit normal (from body 2 into body 1), unit rolling
/// direction `t` and lateral direction `s = n × t`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactFrame {
    /// Contact point (m).
    pub point: Vector3<f64>,
    /// Unit normal, from body 2 into body 1.
    pub normal: Vector3<f64>,
    /// Unit rolling direction (report's x).
    pub rolling: Vector3<f64>,
    /// Unit lateral direction `n × t` (report's y).
    pub lateral: Vector3<f64>,
}

impl ContactFrame {
    /// Build the frame: normalises `normal`, projects `rolling` onto the tangent
    /// plane and normalises it. Errors on zero, non-finite or parallel vectors.
    pub fn new(point: Vector3<f64>, normal: Vector3<f64>, rolling: Vector3<f64>) -> Result<Self> {
        finite_vec("contact point", &point)?;
        finite_vec("contact normal", &normal)?;
        finite_vec("rolling direction", &rolling)?;
        let nn = normal.norm();
        if nn <= f64::MIN_POSITIVE {
            return Err(KinematicsError::Degenerate {
                quantity: "contact normal",
                reason: "zero vector",
            });
        }
        let n = normal / nn;
        let t_raw = rolling - n * rolling.dot(&n);
        let tn = t_raw.norm();
        if tn <= 1e-9 * rolling.norm() || tn <= f64::MIN_POSITIVE {
            return Err(KinematicsError::Degenerate {
                quantity: "rolling direction",
                reason: "zero or parallel to the contact normal",
            });
        }
        let t = t_raw / tn;
        Ok(Self {
            point,
            normal: n,
            rolling: t,
            lateral: n.cross(&t),
        })
    }
}

/// Kinematics at one contact (SI units; sign conventions in the crate docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactKinematics {
    /// Surface velocity of body 1 at the contact (m/s).
    pub surface_velocity_1: Vector3<f64>,
    /// Surface velocity of body 2 at the contact (m/s).
    pub surface_velocity_2: Vector3<f64>,
    /// Mean rolling speed `U = ½(v₁ + v₂)·t` (m/s).
    pub rolling_speed: f64,
    /// Slip `ΔU = (v₁ − v₂)·t` (m/s).
    pub slip: f64,
    /// Side slip `ΔV = (v₁ − v₂)·s` (m/s).
    pub side_slip: f64,
    /// Relative normal velocity `(v₁ − v₂)·n` (m/s); zero for bodies that stay in contact.
    pub approach: f64,
    /// Spin `ω = (Ω₁ − Ω₂)·n` (rad/s).
    pub spin: f64,
    /// The contact frame used.
    pub frame: ContactFrame,
}

impl ContactKinematics {
    fn require_u(&self, what: &'static str) -> Result<f64> {
        let u = self.rolling_speed;
        if u.abs()
            <= f64::EPSILON * (self.surface_velocity_1.norm() + self.surface_velocity_2.norm())
            || u == 0.0
        {
            Err(KinematicsError::ZeroRollingSpeed { u: u.abs(), what })
        } else {
            Ok(u)
        }
    }

    /// Slide-to-roll ratio `ΔU/U`.
    pub fn slip_ratio(&self) -> Result<f64> {
        Ok(self.slip / self.require_u("slide-to-roll ratio ΔU/U")?)
    }

    /// Side-slip ratio `ΔV/U`.
    pub fn side_slip_ratio(&self) -> Result<f64> {
        Ok(self.side_slip / self.require_u("side-slip ratio ΔV/U")?)
    }

    /// Spin per unit rolling speed `ω/U` (1/m).
    pub fn spin_per_speed(&self) -> Result<f64> {
        Ok(self.spin / self.require_u("spin per rolling speed ω/U")?)
    }

    /// Spin grouping `Z = ω√(ab)/U` for semi-axes `a` (along t) and `b` (m).
    pub fn spin_group(&self, a: f64, b: f64) -> Result<f64> {
        spin_group_from_contact(self.spin_per_speed()?, a, b)
    }

    /// Speed-pole location `ε = ΔU/(ω√(ab))` (dimensionless; the J1/J3 of the
    /// report). Errors when the spin is zero.
    pub fn speed_pole(&self, a: f64, b: f64) -> Result<f64> {
        Range::POSITIVE.check("semi-axis a", a)?;
        Range::POSITIVE.check("semi-axis b", b)?;
        if self.spin == 0.0 {
            return Err(KinematicsError::ZeroSpin);
        }
        Ok(self.slip / (self.spin * (a * b).sqrt()))
    }
}

/// Rigid-body kinematics at a contact between body 1 ("+") and body 2 ("−").
///
/// `normal` points from body 2 into body 1; `rolling` is projected onto the
/// tangent plane. See the crate docs for the sign conventions.
pub fn contact_kinematics(
    body1: &BodyMotion,
    body2: &BodyMotion,
    point: Vector3<f64>,
    normal: Vector3<f64>,
    rolling: Vector3<f64>,
) -> Result<ContactKinematics> {
    for (name, b) in [("body 1", body1), ("body 2", body2)] {
        let _ = name;
        finite_vec("angular velocity", &b.angular_velocity)?;
        finite_vec("axis point", &b.axis_point)?;
        finite_vec("translational velocity", &b.velocity)?;
    }
    let frame = ContactFrame::new(point, normal, rolling)?;
    let v1 = body1.velocity_at(&frame.point);
    let v2 = body2.velocity_at(&frame.point);
    let dv = v1 - v2;
    let k = ContactKinematics {
        surface_velocity_1: v1,
        surface_velocity_2: v2,
        rolling_speed: 0.5 * (v1 + v2).dot(&frame.rolling),
        slip: dv.dot(&frame.rolling),
        side_slip: dv.dot(&frame.lateral),
        approach: dv.dot(&frame.normal),
        spin: (body1.angular_velocity - body2.angular_velocity).dot(&frame.normal),
        frame,
    };
    // Finite inputs can still overflow: ω × (p − c) with |p − c| ≈ 1e308.
    let outputs = [
        (
            "surface velocity of body 1 (m/s)",
            k.surface_velocity_1.norm(),
        ),
        (
            "surface velocity of body 2 (m/s)",
            k.surface_velocity_2.norm(),
        ),
        ("rolling speed U (m/s)", k.rolling_speed),
        ("slip ΔU (m/s)", k.slip),
        ("side slip ΔV (m/s)", k.side_slip),
        ("approach speed (m/s)", k.approach),
        ("spin ω (rad/s)", k.spin),
    ];
    for (quantity, value) in outputs {
        if !value.is_finite() {
            return Err(KinematicsError::OutOfRange {
                quantity,
                value,
                range: "must be finite: the angular velocities, axis points and contact point \
                        are outside the floating-point range",
            });
        }
    }
    Ok(k)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finite_inputs_whose_velocities_overflow_are_refused() {
        // An axis point at 1e308 m (finite, so accepted) made ω × (c − p)
        // overflow: `traction kinematics` printed inf and NaN slips.
        let spin = BodyMotion::rotating(Vector3::new(60.0, -6.0, -20.0), Vector3::zeros());
        let far = BodyMotion::rotating(Vector3::z(), Vector3::new(-1e308, 60.0, 63.0));
        let r = contact_kinematics(&spin, &far, Vector3::y(), Vector3::z(), Vector3::x());
        assert!(
            matches!(r, Err(KinematicsError::OutOfRange { .. })),
            "{r:?}"
        );
        let e = r.unwrap_err().to_string();
        assert!(e.contains("surface velocity of body 2"), "{e}");
        // The same bodies with the axis at 1 m are fine.
        let near = BodyMotion::rotating(Vector3::z(), Vector3::new(-1.0, 60.0, 63.0));
        assert!(contact_kinematics(&spin, &near, Vector3::y(), Vector3::z(), Vector3::x()).is_ok());
    }

    #[test]
    fn eq6_hand_check_low_speed_k1() {
        // sin 6° / (12.5 cos 6° + 12.5) mm = 0.104528 / 24.9315 mm = 4.19262 1/m
        let w = tilted_disc_spin_per_speed(6f64.to_radians(), 12.5e-3, 12.5e-3).unwrap();
        assert!((w - 4.19262).abs() < 1e-4);
    }

    #[test]
    fn non_positive_rolling_radius_is_an_error() {
        let e = tilted_disc_spin_per_speed(30f64.to_radians(), 10e-3, -20e-3).unwrap_err();
        assert!(matches!(
            e,
            KinematicsError::NonPositiveRollingRadius { .. }
        ));
        assert!(e.to_string().contains("rolling radius"));
    }

    #[test]
    fn bad_inputs_name_the_quantity() {
        assert!(
            side_slip_ratio(f64::NAN)
                .unwrap_err()
                .to_string()
                .contains("skew angle")
        );
        assert!(
            spin_factor(1.0, -1.0, 1.0)
                .unwrap_err()
                .to_string()
                .contains("contact-size factor C")
        );
        assert!(
            j1(40.0, 0.0, 1.0, 0.01)
                .unwrap_err()
                .to_string()
                .contains("μ")
        );
        assert!(
            spin_group(1e-12, 0.0)
                .unwrap_err()
                .to_string()
                .contains("P0")
        );
    }

    #[test]
    fn zero_rolling_speed_ratio_is_an_error() {
        // Two discs spinning in opposite surface directions: U = 0.
        let b1 = BodyMotion::rotating(Vector3::new(0.0, 10.0, 0.0), Vector3::new(0.0, 0.0, 0.1));
        let b2 = BodyMotion::rotating(Vector3::new(0.0, 10.0, 0.0), Vector3::new(0.0, 0.0, -0.1));
        let k = contact_kinematics(&b1, &b2, Vector3::zeros(), Vector3::z(), Vector3::x()).unwrap();
        assert_eq!(k.rolling_speed, 0.0);
        let e = k.slip_ratio().unwrap_err();
        assert!(e.to_string().contains("rolling speed U is zero"));
    }

    #[test]
    fn degenerate_rolling_direction() {
        let b = BodyMotion::rotating(Vector3::zeros(), Vector3::zeros());
        let e = contact_kinematics(&b, &b, Vector3::zeros(), Vector3::z(), Vector3::z() * 2.0)
            .unwrap_err();
        assert!(e.to_string().contains("rolling direction"));
    }
}
