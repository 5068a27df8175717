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

/// Runs `f` on the instance behind `c`: pointer check, catch_unwind, logging.
fn with_instance(
    c: Fmi2Component,
    func: &str,
    f: impl FnOnce(&mut Instance) -> FmuResult,
) -> Fmi2Status {
    if c.is_null() {
        // No instance, so no logger to report through.
        return FMI2_ERROR;
    }
    // SAFETY: a non-NULL fmi2Component is the pointer fmi2Instantiate returned
    // (the standard requires it); the magic number catches most misuse.
    let inst = unsafe { &mut *c.cast::<Instance>() };
    if inst.magic != INSTANCE_MAGIC {
        return FMI2_ERROR;
    }
    let result = catch_unwind(AssertUnwindSafe(|| f(&mut *inst)));
    match result {
        Ok(Ok(status)) => status as Fmi2Status,
        Ok(Err(e)) => {
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

fn unsupported(c: Fmi2Component, func: &str, why: &str) -> Fmi2Status {
    with_instance(c, func, |_| {
        Err(FmuError::error(format!(
            "{func} is not supported by this FMU: {why}"
        )))
    })
}

// ---------------------------------------------------------------- inquiry

/// `fmi2GetTypesPlatform`: "default".
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
    c"default".as_ptr()
}

/// `fmi2GetVersion`: "2.0".
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetVersion() -> *const c_char {
    c"2.0".as_ptr()
}

// --------------------------------------------------------- instantiation

/// `fmi2Instantiate`: returns NULL (after logging why, if a logger was given)
/// for a NULL/empty instance name or GUID, a model-exchange request, or a GUID
/// of another build.
///
/// # Safety
/// Pointers as in the FMI 2.0 standard: NUL-terminated strings or NULL, and
/// `functions` NULL or a valid `fmi2CallbackFunctions`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Instantiate(
    instance_name: Fmi2String,
    fmu_type: Fmi2Type,
    fmu_guid: Fmi2String,
    _fmu_resource_location: Fmi2String,
    functions: *const Fmi2CallbackFunctions,
    _visible: Fmi2Boolean,
    logging_on: Fmi2Boolean,
) -> Fmi2Component {
    let r = catch_unwind(|| {
        // SAFETY: per the function's contract.
        let callbacks = if functions.is_null() {
            None
        } else {
            Some(unsafe { *functions })
        };
        // SAFETY: NUL-terminated or NULL.
        let name = unsafe { opt_str(instance_name) }.unwrap_or("");
        let mut log = HostLogger {
            logger: callbacks.and_then(|c| c.logger),
            env: callbacks.map_or(std::ptr::null_mut(), |c| c.component_environment),
            name: c_text(
                if name.is_empty() {
                    "TractionContact"
                } else {
                    name
                },
                false,
            ),
            debug: logging_on != 0,
            enabled: [true; LOG_CATEGORIES.len()],
        };
        let fail = |log: &mut HostLogger, m: String| {
            log.log(Status::Error, "logStatusError", &m);
            std::ptr::null_mut()
        };
        if callbacks.is_none() {
            return std::ptr::null_mut();
        }
        if name.is_empty() {
            return fail(
                &mut log,
                "fmi2Instantiate: instanceName is NULL, empty or not UTF-8".into(),
            );
        }
        if fmu_type != FMI2_COSIMULATION {
            return fail(
                &mut log,
                format!(
                    "fmi2Instantiate: fmuType {fmu_type} requested, this FMU supports only co-simulation (1)"
                ),
            );
        }
        // SAFETY: NUL-terminated or NULL.
        let Some(guid) = (unsafe { opt_str(fmu_guid) }) else {
            return fail(&mut log, "fmi2Instantiate: fmuGUID is NULL".into());
        };
        match TractionFmu::instantiate(name, guid) {
            Ok(model) => Box::into_raw(Box::new(Instance {
                magic: INSTANCE_MAGIC,
                model,
                log,
            }))
            .cast::<c_void>(),
            Err(m) => fail(&mut log, m),
        }
    });
    r.unwrap_or(std::ptr::null_mut())
}

/// `fmi2FreeInstance`: frees the instance; NULL is accepted and ignored.
///
/// # Safety
/// `c` NULL or a pointer from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeInstance(c: Fmi2Component) {
    if c.is_null() {
        return;
    }
    let _ = catch_unwind(|| {
        // SAFETY: per contract, c came from Box::into_raw in fmi2Instantiate.
        let mut b = unsafe { Box::from_raw(c.cast::<Instance>()) };
        if b.magic != INSTANCE_MAGIC {
            // Not ours (or freed twice): leak rather than free foreign memory.
            std::mem::forget(b);
            return;
        }
        b.magic = 0;
        drop(b);
    });
}

