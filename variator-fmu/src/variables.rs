//! The variable table: the single source of the FMU's interface.
//!
//! modelDescription.xml ([`crate::model_description`]) and the instance
//! ([`crate::model`]) both read this table. Value references are unique
//! across all types. Real parameters are VR 1..=[`N_REAL_PARAMS`], Real
//! inputs [`vr::OMEGA_IN`].., Real outputs [`vr::TORQUE_IN`].. in table order.

/// FMI 2 causality: `parameter` (variability `fixed`), `input`
/// (`continuous`), `output` (`continuous` Reals, `discrete` Enumerations).
pub use traction_fmi_support::xml::Causality;
pub use traction_fmi_support::xml::{EnumItem, EnumType, Unit};

/// Type and start value of a variable.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kind {
    /// `Real` with its unit (one of [`UNITS`]) and start (parameters, inputs).
    Real {
        /// Unit name.
        unit: &'static str,
        /// Start value.
        start: Option<f64>,
    },
    /// `Integer` with start, min and max.
    Integer {
        /// Start value.
        start: i32,
        /// Minimum.
        min: i32,
        /// Maximum.
        max: i32,
    },
    /// `Enumeration` of a declared type of [`ENUM_TYPES`].
    Enumeration {
        /// Name of the declared type.
        declared: &'static str,
        /// Start value (parameters).
        start: Option<i32>,
    },
    /// `Boolean` with start.
    Boolean {
        /// Start value.
        start: bool,
    },
}

/// One row of the table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Variable {
    /// Name.
    pub name: &'static str,
    /// Value reference.
    pub vr: u32,
    /// Causality.
    pub causality: Causality,
    /// Type and start.
    pub kind: Kind,
    /// Description (units spelled out).
    pub description: &'static str,
    /// For outputs: depends on the tilt only (geometry), not on the other inputs.
    pub tilt_only: bool,
}

/// Units: name, exponents of `[kg, m, s, A, K, mol, cd, rad]`, offset.
pub const UNITS: &[Unit] = &[
    Unit::new("m", [0, 1, 0, 0, 0, 0, 0, 0], 0.0),
    Unit::new("rad", [0, 0, 0, 0, 0, 0, 0, 1], 0.0),
    Unit::new("rad/s", [0, 0, -1, 0, 0, 0, 0, 1], 0.0),
    Unit::new("m/s", [0, 1, -1, 0, 0, 0, 0, 0], 0.0),
    Unit::new("N", [1, 1, -2, 0, 0, 0, 0, 0], 0.0),
    Unit::new("N.m", [1, 2, -2, 0, 0, 0, 0, 0], 0.0),
    Unit::new("W", [1, 2, -3, 0, 0, 0, 0, 0], 0.0),
    Unit::new("Pa", [1, -1, -2, 0, 0, 0, 0, 0], 0.0),
    Unit::new("degC", [0, 0, 0, 0, 1, 0, 0, 0], 273.15),
    Unit::new("K", [0, 0, 0, 0, 1, 0, 0, 0], 0.0),
    Unit::new("1", [0; 8], 0.0),
];

/// Enumeration SimpleTypes: name, description, items.
pub const ENUM_TYPES: &[EnumType] = &[
    (
        "Fluid",
        "Traction fluid",
        &[
            (
                "santotrac_50",
                1,
                "Santotrac 50, report correlations (Appendix III-A)",
            ),
            ("tdf_88", 2, "TDF-88, report correlations (Appendix III-B)"),
            ("user", 3, "user values m_user and mu_user"),
        ],
    ),
    (
        "EnvelopeRule",
        "What the report fluids' correlations do outside their data",
        &[
            ("strict", 1, "error naming the quantity and the data range"),
            (
                "extrapolate",
                2,
                "evaluate the correlation outside the data",
            ),
            (
                "clamp",
                3,
                "evaluate at the nearest point of the data envelope",
            ),
        ],
    ),
    (
        "Regime",
        "Regime of Appendix IV figure 14",
        &[
            ("open", 0, "no normal load: no contact"),
            (
                "elastic_no_spin",
                1,
                "region I: elastic/plastic without spin",
            ),
            (
                "elastic_with_spin",
                2,
                "region II: elastic/plastic with spin",
            ),
            ("rigid_plastic", 3, "region III: rigid/plastic"),
        ],
    ),
];

