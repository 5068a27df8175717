//! FMU states: get, set, free, serialize, deserialize; directional derivatives (unsupported).

use super::*;

// ------------------------------------------------------------ FMU state

/// # Safety
/// `s` NULL or a state made by this library.
unsafe fn state_ref<'a>(s: Fmi2FmuState, func: &str) -> Result<&'a mut Snapshot, FmuError> {
    if s.is_null() {
        return Err(null_arg(func, "FMUstate"));
    }
    // SAFETY: per contract, a state this library allocated.
    unsafe { support::handle_mut(s, STATE_MAGIC) }.ok_or_else(|| not_ours(func))
}

fn not_ours(func: &str) -> FmuError {
    FmuError::error(format!(
        "{func}: FMUstate was not created by this FMU (or was freed)"
    ))
}

/// Stores `state` at `*out`, reusing a state already there.
///
/// # Safety
/// `out` valid and non-NULL; `*out` NULL or a state made by this library.
unsafe fn store_state(out: *mut Fmi2FmuState, state: Snapshot, func: &str) -> FmuResult {
    // SAFETY: per contract.
    if unsafe { support::store_handle(out, STATE_MAGIC, state) } {
        Ok(Status::Ok)
    } else {
        Err(not_ours(func))
    }
}

/// `fmi2GetFMUstate`: a copy of the complete instance state; an existing
/// `*FMUstate` is overwritten.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; `state` a valid pointer whose target is NULL or a state from this library.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetFMUstate(c: Fmi2Component, state: *mut Fmi2FmuState) -> Fmi2Status {
    let f = "fmi2GetFMUstate";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("FMUstate = {state:p}"),
        |i| {
            if state.is_null() {
                return Err(null_arg(f, "FMUstate"));
            }
            let s = i.model.get_state()?;
            // SAFETY: per contract.
            unsafe { store_state(state, s, f) }
        },
    )
}

/// `fmi2SetFMUstate`.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; `state` a state from this library.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetFMUstate(c: Fmi2Component, state: Fmi2FmuState) -> Fmi2Status {
    let f = "fmi2SetFMUstate";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("FMUstate = {state:p}"),
        |i| {
            // SAFETY: per contract.
            let b = unsafe { state_ref(state, f) }?;
            i.model.set_state(b)
        },
    )
}

/// `fmi2FreeFMUstate`: frees `*FMUstate` and sets it to NULL; NULL accepted.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; `state` NULL or a valid pointer whose target is NULL or a state from this library.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeFMUstate(
    c: Fmi2Component,
    state: *mut Fmi2FmuState,
) -> Fmi2Status {
    let f = "fmi2FreeFMUstate";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("FMUstate = {state:p}"),
        |_| {
            // SAFETY: per contract.
            if state.is_null() || unsafe { *state }.is_null() {
                return Ok(Status::Ok);
            }
            // SAFETY: per contract.
            let p = unsafe { *state };
            // SAFETY: per contract (refused if not ours, then freed).
            unsafe { state_ref(p, f) }?;
            // SAFETY: p is a state of this library (checked above).
            unsafe { support::free_handle::<Snapshot>(p, STATE_MAGIC) };
            // SAFETY: valid pointer per contract.
            unsafe { *state = std::ptr::null_mut() };
            Ok(Status::Ok)
        },
    )
}

/// `fmi2SerializedFMUstateSize`.
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; `state` from this library; `size` a valid pointer.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
    c: Fmi2Component,
    state: Fmi2FmuState,
    size: *mut usize,
) -> Fmi2Status {
    let f = "fmi2SerializedFMUstateSize";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("FMUstate = {state:p}"),
        |_| {
            // SAFETY: per contract.
            let b = unsafe { state_ref(state, f) }?;
            if size.is_null() {
                return Err(null_arg(f, "size"));
            }
            // SAFETY: non-NULL, valid per contract.
            unsafe { *size = TractionFmu::serialize_state(b).len() };
            Ok(Status::Ok)
        },
    )
}

/// `fmi2SerializeFMUstate`: writes the state into `serializedState`
/// (`size` must be at least [`fmi2SerializedFMUstateSize`]).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; `state` from this library; `serialized` an array of `size` bytes.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializeFMUstate(
    c: Fmi2Component,
    state: Fmi2FmuState,
    serialized: *mut Fmi2Byte,
    size: usize,
) -> Fmi2Status {
    let f = "fmi2SerializeFMUstate";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("FMUstate = {state:p}, size = {size}"),
        |_| {
            // SAFETY: per contract.
            let b = unsafe { state_ref(state, f) }?;
            let bytes = TractionFmu::serialize_state(b);
            if size < bytes.len() {
                return Err(FmuError::error(format!(
                    "{f}: buffer of {size} bytes, the state needs {}",
                    bytes.len()
                )));
            }
            // SAFETY: per contract.
            let out =
                unsafe { slice_mut(serialized.cast::<u8>(), bytes.len(), f, "serializedState") }?;
            out.copy_from_slice(&bytes);
            Ok(Status::Ok)
        },
    )
}

/// `fmi2DeSerializeFMUstate`: makes a state from bytes of
/// [`fmi2SerializeFMUstate`] (reusing `*FMUstate` if not NULL).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet; `serialized` an array of `size` bytes; `state` a valid pointer whose
/// target is NULL or a state from this library.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: Fmi2Component,
    serialized: *const Fmi2Byte,
    size: usize,
    state: *mut Fmi2FmuState,
) -> Fmi2Status {
    let f = "fmi2DeSerializeFMUstate";
    // SAFETY: per the function's contract.
    let inst = unsafe { instance(c) };
    run(
        inst,
        f,
        || format!("size = {size}"),
        |_| {
            // SAFETY: per contract.
            let bytes = unsafe { slice(serialized.cast::<u8>(), size, f, "serializedState") }?;
            if state.is_null() {
                return Err(null_arg(f, "FMUstate"));
            }
            let s = TractionFmu::deserialize_state(bytes)?;
            // SAFETY: per contract.
            unsafe { store_state(state, s, f) }
        },
    )
}

/// `fmi2GetDirectionalDerivative`: not supported (providesDirectionalDerivative = false).
///
/// # Safety
/// `c` NULL or an instance from [`fmi2Instantiate`] not freed yet.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetDirectionalDerivative(
    c: Fmi2Component,
    _v_unknown: *const Fmi2ValueReference,
    _n_unknown: usize,
    _v_known: *const Fmi2ValueReference,
    _n_known: usize,
    _dv_known: *const Fmi2Real,
    _dv_unknown: *mut Fmi2Real,
) -> Fmi2Status {
    // SAFETY: per the function's contract.
    unsafe {
        unsupported(
            c,
            "fmi2GetDirectionalDerivative",
            "providesDirectionalDerivative is false",
        )
    }
}