/// `fmi2SetDebugLogging`: turns the trace on or off; with categories, only
/// those are enabled (unknown category → fmi2Error).
///
/// # Safety
/// `categories` NULL or `n` NUL-terminated strings.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetDebugLogging(
    c: Fmi2Component,
    logging_on: Fmi2Boolean,
    n_categories: usize,
    categories: *const Fmi2String,
) -> Fmi2Status {
    let f = "fmi2SetDebugLogging";
    with_instance(c, f, |inst| {
        // SAFETY: per contract.
        let cats = unsafe { slice(categories, n_categories, f, "categories") }?;
        let mut enabled = [n_categories == 0; LOG_CATEGORIES.len()];
        for &p in cats {
            // SAFETY: per contract.
            let name = unsafe { opt_str(p) }.ok_or_else(|| null_arg(f, "category"))?;
            let i = LOG_CATEGORIES
                .iter()
                .position(|c| c.0 == name)
                .ok_or_else(|| {
                    let known: Vec<&str> = LOG_CATEGORIES.iter().map(|c| c.0).collect();
                    FmuError::error(format!(
                        "{f}: unknown log category {name:?} (known: {})",
                        known.join(", ")
                    ))
                })?;
            enabled[i] = true;
        }
        inst.log.debug = logging_on != 0;
        inst.log.enabled = enabled;
        Ok(Status::Ok)
    })
}

/// `fmi2SetupExperiment`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2SetupExperiment(
    c: Fmi2Component,
    tolerance_defined: Fmi2Boolean,
    tolerance: Fmi2Real,
    start_time: Fmi2Real,
    stop_time_defined: Fmi2Boolean,
    stop_time: Fmi2Real,
) -> Fmi2Status {
    with_instance(c, "fmi2SetupExperiment", |i| {
        let tol = (tolerance_defined != 0).then_some(tolerance);
        let stop = (stop_time_defined != 0).then_some(stop_time);
        i.model.setup_experiment(tol, start_time, stop)
    })
}

/// `fmi2EnterInitializationMode`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2EnterInitializationMode(c: Fmi2Component) -> Fmi2Status {
    with_instance(c, "fmi2EnterInitializationMode", |i| {
        i.model.enter_initialization_mode()
    })
}

/// `fmi2ExitInitializationMode`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2ExitInitializationMode(c: Fmi2Component) -> Fmi2Status {
    with_instance(c, "fmi2ExitInitializationMode", |i| {
        i.model.exit_initialization_mode(&mut i.log)
    })
}

/// `fmi2Terminate`: ends the simulation; frees nothing.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2Terminate(c: Fmi2Component) -> Fmi2Status {
    with_instance(c, "fmi2Terminate", |i| i.model.terminate())
}

/// `fmi2Reset`: back to the instantiated state with start values.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2Reset(c: Fmi2Component) -> Fmi2Status {
    with_instance(c, "fmi2Reset", |i| i.model.reset())
}

// ------------------------------------------------------- get/set values

