//! The C boundary: the exported `fmi2*` functions of a co-simulation FMU, on
//! the FMI 2.0 types and guards of `traction_fmi_support::ffi` (shared with
//! traction-fmu).
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
//! The instance is a magic-tagged `Box` owned by the host through the
//! `fmi2Component` pointer; there is no global state.
#![allow(unsafe_code)]
// The FMI 2.0 standard names these functions (fmi2DoStep, ...); with the "no-export"
// feature they are plain Rust functions and the lint would ask for snake case.
#![allow(non_snake_case)]

use std::panic::catch_unwind;

use traction_fmi_support::ffi::{
    self as support, HostCallback, guarded, lossy_string, slice, slice_mut,
};
pub use traction_fmi_support::ffi::{
    FMI2_COSIMULATION, FMI2_DISCARD, FMI2_ERROR, FMI2_FATAL, FMI2_LAST_SUCCESSFUL_TIME, FMI2_OK,
    FMI2_TERMINATED, FMI2_WARNING, Fmi2Boolean, Fmi2Byte, Fmi2CallbackFunctions,
    Fmi2CallbackLogger, Fmi2Component, Fmi2ComponentEnvironment, Fmi2FmuState, Fmi2Integer,
    Fmi2Real, Fmi2Status, Fmi2StatusKind, Fmi2String, Fmi2Type, Fmi2ValueReference,
};

use crate::model::{FmuError, FmuResult, Logger, Snapshot, Status, VariatorFmu};
use crate::model_description::LOG_CATEGORIES;

const INSTANCE_MAGIC: u64 = 0x544f_524f_4944_414c; // "TOROIDAL"
const STATE_MAGIC: u64 = 0x544f_524f_5354_4154; // "TOROSTAT"

/// The host's logger with this FMU's filter: errors and warnings always,
/// everything else only with debug logging on.
struct HostLogger {
    host: HostCallback,
    debug: bool,
}

impl Logger for HostLogger {
    fn log(&mut self, status: Status, category: &str, message: &str) {
        if status >= Status::Warning || self.debug {
            self.host.send(status, category, message);
        }
    }
}

/// What the host's `fmi2Component` points to (tagged with [`INSTANCE_MAGIC`]).
struct Instance {
    model: VariatorFmu,
    log: HostLogger,
}

/// Runs `f` on the instance behind `c`: pointer check, catch_unwind, logging.
fn with_instance(
    c: Fmi2Component,
    func: &str,
    f: impl FnOnce(&mut Instance) -> FmuResult,
) -> Fmi2Status {
    // SAFETY: a non-NULL fmi2Component is the pointer fmi2Instantiate
    // returned (the standard requires it); the magic number catches most misuse.
    let Some(inst) = (unsafe { support::handle_mut::<Instance>(c, INSTANCE_MAGIC) }) else {
        return FMI2_ERROR;
    };
    match guarded(|| f(&mut *inst)) {
        Ok(Ok(s)) => s as Fmi2Status,
        Ok(Err(FmuError { status, message })) => {
            inst.log
                .log(status, status.category(), &format!("{func}: {message}"));
            status as Fmi2Status
        }
        Err(panic) => {
            inst.model.poison();
            let msg = format!("{func}: internal error (panic: {panic})");
            inst.log.log(Status::Fatal, "logStatusFatal", &msg);
            FMI2_FATAL
        }
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
        let cb = unsafe { support::callbacks(functions) };
        // SAFETY: NULL or a valid NUL-terminated string (FMI contract).
        let text = |p: Fmi2String| unsafe { lossy_string(p) };
        let name = text(instance_name).unwrap_or_default();
        let mut log = HostLogger {
            // SAFETY: the host's callbacks stay valid until fmi2FreeInstance
            // (FMI 2.0), and the logger lives in the instance.
            host: unsafe { HostCallback::new(cb, &name) },
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
            Ok(model) => support::into_handle(INSTANCE_MAGIC, Instance { model, log }),
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
        // SAFETY: a pointer from fmi2Instantiate (checked by the magic; not
        // freed otherwise).
        unsafe { support::free_handle::<Instance>(c, INSTANCE_MAGIC) }
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
            let s = unsafe { lossy_string(p) }.unwrap_or_default();
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
        // SAFETY: valid pointer (checked non-NULL) to NULL or a state of ours
        // (checked by the magic).
        if unsafe { support::store_handle(state, STATE_MAGIC, snap) } {
            Ok(Status::Ok)
        } else {
            Err(FmuError::error(
                "fmi2GetFMUstate: *FMUstate is not a state of this FMU",
            ))
        }
    })
}

/// Borrow a state of this FMU.
///
/// # Safety
/// `s` NULL or a pointer from [`fmi2GetFMUstate`] / [`fmi2DeSerializeFMUstate`].
unsafe fn state_ref<'a>(s: Fmi2FmuState, func: &str) -> Result<&'a mut Snapshot, FmuError> {
    if s.is_null() {
        return Err(null(func, "FMUstate"));
    }
    // SAFETY: caller contract.
    unsafe { support::handle_mut(s, STATE_MAGIC) }.ok_or_else(|| not_ours(func))
}

fn not_ours(func: &str) -> FmuError {
    FmuError::error(format!("{func}: FMUstate is not a state of this FMU"))
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
        i.model.set_state(b)
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
        // SAFETY: forwarded contract (refused if not ours, then freed).
        unsafe { state_ref(*slot, "fmi2FreeFMUstate") }?;
        // SAFETY: a state of ours (checked above).
        unsafe { support::free_handle::<Snapshot>(*slot, STATE_MAGIC) };
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
        unsafe { *size = b.to_bytes().len() };
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
        let data = b.to_bytes();
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
        // SAFETY: valid pointer (checked non-NULL) to NULL or a state of ours
        // (checked by the magic).
        if unsafe { support::store_handle(state, STATE_MAGIC, snap) } {
            Ok(Status::Ok)
        } else {
            Err(not_ours("fmi2DeSerializeFMUstate"))
        }
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