/// Value references.
pub mod vr {
    /// Cavity radius r0.
    pub const CAVITY_RADIUS: u32 = 1;
    /// Cavity centre radius e0.
    pub const CAVITY_CENTRE_RADIUS: u32 = 2;
    /// Half-cone angle θ0.
    pub const HALF_CONE_ANGLE: u32 = 3;
    /// Roller crown radius r22.
    pub const ROLLER_CROWN_RADIUS: u32 = 4;
    /// Disc Young's modulus.
    pub const DISC_E: u32 = 5;
    /// Disc Poisson's ratio.
    pub const DISC_NU: u32 = 6;
    /// Roller Young's modulus.
    pub const ROLLER_E: u32 = 7;
    /// Roller Poisson's ratio.
    pub const ROLLER_NU: u32 = 8;
    /// User traction slope m.
    pub const M_USER: u32 = 9;
    /// User peak traction coefficient μ.
    pub const MU_USER: u32 = 10;
    /// Rheology accuracy.
    pub const TOLERANCE: u32 = 11;
    /// Rolling-speed floor.
    pub const SPEED_FLOOR: u32 = 12;
    /// Number of rollers (Integer).
    pub const ROLLERS: u32 = 13;
    /// Fluid (Enumeration).
    pub const FLUID: u32 = 14;
    /// Envelope rule (Enumeration).
    pub const ENVELOPE: u32 = 15;
    /// Interpolation map on/off (Boolean).
    pub const MAP: u32 = 16;
    /// Thermal contact model on/off (Boolean).
    pub const THERMAL: u32 = 17;
    /// Input-disc speed.
    pub const OMEGA_IN: u32 = 20;
    /// Output-disc speed.
    pub const OMEGA_OUT: u32 = 21;
    /// Roller tilt.
    pub const TILT: u32 = 22;
    /// End load.
    pub const END_LOAD: u32 = 23;
    /// Inlet temperature.
    pub const INLET_TEMPERATURE: u32 = 24;
    /// First Real output (torque_in).
    pub const TORQUE_IN: u32 = 100;
    /// torque_out.
    pub const TORQUE_OUT: u32 = 101;
    /// speed_ratio.
    pub const SPEED_RATIO: u32 = 102;
    /// roller_speed.
    pub const ROLLER_SPEED: u32 = 103;
    /// power_in.
    pub const POWER_IN: u32 = 104;
    /// power_out.
    pub const POWER_OUT: u32 = 105;
    /// power_loss.
    pub const POWER_LOSS: u32 = 106;
    /// spin_loss.
    pub const SPIN_LOSS: u32 = 107;
    /// efficiency.
    pub const EFFICIENCY: u32 = 108;
    /// roller_side_force.
    pub const SIDE_FORCE: u32 = 109;
    /// tilt_moment.
    pub const TILT_MOMENT: u32 = 110;
    /// First per-contact output of the input contact (see [`super::CONTACT_OUTPUTS`]).
    pub const CONTACT_IN: u32 = 111;
    /// First per-contact output of the output contact.
    pub const CONTACT_OUT: u32 = 111 + super::N_CONTACT_OUTPUTS as u32;
    /// regime_in (Enumeration output).
    pub const REGIME_IN: u32 = 200;
    /// regime_out (Enumeration output).
    pub const REGIME_OUT: u32 = 201;
}

/// Number of Real parameters (VR 1..=12).
pub const N_REAL_PARAMS: usize = 12;
/// Number of Real inputs.
pub const N_INPUTS: usize = 5;
/// Number of variator-level Real outputs.
pub const N_VARIATOR_OUTPUTS: usize = 11;
/// Number of Real outputs per contact.
pub const N_CONTACT_OUTPUTS: usize = 12;
/// Number of Real outputs.
pub const N_REAL_OUTPUTS: usize = N_VARIATOR_OUTPUTS + 2 * N_CONTACT_OUTPUTS;

