//! The C boundary: FMI 2.0 types and the exported `fmi2*` functions of a
//! co-simulation FMU.
//!
//! Every entry point checks its pointers, turns them into slices and strings,
//! calls one method of [`VariatorFmu`] inside [`std::panic::catch_unwind`],
//! and reports a failure through the host's logger (`%` escaped as `%%`,
//! since FMI loggers treat the message as a printf format) with
//! `fmi2Error`/`fmi2Fatal`. A caught panic poisons the instance (`fmi2Fatal`;
//! only `fmi2FreeInstance` remains). Unsupported functions (directional
//! derivatives, input/output derivatives, asynchronous steps, strings)
//! return `fmi2Error` with a logged message.
//!
//! The instance is a `Box` owned by the host through the `fmi2Component`
//! pointer; there is no global state.
#![allow(unsafe_code)]
// The FMI 2.0 standard names these functions (fmi2DoStep, ...); with the "no-export"
// feature they are plain Rust functions and the lint would ask for snake case.
#![allow(non_snake_case)]

use std::ffi::{CStr, CString, c_char, c_int, c_uint, c_void};
use std::panic::{AssertUnwindSafe, catch_unwind};

use crate::model::{FmuError, FmuResult, Logger, Snapshot, Status, VariatorFmu};
use crate::model_description::LOG_CATEGORIES;

/// `fmi2Component`.
pub type Fmi2Component = *mut c_void;
/// `fmi2ComponentEnvironment`.
pub type Fmi2ComponentEnvironment = *mut c_void;
/// `fmi2FMUstate`.
pub type Fmi2FmuState = *mut c_void;
/// `fmi2ValueReference`.
pub type Fmi2ValueReference = c_uint;
/// `fmi2Real`.
pub type Fmi2Real = f64;
/// `fmi2Integer`.
pub type Fmi2Integer = c_int;
/// `fmi2Boolean`.
pub type Fmi2Boolean = c_int;
/// `fmi2String`.
pub type Fmi2String = *const c_char;
/// `fmi2Byte`.
pub type Fmi2Byte = c_char;
/// `fmi2Status`.
pub type Fmi2Status = c_int;
/// `fmi2Type`.
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
/// fmi2CoSimulation.
pub const FMI2_COSIMULATION: Fmi2Type = 1;
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

/// `fmi2CallbackFunctions`; only `logger` and `component_environment` are used.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct Fmi2CallbackFunctions {
    /// Logger (may be NULL).
    pub logger: Fmi2CallbackLogger,
    /// Not used.
    pub allocate_memory: Option<unsafe extern "C" fn(usize, usize) -> *mut c_void>,
    /// Not used.
    pub free_memory: Option<unsafe extern "C" fn(*mut c_void)>,
    /// Not used.
    pub step_finished: Option<unsafe extern "C" fn(Fmi2ComponentEnvironment, Fmi2Status)>,
    /// Passed back to the logger.
    pub component_environment: Fmi2ComponentEnvironment,
}

const INSTANCE_MAGIC: u64 = 0x544f_524f_4944_414c; // "TOROIDAL"
const STATE_MAGIC: u64 = 0x544f_524f_5354_4154; // "TOROSTAT"

struct HostLogger {
    logger: Fmi2CallbackLogger,
    env: Fmi2ComponentEnvironment,
    name: CString,
    debug: bool,
}

fn c_text(s: &str, escape_percent: bool) -> CString {
    let t = if escape_percent {
        s.replace('%', "%%")
    } else {
        s.to_owned()
    };
    CString::new(t.replace('\0', "\u{fffd}")).unwrap_or_default()
}

