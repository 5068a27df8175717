//! [`TractionFmu`]: the traction contact instance, its FMI 2 co-simulation
//! state machine and the translation of its values to and from the physics.

use super::snapshot::{Snapshot, check_enum, check_real};
use super::{CoSimulation, FmuError, FmuResult, Logger, Mode, Status};
use crate::physics::{self, Contact, PhysicsError, UnknownCode};
use crate::variables::{self, Causality, Type, vr};
use traction_contact::{ANGLE_RANGE, OutOfRange, Range, error_chain};

/// An FMU parameter or input outside its range, as the FMU reports it.
fn out_of_range(e: OutOfRange) -> FmuError {
    FmuError::error(e.to_string())
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

/// Where the spin comes from (Enumeration `SpinSource`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpinSource {
    /// The input `spin`.
    Input,
    /// The tilted toroid: ω/U = sin α/(ry1 cos α + e), report eq. 6.
    TiltGeometry,
}

impl TryFrom<i32> for SpinSource {
    type Error = UnknownCode;
    fn try_from(code: i32) -> Result<Self, UnknownCode> {
        match code {
            1 => Ok(Self::Input),
            2 => Ok(Self::TiltGeometry),
            _ => Err(UnknownCode(code)),
        }
    }
}

/// How the side slip is given (Enumeration `SideSlipSource`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SideSlipSource {
    /// The input `side_slip_velocity`.
    Velocity,
    /// The input `skew_angle`: ΔV = U tan β, report eq. 3.
    SkewAngle,
}

impl TryFrom<i32> for SideSlipSource {
    type Error = UnknownCode;
    fn try_from(code: i32) -> Result<Self, UnknownCode> {
        match code {
            1 => Ok(Self::Velocity),
            2 => Ok(Self::SkewAngle),
            _ => Err(UnknownCode(code)),
        }
    }
}

/// Relative tolerance of the communication-point continuity check of
/// fmi2DoStep: a master that computes `t = i h` instead of summing the steps
/// differs from the sum by a few ulp of `t`, far below it.
const CONTINUITY_TOLERANCE: f64 = 1e-9;

fn var(vr: u32, func: &str) -> Result<&'static variables::Variable, FmuError> {
    variables::by_vr(vr)
        .ok_or_else(|| FmuError::error(format!("{func}: unknown value reference {vr}")))
}

impl TractionFmu {
    /// The current lifecycle state.
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// The Real output `vr` as last computed (tests).
    #[cfg(test)]
    pub(super) fn output(&self, vr: u32) -> Option<f64> {
        match variables::slot(vr)? {
            s if s.causality == Causality::Output && s.value_type == Type::Real => {
                Some(self.s.outputs[s.index])
            }
            _ => None,
        }
    }

    /// Enter the error (or fatal) state for `e` and return it. Idempotent in
    /// the error state for non-fatal errors, so getters and refused calls
    /// there leave the mode unchanged; the fatal state stays fatal.
    fn fail(&mut self, mut e: FmuError) -> FmuError {
        if self.mode == Mode::Fatal {
            e.status = Status::Fatal;
        }
        self.mode = if e.status == Status::Fatal {
            Mode::Fatal
        } else {
            Mode::Error
        };
        e
    }

    fn require(&mut self, func: &str, allowed: &[Mode]) -> Result<(), FmuError> {
        self.mode.check(func, allowed).map_err(|e| self.fail(e))
    }

