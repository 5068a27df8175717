//! The C boundary: hand-written FMI 2.0 types and the 34 exported functions
//! of an FMI 2.0 co-simulation FMU (common + co-simulation API).
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
//! The instance is a `Box` owned by the host through the `fmi2Component`
//! pointer; no global or thread-local state exists.
#![allow(unsafe_code)]

use std::ffi::{CStr, CString, c_char, c_int, c_uint, c_void};
use std::panic::{AssertUnwindSafe, catch_unwind};

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

/// `fmi2Component`: an instance created by [`fmi2Instantiate`].
pub type Fmi2Component = *mut c_void;
/// `fmi2ComponentEnvironment`: the host's pointer passed back to callbacks.
pub type Fmi2ComponentEnvironment = *mut c_void;
/// `fmi2FMUstate`: a state created by [`fmi2GetFMUstate`].
pub type Fmi2FmuState = *mut c_void;
/// `fmi2ValueReference`.
pub type Fmi2ValueReference = c_uint;
/// `fmi2Real`.
pub type Fmi2Real = f64;
/// `fmi2Integer`.
pub type Fmi2Integer = c_int;
/// `fmi2Boolean` (`fmi2True` = 1, `fmi2False` = 0).
pub type Fmi2Boolean = c_int;
/// `fmi2String`.
pub type Fmi2String = *const c_char;
/// `fmi2Byte`.
pub type Fmi2Byte = c_char;
/// `fmi2Status` (see the `FMI2_*` constants).
pub type Fmi2Status = c_int;
/// `fmi2Type`: 0 model exchange, 1 co-simulation.
pub type Fmi2Type = c_int;
/// `fmi2StatusKind`.
pub type Fmi2StatusKind = c_int;

/// fmi2OK.
pub const FMI2_OK: Fmi2Status = 0;
/// fmi2Warning.
pub const FMI2_WARNING: Fmi2Status = 1;
/// fmi2Discard.
pub const FMI2_DISCARD: Fmi2Status = 2;
/// fmi2Error.
pub const FMI2_ERROR: Fmi2Status = 3;
/// fmi2Fatal.
pub const FMI2_FATAL: Fmi2Status = 4;
/// fmi2Pending.
pub const FMI2_PENDING: Fmi2Status = 5;
/// fmi2CoSimulation.
pub const FMI2_COSIMULATION: Fmi2Type = 1;
/// fmi2DoStepStatus.
pub const FMI2_DO_STEP_STATUS: Fmi2StatusKind = 0;
/// fmi2PendingStatus.
pub const FMI2_PENDING_STATUS: Fmi2StatusKind = 1;
/// fmi2LastSuccessfulTime.
pub const FMI2_LAST_SUCCESSFUL_TIME: Fmi2StatusKind = 2;
/// fmi2Terminated.
pub const FMI2_TERMINATED: Fmi2StatusKind = 3;

/// `fmi2CallbackLogger` (variadic: the message is a printf format).
pub type Fmi2CallbackLogger = Option<
    unsafe extern "C" fn(
        Fmi2ComponentEnvironment,
        Fmi2String,
        Fmi2Status,
        Fmi2String,
        Fmi2String,
        ...
    ),
>;
/// `fmi2CallbackAllocateMemory`.
pub type Fmi2CallbackAllocateMemory = Option<unsafe extern "C" fn(usize, usize) -> *mut c_void>;
/// `fmi2CallbackFreeMemory`.
pub type Fmi2CallbackFreeMemory = Option<unsafe extern "C" fn(*mut c_void)>;
/// `fmi2StepFinished`.
pub type Fmi2StepFinished = Option<unsafe extern "C" fn(Fmi2ComponentEnvironment, Fmi2Status)>;

/// `fmi2CallbackFunctions`. This FMU uses only `logger` and
/// `componentEnvironment` (it declares canNotUseMemoryManagementFunctions).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct Fmi2CallbackFunctions {
    /// Logger (may be NULL: then nothing is logged).
    pub logger: Fmi2CallbackLogger,
    /// Not used.
    pub allocate_memory: Fmi2CallbackAllocateMemory,
    /// Not used.
    pub free_memory: Fmi2CallbackFreeMemory,
    /// Not used (no asynchronous steps).
    pub step_finished: Fmi2StepFinished,
    /// Passed back to the logger.
    pub component_environment: Fmi2ComponentEnvironment,
}

const INSTANCE_MAGIC: u64 = 0x5452_4143_5449_4f4e; // "TRACTION"
const STATE_MAGIC: u64 = 0x5452_4143_5354_4154; // "TRACSTAT"

