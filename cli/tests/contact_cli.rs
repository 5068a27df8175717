//! Integration tests of `traction contact` and `traction curve`: the binary on
//! CSV through stdin/stdout, compared with the library, and its errors.
// Functions outside #[test] functions unwrap too: any failure is a test failure.
#![allow(clippy::unwrap_used)]

mod common;
use common::{fails, ok, traction};

use traction_contact::{Body, EnvelopeRule, Fluid, OperatingState, Options, TractionContact};

const OUT: [&str; 19] = [
    "fx",
    "fy",
    "mz",
    "loss",
    "a",
    "b",
    "k",
    "p0",
    "m_used",
    "mu_used",
    "J1",
    "J2",
    "J3",
    "J4",
    "J5",
    "J6",
    "J7",
    "regime",
    "temperature_rise",
];

const HEADER: &str = "rx1,ry1,rx2,ry2,e1,nu1,e2,nu2,load,u,du,dv,omega,theta";
/// High-speed machine, k = 5 discs (Table 2-1), trace 79072704 class state.
const HS_K5: &str = "0.033,0.27,0.0714,inf,210e9,0.3,210e9,0.3";

fn hs_k5() -> (Body, Body) {
    (
        Body::steel(33e-3, 270e-3),
        Body::steel(71.4e-3, f64::INFINITY),
    )
}

#[test]
fn contact_rows_match_the_library() {
    let input = format!(
        "{HEADER},m,mu,fluid,label\n\
         {HS_K5},5000,80,0.4,0.65,35,73,35,0.075,,user\n\
         {HS_K5},2000,-20,0.01,-0.02,-3,50,,,santotrac-50,report\n"
    );
    // The Santotrac row is outside the data's k range (Hertz k 5.04 > 5): clamp.
    let rows = ok(&["contact", "--envelope", "clamp"], &input);
    let header: Vec<&str> = HEADER.split(',').collect();
    let mut expect: Vec<String> = header.iter().map(|s| s.to_string()).collect();
    expect.extend(["m", "mu", "fluid", "label"].map(String::from));
    expect.extend(OUT.map(String::from));
    assert_eq!(rows[0], expect);
    assert_eq!(rows.len(), 3);
    let (b1, b2) = hs_k5();
    let fluids = [
        Fluid::constant(35.0, 0.075).unwrap(),
        Fluid::santotrac_50(EnvelopeRule::Clamp).unwrap(),
    ];
    let states = [
        OperatingState::new(5000.0, 80.0, 0.4, 0.65, 35.0, 73.0).unwrap(),
        OperatingState::new(2000.0, -20.0, 0.01, -0.02, -3.0, 50.0).unwrap(),
    ];
    for (i, (fluid, state)) in fluids.into_iter().zip(states).enumerate() {
        let c = TractionContact::new(&b1, &b2, fluid, Options::default()).unwrap();
        let e = c.evaluate(&state).unwrap();
        let row = &rows[i + 1];
        assert_eq!(
            row[header.len() + 3],
            if i == 0 { "user" } else { "report" }
        );
        let col = |name: &str| {
            let j = rows[0].iter().position(|h| h == name).unwrap();
            row[j].clone()
        };
        // Shortest round-trip formatting: the same f64 bit for bit.
        for (name, v) in [
            ("fx", e.fx),
            ("fy", e.fy),
            ("mz", e.mz),
            ("loss", e.loss),
            ("p0", e.p0),
            ("m_used", e.m_used),
            ("mu_used", e.mu_used),
            ("J3", e.j3),
            ("J7", e.j7),
        ] {
            assert_eq!(col(name).parse::<f64>().unwrap(), v, "row {i} {name}");
        }
        assert_eq!(col("regime"), e.regime.name());
    }
}