/// Per-contact outputs: name stem, unit, description (the name is
/// `<stem>_in` or `<stem>_out`; values per roller).
pub const CONTACT_OUTPUTS: [(&str, &str, &str); N_CONTACT_OUTPUTS] = [
    (
        "normal_load",
        "N",
        "normal load of the contact (end load / (n sin(theta0 -+ gamma))), N",
    ),
    (
        "contact_radius",
        "m",
        "distance of the contact from the main axis, m",
    ),
    (
        "rolling_speed",
        "m/s",
        "rolling speed U at the contact, m/s",
    ),
    (
        "slip",
        "m/s",
        "slip dU = (v_disc - v_roller) along rolling, m/s",
    ),
    ("slip_ratio", "1", "slide-to-roll ratio dU/U (0 at U = 0)"),
    (
        "spin",
        "rad/s",
        "spin (disc minus roller angular velocity) about the normal, rad/s",
    ),
    (
        "traction_coefficient",
        "1",
        "traction coefficient Fx/N of the contact",
    ),
    (
        "side_force_coefficient",
        "1",
        "side-force coefficient Fy/N of the contact",
    ),
    (
        "power_loss",
        "W",
        "power loss of the contact (one roller), W",
    ),
    (
        "spin_loss",
        "W",
        "spin part Mz*spin of the contact's power loss (one roller), W",
    ),
    (
        "max_pressure",
        "Pa",
        "maximum Hertz pressure P0 of the contact, Pa",
    ),
    (
        "temperature_rise",
        "K",
        "film temperature rise of the contact above the inlet temperature (thermal = true; 0 otherwise), K",
    ),
];

const fn real_par(
    name: &'static str,
    vr: u32,
    unit: &'static str,
    start: f64,
    d: &'static str,
) -> Variable {
    Variable {
        name,
        vr,
        causality: Causality::Parameter,
        kind: Kind::Real {
            unit,
            start: Some(start),
        },
        description: d,
        tilt_only: false,
    }
}

const fn real_in(
    name: &'static str,
    vr: u32,
    unit: &'static str,
    start: f64,
    d: &'static str,
) -> Variable {
    Variable {
        name,
        vr,
        causality: Causality::Input,
        kind: Kind::Real {
            unit,
            start: Some(start),
        },
        description: d,
        tilt_only: false,
    }
}

const fn real_out(
    name: &'static str,
    vr: u32,
    unit: &'static str,
    tilt_only: bool,
    d: &'static str,
) -> Variable {
    Variable {
        name,
        vr,
        causality: Causality::Output,
        kind: Kind::Real { unit, start: None },
        description: d,
        tilt_only,
    }
}

macro_rules! contact_outputs {
    ($suffix:literal, $base:expr, $side:literal) => {
        [
            real_out(
                concat!("normal_load_", $suffix),
                $base,
                "N",
                false,
                concat!(
                    $side,
                    " contact: normal load (end load / (n sin(theta0 -+ gamma))), N"
                ),
            ),
            real_out(
                concat!("contact_radius_", $suffix),
                $base + 1,
                "m",
                true,
                concat!($side, " contact: distance from the main axis, m"),
            ),
            real_out(
                concat!("rolling_speed_", $suffix),
                $base + 2,
                "m/s",
                false,
                concat!($side, " contact: rolling speed U, m/s"),
            ),
            real_out(
                concat!("slip_", $suffix),
                $base + 3,
                "m/s",
                false,
                concat!(
                    $side,
                    " contact: slip dU = (v_disc - v_roller) along rolling, m/s"
                ),
            ),
            real_out(
                concat!("slip_ratio_", $suffix),
                $base + 4,
                "1",
                false,
                concat!($side, " contact: slide-to-roll ratio dU/U (0 at U = 0)"),
            ),
            real_out(
                concat!("spin_", $suffix),
                $base + 5,
                "rad/s",
                false,
                concat!(
                    $side,
                    " contact: spin (disc minus roller angular velocity about the normal), rad/s"
                ),
            ),
            real_out(
                concat!("traction_coefficient_", $suffix),
                $base + 6,
                "1",
                false,
                concat!($side, " contact: traction coefficient Fx/N"),
            ),
            real_out(
                concat!("side_force_coefficient_", $suffix),
                $base + 7,
                "1",
                false,
                concat!($side, " contact: side-force coefficient Fy/N"),
            ),
            real_out(
                concat!("power_loss_", $suffix),
                $base + 8,
                "W",
                false,
                concat!($side, " contact: power loss (one roller), W"),
            ),
            real_out(
                concat!("spin_loss_", $suffix),
                $base + 9,
                "W",
                false,
                concat!($side, " contact: spin loss Mz*spin (one roller), W"),
            ),
            real_out(
                concat!("max_pressure_", $suffix),
                $base + 10,
                "Pa",
                false,
                concat!($side, " contact: maximum Hertz pressure P0, Pa"),
            ),
            real_out(
                concat!("temperature_rise_", $suffix),
                $base + 11,
                "K",
                false,
                concat!(
                    $side,
                    " contact: film temperature rise above the inlet temperature (thermal = true; 0 otherwise), K"
                ),
            ),
        ]
    };
}

