//! Units and SimpleTypes of the interface (UnitDefinitions, TypeDefinitions).

pub use traction_fmi_support::xml::{EnumItem, EnumType, RealType, Unit};

/// Units of the interface: name, exponents of `[kg, m, s, A, K, mol, cd, rad]`, offset.
pub const UNITS: &[Unit] = &[
    Unit::new("N", [1, 1, -2, 0, 0, 0, 0, 0], 0.0),
    Unit::new("N.m", [1, 2, -2, 0, 0, 0, 0, 0], 0.0),
    Unit::new("m", [0, 1, 0, 0, 0, 0, 0, 0], 0.0),
    Unit::new("Pa", [1, -1, -2, 0, 0, 0, 0, 0], 0.0),
    Unit::new("m/s", [0, 1, -1, 0, 0, 0, 0, 0], 0.0),
    Unit::new("rad", [0, 0, 0, 0, 0, 0, 0, 1], 0.0),
    Unit::new("rad/s", [0, 0, -1, 0, 0, 0, 0, 1], 0.0),
    Unit::new("W", [1, 2, -3, 0, 0, 0, 0, 0], 0.0),
    Unit::new("degC", [0, 0, 0, 0, 1, 0, 0, 0], 273.15),
    Unit::new("K", [0, 0, 0, 0, 1, 0, 0, 0], 0.0),
    Unit::new("W/(m.K)", [1, 1, -3, 0, -1, 0, 0, 0], 0.0),
    Unit::new("1/K", [0, 0, 0, 0, -1, 0, 0, 0], 0.0),
    Unit::new("1", [0; 8], 0.0),
];

/// Real SimpleTypes: name, quantity, unit.
pub const REAL_TYPES: &[RealType] = &[
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