/// `--thermal`: a row with both `fluid` and `m,mu` (the user's values at the
/// inlet, the fluid's temperature dependence), a user fluid with its thermal
/// columns, and the errors of a user fluid without them.
#[test]
fn thermal_rows_match_the_library() {
    let input = format!(
        "{HEADER},fluid,m,mu,film_thickness,fluid_conductivity,mu_temperature_coefficient\n\
         {HS_K5},4620,80,0,0.5,1300,73,santotrac-50,35,0.075,,,\n\
         {HS_K5},4620,80,0,0.5,0,73,,35,0.075,5e-7,0.11,0.003\n"
    );
    let rows = ok(&["contact", "--thermal", "--envelope", "clamp"], &input);
    let (b1, b2) = hs_k5();
    let th = traction_contact::Thermal::default();
    let fluids = [
        (
            Fluid::santotrac_50(EnvelopeRule::Clamp)
                .unwrap()
                .with_inlet_values(35.0, 0.075)
                .unwrap(),
            th,
        ),
        (
            Fluid::constant(35.0, 0.075).unwrap(),
            traction_contact::Thermal {
                film: traction_contact::Film::Thickness(5e-7),
                fluid_conductivity: Some(0.11),
                mu_coefficient: Some(0.003),
                ..th
            },
        ),
    ];
    let w = [1300.0, 0.0];
    for (i, (fluid, th)) in fluids.into_iter().enumerate() {
        let opts = Options {
            thermal: Some(th),
            ..Options::default()
        };
        let c = TractionContact::new(&b1, &b2, fluid, opts).unwrap();
        let s = OperatingState::builder()
            .load(4620.0)
            .rolling_speed(80.0)
            .side_slip(0.5)
            .spin(w[i])
            .inlet_temperature_celsius(73.0)
            .build()
            .unwrap();
        let e = c.evaluate(&s).unwrap();
        let col = |name: &str| -> f64 {
            let j = rows[0].iter().position(|h| h == name).unwrap();
            rows[i + 1][j].parse().unwrap()
        };
        assert!(e.temperature_rise > 1.0, "row {i}");
        assert_eq!(col("temperature_rise"), e.temperature_rise, "row {i}");
        assert_eq!(col("fy"), e.fy, "row {i}");
        assert_eq!(col("mu_used"), e.mu_used, "row {i}");
    }
    // A user fluid needs its temperature coefficient, conductivity and film:
    // the error names the column that supplies each.
    for (columns, values, missing) in [
        (
            "film_thickness,fluid_conductivity",
            "5e-7,0.11",
            "mu_temperature_coefficient",
        ),
        (
            "film_thickness,mu_temperature_coefficient",
            "5e-7,0.003",
            "fluid_conductivity",
        ),
        (
            "fluid_conductivity,mu_temperature_coefficient",
            "0.11,0.003",
            "film_thickness",
        ),
    ] {
        let e = fails(
            &["contact", "--thermal"],
            &format!("{HEADER},m,mu,{columns}\n{HS_K5},4620,80,0,0.5,0,73,35,0.075,{values}\n"),
        );
        assert!(
            e.contains("row 1") && e.contains(&format!("needs `{missing}`")),
            "{e}"
        );
    }
    // Unphysical property: named with its range.
    let e = fails(
        &["contact", "--thermal"],
        &format!("{HEADER},fluid,disc_conductivity\n{HS_K5},4620,80,0,0.5,0,73,santotrac-50,-3\n"),
    );
    assert!(e.contains("disc thermal conductivity"), "{e}");
}

#[test]
fn bad_rows_name_the_row_and_quantity() {
    let input = format!(
        "{HEADER},m,mu\n{HS_K5},5000,80,0.4,0,0,73,35,0.075\n{HS_K5},-1,80,0.4,0,0,73,35,0.075\n"
    );
    let e = fails(&["contact"], &input);
    assert!(e.contains("row 2") && e.contains("load N"), "{e}");
    // No fluid in a row.
    let input = format!("{HEADER},m,mu\n{HS_K5},5000,80,0.4,0,0,73,35,\n");
    let e = fails(&["contact"], &input);
    assert!(e.contains("row 1") && e.contains("`mu`"), "{e}");
    // Unknown fluid name.
    let input = format!("{HEADER},fluid\n{HS_K5},5000,80,0.4,0,0,73,oil\n");
    let e = fails(&["contact"], &input);
    assert!(e.contains("unknown fluid `oil`"), "{e}");
    // Outside the report fluid's envelope under the default strict rule.
    let input = format!("{HEADER},fluid\n{HS_K5},5000,2,0.01,0,0,73,santotrac-50\n");
    let e = fails(&["contact"], &input);
    assert!(e.contains("row 1") && e.contains("envelope"), "{e}");
    // No fluid columns at all.
    let e = fails(
        &["contact"],
        &format!("{HEADER}\n{HS_K5},5000,80,0.4,0,0,73\n"),
    );
    assert!(e.contains("fluid"), "{e}");
}