const PARAMS: [Variable; N_REAL_PARAMS] = [
    real_par(
        "cavity_radius",
        vr::CAVITY_RADIUS,
        "m",
        0.040,
        "radius r0 of the cavity's generating circle, m",
    ),
    real_par(
        "cavity_centre_radius",
        vr::CAVITY_CENTRE_RADIUS,
        "m",
        0.065,
        "distance e0 from the main axis to the cavity centre, m (aspect ratio k0 = e0/r0 - 1)",
    ),
    real_par(
        "half_cone_angle",
        vr::HALF_CONE_ANGLE,
        "rad",
        1.090_830_782_496_456,
        "roller half-cone angle theta0 in (0, pi/2] rad (pi/2: full-toroidal cavity); default 62.5 deg",
    ),
    real_par(
        "roller_crown_radius",
        vr::ROLLER_CROWN_RADIUS,
        "m",
        0.028,
        "roller crown radius r22 in the meridian plane, 0 < r22 < r0, m",
    ),
    real_par(
        "disc_youngs_modulus",
        vr::DISC_E,
        "Pa",
        210e9,
        "Young's modulus of the discs, Pa",
    ),
    real_par(
        "disc_poisson_ratio",
        vr::DISC_NU,
        "1",
        0.3,
        "Poisson's ratio of the discs",
    ),
    real_par(
        "roller_youngs_modulus",
        vr::ROLLER_E,
        "Pa",
        210e9,
        "Young's modulus of the rollers, Pa",
    ),
    real_par(
        "roller_poisson_ratio",
        vr::ROLLER_NU,
        "1",
        0.3,
        "Poisson's ratio of the rollers",
    ),
    real_par(
        "m_user",
        vr::M_USER,
        "1",
        40.0,
        "fluid = user: initial traction slope m (0, 1e6]",
    ),
    real_par(
        "mu_user",
        vr::MU_USER,
        "1",
        0.08,
        "fluid = user: peak traction coefficient mu (0, 10]",
    ),
    real_par(
        "rheology_tolerance",
        vr::TOLERANCE,
        "1",
        1e-4,
        "absolute accuracy of the J+T integration in J4..J6, in [1e-6, 1e-2]",
    ),
    real_par(
        "rolling_speed_floor",
        vr::SPEED_FLOOR,
        "m/s",
        1e-3,
        "rolling-speed floor U_f of the J groups (start-up and stops), in [1e-9, 1] m/s",
    ),
];

const DISCRETE_PARAMS: [Variable; 5] = [
    Variable {
        name: "number_of_rollers",
        vr: vr::ROLLERS,
        causality: Causality::Parameter,
        kind: Kind::Integer {
            start: 2,
            min: 1,
            max: 16,
        },
        description: "number n of rollers in the cavity (they share the end load and the torque equally)",
        tilt_only: false,
    },
    Variable {
        name: "fluid",
        vr: vr::FLUID,
        causality: Causality::Parameter,
        kind: Kind::Enumeration {
            declared: "Fluid",
            start: Some(3),
        },
        description: "traction fluid: 1 Santotrac 50, 2 TDF-88 (report correlations), 3 user m and mu",
        tilt_only: false,
    },
    Variable {
        name: "fluid_envelope",
        vr: vr::ENVELOPE,
        causality: Causality::Parameter,
        kind: Kind::Enumeration {
            declared: "EnvelopeRule",
            start: Some(3),
        },
        description: "outside the data of the report fluids' correlations: 1 error, 2 extrapolate, 3 clamp to the data envelope",
        tilt_only: false,
    },
    Variable {
        name: "rheology_map",
        vr: vr::MAP,
        causality: Causality::Parameter,
        kind: Kind::Boolean { start: false },
        description: "evaluate the J+T model through each contact's lazily built interpolation map (checked against the direct solution; ~10 us per step once a region is visited at a fixed tilt; new cells are built within a budget of 0.5 node evaluations earned per evaluation, states whose cells are not built yet are evaluated directly, so a step costs at most a few direct ones on any input sequence, also when a new tilt brings new contacts and maps; whether a value is interpolated or direct depends on the steps before); false (default): integrate the strips at every evaluation (~10 ms per step with spin)",
        tilt_only: false,
    },
    Variable {
        name: "thermal",
        vr: vr::THERMAL,
        causality: Causality::Parameter,
        kind: Kind::Boolean { start: false },
        description: "thermal contact model (traction-contact Options::thermal with the fluid's own film and temperature coefficients; needs fluid = 1 or 2): each film's temperature rise solved from the contact's own loss, about 3x the cost; false (default): isothermal at the inlet temperature",
        tilt_only: false,
    },
];

