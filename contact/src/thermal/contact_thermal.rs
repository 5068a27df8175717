//! The thermal model of one loaded state (`ContactThermal`), which the
//! contact's evaluation (`crate::contact`) builds once per state and drives
//! with the fixed-point solver (`fixed_point.rs`): the fluid's temperature
//! coefficients, the film (`film.rs`) and the surfaces' resistances
//! (`flash.rs`) summed into the mid-plane rise per watt of loss, the rise of
//! the reference traction peak ([`PEAK_REDUCED_SLIP`]), the factors of m and
//! μ at a rise, and the slope estimate of the solver's first step:
//!
//! ```text
//! ΔT = P (R_s + R_f)/(πab),  R_f = h/(8 k_f)
//! m(ΔT) = m e^(−β_m ΔT),  μ(ΔT) = μ e^(−β_μ (ΔT − ΔT_peak) − (ΔT² − ΔT_peak²)/T*²)
//! ΔT_peak: the rise at ΔV = S (4/π)(μ/m) U, zero spin, loss μ N ΔV (S = 3)
//! d ln P/dΔT ≈ (2 − e) d ln μ/dΔT + e d ln m/dΔT,  e = 1 + S ψ'(S)/ψ(S),  S = (2/3)|J|/√k
//! ```
//!
//! (with a second-order term T* the slope is the chord's to the law's root,
//! `chord_slope`).

use std::f64::consts::PI;

use traction_fluids::ThermalProperties;

use super::Thermal;
use super::film::film;
use super::fixed_point::MAX_TEMPERATURE_RISE;
use super::flash::surfaces_resistance;
use crate::{ContactError, Fluid, OperatingState, TractionContact};

/// Reduced slip S = (π/4)(m/μ)(ΔV/U) of the reference traction peak: the
/// zero-spin traction ψ(S) is 0.96 μ there (App. V eq. 22), where measured
/// side-slip traces reach their plateau (Appendix VII-A: J5 ≥ 0.95 from
/// J2 ≈ 3..4, S = (2/3)J2/√k).
pub const PEAK_REDUCED_SLIP: f64 = 3.0;
/// The thermal model of one loaded state: temperature coefficients and the
/// total resistance.
#[derive(Debug, Clone, Copy)]
pub(crate) struct ContactThermal {
    pub(super) beta_mu: f64,
    pub(super) beta_m: f64,
    /// 1/T*² of the second-order term of ln μ, 1/K² (0: none).
    pub(super) inv_scale_sq: f64,
    /// (R_s + R_f)/(πab): temperature rise per watt of loss, K/W.
    pub(super) rise_per_watt: f64,
    /// Rise of the reference traction peak, K (0 unless `mu_at_traction_peak`).
    pub(super) reference_rise: f64,
}

impl ContactThermal {
    pub(crate) fn new(
        contact: &TractionContact,
        th: &Thermal,
        state: &OperatingState,
        hz: &traction_hertz::Contact,
        physical_film: Option<f64>,
        (m, mu): (f64, f64),
    ) -> Result<Self, ContactError> {
        let props = match contact.fluid() {
            Fluid::Report { fluid, .. } => Some(ThermalProperties::of(fluid.name)?),
            _ => None,
        };
        // For user fluids `new` has checked that the values are given.
        let from = |user: Option<f64>, fluid: Option<f64>| user.or(fluid).unwrap_or(0.0);
        let beta_mu = from(th.mu_coefficient, props.map(|p| p.mu_coefficient));
        let beta_m = from(th.slope_coefficient, props.map(|p| p.slope_coefficient));
        let scale = th
            .mu_rise_scale
            .or(props.map(|p| p.mu_rise_scale))
            .unwrap_or(f64::INFINITY);
        let k_f = from(th.fluid_conductivity, props.map(|p| p.conductivity));
        let g = contact.geometry();
        let h = film(th, g, props, physical_film, state)?;
        let speed = state.rolling_speed.abs();
        let r_s = surfaces_resistance(
            hz.a,
            hz.b,
            state.rolling_speed,
            state.slip,
            state.side_slip,
            th.disc_conductivity,
            th.disc_heat_capacity,
        );
        let r_f = h / (8.0 * k_f);
        let area = PI * hz.a * hz.b;
        // The reference peak: zero spin, side slip ΔV at S = PEAK_REDUCED_SLIP,
        // traction μN by definition, loss μ N ΔV.
        let reference_rise = if th.mu_at_traction_peak {
            let dv = PEAK_REDUCED_SLIP * 4.0 / PI * (mu / m) * speed;
            let r_ref = surfaces_resistance(
                hz.a,
                hz.b,
                speed,
                0.0,
                dv,
                th.disc_conductivity,
                th.disc_heat_capacity,
            );
            (r_ref + r_f) / area * mu * state.load * dv
        } else {
            0.0
        };
        // The given μ is that of a traction peak heated by `reference_rise`;
        // beyond the largest rise the fixed point accepts, that reference is
        // outside the model (the factor back to the unheated μ overflowed:
        // 3.5e7 K at U = 2.5e5 m/s on a 0.1 N contact gave μ = ∞ and NaN
        // forces).
        if reference_rise.is_nan() || reference_rise > MAX_TEMPERATURE_RISE {
            return Err(ContactError::Thermal {
                reason: "the traction peak the fluid's μ refers to heats the film beyond the largest accepted rise (2000 K)",
                temperature_rise: reference_rise,
            });
        }
        Ok(ContactThermal {
            beta_mu,
            beta_m,
            inv_scale_sq: (scale * scale).recip(),
            rise_per_watt: (r_s + r_f) / area,
            reference_rise,
        })
    }