#[test]
fn curve_sweeps_the_slip_and_matches_the_library() {
    let rows = ok(
        &[
            "curve",
            "--rx1",
            "0.025",
            "--ry1",
            "0.0125",
            "--rx2",
            "0.025",
            "--p0",
            "1.96e9",
            "--u",
            "20",
            "--m",
            "57.6",
            "--mu",
            "0.0956",
            "--direction",
            "side",
            "--from",
            "0",
            "--to",
            "0.02",
            "--points",
            "5",
        ],
        "",
    );
    assert_eq!(rows.len(), 6);
    assert_eq!(rows[0][0], "slip_ratio");
    let c = TractionContact::new(
        &Body::steel(0.025, 0.0125),
        &Body::steel(0.025, f64::INFINITY),
        Fluid::constant(57.6, 0.0956).unwrap(),
        Options::default(),
    )
    .unwrap();
    let n = c.geometry().at_p0(1.96e9).unwrap().load;
    let ty = rows[0].iter().position(|h| h == "traction_y").unwrap();
    let mut prev = -1.0;
    for (i, r) in rows[1..].iter().enumerate() {
        let ratio = 0.005 * i as f64;
        let e = c
            .evaluate(&OperatingState::new(n, 20.0, 0.0, ratio * 20.0, 0.0, 70.0).unwrap())
            .unwrap();
        let v: f64 = r[ty].parse().unwrap();
        assert_eq!(v, e.traction_y);
        // Zero spin, side slip only: monotone, bounded by μ.
        assert!(v > prev && v < 0.0956);
        prev = v;
    }
    let e = fails(
        &[
            "curve", "--rx1", "0.025", "--ry1", "0.0125", "--rx2", "0.025", "--u", "20", "--m",
            "57.6", "--mu", "0.0956",
        ],
        "",
    );
    assert!(e.contains("--load") && e.contains("--p0"), "{e}");
}

#[test]
fn curve_plot_writes_png_and_svg() {
    // The picture of `traction curve --plot DIR` (PNG signature, SVG text), and
    // the curve it draws starts at the slope m: Fx/N ≈ m·ΔU/U at the first
    // non-zero point (ΔU/U = 2.5e-5, J1 ≈ 0.045: the eq. 22 curve is linear to
    // 1e-3 relative there, tolerance 1 %).
    let dir = std::env::temp_dir().join(format!("traction-curve-plot-{}", std::process::id()));
    let out = traction(
        &[
            "curve", "--rx1", "0.025", "--ry1", "0.0125", "--rx2", "0.025", "--p0", "1.9e9", "--u",
            "20", "--m", "57.6", "--mu", "0.0956", "--to", "0.001", "--points", "41", "--plot",
        ]
        .into_iter()
        .chain([dir.to_str().unwrap()])
        .collect::<Vec<_>>(),
        "",
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let png = std::fs::read(dir.join("curve.png")).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let svg = std::fs::read_to_string(dir.join("curve.svg")).unwrap();
    assert!(svg.contains("<svg"));
    let csv = String::from_utf8(out.stdout).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| header.iter().position(|h| *h == n).unwrap();
    let second: Vec<&str> = lines.nth(1).unwrap().split(',').collect();
    let ratio: f64 = second[col("slip_ratio")].parse().unwrap();
    let tx: f64 = second[col("traction_x")].parse().unwrap();
    assert!(
        (tx / (57.6 * ratio) - 1.0).abs() < 0.01,
        "{tx} vs {}",
        57.6 * ratio
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn property_distribution_flags() {
    // --modulus/--limit reach the library (fx equal to TractionContact with
    // the same Properties to print precision) and change the answer.
    let input = format!("{HEADER},m,mu\n{HS_K5},1500,20,0.03,-0.02,30,70,52.4,0.089\n");
    let base = ok(&["contact", "--tol", "1e-3"], &input);
    let alt = ok(
        &[
            "contact",
            "--tol",
            "1e-3",
            "--modulus",
            "pressure",
            "--limit",
            "constant",
        ],
        &input,
    );
    let col = base[0].iter().position(|c| c == "fx").unwrap();
    let (f0, f1): (f64, f64) = (base[1][col].parse().unwrap(), alt[1][col].parse().unwrap());
    let (b1, b2) = hs_k5();
    let props = traction_contact::Properties {
        modulus: traction_contact::Modulus::PressureProportional,
        limit: traction_contact::Limit::Constant,
    };
    let c = TractionContact::new(
        &b1,
        &b2,
        Fluid::constant(52.4, 0.089).unwrap(),
        Options {
            properties: props,
            accuracy: traction_contact::Accuracy::new(1e-3).unwrap(),
            ..Options::default()
        },
    )
    .unwrap();
    let s = OperatingState::new(1500.0, 20.0, 0.03, -0.02, 30.0, 70.0).unwrap();
    let fx = c.evaluate(&s).unwrap().fx;
    assert!((f1 - fx).abs() <= 1e-9 * fx.abs().max(1.0), "{f1} {fx}");
    assert!((f1 - f0).abs() > 1e-2 * f0.abs(), "{f0} {f1}");
    let err = fails(&["contact", "--modulus", "linear"], &input);
    assert!(err.contains("--modulus"), "{err}");
}
