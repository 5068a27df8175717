//! The film thickness h of the thermal model, set by the inlet: the
//! Hamrock & Dowson (1977) central film ([`hamrock_dowson_central`]),
//! optionally reduced by the shear heating of the inlet's reverse flow
//! ([`thermal_loading`], [`inlet_heating_factor`], Gupta et al. 1992), and
//! the choice among the [`Film`] sources for one state ([`film_thickness`];
//! `film`, which also takes a physical fluid's own film, is what the
//! contact's thermal model `ContactThermal` (`contact_thermal.rs`) calls):
//!
//! ```text
//! h_HD = 2.69 R_x Ū^0.67 G^0.53 W^−0.067 (1 − 0.61 e^(−0.73 k)),
//!        Ū = η₀ |U| / (E' R_x),  G = α E',  W = N / (E' R_x²)
//! h    = φ_T h_HD,  φ_T = (1 − 13.2 (p_h/E') L^0.42) / (1 + 0.213 (1 + 2.23 S^0.83) L^0.64)
//!        L = β_η η₀ U²/k_f,  S = |ΔU|/U (at most 2)
//! ```
//!
//! h enters the mid-plane rise through the film's resistance h/(8 k_f).
//! Sources, the fits' ranges and why the inlet-heated film is not the report
//! fluids' default: the module docs (`mod.rs`).

use traction_fluids::ThermalProperties;

use super::{Film, Thermal};
use crate::{ContactError, Fluid, OperatingState, Range};

/// Valid slide-to-roll ratios |ΔU|/U of the inlet heating factor
/// ([`inlet_heating_factor`]): both surfaces move into the contact.
pub const SLIDE_ROLL_RANGE: Range = Range::closed(0.0, 2.0);
/// Valid Hertz pressures over the reduced modulus p_h/E' of the inlet heating
/// factor ([`inlet_heating_factor`]).
pub const PRESSURE_RATIO_RANGE: Range = Range::closed(0.0, 0.1);

/// Hamrock–Dowson (1977) central film thickness, m: `R_x` effective radius
/// along rolling (m), `e_prime` = 2/((1−ν₁²)/E₁ + (1−ν₂²)/E₂) (Pa), `k` = b/a,
/// `load` (N), `speed` = |U| (m/s), `viscosity` η₀ (Pa·s), `alpha` (1/Pa).
pub fn hamrock_dowson_central(
    rx: f64,
    e_prime: f64,
    k: f64,
    load: f64,
    speed: f64,
    viscosity: f64,
    alpha: f64,
) -> f64 {
    if speed == 0.0 || load == 0.0 {
        return 0.0;
    }
    let u = viscosity * speed / (e_prime * rx);
    let g = alpha * e_prime;
    let w = load / (e_prime * rx * rx);
    // u^0.67·g^0.53·w^−0.067 as one exponential (half the cost of three powf).
    let group = (0.67 * u.ln() + 0.53 * g.ln() - 0.067 * w.ln()).exp();
    2.69 * rx * group * (1.0 - 0.61 * (-0.73 * k).exp())
}

/// Thermal loading parameter of the inlet `L = β_η η₀ U²/k_f`
/// (dimensionless): the viscous heating of the inlet's reverse flow against
/// its conduction (Murch & Wilson, *J. Lubr. Technol.* 97, 1975): β_η =
/// −d ln η/dθ (1/K), η₀ (Pa·s), U the rolling (mean entraining) speed (m/s),
/// k_f the fluid's conductivity (W/(m·K)).
pub fn thermal_loading(
    viscosity_temperature: f64,
    viscosity: f64,
    speed: f64,
    conductivity: f64,
) -> f64 {
    viscosity_temperature * viscosity * speed * speed / conductivity
}

/// The thermal reduction factor of the central film by inlet shear heating
/// of Gupta, Cheng, Zhu, Forster & Schrand (*J. Tribol.* 114, 1992), fitted
/// to thermal EHL solutions of point contacts in rolling and sliding:
///
/// ```text
/// φ_T = (1 − 13.2 (p_h/E') L^0.42) / (1 + 0.213 (1 + 2.23 S^0.83) L^0.64)
/// ```
///
/// `thermal_loading` L ([`thermal_loading`], ≥ 0), `pressure_ratio` p_h/E'
/// (maximum Hertz pressure over the reduced modulus,
/// [`PRESSURE_RATIO_RANGE`]), `slide_roll_ratio` S = |ΔU|/U
/// ([`SLIDE_ROLL_RANGE`]; side slip and spin do not enter the fit). 1 at
/// L = 0; in (0, 1] where the numerator is positive (up to L ≈ 124 at
/// p_h/E' = 0.01), an error beyond (the fit gives no film there). Its
/// line-contact, pure-rolling counterpart is Murch & Wilson's (1975)
/// 3.94/(3.94 + L^0.62).
pub fn inlet_heating_factor(
    thermal_loading: f64,
    pressure_ratio: f64,
    slide_roll_ratio: f64,
) -> Result<f64, ContactError> {
    Range::NON_NEGATIVE.check(
        "thermal loading L = β_η η₀ U²/k_f of the inlet",
        thermal_loading,
    )?;
    PRESSURE_RATIO_RANGE.check("Hertz pressure over reduced modulus p_h/E'", pressure_ratio)?;
    SLIDE_ROLL_RANGE.check("slide-to-roll ratio |ΔU|/U", slide_roll_ratio)?;
    let numerator = 1.0 - 13.2 * pressure_ratio * thermal_loading.powf(0.42);
    if numerator <= 0.0 {
        return Err(ContactError::OutOfRange {
            quantity: "thermal loading L = β_η η₀ U²/k_f of the inlet",
            value: thermal_loading,
            valid: "below (1/(13.2 p_h/E'))^(1/0.42), where the inlet heating factor of Gupta et al. (1992) is positive",
        });
    }
    let denominator =
        1.0 + 0.213 * (1.0 + 2.23 * slide_roll_ratio.powf(0.83)) * thermal_loading.powf(0.64);
    Ok(numerator / denominator)
}