    pub(super) fn physics_parameters(&self) -> Result<physics::Parameters, FmuError> {
        let s = &self.s;
        for (r, name) in [
            (s.param::<{ vr::ROLLING_RADIUS1 }>(), "rolling_radius1"),
            (s.param::<{ vr::ROLLING_RADIUS2 }>(), "rolling_radius2"),
        ] {
            Range::POSITIVE
                .with_unit("m")
                .check(name, r)
                .map_err(out_of_range)?;
        }
        let alpha = s.param::<{ vr::TILT_ANGLE }>();
        ANGLE_RANGE
            .check("spin_tilt_angle", alpha)
            .map_err(out_of_range)?;
        let offset = s.param::<{ vr::TILT_OFFSET }>();
        Range::FINITE
            .with_unit("m")
            .check("spin_center_offset", offset)
            .map_err(out_of_range)?;
        Ok(physics::Parameters {
            rx1: s.param::<{ vr::RX1 }>(),
            ry1: s.param::<{ vr::RY1 }>(),
            rx2: s.param::<{ vr::RX2 }>(),
            ry2: s.param::<{ vr::RY2 }>(),
            e1: s.param::<{ vr::E1 }>(),
            nu1: s.param::<{ vr::NU1 }>(),
            e2: s.param::<{ vr::E2 }>(),
            nu2: s.param::<{ vr::NU2 }>(),
            fluid: s.choice::<{ vr::FLUID }, _>()?,
            envelope: s.choice::<{ vr::ENVELOPE }, _>()?,
            m_user: s.param::<{ vr::M_USER }>(),
            mu_user: s.param::<{ vr::MU_USER }>(),
            rheology: s.choice::<{ vr::RHEOLOGY }, _>()?,
            deborah: s.param::<{ vr::DEBORAH }>(),
            z0: s.param::<{ vr::Z0 }>(),
            spin_peak: s.flag::<{ vr::SPIN_PEAK }>(),
            mu_spin_user: s.param::<{ vr::MU_SPIN_USER }>(),
            compliance: s.flag::<{ vr::COMPLIANCE }>(),
            u_reg: s.param::<{ vr::U_REG }>(),
            tolerance: s.param::<{ vr::RHEOLOGY_TOLERANCE }>(),
            map: s.flag::<{ vr::RHEOLOGY_MAP }>(),
            thermal: s.flag::<{ vr::THERMAL }>(),
            film_thickness: s.param::<{ vr::FILM_THICKNESS }>(),
            fluid_conductivity: s.param::<{ vr::FLUID_CONDUCTIVITY }>(),
            mu_temperature_coefficient: s.param::<{ vr::MU_TEMPERATURE_COEFFICIENT }>(),
            m_temperature_coefficient: s.param::<{ vr::M_TEMPERATURE_COEFFICIENT }>(),
            mu_rise_scale: s.param::<{ vr::MU_RISE_SCALE }>(),
        })
    }

    /// Invalidate the contact (parameters changed), keeping its rheology map
    /// for the next one: the map's values depend only on k and the
    /// tolerance, so a rebuilt contact with the same ones reuses its cells
    /// and its credit (results within the tolerance with or without it).
    fn drop_contact(&mut self) {
        if let Some(m) = self.contact.take().and_then(|c| c.take_map()) {
            self.spare_map = Some(m);
        }
    }