const INPUTS: [Variable; N_INPUTS] = [
    real_in(
        "omega_in",
        vr::OMEGA_IN,
        "rad/s",
        300.0,
        "input-disc angular speed about its axis, rad/s",
    ),
    real_in(
        "omega_out",
        vr::OMEGA_OUT,
        "rad/s",
        0.0,
        "output-disc angular speed, rad/s, positive in its own sense of rotation (it turns opposite to the input disc)",
    ),
    real_in(
        "tilt_angle",
        vr::TILT,
        "rad",
        0.0,
        "roller tilt gamma, rad, |gamma| < half_cone_angle; gamma > 0: output slower than input",
    ),
    real_in(
        "end_load",
        vr::END_LOAD,
        "N",
        20e3,
        "end (clamping) load pressing the discs together, N, in [0, 1e9]",
    ),
    real_in(
        "inlet_temperature",
        vr::INLET_TEMPERATURE,
        "degC",
        70.0,
        "fluid inlet temperature at every contact, degC",
    ),
];

const VARIATOR_OUTPUTS: [Variable; N_VARIATOR_OUTPUTS] = [
    real_out(
        "torque_in",
        vr::TORQUE_IN,
        "N.m",
        false,
        "torque of the variator on the input disc, positive in the sense of omega_in (negative when the input drives), N.m",
    ),
    real_out(
        "torque_out",
        vr::TORQUE_OUT,
        "N.m",
        false,
        "torque of the variator on the output disc, positive in the sense of omega_out (positive when it drives the output), N.m",
    ),
    real_out(
        "speed_ratio",
        vr::SPEED_RATIO,
        "1",
        true,
        "kinematic speed ratio omega_out/omega_in of the geometry at the tilt, r_in/r_out",
    ),
    real_out(
        "roller_speed",
        vr::ROLLER_SPEED,
        "rad/s",
        false,
        "roller speed from its torque balance, rad/s, positive when the input disc drives it forwards",
    ),
    real_out(
        "power_in",
        vr::POWER_IN,
        "W",
        false,
        "power entering at the input disc, -torque_in*omega_in, W",
    ),
    real_out(
        "power_out",
        vr::POWER_OUT,
        "W",
        false,
        "power leaving at the output disc, torque_out*omega_out, W",
    ),
    real_out(
        "power_loss",
        vr::POWER_LOSS,
        "W",
        false,
        "total power loss of all contacts, W (= power_in - power_out to round-off)",
    ),
    real_out(
        "spin_loss",
        vr::SPIN_LOSS,
        "W",
        false,
        "spin part of the total power loss, W",
    ),
    real_out(
        "efficiency",
        vr::EFFICIENCY,
        "1",
        false,
        "efficiency in the direction of the power flow; 0 when no power flows through",
    ),
    real_out(
        "roller_side_force",
        vr::SIDE_FORCE,
        "N",
        false,
        "force of the discs on one roller along its tilt (trunnion) axis, N",
    ),
    real_out(
        "tilt_moment",
        vr::TILT_MOMENT,
        "N.m",
        false,
        "moment of the discs on one roller about its tilt axis, N.m",
    ),
];

const CONTACT_IN: [Variable; N_CONTACT_OUTPUTS] =
    contact_outputs!("in", vr::CONTACT_IN, "input disc-roller");
const CONTACT_OUT: [Variable; N_CONTACT_OUTPUTS] =
    contact_outputs!("out", vr::CONTACT_OUT, "roller-output disc");

