//! Fuzz-style robustness test through the C ABI: ≥ 10⁵ random steps with
//! random inputs (NaN, ±inf, negative, zero speed, huge, tiny) and random call
//! orders drawn from the FMI 2 co-simulation state machine, plus some calls
//! that the state machine forbids. Checks: no panic escapes (no fmi2Fatal),
//! every fmi2Error comes with a logged message (non-NULL category), and every
//! output returned with fmi2OK/fmi2Warning is finite.
#![allow(unsafe_code)]

use std::ffi::{CStr, CString, c_char, c_int, c_void};

use traction_fmu::ffi::*;
use traction_fmu::model_description::guid;
use traction_fmu::variables::{VARIABLES, vr};
use traction_testkit::XorShift64Star;

#[derive(Default)]
struct Sink {
    messages: usize,
    errors: usize,
    null_category: usize,
    last: String,
    /// Messages of the logAll category (the call trace).
    trace: Vec<String>,
}

/// The logger, without the variadic tail: on x86-64 and aarch64 Linux a
/// non-variadic callee reads the same registers, and the FMU passes no
/// variadic arguments (it escapes `%` instead).
unsafe extern "C" fn logger_impl(
    env: *mut c_void,
    _name: *const c_char,
    status: c_int,
    category: *const c_char,
    message: *const c_char,
) {
    // SAFETY: env is the &mut Sink we registered; strings from the FMU are valid.
    let sink = unsafe { &mut *env.cast::<Sink>() };
    sink.messages += 1;
    if status >= FMI2_ERROR {
        sink.errors += 1;
    }
    if category.is_null() {
        sink.null_category += 1;
    }
    // SAFETY: NUL-terminated when non-NULL.
    let is_trace =
        !category.is_null() && unsafe { CStr::from_ptr(category) }.to_bytes() == b"logAll";
    if is_trace && !message.is_null() {
        // SAFETY: NUL-terminated.
        let m = unsafe { CStr::from_ptr(message) }
            .to_string_lossy()
            .into_owned();
        sink.trace.push(m);
        return;
    }
    if !message.is_null() {
        // SAFETY: NUL-terminated.
        sink.last = unsafe { CStr::from_ptr(message) }
            .to_string_lossy()
            .into_owned();
    }
}

type Plain = unsafe extern "C" fn(*mut c_void, *const c_char, c_int, *const c_char, *const c_char);

fn callbacks(sink: &mut Sink) -> Fmi2CallbackFunctions {
    // SAFETY: see logger_impl; same argument registers for the fixed part.
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
    Fmi2CallbackFunctions {
        logger: Some(logger),
        allocate_memory: None,
        free_memory: None,
        step_finished: None,
        component_environment: std::ptr::from_mut(sink).cast(),
    }
}

