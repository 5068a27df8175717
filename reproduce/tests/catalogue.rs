//! Every reproduced table stays within its golden-test tolerance, lists what is
//! missing, and the summary counts what the CSV holds.
#![allow(clippy::unwrap_used)] // test: a failed unwrap is a failed test

use traction_reproduce::tables::catalogue;
use traction_reproduce::{Deviation, missing_tables, summarise, write_csv};

#[test]
fn every_table_is_within_its_tolerance() {
    for (id, f) in catalogue() {
        let r = f().unwrap();
        assert_eq!(r.table.id, id);
        let s = summarise(&r.table);
        println!(
            "{id}: n {} printed {} max {:.4e} rms {:.4e} measured {} max {:.4e} outside {}",
            s.n,
            s.n_printed,
            s.max_printed,
            s.rms_printed,
            s.n_measured,
            s.max_measured,
            s.n_outside
        );
        assert!(s.n > 0, "{id}: no values");
        assert!(s.within_tolerance, "{id}: {s:?}");
        // A table without printed theory says so instead of passing silently.
        if s.n_printed == 0 {
            assert!(
                r.table.tolerance.is_none() && !r.table.missing.is_empty(),
                "{id}"
            );
        }
    }
}

#[test]
fn the_tolerance_check_can_fail() {
    let (_, f) = catalogue()
        .into_iter()
        .find(|(id, _)| *id == "table-2-2")
        .unwrap();
    let mut t = f().unwrap().table;
    t.rows[0].computed *= 1.01; // A(0.5) 1 % off: beyond 0.4 %
    let s = summarise(&t);
    assert!(!s.within_tolerance);
    assert_eq!(s.n_outside, 1);
    assert_eq!(t.deviation, Deviation::Relative);
}

#[test]
fn held_out_and_untranscribed_tables_are_listed() {
    let names: Vec<&str> = missing_tables().iter().map(|m| m.name).collect();
    assert!(names.iter().any(|n| n.contains("III-F")));
    assert!(names.iter().any(|n| n.contains("VII-C")));
    let (_, f) = catalogue()
        .into_iter()
        .find(|(id, _)| *id == "appendix-iii-f")
        .unwrap();
    let r = f().unwrap();
    assert!(r.table.missing[0].contains("printed values not available"));
    assert!(
        r.table
            .rows
            .iter()
            .all(|x| x.printed.is_none() && x.measured.is_some())
    );
}

#[test]
fn csv_has_one_line_per_row_and_the_three_columns() {
    let (_, f) = catalogue()
        .into_iter()
        .find(|(id, _)| *id == "appendix-vii-a")
        .unwrap();
    let t = f().unwrap().table;
    let dir = std::env::temp_dir().join(format!("traction-reproduce-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("t.csv");
    write_csv(&t, &p).unwrap();
    let text = std::fs::read_to_string(&p).unwrap();
    let data: Vec<&str> = text.lines().filter(|l| !l.starts_with('#')).collect();
    assert!(data[0].starts_with("series,label,x,computed,printed_theory,measured"));
    assert_eq!(data.len(), t.rows.len() + 1);
    std::fs::remove_dir_all(&dir).unwrap();
}