/// The film thickness h (m) the thermal model `th` takes at `state` for a
/// contact of `geometry` and `fluid` (if any): the given thickness, the Hamrock–Dowson
/// film from the given η₀ and α, or (with [`Film::FromFluid`]) a report
/// fluid's own η₀(θ) and α. A physical fluid's own film is set by its inlet
/// state inside the contact's evaluation, not here: with [`Film::FromFluid`]
/// it is an error, as for a user fluid.
pub fn film_thickness(
    th: &Thermal,
    geometry: &traction_hertz::Geometry,
    fluid: Option<&Fluid>,
    state: &OperatingState,
) -> Result<f64, ContactError> {
    let props = match fluid {
        Some(Fluid::Report { fluid, .. }) => Some(ThermalProperties::of(fluid.name)?),
        _ => None,
    };
    film(th, geometry, props, None, state)
}

/// [`film_thickness`] with a physical fluid's own film (`physical_film`).
pub(super) fn film(
    th: &Thermal,
    g: &traction_hertz::Geometry,
    props: Option<ThermalProperties>,
    physical_film: Option<f64>,
    state: &OperatingState,
) -> Result<f64, ContactError> {
    let hd = |viscosity: f64, pressure_viscosity: f64| {
        hamrock_dowson_central(
            1.0 / g.curvature_x,
            g.e_prime,
            g.k,
            state.load,
            state.rolling_speed.abs(),
            viscosity,
            pressure_viscosity,
        )
    };
    match (th.film, physical_film, props) {
        (Film::Thickness(h), _, _) => Ok(h),
        (
            Film::HamrockDowson {
                viscosity,
                pressure_viscosity,
            },
            _,
            _,
        ) => Ok(hd(viscosity, pressure_viscosity)),
        (Film::FromFluid, Some(h), _) => Ok(h),
        (Film::FromFluid, None, Some(p)) => Ok(hd(
            p.viscosity(state.inlet_temperature_celsius),
            p.pressure_viscosity,
        )),
        (Film::FromFluid, None, None) => Err(ContactError::OutOfRange {
            quantity: "film thickness h (m)",
            value: f64::NAN,
            valid: "required for user m, μ: Film::Thickness or Film::HamrockDowson",
        }),
        (
            Film::HamrockDowsonInletHeated {
                viscosity,
                pressure_viscosity,
                viscosity_temperature,
            },
            _,
            _,
        ) => {
            let k_f = th
                .fluid_conductivity
                .or(props.map(|p| p.conductivity))
                .ok_or(ContactError::OutOfRange {
                    quantity: "fluid thermal conductivity k_f (W/(m·K))",
                    value: f64::NAN,
                    valid: "required for the inlet heating of a user fluid (Thermal::fluid_conductivity, in (0, 1e4] W/(m·K))",
                })?;
            inlet_heated(
                g,
                state,
                hd(viscosity, pressure_viscosity),
                viscosity,
                viscosity_temperature,
                k_f,
            )
        }
        (Film::FromFluidInletHeated, _, Some(p)) => {
            let eta = p.viscosity(state.inlet_temperature_celsius);
            let k_f = th.fluid_conductivity.unwrap_or(p.conductivity);
            inlet_heated(
                g,
                state,
                hd(eta, p.pressure_viscosity),
                eta,
                p.viscosity_temperature(),
                k_f,
            )
        }
        (Film::FromFluidInletHeated, _, None) => Err(ContactError::OutOfRange {
            quantity: "film thickness h (m)",
            value: f64::NAN,
            valid: "Film::FromFluidInletHeated needs a report fluid's η₀(θ); for a user fluid: Film::HamrockDowsonInletHeated",
        }),
    }
}

/// The Hamrock–Dowson film `h` (m) at `state` reduced by inlet shear heating
/// ([`inlet_heating_factor`] at the state's Hertz pressure, [`thermal_loading`]
/// from η₀ `viscosity`, β_η `viscosity_temperature` and k_f `conductivity`).
fn inlet_heated(
    g: &traction_hertz::Geometry,
    state: &OperatingState,
    h: f64,
    viscosity: f64,
    viscosity_temperature: f64,
    conductivity: f64,
) -> Result<f64, ContactError> {
    if h == 0.0 {
        return Ok(0.0);
    }
    let speed = state.rolling_speed.abs();
    let p0 = g.at_load(state.load)?.p0;
    let l = thermal_loading(viscosity_temperature, viscosity, speed, conductivity);
    // Beyond the factor's range of slide-to-roll ratios (states starting
    // from rest with slip: S → ∞ as U → 0, where L → 0 and φ_T → 1
    // whatever S) the factor is taken at its largest S.
    let s = (state.slip.abs() / speed).min(SLIDE_ROLL_RANGE.max());
    Ok(h * inlet_heating_factor(l, p0 / g.e_prime, s)?)
}
