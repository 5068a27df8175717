//! Inquiry, instantiation and the lifecycle: fmi2GetTypesPlatform … fmi2Reset.

use super::*;

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
        let callbacks = unsafe { support::callbacks(functions) };
        // SAFETY: NUL-terminated or NULL.
        let name = unsafe { opt_str(instance_name) }.unwrap_or("");
        let mut log = HostLogger {
            // SAFETY: the host's callbacks stay valid until fmi2FreeInstance
            // (FMI 2.0), and the logger lives in the instance.
            host: unsafe {
                HostCallback::new(
                    callbacks,
                    if name.is_empty() {
                        "TractionContact"
                    } else {
                        name
                    },
                )
            },
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
        if name.trim().is_empty() {
            return fail(
                &mut log,
                "fmi2Instantiate: instanceName is NULL, blank or not UTF-8 (FMI 2.0 requires a non-empty name)".into(),
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
            Ok(model) => support::into_handle(INSTANCE_MAGIC, Instance { model, log }),
            Err(m) => fail(&mut log, m),
        }
    });
    r.unwrap_or(std::ptr::null_mut())
}

/// `fmi2FreeInstance`: frees the instance; NULL is accepted and ignored.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeInstance(c: Fmi2Component) {
    if c.is_null() {
        return;
    }
    let _ = catch_unwind(|| {
        // SAFETY: per contract, c came from fmi2Instantiate; a pointer that is
        // not ours (or freed twice) is left alone rather than freed.
        unsafe { support::free_handle::<Instance>(c, INSTANCE_MAGIC) }
    });
}

/// `fmi2SetDebugLogging`: turns the trace on or off; with categories, only
/// those are enabled (unknown category → fmi2Error).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; `categories` NULL or `n` NUL-terminated strings.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetDebugLogging(
    c: Fmi2Component,
    logging_on: Fmi2Boolean,
    n_categories: usize,
    categories: *const Fmi2String,
) -> Fmi2Status {
    let f = "fmi2SetDebugLogging";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("loggingOn = {logging_on}, nCategories = {n_categories}"),
        |inst| {
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
        },
    )
}

/// `fmi2SetupExperiment`.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetupExperiment(
    c: Fmi2Component,
    tolerance_defined: Fmi2Boolean,
    tolerance: Fmi2Real,
    start_time: Fmi2Real,
    stop_time_defined: Fmi2Boolean,
    stop_time: Fmi2Real,
) -> Fmi2Status {
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        "fmi2SetupExperiment",
        || {
            format!(
                "toleranceDefined = {tolerance_defined}, tolerance = {tolerance}, startTime = {start_time}, stopTimeDefined = {stop_time_defined}, stopTime = {stop_time}"
            )
        },
        |i| {
            let tol = (tolerance_defined != 0).then_some(tolerance);
            let stop = (stop_time_defined != 0).then_some(stop_time);
            i.model.setup_experiment(tol, start_time, stop)
        },
    )
}

/// `fmi2EnterInitializationMode`.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2EnterInitializationMode(c: Fmi2Component) -> Fmi2Status {
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(inst, "fmi2EnterInitializationMode", String::new, |i| {
        i.model.enter_initialization_mode()
    })
}

/// `fmi2ExitInitializationMode`.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2ExitInitializationMode(c: Fmi2Component) -> Fmi2Status {
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(inst, "fmi2ExitInitializationMode", String::new, |i| {
        i.model.exit_initialization_mode(&mut i.log)
    })
}

/// `fmi2Terminate`: ends the simulation; frees nothing.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Terminate(c: Fmi2Component) -> Fmi2Status {
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(inst, "fmi2Terminate", String::new, |i| i.model.terminate())
}

/// `fmi2Reset`: back to the instantiated state with start values.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Reset(c: Fmi2Component) -> Fmi2Status {
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(inst, "fmi2Reset", String::new, |i| i.model.reset())
}