/// The fuzz's random choices: xorshift64* with values that include the
/// special floats.
struct Rng(XorShift64Star);
impl Rng {
    fn below(&mut self, n: u64) -> u64 {
        self.0.below(n)
    }
    fn unit(&mut self) -> f64 {
        self.0.unit()
    }
    fn value(&mut self, scale: f64) -> f64 {
        match self.below(20) {
            0 => f64::NAN,
            1 => f64::INFINITY,
            2 => f64::NEG_INFINITY,
            3 => 0.0,
            4 => -0.0,
            5 => 1e300,
            6 => -1e-300,
            7 => f64::MIN_POSITIVE,
            8 => -scale * self.unit(),
            _ => scale * (2.0 * self.unit() - 0.5),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum S {
    Instantiated,
    Init,
    Step,
    Terminated,
    Error,
}

fn output_vrs() -> Vec<u32> {
    VARIABLES
        .iter()
        .filter(|v| v.causality == traction_fmu::variables::Causality::Output && v.vr != vr::REGIME)
        .map(|v| v.vr)
        .collect()
}

#[test]
fn hundred_thousand_random_steps_through_the_c_abi() {
    // rheology_map off: every step integrates the strips (random states would
    // make the map build a new cell at nearly every step).
    let (steps, calls, n_err, n_ok_outputs) = fuzz(0x9e37_79b9_7f4a_7c15, 100_000, false);
    eprintln!(
        "{steps} steps, {calls} calls, {n_err} errors (all logged), {n_ok_outputs} finite output reads"
    );
}

#[test]
fn random_steps_with_the_rheology_map() {
    // rheology_map on (off by default): inputs and parameters drawn from small
    // pools (specials included), the same state machine and checks. The
    // states still hardly recur (8 values per variable), so nearly every
    // step with spin builds map cells (milliseconds each): 3000 steps.
    let (steps, calls, n_err, n_ok_outputs) = fuzz(0x2545_f491_4f6c_dd1d, 3_000, true);
    eprintln!(
        "map: {steps} steps, {calls} calls, {n_err} errors (all logged), {n_ok_outputs} finite output reads"
    );
}

/// Random call sequences from the state machine with random values; with
/// `map` the rheology map is on and values come from small pools. Returns
/// (steps, calls, errors, finite output reads).
#[allow(clippy::unwrap_used)]
fn fuzz(seed: u64, n_steps: usize, map: bool) -> (usize, usize, usize, usize) {
    let mut sink = Box::new(Sink::default());
    let cb = callbacks(&mut sink);
    let name = CString::new("fuzz").unwrap();
    let g = CString::new(guid()).unwrap();
    // SAFETY: valid strings and callbacks that outlive the instance.
    let c = unsafe {
        fmi2Instantiate(
            name.as_ptr(),
            FMI2_COSIMULATION,
            g.as_ptr(),
            std::ptr::null(),
            &cb,
            0,
            0,
        )
    };
    assert!(!c.is_null());
    let outs = output_vrs();
    let mut values = vec![0.0; outs.len()];
    let inputs = [
        (vr::LOAD, 2000.0),
        (vr::OMEGA1, 800.0),
        (vr::OMEGA2, 400.0),
        (vr::SIDE_SLIP_VELOCITY, 2.0),
        (vr::SKEW_ANGLE, 0.1),
        (vr::SPIN, 50.0),
        (vr::INLET_TEMPERATURE, 100.0),
    ];
    let params = [
        (vr::RX1, 0.05),
        (vr::RY2, 0.1),
        (vr::MU_USER, 0.2),
        (vr::TILT_ANGLE, 0.5),
        (vr::U_REG, 0.1),
        (vr::DEBORAH, 2.0),
        (vr::Z0, 1.0),
        (vr::MU_SPIN_USER, 0.2),
    ];
    let mut rng = Rng(XorShift64Star::new(seed));
    let set_map = |c| {
        let x = Fmi2Boolean::from(map);
        // SAFETY: valid instance and pointers.
        assert_eq!(
            unsafe { fmi2SetBoolean(c, &vr::RHEOLOGY_MAP, 1, &x) },
            FMI2_OK
        );
    };
    set_map(c);
    // With the map: each value from a pool of 8 per variable (including the
    // specials) so that operating states recur.
    let pooled = |rng: &mut Rng, scale: f64, special: bool| -> f64 {
        let i = rng.below(8);
        let u = [0.05, 0.2, 0.45, 0.7, 0.95, 0.1, 0.6, 0.85][i as usize];
        if special && i < 3 {
            [f64::NAN, 0.0, -1e-300][i as usize]
        } else {
            scale * (2.0 * u - 0.5)
        }
    };
    let mut s = S::Instantiated;
    let mut saved: Fmi2FmuState = std::ptr::null_mut();
    let (mut steps, mut t) = (0usize, 0.0f64);
    let (mut n_err, mut n_ok_outputs) = (0usize, 0usize);
    let mut calls = 0usize;
    while steps < n_steps {
        calls += 1;
        let before = (sink.messages, sink.errors);
        let op = rng.below(100);
        // SAFETY: all pointers below are valid for the lengths passed.
        let status = unsafe {
            match (s, op) {
                (S::Instantiated, 0..=9) => fmi2SetupExperiment(c, 0, 0.0, 0.0, 1, 1e9),
                (S::Instantiated, 10..=29) | (S::Init, 0..=19) => {
                    let (r, scale) = params[rng.below(params.len() as u64) as usize];
                    let x = if map {
                        let special = rng.below(3) == 0;
                        pooled(&mut rng, scale, special).abs() + 1e-3
                    } else if rng.below(3) == 0 {
                        rng.value(scale)
                    } else {
                        scale * rng.unit() + 1e-3
                    };
                    fmi2SetReal(c, &r, 1, &x)
                }
                (S::Instantiated, 30..=39) | (S::Init, 20..=29) => {
                    if rng.below(4) == 0 {
                        // Spin peak (mu_spin_user) or disc compliance (the
                        // anisotropic-stiffness path) on or off.
                        let x = rng.below(2) as Fmi2Boolean;
                        let r = [vr::SPIN_PEAK, vr::COMPLIANCE][rng.below(2) as usize];
                        fmi2SetBoolean(c, &r, 1, &x)
                    } else {
                        let r = [vr::SPIN_SOURCE, vr::SIDE_SLIP_SOURCE, vr::RHEOLOGY]
                            [rng.below(3) as usize];
                        let x = rng.below(4) as i32;
                        fmi2SetInteger(c, &r, 1, &x)
                    }
                }
                (S::Instantiated, 40..=79) => fmi2EnterInitializationMode(c),
                (S::Init, 30..=89) => fmi2ExitInitializationMode(c),
                (S::Step, 0..=29) | (S::Instantiated | S::Init, 80..=99) => {
                    let (r, scale) = inputs[rng.below(inputs.len() as u64) as usize];
                    let x = if map {
                        let special = rng.below(5) == 0;
                        pooled(&mut rng, scale, special)
                    } else if rng.below(5) == 0 {
                        rng.value(scale)
                    } else {
                        scale * (2.0 * rng.unit() - 0.5)
                    };
                    fmi2SetReal(c, &r, 1, &x)
                }
                (S::Step, 30..=79) => {
                    let h = if rng.below(200) == 0 {
                        rng.value(1.0)
                    } else {
                        1e-3 * rng.unit()
                    };
                    let st = fmi2DoStep(c, t, h, 1);
                    if st <= FMI2_WARNING {
                        t += h;
                    }
                    steps += 1;
                    st
                }
                (S::Step | S::Terminated | S::Error, 80..=89) | (S::Error, 0..=29) => {
                    let st = fmi2GetReal(c, outs.as_ptr(), outs.len(), values.as_mut_ptr());
                    if st <= FMI2_WARNING {
                        n_ok_outputs += 1;
                        assert!(
                            values.iter().all(|v| v.is_finite()),
                            "non-finite output with status {st}: {values:?}"
                        );
                    }
                    st
                }
                (S::Step, 90..=93) | (S::Terminated, 0..=9) => fmi2GetFMUstate(c, &mut saved),
                (S::Step | S::Error | S::Terminated, 94..=96) if !saved.is_null() => {
                    // Round trip through the serialized form, then restore.
                    let mut size = 0usize;
                    assert_eq!(fmi2SerializedFMUstateSize(c, saved, &mut size), FMI2_OK);
                    let mut buf = vec![0 as c_char; size];
                    assert_eq!(
                        fmi2SerializeFMUstate(c, saved, buf.as_mut_ptr(), size),
                        FMI2_OK
                    );
                    let mut copy: Fmi2FmuState = std::ptr::null_mut();
                    assert_eq!(
                        fmi2DeSerializeFMUstate(c, buf.as_ptr(), size, &mut copy),
                        FMI2_OK
                    );
                    let st = fmi2SetFMUstate(c, copy);
                    assert_eq!(fmi2FreeFMUstate(c, &mut copy), FMI2_OK);
                    assert!(copy.is_null());
                    st
                }
                (S::Step, 97) | (S::Error, 30..=39) => fmi2Terminate(c),
                (_, 98) | (S::Error | S::Terminated, 40..=69) => fmi2Reset(c),
                (_, 99) => {
                    // Calls the state machine or the FMU forbids: must be fmi2Error.
                    let bad = 9999u32;
                    let x = 1.0;
                    match rng.below(4) {
                        0 => fmi2SetReal(c, &bad, 1, &x),
                        1 => fmi2GetReal(c, &bad, 1, values.as_mut_ptr()),
                        2 => fmi2SetReal(c, &vr::FX, 1, &x),
                        _ => fmi2GetReal(c, std::ptr::null(), 3, std::ptr::null_mut()),
                    }
                }
                _ => continue,
            }
        };
        assert_ne!(status, FMI2_FATAL, "fatal status: {}", sink.last);
        assert_eq!(sink.null_category, 0);
        if status == FMI2_ERROR {
            n_err += 1;
            assert!(
                sink.errors > before.1,
                "fmi2Error without a logged error message (op {op}, state {s:?})"
            );
            assert!(!sink.last.is_empty());
        }
        // Follow the state machine from the FMU's answers.
        s = match (status, s, op) {
            // Any error, in any state, leaves the instance in the Error state.
            (FMI2_ERROR, _, _) => S::Error,
            (_, S::Instantiated, 40..=79) => S::Init,
            (_, S::Init, 30..=89) => S::Step,
            (_, S::Step, 97) | (_, S::Error, 30..=39) => S::Terminated,
            (_, _, 98) | (_, S::Error | S::Terminated, 40..=69) => {
                t = 0.0;
                set_map(c);
                S::Instantiated
            }
            (_, S::Step | S::Error | S::Terminated, 94..=96) => {
                // Restored a state saved in Step or Terminated.
                let mut x = 0.0;
                // SAFETY: valid instance and pointer.
                if unsafe { fmi2GetRealStatus(c, FMI2_LAST_SUCCESSFUL_TIME, &mut x) } == FMI2_OK {
                    t = x;
                }
                // SAFETY: valid instance.
                let probe = unsafe { fmi2DoStep(c, t, 0.0, 1) };
                if probe == FMI2_ERROR {
                    S::Error
                } else {
                    S::Step
                }
            }
            _ => s,
        };
        if s == S::Error && rng.below(2) == 0 {
            // Recover as a master would: reset.
            // SAFETY: valid instance.
            assert_eq!(unsafe { fmi2Reset(c) }, FMI2_OK);
            set_map(c);
            s = S::Instantiated;
            t = 0.0;
        }
    }
    // SAFETY: saved is NULL or ours; c is ours.
    unsafe {
        assert_eq!(fmi2FreeFMUstate(c, &mut saved), FMI2_OK);
        fmi2FreeInstance(c);
        fmi2FreeInstance(std::ptr::null_mut());
    }
    assert!(
        n_err > n_steps / 1000 && n_ok_outputs > n_steps / 100,
        "too few errors ({n_err}) or outputs ({n_ok_outputs}) exercised"
    );
    (steps, calls, n_err, n_ok_outputs)
}

#[test]
fn null_pointers_and_unsupported_functions_are_errors_with_messages() {
    let mut sink = Box::new(Sink::default());
    let cb = callbacks(&mut sink);
    let name = CString::new("nulls").unwrap();
    let g = CString::new(guid()).unwrap();
    let wrong = CString::new("{00000000-0000-0000-0000-000000000000}").unwrap();
    // SAFETY: valid or NULL pointers as the standard allows.
    unsafe {
        assert!(
            fmi2Instantiate(name.as_ptr(), 0, g.as_ptr(), std::ptr::null(), &cb, 0, 0).is_null()
        );
        assert!(sink.last.contains("co-simulation"), "{}", sink.last);
        assert!(
            fmi2Instantiate(
                name.as_ptr(),
                1,
                wrong.as_ptr(),
                std::ptr::null(),
                &cb,
                0,
                0
            )
            .is_null()
        );
        assert!(sink.last.contains("GUID"));
        assert!(
            fmi2Instantiate(std::ptr::null(), 1, g.as_ptr(), std::ptr::null(), &cb, 0, 0).is_null()
        );
        assert!(
            fmi2Instantiate(
                name.as_ptr(),
                1,
                g.as_ptr(),
                std::ptr::null(),
                std::ptr::null(),
                0,
                0
            )
            .is_null()
        );
        let c = fmi2Instantiate(name.as_ptr(), 1, g.as_ptr(), std::ptr::null(), &cb, 0, 1);
        assert!(!c.is_null());
        assert_eq!(
            fmi2SetupExperiment(std::ptr::null_mut(), 0, 0.0, 0.0, 0, 0.0),
            FMI2_ERROR
        );
        let e0 = sink.errors;
        assert_eq!(
            fmi2GetDirectionalDerivative(
                c,
                std::ptr::null(),
                0,
                std::ptr::null(),
                0,
                std::ptr::null(),
                std::ptr::null_mut()
            ),
            FMI2_ERROR
        );
        assert_eq!(
            fmi2SetRealInputDerivatives(c, std::ptr::null(), 0, std::ptr::null(), std::ptr::null()),
            FMI2_ERROR
        );
        assert_eq!(
            fmi2GetRealOutputDerivatives(
                c,
                std::ptr::null(),
                0,
                std::ptr::null(),
                std::ptr::null_mut()
            ),
            FMI2_ERROR
        );
        assert_eq!(fmi2CancelStep(c), FMI2_ERROR);
        let mut st = 0;
        assert_eq!(fmi2GetStatus(c, FMI2_DO_STEP_STATUS, &mut st), FMI2_ERROR);
        let mut i = 0;
        assert_eq!(
            fmi2GetIntegerStatus(c, FMI2_DO_STEP_STATUS, &mut i),
            FMI2_ERROR
        );
        let mut sp: Fmi2String = std::ptr::null();
        assert_eq!(
            fmi2GetStringStatus(c, FMI2_PENDING_STATUS, &mut sp),
            FMI2_ERROR
        );
        assert_eq!(sink.errors, e0 + 7, "each unsupported call logs one error");
        assert!(sink.last.contains("not supported"));
        // '%' in messages is escaped for printf-style loggers.
        let pct = CString::new("100%").unwrap();
        let cats = [pct.as_ptr()];
        assert_eq!(fmi2SetDebugLogging(c, 1, 1, cats.as_ptr()), FMI2_ERROR);
        assert!(sink.last.contains("100%%"), "{}", sink.last);
        let ok = CString::new("logAll").unwrap();
        let cats = [ok.as_ptr()];
        assert_eq!(fmi2SetDebugLogging(c, 1, 1, cats.as_ptr()), FMI2_OK);
        // Empty array calls are fine with NULL pointers.
        assert_eq!(
            fmi2SetReal(c, std::ptr::null(), 0, std::ptr::null()),
            FMI2_OK
        );
        assert_eq!(
            fmi2GetString(c, std::ptr::null(), 0, std::ptr::null_mut()),
            FMI2_OK
        );
        let one = vr::FX;
        let mut sp = std::ptr::null();
        assert_eq!(fmi2GetString(c, &one, 1, &mut sp), FMI2_ERROR);
        assert_eq!(CStr::from_ptr(fmi2GetVersion()).to_str().unwrap(), "2.0");
        assert_eq!(
            CStr::from_ptr(fmi2GetTypesPlatform()).to_str().unwrap(),
            "default"
        );
        // Terminate frees nothing: outputs are still readable afterwards.
        assert_eq!(fmi2Reset(c), FMI2_OK);
        assert_eq!(fmi2EnterInitializationMode(c), FMI2_OK);
        assert_eq!(fmi2ExitInitializationMode(c), FMI2_OK);
        assert_eq!(fmi2DoStep(c, 0.0, 0.1, 1), FMI2_OK);
        assert_eq!(fmi2Terminate(c), FMI2_OK);
        let mut x = f64::NAN;
        assert_eq!(fmi2GetReal(c, &vr::P0, 1, &mut x), FMI2_OK);
        assert!(x > 1e8);
        let mut b = 1;
        assert_eq!(fmi2GetBooleanStatus(c, FMI2_TERMINATED, &mut b), FMI2_OK);
        assert_eq!(b, 0);
        fmi2FreeInstance(c);
    }
}

#[test]
fn instances_are_independent_across_threads() {
    let run = |omega1: f64| {
        let mut sink = Box::new(Sink::default());
        let cb = callbacks(&mut sink);
        let name = CString::new(format!("i{omega1}")).unwrap();
        let g = CString::new(guid()).unwrap();
        // SAFETY: valid pointers for the instance's lifetime.
        unsafe {
            let c = fmi2Instantiate(name.as_ptr(), 1, g.as_ptr(), std::ptr::null(), &cb, 0, 0);
            assert!(!c.is_null());
            let vrs = [vr::OMEGA1, vr::OMEGA2];
            let v = [omega1, 270.0];
            assert_eq!(fmi2SetReal(c, vrs.as_ptr(), 2, v.as_ptr()), FMI2_OK);
            assert_eq!(fmi2EnterInitializationMode(c), FMI2_OK);
            assert_eq!(fmi2ExitInitializationMode(c), FMI2_OK);
            let mut fx = 0.0;
            for k in 0..10_000 {
                assert_eq!(fmi2DoStep(c, f64::from(k) * 1e-4, 1e-4, 1), FMI2_OK);
                assert_eq!(fmi2GetReal(c, &vr::FX, 1, &mut fx), FMI2_OK);
            }
            fmi2FreeInstance(c);
            fx
        }
    };
    let sequential = [run(600.0), run(590.0)];
    let a = std::thread::spawn(move || run(600.0));
    let b = std::thread::spawn(move || run(590.0));
    let threaded = [a.join().unwrap(), b.join().unwrap()];
    assert_eq!(sequential, threaded);
    assert_ne!(sequential[0], sequential[1]);
}

fn instantiate(
    sink: &mut Sink,
    cb: &Fmi2CallbackFunctions,
    name: &str,
    logging_on: Fmi2Boolean,
) -> Fmi2Component {
    let name = CString::new(name).expect("instance name without NUL");
    let g = CString::new(guid()).expect("GUID without NUL");
    let _ = sink;
    // SAFETY: valid strings and callbacks that outlive the instance.
    unsafe {
        fmi2Instantiate(
            name.as_ptr(),
            FMI2_COSIMULATION,
            g.as_ptr(),
            std::ptr::null(),
            cb,
            0,
            logging_on,
        )
    }
}

#[test]
fn log_all_traces_the_fmi_calls() {
    let mut sink = Box::new(Sink::default());
    let cb = callbacks(&mut sink);
    let c = instantiate(&mut sink, &cb, "trace", 0);
    assert!(!c.is_null());
    // SAFETY: c is ours; valid pointers.
    unsafe {
        // Logging off: no trace.
        assert_eq!(fmi2EnterInitializationMode(c), FMI2_OK);
        assert!(sink.trace.is_empty(), "{:?}", sink.trace);
        let all = CString::new("logAll").unwrap();
        let cats = [all.as_ptr()];
        assert_eq!(fmi2SetDebugLogging(c, 1, 1, cats.as_ptr()), FMI2_OK);
        assert_eq!(fmi2ExitInitializationMode(c), FMI2_OK);
        let w = 600.0;
        assert_eq!(fmi2SetReal(c, &vr::OMEGA1, 1, &w), FMI2_OK);
        assert_eq!(fmi2DoStep(c, 0.0, 0.001, 1), FMI2_OK);
        let mut fx = 0.0;
        assert_eq!(fmi2GetReal(c, &vr::FX, 1, &mut fx), FMI2_OK);
        assert_eq!(
            sink.trace,
            [
                "fmi2ExitInitializationMode()",
                "fmi2SetReal(nvr = 1)",
                "fmi2DoStep(currentCommunicationPoint = 0, communicationStepSize = 0.001, noSetFMUStatePriorToCurrentPoint = 1)",
                "fmi2GetReal(nvr = 1)",
            ]
        );
        // Only the warning category enabled: no trace; logging off: none.
        let warn = CString::new("logStatusWarning").unwrap();
        let cats = [warn.as_ptr()];
        assert_eq!(fmi2SetDebugLogging(c, 1, 1, cats.as_ptr()), FMI2_OK);
        let n = sink.trace.len();
        assert_eq!(fmi2DoStep(c, 0.001, 0.001, 1), FMI2_OK);
        assert_eq!(fmi2SetDebugLogging(c, 0, 0, std::ptr::null()), FMI2_OK);
        assert_eq!(fmi2DoStep(c, 0.002, 0.001, 1), FMI2_OK);
        assert_eq!(sink.trace.len(), n);
        fmi2FreeInstance(c);
    }
    // loggingOn at instantiation, no categories given: everything, trace included.
    let c = instantiate(&mut sink, &cb, "trace2", 1);
    // SAFETY: c is ours.
    unsafe {
        assert_eq!(fmi2Terminate(c), FMI2_ERROR);
        fmi2FreeInstance(c);
    }
    assert_eq!(
        sink.trace.last().map(String::as_str),
        Some("fmi2Terminate()")
    );
}

#[test]
fn every_refused_call_enters_the_error_state() {
    let mut sink = Box::new(Sink::default());
    let cb = callbacks(&mut sink);
    // SAFETY: each c is ours; NULL arrays are what is tested.
    unsafe {
        // fmi2CancelStep (unsupported) refuses and enters the error state:
        // only fmi2GetXXX, fmi2Reset and fmi2FreeInstance remain allowed.
        let c = instantiate(&mut sink, &cb, "cancel", 0);
        assert_eq!(fmi2CancelStep(c), FMI2_ERROR);
        assert!(sink.last.contains("fmi2CancelStep"), "{}", sink.last);
        assert_eq!(fmi2EnterInitializationMode(c), FMI2_ERROR);
        assert!(sink.last.contains("Error"), "{}", sink.last);
        assert_eq!(fmi2Reset(c), FMI2_OK);
        assert_eq!(fmi2EnterInitializationMode(c), FMI2_OK);
        // A NULL array refused at the boundary: the same.
        assert_eq!(
            fmi2GetReal(c, std::ptr::null(), 2, std::ptr::null_mut()),
            FMI2_ERROR
        );
        assert_eq!(fmi2ExitInitializationMode(c), FMI2_ERROR);
        fmi2FreeInstance(c);
        // A blank instance name is refused with a message.
        for name in ["", "   ", "\t \n"] {
            assert!(instantiate(&mut sink, &cb, name, 0).is_null(), "{name:?}");
            assert!(sink.last.contains("instanceName"), "{}", sink.last);
        }
    }
}