impl Logger for HostLogger {
    fn log(&mut self, status: Status, category: &str, message: &str) {
        let Some(f) = self.logger else { return };
        if status < Status::Warning && !self.debug {
            return;
        }
        let cat = c_text(category, false);
        let msg = c_text(message, true);
        // SAFETY: the host's logger with its environment pointer; all strings
        // are valid NUL-terminated C strings that outlive the call.
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
    model: VariatorFmu,
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
    p.downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| p.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic payload".to_owned())
}

/// Runs `f` on the instance behind `c`: pointer check, catch_unwind, logging.
fn with_instance(
    c: Fmi2Component,
    func: &str,
    f: impl FnOnce(&mut Instance) -> FmuResult,
) -> Fmi2Status {
    if c.is_null() {
        return FMI2_ERROR;
    }
    // SAFETY: a non-NULL fmi2Component is the pointer fmi2Instantiate
    // returned (the standard requires it); the magic number catches most misuse.
    let inst = unsafe { &mut *c.cast::<Instance>() };
    if inst.magic != INSTANCE_MAGIC {
        return FMI2_ERROR;
    }
    match catch_unwind(AssertUnwindSafe(|| f(inst))) {
        Ok(Ok(s)) => s as Fmi2Status,
        Ok(Err(FmuError { status, message })) => {
            inst.log
                .log(status, category(status), &format!("{func}: {message}"));
            status as Fmi2Status
        }
        Err(p) => {
            inst.model.poison();
            let msg = format!(
                "{func}: internal error (panic: {})",
                panic_message(p.as_ref())
            );
            inst.log.log(Status::Fatal, "logStatusFatal", &msg);
            FMI2_FATAL
        }
    }
}

/// Slice from a (pointer, length) pair; NULL is accepted only for length 0.
///
/// # Safety
/// A non-NULL `p` must point to `n` valid elements.
unsafe fn slice<'a, T>(p: *const T, n: usize) -> Option<&'a [T]> {
    if n == 0 {
        Some(&[])
    } else if p.is_null() {
        None
    } else {
        // SAFETY: the caller guarantees n valid elements.
        Some(unsafe { std::slice::from_raw_parts(p, n) })
    }
}

/// Mutable slice from a (pointer, length) pair.
///
/// # Safety
/// A non-NULL `p` must point to `n` valid, writable elements.
unsafe fn slice_mut<'a, T>(p: *mut T, n: usize) -> Option<&'a mut [T]> {
    if n == 0 {
        Some(&mut [])
    } else if p.is_null() {
        None
    } else {
        // SAFETY: the caller guarantees n valid elements.
        Some(unsafe { std::slice::from_raw_parts_mut(p, n) })
    }
}

fn null(func: &str, what: &str) -> FmuError {
    FmuError::error(format!("{func}: {what} is NULL"))
}

/// fmi2GetTypesPlatform.
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub extern "C" fn fmi2GetTypesPlatform() -> Fmi2String {
    c"default".as_ptr()
}

/// fmi2GetVersion.
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub extern "C" fn fmi2GetVersion() -> Fmi2String {
    c"2.0".as_ptr()
}

/// fmi2Instantiate: NULL on failure (logged through the callbacks when possible).
///
/// # Safety
/// Strings must be NULL or valid C strings; `functions` NULL or valid.
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2Instantiate(
    instance_name: Fmi2String,
    fmu_type: Fmi2Type,
    guid: Fmi2String,
    _resource_location: Fmi2String,
    functions: *const Fmi2CallbackFunctions,
    _visible: Fmi2Boolean,
    logging_on: Fmi2Boolean,
) -> Fmi2Component {
    let r = catch_unwind(|| {
        // SAFETY: the host passes NULL or a valid callback struct.
        let cb = unsafe { functions.as_ref() }.copied();
        let text = |p: Fmi2String| -> Option<String> {
            // SAFETY: NULL or a valid NUL-terminated string (FMI contract).
            (!p.is_null()).then(|| unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned())
        };
        let name = text(instance_name).unwrap_or_default();
        let mut log = HostLogger {
            logger: cb.and_then(|c| c.logger),
            env: cb.map_or(std::ptr::null_mut(), |c| c.component_environment),
            name: c_text(&name, false),
            debug: logging_on != 0,
        };
        let fail = |log: &mut HostLogger, m: String| {
            log.log(
                Status::Error,
                "logStatusError",
                &format!("fmi2Instantiate: {m}"),
            );
            std::ptr::null_mut()
        };
        if name.is_empty() {
            return fail(&mut log, "instanceName is NULL or empty".into());
        }
        if fmu_type != FMI2_COSIMULATION {
            return fail(
                &mut log,
                format!("fmuType {fmu_type}: this FMU supports co-simulation (1) only"),
            );
        }
        let Some(g) = text(guid) else {
            return fail(&mut log, "GUID is NULL".into());
        };
        match VariatorFmu::instantiate(&g) {
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

/// fmi2FreeInstance.
///
/// # Safety
/// `c` must be NULL or a pointer from [`fmi2Instantiate`] not yet freed.
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2FreeInstance(c: Fmi2Component) {
    if c.is_null() {
        return;
    }
    let _ = catch_unwind(|| {
        // SAFETY: a pointer from fmi2Instantiate (checked by the magic).
        let inst = unsafe { &mut *c.cast::<Instance>() };
        if inst.magic == INSTANCE_MAGIC {
            inst.magic = 0;
            // SAFETY: created by Box::into_raw in fmi2Instantiate.
            drop(unsafe { Box::from_raw(c.cast::<Instance>()) });
        }
    });
}

/// fmi2SetDebugLogging: categories must be declared ones.
///
/// # Safety
/// `c` from [`fmi2Instantiate`]; `categories` NULL (n = 0) or n valid strings.
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2SetDebugLogging(
    c: Fmi2Component,
    logging_on: Fmi2Boolean,
    n: usize,
    categories: *const Fmi2String,
) -> Fmi2Status {
    with_instance(c, "fmi2SetDebugLogging", |inst| {
        // SAFETY: n valid string pointers (FMI contract).
        let cats = unsafe { slice(categories, n) }
            .ok_or_else(|| null("fmi2SetDebugLogging", "categories"))?;
        for &p in cats {
            if p.is_null() {
                return Err(null("fmi2SetDebugLogging", "a category"));
            }
            // SAFETY: non-NULL, NUL-terminated (FMI contract).
            let s = unsafe { CStr::from_ptr(p) }.to_string_lossy();
            if !LOG_CATEGORIES.iter().any(|c| c.0 == s) {
                return Err(FmuError::error(format!(
                    "fmi2SetDebugLogging: unknown category {s}"
                )));
            }
        }
        inst.log.debug = logging_on != 0;
        Ok(Status::Ok)
    })
}

/// fmi2SetupExperiment.
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2SetupExperiment(
    c: Fmi2Component,
    _tolerance_defined: Fmi2Boolean,
    _tolerance: Fmi2Real,
    start_time: Fmi2Real,
    _stop_time_defined: Fmi2Boolean,
    _stop_time: Fmi2Real,
) -> Fmi2Status {
    with_instance(c, "fmi2SetupExperiment", |i| {
        i.model.setup_experiment(start_time)
    })
}

/// fmi2EnterInitializationMode.
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2EnterInitializationMode(c: Fmi2Component) -> Fmi2Status {
    with_instance(c, "fmi2EnterInitializationMode", |i| {
        i.model.enter_initialization_mode()
    })
}

/// fmi2ExitInitializationMode.
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2ExitInitializationMode(c: Fmi2Component) -> Fmi2Status {
    with_instance(c, "fmi2ExitInitializationMode", |i| {
        i.model.exit_initialization_mode(&mut i.log)
    })
}

/// fmi2Terminate.
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2Terminate(c: Fmi2Component) -> Fmi2Status {
    with_instance(c, "fmi2Terminate", |i| i.model.terminate())
}

/// fmi2Reset.
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2Reset(c: Fmi2Component) -> Fmi2Status {
    with_instance(c, "fmi2Reset", |i| i.model.reset())
}

/// fmi2GetReal.
///
/// # Safety
/// `c` from [`fmi2Instantiate`]; `vr` and `value` NULL (n = 0) or n elements.
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2GetReal(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    n: usize,
    value: *mut Fmi2Real,
) -> Fmi2Status {
    with_instance(c, "fmi2GetReal", |i| {
        // SAFETY: n elements each (FMI contract).
        let vrs = unsafe { slice(vr, n) }.ok_or_else(|| null("fmi2GetReal", "vr"))?;
        // SAFETY: as above.
        let out = unsafe { slice_mut(value, n) }.ok_or_else(|| null("fmi2GetReal", "value"))?;
        i.model.get_real(vrs, out, &mut i.log)
    })
}

/// fmi2GetInteger.
///
/// # Safety
/// As [`fmi2GetReal`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2GetInteger(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    n: usize,
    value: *mut Fmi2Integer,
) -> Fmi2Status {
    with_instance(c, "fmi2GetInteger", |i| {
        // SAFETY: n elements each (FMI contract).
        let vrs = unsafe { slice(vr, n) }.ok_or_else(|| null("fmi2GetInteger", "vr"))?;
        // SAFETY: as above.
        let out = unsafe { slice_mut(value, n) }.ok_or_else(|| null("fmi2GetInteger", "value"))?;
        i.model.get_integer(vrs, out, &mut i.log)
    })
}

/// fmi2GetBoolean.
///
/// # Safety
/// As [`fmi2GetReal`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2GetBoolean(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    n: usize,
    value: *mut Fmi2Boolean,
) -> Fmi2Status {
    with_instance(c, "fmi2GetBoolean", |i| {
        // SAFETY: n elements each (FMI contract).
        let vrs = unsafe { slice(vr, n) }.ok_or_else(|| null("fmi2GetBoolean", "vr"))?;
        // SAFETY: as above.
        let out = unsafe { slice_mut(value, n) }.ok_or_else(|| null("fmi2GetBoolean", "value"))?;
        let mut b = vec![false; n];
        let s = i.model.get_boolean(vrs, &mut b)?;
        for (o, x) in out.iter_mut().zip(b) {
            *o = Fmi2Boolean::from(x);
        }
        Ok(s)
    })
}

/// fmi2GetString: this FMU has no String variables.
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2GetString(
    c: Fmi2Component,
    _vr: *const Fmi2ValueReference,
    n: usize,
    _value: *mut Fmi2String,
) -> Fmi2Status {
    with_instance(c, "fmi2GetString", |_| {
        if n == 0 {
            Ok(Status::Ok)
        } else {
            Err(FmuError::error("this FMU has no String variables"))
        }
    })
}

/// fmi2SetReal.
///
/// # Safety
/// As [`fmi2GetReal`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2SetReal(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    n: usize,
    value: *const Fmi2Real,
) -> Fmi2Status {
    with_instance(c, "fmi2SetReal", |i| {
        // SAFETY: n elements each (FMI contract).
        let vrs = unsafe { slice(vr, n) }.ok_or_else(|| null("fmi2SetReal", "vr"))?;
        // SAFETY: as above.
        let v = unsafe { slice(value, n) }.ok_or_else(|| null("fmi2SetReal", "value"))?;
        i.model.set_real(vrs, v)
    })
}

/// fmi2SetInteger.
///
/// # Safety
/// As [`fmi2GetReal`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2SetInteger(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    n: usize,
    value: *const Fmi2Integer,
) -> Fmi2Status {
    with_instance(c, "fmi2SetInteger", |i| {
        // SAFETY: n elements each (FMI contract).
        let vrs = unsafe { slice(vr, n) }.ok_or_else(|| null("fmi2SetInteger", "vr"))?;
        // SAFETY: as above.
        let v = unsafe { slice(value, n) }.ok_or_else(|| null("fmi2SetInteger", "value"))?;
        i.model.set_integer(vrs, v)
    })
}

/// fmi2SetBoolean.
///
/// # Safety
/// As [`fmi2GetReal`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2SetBoolean(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    n: usize,
    value: *const Fmi2Boolean,
) -> Fmi2Status {
    with_instance(c, "fmi2SetBoolean", |i| {
        // SAFETY: n elements each (FMI contract).
        let vrs = unsafe { slice(vr, n) }.ok_or_else(|| null("fmi2SetBoolean", "vr"))?;
        // SAFETY: as above.
        let v = unsafe { slice(value, n) }.ok_or_else(|| null("fmi2SetBoolean", "value"))?;
        let b: Vec<bool> = v.iter().map(|&x| x != 0).collect();
        i.model.set_boolean(vrs, &b)
    })
}

