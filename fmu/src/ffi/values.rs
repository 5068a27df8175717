//! Getting and setting variable values: fmi2GetReal … fmi2SetString.

use super::*;

// ------------------------------------------------------- get/set values

/// `fmi2GetReal`.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; `vr` and `value` NULL (only with `nvr` = 0) or arrays of `nvr` elements.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetReal(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *mut Fmi2Real,
) -> Fmi2Status {
    let f = "fmi2GetReal";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("nvr = {nvr}"),
        |i| {
            // SAFETY: per contract.
            let (vr, value) =
                unsafe { (slice(vr, nvr, f, "vr")?, slice_mut(value, nvr, f, "value")?) };
            i.model.get_real(vr, value, &mut i.log)
        },
    )
}

/// `fmi2GetInteger` (Integer and Enumeration variables).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; the arrays as in [`fmi2GetReal`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetInteger(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *mut Fmi2Integer,
) -> Fmi2Status {
    let f = "fmi2GetInteger";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("nvr = {nvr}"),
        |i| {
            // SAFETY: per contract.
            let (vr, value) =
                unsafe { (slice(vr, nvr, f, "vr")?, slice_mut(value, nvr, f, "value")?) };
            i.model.get_integer(vr, value, &mut i.log)
        },
    )
}

/// `fmi2GetBoolean`.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; the arrays as in [`fmi2GetReal`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetBoolean(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *mut Fmi2Boolean,
) -> Fmi2Status {
    let f = "fmi2GetBoolean";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("nvr = {nvr}"),
        |i| {
            // SAFETY: per contract.
            let (vr, value) =
                unsafe { (slice(vr, nvr, f, "vr")?, slice_mut(value, nvr, f, "value")?) };
            let mut b = vec![false; vr.len()];
            let st = i.model.get_boolean(vr, &mut b)?;
            for (o, x) in value.iter_mut().zip(b) {
                *o = Fmi2Boolean::from(x);
            }
            Ok(st)
        },
    )
}

/// `fmi2GetString`: this FMU has no String variables.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; the arrays as in [`fmi2GetReal`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetString(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *mut Fmi2String,
) -> Fmi2Status {
    let f = "fmi2GetString";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("nvr = {nvr}"),
        |_| {
            // SAFETY: per contract.
            let (vr, _) = unsafe { (slice(vr, nvr, f, "vr")?, slice_mut(value, nvr, f, "value")?) };
            match vr.first() {
                None => Ok(Status::Ok),
                Some(r) => Err(FmuError::error(format!(
                    "{f}: value reference {r} is not a String variable (this FMU has none)"
                ))),
            }
        },
    )
}

/// `fmi2SetReal` (parameters before initialization ends, inputs any time).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; the arrays as in [`fmi2GetReal`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetReal(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *const Fmi2Real,
) -> Fmi2Status {
    let f = "fmi2SetReal";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("nvr = {nvr}"),
        |i| {
            // SAFETY: per contract.
            let (vr, value) = unsafe { (slice(vr, nvr, f, "vr")?, slice(value, nvr, f, "value")?) };
            i.model.set_real(vr, value)
        },
    )
}

/// `fmi2SetInteger` (Enumeration parameters).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; the arrays as in [`fmi2GetReal`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetInteger(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *const Fmi2Integer,
) -> Fmi2Status {
    let f = "fmi2SetInteger";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("nvr = {nvr}"),
        |i| {
            // SAFETY: per contract.
            let (vr, value) = unsafe { (slice(vr, nvr, f, "vr")?, slice(value, nvr, f, "value")?) };
            i.model.set_integer(vr, value)
        },
    )
}

/// `fmi2SetBoolean`.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; the arrays as in [`fmi2GetReal`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetBoolean(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *const Fmi2Boolean,
) -> Fmi2Status {
    let f = "fmi2SetBoolean";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("nvr = {nvr}"),
        |i| {
            // SAFETY: per contract.
            let (vr, value) = unsafe { (slice(vr, nvr, f, "vr")?, slice(value, nvr, f, "value")?) };
            let b: Vec<bool> = value.iter().map(|&x| x != 0).collect();
            i.model.set_boolean(vr, &b)
        },
    )
}

/// `fmi2SetString`: this FMU has no String variables.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; the arrays as in [`fmi2GetReal`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetString(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *const Fmi2String,
) -> Fmi2Status {
    let f = "fmi2SetString";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("nvr = {nvr}"),
        |_| {
            // SAFETY: per contract.
            let (vr, _) = unsafe { (slice(vr, nvr, f, "vr")?, slice(value, nvr, f, "value")?) };
            match vr.first() {
                None => Ok(Status::Ok),
                Some(r) => Err(FmuError::error(format!(
                    "{f}: value reference {r} is not a String variable (this FMU has none)"
                ))),
            }
        },
    )
}
