//! The C side shared by the FMUs: the hand-written FMI 2.0 types and
//! constants, and the guards an exported `fmi2*` function is built from.
//!
//! * [`slice()`], [`slice_mut`], [`opt_str`], [`lossy_string`]: a (pointer,
//!   count) pair or a C string checked and turned into a slice or string
//!   (`None` for NULL where a value is needed).
//! * [`into_handle`], [`handle_mut`], [`free_handle`], [`store_handle`]: the
//!   boxes behind `fmi2Component` and `fmi2FMUstate`, tagged with a magic
//!   number so that most misuse (a freed, foreign or NULL pointer) is refused
//!   instead of dereferenced as the wrong type.
//! * [`guarded`]: `catch_unwind` around a call of the safe side, with the
//!   panic's message; no panic crosses the C boundary.
//! * [`HostCallback`]: the host's `fmi2CallbackLogger` bound to one instance,
//!   `%` escaped as `%%` (FMI loggers treat the message as a printf format).
//!
//! What each FMU does with a refused call (its messages, the state it
//! enters, which messages its logger lets through) stays in that FMU's own
//! `ffi` module. Nothing here is exported as a C symbol.
#![allow(unsafe_code)]

use std::ffi::{CStr, CString, c_char, c_int, c_uint, c_void};
use std::panic::{AssertUnwindSafe, catch_unwind};

use crate::status::{FmuResult, Status};

/// `fmi2Component`: an instance created by `fmi2Instantiate`.
pub type Fmi2Component = *mut c_void;
/// `fmi2ComponentEnvironment`: the host's pointer passed back to callbacks.
pub type Fmi2ComponentEnvironment = *mut c_void;
/// `fmi2FMUstate`: a state created by `fmi2GetFMUstate`.
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

/// `fmi2CallbackFunctions`. The FMUs use only `logger` and
/// `component_environment` (they declare canNotUseMemoryManagementFunctions).
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

/// Makes a C string of any text: `%` doubled when `escape_percent`, NUL bytes
/// replaced by U+FFFD.
pub fn c_text(s: &str, escape_percent: bool) -> CString {
    let t = if escape_percent {
        s.replace('%', "%%")
    } else {
        s.to_owned()
    };
    CString::new(t.replace('\0', "\u{fffd}")).unwrap_or_default()
}

/// The message of a caught panic (`&str` or `String` payloads).
pub fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic payload".to_owned())
}

/// Runs one call of the safe side with unwinding caught: `Ok` with its
/// result, or `Err` with the panic's message. The caller poisons the
/// instance on `Err`: a caught panic may have left it half-updated.
///
/// # Errors
/// The message of the panic `f` raised.
pub fn guarded(f: impl FnOnce() -> FmuResult) -> Result<FmuResult, String> {
    catch_unwind(AssertUnwindSafe(f)).map_err(|p| panic_message(&*p))
}

/// The host's logging callback of one instance, with the instance name it
/// reports.
#[derive(Debug)]
pub struct HostCallback {
    logger: Fmi2CallbackLogger,
    env: Fmi2ComponentEnvironment,
    name: CString,
}

impl HostCallback {
    /// Binds the host's callbacks (`None`: nothing is logged) to an instance
    /// named `name`.
    ///
    /// # Safety
    /// The logger and its environment pointer must stay valid while this
    /// value lives (the FMI 2.0 contract: the callbacks given to
    /// `fmi2Instantiate` are valid until `fmi2FreeInstance`).
    pub unsafe fn new(callbacks: Option<Fmi2CallbackFunctions>, name: &str) -> Self {
        Self {
            logger: callbacks.and_then(|c| c.logger),
            env: callbacks.map_or(std::ptr::null_mut(), |c| c.component_environment),
            name: c_text(name, false),
        }
    }

    /// Whether the host gave a logger.
    pub fn has_logger(&self) -> bool {
        self.logger.is_some()
    }

