//! The complete state of an instance ([`Snapshot`], also its fmi2FMUstate),
//! its values by name and by value reference, the checks every value passes
//! (setters and restored states alike) and the serialized form.

use super::{FmuError, Mode};
use crate::physics::UnknownCode;
use crate::variables::{
    self, Causality, ENUM_TYPES, Kind, N_BOOL_PARAMS, N_ENUM_OUTPUTS, N_ENUM_PARAMS, N_INPUTS,
    N_REAL_OUTPUTS, N_REAL_PARAMS, Type, VARIABLES, Variable, vr,
};

/// The complete state of a [`super::TractionFmu`] (also its fmi2FMUstate).
/// Values of a causality and type sit in table order
/// ([`variables::Slot`]); the model reads them by value reference with
/// positions resolved at compile time (`Snapshot::param`, ...).
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    pub(super) mode: Mode,
    pub(super) start_time: f64,
    pub(super) time: f64,
    pub(super) params: [f64; N_REAL_PARAMS],
    pub(super) inputs: [f64; N_INPUTS],
    pub(super) enums: [i32; N_ENUM_PARAMS],
    pub(super) flags: [bool; N_BOOL_PARAMS],
    pub(super) outputs: [f64; N_REAL_OUTPUTS],
    pub(super) regime: i32,
    pub(super) dirty: bool,
    pub(super) envelope_warned: bool,
}

// The regime is the only Enumeration output and is kept in `regime`.
const _: () = assert!(N_ENUM_OUTPUTS == 1);

const MAGIC: &[u8; 8] = b"TRACFMU2";
const SNAPSHOT_LEN: usize = 8
    + 1
    + 8 * 2
    + 8 * N_REAL_PARAMS
    + 8 * N_INPUTS
    + 4 * N_ENUM_PARAMS
    + N_BOOL_PARAMS
    + 8 * N_REAL_OUTPUTS
    + 4
    + 2
    + 16;

/// The enumeration items of a variable's declared type.
pub(super) fn enum_items(v: &Variable) -> &'static [variables::EnumItem] {
    match v.kind {
        Kind::Enumeration { declared, .. } => ENUM_TYPES
            .iter()
            .find(|t| t.0 == declared)
            .map_or(&[][..], |t| t.2),
        _ => &[],
    }
}

/// The check of a Real value of a parameter or input (fmi2SetReal and a
/// restored state): no NaN; no infinity except for the radii (±inf = flat)
/// and the viscoelastic D, Z0 (+inf = a limit model; the physics checks the
/// sign); inputs finite. Ranges are checked by the physics when the contact
/// is built or evaluated.
pub(super) fn check_real(func: &str, v: &Variable, x: f64) -> Result<(), FmuError> {
    let may_be_infinite = v.causality == Causality::Parameter
        && matches!(v.vr, vr::RX1..=vr::RY2 | vr::DEBORAH | vr::Z0);
    let ok = match v.causality {
        Causality::Parameter => !(x.is_nan() || (x.is_infinite() && !may_be_infinite)),
        Causality::Input => x.is_finite(),
        Causality::Output => true,
    };
    if ok {
        Ok(())
    } else {
        let what = if v.causality == Causality::Input {
            "input "
        } else {
            ""
        };
        Err(FmuError::error(format!(
            "{func}: {what}{} = {x} is not a finite number",
            v.name
        )))
    }
}

/// The check of an Enumeration value (fmi2SetInteger and a restored state):
/// one of the items of its declared type.
pub(super) fn check_enum(func: &str, v: &Variable, x: i32) -> Result<(), FmuError> {
    let items = enum_items(v);
    if items.iter().any(|it| it.1 == x) {
        return Ok(());
    }
    let valid: Vec<String> = items
        .iter()
        .map(|it| format!("{} {}", it.1, it.0))
        .collect();
    Err(FmuError::error(format!(
        "{func}: {} = {x} is not one of {}",
        v.name,
        valid.join(", ")
    )))
}

