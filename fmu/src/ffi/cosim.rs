//! The co-simulation functions: input/output derivatives (unsupported), fmi2DoStep, step status.

use super::*;

// ------------------------------------------------------- co-simulation

/// `fmi2SetRealInputDerivatives`: not supported (canInterpolateInputs = false).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetRealInputDerivatives(
    c: Fmi2Component,
    _vr: *const Fmi2ValueReference,
    _nvr: usize,
    _order: *const Fmi2Integer,
    _value: *const Fmi2Real,
) -> Fmi2Status {
    // SAFETY: per the function's contract.
    unsafe {
        unsupported(
            c,
            "fmi2SetRealInputDerivatives",
            "canInterpolateInputs is false",
        )
    }
}

/// `fmi2GetRealOutputDerivatives`: not supported (maxOutputDerivativeOrder = 0).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
    c: Fmi2Component,
    _vr: *const Fmi2ValueReference,
    _nvr: usize,
    _order: *const Fmi2Integer,
    _value: *mut Fmi2Real,
) -> Fmi2Status {
    // SAFETY: per the function's contract.
    unsafe {
        unsupported(
            c,
            "fmi2GetRealOutputDerivatives",
            "maxOutputDerivativeOrder is 0",
        )
    }
}

/// `fmi2DoStep`: evaluates the contact at the current inputs and advances the
/// time to `currentCommunicationPoint + communicationStepSize` (any step
/// size ≥ 0: canHandleVariableCommunicationStepSize).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DoStep(
    c: Fmi2Component,
    current_communication_point: Fmi2Real,
    communication_step_size: Fmi2Real,
    no_set_fmu_state_prior_to_current_point: Fmi2Boolean,
) -> Fmi2Status {
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        "fmi2DoStep",
        || {
            format!(
                "currentCommunicationPoint = {current_communication_point}, communicationStepSize = {communication_step_size}, noSetFMUStatePriorToCurrentPoint = {no_set_fmu_state_prior_to_current_point}"
            )
        },
        |i| {
            i.model.do_step(
                current_communication_point,
                communication_step_size,
                &mut i.log,
            )
        },
    )
}

/// `fmi2CancelStep`: not supported (steps are never asynchronous).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2CancelStep(c: Fmi2Component) -> Fmi2Status {
    // SAFETY: per the function's contract.
    unsafe { unsupported(c, "fmi2CancelStep", "fmi2DoStep never returns fmi2Pending") }
}

/// `fmi2GetStatus`: not supported (no asynchronous steps).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetStatus(
    c: Fmi2Component,
    _s: Fmi2StatusKind,
    _value: *mut Fmi2Status,
) -> Fmi2Status {
    // SAFETY: per the function's contract.
    unsafe { unsupported(c, "fmi2GetStatus", "fmi2DoStep never returns fmi2Pending") }
}

/// `fmi2GetRealStatus`: `fmi2LastSuccessfulTime` only.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; `value` a valid pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetRealStatus(
    c: Fmi2Component,
    s: Fmi2StatusKind,
    value: *mut Fmi2Real,
) -> Fmi2Status {
    let f = "fmi2GetRealStatus";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("s = {s}"),
        |i| {
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
        },
    )
}

/// `fmi2GetIntegerStatus`: not supported (no integer status kinds in FMI 2.0).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetIntegerStatus(
    c: Fmi2Component,
    _s: Fmi2StatusKind,
    _value: *mut Fmi2Integer,
) -> Fmi2Status {
    // SAFETY: per the function's contract.
    unsafe {
        unsupported(
            c,
            "fmi2GetIntegerStatus",
            "FMI 2.0 defines no integer status",
        )
    }
}

/// `fmi2GetBooleanStatus`: `fmi2Terminated` only (always false: the
/// contact never asks to end the simulation).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; `value` a valid pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetBooleanStatus(
    c: Fmi2Component,
    s: Fmi2StatusKind,
    value: *mut Fmi2Boolean,
) -> Fmi2Status {
    let f = "fmi2GetBooleanStatus";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("s = {s}"),
        |_| {
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
        },
    )
}

/// `fmi2GetStringStatus`: not supported (no asynchronous steps).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetStringStatus(
    c: Fmi2Component,
    _s: Fmi2StatusKind,
    _value: *mut Fmi2String,
) -> Fmi2Status {
    // SAFETY: per the function's contract.
    unsafe {
        unsupported(
            c,
            "fmi2GetStringStatus",
            "fmi2DoStep never returns fmi2Pending",
        )
    }
}