    /// Sends one message to the host's logger (nothing without one): the
    /// category as is, the message with `%` escaped. Which messages to send
    /// is the caller's policy.
    pub fn send(&self, status: Status, category: &str, message: &str) {
        let Some(f) = self.logger else { return };
        let cat = c_text(category, false);
        let msg = c_text(message, true);
        // SAFETY: the host's logger with its environment pointer, valid per
        // `new`'s contract; all strings are valid NUL-terminated C strings
        // that outlive the call, and no variadic argument is passed.
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

/// The callbacks behind `functions` (`None` for NULL).
///
/// # Safety
/// `functions` NULL or a valid `fmi2CallbackFunctions`.
pub unsafe fn callbacks(functions: *const Fmi2CallbackFunctions) -> Option<Fmi2CallbackFunctions> {
    // SAFETY: NULL or valid, per the contract.
    unsafe { functions.as_ref() }.copied()
}

/// Turns (pointer, count) into a slice; NULL is allowed only with count 0
/// (`None` otherwise).
///
/// # Safety
/// `p` must point to `n` valid elements when non-NULL.
pub unsafe fn slice<'a, T>(p: *const T, n: usize) -> Option<&'a [T]> {
    if n == 0 {
        Some(&[])
    } else if p.is_null() {
        None
    } else {
        // SAFETY: the caller guarantees n valid elements.
        Some(unsafe { std::slice::from_raw_parts(p, n) })
    }
}

/// Mutable version of [`slice()`].
///
/// # Safety
/// `p` must point to `n` valid, writable elements when non-NULL.
pub unsafe fn slice_mut<'a, T>(p: *mut T, n: usize) -> Option<&'a mut [T]> {
    if n == 0 {
        Some(&mut [])
    } else if p.is_null() {
        None
    } else {
        // SAFETY: the caller guarantees n valid elements.
        Some(unsafe { std::slice::from_raw_parts_mut(p, n) })
    }
}

/// A C string as UTF-8: `None` for NULL or text that is not UTF-8.
///
/// # Safety
/// `s` NULL or a NUL-terminated string.
pub unsafe fn opt_str<'a>(s: *const c_char) -> Option<&'a str> {
    if s.is_null() {
        None
    } else {
        // SAFETY: non-NULL fmi2String arguments are NUL-terminated.
        unsafe { CStr::from_ptr(s) }.to_str().ok()
    }
}

/// A C string, invalid UTF-8 replaced by U+FFFD: `None` for NULL.
///
/// # Safety
/// `s` NULL or a NUL-terminated string.
pub unsafe fn lossy_string(s: *const c_char) -> Option<String> {
    // SAFETY: NULL checked; otherwise NUL-terminated per the contract.
    (!s.is_null()).then(|| unsafe { CStr::from_ptr(s) }.to_string_lossy().into_owned())
}

/// The box behind an `fmi2Component` or `fmi2FMUstate`: the magic number
/// first, so that it is read at the same place whatever `T` is.
#[repr(C)]
struct Tagged<T> {
    magic: u64,
    value: T,
}

/// Moves `value` into a box tagged with `magic` and hands the pointer to
/// the host; [`handle_mut`] borrows it, [`free_handle`] frees it.
pub fn into_handle<T>(magic: u64, value: T) -> *mut c_void {
    Box::into_raw(Box::new(Tagged { magic, value })).cast::<c_void>()
}

/// The value behind a handle of [`into_handle`]; `None` for NULL or a
/// pointer without `magic` (a freed or foreign pointer, most of the time).
///
/// # Safety
/// `p` NULL or a pointer from [`into_handle`] with this `T` (freed ones are
/// refused by the magic as long as their memory was not reused).
pub unsafe fn handle_mut<'a, T>(p: *mut c_void, magic: u64) -> Option<&'a mut T> {
    if p.is_null() {
        return None;
    }
    // SAFETY: per the contract, a Tagged<T> made by into_handle.
    let tagged = unsafe { &mut *p.cast::<Tagged<T>>() };
    (tagged.magic == magic).then_some(&mut tagged.value)
}

/// Frees a handle of [`into_handle`] (its magic cleared first); `false`,
/// and nothing freed, for NULL or a pointer without `magic`: leaking is
/// better than freeing foreign memory.
///
/// # Safety
/// As [`handle_mut`]; `p` is not used afterwards.
pub unsafe fn free_handle<T>(p: *mut c_void, magic: u64) -> bool {
    // SAFETY: per the contract.
    if unsafe { handle_mut::<T>(p, magic) }.is_none() {
        return false;
    }
    let tagged = p.cast::<Tagged<T>>();
    // SAFETY: a live Tagged<T> (checked above) made by Box::into_raw.
    unsafe {
        (*tagged).magic = 0;
        drop(Box::from_raw(tagged));
    }
    true
}

/// Stores `value` at `*slot`: a new handle when `*slot` is NULL, else into
/// the handle already there (the FMI 2 rule for `fmi2GetFMUstate` and
/// `fmi2DeSerializeFMUstate`). `false`, and nothing stored, when `*slot`
/// holds a pointer without `magic`.
///
/// # Safety
/// `slot` a valid, non-NULL pointer; `*slot` as [`handle_mut`]'s `p`.
pub unsafe fn store_handle<T>(slot: *mut *mut c_void, magic: u64, value: T) -> bool {
    // SAFETY: valid per the contract.
    let existing = unsafe { *slot };
    if existing.is_null() {
        // SAFETY: valid per the contract.
        unsafe { *slot = into_handle(magic, value) };
        return true;
    }
    // SAFETY: per the contract.
    match unsafe { handle_mut::<T>(existing, magic) } {
        Some(v) => {
            *v = value;
            true
        }
        None => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::status::FmuError;

    const MAGIC: u64 = 0x5445_5354_4d41_4749; // "TESTMAGI"

    #[test]
    fn slices_refuse_null_with_a_count_and_accept_it_without() {
        let data = [1.0, 2.0];
        // SAFETY: NULL with n = 0, or the two elements of `data`.
        unsafe {
            assert_eq!(slice::<f64>(std::ptr::null(), 0), Some(&[][..]));
            assert_eq!(slice::<f64>(std::ptr::null(), 2), None);
            assert_eq!(slice(data.as_ptr(), 2), Some(&data[..]));
            assert!(slice_mut::<f64>(std::ptr::null_mut(), 1).is_none());
        }
        let mut out = [0_i32; 3];
        // SAFETY: the three elements of `out`.
        let s = unsafe { slice_mut(out.as_mut_ptr(), 3) }.unwrap();
        s[2] = 7;
        assert_eq!(out, [0, 0, 7]);
    }

    #[test]
    fn strings_null_invalid_utf8_and_valid() {
        let bad = c"a\xffb";
        // SAFETY: NULL or NUL-terminated literals.
        unsafe {
            assert_eq!(opt_str(std::ptr::null()), None);
            assert_eq!(opt_str(c"inst".as_ptr()), Some("inst"));
            assert_eq!(opt_str(bad.as_ptr()), None);
            assert_eq!(lossy_string(std::ptr::null()), None);
            assert_eq!(lossy_string(bad.as_ptr()).as_deref(), Some("a\u{fffd}b"));
        }
        assert_eq!(
            c_text("50 % of 1\0", true).as_bytes(),
            "50 %% of 1\u{fffd}".as_bytes()
        );
        assert_eq!(c_text("a%b", false).as_bytes(), b"a%b");
    }

    #[test]
    fn handles_check_the_magic_and_are_reused_by_store() {
        let h = into_handle(MAGIC, 41_u32);
        // SAFETY: a handle of into_handle with T = u32, or NULL.
        unsafe {
            assert!(handle_mut::<u32>(h, MAGIC ^ 1).is_none());
            assert!(handle_mut::<u32>(std::ptr::null_mut(), MAGIC).is_none());
            *handle_mut::<u32>(h, MAGIC).unwrap() += 1;
            assert_eq!(*handle_mut::<u32>(h, MAGIC).unwrap(), 42);
            let mut slot = h;
            assert!(store_handle(&raw mut slot, MAGIC, 7_u32));
            assert_eq!(slot, h, "an existing handle is reused");
            assert_eq!(*handle_mut::<u32>(h, MAGIC).unwrap(), 7);
            assert!(!store_handle(&raw mut slot, MAGIC ^ 1, 8_u32));
            assert_eq!(*handle_mut::<u32>(h, MAGIC).unwrap(), 7);
            let mut empty: *mut c_void = std::ptr::null_mut();
            assert!(store_handle(&raw mut empty, MAGIC, 9_u32));
            assert_eq!(*handle_mut::<u32>(empty, MAGIC).unwrap(), 9);
            assert!(!free_handle::<u32>(h, MAGIC ^ 1), "wrong magic: not freed");
            assert!(free_handle::<u32>(h, MAGIC));
            assert!(free_handle::<u32>(empty, MAGIC));
            assert!(!free_handle::<u32>(std::ptr::null_mut(), MAGIC));
        }
    }

    #[test]
    fn guarded_returns_results_and_catches_panics() {
        assert_eq!(guarded(|| Ok(Status::Warning)), Ok(Ok(Status::Warning)));
        assert_eq!(
            guarded(|| Err(FmuError::error("no"))),
            Ok(Err(FmuError::error("no")))
        );
        // The panics print their message on stderr (the default hook).
        let s = guarded(|| panic!("boom {}", 1));
        let t = guarded(|| std::panic::panic_any(3_u8));
        assert_eq!(s, Err("boom 1".to_owned()));
        assert_eq!(t, Err("unknown panic payload".to_owned()));
    }

    /// What the test logger received.
    #[derive(Default)]
    struct Sink(Vec<(String, i32, String, String)>);

    /// The logger without the variadic tail: on x86-64 and aarch64 Linux a
    /// non-variadic callee reads the same registers, and no variadic
    /// argument is passed (`%` is escaped instead).
    unsafe extern "C" fn logger_impl(
        env: *mut c_void,
        name: *const c_char,
        status: c_int,
        category: *const c_char,
        message: *const c_char,
    ) {
        // SAFETY: env is the Sink registered below; the strings are valid.
        unsafe {
            let text = |p: *const c_char| CStr::from_ptr(p).to_string_lossy().into_owned();
            (*env.cast::<Sink>())
                .0
                .push((text(name), status, text(category), text(message)));
        }
    }

    type Plain =
        unsafe extern "C" fn(*mut c_void, *const c_char, c_int, *const c_char, *const c_char);

    #[test]
    #[cfg(all(
        target_os = "linux",
        any(target_arch = "x86_64", target_arch = "aarch64")
    ))]
    fn host_callback_sends_escaped_messages_with_the_instance_name() {
        let mut sink = Sink::default();
        // SAFETY: see logger_impl; the same argument registers for the fixed part.
        let logger = unsafe {
            std::mem::transmute::<
                Plain,
                unsafe extern "C" fn(
                    *mut c_void,
                    *const c_char,
                    c_int,
                    *const c_char,
                    *const c_char,
                    ...
                ),
            >(logger_impl)
        };
        let functions = Fmi2CallbackFunctions {
            logger: Some(logger),
            allocate_memory: None,
            free_memory: None,
            step_finished: None,
            component_environment: (&raw mut sink).cast(),
        };
        {
            // SAFETY: a valid struct; the sink outlives the callback.
            let host = unsafe { HostCallback::new(callbacks(&raw const functions), "inst") };
            assert!(host.has_logger());
            host.send(Status::Error, "logStatusError", "slip 5 % too high");
        }
        // SAFETY: NULL.
        let none = unsafe { HostCallback::new(callbacks(std::ptr::null()), "x") };
        assert!(!none.has_logger());
        none.send(Status::Error, "logStatusError", "dropped");
        assert_eq!(
            sink.0,
            [(
                "inst".to_owned(),
                FMI2_ERROR,
                "logStatusError".to_owned(),
                "slip 5 %% too high".to_owned()
            )]
        );
    }
}
