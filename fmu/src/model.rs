//! The safe side of the FMU: the [`CoSimulation`] trait and the traction
//! contact instance [`TractionFmu`] with the FMI 2 co-simulation state machine.
//!
//! Nothing here is `unsafe` and nothing is global: each instance owns all its
//! data, so instances are independent and may be driven from different
//! threads one at a time. The C wrappers in [`crate::ffi`] only translate
//! pointers to slices and strings and call these methods.

use crate::physics::{self, Contact, Envelope, Fluid, PhysicsError, Rheology};
use crate::variables::{
    self, Causality, Kind, N_INPUTS, N_REAL_OUTPUTS, N_REAL_PARAMS, Variable, vr,
};

/// Status of a call, mirroring `fmi2Status`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Status {
    /// fmi2OK.
    Ok = 0,
    /// fmi2Warning.
    Warning = 1,
    /// fmi2Discard.
    Discard = 2,
    /// fmi2Error.
    Error = 3,
    /// fmi2Fatal.
    Fatal = 4,
}

/// A failed call: status (Error or Fatal) and the message to log.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct FmuError {
    /// fmi2Error or fmi2Fatal.
    pub status: Status,
    /// What went wrong, naming the function, variable or quantity.
    pub message: String,
}

impl FmuError {
    /// An fmi2Error with a message.
    pub fn error(message: impl Into<String>) -> Self {
        Self {
            status: Status::Error,
            message: message.into(),
        }
    }
}

/// Where a model sends warnings (the host's logger behind the C boundary).
pub trait Logger {
    /// Logs one message under an FMI log category.
    fn log(&mut self, status: Status, category: &str, message: &str);
}

/// A logger that drops everything (tests, benches).
#[derive(Debug, Default, Clone, Copy)]
pub struct NullLogger;

impl Logger for NullLogger {
    fn log(&mut self, _: Status, _: &str, _: &str) {}
}

/// Result of a model call: `Ok(Status::Ok | Status::Warning)` or an error.
pub type FmuResult = Result<Status, FmuError>;

/// One FMI 2 co-simulation slave, safe Rust. The C wrappers of [`crate::ffi`]
/// call exactly these methods; every method checks that it is allowed in the
/// current state of the FMI 2 state machine.
pub trait CoSimulation: Sized {
    /// A snapshot of the complete instance state (fmi2FMUstate).
    type State;
    /// fmi2Instantiate (co-simulation only; the GUID must match).
    ///
    /// # Errors
    /// A message when the GUID or the FMU type does not match.
    fn instantiate(instance_name: &str, guid: &str) -> Result<Self, String>;
    /// fmi2SetupExperiment.
    ///
    /// # Errors
    /// Wrong state or invalid times.
    fn setup_experiment(
        &mut self,
        tolerance: Option<f64>,
        start_time: f64,
        stop_time: Option<f64>,
    ) -> FmuResult;
    /// fmi2EnterInitializationMode.
    ///
    /// # Errors
    /// Wrong state.
    fn enter_initialization_mode(&mut self) -> FmuResult;
    /// fmi2ExitInitializationMode: validates the parameters, computes the outputs.
    ///
    /// # Errors
    /// Wrong state, invalid parameter or input.
    fn exit_initialization_mode(&mut self, log: &mut dyn Logger) -> FmuResult;
    /// fmi2Terminate (does not free anything).
    ///
    /// # Errors
    /// Wrong state.
    fn terminate(&mut self) -> FmuResult;
    /// fmi2Reset: back to the instantiated state with start values.
    ///
    /// # Errors
    /// After a fatal error.
    fn reset(&mut self) -> FmuResult;
    /// fmi2GetReal.
    ///
    /// # Errors
    /// Wrong state, unknown value reference, outputs not computable.
    fn get_real(&mut self, vrs: &[u32], values: &mut [f64], log: &mut dyn Logger) -> FmuResult;
    /// fmi2SetReal.
    ///
    /// # Errors
    /// Wrong state, unknown or non-settable value reference, NaN or infinite value.
    fn set_real(&mut self, vrs: &[u32], values: &[f64]) -> FmuResult;
    /// fmi2GetInteger (Integer and Enumeration variables).
    ///
    /// # Errors
    /// As [`CoSimulation::get_real`].
    fn get_integer(&mut self, vrs: &[u32], values: &mut [i32], log: &mut dyn Logger) -> FmuResult;
    /// fmi2SetInteger (Enumeration parameters).
    ///
    /// # Errors
    /// As [`CoSimulation::set_real`], or a value outside the enumeration.
    fn set_integer(&mut self, vrs: &[u32], values: &[i32]) -> FmuResult;
    /// fmi2GetBoolean.
    ///
    /// # Errors
    /// Wrong state, unknown value reference.
    fn get_boolean(&mut self, vrs: &[u32], values: &mut [bool]) -> FmuResult;
    /// fmi2SetBoolean.
    ///
    /// # Errors
    /// Wrong state, unknown value reference.
    fn set_boolean(&mut self, vrs: &[u32], values: &[bool]) -> FmuResult;
    /// fmi2DoStep from `current_time` over `step_size`.
    ///
    /// # Errors
    /// Wrong state, negative or non-finite step, outputs not computable.
    fn do_step(&mut self, current_time: f64, step_size: f64, log: &mut dyn Logger) -> FmuResult;
    /// The time reached by the last successful step (fmi2LastSuccessfulTime).
    fn last_successful_time(&self) -> f64;
    /// fmi2GetFMUstate.
    ///
    /// # Errors
    /// Wrong state.
    fn get_state(&self) -> Result<Self::State, FmuError>;
    /// fmi2SetFMUstate.
    ///
    /// # Errors
    /// After a fatal error, or a state that does not fit this instance.
    fn set_state(&mut self, state: &Self::State) -> FmuResult;
    /// fmi2SerializeFMUstate: the bytes of a state.
    fn serialize_state(state: &Self::State) -> Vec<u8>;
    /// fmi2DeSerializeFMUstate.
    ///
    /// # Errors
    /// Bytes that are not a serialized state of this FMU.
    fn deserialize_state(bytes: &[u8]) -> Result<Self::State, FmuError>;
    /// Marks the instance unusable after a panic was caught at the boundary.
    fn poison(&mut self);
}

/// FMI 2 co-simulation states.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// After fmi2Instantiate or fmi2Reset.
    Instantiated = 0,
    /// Between fmi2EnterInitializationMode and fmi2ExitInitializationMode.
    Initialization = 1,
    /// Initialized; steps may be taken.
    StepComplete = 2,
    /// After fmi2Terminate.
    Terminated = 3,
    /// After a call returned fmi2Error.
    Error = 4,
    /// After a call returned fmi2Fatal.
    Fatal = 5,
}

impl Mode {
    fn from_code(c: u8) -> Option<Self> {
        Some(match c {
            0 => Mode::Instantiated,
            1 => Mode::Initialization,
            2 => Mode::StepComplete,
            3 => Mode::Terminated,
            _ => return None,
        })
    }
}

const N_OUT: usize = N_REAL_OUTPUTS;

