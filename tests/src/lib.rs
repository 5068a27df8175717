//! Workspace-wide golden tests against the report's printed tables.
//!
//! The tests live in `tests/tests/*.rs`, one file per group of tables. This
//! library holds the test support shared by them: deviations ([`rel_diff`],
//! [`max_rms`]) and the reading of the report's data files ([`Csv`], with the
//! files themselves in [`data`]).
#![forbid(unsafe_code)]

pub use traction_reproduce::max_rms;

/// The report's data files of Appendices VI, VII-A and VII-B (`fluids/data/`),
/// as the reproduction reads them.
pub mod data {
    pub use traction_reproduce::data::{APPENDIX_VI, APPENDIX_VII_A, APPENDIX_VII_B};
}

/// Relative difference `|computed - printed| / |printed|`, or the absolute
/// difference when the printed value is zero.
pub fn rel_diff(computed: f64, printed: f64) -> f64 {
    if printed == 0.0 {
        (computed - printed).abs()
    } else {
        ((computed - printed) / printed).abs()
    }
}

/// A `#`-commented CSV data file as header and rows of trimmed cells (read by
/// the reproduction's [`traction_reproduce::data::DataTable`]). The accessors
/// panic with the file, column and cell: in a test, a malformed file is a
/// failure.
#[derive(Debug, Clone)]
pub struct Csv {
    /// File name, for messages.
    pub name: &'static str,
    /// Column names.
    pub header: Vec<String>,
    /// Data rows.
    pub rows: Vec<Vec<String>>,
}

impl Csv {
    /// Parses `text`, the contents of the data file `name`.
    ///
    /// # Panics
    /// If the file has no header or a row has the wrong number of cells.
    pub fn parse(name: &'static str, text: &str) -> Csv {
        let t = traction_reproduce::data::DataTable::parse(name, text)
            .unwrap_or_else(|e| panic!("{e}"));
        Csv {
            name,
            header: t.header,
            rows: t.rows,
        }
    }

    /// Index of the column `name`.
    ///
    /// # Panics
    /// If there is no such column.
    pub fn idx(&self, name: &str) -> usize {
        self.header
            .iter()
            .position(|c| c == name)
            .unwrap_or_else(|| panic!("{}: no column `{name}`", self.name))
    }

    /// The number in column `name` of `row`.
    ///
    /// # Panics
    /// If there is no such column or the cell is not a number.
    pub fn f(&self, row: &[String], name: &str) -> f64 {
        let s = &row[self.idx(name)];
        s.parse()
            .unwrap_or_else(|_| panic!("{}: `{s}` in column `{name}` is not a number", self.name))
    }

    /// The text in column `name` of `row`.
    ///
    /// # Panics
    /// If there is no such column.
    pub fn s<'a>(&self, row: &'a [String], name: &str) -> &'a str {
        &row[self.idx(name)]
    }
}

/// The number in cell `i` of `row`.
///
/// # Panics
/// If the cell is not a number.
pub fn cell(row: &[String], i: usize) -> f64 {
    row[i]
        .parse()
        .unwrap_or_else(|_| panic!("`{}` (cell {i}) is not a number", row[i]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rel_diff_and_max_rms() {
        assert!((rel_diff(1.01, 1.0) - 0.01).abs() < 1e-12);
        assert_eq!(rel_diff(0.5, 0.0), 0.5);
        let (m, r) = max_rms(&[3.0, -4.0]);
        assert_eq!(m, 4.0);
        assert!((r - (12.5_f64).sqrt()).abs() < 1e-12);
    }

    #[test]
    fn csv_reads_columns_and_names_bad_cells() {
        let t = Csv::parse("t.csv", "# comment\na,b\n1, x\n");
        assert_eq!(t.rows.len(), 1);
        assert_eq!(t.f(&t.rows[0], "a"), 1.0);
        assert_eq!(t.s(&t.rows[0], "b"), "x");
        assert_eq!(cell(&t.rows[0], 0), 1.0);
        let bad = std::panic::catch_unwind(|| t.f(&t.rows[0], "b"));
        assert!(bad.is_err());
    }
}
