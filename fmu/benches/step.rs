//! doStep + getReal of all Real outputs, with spin, through the C ABI (what a
//! host pays per communication step). Goal: ≥ 200 000 steps/s on one core.
#![allow(unsafe_code)]
#![allow(missing_docs)]

use std::ffi::CString;
use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use traction_fmu::ffi::*;
use traction_fmu::model_description::guid;
use traction_fmu::variables::{Causality, VARIABLES, vr};

fn bench(c: &mut Criterion) {
    let cb = Fmi2CallbackFunctions {
        logger: None,
        allocate_memory: None,
        free_memory: None,
        step_finished: None,
        component_environment: std::ptr::null_mut(),
    };
    let name = CString::new("bench").unwrap_or_default();
    let g = CString::new(guid()).unwrap_or_default();
    let outs: Vec<u32> = VARIABLES
        .iter()
        .filter(|v| v.causality == Causality::Output && v.vr != vr::REGIME)
        .map(|v| v.vr)
        .collect();
    let mut values = vec![0.0; outs.len()];
    // (label, ω1, ω2, side slip velocity, spin, map): rolling at U ≈ 20 m/s,
    // and at rest (u1 = −u2 = 2 mm/s: U = 0 with 4 mm/s of slip) with spin,
    // where both rolling frames are blended.
    let rolling = (600.0, 275.0, 0.05);
    let at_rest = (0.002 / 0.033, -0.002 / 0.0714, 0.0);
    for (label, (w1, w2, dv), spin, map) in [
        ("with spin (20 rad/s), rheology_map on", rolling, 20.0, true),
        (
            "with spin (20 rad/s), rheology_map off (default)",
            rolling,
            20.0,
            false,
        ),
        ("without spin", rolling, 0.0, true),
        (
            "at rest with spin (32 rad/s) and 4 mm/s of slip, rheology_map off",
            at_rest,
            32.0,
            false,
        ),
    ] {
        // SAFETY: valid pointers for the lifetime of the instance.
        unsafe {
            let inst = fmi2Instantiate(
                name.as_ptr(),
                FMI2_COSIMULATION,
                g.as_ptr(),
                std::ptr::null(),
                &cb,
                0,
                0,
            );
            assert!(!inst.is_null());
            let ins = [
                vr::LOAD,
                vr::OMEGA1,
                vr::OMEGA2,
                vr::SIDE_SLIP_VELOCITY,
                vr::SPIN,
            ];
            let x = [800.0, w1, w2, dv, spin];
            assert_eq!(
                fmi2SetReal(inst, ins.as_ptr(), ins.len(), x.as_ptr()),
                FMI2_OK
            );
            let m = Fmi2Boolean::from(map);
            assert_eq!(fmi2SetBoolean(inst, &vr::RHEOLOGY_MAP, 1, &m), FMI2_OK);
            assert_eq!(fmi2EnterInitializationMode(inst), FMI2_OK);
            // fmi2ExitInitializationMode evaluates the contact: with the
            // map it builds the cells of this operating region; report the
            // cost of that first evaluation and step once.
            let t0 = std::time::Instant::now();
            assert!(fmi2ExitInitializationMode(inst) <= FMI2_WARNING);
            fmi2DoStep(inst, 0.0, 1e-4, 1);
            eprintln!(
                "{label}: exitInitializationMode + first doStep {:.3} ms",
                t0.elapsed().as_secs_f64() * 1e3
            );
            // The next doStep with a new input: one evaluation, right after
            // the first (what a host pays at its first step under a deadline
            // when the inputs move after the initialisation).
            let t0 = std::time::Instant::now();
            let w1_new = w1 * (1.0 + 1.7e-5);
            fmi2SetReal(inst, &vr::OMEGA1, 1, &w1_new);
            fmi2DoStep(inst, 1e-4, 1e-4, 1);
            eprintln!(
                "{label}: the next doStep, with a new input {:.3} ms",
                t0.elapsed().as_secs_f64() * 1e3
            );
            let mut t = 2e-4;
            let mut k = 0u32;
            // The map's warm-up: it builds its cells within a budget (0.5
            // node evaluations per evaluation, docs/decisions/0078), so the
            // first steps are direct; the mean step time per block of 100.
            if map && spin != 0.0 {
                let mut blocks = Vec::new();
                for _ in 0..20 {
                    let t0 = std::time::Instant::now();
                    for _ in 0..100 {
                        k = k.wrapping_add(1);
                        let w1 = w1 * (1.0 + f64::from(k % 100) * 1.7e-5);
                        fmi2SetReal(inst, &vr::OMEGA1, 1, &w1);
                        fmi2DoStep(inst, t, 1e-4, 1);
                        t += 1e-4;
                    }
                    blocks.push(format!("{:.1}", t0.elapsed().as_secs_f64() * 1e4));
                }
                eprintln!(
                    "{label}: µs per step in blocks of 100 steps: {}",
                    blocks.join(" ")
                );
            }
            c.bench_function(
                &format!("setReal(omega1) + doStep + getReal(all Real outputs), {label}"),
                |b| {
                    b.iter(|| {
                        // A new input each step, as in a coupled simulation.
                        k = k.wrapping_add(1);
                        let w1 = w1 * (1.0 + f64::from(k % 100) * 1.7e-5);
                        fmi2SetReal(inst, &vr::OMEGA1, 1, &w1);
                        fmi2DoStep(inst, t, 1e-4, 1);
                        t += 1e-4;
                        fmi2GetReal(inst, outs.as_ptr(), outs.len(), values.as_mut_ptr());
                        black_box(&values);
                    });
                },
            );
            fmi2FreeInstance(inst);
        }
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
