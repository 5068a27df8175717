//! CLI tests of `traction compliance` (slope conversion, Appendix IV B7).

mod common;
use common::run;

#[test]
fn single_conversion_prints_the_slope_alone() {
    let (ok, out, err) = run(
        &[
            "compliance",
            "--k",
            "0.5",
            "--p0",
            "2.53e9",
            "--slope",
            "64.06",
            "--from",
            "side",
            "--to",
            "longitudinal",
        ],
        "",
    );
    assert!(ok, "{err}");
    assert_eq!(out.lines().count(), 1, "{out}");
    let m: f64 = out.trim().parse().unwrap();
    // Table 4-3 prints 66.74; the model gives 66.76 (+0.03 %, see
    // tests/tests/compliance_tables.rs). 1 % is the aim stated there.
    assert!((m / 66.74 - 1.0).abs() < 0.01, "{m}");
}

#[test]
fn material_options_change_the_result() {
    let base = [
        "compliance",
        "--k",
        "5",
        "--p0",
        "1.22e9",
        "--slope",
        "52.4",
        "--from",
        "side",
        "--to",
        "longitudinal",
    ];
    let (_, a, _) = run(&base, "");
    let mut soft = base.to_vec();
    soft.extend(["--e", "105e9"]);
    let (ok, b, err) = run(&soft, "");
    assert!(ok, "{err}");
    let (a, b): (f64, f64) = (a.trim().parse().unwrap(), b.trim().parse().unwrap());
    // Softer discs: larger disc creep, larger correction of the slope.
    assert!(b > a, "{a} {b}");
}

#[test]
fn batch_keeps_columns_and_names_bad_cells() {
    let (ok, out, err) = run(
        &["compliance", "--input", "-"],
        "label,k,p0,slope,from,to\nA,1,1.96e9,57.6,side,longitudinal\nB,1,1.96e9,65.19,longitudinal,side\n",
    );
    assert!(ok, "{err}");
    let mut lines = out.lines();
    assert_eq!(
        lines.next().unwrap(),
        "label,k,p0,slope,from,to,q_from,q_to,g_s,dry_slope_from,slope_converted"
    );
    let cells: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(cells[0], "A");
    let m: f64 = cells[10].parse().unwrap();
    // Printed 65.19; the model gives 64.31 (−1.35 %, figure-reading residual
    // explained in tests/tests/compliance_tables.rs): within 1.5 %.
    assert!((m / 65.19 - 1.0).abs() < 0.015, "{m}");
    // G_s = 210e9 / 2.6 exactly.
    let gs: f64 = cells[8].parse().unwrap();
    assert!((gs - 210e9 / 2.6).abs() < 1.0);
    // The reverse conversion goes the other way.
    let back: f64 = lines
        .next()
        .unwrap()
        .split(',')
        .nth(10)
        .unwrap()
        .parse()
        .unwrap();
    assert!(back < 65.19);

    let (ok, _, err) = run(
        &["compliance"],
        "k,p0,slope,from,to\n1,-2e9,50,side,longitudinal\n",
    );
    assert!(!ok);
    assert!(err.contains("row 1") && err.contains("P0"), "{err}");
    let (ok, _, err) = run(
        &["compliance"],
        "k,p0,slope,from,to\n1,2e9,50,up,longitudinal\n",
    );
    assert!(!ok);
    assert!(err.contains("`from`"), "{err}");
    let (ok, _, err) = run(&["compliance", "--k", "1", "--slope", "50"], "");
    assert!(!ok);
    assert!(err.contains("--p0"), "{err}");
    let (ok, _, err) = run(
        &[
            "compliance",
            "--k",
            "1",
            "--p0",
            "2e9",
            "--slope",
            "50",
            "--from",
            "side",
            "--to",
            "side",
            "--nu",
            "0.7",
        ],
        "",
    );
    assert!(!ok);
    assert!(err.contains("Poisson"), "{err}");
}
