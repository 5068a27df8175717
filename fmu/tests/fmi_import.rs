//! The Rust `fmi` crate's import side (an independent FMI 2 importer) loads
//! the packaged FMU: instantiate, step, get/set/serialize the FMU state, and
//! a bad value reference → error.
#![allow(unsafe_code)]

use std::path::PathBuf;

use fmi::fmi2::import::Fmi2Import;
use fmi::fmi2::instance::{CoSimulation, Common};
use fmi::traits::{FmiImport, FmiInstance};
use traction_fmu::physics::{Contact, Inputs};
use traction_fmu::variables::vr;

/// Packs the cdylib that cargo built beside this test into a temporary FMU.
fn packaged_fmu(test: &str) -> (tempfile_dir::Dir, PathBuf) {
    let exe = std::env::current_exe().expect("test executable path");
    let deps = exe.parent().expect("deps directory");
    let lib = [
        deps.join("libtraction_fmu.so"),
        deps.join("../libtraction_fmu.so"),
    ]
    .into_iter()
    .find(|p| p.is_file())
    .expect("libtraction_fmu.so beside the test binary (crate-type cdylib)");
    let dir = tempfile_dir::Dir::new(test);
    let fmu = dir.0.join("TractionContact.fmu");
    traction_fmu::package::write_fmu(&lib, &fmu).expect("packaging");
    (dir, fmu)
}