/// fmi2SetString: this FMU has no String variables.
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2SetString(
    c: Fmi2Component,
    _vr: *const Fmi2ValueReference,
    n: usize,
    _value: *const Fmi2String,
) -> Fmi2Status {
    // SAFETY: forwarded contract.
    unsafe { fmi2GetString(c, std::ptr::null(), n, std::ptr::null_mut()) }
}

/// fmi2GetFMUstate: a new state, or overwrite `*state` if it holds one of ours.
///
/// # Safety
/// `c` from [`fmi2Instantiate`]; `state` a valid pointer to NULL or to a state of this FMU.
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2GetFMUstate(c: Fmi2Component, state: *mut Fmi2FmuState) -> Fmi2Status {
    with_instance(c, "fmi2GetFMUstate", |i| {
        if state.is_null() {
            return Err(null("fmi2GetFMUstate", "FMUstate"));
        }
        let snap = i.model.get_state()?;
        // SAFETY: valid pointer (checked non-NULL).
        let slot = unsafe { &mut *state };
        if !slot.is_null() {
            // SAFETY: a previous state of ours (checked by the magic).
            let b = unsafe { &mut *slot.cast::<StateBox>() };
            if b.magic != STATE_MAGIC {
                return Err(FmuError::error(
                    "fmi2GetFMUstate: *FMUstate is not a state of this FMU",
                ));
            }
            b.state = snap;
        } else {
            *slot = Box::into_raw(Box::new(StateBox {
                magic: STATE_MAGIC,
                state: snap,
            }))
            .cast::<c_void>();
        }
        Ok(Status::Ok)
    })
}

