//! The variable table: the single source of the FMU's interface.
//!
//! modelDescription.xml ([`crate::model_description`]) and the instance code
//! ([`crate::model`]) both read this table, so the XML cannot drift from what
//! the binary does. Value references are unique across all types. Where an
//! instance keeps a value ([`Slot`]: its causality, type and position among
//! the rows of the same causality and type) and how many values of each kind
//! it keeps ([`N_REAL_PARAMS`], ...) are derived from the table at compile
//! time.

mod table;
mod types;

pub use table::VARIABLES;
pub use types::{ENUM_TYPES, EnumItem, EnumType, REAL_TYPES, RealType, UNITS, Unit};

pub use traction_fmi_support::xml::{Causality, Variability};

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

/// Which knowns an output depends on (ModelStructure). The knowns are the
/// inputs and, in Initialization Mode (InitialUnknowns), also the parameters
/// (all have `initial="exact"`); [`Depends::on`] lists them by name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Depends {
    /// Not an output.
    None,
    /// The Hertz contact (a, b, k, P0): the normal load and the bodies'
    /// curvatures and elastic constants.
    Hertz,
    /// Rolling and slip speed: the angular speeds and the rolling radii.
    Speeds,
    /// The side slip used: the speeds, side slip velocity or skew angle.
    SideSlip,
    /// The spin used: the speeds, the input spin or the tilt geometry.
    Spin,
    /// Every input and every parameter (forces, J groups, ...).
    All,
}

impl Depends {
    /// Names of the knowns (inputs and parameters) this output depends on;
    /// `None` for [`Depends::All`] (every known).
    pub fn on(self) -> Option<&'static [&'static str]> {
        const SPEEDS: &[&str] = &["omega1", "omega2", "rolling_radius1", "rolling_radius2"];
        Some(match self {
            Depends::None => &[],
            Depends::Hertz => &[
                "normal_load",
                "rx1",
                "ry1",
                "rx2",
                "ry2",
                "e1",
                "nu1",
                "e2",
                "nu2",
            ],
            Depends::Speeds => SPEEDS,
            Depends::SideSlip => &[
                "omega1",
                "omega2",
                "rolling_radius1",
                "rolling_radius2",
                "side_slip_velocity",
                "skew_angle",
                "side_slip_source",
            ],
            Depends::Spin => &[
                "omega1",
                "omega2",
                "rolling_radius1",
                "rolling_radius2",
                "spin",
                "ry1",
                "spin_tilt_angle",
                "spin_center_offset",
                "spin_source",
            ],
            Depends::All => return None,
        })
    }

    /// Whether the output depends on `known` (an input or a parameter).
    pub fn includes(self, known: &Variable) -> bool {
        match self.on() {
            None => known.causality != Causality::Output,
            Some(names) => names.contains(&known.name),
        }
    }
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