/// `fmi2GetReal`.
///
/// # Safety
/// `vr` and `value` NULL (only with `nvr` = 0) or arrays of `nvr` elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetReal(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *mut Fmi2Real,
) -> Fmi2Status {
    let f = "fmi2GetReal";
    with_instance(c, f, |i| {
        // SAFETY: per contract.
        let (vr, value) = unsafe { (slice(vr, nvr, f, "vr")?, slice_mut(value, nvr, f, "value")?) };
        i.model.get_real(vr, value, &mut i.log)
    })
}

/// `fmi2GetInteger` (Integer and Enumeration variables).
///
/// # Safety
/// As [`fmi2GetReal`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetInteger(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *mut Fmi2Integer,
) -> Fmi2Status {
    let f = "fmi2GetInteger";
    with_instance(c, f, |i| {
        // SAFETY: per contract.
        let (vr, value) = unsafe { (slice(vr, nvr, f, "vr")?, slice_mut(value, nvr, f, "value")?) };
        i.model.get_integer(vr, value, &mut i.log)
    })
}

/// `fmi2GetBoolean`.
///
/// # Safety
/// As [`fmi2GetReal`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetBoolean(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *mut Fmi2Boolean,
) -> Fmi2Status {
    let f = "fmi2GetBoolean";
    with_instance(c, f, |i| {
        // SAFETY: per contract.
        let (vr, value) = unsafe { (slice(vr, nvr, f, "vr")?, slice_mut(value, nvr, f, "value")?) };
        let mut b = vec![false; vr.len()];
        let st = i.model.get_boolean(vr, &mut b)?;
        for (o, x) in value.iter_mut().zip(b) {
            *o = Fmi2Boolean::from(x);
        }
        Ok(st)
    })
}

/// `fmi2GetString`: this FMU has no String variables.
///
/// # Safety
/// As [`fmi2GetReal`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetString(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *mut Fmi2String,
) -> Fmi2Status {
    let f = "fmi2GetString";
    with_instance(c, f, |_| {
        // SAFETY: per contract.
        let (vr, _) = unsafe { (slice(vr, nvr, f, "vr")?, slice_mut(value, nvr, f, "value")?) };
        match vr.first() {
            None => Ok(Status::Ok),
            Some(r) => Err(FmuError::error(format!(
                "{f}: value reference {r} is not a String variable (this FMU has none)"
            ))),
        }
    })
}

/// `fmi2SetReal` (parameters before initialization ends, inputs any time).
///
/// # Safety
/// As [`fmi2GetReal`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetReal(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *const Fmi2Real,
) -> Fmi2Status {
    let f = "fmi2SetReal";
    with_instance(c, f, |i| {
        // SAFETY: per contract.
        let (vr, value) = unsafe { (slice(vr, nvr, f, "vr")?, slice(value, nvr, f, "value")?) };
        i.model.set_real(vr, value)
    })
}

/// `fmi2SetInteger` (Enumeration parameters).
///
/// # Safety
/// As [`fmi2GetReal`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetInteger(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *const Fmi2Integer,
) -> Fmi2Status {
    let f = "fmi2SetInteger";
    with_instance(c, f, |i| {
        // SAFETY: per contract.
        let (vr, value) = unsafe { (slice(vr, nvr, f, "vr")?, slice(value, nvr, f, "value")?) };
        i.model.set_integer(vr, value)
    })
}

/// `fmi2SetBoolean`.
///
/// # Safety
/// As [`fmi2GetReal`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetBoolean(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *const Fmi2Boolean,
) -> Fmi2Status {
    let f = "fmi2SetBoolean";
    with_instance(c, f, |i| {
        // SAFETY: per contract.
        let (vr, value) = unsafe { (slice(vr, nvr, f, "vr")?, slice(value, nvr, f, "value")?) };
        let b: Vec<bool> = value.iter().map(|&x| x != 0).collect();
        i.model.set_boolean(vr, &b)
    })
}

