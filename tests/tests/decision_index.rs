//! The decision records' index (docs/decisions/README.md) lists every record
//! once, and every entry it lists exists: a newcomer finds each decision by
//! topic there.

use std::collections::BTreeSet;
use std::path::PathBuf;

fn decisions_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/decisions")
}

#[test]
fn every_decision_record_is_indexed_once() {
    let dir = decisions_dir();
    let records: BTreeSet<String> = std::fs::read_dir(&dir)
        .expect("docs/decisions exists")
        .map(|e| {
            e.expect("readable entry")
                .file_name()
                .to_string_lossy()
                .into_owned()
        })
        .filter(|n| n.ends_with(".md") && n.as_bytes().first().is_some_and(u8::is_ascii_digit))
        .collect();
    assert!(records.len() > 50, "found only {} records", records.len());
    let index = std::fs::read_to_string(dir.join("README.md")).expect("index readable");
    let linked: Vec<String> = index
        .split("](")
        .skip(1)
        .filter_map(|rest| rest.split(')').next())
        .filter(|target| target.ends_with(".md") && !target.contains('/'))
        .map(str::to_string)
        .collect();
    let linked_set: BTreeSet<String> = linked.iter().cloned().collect();
    assert_eq!(linked.len(), linked_set.len(), "a record is linked twice");
    let missing: Vec<_> = records.difference(&linked_set).collect();
    assert!(missing.is_empty(), "records not in the index: {missing:?}");
    let dangling: Vec<_> = linked_set.difference(&records).collect();
    assert!(
        dangling.is_empty(),
        "index entries without a record: {dangling:?}"
    );
}
