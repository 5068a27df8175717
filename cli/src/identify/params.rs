//! The parameters `traction identify` can fit and how they act on the model.

use traction_contact::Options;

/// The values every row's model is built from, set by the fitted parameters.
#[derive(Debug, Clone)]
pub struct Trial {
    /// Slope m for all rows (replaces the baseline).
    pub m: Option<f64>,
    /// Peak μ for all rows (replaces the baseline).
    pub mu: Option<f64>,
    /// Spin-peak μ_s scaling the forces, all rows.
    pub mu_spin: Option<f64>,
    /// Factor on each row's baseline m.
    pub m_factor: f64,
    /// Factor on each row's baseline μ (and μ_s).
    pub mu_factor: f64,
    /// Zero offset of ΔU/U.
    pub slip_offset: f64,
    /// Zero offset of ΔV/U.
    pub side_slip_offset: f64,
    /// Contact options.
    pub options: Options,
    /// β_μ for all rows, 1/K (thermal; replaces the row's value).
    pub mu_temperature_coefficient: Option<f64>,
    /// β_m for all rows, 1/K (thermal; replaces the row's value).
    pub m_temperature_coefficient: Option<f64>,
    /// T* of the second-order term of ln μ for all rows, K (thermal;
    /// replaces the row's value).
    pub mu_rise_scale: Option<f64>,
    /// Factor on every row's film thickness (thermal).
    pub film_factor: f64,
}

/// What the initial value of a parameter is taken from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Initial {
    /// Mean baseline m, else an estimate from the data's initial slope.
    Slope,
    /// Mean baseline μ, else 1.05 × the largest measured |F/N|.
    Peak,
    /// Mean baseline μ_s, else as [`Initial::Peak`].
    SpinPeak,
    /// A fixed value.
    Value(f64),
}

/// A named parameter of the calibration and how it maps onto the model.
#[derive(Debug, Clone, Copy)]
pub struct ParameterSpec {
    /// Name used in `--fit`, `--start` and the output.
    pub name: &'static str,
    /// What it is (with unit).
    pub description: &'static str,
    /// Typical magnitude: finite-difference step and identifiability floor.
    pub scale: f64,
    /// Lower bound.
    pub lower: f64,
    /// Upper bound.
    pub upper: f64,
    /// Parameters that cannot be fitted together with this one.
    pub excludes: &'static [&'static str],
    /// A parameter of the thermal model (fitted only with `--thermal`).
    pub thermal: bool,
    pub(super) initial: Initial,
    pub(super) apply: fn(&mut Trial, f64),
}

/// The parameters `traction identify` can fit.
pub const PARAMETERS: &[ParameterSpec] = &[
    ParameterSpec {
        name: "m",
        description: "traction slope m (-), one value for all rows",
        scale: 10.0,
        lower: 1e-3,
        upper: traction_contact::MAX_SLOPE,
        excludes: &["m_factor"],
        thermal: false,
        initial: Initial::Slope,
        apply: |t, v| t.m = Some(v),
    },
    ParameterSpec {
        name: "mu",
        description: "peak traction coefficient μ (-), one value for all rows",
        scale: 0.01,
        lower: 1e-6,
        upper: traction_contact::MAX_TRACTION_COEFFICIENT,
        excludes: &["mu_factor"],
        thermal: false,
        initial: Initial::Peak,
        apply: |t, v| t.mu = Some(v),
    },
    ParameterSpec {
        name: "mu_spin",
        description: "spin-peak traction coefficient μ_s scaling the forces (-), one value for all rows",
        scale: 0.01,
        lower: 1e-6,
        upper: traction_contact::MAX_TRACTION_COEFFICIENT,
        excludes: &[],
        thermal: false,
        initial: Initial::SpinPeak,
        apply: |t, v| t.mu_spin = Some(v),
    },
    ParameterSpec {
        name: "m_factor",
        description: "factor on each row's baseline slope m (-)",
        scale: 0.1,
        lower: 1e-3,
        upper: 1e3,
        excludes: &["m"],
        thermal: false,
        initial: Initial::Value(1.0),
        apply: |t, v| t.m_factor = v,
    },
    ParameterSpec {
        name: "mu_factor",
        description: "factor on each row's baseline μ and μ_s (-)",
        scale: 0.1,
        lower: 1e-3,
        upper: 1e3,
        excludes: &["mu"],
        thermal: false,
        initial: Initial::Value(1.0),
        apply: |t, v| t.mu_factor = v,
    },
    ParameterSpec {
        name: "slip_offset",
        description: "zero offset of the measured slip ratio ΔU/U (-): the model sees ΔU + offset·U",
        scale: 1e-3,
        lower: -0.5,
        upper: 0.5,
        excludes: &[],
        thermal: false,
        initial: Initial::Value(0.0),
        apply: |t, v| t.slip_offset = v,
    },
    ParameterSpec {
        name: "side_slip_offset",
        description: "zero offset of the measured side slip ratio ΔV/U (-): the model sees ΔV + offset·U",
        scale: 1e-3,
        lower: -0.5,
        upper: 0.5,
        excludes: &[],
        thermal: false,
        initial: Initial::Value(0.0),
        apply: |t, v| t.side_slip_offset = v,
    },
    ParameterSpec {
        name: "mu_temperature_coefficient",
        description: "temperature coefficient β_μ = −d ln μ/dθ of the peak traction coefficient (1/K), one value for all rows",
        scale: 1e-3,
        lower: -traction_contact::thermal::MAX_TEMPERATURE_COEFFICIENT,
        upper: traction_contact::thermal::MAX_TEMPERATURE_COEFFICIENT,
        excludes: &[],
        thermal: true,
        initial: Initial::Value(0.0025),
        apply: |t, v| t.mu_temperature_coefficient = Some(v),
    },
    ParameterSpec {
        name: "m_temperature_coefficient",
        description: "temperature coefficient β_m = −d ln m/dθ of the traction slope (1/K), one value for all rows",
        scale: 1e-3,
        lower: -traction_contact::thermal::MAX_TEMPERATURE_COEFFICIENT,
        upper: traction_contact::thermal::MAX_TEMPERATURE_COEFFICIENT,
        excludes: &[],
        thermal: true,
        initial: Initial::Value(0.0),
        apply: |t, v| t.m_temperature_coefficient = Some(v),
    },
    ParameterSpec {
        name: "mu_rise_scale",
        description: "temperature scale T* of the second-order term of ln μ in the film's rise (K): μ(ΔT) = μ e^(−(ΔT² − ΔT_peak²)/T*²), one value for all rows",
        scale: 50.0,
        lower: 1.0,
        upper: 1e5,
        excludes: &[],
        thermal: true,
        initial: Initial::Value(500.0),
        apply: |t, v| t.mu_rise_scale = Some(v),
    },
    ParameterSpec {
        name: "film_factor",
        description: "factor on every row's film thickness h, i.e. on the film's thermal resistance h/(8 k_f) (-)",
        scale: 0.1,
        lower: 1e-3,
        upper: 1e3,
        excludes: &[],
        thermal: true,
        initial: Initial::Value(1.0),
        apply: |t, v| t.film_factor = v,
    },
];