/// The host's logger, bound to one instance.
struct HostLogger {
    logger: Fmi2CallbackLogger,
    env: Fmi2ComponentEnvironment,
    name: CString,
    debug: bool,
    /// Enabled categories (index into [`LOG_CATEGORIES`]).
    enabled: [bool; LOG_CATEGORIES.len()],
}

/// Makes a C string of any text: `%` doubled, NUL bytes replaced.
fn c_text(s: &str, escape_percent: bool) -> CString {
    let mut t = if escape_percent {
        s.replace('%', "%%")
    } else {
        s.to_owned()
    };
    if t.contains('\0') {
        t = t.replace('\0', "\u{fffd}");
    }
    CString::new(t).unwrap_or_default()
}

/// The category of the call trace.
const TRACE_CATEGORY: &str = "logAll";

impl HostLogger {
    /// Whether calls are traced: a logger, debug logging on and `logAll`
    /// enabled.
    fn tracing(&self) -> bool {
        self.logger.is_some()
            && self.debug
            && LOG_CATEGORIES
                .iter()
                .position(|c| c.0 == TRACE_CATEGORY)
                .is_some_and(|i| self.enabled[i])
    }
}

impl Logger for HostLogger {
    fn log(&mut self, status: Status, category: &str, message: &str) {
        let Some(f) = self.logger else { return };
        // Errors and warnings are always reported; the trace (logAll) only when
        // debug logging is on and the category is enabled.
        let idx = LOG_CATEGORIES.iter().position(|c| c.0 == category);
        let always = status >= Status::Warning;
        if !(always || (self.debug && idx.is_some_and(|i| self.enabled[i]))) {
            return;
        }
        let cat = c_text(category, false);
        let msg = c_text(message, true);
        // SAFETY: the host gave us this logger with the environment pointer; all
        // strings are valid NUL-terminated C strings that outlive the call.
        unsafe {
            f(
                self.env,
                self.name.as_ptr(),
                status as Fmi2Status,
                cat.as_ptr(),
                msg.as_ptr(),
            )
        };
    }
}

struct Instance {
    magic: u64,
    model: TractionFmu,
    log: HostLogger,
}

struct StateBox {
    magic: u64,
    state: Snapshot,
}

fn category(status: Status) -> &'static str {
    match status {
        Status::Fatal => "logStatusFatal",
        Status::Warning => "logStatusWarning",
        _ => "logStatusError",
    }
}

fn panic_message(p: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = p.downcast_ref::<&str>() {
        (*s).to_owned()
    } else if let Some(s) = p.downcast_ref::<String>() {
        s.clone()
    } else {
        "unknown panic payload".to_owned()
    }
}

/// The instance behind `c`; None for NULL or a pointer without the
/// instance's magic number (most misuse: a freed or foreign pointer).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
unsafe fn instance<'a>(c: Fmi2Component) -> Option<&'a mut Instance> {
    if c.is_null() {
        return None;
    }
    // SAFETY: a non-NULL fmi2Component is the pointer fmi2Instantiate
    // returned (the caller's contract).
    let inst = unsafe { &mut *c.cast::<Instance>() };
    (inst.magic == INSTANCE_MAGIC).then_some(inst)
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
    let result = catch_unwind(AssertUnwindSafe(|| f(&mut *inst)));
    match result {
        Ok(Ok(status)) => status as Fmi2Status,
        Ok(Err(e)) => {
            let e = inst.model.enter_error_state(e);
            inst.log.log(e.status, category(e.status), &e.message);
            e.status as Fmi2Status
        }
        Err(payload) => {
            inst.model.poison();
            let msg = format!(
                "{func}: internal error (caught panic: {}); the instance is unusable",
                panic_message(&*payload)
            );
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
    if n == 0 {
        Ok(&[])
    } else if p.is_null() {
        Err(null_arg(func, what))
    } else {
        // SAFETY: caller guarantees n valid elements.
        Ok(unsafe { std::slice::from_raw_parts(p, n) })
    }
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
    if n == 0 {
        Ok(&mut [])
    } else if p.is_null() {
        Err(null_arg(func, what))
    } else {
        // SAFETY: caller guarantees n valid elements.
        Ok(unsafe { std::slice::from_raw_parts_mut(p, n) })
    }
}

/// # Safety
/// `s` NULL or a NUL-terminated string.
unsafe fn opt_str<'a>(s: *const c_char) -> Option<&'a str> {
    if s.is_null() {
        None
    } else {
        // SAFETY: non-NULL fmi2String arguments are NUL-terminated.
        unsafe { CStr::from_ptr(s) }.to_str().ok()
    }
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
