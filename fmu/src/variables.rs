//! The variable table: the single source of the FMU's interface.
//!
//! modelDescription.xml ([`crate::model_description`]) and the instance code
//! ([`crate::model`]) both read this table, so the XML cannot drift from what
//! the binary does. Value references are unique across all types.

/// FMI 2 causality.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Causality {
    /// `parameter`.
    Parameter,
    /// `input`.
    Input,
    /// `output`.
    Output,
}

/// FMI 2 variability.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Variability {
    /// `fixed`: set before initialization ends, constant afterwards.
    Fixed,
    /// `discrete`: changes only at communication points (Integer, Enumeration).
    Discrete,
    /// `continuous` (Real only).
    Continuous,
}

/// Type and start value of a variable.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kind {
    /// `Real` with its `declaredType` (a SimpleType of [`REAL_TYPES`]) and start.
    Real {
        /// Name of the declared type.
        declared: &'static str,
        /// Start value (inputs and parameters).
        start: Option<f64>,
        /// Minimum, if bounded.
        min: Option<f64>,
        /// Maximum, if bounded.
        max: Option<f64>,
    },
    /// `Enumeration` of a declared type of [`ENUM_TYPES`].
    Enumeration {
        /// Name of the declared type.
        declared: &'static str,
        /// Start value (parameters).
        start: Option<i32>,
    },
    /// `Boolean`.
    Boolean {
        /// Start value (parameters).
        start: Option<bool>,
    },
}

/// Which inputs an output depends on (ModelStructure).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Depends {
    /// Not an output.
    None,
    /// The normal load only (contact size and pressure).
    Load,
    /// Every input (forces, J groups, ...).
    AllInputs,
    /// Every input except the inlet temperature (kinematic outputs).
    Kinematic,
}

/// One row of the table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Variable {
    /// Structured name.
    pub name: &'static str,
    /// Value reference.
    pub vr: u32,
    /// Causality.
    pub causality: Causality,
    /// Variability.
    pub variability: Variability,
    /// Type, declared type and start value.
    pub kind: Kind,
    /// Description with the unit spelled out for humans.
    pub description: &'static str,
    /// Dependencies of outputs.
    pub depends: Depends,
}

/// A unit of UnitDefinitions: name, SI base-unit exponents
/// `[kg, m, s, A, K, mol, cd, rad]` and offset.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unit {
    /// Unit name as used in `unit=`.
    pub name: &'static str,
    /// Exponents of kg, m, s, A, K, mol, cd, rad.
    pub exponents: [i32; 8],
    /// Offset to the SI base unit (degC: 273.15).
    pub offset: f64,
}

/// Units of the interface.
pub const UNITS: &[Unit] = &[
    Unit {
        name: "N",
        exponents: [1, 1, -2, 0, 0, 0, 0, 0],
        offset: 0.0,
    },
    Unit {
        name: "N.m",
        exponents: [1, 2, -2, 0, 0, 0, 0, 0],
        offset: 0.0,
    },
    Unit {
        name: "m",
        exponents: [0, 1, 0, 0, 0, 0, 0, 0],
        offset: 0.0,
    },
    Unit {
        name: "Pa",
        exponents: [1, -1, -2, 0, 0, 0, 0, 0],
        offset: 0.0,
    },
    Unit {
        name: "m/s",
        exponents: [0, 1, -1, 0, 0, 0, 0, 0],
        offset: 0.0,
    },
    Unit {
        name: "rad",
        exponents: [0, 0, 0, 0, 0, 0, 0, 1],
        offset: 0.0,
    },
    Unit {
        name: "rad/s",
        exponents: [0, 0, -1, 0, 0, 0, 0, 1],
        offset: 0.0,
    },
    Unit {
        name: "W",
        exponents: [1, 2, -3, 0, 0, 0, 0, 0],
        offset: 0.0,
    },
    Unit {
        name: "degC",
        exponents: [0, 0, 0, 0, 1, 0, 0, 0],
        offset: 273.15,
    },
    Unit {
        name: "1",
        exponents: [0; 8],
        offset: 0.0,
    },
];

