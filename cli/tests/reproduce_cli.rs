//! CLI tests of `traction reproduce` and `traction map`.
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

use std::path::PathBuf;
use std::process::Command;

fn run(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_traction"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("traction-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn is_png(p: &PathBuf) -> bool {
    std::fs::read(p)
        .map(|b| b.starts_with(b"\x89PNG"))
        .unwrap_or(false)
}

#[test]
fn reproduce_writes_every_table_figure_and_the_summary() {
    let d = tmp("reproduce");
    let figs = d.join("figs");
    let (ok, out, err) = run(&[
        "reproduce",
        "--out",
        d.to_str().unwrap(),
        "--jobs",
        "2",
        "--figures",
        figs.to_str().unwrap(),
    ]);
    assert!(ok, "{err}\n{out}");
    // Every table within tolerance and the summary printed.
    assert!(out.contains("| Table 2-2 (A, B, C) |"), "{out}");
    assert!(!out.contains("**NO**"), "{out}");
    assert!(out.contains("printed values not available"), "{out}");
    for id in [
        "table-2-1",
        "table-2-2",
        "table-2-3",
        "table-2-5",
        "table-4-3",
        "appendix-i",
        "appendix-iii-a",
        "appendix-iii-e",
        "appendix-iii-f",
        "appendix-vi",
        "appendix-vii-a",
        "appendix-vii-b",
    ] {
        assert!(d.join(format!("{id}.csv")).exists(), "{id}");
    }
    for fig in [
        "fig-3-3", "fig-4-1", "fig-4-2", "fig-4-4", "fig-4-6", "fig-4-9", "fig-4-16",
    ] {
        assert!(is_png(&d.join(format!("{fig}.png"))), "{fig}");
        let svg = std::fs::read_to_string(d.join(format!("{fig}.svg"))).unwrap();
        assert!(svg.contains("<svg"), "{fig}");
    }
    let summary = std::fs::read_to_string(d.join("summary.md")).unwrap();
    assert!(summary.contains("Appendix VI (spin traces)"));
    assert!(summary.contains("VII-C"));
    assert!(is_png(&figs.join("fig-3-3.png")));
    assert!(figs.join("summary.md").exists());
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn reproduce_rejects_bad_arguments_clearly() {
    let d = tmp("reproduce-bad");
    let (ok, _, err) = run(&["reproduce", "--out", d.to_str().unwrap(), "--jobs", "0"]);
    assert!(!ok);
    assert!(err.contains("--jobs must be at least 1"), "{err}");
    let (ok, _, err) = run(&[
        "reproduce",
        "--out",
        d.to_str().unwrap(),
        "--only",
        "table-9-9",
    ]);
    assert!(!ok);
    assert!(
        err.contains("matches no table") && err.contains("table-2-2"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn map_writes_the_grid_and_a_heat_map() {
    let d = tmp("map");
    std::fs::create_dir_all(&d).unwrap();
    let csv = d.join("map.csv");
    let (ok, _, err) = run(&[
        "map",
        "--k",
        "1",
        "--j1",
        "0:4:5",
        "--j3",
        "0:6:4",
        "--out",
        csv.to_str().unwrap(),
        "--jobs",
        "2",
    ]);
    assert!(ok, "{err}");
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next().unwrap(), "k,J1,J2,J3,J4,J5,J6,J7");
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 20);
    // J1 varies fastest; the origin has no traction; losses are never negative.
    assert_eq!((rows[1][1], rows[1][3]), (1.0, 0.0));
    assert_eq!((rows[5][1], rows[5][3]), (0.0, 2.0));
    assert!(rows[0][4].abs() < 1e-12 && rows[0][7].abs() < 1e-12);
    assert!(rows.iter().all(|r| r[7] >= -1e-9));
    // Zero spin, slip only: eq. 22, J4 = ψ(2/3·J1) at J1 = 3 (ψ(2) = (2/π)(atan 2 + 0.4)).
    let psi2 = (2.0 / std::f64::consts::PI) * (2.0_f64.atan() + 0.4);
    assert!((rows[3][4] - psi2).abs() < 1e-3, "{}", rows[3][4]);
    assert!(is_png(&d.join("map.png")));
    std::fs::remove_dir_all(&d).unwrap();
}

#[test]
fn map_rejects_bad_ranges_and_models_clearly() {
    for (arg, msg) in [
        ("0:1", "wrong number"),
        ("a:1:3", "not a number"),
        ("0:1:0", "at least 1"),
        ("0:1:x", "whole number"),
    ] {
        let (ok, _, err) = run(&["map", "--j1", arg, "--out", "-"]);
        assert!(!ok, "{arg}");
        assert!(err.contains("--j1") && err.contains(msg), "{arg}: {err}");
    }
    let (ok, _, err) = run(&["map", "--k", "0", "--out", "-"]);
    assert!(!ok && err.contains("aspect ratio"), "{err}");
    let (ok, _, err) = run(&["map", "--model", "viscoelastic", "--out", "-"]);
    assert!(!ok && err.contains("--deborah"), "{err}");
}