/// Borrow a state of this FMU.
///
/// # Safety
/// `s` NULL or a pointer from [`fmi2GetFMUstate`] / [`fmi2DeSerializeFMUstate`].
unsafe fn state_ref<'a>(s: Fmi2FmuState, func: &str) -> Result<&'a mut StateBox, FmuError> {
    if s.is_null() {
        return Err(null(func, "FMUstate"));
    }
    // SAFETY: caller contract.
    let b = unsafe { &mut *s.cast::<StateBox>() };
    if b.magic == STATE_MAGIC {
        Ok(b)
    } else {
        Err(FmuError::error(format!(
            "{func}: FMUstate is not a state of this FMU"
        )))
    }
}

/// fmi2SetFMUstate.
///
/// # Safety
/// `state` NULL or a state of this FMU (from fmi2GetFMUstate or fmi2DeSerializeFMUstate).
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2SetFMUstate(c: Fmi2Component, state: Fmi2FmuState) -> Fmi2Status {
    with_instance(c, "fmi2SetFMUstate", |i| {
        // SAFETY: forwarded contract.
        let b = unsafe { state_ref(state, "fmi2SetFMUstate") }?;
        i.model.set_state(&b.state)
    })
}

/// fmi2FreeFMUstate: frees `*state` and sets it to NULL.
///
/// # Safety
/// `state` NULL, or a valid pointer to NULL or to a state of this FMU.
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2FreeFMUstate(
    c: Fmi2Component,
    state: *mut Fmi2FmuState,
) -> Fmi2Status {
    with_instance(c, "fmi2FreeFMUstate", |_| {
        if state.is_null() {
            return Ok(Status::Ok);
        }
        // SAFETY: valid pointer (checked non-NULL).
        let slot = unsafe { &mut *state };
        if slot.is_null() {
            return Ok(Status::Ok);
        }
        // SAFETY: forwarded contract.
        let b = unsafe { state_ref(*slot, "fmi2FreeFMUstate") }?;
        b.magic = 0;
        // SAFETY: created by Box::into_raw.
        drop(unsafe { Box::from_raw(slot.cast::<StateBox>()) });
        *slot = std::ptr::null_mut();
        Ok(Status::Ok)
    })
}

