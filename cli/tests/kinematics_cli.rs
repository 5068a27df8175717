//! CLI tests of `traction kinematics` (twin-disc and general forms).

mod common;
use common::run;

use traction_reproduce::tables::spin::C2_TOL;
use traction_testkit::Table;

/// The one data row of a CSV output.
fn only_row(out: &str) -> (Table, usize) {
    let t = Table::parse(out);
    assert_eq!(t.rows.len(), 1, "{out}");
    (t, 0)
}

#[test]
fn twin_disc_reproduces_table_2_5_and_2_6() {
    // Low-speed machine, k = 1, 6° (Tables 2-2, 2-4, 2-5), trace 80062306 of
    // Table 2-6 with its m, μ of Table 4-1: all read from fluids/data.
    let t = traction_fluids::spin_tests()
        .unwrap()
        .into_iter()
        .find(|t| t.machine.name == "LS k=1")
        .unwrap();
    let tables = traction_fluids::main_text_tables().unwrap();
    let printed = |table: &str| {
        tables
            .iter()
            .find(|r| r.table == table && r.trace == "80062306")
            .unwrap()
            .values
    };
    let [_, Some(p0_gpa), _, _, _, Some(z_printed), ..] = printed("2-6") else {
        panic!("Table 2-6 row of 80062306");
    };
    let [.., Some(m), Some(mu), _] = printed("4-1") else {
        panic!("Table 4-1 row of 80062306");
    };
    let m_row = &t.machine;
    let input = format!(
        "label,alpha,ry,e,c,k,p0,m,mu\nLS,{},{},{},{},{},{},{m},{mu}\n",
        t.spin_deg.to_radians(),
        m_row.ry1_mm * 1e-3,
        t.e_mm * 1e-3,
        m_row.c_e12_m_per_pa.value * 1e-12,
        m_row.k,
        p0_gpa * 1e9,
    );
    let (ok, out, err) = run(&["kinematics", "--input", "-"], &input);
    assert!(ok, "{err}");
    assert!(
        out.starts_with("label,alpha,ry,e,c,k,p0,m,mu,rolling_radius,omega_per_u"),
        "{out}"
    );
    let (o, r) = only_row(&out);
    let c2 = o.f64(r, "c_double_prime");
    // Computed 0.71275e-3 1/GPa against the printed .713e-3 (0.04 %), within
    // the Table 2-5 tolerance.
    let c2_printed = t.spin_factor.c_table_2_5;
    assert!((c2 * 1e9 / c2_printed - 1.0).abs() < C2_TOL, "{c2}");
    let z = o.f64(r, "z");
    // Table 2-6 prints Z to 3 digits (.00135): half a unit of the last digit.
    assert!((z - z_printed).abs() <= 0.000005, "{z}");
    // No beta column: side_slip_ratio and j2 are empty.
    assert_eq!(o.get(r, "side_slip_ratio"), "");
    assert_eq!(o.get(r, "j2"), "");
    let j3 = o.f64(r, "j3");
    // J3 = (3π/8)(m/μ)Z√k with the same Z: exact arithmetic, 1e-12.
    let expect = 3.0 * std::f64::consts::PI / 8.0 * (m / mu) * z;
    assert!((j3 / expect - 1.0).abs() < 1e-12);
}

#[test]
fn twin_disc_errors_name_the_quantity() {
    let (ok, _, err) = run(&["kinematics"], "alpha,ry,e\n0.5,0.01,-0.02\n");
    assert!(!ok);
    assert!(
        err.contains("row 1") && err.contains("rolling radius"),
        "{err}"
    );
    let (ok, _, err) = run(&["kinematics"], "x,y\n1,2\n");
    assert!(!ok);
    assert!(err.contains("--form"), "{err}");
}

#[test]
fn general_form_two_cylinders() {
    // Two parallel cylinders (axes along y) at 25 mm and 50 mm, body 1 above,
    // body 1 surface speed 10 m/s, body 2 9.8 m/s: U = 9.9, ΔU = 0.2, no spin.
    let header = "w1x,w1y,w1z,p1x,p1y,p1z,w2x,w2y,w2z,p2x,p2y,p2z,cx,cy,cz,nx,ny,nz,tx,ty,tz,a,b";
    let row = "0,-400,0,0,0,0.025,0,196,0,0,0,-0.05,0,0,0,0,0,1,1,0,0,1e-4,2e-4";
    let (ok, out, err) = run(
        &["kinematics", "--input", "-"],
        &format!("{header}\n{row}\n"),
    );
    assert!(ok, "{err}");
    let (o, r) = only_row(&out);
    let f = |n: &str| o.f64(r, n);
    // Exact arithmetic on representable inputs: 1e-12.
    assert!((f("u") - 9.9).abs() < 1e-12);
    assert!((f("du") - 0.2).abs() < 1e-12);
    assert!((f("du_u") - 0.2 / 9.9).abs() < 1e-12);
    assert_eq!(f("omega"), 0.0);
    assert_eq!(o.get(r, "epsilon"), "");
    // U = 0 is an error naming the rolling speed.
    let row0 = "0,-400,0,0,0,0.025,0,-200,0,0,0,-0.05,0,0,0,0,0,1,1,0,0,1e-4,2e-4";
    let (ok, _, err) = run(&["kinematics"], &format!("{header}\n{row0}\n"));
    assert!(!ok);
    assert!(err.contains("rolling speed U is zero"), "{err}");
}