/// `fmi2SetString`: this FMU has no String variables.
///
/// # Safety
/// As [`fmi2GetReal`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetString(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *const Fmi2String,
) -> Fmi2Status {
    let f = "fmi2SetString";
    with_instance(c, f, |_| {
        // SAFETY: per contract.
        let (vr, _) = unsafe { (slice(vr, nvr, f, "vr")?, slice(value, nvr, f, "value")?) };
        match vr.first() {
            None => Ok(Status::Ok),
            Some(r) => Err(FmuError::error(format!(
                "{f}: value reference {r} is not a String variable (this FMU has none)"
            ))),
        }
    })
}

// ------------------------------------------------------------ FMU state

/// # Safety
/// `s` NULL or a state made by this library.
unsafe fn state_ref<'a>(s: Fmi2FmuState, func: &str) -> Result<&'a mut StateBox, FmuError> {
    if s.is_null() {
        return Err(null_arg(func, "FMUstate"));
    }
    // SAFETY: per contract, a state this library allocated.
    let b = unsafe { &mut *s.cast::<StateBox>() };
    if b.magic != STATE_MAGIC {
        return Err(FmuError::error(format!(
            "{func}: FMUstate was not created by this FMU (or was freed)"
        )));
    }
    Ok(b)
}

/// Stores `state` at `*out`, reusing a state already there.
///
/// # Safety
/// `*out` NULL or a state made by this library.
unsafe fn store_state(out: *mut Fmi2FmuState, state: Snapshot, func: &str) -> FmuResult {
    // SAFETY: out checked non-NULL by callers.
    let existing = unsafe { *out };
    if existing.is_null() {
        let b = Box::new(StateBox {
            magic: STATE_MAGIC,
            state,
        });
        // SAFETY: out is a valid pointer per contract.
        unsafe { *out = Box::into_raw(b).cast::<c_void>() };
    } else {
        // SAFETY: per contract.
        unsafe { state_ref(existing, func) }?.state = state;
    }
    Ok(Status::Ok)
}

/// `fmi2GetFMUstate`: a copy of the complete instance state; an existing
/// `*FMUstate` is overwritten.
///
/// # Safety
/// `state` a valid pointer whose target is NULL or a state from this library.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetFMUstate(c: Fmi2Component, state: *mut Fmi2FmuState) -> Fmi2Status {
    let f = "fmi2GetFMUstate";
    with_instance(c, f, |i| {
        if state.is_null() {
            return Err(null_arg(f, "FMUstate"));
        }
        let s = i.model.get_state()?;
        // SAFETY: per contract.
        unsafe { store_state(state, s, f) }
    })
}

/// `fmi2SetFMUstate`.
///
/// # Safety
/// `state` a state from this library.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetFMUstate(c: Fmi2Component, state: Fmi2FmuState) -> Fmi2Status {
    let f = "fmi2SetFMUstate";
    with_instance(c, f, |i| {
        // SAFETY: per contract.
        let b = unsafe { state_ref(state, f) }?;
        i.model.set_state(&b.state)
    })
}

/// `fmi2FreeFMUstate`: frees `*FMUstate` and sets it to NULL; NULL accepted.
///
/// # Safety
/// `state` NULL or a valid pointer whose target is NULL or a state from this library.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeFMUstate(
    c: Fmi2Component,
    state: *mut Fmi2FmuState,
) -> Fmi2Status {
    let f = "fmi2FreeFMUstate";
    with_instance(c, f, |_| {
        // SAFETY: per contract.
        if state.is_null() || unsafe { *state }.is_null() {
            return Ok(Status::Ok);
        }
        // SAFETY: per contract.
        let p = unsafe { *state };
        // SAFETY: per contract.
        unsafe { state_ref(p, f) }?.magic = 0;
        // SAFETY: p came from Box::into_raw in store_state.
        drop(unsafe { Box::from_raw(p.cast::<StateBox>()) });
        // SAFETY: valid pointer per contract.
        unsafe { *state = std::ptr::null_mut() };
        Ok(Status::Ok)
    })
}