/// Value references, one per row of [`crate::variables::VARIABLES`] (stable: hosts store
/// them). Blocks: Real parameters from 1, Real inputs from 100, Real outputs
/// from 200, Enumerations and Booleans from 300. Each constant names its
/// variable; [`crate::variables::VARIABLES`] holds its description, unit and range.
pub mod vr {
    // Real parameters 1..
    /// `rx1`.
    pub const RX1: u32 = 1;
    /// `ry1`.
    pub const RY1: u32 = 2;
    /// `rx2`.
    pub const RX2: u32 = 3;
    /// `ry2`.
    pub const RY2: u32 = 4;
    /// `e1`.
    pub const E1: u32 = 5;
    /// `nu1`.
    pub const NU1: u32 = 6;
    /// `e2`.
    pub const E2: u32 = 7;
    /// `nu2`.
    pub const NU2: u32 = 8;
    /// `rolling_radius1`.
    pub const ROLLING_RADIUS1: u32 = 9;
    /// `rolling_radius2`.
    pub const ROLLING_RADIUS2: u32 = 10;
    /// `m_user`.
    pub const M_USER: u32 = 11;
    /// `mu_user`.
    pub const MU_USER: u32 = 12;
    /// `spin_tilt_angle`.
    pub const TILT_ANGLE: u32 = 13;
    /// `spin_center_offset`.
    pub const TILT_OFFSET: u32 = 14;
    /// `rolling_speed_regularisation`.
    pub const U_REG: u32 = 15;
    /// `deborah`.
    pub const DEBORAH: u32 = 16;
    /// `z0`.
    pub const Z0: u32 = 17;
    /// `mu_spin_user`.
    pub const MU_SPIN_USER: u32 = 18;
    /// `rheology_tolerance`.
    pub const RHEOLOGY_TOLERANCE: u32 = 19;
    /// `film_thickness`.
    pub const FILM_THICKNESS: u32 = 20;
    /// `fluid_conductivity`.
    pub const FLUID_CONDUCTIVITY: u32 = 21;
    /// `mu_temperature_coefficient`.
    pub const MU_TEMPERATURE_COEFFICIENT: u32 = 22;
    /// `m_temperature_coefficient`.
    pub const M_TEMPERATURE_COEFFICIENT: u32 = 23;
    /// `mu_rise_scale`.
    pub const MU_RISE_SCALE: u32 = 24;
    // Real inputs 100..
    /// `normal_load`.
    pub const LOAD: u32 = 100;
    /// `omega1`.
    pub const OMEGA1: u32 = 101;
    /// `omega2`.
    pub const OMEGA2: u32 = 102;
    /// `side_slip_velocity`.
    pub const SIDE_SLIP_VELOCITY: u32 = 103;
    /// `skew_angle`.
    pub const SKEW_ANGLE: u32 = 104;
    /// `spin`.
    pub const SPIN: u32 = 105;
    /// `inlet_temperature`.
    pub const INLET_TEMPERATURE: u32 = 106;
    // Real outputs 200..
    /// `fx`.
    pub const FX: u32 = 200;
    /// `fy`.
    pub const FY: u32 = 201;
    /// `mz`.
    pub const MZ: u32 = 202;
    /// `torque1`.
    pub const TORQUE1: u32 = 203;
    /// `torque2`.
    pub const TORQUE2: u32 = 204;
    /// `traction_coefficient`.
    pub const TRACTION_COEFFICIENT: u32 = 205;
    /// `side_traction_coefficient`.
    pub const SIDE_TRACTION_COEFFICIENT: u32 = 206;
    /// `power_loss`.
    pub const POWER_LOSS: u32 = 207;
    /// `a`.
    pub const A: u32 = 208;
    /// `b`.
    pub const B: u32 = 209;
    /// `k`.
    pub const K: u32 = 210;
    /// `p0`.
    pub const P0: u32 = 211;
    /// `rolling_speed`.
    pub const U: u32 = 212;
    /// `slip_velocity`.
    pub const DU: u32 = 213;
    /// `side_slip`.
    pub const DV: u32 = 214;
    /// `spin_used`.
    pub const OMEGA: u32 = 215;
    /// `m`.
    pub const M_USED: u32 = 216;
    /// `mu`.
    pub const MU_USED: u32 = 217;
    /// `mu_force`.
    pub const MU_FORCE: u32 = 218;
    /// `temperature_rise`.
    pub const TEMPERATURE_RISE: u32 = 219;
    /// `J1`.
    pub const J1: u32 = 221;
    /// `J2`.
    pub const J2: u32 = 222;
    /// `J3`.
    pub const J3: u32 = 223;
    /// `J4`.
    pub const J4: u32 = 224;
    /// `J5`.
    pub const J5: u32 = 225;
    /// `J6`.
    pub const J6: u32 = 226;
    /// `J7`.
    pub const J7: u32 = 227;
    // Enumerations and Booleans 300..
    /// `fluid`.
    pub const FLUID: u32 = 300;
    /// `rheology_model`.
    pub const RHEOLOGY: u32 = 301;
    /// `spin_source`.
    pub const SPIN_SOURCE: u32 = 302;
    /// `side_slip_source`.
    pub const SIDE_SLIP_SOURCE: u32 = 303;
    /// `compliance_correction`.
    pub const COMPLIANCE: u32 = 304;
    /// `fluid_envelope`.
    pub const ENVELOPE: u32 = 305;
    /// `use_spin_peak`.
    pub const SPIN_PEAK: u32 = 306;
    /// `rheology_map`.
    pub const RHEOLOGY_MAP: u32 = 307;
    /// `thermal`.
    pub const THERMAL: u32 = 308;
    /// `regime`.
    pub const REGIME: u32 = 310;
}

/// The value type of a variable (without its declared type and start).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Type {
    /// `Real`.
    Real,
    /// `Enumeration`.
    Enumeration,
    /// `Boolean`.
    Boolean,
}

impl Kind {
    /// The value type.
    pub const fn value_type(&self) -> Type {
        match self {
            Kind::Real { .. } => Type::Real,
            Kind::Enumeration { .. } => Type::Enumeration,
            Kind::Boolean { .. } => Type::Boolean,
        }
    }
}

/// Where an instance keeps a variable's value: the variables of one
/// causality and type are stored in an array in table order, `index` is the
/// position in it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Slot {
    /// Causality of the variable.
    pub causality: Causality,
    /// Value type of the variable.
    pub value_type: Type,
    /// Position among the rows of the same causality and type.
    pub index: usize,
}

const fn same_class(v: &Variable, causality: Causality, value_type: Type) -> bool {
    v.causality as u8 == causality as u8 && v.kind.value_type() as u8 == value_type as u8
}

/// Number of rows of a causality and value type.
pub const fn count(causality: Causality, value_type: Type) -> usize {
    let mut n = 0;
    let mut i = 0;
    while i < VARIABLES.len() {
        if same_class(&VARIABLES[i], causality, value_type) {
            n += 1;
        }
        i += 1;
    }
    n
}

