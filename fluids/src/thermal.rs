//! Thermal and film properties of the report fluids (`data/thermal_properties.csv`)
//! for the thermal contact model: inlet viscosity η₀(θ), pressure–viscosity
//! coefficient α (Hamrock–Dowson film thickness), fluid conductivity k_f and
//! the temperature coefficients of μ and m. Sources in the data file's header.

use std::sync::OnceLock;

use crate::{FluidError, FluidName};

const THERMAL_CSV: &str = include_str!("../data/thermal_properties.csv");

/// Thermal and film properties of a report fluid (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThermalProperties {
    /// Dynamic viscosity at 40 °C, Pa·s.
    pub viscosity_40c: f64,
    /// Dynamic viscosity at 100 °C, Pa·s.
    pub viscosity_100c: f64,
    /// Pressure–viscosity coefficient α, 1/Pa.
    pub pressure_viscosity: f64,
    /// Thermal conductivity k_f, W/(m·K).
    pub conductivity: f64,
    /// β_μ = −d ln μ/dθ (first-order term of ln μ in the rise), 1/K.
    pub mu_coefficient: f64,
    /// Temperature scale T* of the second-order term of ln μ in the rise, K
    /// (μ falls by e^(−(ΔT/T*)²) from the reference; infinite: none).
    pub mu_rise_scale: f64,
    /// β_m = −d ln m/dθ, 1/K.
    pub slope_coefficient: f64,
}

impl ThermalProperties {
    /// The properties of a report fluid from `data/thermal_properties.csv`
    /// (parsed once per process; the thermal contact asks for them at every
    /// evaluation).
    pub fn of(name: FluidName) -> Result<ThermalProperties, FluidError> {
        static PARSED: OnceLock<[Result<ThermalProperties, FluidError>; 2]> = OnceLock::new();
        let all = PARSED.get_or_init(|| {
            [
                Self::parse(FluidName::Santotrac50),
                Self::parse(FluidName::Tdf88),
            ]
        });
        match name {
            FluidName::Santotrac50 => all[0].clone(),
            FluidName::Tdf88 => all[1].clone(),
        }
    }

    /// Parse the data file's row of a fluid.
    fn parse(name: FluidName) -> Result<ThermalProperties, FluidError> {
        let bad = |line: usize, message: String| FluidError::Data {
            file: "thermal_properties.csv",
            line,
            message,
        };
        for (no, line) in THERMAL_CSV.lines().enumerate() {
            let no = no + 1;
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') || line.starts_with("fluid,") {
                continue;
            }
            let f: Vec<&str> = line.split(',').collect();
            if f.len() != 8 {
                return Err(bad(no, format!("expected 8 fields in `{line}`")));
            }
            if f[0] != name.slug() {
                continue;
            }
            let mut v = [0.0; 7];
            for (i, s) in f[1..].iter().enumerate() {
                v[i] = s
                    .trim()
                    .parse()
                    .map_err(|_| bad(no, format!("`{s}` is not a number")))?;
            }
            return Ok(ThermalProperties {
                viscosity_40c: v[0],
                viscosity_100c: v[1],
                pressure_viscosity: v[2],
                conductivity: v[3],
                mu_coefficient: v[4],
                slope_coefficient: v[5],
                mu_rise_scale: v[6],
            });
        }
        Err(bad(0, format!("no row for {}", name.slug())))
    }

    /// Inlet viscosity at θ (°C), Pa·s: ln η linear in θ through the 40 °C and
    /// 100 °C values (Reynolds' law; extrapolated outside, always > 0).
    pub fn viscosity(&self, theta_celsius: f64) -> f64 {
        let s = (self.viscosity_100c / self.viscosity_40c).ln() / 60.0;
        self.viscosity_40c * (s * (theta_celsius - 40.0)).exp()
    }

    /// Temperature–viscosity coefficient β_η = −d ln η/dθ of the inlet
    /// viscosity, 1/K: the slope of [`Self::viscosity`]'s ln η, the same at
    /// every θ (ln η linear in θ through the 40 °C and 100 °C values).
    pub fn viscosity_temperature(&self) -> f64 {
        (self.viscosity_40c / self.viscosity_100c).ln() / 60.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_fluids_have_physical_properties() {
        for n in [FluidName::Santotrac50, FluidName::Tdf88] {
            let p = ThermalProperties::of(n).unwrap();
            assert!(p.viscosity_40c > p.viscosity_100c && p.viscosity_100c > 0.0);
            assert!(p.pressure_viscosity > 5e-9 && p.pressure_viscosity < 5e-8);
            assert!(p.conductivity > 0.05 && p.conductivity < 0.3);
            assert!(p.mu_coefficient >= 0.0 && p.mu_coefficient < 0.1);
            // T* far above the rises of slow side-slip traces (tens of K),
            // finite: the report's 80 m/s spin traces need one.
            assert!(p.mu_rise_scale > 100.0 && p.mu_rise_scale < 5000.0);
            // The interpolation passes through both data points.
            assert!((p.viscosity(40.0) / p.viscosity_40c - 1.0).abs() < 1e-12);
            assert!((p.viscosity(100.0) / p.viscosity_100c - 1.0).abs() < 1e-12);
        }
    }

    /// β_η is −d ln η/dθ of the interpolation: a central difference of
    /// ln η at 70 °C (exact for ln η linear in θ, to rounding), and for the
    /// data file's 30.3 / 5.0 mPa·s ln(6.06)/60 K = 0.03003 1/K (printed
    /// digits).
    #[test]
    fn viscosity_temperature_is_the_slope_of_ln_viscosity() {
        for n in [FluidName::Santotrac50, FluidName::Tdf88] {
            let p = ThermalProperties::of(n).unwrap();
            let fd = -(p.viscosity(71.0).ln() - p.viscosity(69.0).ln()) / 2.0;
            assert!((p.viscosity_temperature() - fd).abs() < 1e-12, "{fd}");
            assert!((p.viscosity_temperature() - 0.03003).abs() < 1e-5);
        }
    }
}