/// `fmi2SerializedFMUstateSize`.
///
/// # Safety
/// `state` from this library; `size` a valid pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
    c: Fmi2Component,
    state: Fmi2FmuState,
    size: *mut usize,
) -> Fmi2Status {
    let f = "fmi2SerializedFMUstateSize";
    with_instance(c, f, |_| {
        // SAFETY: per contract.
        let b = unsafe { state_ref(state, f) }?;
        if size.is_null() {
            return Err(null_arg(f, "size"));
        }
        // SAFETY: non-NULL, valid per contract.
        unsafe { *size = TractionFmu::serialize_state(&b.state).len() };
        Ok(Status::Ok)
    })
}

/// `fmi2SerializeFMUstate`: writes the state into `serializedState`
/// (`size` must be at least [`fmi2SerializedFMUstateSize`]).
///
/// # Safety
/// `state` from this library; `serialized` an array of `size` bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializeFMUstate(
    c: Fmi2Component,
    state: Fmi2FmuState,
    serialized: *mut Fmi2Byte,
    size: usize,
) -> Fmi2Status {
    let f = "fmi2SerializeFMUstate";
    with_instance(c, f, |_| {
        // SAFETY: per contract.
        let b = unsafe { state_ref(state, f) }?;
        let bytes = TractionFmu::serialize_state(&b.state);
        if size < bytes.len() {
            return Err(FmuError::error(format!(
                "{f}: buffer of {size} bytes, the state needs {}",
                bytes.len()
            )));
        }
        // SAFETY: per contract.
        let out = unsafe { slice_mut(serialized.cast::<u8>(), bytes.len(), f, "serializedState") }?;
        out.copy_from_slice(&bytes);
        Ok(Status::Ok)
    })
}

/// `fmi2DeSerializeFMUstate`: makes a state from bytes of
/// [`fmi2SerializeFMUstate`] (reusing `*FMUstate` if not NULL).
///
/// # Safety
/// `serialized` an array of `size` bytes; `state` a valid pointer whose
/// target is NULL or a state from this library.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: Fmi2Component,
    serialized: *const Fmi2Byte,
    size: usize,
    state: *mut Fmi2FmuState,
) -> Fmi2Status {
    let f = "fmi2DeSerializeFMUstate";
    with_instance(c, f, |_| {
        // SAFETY: per contract.
        let bytes = unsafe { slice(serialized.cast::<u8>(), size, f, "serializedState") }?;
        if state.is_null() {
            return Err(null_arg(f, "FMUstate"));
        }
        let s = TractionFmu::deserialize_state(bytes)?;
        // SAFETY: per contract.
        unsafe { store_state(state, s, f) }
    })
}

/// `fmi2GetDirectionalDerivative`: not supported (providesDirectionalDerivative = false).
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetDirectionalDerivative(
    c: Fmi2Component,
    _v_unknown: *const Fmi2ValueReference,
    _n_unknown: usize,
    _v_known: *const Fmi2ValueReference,
    _n_known: usize,
    _dv_known: *const Fmi2Real,
    _dv_unknown: *mut Fmi2Real,
) -> Fmi2Status {
    unsupported(
        c,
        "fmi2GetDirectionalDerivative",
        "providesDirectionalDerivative is false",
    )
}

// ------------------------------------------------------- co-simulation

/// `fmi2SetRealInputDerivatives`: not supported (canInterpolateInputs = false).
#[unsafe(no_mangle)]
pub extern "C" fn fmi2SetRealInputDerivatives(
    c: Fmi2Component,
    _vr: *const Fmi2ValueReference,
    _nvr: usize,
    _order: *const Fmi2Integer,
    _value: *const Fmi2Real,
) -> Fmi2Status {
    unsupported(
        c,
        "fmi2SetRealInputDerivatives",
        "canInterpolateInputs is false",
    )
}

/// `fmi2GetRealOutputDerivatives`: not supported (maxOutputDerivativeOrder = 0).
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetRealOutputDerivatives(
    c: Fmi2Component,
    _vr: *const Fmi2ValueReference,
    _nvr: usize,
    _order: *const Fmi2Integer,
    _value: *mut Fmi2Real,
) -> Fmi2Status {
    unsupported(
        c,
        "fmi2GetRealOutputDerivatives",
        "maxOutputDerivativeOrder is 0",
    )
}