    /// Factors (m, μ) at a temperature rise `dt`.
    pub(crate) fn factors(&self, dt: f64) -> (f64, f64) {
        let r = self.reference_rise;
        (
            (-self.beta_m * dt).exp(),
            (-self.beta_mu * (dt - r) - (dt * dt - r * r) * self.inv_scale_sq).exp(),
        )
    }

    /// An estimate of d ln(loss)/dΔT, 1/K, from the solution at the rise `dt`
    /// (K; J groups `j` = J1..J7 on a contact of aspect ratio `k`, giving the
    /// rise `rise`, K): the loss scales as μ²·J7 with the J's ∝ m/μ, so
    /// d ln loss = (2 − e)·d ln μ + e·d ln m with
    /// e = d ln J7/d ln |J| = 1 + S ψ'(S)/ψ(S) for the zero-spin closed form
    /// (eq. 23, S = (2/3)|J|/√k; 2 when elastic, → 1 when plastic), taken
    /// here with |J|² = J1² + J2² + (J3/2)² (spin as a mean slip: an estimate).
    /// With the first-order law (d ln μ/dΔT = −β_μ, d ln m/dΔT = −β_m) that
    /// slope is constant; with a second-order term (T*) the loss is not
    /// exponential in ΔT, and the slope returned is the chord's between `dt`
    /// and the fixed point of the loss at constant e ([`Self::chord_slope`]),
    /// so that the solver's exponential step lands on that point.
    /// Used only as the first step's slope of the fixed point: its error
    /// costs evaluations, not accuracy.
    // Inlined into the contact's fixed-point closure (`crate::contact`):
    // without the hint it is not (+0.8 % instructions on a zero-spin thermal
    // evaluation).
    #[inline]
    pub(crate) fn log_slope(&self, k: f64, j: &[f64; 7], dt: f64, rise: f64) -> f64 {
        let mag = (j[0] * j[0] + j[1] * j[1] + 0.25 * j[2] * j[2]).sqrt();
        let s = (2.0 / 3.0) * mag / k.sqrt();
        let q = 1.0 + s * s;
        let e = if s < 1e-8 {
            2.0
        } else if s.is_finite() {
            1.0 + (2.0 * s / (q * q)) / (s.atan() + s / q)
        } else {
            1.0
        };
        self.chord_slope(e, dt, rise)
    }

    /// ln(loss(x)/loss(dt)) at constant e (see [`Self::log_slope`]).
    pub(super) fn log_loss_ratio(&self, e: f64, dt: f64, x: f64) -> f64 {
        let ln_mu = -self.beta_mu * (x - dt) - (x * x - dt * dt) * self.inv_scale_sq;
        (2.0 - e) * ln_mu - e * self.beta_m * (x - dt)
    }

    /// The slope of ln(loss) for the solver's first step: the local slope at
    /// `dt` (exact for the first-order law), or with a second-order term the
    /// chord slope (ln x₁ − ln rise)/(x₁ − dt) = L(x₁)/(x₁ − dt) to the root
    /// x₁ of h(x) = x − rise·e^{L(x)}, L = [`Self::log_loss_ratio`] (so that
    /// the solver's exponential step through (dt, rise) lands on x₁), found by
    /// Newton's method safeguarded in the bracket between `dt` and `rise` (h is
    /// increasing there when heating lowers the loss); the local slope when
    /// that root is not bracketed or `rise` lies within 1 % of `dt`.
    pub(super) fn chord_slope(&self, e: f64, dt: f64, rise: f64) -> f64 {
        let dl =
            |x: f64| (2.0 - e) * (-self.beta_mu - 2.0 * x * self.inv_scale_sq) - e * self.beta_m;
        let local = dl(dt);
        // Near the fixed point (within 1 %) the local slope serves as well.
        if self.inv_scale_sq == 0.0
            || !(rise > 0.0 && rise.is_finite())
            || (rise - dt).abs() <= 0.01 * rise
        {
            return local;
        }
        // h(dt) = dt − rise (L(dt) = 0), h(rise) = rise·(1 − e^{L(rise)}).
        let h_dt = dt - rise;
        let h_rise = rise * (1.0 - self.log_loss_ratio(e, dt, rise).exp());
        if !(h_dt.min(h_rise) <= 0.0 && h_dt.max(h_rise) >= 0.0) {
            return local;
        }
        let (mut lo, mut hi) = if dt < rise { (dt, rise) } else { (rise, dt) };
        // Newton from rise, safeguarded by bisection of the bracket; x to
        // 1e-7 relative (the solver's tolerance is 1e-3 of the rise).
        let mut x = rise;
        for _ in 0..40 {
            let ex = rise * self.log_loss_ratio(e, dt, x).exp();
            let h = x - ex;
            if h.abs() <= 1e-7 * x {
                break;
            }
            if h < 0.0 {
                lo = x;
            } else {
                hi = x;
            }
            let d = 1.0 - ex * dl(x);
            let mut next = x - h / d;
            if !(d > 0.0 && next > lo && next < hi) {
                next = 0.5 * (lo + hi);
            }
            x = next;
        }
        if (x - dt).abs() <= 1e-12 * x.max(1.0) {
            return local;
        }
        self.log_loss_ratio(e, dt, x) / (x - dt)
    }

    /// A starting guess of the fixed point: the reference peak's rise, K.
    pub(crate) fn start(&self) -> f64 {
        self.reference_rise
    }

    /// Mid-plane temperature rise for a loss (W).
    pub(crate) fn rise(&self, loss: f64) -> f64 {
        self.rise_per_watt * loss
    }
}