/// The complete state of a [`TractionFmu`] (also its fmi2FMUstate).
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    mode: Mode,
    start_time: f64,
    time: f64,
    params: [f64; N_REAL_PARAMS],
    inputs: [f64; N_INPUTS],
    enums: [i32; N_ENUMS],
    compliance: bool,
    spin_peak: bool,
    map: bool,
    outputs: [f64; N_OUT],
    regime: i32,
    dirty: bool,
    envelope_warned: bool,
}

const N_ENUMS: usize = 5;
const MAGIC: &[u8; 8] = b"TRACFMU2";
const SNAPSHOT_LEN: usize =
    8 + 1 + 8 * 2 + 8 * N_REAL_PARAMS + 8 * N_INPUTS + 4 * N_ENUMS + 3 + 8 * N_OUT + 4 + 2 + 16;

/// Index of an Enumeration parameter in [`Snapshot::enums`].
fn enum_index(r: u32) -> Option<usize> {
    match r {
        vr::FLUID..=vr::SIDE_SLIP_SOURCE => Some((r - vr::FLUID) as usize),
        vr::ENVELOPE => Some(4),
        _ => None,
    }
}

impl Snapshot {
    fn start_values() -> Self {
        let mut params = [0.0; N_REAL_PARAMS];
        let mut inputs = [0.0; N_INPUTS];
        let mut enums = [0; N_ENUMS];
        let mut compliance = false;
        let mut spin_peak = false;
        let mut map = false;
        for v in variables::VARIABLES {
            match (v.causality, v.kind) {
                (Causality::Parameter, Kind::Real { start: Some(s), .. }) => {
                    params[v.vr as usize - 1] = s
                }
                (Causality::Input, Kind::Real { start: Some(s), .. }) => {
                    inputs[(v.vr - vr::LOAD) as usize] = s
                }
                (Causality::Parameter, Kind::Enumeration { start: Some(s), .. }) => {
                    if let Some(i) = enum_index(v.vr) {
                        enums[i] = s;
                    }
                }
                (Causality::Parameter, Kind::Boolean { start: Some(s) }) => match v.vr {
                    vr::SPIN_PEAK => spin_peak = s,
                    vr::RHEOLOGY_MAP => map = s,
                    _ => compliance = s,
                },
                _ => {}
            }
        }
        Self {
            mode: Mode::Instantiated,
            start_time: 0.0,
            time: 0.0,
            params,
            inputs,
            enums,
            compliance,
            spin_peak,
            map,
            outputs: [0.0; N_OUT],
            regime: 0,
            dirty: true,
            envelope_warned: false,
        }
    }

    fn to_bytes(&self) -> Vec<u8> {
        let mut b = Vec::with_capacity(SNAPSHOT_LEN);
        b.extend_from_slice(MAGIC);
        b.push(self.mode as u8);
        b.extend_from_slice(&self.start_time.to_bits().to_le_bytes());
        b.extend_from_slice(&self.time.to_bits().to_le_bytes());
        for x in self.params.iter().chain(&self.inputs) {
            b.extend_from_slice(&x.to_bits().to_le_bytes());
        }
        for e in &self.enums {
            b.extend_from_slice(&e.to_le_bytes());
        }
        b.push(u8::from(self.compliance));
        b.push(u8::from(self.spin_peak));
        b.push(u8::from(self.map));
        for x in &self.outputs {
            b.extend_from_slice(&x.to_bits().to_le_bytes());
        }
        b.extend_from_slice(&self.regime.to_le_bytes());
        b.push(u8::from(self.dirty));
        b.push(u8::from(self.envelope_warned));
        // Checksum (FNV-1a 128) of everything before it.
        b.extend_from_slice(&crate::model_description::fnv1a_128(&b).to_le_bytes());
        b
    }

    fn from_bytes(bytes: &[u8]) -> Result<Self, FmuError> {
        let bad = |what: &str| {
            FmuError::error(format!(
                "fmi2DeSerializeFMUstate: not a serialized state of this FMU ({what})"
            ))
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
        let mut pos = 8;
        let mut take = |n: usize| {
            let s = &body[pos..pos + n];
            pos += n;
            s
        };
        let f = |s: &[u8]| {
            let mut a = [0u8; 8];
            a.copy_from_slice(s);
            f64::from_bits(u64::from_le_bytes(a))
        };
        let i = |s: &[u8]| {
            let mut a = [0u8; 4];
            a.copy_from_slice(s);
            i32::from_le_bytes(a)
        };
        let mode = Mode::from_code(take(1)[0]).ok_or_else(|| bad("mode"))?;
        let start_time = f(take(8));
        let time = f(take(8));
        let mut params = [0.0; N_REAL_PARAMS];
        for p in &mut params {
            *p = f(take(8));
        }
        let mut inputs = [0.0; N_INPUTS];
        for p in &mut inputs {
            *p = f(take(8));
        }
        let mut enums = [0; N_ENUMS];
        for e in &mut enums {
            *e = i(take(4));
        }
        let compliance = take(1)[0] != 0;
        let spin_peak = take(1)[0] != 0;
        let map = take(1)[0] != 0;
        let mut outputs = [0.0; N_OUT];
        for p in &mut outputs {
            *p = f(take(8));
        }
        let regime = i(take(4));
        let dirty = take(1)[0] != 0;
        let envelope_warned = take(1)[0] != 0;
        Ok(Self {
            mode,
            start_time,
            time,
            params,
            inputs,
            enums,
            compliance,
            spin_peak,
            map,
            outputs,
            regime,
            dirty,
            envelope_warned,
        })
    }
}

/// The traction contact FMU instance.
#[derive(Debug, Clone)]
pub struct TractionFmu {
    s: Snapshot,
    /// The contact built from the current parameters (None: rebuild).
    contact: Option<Contact>,
    /// The rheology map of the last contact, offered to the next one (kept
    /// when k and the tolerance are unchanged; see `drop_contact`).
    spare_map: Option<traction_contact::Map>,
    /// Lifecycle state (Error/Fatal are not part of a snapshot).
    mode: Mode,
}

/// Number of Real outputs before J1 (VR 200..=218) in [`Snapshot::outputs`].
const N_OUT_BEFORE_J: usize = (vr::MU_FORCE - vr::FX) as usize + 1;

fn out_index(vr: u32) -> Option<usize> {
    match vr {
        vr::FX..=vr::MU_FORCE => Some((vr - vr::FX) as usize),
        vr::J1..=vr::J7 => Some((vr - vr::J1) as usize + N_OUT_BEFORE_J),
        _ => None,
    }
}

fn var(vr: u32, func: &str) -> Result<&'static Variable, FmuError> {
    variables::by_vr(vr)
        .ok_or_else(|| FmuError::error(format!("{func}: unknown value reference {vr}")))
}

impl TractionFmu {
    /// The current lifecycle state.
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// Enter the error (or fatal) state for `e` and return it. Idempotent in
    /// the error state for non-fatal errors, so getters and refused calls
    /// there leave the mode unchanged.
    fn fail(&mut self, e: FmuError) -> FmuError {
        self.mode = if e.status == Status::Fatal {
            Mode::Fatal
        } else {
            Mode::Error
        };
        e
    }