/// `fmi2DoStep`: evaluates the contact at the current inputs and advances the
/// time to `currentCommunicationPoint + communicationStepSize` (any step
/// size ≥ 0: canHandleVariableCommunicationStepSize).
#[unsafe(no_mangle)]
pub extern "C" fn fmi2DoStep(
    c: Fmi2Component,
    current_communication_point: Fmi2Real,
    communication_step_size: Fmi2Real,
    _no_set_fmu_state_prior_to_current_point: Fmi2Boolean,
) -> Fmi2Status {
    with_instance(c, "fmi2DoStep", |i| {
        i.model.do_step(
            current_communication_point,
            communication_step_size,
            &mut i.log,
        )
    })
}

/// `fmi2CancelStep`: not supported (steps are never asynchronous).
#[unsafe(no_mangle)]
pub extern "C" fn fmi2CancelStep(c: Fmi2Component) -> Fmi2Status {
    unsupported(c, "fmi2CancelStep", "fmi2DoStep never returns fmi2Pending")
}

/// `fmi2GetStatus`: not supported (no asynchronous steps).
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetStatus(
    c: Fmi2Component,
    _s: Fmi2StatusKind,
    _value: *mut Fmi2Status,
) -> Fmi2Status {
    unsupported(c, "fmi2GetStatus", "fmi2DoStep never returns fmi2Pending")
}

/// `fmi2GetRealStatus`: `fmi2LastSuccessfulTime` only.
///
/// # Safety
/// `value` a valid pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetRealStatus(
    c: Fmi2Component,
    s: Fmi2StatusKind,
    value: *mut Fmi2Real,
) -> Fmi2Status {
    let f = "fmi2GetRealStatus";
    with_instance(c, f, |i| {
        if s != FMI2_LAST_SUCCESSFUL_TIME {
            return Err(FmuError::error(format!(
                "{f}: status kind {s} is not supported (only fmi2LastSuccessfulTime = 2)"
            )));
        }
        if value.is_null() {
            return Err(null_arg(f, "value"));
        }
        // SAFETY: non-NULL, valid per contract.
        unsafe { *value = i.model.last_successful_time() };
        Ok(Status::Ok)
    })
}

/// `fmi2GetIntegerStatus`: not supported (no integer status kinds in FMI 2.0).
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetIntegerStatus(
    c: Fmi2Component,
    _s: Fmi2StatusKind,
    _value: *mut Fmi2Integer,
) -> Fmi2Status {
    unsupported(
        c,
        "fmi2GetIntegerStatus",
        "FMI 2.0 defines no integer status",
    )
}

/// `fmi2GetBooleanStatus`: `fmi2Terminated` only (always false: the
/// contact never asks to end the simulation).
///
/// # Safety
/// `value` a valid pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetBooleanStatus(
    c: Fmi2Component,
    s: Fmi2StatusKind,
    value: *mut Fmi2Boolean,
) -> Fmi2Status {
    let f = "fmi2GetBooleanStatus";
    with_instance(c, f, |_| {
        if s != FMI2_TERMINATED {
            return Err(FmuError::error(format!(
                "{f}: status kind {s} is not supported (only fmi2Terminated = 3)"
            )));
        }
        if value.is_null() {
            return Err(null_arg(f, "value"));
        }
        // SAFETY: non-NULL, valid per contract.
        unsafe { *value = 0 };
        Ok(Status::Ok)
    })
}

/// `fmi2GetStringStatus`: not supported (no asynchronous steps).
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetStringStatus(
    c: Fmi2Component,
    _s: Fmi2StatusKind,
    _value: *mut Fmi2String,
) -> Fmi2Status {
    unsupported(
        c,
        "fmi2GetStringStatus",
        "fmi2DoStep never returns fmi2Pending",
    )
}
