//! The FMU through its C functions: a random call-sequence fuzz, NULL
//! pointers, FMU state get/set/serialize, and independent instances on
//! threads.
#![allow(unsafe_code, missing_docs, clippy::unwrap_used)]

use std::ffi::{CString, c_char, c_void};
use std::ptr::{null, null_mut};

use traction_testkit::XorShift64Star;
use traction_variator_fmu::ffi::*;
use traction_variator_fmu::model_description::guid;
use traction_variator_fmu::variables::{VARIABLES, vr};

/// A real for the fuzz: a special value (zero, ±0, NaN, ±∞, extremes) one
/// time in four, otherwise uniform in [−210, 490).
fn real(rng: &mut XorShift64Star) -> f64 {
    const SPECIAL: [f64; 10] = [
        0.0,
        -0.0,
        f64::NAN,
        f64::INFINITY,
        -f64::INFINITY,
        1e300,
        -1e-300,
        1.5,
        -2.0,
        1e6,
    ];
    if rng.below(4) == 0 {
        SPECIAL[rng.below(SPECIAL.len() as u64) as usize]
    } else {
        (rng.next_u64() as f64 / u64::MAX as f64 - 0.3) * 700.0
    }
}

fn instantiate() -> Fmi2Component {
    let name = CString::new("v").unwrap();
    let g = CString::new(guid()).unwrap();
    // SAFETY: valid strings; NULL callbacks are allowed (nothing logged).
    let c = unsafe {
        fmi2Instantiate(
            name.as_ptr(),
            FMI2_COSIMULATION,
            g.as_ptr(),
            null(),
            null(),
            0,
            0,
        )
    };
    assert!(!c.is_null());
    c
}

fn set(c: Fmi2Component, vrs: &[u32], v: &[f64]) -> Fmi2Status {
    // SAFETY: slices of equal length.
    unsafe { fmi2SetReal(c, vrs.as_ptr(), vrs.len(), v.as_ptr()) }
}

fn get(c: Fmi2Component, vrs: &[u32]) -> (Fmi2Status, Vec<f64>) {
    let mut v = vec![0.0; vrs.len()];
    // SAFETY: slices of equal length.
    let s = unsafe { fmi2GetReal(c, vrs.as_ptr(), vrs.len(), v.as_mut_ptr()) };
    (s, v)
}

/// Initialize with the interpolation map off: a few evaluations per test are
/// cheaper than filling the maps (the map path is benchmarked and checked
/// against the variator crate in the unit tests).
fn initialize(c: Fmi2Component) {
    // SAFETY: valid instance.
    unsafe {
        assert_eq!(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), FMI2_OK);
        assert_eq!(
            fmi2SetBoolean(c, [vr::MAP].as_ptr(), 1, [0].as_ptr()),
            FMI2_OK
        );
        assert_eq!(fmi2EnterInitializationMode(c), FMI2_OK);
        assert_eq!(fmi2ExitInitializationMode(c), FMI2_OK);
    }
}

const OUTPUTS: [u32; 6] = [
    vr::TORQUE_IN,
    vr::TORQUE_OUT,
    vr::POWER_LOSS,
    vr::EFFICIENCY,
    vr::SIDE_FORCE,
    vr::CONTACT_IN + 3,
];