impl Snapshot {
    /// The start values of the table.
    pub(super) fn start_values() -> Self {
        let mut s = Self {
            mode: Mode::Instantiated,
            start_time: 0.0,
            time: 0.0,
            params: [0.0; N_REAL_PARAMS],
            inputs: [0.0; N_INPUTS],
            enums: [0; N_ENUM_PARAMS],
            flags: [false; N_BOOL_PARAMS],
            outputs: [0.0; N_REAL_OUTPUTS],
            regime: 0,
            dirty: true,
            envelope_warned: false,
        };
        for v in VARIABLES {
            let Some(slot) = variables::slot(v.vr) else {
                continue;
            };
            let i = slot.index;
            match (v.causality, v.kind) {
                (Causality::Parameter, Kind::Real { start: Some(x), .. }) => s.params[i] = x,
                (Causality::Input, Kind::Real { start: Some(x), .. }) => s.inputs[i] = x,
                (Causality::Parameter, Kind::Enumeration { start: Some(x), .. }) => s.enums[i] = x,
                (Causality::Parameter, Kind::Boolean { start: Some(x) }) => s.flags[i] = x,
                _ => {}
            }
        }
        s
    }

    /// A Real parameter (position resolved at compile time).
    pub(super) fn param<const VR: u32>(&self) -> f64 {
        self.params[const { variables::index(VR, Causality::Parameter, Type::Real) }]
    }

    /// A Real input (position resolved at compile time).
    pub(super) fn input<const VR: u32>(&self) -> f64 {
        self.inputs[const { variables::index(VR, Causality::Input, Type::Real) }]
    }

    /// A Boolean parameter (position resolved at compile time).
    pub(super) fn flag<const VR: u32>(&self) -> bool {
        self.flags[const { variables::index(VR, Causality::Parameter, Type::Boolean) }]
    }

    /// An Enumeration parameter as its type; an unknown code is an error
    /// naming the variable (the setters and restored states refuse such
    /// codes, so it cannot occur).
    pub(super) fn choice<const VR: u32, T: TryFrom<i32, Error = UnknownCode>>(
        &self,
    ) -> Result<T, FmuError> {
        let code =
            self.enums[const { variables::index(VR, Causality::Parameter, Type::Enumeration) }];
        T::try_from(code).map_err(|e| {
            FmuError::error(format!(
                "{} = {}: {e}",
                const { VARIABLES[variables::row(VR)].name },
                e.0
            ))
        })
    }

    /// Sets a Real output (position resolved at compile time).
    pub(super) fn set_output<const VR: u32>(&mut self, x: f64) {
        self.outputs[const { variables::index(VR, Causality::Output, Type::Real) }] = x;
    }

    /// Checks every value as the setters do (and outputs finite, the regime
    /// one of its items), naming the first variable that fails.
    fn validate(&self, func: &str) -> Result<(), FmuError> {
        for t in [self.start_time, self.time] {
            if !t.is_finite() {
                return Err(FmuError::error(format!(
                    "{func}: the time {t} of the state is not finite"
                )));
            }
        }
        for v in VARIABLES {
            let Some(slot) = variables::slot(v.vr) else {
                continue;
            };
            let i = slot.index;
            match (v.causality, slot.value_type) {
                (Causality::Parameter, Type::Real) => check_real(func, v, self.params[i])?,
                (Causality::Input, Type::Real) => check_real(func, v, self.inputs[i])?,
                (Causality::Parameter, Type::Enumeration) => check_enum(func, v, self.enums[i])?,
                (Causality::Output, Type::Enumeration) => check_enum(func, v, self.regime)?,
                (Causality::Output, Type::Real) if !self.outputs[i].is_finite() => {
                    return Err(FmuError::error(format!(
                        "{func}: output {} = {} of the state is not finite",
                        v.name, self.outputs[i]
                    )));
                }
                _ => {}
            }
        }
        Ok(())
    }