/// fmi2SerializedFMUstateSize.
///
/// # Safety
/// `state` NULL or a state of this FMU; `size` a valid pointer.
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
    c: Fmi2Component,
    state: Fmi2FmuState,
    size: *mut usize,
) -> Fmi2Status {
    with_instance(c, "fmi2SerializedFMUstateSize", |_| {
        // SAFETY: forwarded contract.
        let b = unsafe { state_ref(state, "fmi2SerializedFMUstateSize") }?;
        if size.is_null() {
            return Err(null("fmi2SerializedFMUstateSize", "size"));
        }
        // SAFETY: valid pointer (checked non-NULL).
        unsafe { *size = b.state.to_bytes().len() };
        Ok(Status::Ok)
    })
}

/// fmi2SerializeFMUstate.
///
/// # Safety
/// `state` NULL or a state of this FMU; `bytes` valid for `size` bytes.
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2SerializeFMUstate(
    c: Fmi2Component,
    state: Fmi2FmuState,
    bytes: *mut Fmi2Byte,
    size: usize,
) -> Fmi2Status {
    with_instance(c, "fmi2SerializeFMUstate", |_| {
        // SAFETY: forwarded contract.
        let b = unsafe { state_ref(state, "fmi2SerializeFMUstate") }?;
        let data = b.state.to_bytes();
        if size < data.len() {
            return Err(FmuError::error(format!(
                "fmi2SerializeFMUstate: buffer of {size} bytes, {} needed",
                data.len()
            )));
        }
        // SAFETY: size bytes (FMI contract).
        let out = unsafe { slice_mut(bytes.cast::<u8>(), data.len()) }
            .ok_or_else(|| null("fmi2SerializeFMUstate", "serializedState"))?;
        out.copy_from_slice(&data);
        Ok(Status::Ok)
    })
}

