//! CLI tests of `traction field` (the J+T stress field on a grid).
#![allow(clippy::unwrap_used)] // a failed unwrap is a failed test

mod common;
use common::{fails, ok};

#[test]
fn field_grid_matches_the_slip_only_closed_form() {
    // k = 1, J1 = 1.5 only: Zx = min(A(X + c), (3/2)√(c² − X²)), A = J1,
    // Zy = 0 (exact in the integrator; printed with round-trip precision):
    // 1e-12 at every inside point, and the header and grid size.
    let rows = ok(
        &[
            "field", "--k", "1", "--j1", "1.5", "--nx", "21", "--ny", "11",
        ],
        "",
    );
    assert_eq!(rows[0], ["X", "Y", "Zx", "Zy", "state"]);
    assert_eq!(rows.len(), 1 + 21 * 11);
    let mut seen = std::collections::BTreeSet::new();
    for r in &rows[1..] {
        let v: Vec<f64> = r[..4].iter().map(|c| c.parse().unwrap()).collect();
        let (x, y) = (v[0], v[1]);
        seen.insert(r[4].clone());
        let c2 = 1.0 - y * y;
        if x * x >= c2 {
            assert_eq!(r[4], "outside");
            assert_eq!((v[2], v[3]), (0.0, 0.0));
            continue;
        }
        let c = c2.sqrt();
        let want = (1.5 * (x + c)).min(1.5 * (c2 - x * x).sqrt());
        assert!((v[2] - want).abs() < 1e-12, "{r:?} {want}");
        assert!(v[3].abs() < 1e-12);
    }
    assert_eq!(seen.len(), 3, "{seen:?}");
}

#[test]
fn field_errors_name_the_quantity() {
    let err = fails(&["field", "--k", "500", "--j1", "1"], "");
    assert!(err.contains("aspect ratio"), "{err}");
    let err = fails(&["field", "--k", "1", "--nx", "0"], "");
    assert!(err.contains("grid size"), "{err}");
    let err = fails(&["field", "--k", "1", "--gy", "50"], "");
    assert!(err.contains("stiffness ratio"), "{err}");
}

#[test]
fn field_png_is_written() {
    let dir = std::env::temp_dir().join(format!("traction-field-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let png = dir.join("f.png");
    let out = dir.join("f.csv");
    let rows = ok(
        &[
            "field",
            "--k",
            "2",
            "--j1",
            "1",
            "--j3",
            "3",
            "--nx",
            "30",
            "--ny",
            "20",
            "--output",
            out.to_str().unwrap(),
            "--png",
            png.to_str().unwrap(),
        ],
        "",
    );
    assert!(rows.is_empty(), "CSV went to the file");
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    assert_eq!(
        std::fs::read_to_string(&out).unwrap().lines().count(),
        1 + 30 * 20
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
