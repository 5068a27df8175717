//! The C boundary: the 34 exported functions of an FMI 2.0 co-simulation FMU
//! (common + co-simulation API), on the hand-written FMI 2.0 types and
//! guards of `traction_fmi_support::ffi` (shared with the variator FMU).
//!
//! Every entry point is a thin wrapper: it checks its pointers, turns them
//! into slices and strings, calls one method of the safe
//! [`CoSimulation`] trait inside [`std::panic::catch_unwind`], and reports a
//! failure through the host's logger (category `logStatusError` or
//! `logStatusFatal`, `%` escaped as `%%` because FMI loggers treat the
//! message as a printf format) with `fmi2Error`/`fmi2Fatal`. A caught panic
//! poisons the instance (`fmi2Fatal`; only `fmi2FreeInstance` remains
//! allowed). Functions this FMU does not support (directional derivatives,
//! input/output derivatives, asynchronous steps, string variables) return
//! `fmi2Error` with a logged message, never `fmi2OK`.
//!
//! The instance is a magic-tagged `Box` owned by the host through the
//! `fmi2Component` pointer; no global or thread-local state exists.
#![allow(unsafe_code)]

use std::ffi::c_char;
use std::panic::catch_unwind;

use traction_fmi_support::ffi::{self as support, HostCallback, guarded, opt_str};
pub use traction_fmi_support::ffi::{
    FMI2_COSIMULATION, FMI2_DISCARD, FMI2_DO_STEP_STATUS, FMI2_ERROR, FMI2_FATAL,
    FMI2_LAST_SUCCESSFUL_TIME, FMI2_OK, FMI2_PENDING, FMI2_PENDING_STATUS, FMI2_TERMINATED,
    FMI2_WARNING, Fmi2Boolean, Fmi2Byte, Fmi2CallbackAllocateMemory, Fmi2CallbackFreeMemory,
    Fmi2CallbackFunctions, Fmi2CallbackLogger, Fmi2Component, Fmi2ComponentEnvironment,
    Fmi2FmuState, Fmi2Integer, Fmi2Real, Fmi2Status, Fmi2StatusKind, Fmi2StepFinished, Fmi2String,
    Fmi2Type, Fmi2ValueReference,
};

use crate::model::{CoSimulation, FmuError, FmuResult, Logger, Snapshot, Status, TractionFmu};
use crate::model_description::LOG_CATEGORIES;

mod cosim;
mod lifecycle;
mod state;
mod values;

pub use cosim::*;
pub use lifecycle::*;
pub use state::*;
pub use values::*;

const INSTANCE_MAGIC: u64 = 0x5452_4143_5449_4f4e; // "TRACTION"
const STATE_MAGIC: u64 = 0x5452_4143_5354_4154; // "TRACSTAT"

/// The host's logger, bound to one instance, with this FMU's filter: errors
/// and warnings always, the rest (the `logAll` trace) only with debug
/// logging on and its category enabled.
struct HostLogger {
    host: HostCallback,
    debug: bool,
    /// Enabled categories (index into [`LOG_CATEGORIES`]).
    enabled: [bool; LOG_CATEGORIES.len()],
}

/// The category of the call trace.
const TRACE_CATEGORY: &str = "logAll";

impl HostLogger {
    /// Whether calls are traced: a logger, debug logging on and `logAll`
    /// enabled.
    fn tracing(&self) -> bool {
        self.host.has_logger()
            && self.debug
            && LOG_CATEGORIES
                .iter()
                .position(|c| c.0 == TRACE_CATEGORY)
                .is_some_and(|i| self.enabled[i])
    }
}

impl Logger for HostLogger {
    fn log(&mut self, status: Status, category: &str, message: &str) {
        // Errors and warnings are always reported; the trace (logAll) only when
        // debug logging is on and the category is enabled.
        let idx = LOG_CATEGORIES.iter().position(|c| c.0 == category);
        let always = status >= Status::Warning;
        if always || (self.debug && idx.is_some_and(|i| self.enabled[i])) {
            self.host.send(status, category, message);
        }
    }
}

/// What the host's `fmi2Component` points to (tagged with [`INSTANCE_MAGIC`]).
struct Instance {
    model: TractionFmu,
    log: HostLogger,
}

/// The instance behind `c`; None for NULL or a pointer without the
/// instance's magic number (most misuse: a freed or foreign pointer).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
unsafe fn instance<'a>(c: Fmi2Component) -> Option<&'a mut Instance> {
    // SAFETY: a non-NULL fmi2Component is the pointer fmi2Instantiate
    // returned (the caller's contract).
    unsafe { support::handle_mut(c, INSTANCE_MAGIC) }
}

/// Runs `f` on an instance: the logAll trace of the call (`func(args)`,
/// built only when traced), catch_unwind, logging. Without an instance
/// (NULL) it is fmi2Error with nothing to log through. Every refused call
/// (fmi2Error or fmi2Fatal) leaves the instance in the error (or fatal)
/// state, whichever check refused it.
fn run(
    inst: Option<&mut Instance>,
    func: &str,
    args: impl FnOnce() -> String,
    f: impl FnOnce(&mut Instance) -> FmuResult,
) -> Fmi2Status {
    let Some(inst) = inst else {
        return FMI2_ERROR;
    };
    if inst.log.tracing() {
        let call = format!("{func}({})", args());
        inst.log.log(Status::Ok, TRACE_CATEGORY, &call);
    }
    match guarded(|| f(&mut *inst)) {
        Ok(Ok(status)) => status as Fmi2Status,
        Ok(Err(e)) => {
            let e = inst.model.enter_error_state(e);
            inst.log.log(e.status, e.status.category(), &e.message);
            e.status as Fmi2Status
        }
        Err(panic) => {
            inst.model.poison();
            let msg =
                format!("{func}: internal error (caught panic: {panic}); the instance is unusable");
            inst.log.log(Status::Fatal, "logStatusFatal", &msg);
            FMI2_FATAL
        }
    }
}

fn null_arg(func: &str, what: &str) -> FmuError {
    FmuError::error(format!("{func}: argument {what} is NULL"))
}

/// Turns (pointer, count) into a slice; NULL is allowed only with count 0.
///
/// # Safety
/// `p` must point to `n` valid elements when non-NULL.
unsafe fn slice<'a, T>(p: *const T, n: usize, func: &str, what: &str) -> Result<&'a [T], FmuError> {
    // SAFETY: per this function's contract.
    unsafe { support::slice(p, n) }.ok_or_else(|| null_arg(func, what))
}

/// Mutable version of [`slice`].
///
/// # Safety
/// `p` must point to `n` valid, writable elements when non-NULL.
unsafe fn slice_mut<'a, T>(
    p: *mut T,
    n: usize,
    func: &str,
    what: &str,
) -> Result<&'a mut [T], FmuError> {
    // SAFETY: per this function's contract.
    unsafe { support::slice_mut(p, n) }.ok_or_else(|| null_arg(func, what))
}

/// An fmi2Error for a function this FMU does not support.
///
/// # Safety
/// As [`instance`].
unsafe fn unsupported(c: Fmi2Component, func: &str, why: &str) -> Fmi2Status {
    // SAFETY: per this function's contract.
    let inst = unsafe { instance(c) };
    run(inst, func, String::new, |_| {
        Err(FmuError::error(format!(
            "{func} is not supported by this FMU: {why}"
        )))
    })
}