/// fmi2DeSerializeFMUstate.
///
/// # Safety
/// `bytes` valid for `size` bytes; `state` a valid pointer to NULL or to a state of this FMU.
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: Fmi2Component,
    bytes: *const Fmi2Byte,
    size: usize,
    state: *mut Fmi2FmuState,
) -> Fmi2Status {
    with_instance(c, "fmi2DeSerializeFMUstate", |_| {
        // SAFETY: size bytes (FMI contract).
        let data = unsafe { slice(bytes.cast::<u8>(), size) }
            .ok_or_else(|| null("fmi2DeSerializeFMUstate", "serializedState"))?;
        if state.is_null() {
            return Err(null("fmi2DeSerializeFMUstate", "FMUstate"));
        }
        let snap = Snapshot::from_bytes(data)?;
        // SAFETY: valid pointer (checked non-NULL).
        let slot = unsafe { &mut *state };
        if slot.is_null() {
            *slot = Box::into_raw(Box::new(StateBox {
                magic: STATE_MAGIC,
                state: snap,
            }))
            .cast::<c_void>();
        } else {
            // SAFETY: forwarded contract.
            unsafe { state_ref(*slot, "fmi2DeSerializeFMUstate") }?.state = snap;
        }
        Ok(Status::Ok)
    })
}

fn unsupported(c: Fmi2Component, func: &str) -> Fmi2Status {
    with_instance(c, func, |_| {
        Err(FmuError::error(
            "not supported by this FMU (see modelDescription.xml)",
        ))
    })
}

/// fmi2GetDirectionalDerivative: not provided.
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2GetDirectionalDerivative(
    c: Fmi2Component,
    _vu: *const Fmi2ValueReference,
    _nu: usize,
    _vk: *const Fmi2ValueReference,
    _nk: usize,
    _dvk: *const Fmi2Real,
    _dvu: *mut Fmi2Real,
) -> Fmi2Status {
    unsupported(c, "fmi2GetDirectionalDerivative")
}