    fn contact(&mut self) -> Result<&Contact, FmuError> {
        if self.contact.is_none() {
            let p = self.physics_parameters()?;
            let c = Contact::new(&p).map_err(|e: PhysicsError| {
                FmuError::error(format!("invalid parameters: {}", error_chain(&e)))
            })?;
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
        let alpha = self.s.param::<{ vr::TILT_ANGLE }>();
        let e = self.s.param::<{ vr::TILT_OFFSET }>();
        let ry = self.s.param::<{ vr::RY1 }>();
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
        let s = &self.s;
        let (r1, r2) = (
            s.param::<{ vr::ROLLING_RADIUS1 }>(),
            s.param::<{ vr::ROLLING_RADIUS2 }>(),
        );
        let (u1, u2) = (
            s.input::<{ vr::OMEGA1 }>() * r1,
            s.input::<{ vr::OMEGA2 }>() * r2,
        );
        let u = 0.5 * (u1 + u2);
        let du = u1 - u2;
        let dv = match s.choice::<{ vr::SIDE_SLIP_SOURCE }, _>()? {
            SideSlipSource::SkewAngle => {
                let beta = s.input::<{ vr::SKEW_ANGLE }>();
                ANGLE_RANGE
                    .check("skew_angle", beta)
                    .map_err(out_of_range)?;
                u * beta.tan()
            }
            SideSlipSource::Velocity => s.input::<{ vr::SIDE_SLIP_VELOCITY }>(),
        };
        let omega = match s.choice::<{ vr::SPIN_SOURCE }, _>()? {
            SpinSource::TiltGeometry => u * self.tilt_spin_per_u()?,
            SpinSource::Input => s.input::<{ vr::SPIN }>(),
        };
        let op = physics::Inputs {
            load: s.input::<{ vr::LOAD }>(),
            u,
            du,
            dv,
            omega,
            inlet_temperature_celsius: s.input::<{ vr::INLET_TEMPERATURE }>(),
        };
        let o = self.contact()?.evaluate(&op).map_err(|e| {
            FmuError::error(format!("contact evaluation failed: {}", error_chain(&e)))
        })?;
        let coef = |f: f64| if op.load > 0.0 { f / op.load } else { 0.0 };
        let s = &mut self.s;
        let previous = s.outputs;
        s.set_output::<{ vr::FX }>(o.fx);
        s.set_output::<{ vr::FY }>(o.fy);
        s.set_output::<{ vr::MZ }>(o.mz);
        s.set_output::<{ vr::TORQUE1 }>(-o.fx * r1);
        s.set_output::<{ vr::TORQUE2 }>(o.fx * r2);
        s.set_output::<{ vr::TRACTION_COEFFICIENT }>(coef(o.fx));
        s.set_output::<{ vr::SIDE_TRACTION_COEFFICIENT }>(coef(o.fy));
        s.set_output::<{ vr::POWER_LOSS }>(o.fx * du + o.fy * dv + o.mz * omega);
        s.set_output::<{ vr::A }>(o.a);
        s.set_output::<{ vr::B }>(o.b);
        s.set_output::<{ vr::K }>(o.k);
        s.set_output::<{ vr::P0 }>(o.p0);
        s.set_output::<{ vr::U }>(u);
        s.set_output::<{ vr::DU }>(du);
        s.set_output::<{ vr::DV }>(dv);
        s.set_output::<{ vr::OMEGA }>(omega);
        s.set_output::<{ vr::M_USED }>(o.m);
        s.set_output::<{ vr::MU_USED }>(o.mu);
        s.set_output::<{ vr::MU_FORCE }>(o.mu_force);
        s.set_output::<{ vr::TEMPERATURE_RISE }>(o.temperature_rise);
        s.set_output::<{ vr::J1 }>(o.j[0]);
        s.set_output::<{ vr::J2 }>(o.j[1]);
        s.set_output::<{ vr::J3 }>(o.j[2]);
        s.set_output::<{ vr::J4 }>(o.j[3]);
        s.set_output::<{ vr::J5 }>(o.j[4]);
        s.set_output::<{ vr::J6 }>(o.j[5]);
        s.set_output::<{ vr::J7 }>(o.j[6]);
        if let Some(bad) = s.outputs.iter().position(|v| !v.is_finite()) {
            // Defensive: the physics promises finite outputs for finite
            // inputs. The last finite outputs stay.
            s.outputs = previous;
            return Err(FmuError::error(format!(
                "the contact produced a non-finite output (index {bad}) for load {} N, U {u} m/s, dU {du} m/s, dV {dv} m/s, spin {omega} rad/s",
                op.load
            )));
        }
        s.regime = o.regime.map_or(0, |r| r as i32);
        s.dirty = false;
        if o.outside_envelope && !s.envelope_warned {
            s.envelope_warned = true;
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

/// Whether `vr` is a Real output (its value needs an up-to-date evaluation).
fn is_real_output(vr: u32) -> bool {
    variables::slot(vr)
        .is_some_and(|s| s.causality == Causality::Output && s.value_type == Type::Real)
}

impl CoSimulation for TractionFmu {
    type State = Snapshot;

    fn instantiate(instance_name: &str, guid: &str) -> Result<Self, String> {
        if instance_name.trim().is_empty() {
            return Err(format!(
                "fmi2Instantiate: instanceName {instance_name:?} is blank (FMI 2.0 requires a non-empty name)"
            ));
        }
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
        self.require("fmi2Reset", Mode::NOT_FATAL)?;
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
        self.require("fmi2GetReal", Mode::GET)?;
        let mut status = Status::Ok;
        if self.mode != Mode::Error && vrs.iter().any(|&r| is_real_output(r)) {
            status = self.with_update(log)?;
        }
        for (&r, v) in vrs.iter().zip(values.iter_mut()) {
            *v = match variables::slot(r) {
                Some(s) if s.value_type == Type::Real => match s.causality {
                    Causality::Parameter => self.s.params[s.index],
                    Causality::Input => self.s.inputs[s.index],
                    Causality::Output => self.s.outputs[s.index],
                },
                _ => {
                    let e = FmuError::error(format!(
                        "fmi2GetReal: value reference {r} is not a Real variable of this FMU"
                    ));
                    return Err(self.fail(e));
                }
            };
        }
        Ok(status)
    }

    fn set_real(&mut self, vrs: &[u32], values: &[f64]) -> FmuResult {
        const F: &str = "fmi2SetReal";
        for (&r, &x) in vrs.iter().zip(values) {
            let v = var(r, F).map_err(|e| self.fail(e))?;
            let Some(slot) = variables::slot(r).filter(|s| s.value_type == Type::Real) else {
                return Err(self.fail(FmuError::error(format!(
                    "{F}: {} (value reference {r}) is not a Real",
                    v.name
                ))));
            };
            match v.causality {
                Causality::Output => {
                    return Err(self.fail(FmuError::error(format!(
                        "{F}: {} is an output and cannot be set",
                        v.name
                    ))));
                }
                Causality::Parameter => {
                    self.require("fmi2SetReal of a fixed parameter", Mode::SET_PARAMETER)?;
                    check_real(F, v, x).map_err(|e| self.fail(e))?;
                    self.s.params[slot.index] = x;
                    self.drop_contact();
                }
                Causality::Input => {
                    self.require("fmi2SetReal of an input", Mode::SET_INPUT)?;
                    check_real(F, v, x).map_err(|e| self.fail(e))?;
                    self.s.inputs[slot.index] = x;
                }
            }
            self.s.dirty = true;
        }
        Ok(Status::Ok)
    }

    fn get_integer(&mut self, vrs: &[u32], values: &mut [i32], log: &mut dyn Logger) -> FmuResult {
        self.require("fmi2GetInteger", Mode::GET)?;
        let mut status = Status::Ok;
        if self.mode != Mode::Error && vrs.contains(&vr::REGIME) {
            status = self.with_update(log)?;
        }
        for (&r, v) in vrs.iter().zip(values.iter_mut()) {
            *v = match variables::slot(r) {
                Some(s) if s.value_type == Type::Enumeration => match s.causality {
                    Causality::Output => self.s.regime,
                    _ => self.s.enums[s.index],
                },
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
        const F: &str = "fmi2SetInteger";
        for (&r, &x) in vrs.iter().zip(values) {
            let v = var(r, F).map_err(|e| self.fail(e))?;
            let Some(slot) = variables::slot(r).filter(|s| s.value_type == Type::Enumeration)
            else {
                return Err(self.fail(FmuError::error(format!(
                    "{F}: {} (value reference {r}) is not an Integer or Enumeration",
                    v.name
                ))));
            };
            if v.causality != Causality::Parameter {
                return Err(self.fail(FmuError::error(format!(
                    "{F}: {} is an output and cannot be set",
                    v.name
                ))));
            }
            self.require("fmi2SetInteger of a fixed parameter", Mode::SET_PARAMETER)?;
            check_enum(F, v, x).map_err(|e| self.fail(e))?;
            self.s.enums[slot.index] = x;
            self.drop_contact();
            self.s.dirty = true;
        }
        Ok(Status::Ok)
    }

    fn get_boolean(&mut self, vrs: &[u32], values: &mut [bool]) -> FmuResult {
        self.require("fmi2GetBoolean", Mode::GET)?;
        for (&r, v) in vrs.iter().zip(values.iter_mut()) {
            *v = match variables::slot(r) {
                Some(s) if s.value_type == Type::Boolean => self.s.flags[s.index],
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
            let Some(slot) = variables::slot(r).filter(|s| s.value_type == Type::Boolean) else {
                return Err(self.fail(FmuError::error(format!(
                    "fmi2SetBoolean: value reference {r} is not a Boolean variable of this FMU"
                ))));
            };
            self.require("fmi2SetBoolean of a fixed parameter", Mode::SET_PARAMETER)?;
            self.s.flags[slot.index] = x;
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
        let mut st = self.with_update(log)?;
        let expected = self.s.time;
        if (current_time - expected).abs() > CONTINUITY_TOLERANCE * expected.abs().max(step_size) {
            // An algebraic model: the outputs do not depend on the time, so
            // the step is taken and the master is told
            // (docs/decisions/0050-communication-point-continuity.md).
            log.log(
                Status::Warning,
                "logStatusWarning",
                &format!(
                    "fmi2DoStep: currentCommunicationPoint {current_time} does not continue from the last communication point {expected} (FMI 2.0: the previous currentCommunicationPoint + communicationStepSize, or startTime for the first step); the step is taken from {current_time}"
                ),
            );
            st = Status::Warning;
        }
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
        self.require("fmi2SetFMUstate", Mode::NOT_FATAL)?;
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

    fn enter_error_state(&mut self, error: FmuError) -> FmuError {
        self.fail(error)
    }
}