    fn require(&mut self, func: &str, allowed: &[Mode]) -> Result<(), FmuError> {
        if allowed.contains(&self.mode) {
            Ok(())
        } else if self.mode == Mode::Fatal {
            Err(FmuError {
                status: Status::Fatal,
                message: format!(
                    "{func}: the instance had a fatal error; only fmi2FreeInstance is allowed"
                ),
            })
        } else {
            let e = FmuError::error(format!(
                "{func}: not allowed in state {:?} (allowed: {allowed:?})",
                self.mode
            ));
            Err(self.fail(e))
        }
    }

    fn physics_parameters(&self) -> Result<physics::Parameters, FmuError> {
        let p = &self.s.params;
        let fluid = match self.s.enums[0] {
            1 => Fluid::Santotrac50,
            2 => Fluid::Tdf88,
            _ => Fluid::User,
        };
        let envelope = match self.s.enums[4] {
            1 => Envelope::Strict,
            2 => Envelope::Extrapolate,
            _ => Envelope::Clamp,
        };
        let rheology = match self.s.enums[1] {
            2 => Rheology::RigidPlastic,
            3 => Rheology::Viscoelastic,
            _ => Rheology::ElasticPlastic,
        };
        for (i, name) in [
            (vr::ROLLING_RADIUS1, "rolling_radius1"),
            (vr::ROLLING_RADIUS2, "rolling_radius2"),
        ] {
            let r = p[i as usize - 1];
            if !(r.is_finite() && r > 0.0) {
                return Err(FmuError::error(format!(
                    "{name} = {r} is invalid: a distance in m, finite and > 0"
                )));
            }
        }
        let alpha = p[vr::TILT_ANGLE as usize - 1];
        if !(alpha.is_finite() && alpha.abs() < std::f64::consts::FRAC_PI_2) {
            return Err(FmuError::error(format!(
                "spin_tilt_angle = {alpha} is invalid: an angle in rad with |alpha| < pi/2"
            )));
        }
        let offset = p[vr::TILT_OFFSET as usize - 1];
        if !offset.is_finite() {
            return Err(FmuError::error(format!(
                "spin_center_offset = {offset} is invalid: a finite distance in m"
            )));
        }
        Ok(physics::Parameters {
            rx1: p[0],
            ry1: p[1],
            rx2: p[2],
            ry2: p[3],
            e1: p[4],
            nu1: p[5],
            e2: p[6],
            nu2: p[7],
            fluid,
            envelope,
            m_user: p[vr::M_USER as usize - 1],
            mu_user: p[vr::MU_USER as usize - 1],
            rheology,
            deborah: p[vr::DEBORAH as usize - 1],
            z0: p[vr::Z0 as usize - 1],
            spin_peak: self.s.spin_peak,
            mu_spin_user: p[vr::MU_SPIN_USER as usize - 1],
            compliance: self.s.compliance,
            u_reg: p[vr::U_REG as usize - 1],
            tolerance: p[vr::RHEOLOGY_TOLERANCE as usize - 1],
            map: self.s.map,
        })
    }

    /// Invalidate the contact (parameters changed), keeping its rheology map
    /// for the next one: the map's values depend only on k and the
    /// tolerance, so a rebuilt contact with the same ones reuses its cells
    /// (results are the same with or without it).
    fn drop_contact(&mut self) {
        if let Some(m) = self.contact.take().and_then(|c| c.take_map()) {
            self.spare_map = Some(m);
        }
    }

    fn contact(&mut self) -> Result<&Contact, FmuError> {
        if self.contact.is_none() {
            let p = self.physics_parameters()?;
            let c = Contact::new(&p)
                .map_err(|e: PhysicsError| FmuError::error(format!("invalid parameters: {e}")))?;
            if let Some(m) = self.spare_map.take() {
                c.adopt_map(m);
            }
            self.contact = Some(c);
        }
        self.contact
            .as_ref()
            .ok_or_else(|| FmuError::error("internal: contact not built"))
    }

    /// Spin per rolling speed of the tilt geometry (report eq. 6).
    fn tilt_spin_per_u(&self) -> Result<f64, FmuError> {
        let p = &self.s.params;
        let alpha = p[vr::TILT_ANGLE as usize - 1];
        let e = p[vr::TILT_OFFSET as usize - 1];
        let ry = p[vr::RY1 as usize - 1];
        if alpha == 0.0 {
            return Ok(0.0);
        }
        if ry == 0.0 || ry.is_infinite() {
            // Flat transverse profile: infinite radius, no spin from tilt.
            return Ok(0.0);
        }
        let den = ry * alpha.cos() + e;
        if den == 0.0 || !den.is_finite() {
            return Err(FmuError::error(
                "spin_source = tilt_geometry: ry1 cos(spin_tilt_angle) + spin_center_offset is 0 (report eq. 6 undefined)",
            ));
        }
        Ok(alpha.sin() / den)
    }

    /// Recomputes the outputs if an input or parameter changed.
    fn update(&mut self, log: &mut dyn Logger) -> FmuResult {
        if !self.s.dirty {
            return Ok(Status::Ok);
        }
        let x = &self.s.inputs;
        let p = &self.s.params;
        let (r1, r2) = (
            p[vr::ROLLING_RADIUS1 as usize - 1],
            p[vr::ROLLING_RADIUS2 as usize - 1],
        );
        let input = |v: u32| x[(v - vr::LOAD) as usize];
        let (u1, u2) = (input(vr::OMEGA1) * r1, input(vr::OMEGA2) * r2);
        let u = 0.5 * (u1 + u2);
        let du = u1 - u2;
        let dv = if self.s.enums[3] == 2 {
            let beta = input(vr::SKEW_ANGLE);
            if beta.abs() >= std::f64::consts::FRAC_PI_2 {
                return Err(FmuError::error(format!(
                    "skew_angle = {beta} is invalid: an angle in rad with |beta| < pi/2"
                )));
            }
            u * beta.tan()
        } else {
            input(vr::SIDE_SLIP_VELOCITY)
        };
        let omega = if self.s.enums[2] == 2 {
            u * self.tilt_spin_per_u()?
        } else {
            input(vr::SPIN)
        };
        let op = physics::Inputs {
            load: input(vr::LOAD),
            u,
            du,
            dv,
            omega,
            inlet_temperature_celsius: input(vr::INLET_TEMPERATURE),
        };
        let o = self
            .contact()?
            .evaluate(&op)
            .map_err(|e| FmuError::error(format!("contact evaluation failed: {e}")))?;
        let coef = |f: f64| if op.load > 0.0 { f / op.load } else { 0.0 };
        let loss = o.fx * du + o.fy * dv + o.mz * omega;
        let values = [
            o.fx,
            o.fy,
            o.mz,
            -o.fx * r1,
            o.fx * r2,
            coef(o.fx),
            coef(o.fy),
            loss,
            o.a,
            o.b,
            o.k,
            o.p0,
            u,
            du,
            dv,
            omega,
            o.m,
            o.mu,
            o.mu_force,
        ];
        if let Some(bad) = values.iter().chain(&o.j).position(|v| !v.is_finite()) {
            // Defensive: the physics promises finite outputs for finite inputs.
            return Err(FmuError::error(format!(
                "the contact produced a non-finite output (index {bad}) for load {} N, U {u} m/s, dU {du} m/s, dV {dv} m/s, spin {omega} rad/s",
                op.load
            )));
        }
        self.s.outputs[..N_OUT_BEFORE_J].copy_from_slice(&values);
        self.s.outputs[N_OUT_BEFORE_J..].copy_from_slice(&o.j);
        self.s.regime = o.regime.map_or(0, |r| r as i32);
        self.s.dirty = false;
        if o.outside_envelope && !self.s.envelope_warned {
            self.s.envelope_warned = true;
            log.log(
                Status::Warning,
                "logStatusWarning",
                &format!(
                    "the fluid correlations are used outside their data (P0 {:.4e} Pa, U {u} m/s, inlet {} degC, k {:.3}); fluid_envelope decides what happens (logged once per instance)",
                    o.p0, op.inlet_temperature_celsius, o.k
                ),
            );
            return Ok(Status::Warning);
        }
        Ok(Status::Ok)
    }