    /// The serialized form: a fixed little-endian layout and an FNV-1a-128
    /// checksum of everything before it.
    pub(super) fn to_bytes(&self) -> Vec<u8> {
        let mut b = Vec::with_capacity(SNAPSHOT_LEN);
        b.extend_from_slice(MAGIC);
        b.push(self.mode as u8);
        for x in [self.start_time, self.time]
            .iter()
            .chain(&self.params)
            .chain(&self.inputs)
        {
            b.extend_from_slice(&x.to_bits().to_le_bytes());
        }
        for e in &self.enums {
            b.extend_from_slice(&e.to_le_bytes());
        }
        b.extend(self.flags.iter().map(|&f| u8::from(f)));
        for x in &self.outputs {
            b.extend_from_slice(&x.to_bits().to_le_bytes());
        }
        b.extend_from_slice(&self.regime.to_le_bytes());
        b.push(u8::from(self.dirty));
        b.push(u8::from(self.envelope_warned));
        b.extend_from_slice(&crate::model_description::fnv1a_128(&b).to_le_bytes());
        b
    }

    /// Reads [`Snapshot::to_bytes`] back: length, magic and checksum, then
    /// every value checked as the setters check it.
    pub(super) fn from_bytes(bytes: &[u8]) -> Result<Self, FmuError> {
        const F: &str = "fmi2DeSerializeFMUstate";
        let bad = |what: &str| {
            FmuError::error(format!("{F}: not a serialized state of this FMU ({what})"))
        };
        if bytes.len() != SNAPSHOT_LEN {
            return Err(bad(&format!(
                "{} bytes, expected {SNAPSHOT_LEN}",
                bytes.len()
            )));
        }
        if &bytes[..8] != MAGIC {
            return Err(bad("wrong magic"));
        }
        let (body, sum) = bytes.split_at(SNAPSHOT_LEN - 16);
        let mut s16 = [0u8; 16];
        s16.copy_from_slice(sum);
        if u128::from_le_bytes(s16) != crate::model_description::fnv1a_128(body) {
            return Err(bad("checksum mismatch"));
        }
        let mut r = Reader { body, pos: 8 };
        // A saved state is never in the error or fatal mode (fmi2GetFMUstate
        // is refused there).
        let mode = Mode::from_code(r.byte())
            .filter(|m| !matches!(m, Mode::Error | Mode::Fatal))
            .ok_or_else(|| bad("mode"))?;
        let mut s = Self::start_values();
        s.mode = mode;
        s.start_time = r.real();
        s.time = r.real();
        s.params.iter_mut().for_each(|x| *x = r.real());
        s.inputs.iter_mut().for_each(|x| *x = r.real());
        s.enums.iter_mut().for_each(|x| *x = r.integer());
        s.flags.iter_mut().for_each(|x| *x = r.flag());
        s.outputs.iter_mut().for_each(|x| *x = r.real());
        s.regime = r.integer();
        s.dirty = r.flag();
        s.envelope_warned = r.flag();
        s.validate(F)?;
        Ok(s)
    }
}

/// Reads the fields of a serialized state in order.
struct Reader<'a> {
    body: &'a [u8],
    pos: usize,
}

impl Reader<'_> {
    fn take<const N: usize>(&mut self) -> [u8; N] {
        let mut a = [0u8; N];
        a.copy_from_slice(&self.body[self.pos..self.pos + N]);
        self.pos += N;
        a
    }
    fn byte(&mut self) -> u8 {
        self.take::<1>()[0]
    }
    fn flag(&mut self) -> bool {
        self.byte() != 0
    }
    fn real(&mut self) -> f64 {
        f64::from_bits(u64::from_le_bytes(self.take()))
    }
    fn integer(&mut self) -> i32 {
        i32::from_le_bytes(self.take())
    }
}