const REGIMES: [Variable; 2] = [
    Variable {
        name: "regime_in",
        vr: vr::REGIME_IN,
        causality: Causality::Output,
        kind: Kind::Enumeration {
            declared: "Regime",
            start: None,
        },
        description: "regime of the input contact (Appendix IV figure 14): 0 open, 1 elastic without spin, 2 elastic with spin, 3 rigid/plastic",
        tilt_only: false,
    },
    Variable {
        name: "regime_out",
        vr: vr::REGIME_OUT,
        causality: Causality::Output,
        kind: Kind::Enumeration {
            declared: "Regime",
            start: None,
        },
        description: "regime of the output contact: 0 open, 1 elastic without spin, 2 elastic with spin, 3 rigid/plastic",
        tilt_only: false,
    },
];

const N_ALL: usize = N_REAL_PARAMS + DISCRETE_PARAMS.len() + N_INPUTS + N_REAL_OUTPUTS + 2;

const fn all() -> [Variable; N_ALL] {
    let mut out = [PARAMS[0]; N_ALL];
    let mut i = 0;
    let mut k = 0;
    while k < PARAMS.len() {
        out[i] = PARAMS[k];
        i += 1;
        k += 1;
    }
    k = 0;
    while k < DISCRETE_PARAMS.len() {
        out[i] = DISCRETE_PARAMS[k];
        i += 1;
        k += 1;
    }
    k = 0;
    while k < INPUTS.len() {
        out[i] = INPUTS[k];
        i += 1;
        k += 1;
    }
    k = 0;
    while k < VARIATOR_OUTPUTS.len() {
        out[i] = VARIATOR_OUTPUTS[k];
        i += 1;
        k += 1;
    }
    k = 0;
    while k < N_CONTACT_OUTPUTS {
        out[i] = CONTACT_IN[k];
        i += 1;
        k += 1;
    }
    k = 0;
    while k < N_CONTACT_OUTPUTS {
        out[i] = CONTACT_OUT[k];
        i += 1;
        k += 1;
    }
    k = 0;
    while k < REGIMES.len() {
        out[i] = REGIMES[k];
        i += 1;
        k += 1;
    }
    out
}

/// Every variable, in modelDescription order.
pub const VARIABLES: &[Variable] = &all();

/// Looks a variable up by value reference.
pub fn by_vr(vr: u32) -> Option<&'static Variable> {
    VARIABLES.iter().find(|v| v.vr == vr)
}

/// Index of a Real output in the output array.
pub fn output_index(r: u32) -> Option<usize> {
    let i = r.checked_sub(vr::TORQUE_IN)? as usize;
    (i < N_REAL_OUTPUTS).then_some(i)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn value_references_and_names_are_unique_and_ordered() {
        for (i, v) in VARIABLES.iter().enumerate() {
            for w in &VARIABLES[i + 1..] {
                assert_ne!(v.vr, w.vr, "{} and {}", v.name, w.name);
                assert_ne!(v.name, w.name);
            }
        }
        for (i, v) in PARAMS.iter().enumerate() {
            assert_eq!(v.vr as usize, i + 1);
        }
        for (i, v) in INPUTS.iter().enumerate() {
            assert_eq!(v.vr, vr::OMEGA_IN + i as u32);
        }
        let outs: Vec<_> = VARIATOR_OUTPUTS
            .iter()
            .chain(&CONTACT_IN)
            .chain(&CONTACT_OUT)
            .collect();
        for (i, v) in outs.iter().enumerate() {
            assert_eq!(output_index(v.vr), Some(i), "{}", v.name);
        }
        assert!(vr::REGIME_IN as usize > vr::TORQUE_IN as usize + N_REAL_OUTPUTS);
    }

    #[test]
    fn contact_outputs_follow_the_stem_table() {
        for (k, (stem, unit, _)) in CONTACT_OUTPUTS.iter().enumerate() {
            for (side, table) in [("in", &CONTACT_IN), ("out", &CONTACT_OUT)] {
                assert_eq!(table[k].name, format!("{stem}_{side}"));
                assert_eq!(table[k].kind, Kind::Real { unit, start: None });
            }
        }
    }

    #[test]
    fn every_unit_and_declared_type_exists() {
        for v in VARIABLES {
            match v.kind {
                Kind::Real { unit, .. } => assert!(UNITS.iter().any(|u| u.name == unit), "{unit}"),
                Kind::Enumeration { declared, .. } => {
                    assert!(ENUM_TYPES.iter().any(|t| t.0 == declared))
                }
                _ => {}
            }
        }
    }
}
