//! Units and SimpleTypes of the interface (UnitDefinitions, TypeDefinitions).

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
        name: "K",
        exponents: [0, 0, 0, 0, 1, 0, 0, 0],
        offset: 0.0,
    },
    Unit {
        name: "W/(m.K)",
        exponents: [1, 1, -3, 0, -1, 0, 0, 0],
        offset: 0.0,
    },
    Unit {
        name: "1/K",
        exponents: [0, 0, 0, 0, -1, 0, 0, 0],
        offset: 0.0,
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
    ("TemperatureDifference", "TemperatureDifference", "K"),
    ("ThermalConductivity", "ThermalConductivity", "W/(m.K)"),
    ("TemperatureCoefficient", "TemperatureCoefficient", "1/K"),
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