#[test]
fn random_call_sequences_never_crash_or_return_nan() {
    // xorshift64*: a small deterministic generator for the fuzz.
    let mut rng = XorShift64Star::new(0x9e37_79b9_7f4a_7c15);
    let reals: Vec<u32> = VARIABLES.iter().map(|v| v.vr).collect();
    for _ in 0..6 {
        let c = instantiate();
        // SAFETY: valid instance and arrays.
        unsafe { fmi2SetBoolean(c, [vr::MAP].as_ptr(), 1, [0].as_ptr()) };
        for _ in 0..150 {
            let r = reals[rng.below(reals.len() as u64) as usize];
            // SAFETY: every call gets a valid instance and valid or NULL
            // pointers with matching lengths (NULL only with length checks).
            let status = unsafe {
                match rng.below(14) {
                    0 => fmi2SetupExperiment(c, 0, 0.0, real(&mut rng), 0, 0.0),
                    1 => fmi2EnterInitializationMode(c),
                    2 => fmi2ExitInitializationMode(c),
                    3 => fmi2DoStep(c, real(&mut rng).abs(), 1e-3, 1),
                    4 | 5 => set(c, &[r], &[real(&mut rng)]),
                    6 => {
                        // Plausible operating inputs.
                        let w = real(&mut rng).abs().min(500.0);
                        set(
                            c,
                            &[vr::OMEGA_IN, vr::OMEGA_OUT, vr::TILT, vr::END_LOAD],
                            &[
                                w,
                                w * (0.9 + 0.2 * rng.below(100) as f64 / 100.0),
                                (rng.below(100) as f64 - 50.0) / 100.0,
                                2e4,
                            ],
                        )
                    }
                    7 => {
                        let (s, v) = get(c, &OUTPUTS);
                        if s <= FMI2_WARNING {
                            assert!(v.iter().all(|x| x.is_finite()), "{v:?}");
                        }
                        s
                    }
                    8 => fmi2GetReal(c, null(), 1, null_mut()),
                    9 => {
                        let mut x = [0];
                        fmi2GetInteger(c, [vr::REGIME_IN].as_ptr(), 1, x.as_mut_ptr())
                    }
                    10 => fmi2SetInteger(c, [r].as_ptr(), 1, [rng.below(20) as i32 - 2].as_ptr()),
                    11 => fmi2Terminate(c),
                    12 => {
                        let s = fmi2Reset(c);
                        fmi2SetBoolean(c, [vr::MAP].as_ptr(), 1, [0].as_ptr());
                        s
                    }
                    _ => {
                        let mut s: Fmi2FmuState = null_mut();
                        let st = fmi2GetFMUstate(c, &mut s);
                        if st == FMI2_OK {
                            assert_eq!(fmi2SetFMUstate(c, s), FMI2_OK);
                        }
                        fmi2FreeFMUstate(c, &mut s);
                        st
                    }
                }
            };
            assert!((FMI2_OK..=FMI2_FATAL).contains(&status));
            assert_ne!(status, FMI2_FATAL, "no panic may reach the boundary");
        }
        // SAFETY: instance from fmi2Instantiate.
        unsafe { fmi2FreeInstance(c) };
    }
}

#[test]
fn null_pointers_are_errors() {
    // SAFETY: NULL instance and NULL arguments are what is tested.
    unsafe {
        assert_eq!(fmi2DoStep(null_mut(), 0.0, 1.0, 0), FMI2_ERROR);
        assert_eq!(fmi2GetReal(null_mut(), null(), 0, null_mut()), FMI2_ERROR);
        fmi2FreeInstance(null_mut());
        let g = CString::new(guid()).unwrap();
        assert!(
            fmi2Instantiate(null(), FMI2_COSIMULATION, g.as_ptr(), null(), null(), 0, 0).is_null()
        );
        let n = CString::new("v").unwrap();
        assert!(
            fmi2Instantiate(n.as_ptr(), FMI2_COSIMULATION, null(), null(), null(), 0, 0).is_null()
        );
        assert!(fmi2Instantiate(n.as_ptr(), 0, g.as_ptr(), null(), null(), 0, 0).is_null());
        let c = instantiate();
        initialize(c);
        assert_eq!(fmi2SetReal(c, null(), 1, null()), FMI2_ERROR);
        fmi2Reset(c);
        assert_eq!(fmi2GetFMUstate(c, null_mut()), FMI2_ERROR);
        assert_eq!(fmi2SetFMUstate(c, null_mut()), FMI2_ERROR);
        let mut t = 0.0;
        assert_eq!(
            fmi2GetRealStatus(c, FMI2_LAST_SUCCESSFUL_TIME, &mut t),
            FMI2_OK
        );
        fmi2FreeInstance(c);
    }
}