/// A temporary directory removed on drop (std only).
mod tempfile_dir {
    pub struct Dir(pub std::path::PathBuf);
    impl Dir {
        pub fn new(test: &str) -> Self {
            let p = std::env::temp_dir()
                .join(format!("traction-fmu-import-{}-{test}", std::process::id()));
            std::fs::create_dir_all(&p).expect("temp dir");
            Dir(p)
        }
    }
    impl Drop for Dir {
        fn drop(&mut self) {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }
}

#[test]
fn fmi_crate_instantiates_steps_and_rejects_a_bad_value_reference() {
    let (_dir, fmu) = packaged_fmu("step");
    let import: Fmi2Import = fmi::import::from_path(&fmu).expect("fmi import");
    assert_eq!(
        import.model_description().guid,
        traction_fmu::model_description::guid()
    );
    let mut inst = import
        .instantiate_cs("rust-import", false, true)
        .expect("instantiate");
    assert_eq!(Common::get_version(&inst), "2.0");
    inst.set_real(&[vr::LOAD, vr::OMEGA1, vr::OMEGA2], &[700.0, 600.0, 270.0])
        .expect("set inputs");
    FmiInstance::enter_initialization_mode(&mut inst, None, 0.0, Some(1.0)).expect("init");
    FmiInstance::exit_initialization_mode(&mut inst).expect("exit init");
    let h = 1e-3;
    for k in 0..100 {
        inst.do_step(f64::from(k) * h, h, true).expect("step");
    }
    assert!((inst.last_successful_time().expect("time") - 0.1).abs() < 1e-12);
    let mut out = [0.0; 4];
    inst.get_real(&[vr::FX, vr::A, vr::U, vr::DU], &mut out)
        .expect("get outputs");
    // Same numbers as the physics seam called directly.
    let params = default_parameters();
    let direct = Contact::new(&params)
        .expect("contact")
        .evaluate(&Inputs {
            load: 700.0,
            u: out[2],
            du: out[3],
            dv: 0.0,
            omega: 0.0,
            inlet_temperature_celsius: 40.0,
        })
        .expect("evaluate");
    assert_eq!((out[0], out[1]), (direct.fx, direct.a));
    assert!(out[0] > 0.0);
    // A bad value reference is an error, not a crash.
    let mut one = [0.0];
    assert!(inst.get_real(&[9999], &mut one).is_err());
}

fn default_parameters() -> traction_fmu::physics::Parameters {
    use traction_fmu::variables::{Kind, VARIABLES};
    let s = |n: &str| {
        VARIABLES
            .iter()
            .find(|v| v.name == n)
            .and_then(|v| {
                if let Kind::Real { start, .. } = v.kind {
                    start
                } else {
                    None
                }
            })
            .expect("start value")
    };
    traction_fmu::physics::Parameters {
        rx1: s("rx1"),
        ry1: s("ry1"),
        rx2: s("rx2"),
        ry2: s("ry2"),
        e1: s("e1"),
        nu1: s("nu1"),
        e2: s("e2"),
        nu2: s("nu2"),
        fluid: traction_fmu::physics::Fluid::User,
        envelope: traction_fmu::physics::Envelope::Clamp,
        m_user: s("m_user"),
        mu_user: s("mu_user"),
        rheology: traction_fmu::physics::Rheology::ElasticPlastic,
        deborah: s("deborah"),
        z0: s("z0"),
        spin_peak: false,
        mu_spin_user: s("mu_spin_user"),
        compliance: false,
        u_reg: s("rolling_speed_regularisation"),
        tolerance: s("rheology_tolerance"),
        map: VARIABLES
            .iter()
            .find(|v| v.name == "rheology_map")
            .is_some_and(|v| matches!(v.kind, Kind::Boolean { start: Some(true) })),
        thermal: VARIABLES
            .iter()
            .find(|v| v.name == "thermal")
            .is_some_and(|v| matches!(v.kind, Kind::Boolean { start: Some(true) })),
        film_thickness: s("film_thickness"),
        fluid_conductivity: s("fluid_conductivity"),
        mu_temperature_coefficient: s("mu_temperature_coefficient"),
        m_temperature_coefficient: s("m_temperature_coefficient"),
        mu_rise_scale: s("mu_rise_scale"),
    }
}

#[test]
fn fmi_crate_bindings_round_trip_the_serialized_state() {
    // The fmi crate's safe API has no FMU-state calls; its raw bindings
    // (fmi-sys, loaded by the importer) do.
    let (_dir, fmu) = packaged_fmu("state");
    let import: Fmi2Import = fmi::import::from_path(&fmu).expect("fmi import");
    let b = import.binding("TractionContact").expect("binding");
    let callbacks = fmi::fmi2::CallbackFunctions {
        logger: None,
        allocate_memory: None,
        free_memory: None,
        step_finished: None,
        component_environment: std::ptr::null_mut(),
    };
    let name = c"state";
    let guid = std::ffi::CString::new(import.model_description().guid.clone()).expect("guid");
    let outs = [
        vr::FX,
        vr::TORQUE1,
        vr::TORQUE2,
        vr::POWER_LOSS,
        vr::J1,
        vr::J1 + 3,
    ];
    // SAFETY: FMI 2 calls with valid pointers, in the order the standard allows.
    unsafe {
        let c = b.fmi2Instantiate(
            name.as_ptr(),
            1,
            guid.as_ptr(),
            c"".as_ptr(),
            std::ptr::from_ref(&callbacks).cast(),
            0,
            0,
        );
        assert!(!c.is_null());
        assert_eq!(b.fmi2EnterInitializationMode(c), 0);
        assert_eq!(b.fmi2ExitInitializationMode(c), 0);
        let step = |w1: f64, t: f64| {
            let vrs = [vr::OMEGA1, vr::OMEGA2];
            let v = [w1, 270.0];
            assert_eq!(b.fmi2SetReal(c, vrs.as_ptr(), 2, v.as_ptr()), 0);
            assert_eq!(b.fmi2DoStep(c, t, 0.01, 1), 0);
            let mut o = [0.0; 6];
            assert_eq!(
                b.fmi2GetReal(c, outs.as_ptr(), outs.len(), o.as_mut_ptr()),
                0
            );
            o
        };
        step(601.0, 0.0);
        let mut st: *mut std::ffi::c_void = std::ptr::null_mut();
        assert_eq!(b.fmi2GetFMUstate(c, &mut st), 0);
        let mut size = 0usize;
        assert_eq!(b.fmi2SerializedFMUstateSize(c, st, &mut size), 0);
        let mut bytes = vec![0 as std::ffi::c_char; size];
        assert_eq!(b.fmi2SerializeFMUstate(c, st, bytes.as_mut_ptr(), size), 0);
        assert_eq!(b.fmi2FreeFMUstate(c, &mut st), 0);
        let expected = step(602.5, 0.01);
        step(580.0, 0.02);
        let mut back: *mut std::ffi::c_void = std::ptr::null_mut();
        assert_eq!(
            b.fmi2DeSerializeFMUstate(c, bytes.as_ptr(), size, &mut back),
            0
        );
        assert_eq!(b.fmi2SetFMUstate(c, back), 0);
        let again = step(602.5, 0.01);
        assert_eq!(
            expected.map(f64::to_bits),
            again.map(f64::to_bits),
            "bit-exact after restore"
        );
        bytes[9] ^= 0x40;
        let mut bad: *mut std::ffi::c_void = std::ptr::null_mut();
        assert_eq!(
            b.fmi2DeSerializeFMUstate(c, bytes.as_ptr(), size, &mut bad),
            3
        );
        assert_eq!(b.fmi2FreeFMUstate(c, &mut back), 0);
        b.fmi2FreeInstance(c);
    }
}
