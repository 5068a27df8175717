//! The surfaces' flash temperature: the resistance (mean surface
//! temperature rise over the Hertz ellipse per unit mean flux) of one body
//! moving through the contact ([`surface_resistance`]) and of the two
//! surfaces in parallel ([`surfaces_resistance`], R_s of the mid-plane rise
//! ΔT = q (R_s + R_f), which the contact's thermal model `ContactThermal`
//! (`contact_thermal.rs`) sums):
//!
//! ```text
//! R_i = (1/K) / √( 1/(c₀ √(ab))² + Pe_i/(c∞ l_i)² ),  Pe_i = |v_i| l_i / (2χ),  χ = K/(ρc)
//! R_s = R₁ R₂ / (R₁ + R₂),  v_1,2 = (U ± ΔU/2, ±ΔV/2)
//! ```
//!
//! with `l_i` the half-chord of the ellipse along `v_i` and the constants
//! c∞ = [`FLASH_HIGH_PECLET`], c₀ = [`FLASH_STATIONARY`]. Their derivation
//! and sources (Jaeger, Blok, Tian & Kennedy): the module docs (`mod.rs`).

use std::f64::consts::PI;

/// Mean surface temperature rise over the ellipse in the high-Péclet limit,
/// in units of q l/(K√Pe): `(4/(3√π))·(2/π)·B(½, 7/4)`.
pub const FLASH_HIGH_PECLET: f64 = 0.688_545_8;
/// Mean temperature rise of a uniformly heated circle (radius r) on a
/// stationary half-space, in units of q r/K: 8/(3π).
pub const FLASH_STATIONARY: f64 = 8.0 / (3.0 * PI);

/// Thermal resistance (mean surface temperature rise per unit mean flux,
/// K·m²/W) of one body whose surface moves at `velocity` = (vx, vy) m/s
/// through an elliptical source of semi-axes `a` (along x) and `b`.
pub fn surface_resistance(
    a: f64,
    b: f64,
    velocity: [f64; 2],
    conductivity: f64,
    heat_capacity: f64,
) -> f64 {
    let chi = conductivity / heat_capacity;
    // Speeds are bounded (the state's ranges): no overflow without hypot.
    let v = (velocity[0] * velocity[0] + velocity[1] * velocity[1]).sqrt();
    // Half-chord of the ellipse along the direction of motion.
    let l = if v > 0.0 {
        let (c, s) = (velocity[0] / v, velocity[1] / v);
        a * b / (b * b * c * c + a * a * s * s).sqrt()
    } else {
        a
    };
    let pe = v * l / (2.0 * chi);
    let r0 = FLASH_STATIONARY * (a * b).sqrt();
    let r_inf = FLASH_HIGH_PECLET * l;
    1.0 / (conductivity * (1.0 / (r0 * r0) + pe / (r_inf * r_inf)).sqrt())
}

/// Thermal resistances of a loaded contact for the thermal model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Resistances {
    /// Flash temperature of the two surfaces in parallel, K·m²/W.
    pub surfaces: f64,
    /// Conduction across the film to its mid-plane, h/(8 k_f), K·m²/W.
    pub film: f64,
    /// Film thickness used, m.
    pub film_thickness: f64,
}

impl Resistances {
    /// Total: mid-plane temperature rise per unit mean flux, K·m²/W.
    pub fn total(&self) -> f64 {
        self.surfaces + self.film
    }
}

/// The two surfaces' resistances in parallel for rolling speed U, slip ΔU
/// and side slip ΔV (surfaces move at (U ± ΔU/2, ±ΔV/2) through the contact).
pub fn surfaces_resistance(
    a: f64,
    b: f64,
    rolling_speed: f64,
    slip: f64,
    side_slip: f64,
    conductivity: f64,
    heat_capacity: f64,
) -> f64 {
    let r1 = surface_resistance(
        a,
        b,
        [rolling_speed + 0.5 * slip, 0.5 * side_slip],
        conductivity,
        heat_capacity,
    );
    let r2 = surface_resistance(
        a,
        b,
        [rolling_speed - 0.5 * slip, -0.5 * side_slip],
        conductivity,
        heat_capacity,
    );
    r1 * r2 / (r1 + r2)
}