/// Real SimpleTypes: name, quantity, unit.
pub const REAL_TYPES: &[(&str, &str, &str)] = &[
    ("Force", "Force", "N"),
    ("Torque", "Torque", "N.m"),
    ("Length", "Length", "m"),
    ("Pressure", "Pressure", "Pa"),
    ("Velocity", "Velocity", "m/s"),
    ("Angle", "Angle", "rad"),
    ("AngularVelocity", "AngularVelocity", "rad/s"),
    ("Power", "Power", "W"),
    ("Temperature", "ThermodynamicTemperature", "degC"),
    ("Dimensionless", "Dimensionless", "1"),
];

/// An enumeration item: name, value, description.
pub type EnumItem = (&'static str, i32, &'static str);
/// An enumeration SimpleType: name, description, items.
pub type EnumType = (&'static str, &'static str, &'static [EnumItem]);

/// Enumeration SimpleTypes of the interface.
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
        "RheologyModel",
        "Rheological model of the film",
        &[
            ("elastic_plastic", 1, "Johnson & Tevaarwerk elastic/plastic"),
            ("rigid_plastic", 2, "rigid/plastic"),
            (
                "viscoelastic",
                3,
                "viscoelastic sinh law with the limit as a cap (parameters deborah, z0)",
            ),
        ],
    ),
    (
        "SpinSource",
        "Where the spin comes from",
        &[
            ("input", 1, "the input spin"),
            (
                "tilt_geometry",
                2,
                "tilted toroid: omega/U = sin(alpha)/(ry1 cos(alpha) + e), report eq. 6",
            ),
        ],
    ),
    (
        "SideSlipSource",
        "How the side slip is given",
        &[
            ("velocity", 1, "the input side_slip_velocity"),
            (
                "skew_angle",
                2,
                "the input skew_angle: dV = U tan(beta), report eq. 3",
            ),
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
                "evaluate the correlation outside the data (warning logged)",
            ),
            (
                "clamp",
                3,
                "evaluate at the nearest point of the data envelope (warning logged)",
            ),
        ],
    ),
    (
        "Regime",
        "Regime of Appendix IV figure 14",
        &[
            ("open", 0, "normal load <= 0: no contact"),
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

const fn par(
    name: &'static str,
    vr: u32,
    declared: &'static str,
    start: f64,
    description: &'static str,
) -> Variable {
    Variable {
        name,
        vr,
        causality: Causality::Parameter,
        variability: Variability::Fixed,
        kind: Kind::Real {
            declared,
            start: Some(start),
            min: None,
            max: None,
        },
        description,
        depends: Depends::None,
    }
}

const fn par_bounded(
    name: &'static str,
    vr: u32,
    declared: &'static str,
    start: f64,
    min: f64,
    max: f64,
    description: &'static str,
) -> Variable {
    Variable {
        name,
        vr,
        causality: Causality::Parameter,
        variability: Variability::Fixed,
        kind: Kind::Real {
            declared,
            start: Some(start),
            min: Some(min),
            max: Some(max),
        },
        description,
        depends: Depends::None,
    }
}

const fn input(
    name: &'static str,
    vr: u32,
    declared: &'static str,
    start: f64,
    description: &'static str,
) -> Variable {
    Variable {
        name,
        vr,
        causality: Causality::Input,
        variability: Variability::Continuous,
        kind: Kind::Real {
            declared,
            start: Some(start),
            min: None,
            max: None,
        },
        description,
        depends: Depends::None,
    }
}

const fn output(
    name: &'static str,
    vr: u32,
    declared: &'static str,
    depends: Depends,
    description: &'static str,
) -> Variable {
    Variable {
        name,
        vr,
        causality: Causality::Output,
        variability: Variability::Continuous,
        kind: Kind::Real {
            declared,
            start: None,
            min: None,
            max: None,
        },
        description,
        depends,
    }
}

/// Value references (stable; the table below uses them).
#[allow(missing_docs)]
pub mod vr {
    // Real parameters 1..
    pub const RX1: u32 = 1;
    pub const RY1: u32 = 2;
    pub const RX2: u32 = 3;
    pub const RY2: u32 = 4;
    pub const E1: u32 = 5;
    pub const NU1: u32 = 6;
    pub const E2: u32 = 7;
    pub const NU2: u32 = 8;
    pub const ROLLING_RADIUS1: u32 = 9;
    pub const ROLLING_RADIUS2: u32 = 10;
    pub const M_USER: u32 = 11;
    pub const MU_USER: u32 = 12;
    pub const TILT_ANGLE: u32 = 13;
    pub const TILT_OFFSET: u32 = 14;
    pub const U_REG: u32 = 15;
    pub const DEBORAH: u32 = 16;
    pub const Z0: u32 = 17;
    pub const MU_SPIN_USER: u32 = 18;
    pub const RHEOLOGY_TOLERANCE: u32 = 19;
    // Real inputs 100..
    pub const LOAD: u32 = 100;
    pub const OMEGA1: u32 = 101;
    pub const OMEGA2: u32 = 102;
    pub const SIDE_SLIP_VELOCITY: u32 = 103;
    pub const SKEW_ANGLE: u32 = 104;
    pub const SPIN: u32 = 105;
    pub const INLET_TEMPERATURE: u32 = 106;
    // Real outputs 200..
    pub const FX: u32 = 200;
    pub const FY: u32 = 201;
    pub const MZ: u32 = 202;
    pub const TORQUE1: u32 = 203;
    pub const TORQUE2: u32 = 204;
    pub const TRACTION_COEFFICIENT: u32 = 205;
    pub const SIDE_TRACTION_COEFFICIENT: u32 = 206;
    pub const POWER_LOSS: u32 = 207;
    pub const A: u32 = 208;
    pub const B: u32 = 209;
    pub const K: u32 = 210;
    pub const P0: u32 = 211;
    pub const U: u32 = 212;
    pub const DU: u32 = 213;
    pub const DV: u32 = 214;
    pub const OMEGA: u32 = 215;
    pub const M_USED: u32 = 216;
    pub const MU_USED: u32 = 217;
    pub const MU_FORCE: u32 = 218;
    pub const J1: u32 = 221; // J1..J7 = 221..227
    pub const J7: u32 = 227;
    // Enumerations and Booleans 300..
    pub const FLUID: u32 = 300;
    pub const RHEOLOGY: u32 = 301;
    pub const SPIN_SOURCE: u32 = 302;
    pub const SIDE_SLIP_SOURCE: u32 = 303;
    pub const COMPLIANCE: u32 = 304;
    pub const ENVELOPE: u32 = 305;
    pub const SPIN_PEAK: u32 = 306;
    pub const RHEOLOGY_MAP: u32 = 307;
    pub const REGIME: u32 = 310;
}

/// Number of Real parameters (VR 1..=N_REAL_PARAMS).
pub const N_REAL_PARAMS: usize = 19;
/// Number of Real inputs (VR 100..).
pub const N_INPUTS: usize = 7;
/// Number of Real outputs (VR 200..=218 and 221..=227).
pub const N_REAL_OUTPUTS: usize = 26;

/// The table, in the order of ModelVariables (indices are 1-based there).
pub const VARIABLES: &[Variable] = &[
    par(
        "rx1",
        vr::RX1,
        "Length",
        0.033,
        "Body 1 (driving body, tilted toroid for spin) radius of curvature in the rolling direction x, m; 0 = flat, negative = concave",
    ),
    par(
        "ry1",
        vr::RY1,
        "Length",
        0.0226,
        "Body 1 radius of curvature across the rolling direction (y), m; 0 = flat, negative = concave",
    ),
    par(
        "rx2",
        vr::RX2,
        "Length",
        0.0714,
        "Body 2 (driven body) radius of curvature in the rolling direction x, m; 0 = flat, negative = concave",
    ),
    par(
        "ry2",
        vr::RY2,
        "Length",
        0.0,
        "Body 2 radius of curvature across the rolling direction (y), m; 0 = flat, negative = concave",
    ),
    par_bounded(
        "e1",
        vr::E1,
        "Pressure",
        2.07e11,
        1e6,
        1e13,
        "Young's modulus of body 1, Pa",
    ),
    par_bounded(
        "nu1",
        vr::NU1,
        "Dimensionless",
        0.3,
        -0.999,
        0.499,
        "Poisson's ratio of body 1",
    ),
    par_bounded(
        "e2",
        vr::E2,
        "Pressure",
        2.07e11,
        1e6,
        1e13,
        "Young's modulus of body 2, Pa",
    ),
    par_bounded(
        "nu2",
        vr::NU2,
        "Dimensionless",
        0.3,
        -0.999,
        0.499,
        "Poisson's ratio of body 2",
    ),
    par(
        "rolling_radius1",
        vr::ROLLING_RADIUS1,
        "Length",
        0.033,
        "Distance from the axis of body 1 to the contact: surface speed u1 = omega1*rolling_radius1, torque1 = -fx*rolling_radius1, m",
    ),
    par(
        "rolling_radius2",
        vr::ROLLING_RADIUS2,
        "Length",
        0.0714,
        "Distance from the axis of body 2 to the contact: u2 = omega2*rolling_radius2, torque2 = fx*rolling_radius2, m",
    ),
    par_bounded(
        "m_user",
        vr::M_USER,
        "Dimensionless",
        35.0,
        1e-6,
        1e6,
        "Initial traction slope m (d(F/N)/d(dU/U) at zero slip), used when fluid = user",
    ),
    par_bounded(
        "mu_user",
        vr::MU_USER,
        "Dimensionless",
        0.075,
        1e-6,
        0.999,
        "Peak traction coefficient mu, used when fluid = user",
    ),
    par(
        "spin_tilt_angle",
        vr::TILT_ANGLE,
        "Angle",
        0.0,
        "Tilt (spin) angle alpha of body 1 for spin_source = tilt_geometry (report eq. 6), rad",
    ),
    par(
        "spin_center_offset",
        vr::TILT_OFFSET,
        "Length",
        0.0,
        "Offset e of the centre of ry1 from the axis of body 1 for spin_source = tilt_geometry (report eq. 6, Table 2-4), m",
    ),
    par_bounded(
        "rolling_speed_regularisation",
        vr::U_REG,
        "Velocity",
        0.01,
        1e-9,
        1e3,
        "U_reg: the J groups use max(|U|, U_reg) so that forces stay finite and continuous through zero rolling speed, m/s",
    ),
    par(
        "deborah",
        vr::DEBORAH,
        "Dimensionless",
        1.0,
        "Deborah number D = eta U/(G a) of the viscoelastic model (rheology_model = viscoelastic, report App. V eqs. 3-6); valid range D > 0, inf allowed (= the elastic/plastic model); a constant: it does not follow U or a during the simulation",
    ),
    par(
        "z0",
        vr::Z0,
        "Dimensionless",
        1.0,
        "Sinh reference stress Z0 = tau0/tau_bar of the viscoelastic model (rheology_model = viscoelastic, report App. V eq. 3), tau_bar = mu N/(pi a b); valid range Z0 > 0, inf allowed (= the linear Maxwell fluid)",
    ),
    par_bounded(
        "mu_spin_user",
        vr::MU_SPIN_USER,
        "Dimensionless",
        0.075,
        1e-6,
        0.999,
        "Spin-peak traction coefficient mu_s, used when fluid = user and use_spin_peak = true: forces = mu_s N J, the J groups keep mu_user (report App. VI, J5*MS); valid range (0, 1)",
    ),
    par_bounded(
        "rheology_tolerance",
        vr::RHEOLOGY_TOLERANCE,
        "Dimensionless",
        1e-4,
        1e-6,
        1e-2,
        "Absolute accuracy of the J+T solution in J4, J5, J6 (all rheology models; with rheology_map the interpolation is checked to it too); valid range [1e-6, 1e-2]",
    ),
    input(
        "normal_load",
        vr::LOAD,
        "Force",
        500.0,
        "Normal load pressing the bodies together, N; <= 0 opens the contact (zero forces)",
    ),
    input(
        "omega1",
        vr::OMEGA1,
        "AngularVelocity",
        0.0,
        "Angular speed of body 1, positive when its surface moves in +x at the contact, rad/s",
    ),
    input(
        "omega2",
        vr::OMEGA2,
        "AngularVelocity",
        0.0,
        "Angular speed of body 2, positive when its surface moves in +x at the contact, rad/s",
    ),
    input(
        "side_slip_velocity",
        vr::SIDE_SLIP_VELOCITY,
        "Velocity",
        0.0,
        "Side slip velocity dV of body 1 relative to body 2 (side_slip_source = velocity), m/s",
    ),
    input(
        "skew_angle",
        vr::SKEW_ANGLE,
        "Angle",
        0.0,
        "Skew angle beta, dV = U tan(beta) (side_slip_source = skew_angle), rad",
    ),
    input(
        "spin",
        vr::SPIN,
        "AngularVelocity",
        0.0,
        "Spin omega about the contact normal (spin_source = input), rad/s",
    ),
    input(
        "inlet_temperature",
        vr::INLET_TEMPERATURE,
        "Temperature",
        40.0,
        "Fluid inlet temperature, degC",
    ),
    output(
        "fx",
        vr::FX,
        "Force",
        Depends::AllInputs,
        "Traction force along the rolling direction on body 2 (from body 1), N",
    ),
    output(
        "fy",
        vr::FY,
        "Force",
        Depends::AllInputs,
        "Traction force across the rolling direction on body 2 (from body 1), N",
    ),
    output(
        "mz",
        vr::MZ,
        "Torque",
        Depends::AllInputs,
        "Spin moment about the contact normal on body 2, N.m",
    ),
    output(
        "torque1",
        vr::TORQUE1,
        "Torque",
        Depends::AllInputs,
        "Torque of the contact on body 1 about its axis, positive in the sense of omega1: -fx*rolling_radius1, N.m",
    ),
    output(
        "torque2",
        vr::TORQUE2,
        "Torque",
        Depends::AllInputs,
        "Torque of the contact on body 2 about its axis, positive in the sense of omega2: fx*rolling_radius2, N.m",
    ),
    output(
        "traction_coefficient",
        vr::TRACTION_COEFFICIENT,
        "Dimensionless",
        Depends::AllInputs,
        "Traction coefficient fx/normal_load (0 when the contact is open)",
    ),
    output(
        "side_traction_coefficient",
        vr::SIDE_TRACTION_COEFFICIENT,
        "Dimensionless",
        Depends::AllInputs,
        "Side traction coefficient fy/normal_load (0 when the contact is open)",
    ),
    output(
        "power_loss",
        vr::POWER_LOSS,
        "Power",
        Depends::AllInputs,
        "Power dissipated in the contact fx*dU + fy*dV + mz*omega, W",
    ),
    output(
        "a",
        vr::A,
        "Length",
        Depends::Load,
        "Hertz semi-axis along the rolling direction, m",
    ),
    output(
        "b",
        vr::B,
        "Length",
        Depends::Load,
        "Hertz semi-axis across the rolling direction, m",
    ),
    output(
        "k",
        vr::K,
        "Dimensionless",
        Depends::Load,
        "Aspect ratio k = b/a",
    ),
    output(
        "p0",
        vr::P0,
        "Pressure",
        Depends::Load,
        "Maximum Hertz pressure P0, Pa",
    ),
    output(
        "rolling_speed",
        vr::U,
        "Velocity",
        Depends::Kinematic,
        "Rolling speed U = (u1 + u2)/2, m/s",
    ),
    output(
        "slip_velocity",
        vr::DU,
        "Velocity",
        Depends::Kinematic,
        "Slip velocity dU = u1 - u2, m/s",
    ),
    output(
        "side_slip",
        vr::DV,
        "Velocity",
        Depends::Kinematic,
        "Side slip velocity dV used, m/s",
    ),
    output(
        "spin_used",
        vr::OMEGA,
        "AngularVelocity",
        Depends::Kinematic,
        "Spin omega used, rad/s",
    ),
    output(
        "m",
        vr::M_USED,
        "Dimensionless",
        Depends::AllInputs,
        "Initial traction slope m used",
    ),
    output(
        "mu",
        vr::MU_USED,
        "Dimensionless",
        Depends::AllInputs,
        "Zero-spin peak traction coefficient mu used in the J groups",
    ),
    output(
        "mu_force",
        vr::MU_FORCE,
        "Dimensionless",
        Depends::AllInputs,
        "Traction coefficient mu_f that scales the forces: mu, or the spin-peak mu_s when use_spin_peak = true (J4 = fx/(mu_f N))",
    ),
    output(
        "J1",
        vr::J1,
        "Dimensionless",
        Depends::AllInputs,
        "J1, dimensionless slip (3 pi/8)(m/mu)(dU/U)sqrt(k)",
    ),
    output(
        "J2",
        vr::J1 + 1,
        "Dimensionless",
        Depends::AllInputs,
        "J2, dimensionless side slip (3 pi/8)(m/mu)(dV/U)sqrt(k)",
    ),
    output(
        "J3",
        vr::J1 + 2,
        "Dimensionless",
        Depends::AllInputs,
        "J3, dimensionless spin (3 pi/8)(m/mu)(omega sqrt(ab)/U)sqrt(k)",
    ),
    output(
        "J4",
        vr::J1 + 3,
        "Dimensionless",
        Depends::AllInputs,
        "J4, dimensionless traction along x, fx/(mu_f N)",
    ),
    output(
        "J5",
        vr::J1 + 4,
        "Dimensionless",
        Depends::AllInputs,
        "J5, dimensionless traction across, fy/(mu_f N)",
    ),
    output(
        "J6",
        vr::J1 + 5,
        "Dimensionless",
        Depends::AllInputs,
        "J6, dimensionless spin moment mz/(mu_f N sqrt(ab))",
    ),
    output(
        "J7",
        vr::J7,
        "Dimensionless",
        Depends::AllInputs,
        "J7 = J1 J4 + J2 J5 + J3 J6, dimensionless losses",
    ),
    Variable {
        name: "fluid",
        vr: vr::FLUID,
        causality: Causality::Parameter,
        variability: Variability::Fixed,
        kind: Kind::Enumeration {
            declared: "Fluid",
            start: Some(3),
        },
        description: "Traction fluid: 1 Santotrac 50, 2 TDF-88 (report correlations), 3 user m and mu",
        depends: Depends::None,
    },
    Variable {
        name: "fluid_envelope",
        vr: vr::ENVELOPE,
        causality: Causality::Parameter,
        variability: Variability::Fixed,
        kind: Kind::Enumeration {
            declared: "EnvelopeRule",
            start: Some(3),
        },
        description: "Outside the data of the report fluids' correlations: 1 error, 2 extrapolate, 3 clamp to the data envelope (default: start-up through U = 0 stays evaluable)",
        depends: Depends::None,
    },
    Variable {
        name: "rheology_model",
        vr: vr::RHEOLOGY,
        causality: Causality::Parameter,
        variability: Variability::Fixed,
        kind: Kind::Enumeration {
            declared: "RheologyModel",
            start: Some(1),
        },
        description: "Rheological model: 1 elastic/plastic, 2 rigid/plastic, 3 viscoelastic (deborah, z0)",
        depends: Depends::None,
    },
    Variable {
        name: "spin_source",
        vr: vr::SPIN_SOURCE,
        causality: Causality::Parameter,
        variability: Variability::Fixed,
        kind: Kind::Enumeration {
            declared: "SpinSource",
            start: Some(1),
        },
        description: "Spin source: 1 the input spin, 2 the tilt geometry (spin_tilt_angle, spin_center_offset, ry1)",
        depends: Depends::None,
    },
    Variable {
        name: "side_slip_source",
        vr: vr::SIDE_SLIP_SOURCE,
        causality: Causality::Parameter,
        variability: Variability::Fixed,
        kind: Kind::Enumeration {
            declared: "SideSlipSource",
            start: Some(1),
        },
        description: "Side slip source: 1 the input side_slip_velocity, 2 the input skew_angle",
        depends: Depends::None,
    },
    Variable {
        name: "compliance_correction",
        vr: vr::COMPLIANCE,
        causality: Causality::Parameter,
        variability: Variability::Fixed,
        kind: Kind::Boolean { start: Some(false) },
        description: "Correct the traction slope for disc compliance (report Appendix IV A, B); both discs elastic with Kalker's combined constants of body 1 and body 2 (1/G = (1/G1 + 1/G2)/2, nu/G = (nu1/G1 + nu2/G2)/2); m is taken as measured in side slip; the J+T model then uses the direction-dependent stiffness ratio Gy/Gx = m_y/m_x",
        depends: Depends::None,
    },
    Variable {
        name: "use_spin_peak",
        vr: vr::SPIN_PEAK,
        causality: Causality::Parameter,
        variability: Variability::Fixed,
        kind: Kind::Boolean { start: Some(false) },
        description: "Scale the forces by the spin-peak traction coefficient mu_s instead of mu (the J groups keep mu): fluid = user: mu_spin_user; report fluids: their spin-peak correlation mu_s(P0, U, inlet temperature, k, |Z|) (Appendix III-E, III-F)",
        depends: Depends::None,
    },
    Variable {
        name: "rheology_map",
        vr: vr::RHEOLOGY_MAP,
        causality: Causality::Parameter,
        variability: Variability::Fixed,
        kind: Kind::Boolean { start: Some(false) },
        description: "Evaluate the elastic/plastic J+T model (and the rigid/plastic one of the regime) through an interpolation map built lazily per instance: every map cell is checked against the direct solution to rheology_tolerance/4 before use and refined where the model is not smooth; ~1 us per step once a region of operating states has been visited, up to tens of ms when a new region is first entered; results depend only on the inputs. Used when rheology_model = elastic/plastic, rheology_tolerance >= 1e-4 and (for the elastic/plastic part) compliance_correction = false; false: the strips are integrated at every step (10-700 us with spin)",
        depends: Depends::None,
    },
    Variable {
        name: "regime",
        vr: vr::REGIME,
        causality: Causality::Output,
        variability: Variability::Discrete,
        kind: Kind::Enumeration {
            declared: "Regime",
            start: None,
        },
        description: "Regime of Appendix IV figure 14: 0 open, 1 elastic without spin, 2 elastic with spin, 3 rigid/plastic",
        depends: Depends::AllInputs,
    },
];

/// Looks a variable up by value reference.
pub fn by_vr(vr: u32) -> Option<&'static Variable> {
    VARIABLES.iter().find(|v| v.vr == vr)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn value_references_and_names_are_unique() {
        for (i, v) in VARIABLES.iter().enumerate() {
            for w in &VARIABLES[i + 1..] {
                assert_ne!(v.vr, w.vr, "{} and {}", v.name, w.name);
                assert_ne!(v.name, w.name);
            }
        }
    }

    #[test]
    fn counts_match_the_table() {
        let count = |c: Causality| {
            VARIABLES
                .iter()
                .filter(|v| v.causality == c && matches!(v.kind, Kind::Real { .. }))
                .count()
        };
        assert_eq!(count(Causality::Parameter), N_REAL_PARAMS);
        assert_eq!(count(Causality::Input), N_INPUTS);
        assert_eq!(count(Causality::Output), N_REAL_OUTPUTS);
    }

    #[test]
    fn every_declared_type_and_unit_exists() {
        for v in VARIABLES {
            match v.kind {
                Kind::Real { declared, .. } => {
                    assert!(REAL_TYPES.iter().any(|t| t.0 == declared), "{declared}")
                }
                Kind::Enumeration { declared, .. } => {
                    assert!(ENUM_TYPES.iter().any(|t| t.0 == declared))
                }
                Kind::Boolean { .. } => {}
            }
        }
        for t in REAL_TYPES {
            assert!(UNITS.iter().any(|u| u.name == t.2), "{}", t.2);
        }
    }
}
