//! Reading the `#`-commented CSV data files (compiled in with `include_str!`).

use crate::ReproduceError;

/// A parsed `#`-commented CSV: header and rows of trimmed cells.
#[derive(Debug, Clone)]
pub struct DataTable {
    /// File name, for error messages.
    pub name: &'static str,
    /// Column names.
    pub header: Vec<String>,
    /// Data rows.
    pub rows: Vec<Vec<String>>,
}

impl DataTable {
    /// Parse `text` (lines starting with `#` and blank lines are skipped).
    pub fn parse(name: &'static str, text: &str) -> Result<Self, ReproduceError> {
        let mut lines = text
            .lines()
            .filter(|l| !l.starts_with('#') && !l.trim().is_empty());
        let header: Vec<String> = lines
            .next()
            .ok_or_else(|| ReproduceError::Data(format!("{name}: no header line")))?
            .split(',')
            .map(|s| s.trim().to_string())
            .collect();
        let mut rows = Vec::new();
        for (i, l) in lines.enumerate() {
            let r: Vec<String> = l.split(',').map(|s| s.trim().to_string()).collect();
            if r.len() != header.len() {
                return Err(ReproduceError::Data(format!(
                    "{name}: data row {} has {} cells, header has {}",
                    i + 1,
                    r.len(),
                    header.len()
                )));
            }
            rows.push(r);
        }
        Ok(DataTable { name, header, rows })
    }

    /// Index of a column.
    pub fn col(&self, column: &str) -> Result<usize, ReproduceError> {
        self.header.iter().position(|c| c == column).ok_or_else(|| {
            ReproduceError::Data(format!("{}: missing column `{column}`", self.name))
        })
    }

    /// Numeric cell.
    pub fn num(&self, row: usize, col: usize) -> Result<f64, ReproduceError> {
        let s = &self.rows[row][col];
        s.parse::<f64>().map_err(|_| {
            ReproduceError::Data(format!(
                "{}: data row {}, column `{}`: `{s}` is not a number",
                self.name,
                row + 1,
                self.header[col]
            ))
        })
    }

    /// Text cell.
    pub fn str(&self, row: usize, col: usize) -> &str {
        &self.rows[row][col]
    }
}

/// Appendix VI spin traces (curated by traction-fluids' data set).
pub const APPENDIX_VI: &str = include_str!("../../fluids/data/appendix_vi_spin_traces.csv");
/// Appendix VII-A side-slip traces.
pub const APPENDIX_VII_A: &str = include_str!("../../fluids/data/appendix_vii_a_side_slip.csv");
/// Appendix VII-B combined-slip traces.
pub const APPENDIX_VII_B: &str = include_str!("../../fluids/data/appendix_vii_b_combined_slip.csv");