    fn with_update(&mut self, log: &mut dyn Logger) -> FmuResult {
        match self.update(log) {
            Ok(s) => Ok(s),
            Err(e) => Err(self.fail(e)),
        }
    }
}

/// Largest value reference of a Real parameter (VR 1..=N_REAL_PARAMS).
const PARAM_VR_MAX: u32 = N_REAL_PARAMS as u32;

const SETTABLE_PARAM_MODES: &[Mode] = &[Mode::Instantiated, Mode::Initialization];
const SETTABLE_INPUT_MODES: &[Mode] =
    &[Mode::Instantiated, Mode::Initialization, Mode::StepComplete];
const GET_MODES: &[Mode] = &[
    Mode::Initialization,
    Mode::StepComplete,
    Mode::Terminated,
    Mode::Error,
];

impl CoSimulation for TractionFmu {
    type State = Snapshot;

    fn instantiate(instance_name: &str, guid: &str) -> Result<Self, String> {
        let expected = crate::model_description::guid();
        if guid != expected {
            return Err(format!(
                "fmi2Instantiate: GUID {guid:?} of instance {instance_name:?} does not match this binary's {expected:?} (modelDescription.xml and binary from different builds)"
            ));
        }
        Ok(Self {
            s: Snapshot::start_values(),
            contact: None,
            spare_map: None,
            mode: Mode::Instantiated,
        })
    }

    fn setup_experiment(
        &mut self,
        tolerance: Option<f64>,
        start_time: f64,
        stop_time: Option<f64>,
    ) -> FmuResult {
        self.require("fmi2SetupExperiment", &[Mode::Instantiated])?;
        let _ = tolerance; // algebraic model: no tolerance to honour
        if !start_time.is_finite() || stop_time.is_some_and(|t| t.is_nan() || t < start_time) {
            return Err(self.fail(FmuError::error(format!(
                "fmi2SetupExperiment: startTime {start_time} must be finite and stopTime {stop_time:?} >= startTime"
            ))));
        }
        self.s.start_time = start_time;
        self.s.time = start_time;
        Ok(Status::Ok)
    }

    fn enter_initialization_mode(&mut self) -> FmuResult {
        self.require("fmi2EnterInitializationMode", &[Mode::Instantiated])?;
        self.mode = Mode::Initialization;
        self.s.mode = Mode::Initialization;
        Ok(Status::Ok)
    }

    fn exit_initialization_mode(&mut self, log: &mut dyn Logger) -> FmuResult {
        self.require("fmi2ExitInitializationMode", &[Mode::Initialization])?;
        let st = self.with_update(log)?;
        self.mode = Mode::StepComplete;
        self.s.mode = Mode::StepComplete;
        Ok(st)
    }

    fn terminate(&mut self) -> FmuResult {
        self.require("fmi2Terminate", &[Mode::StepComplete, Mode::Error])?;
        self.mode = Mode::Terminated;
        self.s.mode = Mode::Terminated;
        Ok(Status::Ok)
    }

    fn reset(&mut self) -> FmuResult {
        self.require(
            "fmi2Reset",
            &[
                Mode::Instantiated,
                Mode::Initialization,
                Mode::StepComplete,
                Mode::Terminated,
                Mode::Error,
            ],
        )?;
        self.drop_contact();
        *self = Self {
            s: Snapshot::start_values(),
            contact: None,
            spare_map: self.spare_map.take(),
            mode: Mode::Instantiated,
        };
        Ok(Status::Ok)
    }

    fn get_real(&mut self, vrs: &[u32], values: &mut [f64], log: &mut dyn Logger) -> FmuResult {
        self.require("fmi2GetReal", GET_MODES)?;
        let mut status = Status::Ok;
        if self.mode != Mode::Error && vrs.iter().any(|&r| out_index(r).is_some()) {
            status = self.with_update(log)?;
        }
        for (&r, v) in vrs.iter().zip(values.iter_mut()) {
            *v = match r {
                1..=PARAM_VR_MAX => self.s.params[r as usize - 1],
                vr::LOAD..=vr::INLET_TEMPERATURE => self.s.inputs[(r - vr::LOAD) as usize],
                _ => match out_index(r) {
                    Some(i) => self.s.outputs[i],
                    None => {
                        let e = FmuError::error(format!(
                            "fmi2GetReal: value reference {r} is not a Real variable of this FMU"
                        ));
                        return Err(self.fail(e));
                    }
                },
            };
        }
        Ok(status)
    }

    fn set_real(&mut self, vrs: &[u32], values: &[f64]) -> FmuResult {
        for (&r, &x) in vrs.iter().zip(values) {
            let v = var(r, "fmi2SetReal").map_err(|e| self.fail(e))?;
            let is_real = matches!(v.kind, Kind::Real { .. });
            // Radii (±inf = flat) and the viscoelastic D, Z0 (+inf = a limit
            // model) accept infinity; the physics checks the sign.
            let may_be_infinite = matches!(r, vr::RX1..=vr::RY2 | vr::DEBORAH | vr::Z0);
            match v.causality {
                _ if !is_real => {
                    return Err(self.fail(FmuError::error(format!(
                        "fmi2SetReal: {} (value reference {r}) is not a Real",
                        v.name
                    ))));
                }
                Causality::Output => {
                    return Err(self.fail(FmuError::error(format!(
                        "fmi2SetReal: {} is an output and cannot be set",
                        v.name
                    ))));
                }
                Causality::Parameter => {
                    self.require("fmi2SetReal of a fixed parameter", SETTABLE_PARAM_MODES)?;
                    if x.is_nan() || (x.is_infinite() && !may_be_infinite) {
                        return Err(self.fail(FmuError::error(format!(
                            "fmi2SetReal: {} = {x} is not a finite number",
                            v.name
                        ))));
                    }
                    self.s.params[r as usize - 1] = x;
                    self.drop_contact();
                }
                Causality::Input => {
                    self.require("fmi2SetReal of an input", SETTABLE_INPUT_MODES)?;
                    if !x.is_finite() {
                        return Err(self.fail(FmuError::error(format!(
                            "fmi2SetReal: input {} = {x} is not a finite number",
                            v.name
                        ))));
                    }
                    self.s.inputs[(r - vr::LOAD) as usize] = x;
                }
            }
            self.s.dirty = true;
        }
        Ok(Status::Ok)
    }