/// Row of a value reference in [`VARIABLES`] (compile-time use).
///
/// # Panics
/// If no row has this value reference (a compile error in a constant).
pub const fn row(vr: u32) -> usize {
    let mut i = 0;
    while i < VARIABLES.len() {
        if VARIABLES[i].vr == vr {
            return i;
        }
        i += 1;
    }
    panic!("no variable has this value reference")
}

const fn slot_of_row(r: usize) -> Slot {
    let v = &VARIABLES[r];
    let mut index = 0;
    let mut i = 0;
    while i < r {
        if same_class(&VARIABLES[i], v.causality, v.kind.value_type()) {
            index += 1;
        }
        i += 1;
    }
    Slot {
        causality: v.causality,
        value_type: v.kind.value_type(),
        index,
    }
}

/// Position of a variable of the given causality and type in its array
/// (compile-time use: `const { index(vr::RX1, Causality::Parameter, Type::Real) }`).
///
/// # Panics
/// If the variable does not exist or has another causality or type (a
/// compile error in a constant).
pub const fn index(vr: u32, causality: Causality, value_type: Type) -> usize {
    let r = row(vr);
    if !same_class(&VARIABLES[r], causality, value_type) {
        panic!("the variable has another causality or type");
    }
    slot_of_row(r).index
}

/// One past the largest value reference.
const VR_END: usize = {
    let mut end = 0;
    let mut i = 0;
    while i < VARIABLES.len() {
        if VARIABLES[i].vr as usize + 1 > end {
            end = VARIABLES[i].vr as usize + 1;
        }
        i += 1;
    }
    end
};

/// Slots by value reference, built at compile time.
const SLOTS: [Option<Slot>; VR_END] = {
    let mut slots = [None; VR_END];
    let mut r = 0;
    while r < VARIABLES.len() {
        slots[VARIABLES[r].vr as usize] = Some(slot_of_row(r));
        r += 1;
    }
    slots
};

/// Rows by value reference, built at compile time.
const ROWS: [Option<usize>; VR_END] = {
    let mut rows = [None; VR_END];
    let mut r = 0;
    while r < VARIABLES.len() {
        rows[VARIABLES[r].vr as usize] = Some(r);
        r += 1;
    }
    rows
};

/// Where an instance keeps the variable `vr` (None: not a variable).
pub fn slot(vr: u32) -> Option<Slot> {
    SLOTS.get(vr as usize).copied().flatten()
}

/// Looks a variable up by value reference.
pub fn by_vr(vr: u32) -> Option<&'static Variable> {
    ROWS.get(vr as usize)
        .copied()
        .flatten()
        .map(|r| &VARIABLES[r])
}

/// Number of Real parameters.
pub const N_REAL_PARAMS: usize = count(Causality::Parameter, Type::Real);
/// Number of Real inputs.
pub const N_INPUTS: usize = count(Causality::Input, Type::Real);
/// Number of Real outputs.
pub const N_REAL_OUTPUTS: usize = count(Causality::Output, Type::Real);
/// Number of Enumeration parameters.
pub const N_ENUM_PARAMS: usize = count(Causality::Parameter, Type::Enumeration);
/// Number of Boolean parameters.
pub const N_BOOL_PARAMS: usize = count(Causality::Parameter, Type::Boolean);
/// Number of Enumeration outputs (the regime).
pub const N_ENUM_OUTPUTS: usize = count(Causality::Output, Type::Enumeration);

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
    fn counts_and_slots_follow_the_table() {
        // Counted here by hand from the table.
        assert_eq!(
            (
                N_REAL_PARAMS,
                N_INPUTS,
                N_REAL_OUTPUTS,
                N_ENUM_PARAMS,
                N_BOOL_PARAMS
            ),
            (24, 7, 27, 5, 4)
        );
        assert_eq!(N_ENUM_OUTPUTS, 1);
        // Every row has a slot, the slots of a class are 0..count in table order.
        let mut next = std::collections::HashMap::new();
        for v in VARIABLES {
            let s = slot(v.vr).unwrap();
            assert_eq!(
                (s.causality, s.value_type),
                (v.causality, v.kind.value_type())
            );
            let n = next
                .entry((v.causality as u8, s.value_type as u8))
                .or_insert(0);
            assert_eq!(s.index, *n, "{}", v.name);
            *n += 1;
            assert_eq!(by_vr(v.vr).unwrap().name, v.name);
        }
        assert_eq!(slot(9999), None);
        assert_eq!(slot(0), None);
        assert_eq!(by_vr(99), None);
        assert_eq!(index(vr::RY1, Causality::Parameter, Type::Real), 1);
        assert_eq!(index(vr::J1, Causality::Output, Type::Real), 20);
    }

    #[test]
    fn dependencies_name_variables_of_the_table() {
        for v in VARIABLES {
            for name in v.depends.on().unwrap_or(&[]) {
                let k = VARIABLES.iter().find(|k| k.name == *name).unwrap();
                assert_ne!(k.causality, Causality::Output, "{name}");
            }
        }
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
