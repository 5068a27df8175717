//! One co-simulation step of the variator FMU through its C functions, warm:
//! set the two disc speeds (the output speed changes every step, so every
//! step solves the roller balance and evaluates both contacts), fmi2DoStep,
//! read the torques. Tilt 0.3 rad: both contacts spin. The interpolation
//! map (default on) has visited the region before timing.
#![allow(unsafe_code, missing_docs)]

use std::ffi::CString;
use std::hint::black_box;
use std::ptr::null;

use criterion::{Criterion, criterion_group, criterion_main};
use traction_variator_fmu::ffi::*;
use traction_variator_fmu::variables::vr;

fn bench(c: &mut Criterion) {
    let name = CString::new("bench").expect("name");
    let guid = CString::new(traction_variator_fmu::model_description::guid()).expect("guid");
    // SAFETY: valid strings and NULL callbacks; the instance is used only here.
    let fmu = unsafe {
        fmi2Instantiate(
            name.as_ptr(),
            FMI2_COSIMULATION,
            guid.as_ptr(),
            null(),
            null(),
            0,
            0,
        )
    };
    assert!(!fmu.is_null());
    let inputs = [vr::OMEGA_IN, vr::OMEGA_OUT, vr::TILT];
    let outputs = [vr::TORQUE_IN, vr::TORQUE_OUT, vr::POWER_LOSS];
    let mut out = [0.0; 3];
    // Output speeds around 1 % creep at tilt 0.3 (ratio 0.8118).
    let speeds: Vec<f64> = (0..64)
        .map(|i| 300.0 * 0.8118 * (0.985 + 0.0002 * f64::from(i)))
        .collect();
    let mut k = 0usize;
    let mut t = 0.0;
    // SAFETY: the instance from fmi2Instantiate and arrays of matching lengths.
    let mut step = || unsafe {
        k = (k + 1) % speeds.len();
        let x = [300.0, speeds[k], 0.3];
        fmi2SetReal(fmu, inputs.as_ptr(), 3, x.as_ptr());
        let s = fmi2DoStep(fmu, t, 1e-3, 1);
        t += 1e-3;
        fmi2GetReal(fmu, outputs.as_ptr(), 3, out.as_mut_ptr());
        black_box((s, out))
    };
    // SAFETY: as above.
    unsafe {
        fmi2SetupExperiment(fmu, 0, 0.0, 0.0, 0, 0.0);
        fmi2EnterInitializationMode(fmu);
        fmi2ExitInitializationMode(fmu);
    }
    for _ in 0..2000 {
        assert_eq!(step().0, FMI2_OK);
    }
    c.bench_function("variator_fmu_step_spin_map", |b| b.iter(&mut step));
    // SAFETY: instance from fmi2Instantiate.
    unsafe { fmi2FreeInstance(fmu) };
}

criterion_group!(benches, bench);
criterion_main!(benches);