    fn get_integer(&mut self, vrs: &[u32], values: &mut [i32], log: &mut dyn Logger) -> FmuResult {
        self.require("fmi2GetInteger", GET_MODES)?;
        let mut status = Status::Ok;
        if self.mode != Mode::Error && vrs.contains(&vr::REGIME) {
            status = self.with_update(log)?;
        }
        for (&r, v) in vrs.iter().zip(values.iter_mut()) {
            *v = match r {
                vr::REGIME => self.s.regime,
                _ if enum_index(r).is_some() => self.s.enums[enum_index(r).unwrap_or(0)],
                _ => {
                    let e = FmuError::error(format!(
                        "fmi2GetInteger: value reference {r} is not an Integer or Enumeration variable of this FMU"
                    ));
                    return Err(self.fail(e));
                }
            };
        }
        Ok(status)
    }

    fn set_integer(&mut self, vrs: &[u32], values: &[i32]) -> FmuResult {
        for (&r, &x) in vrs.iter().zip(values) {
            let v = var(r, "fmi2SetInteger").map_err(|e| self.fail(e))?;
            let Kind::Enumeration { declared, .. } = v.kind else {
                return Err(self.fail(FmuError::error(format!(
                    "fmi2SetInteger: {} (value reference {r}) is not an Integer or Enumeration",
                    v.name
                ))));
            };
            if v.causality != Causality::Parameter {
                return Err(self.fail(FmuError::error(format!(
                    "fmi2SetInteger: {} is an output and cannot be set",
                    v.name
                ))));
            }
            self.require("fmi2SetInteger of a fixed parameter", SETTABLE_PARAM_MODES)?;
            let items = variables::ENUM_TYPES
                .iter()
                .find(|t| t.0 == declared)
                .map_or(&[][..], |t| t.2);
            if !items.iter().any(|it| it.1 == x) {
                let valid: Vec<String> = items
                    .iter()
                    .map(|it| format!("{} {}", it.1, it.0))
                    .collect();
                return Err(self.fail(FmuError::error(format!(
                    "fmi2SetInteger: {} = {x} is not one of {}",
                    v.name,
                    valid.join(", ")
                ))));
            }
            if let Some(i) = enum_index(r) {
                self.s.enums[i] = x;
            }
            self.drop_contact();
            self.s.dirty = true;
        }
        Ok(Status::Ok)
    }

    fn get_boolean(&mut self, vrs: &[u32], values: &mut [bool]) -> FmuResult {
        self.require("fmi2GetBoolean", GET_MODES)?;
        for (&r, v) in vrs.iter().zip(values.iter_mut()) {
            *v = match r {
                vr::SPIN_PEAK => self.s.spin_peak,
                vr::COMPLIANCE => self.s.compliance,
                vr::RHEOLOGY_MAP => self.s.map,
                _ => {
                    let e = FmuError::error(format!(
                        "fmi2GetBoolean: value reference {r} is not a Boolean variable of this FMU"
                    ));
                    return Err(self.fail(e));
                }
            };
        }
        Ok(Status::Ok)
    }

    fn set_boolean(&mut self, vrs: &[u32], values: &[bool]) -> FmuResult {
        for (&r, &x) in vrs.iter().zip(values) {
            if ![vr::COMPLIANCE, vr::SPIN_PEAK, vr::RHEOLOGY_MAP].contains(&r) {
                return Err(self.fail(FmuError::error(format!(
                    "fmi2SetBoolean: value reference {r} is not a Boolean variable of this FMU"
                ))));
            }
            self.require("fmi2SetBoolean of a fixed parameter", SETTABLE_PARAM_MODES)?;
            match r {
                vr::SPIN_PEAK => self.s.spin_peak = x,
                vr::RHEOLOGY_MAP => self.s.map = x,
                _ => self.s.compliance = x,
            }
            self.drop_contact();
            self.s.dirty = true;
        }
        Ok(Status::Ok)
    }

    fn do_step(&mut self, current_time: f64, step_size: f64, log: &mut dyn Logger) -> FmuResult {
        self.require("fmi2DoStep", &[Mode::StepComplete])?;
        if !(current_time.is_finite()
            && step_size.is_finite()
            && step_size >= 0.0
            && (current_time + step_size).is_finite())
        {
            return Err(self.fail(FmuError::error(format!(
                "fmi2DoStep: currentCommunicationPoint {current_time} and communicationStepSize {step_size} must be finite, step >= 0"
            ))));
        }
        let st = self.with_update(log)?;
        self.s.time = current_time + step_size;
        Ok(st)
    }

    fn last_successful_time(&self) -> f64 {
        self.s.time
    }

    fn get_state(&self) -> Result<Snapshot, FmuError> {
        match self.mode {
            Mode::Error | Mode::Fatal => Err(FmuError {
                status: if self.mode == Mode::Fatal {
                    Status::Fatal
                } else {
                    Status::Error
                },
                message: format!("fmi2GetFMUstate: not allowed in state {:?}", self.mode),
            }),
            _ => Ok(self.s.clone()),
        }
    }

    fn set_state(&mut self, state: &Snapshot) -> FmuResult {
        self.require(
            "fmi2SetFMUstate",
            &[
                Mode::Instantiated,
                Mode::Initialization,
                Mode::StepComplete,
                Mode::Terminated,
                Mode::Error,
            ],
        )?;
        self.s = state.clone();
        self.mode = state.mode;
        self.drop_contact();
        Ok(Status::Ok)
    }

    fn serialize_state(state: &Snapshot) -> Vec<u8> {
        state.to_bytes()
    }

    fn deserialize_state(bytes: &[u8]) -> Result<Snapshot, FmuError> {
        Snapshot::from_bytes(bytes)
    }

