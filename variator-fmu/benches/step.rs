//! One co-simulation step of the variator FMU through its C functions, warm:
//! set the two disc speeds (the output speed changes every step, so every
//! step solves the roller balance and evaluates both contacts), fmi2DoStep,
//! read the torques. Tilt 0.3 rad (speed ratio 0.637): both contacts spin;
//! the output runs 0.3–1.5 % below the geometric speed (creep of a driven
//! vehicle). `_map`: `rheology_map = true`, its cells visited before timing;
//! `_direct`: `rheology_map = false` (the rheology integrated at every call).
#![allow(unsafe_code, missing_docs)]

use std::ffi::CString;
use std::hint::black_box;
use std::ptr::null;

use criterion::{Criterion, criterion_group, criterion_main};
use traction_variator_fmu::ffi::*;
use traction_variator_fmu::variables::vr;

fn bench_with(c: &mut Criterion, name: &str, map: bool, warm_steps: usize) {
    let inst = CString::new("bench").expect("name");
    let guid = CString::new(traction_variator_fmu::model_description::guid()).expect("guid");
    // SAFETY: valid strings and NULL callbacks; the instance is used only here.
    let fmu = unsafe {
        fmi2Instantiate(
            inst.as_ptr(),
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
    let mut ratio = 0.0;
    // SAFETY: the instance from fmi2Instantiate, arrays of matching lengths.
    unsafe {
        fmi2SetBoolean(fmu, [vr::MAP].as_ptr(), 1, [i32::from(map)].as_ptr());
        fmi2SetupExperiment(fmu, 0, 0.0, 0.0, 0, 0.0);
        fmi2EnterInitializationMode(fmu);
        fmi2SetReal(fmu, inputs.as_ptr(), 3, [300.0, 190.0, 0.3].as_ptr());
        fmi2ExitInitializationMode(fmu);
        fmi2GetReal(fmu, [vr::SPEED_RATIO].as_ptr(), 1, &mut ratio);
    }
    assert!((ratio - 0.6374).abs() < 1e-3, "speed ratio {ratio}");
    let speeds: Vec<f64> = (0..64)
        .map(|i| 300.0 * ratio * (0.985 + 0.0002 * f64::from(i)))
        .collect();
    let mut k = 0usize;
    let mut t = 0.0;
    // SAFETY: as above.
    let mut step = || unsafe {
        k = (k + 1) % speeds.len();
        let x = [300.0, speeds[k], 0.3];
        fmi2SetReal(fmu, inputs.as_ptr(), 3, x.as_ptr());
        let s = fmi2DoStep(fmu, t, 1e-3, 1);
        t += 1e-3;
        fmi2GetReal(fmu, outputs.as_ptr(), 3, out.as_mut_ptr());
        black_box((s, out))
    };
    // The maps' warm-up: they build their cells within a budget (0.5 node
    // evaluations per evaluation, docs/decisions/0078), so the first steps
    // are direct; the mean step time per block of 100.
    let mut blocks = Vec::new();
    for _ in 0..warm_steps / 100 {
        let t0 = std::time::Instant::now();
        for _ in 0..100 {
            assert_eq!(step().0, FMI2_OK);
        }
        blocks.push(format!("{:.0}", t0.elapsed().as_secs_f64() * 1e4));
    }
    eprintln!(
        "{name}: µs per step in blocks of 100 warm-up steps: {}",
        blocks.join(" ")
    );
    c.bench_function(name, |b| b.iter(&mut step));
    // SAFETY: instance from fmi2Instantiate.
    unsafe { fmi2FreeInstance(fmu) };
}

fn bench(c: &mut Criterion) {
    bench_with(c, "variator_fmu_step_spin_map", true, 2000);
    bench_with(c, "variator_fmu_step_spin_direct", false, 100);
}

criterion_group!(benches, bench);
criterion_main!(benches);
