//! The safe side of the FMU: the [`CoSimulation`] trait and the traction
//! contact instance [`TractionFmu`] with the FMI 2 co-simulation state machine.
//!
//! Nothing here is `unsafe` and nothing is global: each instance owns all its
//! data, so instances are independent and may be driven from different
//! threads one at a time. The C wrappers in [`crate::ffi`] only translate
//! pointers to slices and strings and call these methods.

mod instance;
mod snapshot;
#[cfg(test)]
mod tests;

pub use instance::{SideSlipSource, SpinSource, TractionFmu};
pub use snapshot::Snapshot;

pub use traction_fmi_support::{FmuError, FmuResult, Logger, Mode, NullLogger, Status};

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
    /// Enters the error state (the fatal state for an fmi2Fatal `error`; a
    /// fatal state stays fatal) for a call refused outside the model (a NULL
    /// argument, an unsupported function), as the model's own refusals do;
    /// returns `error` with the status it now has.
    fn enter_error_state(&mut self, error: FmuError) -> FmuError;
}