/// fmi2SetRealInputDerivatives: not supported (canInterpolateInputs = false).
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2SetRealInputDerivatives(
    c: Fmi2Component,
    _vr: *const Fmi2ValueReference,
    _n: usize,
    _order: *const Fmi2Integer,
    _value: *const Fmi2Real,
) -> Fmi2Status {
    unsupported(c, "fmi2SetRealInputDerivatives")
}

/// fmi2GetRealOutputDerivatives: not supported (maxOutputDerivativeOrder = 0).
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
    c: Fmi2Component,
    _vr: *const Fmi2ValueReference,
    _n: usize,
    _order: *const Fmi2Integer,
    _value: *mut Fmi2Real,
) -> Fmi2Status {
    unsupported(c, "fmi2GetRealOutputDerivatives")
}

/// fmi2DoStep.
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2DoStep(
    c: Fmi2Component,
    current: Fmi2Real,
    step: Fmi2Real,
    _no_set_prior: Fmi2Boolean,
) -> Fmi2Status {
    with_instance(c, "fmi2DoStep", |i| {
        i.model.do_step(current, step, &mut i.log)
    })
}

/// fmi2CancelStep: steps are synchronous; nothing to cancel.
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2CancelStep(c: Fmi2Component) -> Fmi2Status {
    unsupported(c, "fmi2CancelStep")
}

/// fmi2GetStatus: no asynchronous steps.
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2GetStatus(
    c: Fmi2Component,
    _s: Fmi2StatusKind,
    _v: *mut Fmi2Status,
) -> Fmi2Status {
    unsupported(c, "fmi2GetStatus")
}

/// fmi2GetRealStatus: fmi2LastSuccessfulTime.
///
/// # Safety
/// `c` from [`fmi2Instantiate`]; `value` a valid pointer.
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2GetRealStatus(
    c: Fmi2Component,
    s: Fmi2StatusKind,
    value: *mut Fmi2Real,
) -> Fmi2Status {
    with_instance(c, "fmi2GetRealStatus", |i| {
        if s != FMI2_LAST_SUCCESSFUL_TIME {
            return Err(FmuError::error(format!("status kind {s} is not available")));
        }
        if value.is_null() {
            return Err(null("fmi2GetRealStatus", "value"));
        }
        // SAFETY: valid pointer (checked non-NULL).
        unsafe { *value = i.model.last_successful_time() };
        Ok(Status::Ok)
    })
}

/// fmi2GetIntegerStatus: none available.
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2GetIntegerStatus(
    c: Fmi2Component,
    _s: Fmi2StatusKind,
    _v: *mut Fmi2Integer,
) -> Fmi2Status {
    unsupported(c, "fmi2GetIntegerStatus")
}

/// fmi2GetBooleanStatus: fmi2Terminated is always false.
///
/// # Safety
/// `c` from [`fmi2Instantiate`]; `value` a valid pointer.
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2GetBooleanStatus(
    c: Fmi2Component,
    s: Fmi2StatusKind,
    value: *mut Fmi2Boolean,
) -> Fmi2Status {
    with_instance(c, "fmi2GetBooleanStatus", |_| {
        if s != FMI2_TERMINATED {
            return Err(FmuError::error(format!("status kind {s} is not available")));
        }
        if value.is_null() {
            return Err(null("fmi2GetBooleanStatus", "value"));
        }
        // SAFETY: valid pointer (checked non-NULL).
        unsafe { *value = 0 };
        Ok(Status::Ok)
    })
}

/// fmi2GetStringStatus: none available.
///
/// # Safety
/// `c` from [`fmi2Instantiate`].
#[cfg_attr(not(feature = "no-export"), unsafe(no_mangle))]
pub unsafe extern "C" fn fmi2GetStringStatus(
    c: Fmi2Component,
    _s: Fmi2StatusKind,
    _v: *mut Fmi2String,
) -> Fmi2Status {
    unsupported(c, "fmi2GetStringStatus")
}