    fn poison(&mut self) {
        self.mode = Mode::Fatal;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Capture(Vec<(Status, String)>);
    impl Logger for Capture {
        fn log(&mut self, status: Status, _: &str, message: &str) {
            self.0.push((status, message.to_owned()));
        }
    }

    fn initialized() -> TractionFmu {
        let mut f = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
        f.setup_experiment(None, 0.0, Some(1.0)).unwrap();
        f.enter_initialization_mode().unwrap();
        f.exit_initialization_mode(&mut NullLogger).unwrap();
        f
    }

    #[test]
    fn wrong_guid_is_refused() {
        assert!(
            TractionFmu::instantiate("t", "{nope}")
                .unwrap_err()
                .contains("GUID")
        );
    }

    #[test]
    fn state_machine_allows_and_refuses_per_the_standard() {
        let mut f = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
        // SetReal before initialization is accepted; GetReal is not yet allowed.
        f.set_real(&[vr::LOAD, vr::RX1], &[700.0, 0.03]).unwrap();
        assert!(f.do_step(0.0, 0.1, &mut NullLogger).is_err());
        assert_eq!(f.mode(), Mode::Error);
        f.reset().unwrap();
        assert_eq!(f.mode(), Mode::Instantiated);
        let mut x = [0.0];
        f.enter_initialization_mode().unwrap();
        f.get_real(&[vr::LOAD], &mut x, &mut NullLogger).unwrap();
        assert_eq!(x[0], 500.0, "reset restores the start value");
        f.exit_initialization_mode(&mut NullLogger).unwrap();
        // Fixed parameters cannot change after initialization.
        let e = f.set_real(&[vr::RX1], &[0.05]).unwrap_err();
        assert!(e.message.contains("fixed parameter"), "{e}");
        f.reset().unwrap();
        let mut f = initialized();
        f.do_step(0.0, 0.5, &mut NullLogger).unwrap();
        f.terminate().unwrap();
        assert_eq!(f.mode(), Mode::Terminated);
        f.get_real(&[vr::FX], &mut x, &mut NullLogger).unwrap();
        assert!(f.do_step(0.5, 0.5, &mut NullLogger).is_err());
    }

    #[test]
    fn outputs_follow_kinematics_and_torque_convention() {
        let mut f = initialized();
        // u1 = 600*0.033 = 19.8 m/s, u2 = 270*0.0714 = 19.278 m/s.
        f.set_real(&[vr::OMEGA1, vr::OMEGA2], &[600.0, 270.0])
            .unwrap();
        f.do_step(0.0, 0.01, &mut NullLogger).unwrap();
        let vrs = [
            vr::FX,
            vr::TORQUE1,
            vr::TORQUE2,
            vr::U,
            vr::DU,
            vr::POWER_LOSS,
        ];
        let mut o = [0.0; 6];
        f.get_real(&vrs, &mut o, &mut NullLogger).unwrap();
        let (u1, u2) = (600.0 * 0.033, 270.0 * 0.0714);
        assert!((o[3] - 0.5 * (u1 + u2)).abs() < 1e-12 && (o[4] - (u1 - u2)).abs() < 1e-12);
        assert!(o[0] > 0.0, "body 1 is faster: it drives body 2 forward");
        assert!((o[1] + o[0] * 0.033).abs() < 1e-12 && (o[2] - o[0] * 0.0714).abs() < 1e-12);
        // Power balance: the loss is what the two torques take out of the bodies.
        let p = -(o[1] * 600.0 + o[2] * 270.0);
        assert!(
            (o[5] - p).abs() < 1e-9 * p.abs().max(1.0),
            "{} vs {p}",
            o[5]
        );
        // The contact equals the seam evaluated directly.
        let c = Contact::new(&f.physics_parameters().unwrap()).unwrap();
        let d = c
            .evaluate(&physics::Inputs {
                load: 500.0,
                u: o[3],
                du: o[4],
                dv: 0.0,
                omega: 0.0,
                inlet_temperature_celsius: 40.0,
            })
            .unwrap();
        assert_eq!(d.fx, o[0]);
    }

    #[test]
    fn skew_angle_and_tilt_geometry_sources() {
        let mut f = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
        f.set_integer(&[vr::SIDE_SLIP_SOURCE, vr::SPIN_SOURCE], &[2, 2])
            .unwrap();
        f.set_real(
            &[vr::TILT_ANGLE, vr::TILT_OFFSET, vr::SKEW_ANGLE],
            &[0.1, 0.0104, 0.01],
        )
        .unwrap();
        f.set_real(&[vr::OMEGA1, vr::OMEGA2], &[600.0, 600.0 * 0.033 / 0.0714])
            .unwrap();
        f.enter_initialization_mode().unwrap();
        let mut log = Capture(Vec::new());
        assert_eq!(f.exit_initialization_mode(&mut log).unwrap(), Status::Ok);
        assert!(log.0.is_empty(), "{:?}", log.0);
        let mut o = [0.0; 5];
        f.get_real(
            &[vr::U, vr::DV, vr::OMEGA, vr::MZ, vr::POWER_LOSS],
            &mut o,
            &mut log,
        )
        .unwrap();
        assert!((o[1] - o[0] * 0.01_f64.tan()).abs() < 1e-12);
        let w = o[0] * 0.1_f64.sin() / (0.0226 * 0.1_f64.cos() + 0.0104);
        assert!((o[2] - w).abs() < 1e-9);
        assert!(o[3] != 0.0, "spin gives a spin moment");
        assert!(o[4] >= 0.0);
        assert!(f.set_integer(&[vr::FLUID], &[9]).is_err());
    }

    #[test]
    fn report_fluid_through_start_up_warns_once_and_stays_finite() {
        let mut f = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
        f.set_integer(&[vr::FLUID], &[1]).unwrap(); // Santotrac 50, clamp (default)
        f.set_real(&[vr::OMEGA1, vr::OMEGA2], &[0.0, 0.0]).unwrap();
        f.enter_initialization_mode().unwrap();
        let mut log = Capture(Vec::new());
        f.exit_initialization_mode(&mut log).unwrap();
        let all: Vec<u32> = (vr::FX..=vr::MU_FORCE).chain(vr::J1..=vr::J7).collect();
        let mut o = vec![0.0; all.len()];
        for k in 0..200 {
            // Run up from rest with 1 % slip.
            let w1 = f64::from(k) * 3.0;
            f.set_real(&[vr::OMEGA1, vr::OMEGA2], &[w1, 0.99 * w1 * 0.033 / 0.0714])
                .unwrap();
            f.do_step(f64::from(k) * 1e-3, 1e-3, &mut log).unwrap();
            f.get_real(&all, &mut o, &mut log).unwrap();
            assert!(o.iter().all(|x| x.is_finite()));
        }
        assert_eq!(log.0.len(), 1, "{:?}", log.0);
        assert_eq!(log.0[0].0, Status::Warning);
        assert!(o[0] > 0.0 && o[16] > 0.0 && o[17] > 0.0, "fx, m, mu: {o:?}");
        // Strict envelope: the same start-up is an error naming the quantity.
        let mut g = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
        g.set_integer(&[vr::FLUID, vr::ENVELOPE], &[1, 1]).unwrap();
        g.enter_initialization_mode().unwrap();
        let e = g.exit_initialization_mode(&mut log).unwrap_err();
        assert!(e.message.contains("fluid correlation"), "{e}");
    }

    #[test]
    fn state_round_trip_is_bit_exact() {
        let mut f = initialized();
        f.set_real(&[vr::OMEGA1, vr::OMEGA2, vr::LOAD], &[612.3, 270.1, 1234.5])
            .unwrap();
        f.do_step(0.0, 0.1, &mut NullLogger).unwrap();
        let s = f.get_state().unwrap();
        let bytes = TractionFmu::serialize_state(&s);
        let back = TractionFmu::deserialize_state(&bytes).unwrap();
        assert_eq!(TractionFmu::serialize_state(&back), bytes);
        let mut o1 = [0.0; N_OUT];
        let all: Vec<u32> = (vr::FX..=vr::MU_FORCE).chain(vr::J1..=vr::J7).collect();
        f.do_step(0.1, 0.1, &mut NullLogger).unwrap();
        f.get_real(&all, &mut o1, &mut NullLogger).unwrap();
        f.set_real(&[vr::OMEGA1], &[1.0]).unwrap();
        f.do_step(0.2, 0.1, &mut NullLogger).unwrap();
        f.set_state(&back).unwrap();
        f.do_step(0.1, 0.1, &mut NullLogger).unwrap();
        let mut o2 = [0.0; N_OUT];
        f.get_real(&all, &mut o2, &mut NullLogger).unwrap();
        assert_eq!(o1.map(f64::to_bits), o2.map(f64::to_bits));
        let mut corrupt = bytes.clone();
        corrupt[20] ^= 1;
        assert!(TractionFmu::deserialize_state(&corrupt).is_err());
        assert!(TractionFmu::deserialize_state(&bytes[..10]).is_err());
    }

    #[test]
    fn invalid_values_are_errors_that_name_the_variable() {
        let mut f = initialized();
        let e = f.set_real(&[vr::LOAD], &[f64::NAN]).unwrap_err();
        assert!(e.message.contains("normal_load"));
        assert_eq!(f.mode(), Mode::Error);
        let mut f = initialized();
        assert!(
            f.set_real(&[vr::FX], &[1.0])
                .unwrap_err()
                .message
                .contains("output")
        );
        let mut f = initialized();
        assert!(
            f.set_real(&[9999], &[1.0])
                .unwrap_err()
                .message
                .contains("9999")
        );
        let mut f = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
        f.set_real(&[vr::MU_USER], &[2.0]).unwrap();
        f.enter_initialization_mode().unwrap();
        assert!(
            f.exit_initialization_mode(&mut NullLogger)
                .unwrap_err()
                .message
                .contains("mu_user")
        );
    }

    /// Body 1 and body 2 of the default parameters (ry2 = 0 is flat).
    fn default_bodies(e2: f64, nu2: f64) -> (traction_contact::Body, traction_contact::Body) {
        (
            traction_contact::Body::new(0.033, 0.0226, 2.07e11, 0.3),
            traction_contact::Body::new(0.0714, f64::INFINITY, e2, nu2),
        )
    }

    /// An instance with the given parameters set before initialization, the
    /// operating point of the tests (U ≈ 19.5 m/s, slip, side slip, spin),
    /// initialized; returns it with all Real outputs.
    fn run(
        reals: &[(u32, f64)],
        ints: &[(u32, i32)],
        bools: &[(u32, bool)],
    ) -> Result<(TractionFmu, Vec<f64>), FmuError> {
        let mut f = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
        for &(r, x) in reals {
            f.set_real(&[r], &[x])?;
        }
        for &(r, x) in ints {
            f.set_integer(&[r], &[x])?;
        }
        for &(r, x) in bools {
            f.set_boolean(&[r], &[x])?;
        }
        f.set_real(
            &[vr::OMEGA1, vr::OMEGA2, vr::SIDE_SLIP_VELOCITY, vr::SPIN],
            &[600.0, 270.0, 0.05, 20.0],
        )?;
        f.enter_initialization_mode()?;
        f.exit_initialization_mode(&mut NullLogger)?;
        let all: Vec<u32> = (vr::FX..=vr::MU_FORCE).chain(vr::J1..=vr::J7).collect();
        let mut o = vec![0.0; all.len()];
        f.get_real(&all, &mut o, &mut NullLogger)?;
        Ok((f, o))
    }

    /// traction-contact evaluated directly at the FMU's operating point
    /// (U, dU, dV, omega read back from the FMU's outputs).
    fn direct(c: &traction_contact::TractionContact, o: &[f64]) -> traction_contact::Evaluation {
        let i = |r: u32| o[out_index(r).unwrap()];
        let state = traction_contact::OperatingState::new(
            500.0,
            i(vr::U),
            i(vr::DU),
            i(vr::DV),
            i(vr::OMEGA),
            40.0,
        )
        .unwrap();
        c.evaluate(&state).unwrap()
    }

    /// FMU outputs against a traction-contact evaluation: forces, moment,
    /// J1..J7, m, mu and mu_f to 1e-12 relative (the FMU adds no arithmetic
    /// to these beyond copying; the bound leaves room for nothing else).
    fn assert_matches(o: &[f64], d: &traction_contact::Evaluation) {
        let i = |r: u32| o[out_index(r).unwrap()];
        let pairs = [
            ("fx", i(vr::FX), d.fx),
            ("fy", i(vr::FY), d.fy),
            ("mz", i(vr::MZ), d.mz),
            ("m", i(vr::M_USED), d.m_used),
            ("mu", i(vr::MU_USED), d.mu_used),
            ("mu_force", i(vr::MU_FORCE), d.mu_force),
            ("J1", i(vr::J1), d.j1),
            ("J2", i(vr::J1 + 1), d.j2),
            ("J3", i(vr::J1 + 2), d.j3),
            ("J4", i(vr::J1 + 3), d.j4),
            ("J5", i(vr::J1 + 4), d.j5),
            ("J6", i(vr::J1 + 5), d.j6),
            ("J7", i(vr::J7), d.j7),
        ];
        for (name, fmu, contact) in pairs {
            assert!(
                (fmu - contact).abs() <= 1e-12 * contact.abs(),
                "{name}: FMU {fmu} vs traction-contact {contact}"
            );
        }
    }

    fn user_fluid() -> traction_contact::Fluid {
        traction_contact::Fluid::constant(35.0, 0.075).unwrap()
    }

    /// The FMU's default options (rheology_map on, tolerance 1e-4).
    fn options(model: traction_contact::Model) -> traction_contact::Options {
        traction_contact::Options {
            model,
            rolling_speed_floor: 0.01,
            map: true,
            ..traction_contact::Options::default()
        }
    }

    #[test]
    fn viscoelastic_equals_traction_contact_and_infinite_deborah_is_elastic_plastic() {
        let (d, z0) = (0.5, 0.3);
        let (_, visco) = run(&[(vr::DEBORAH, d), (vr::Z0, z0)], &[(vr::RHEOLOGY, 3)], &[]).unwrap();
        let (b1, b2) = default_bodies(2.07e11, 0.3);
        let model = traction_contact::Model::Viscoelastic { deborah: d, z0 };
        let c =
            traction_contact::TractionContact::new(&b1, &b2, user_fluid(), options(model)).unwrap();
        assert_matches(&visco, &direct(&c, &visco));
        // D = inf through fmi2SetReal: the elastic/plastic model.
        let (_, inf) = run(
            &[(vr::DEBORAH, f64::INFINITY), (vr::Z0, z0)],
            &[(vr::RHEOLOGY, 3)],
            &[],
        )
        .unwrap();
        let (_, ep) = run(&[], &[(vr::RHEOLOGY, 1)], &[]).unwrap();
        assert_eq!(inf, ep);
        let c = traction_contact::TractionContact::new(
            &b1,
            &b2,
            user_fluid(),
            options(traction_contact::Model::ElasticPlastic),
        )
        .unwrap();
        assert_matches(&ep, &direct(&c, &ep));
        // A finite D relaxes the stress: less traction than elastic/plastic.
        let fx = out_index(vr::FX).unwrap();
        assert!(visco[fx] < ep[fx] * 0.99, "{} vs {}", visco[fx], ep[fx]);
        // Bad D or Z0: fmi2Error at initialization naming the parameter.
        for (r, x, name) in [
            (vr::DEBORAH, -1.0, "deborah"),
            (vr::DEBORAH, 0.0, "deborah"),
            (vr::DEBORAH, f64::NEG_INFINITY, "deborah"),
            (vr::Z0, -0.3, "z0"),
        ] {
            let e = run(&[(r, x)], &[(vr::RHEOLOGY, 3)], &[]).unwrap_err();
            assert_eq!(e.status, Status::Error);
            assert!(e.message.contains(name), "{e}");
        }
        let mut f = TractionFmu::instantiate("t", &crate::model_description::guid()).unwrap();
        let e = f.set_real(&[vr::DEBORAH], &[f64::NAN]).unwrap_err();
        assert!(e.message.contains("deborah"), "{e}");
    }

    #[test]
    fn rheology_map_and_tolerance_parameters() {
        // rheology_map off: traction-contact without the map, bit-identical;
        // on (the default): within 2·tol = 2e-4 of it in J4..J6 (both are
        // within tol of the converged solution; spin 20 rad/s, side slip);
        // rheology_tolerance
        // reaches the contact (1e-3: same as traction-contact at 1e-3); out
        // of [1e-6, 1e-2] it is refused with a message naming it.
        let (b1, b2) = default_bodies(2.07e11, 0.3);
        let ep = traction_contact::Model::ElasticPlastic;
        let contact = |map: bool, tol: f64| {
            traction_contact::TractionContact::new(
                &b1,
                &b2,
                user_fluid(),
                traction_contact::Options {
                    map,
                    accuracy: traction_contact::Accuracy::new(tol).unwrap(),
                    ..options(ep)
                },
            )
            .unwrap()
        };
        let (_, off) = run(&[], &[], &[(vr::RHEOLOGY_MAP, false)]).unwrap();
        assert_matches(&off, &direct(&contact(false, 1e-4), &off));
        let (_, on) = run(&[], &[], &[]).unwrap();
        for n in 3..6 {
            let (a, b) = (
                on[out_index(vr::J1 + n).unwrap()],
                off[out_index(vr::J1 + n).unwrap()],
            );
            assert!((a - b).abs() <= 2e-4, "J{}: {a} vs {b}", n + 1);
        }
        assert!(
            on[out_index(vr::J1 + 2).unwrap()].abs() > 0.1,
            "no spin: vacuous"
        );
        let (_, coarse) = run(&[(vr::RHEOLOGY_TOLERANCE, 1e-3)], &[], &[]).unwrap();
        assert_matches(&coarse, &direct(&contact(true, 1e-3), &coarse));
        for bad in [1e-8, 0.5] {
            let e = run(&[(vr::RHEOLOGY_TOLERANCE, bad)], &[], &[]).unwrap_err();
            assert!(e.message.contains("rheology_tolerance"), "{e}");
        }
    }

    #[test]
    fn spin_peak_equals_traction_contact() {
        // User fluid: forces scaled by mu_spin_user, J groups by mu_user.
        let (_, o) = run(&[(vr::MU_SPIN_USER, 0.06)], &[], &[(vr::SPIN_PEAK, true)]).unwrap();
        let (b1, b2) = default_bodies(2.07e11, 0.3);
        let fluid = user_fluid().with_spin_peak(0.06).unwrap();
        let c = traction_contact::TractionContact::new(
            &b1,
            &b2,
            fluid,
            options(traction_contact::Model::ElasticPlastic),
        )
        .unwrap();
        assert_matches(&o, &direct(&c, &o));
        assert_eq!(o[out_index(vr::MU_FORCE).unwrap()], 0.06);
        assert_eq!(o[out_index(vr::MU_USED).unwrap()], 0.075);
        // Off (default): mu_spin_user is ignored and mu_f = mu.
        let (_, off) = run(&[(vr::MU_SPIN_USER, 0.06)], &[], &[]).unwrap();
        assert_eq!(off[out_index(vr::MU_FORCE).unwrap()], 0.075);
        // TDF-88: its spin-peak correlation.
        let (_, o) = run(&[], &[(vr::FLUID, 2)], &[(vr::SPIN_PEAK, true)]).unwrap();
        let fluid = traction_contact::Fluid::tdf_88(traction_contact::EnvelopeRule::Clamp)
            .unwrap()
            .use_spin_peak(true);
        let c = traction_contact::TractionContact::new(
            &b1,
            &b2,
            fluid,
            options(traction_contact::Model::ElasticPlastic),
        )
        .unwrap();
        let d = direct(&c, &o);
        assert_matches(&o, &d);
        assert!(d.mu_force != d.mu_used, "the correlation is used");
        // Out of range: error naming the parameter.
        let e = run(&[(vr::MU_SPIN_USER, 1.5)], &[], &[(vr::SPIN_PEAK, true)]).unwrap_err();
        assert!(e.message.contains("mu_spin_user"), "{e}");
    }

    #[test]
    fn compliance_uses_both_bodies_materials() {
        // Steel on a softer body 2 (E 110 GPa, nu 0.34), compliance on.
        let (e2, nu2) = (1.1e11, 0.34);
        let (_, o) = run(
            &[(vr::E2, e2), (vr::NU2, nu2)],
            &[],
            &[(vr::COMPLIANCE, true)],
        )
        .unwrap();
        // Kalker's combined constants, computed here by hand.
        let (g1, g2) = (2.07e11 / 2.6, e2 / (2.0 * (1.0 + nu2)));
        let g = 1.0 / (0.5 * (1.0 / g1 + 1.0 / g2));
        let nu = 0.5 * g * (0.3 / g1 + nu2 / g2);
        let material = traction_contact::DiscMaterial {
            youngs_modulus: 2.0 * g * (1.0 + nu),
            poisson_ratio: nu,
        };
        let (b1, b2) = default_bodies(e2, nu2);
        let compliant = |material| traction_contact::Options {
            compliance: traction_contact::Compliance::Discs {
                material,
                slope_measured_in: traction_contact::Direction::Side,
            },
            ..options(traction_contact::Model::ElasticPlastic)
        };
        let c = traction_contact::TractionContact::new(&b1, &b2, user_fluid(), compliant(material))
            .unwrap();
        let d = direct(&c, &o);
        assert_matches(&o, &d);
        // Not body 1's material alone (the previous assumption).
        let body1 = traction_contact::DiscMaterial {
            youngs_modulus: 2.07e11,
            poisson_ratio: 0.3,
        };
        let c1 = traction_contact::TractionContact::new(&b1, &b2, user_fluid(), compliant(body1))
            .unwrap();
        let d1 = direct(&c1, &o);
        assert!((d1.m_used - d.m_used).abs() > 1e-3 * d.m_used);
        // Symmetric in the two bodies; identical bodies give their own material.
        let m12 = physics::kalker_combined(2.07e11, 0.3, e2, nu2);
        let m21 = physics::kalker_combined(e2, nu2, 2.07e11, 0.3);
        assert!((m12.youngs_modulus / m21.youngs_modulus - 1.0).abs() < 1e-15);
        assert!((m12.poisson_ratio - m21.poisson_ratio).abs() < 1e-15);
        assert!((m12.youngs_modulus / material.youngs_modulus - 1.0).abs() < 1e-14);
        assert_eq!(physics::kalker_combined(2.07e11, 0.3, 2.07e11, 0.3), body1);
    }
}