fn operate(c: Fmi2Component, t: f64, w_out: f64) -> Vec<f64> {
    assert_eq!(
        set(
            c,
            &[vr::OMEGA_IN, vr::OMEGA_OUT, vr::TILT],
            &[300.0, w_out, 0.2]
        ),
        FMI2_OK
    );
    // SAFETY: valid instance.
    assert_eq!(unsafe { fmi2DoStep(c, t, 1e-3, 1) }, FMI2_OK);
    let (s, v) = get(c, &OUTPUTS);
    assert_eq!(s, FMI2_OK);
    v
}

#[test]
fn fmu_state_restores_and_serializes() {
    let c = instantiate();
    initialize(c);
    let a = operate(c, 0.0, 240.0);
    let mut s: Fmi2FmuState = null_mut();
    // SAFETY: valid instance and state pointers throughout.
    unsafe {
        assert_eq!(fmi2GetFMUstate(c, &mut s), FMI2_OK);
        let b = operate(c, 1e-3, 230.0);
        assert_ne!(a, b);
        assert_eq!(fmi2SetFMUstate(c, s), FMI2_OK);
        assert_eq!(get(c, &OUTPUTS).1, a);
        let mut size = 0;
        assert_eq!(fmi2SerializedFMUstateSize(c, s, &mut size), FMI2_OK);
        let mut bytes = vec![0 as c_char; size];
        assert_eq!(
            fmi2SerializeFMUstate(c, s, bytes.as_mut_ptr(), size),
            FMI2_OK
        );
        assert_eq!(
            fmi2SerializeFMUstate(c, s, bytes.as_mut_ptr(), size - 1),
            FMI2_ERROR
        );
        fmi2Reset(c);
        initialize(c);
        operate(c, 0.0, 200.0);
        let mut s2: Fmi2FmuState = null_mut();
        assert_eq!(
            fmi2DeSerializeFMUstate(c, bytes.as_ptr(), size, &mut s2),
            FMI2_OK
        );
        assert_eq!(fmi2SetFMUstate(c, s2), FMI2_OK);
        assert_eq!(get(c, &OUTPUTS).1, a);
        let mut t = 0.0;
        fmi2GetRealStatus(c, FMI2_LAST_SUCCESSFUL_TIME, &mut t);
        assert_eq!(t, 1e-3);
        // A state of another kind is refused by its magic number.
        let mut bogus = [0u64; 8];
        assert_eq!(
            fmi2SetFMUstate(c, bogus.as_mut_ptr().cast::<c_void>()),
            FMI2_ERROR
        );
        fmi2FreeFMUstate(c, &mut s);
        fmi2FreeFMUstate(c, &mut s2);
        assert!(s.is_null() && s2.is_null());
        fmi2FreeInstance(c);
    }
}

#[test]
fn instances_on_threads_are_independent() {
    // Each roller solve starts from the previous root, so results repeat bit
    // for bit for the same call sequence (docs/decisions/0062): one instance
    // stepped five times at the output speed of case `k`.
    fn sequence(k: usize) -> Vec<f64> {
        let c = instantiate();
        initialize(c);
        let mut v = Vec::new();
        for _ in 0..5 {
            v = operate(c, 0.0, 240.0 - 10.0 * k as f64);
        }
        // SAFETY: instance from fmi2Instantiate.
        unsafe { fmi2FreeInstance(c) };
        v
    }
    let serial: Vec<Vec<f64>> = (0..3).map(sequence).collect();
    let threads: Vec<_> = (0..3)
        .map(|k| std::thread::spawn(move || sequence(k)))
        .collect();
    for (k, t) in threads.into_iter().enumerate() {
        assert_eq!(t.join().unwrap(), serial[k]);
    }
}
