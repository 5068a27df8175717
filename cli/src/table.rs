//! CSV input and output shared by every batch subcommand.
//!
//! Input: a header row, then data rows; lines starting with `#` are comments;
//! `-` as the path means stdin. Numbers are parsed as `f64`; `inf`/`-inf` are
//! accepted (a flat surface has an infinite radius), NaN never is. Every error
//! names the input, the 1-based data row, the line and the column. A radius of
//! 0 means flat too, as in the FMU ([`radius`]).
//!
//! Output: the input columns unchanged, followed by the computed columns,
//! numbers in Rust's shortest round-trip form; `-` means stdout.

use std::io::{Read, Write};

use crate::error::{CliError, chain};

/// A radius of curvature as the CLI takes it: 0 and ±inf both mean a flat
/// profile (the FMU's convention, docs/decisions/0014), returned as the
/// library's flat = +inf; any other value is passed on for the library to check.
pub fn radius(r: f64) -> f64 {
    if r == 0.0 || r.is_infinite() {
        f64::INFINITY
    } else {
        r
    }
}

/// A CSV table read fully into memory (the inputs are small batch files).
#[derive(Debug, Clone)]
pub struct Table {
    /// Input name used in error messages (`stdin` or the path).
    pub source_name: String,
    /// Header cells, trimmed.
    pub headers: Vec<String>,
    /// Data rows, cells trimmed.
    pub rows: Vec<Vec<String>>,
    /// 1-based input line of each data row.
    pub lines: Vec<u64>,
}

impl Table {
    /// Read a table from a path, or from stdin when `path` is `-`.
    pub fn read(path: &str) -> Result<Table, CliError> {
        let (source_name, text) = if path == "-" {
            let mut s = String::new();
            std::io::stdin()
                .read_to_string(&mut s)
                .map_err(|source| CliError::Io {
                    context: "reading stdin".into(),
                    source,
                })?;
            ("stdin".to_string(), s)
        } else {
            let s = std::fs::read_to_string(path).map_err(|source| CliError::Io {
                context: format!("reading {path}"),
                source,
            })?;
            (path.to_string(), s)
        };
        Table::parse(&source_name, &text)
    }

    /// Parse a table from text; `source_name` is used in error messages.
    pub fn parse(source_name: &str, text: &str) -> Result<Table, CliError> {
        let mut rdr = csv::ReaderBuilder::new()
            .comment(Some(b'#'))
            .trim(csv::Trim::All)
            .flexible(false)
            .from_reader(text.as_bytes());
        let headers: Vec<String> = rdr
            .headers()
            .map_err(|source| CliError::Csv {
                context: format!("{source_name}: header"),
                source,
            })?
            .iter()
            .map(str::to_string)
            .collect();
        // A column read by name must be unambiguous.
        for (i, h) in headers.iter().enumerate() {
            if !h.is_empty() && headers[..i].contains(h) {
                return Err(CliError::Usage(format!(
                    "{source_name}: header: column `{h}` appears more than once"
                )));
            }
        }
        let mut rows = Vec::new();
        let mut lines = Vec::new();
        for rec in rdr.records() {
            let rec = rec.map_err(|source| CliError::Csv {
                context: source_name.to_string(),
                source,
            })?;
            lines.push(rec.position().map_or(0, |p| p.line()));
            rows.push(rec.iter().map(str::to_string).collect());
        }
        Ok(Table {
            source_name: source_name.to_string(),
            headers,
            rows,
            lines,
        })
    }

    /// Number of data rows.
    pub fn len(&self) -> usize {
        self.rows.len()
    }

    /// Index of a column, if present.
    pub fn column(&self, name: &str) -> Option<usize> {
        self.headers.iter().position(|h| h == name)
    }

    /// Whether a column is present.
    pub fn has(&self, name: &str) -> bool {
        self.column(name).is_some()
    }

    /// Fail with [`CliError::MissingColumn`] unless all `names` are present.
    pub fn require(&self, names: &[&str]) -> Result<(), CliError> {
        for n in names {
            if !self.has(n) {
                return Err(CliError::MissingColumn {
                    source_name: self.source_name.clone(),
                    column: (*n).to_string(),
                    expected: names.join(","),
                });
            }
        }
        Ok(())
    }

    /// An error about cell (`row`, `column`); `row` is 0-based here.
    pub fn cell_error(&self, row: usize, column: &str, message: impl Into<String>) -> CliError {
        CliError::Cell {
            source_name: self.source_name.clone(),
            row: row + 1,
            line: self.lines.get(row).copied().unwrap_or(0),
            column: column.to_string(),
            message: message.into(),
        }
    }

    /// The model rejected a whole row: `error` and its sources ([`chain`]);
    /// `row` is 0-based.
    pub fn row_error(&self, row: usize, error: impl std::error::Error) -> CliError {
        self.row_message(row, chain(&error))
    }

    /// An error about a whole row, in words; `row` is 0-based.
    pub fn row_message(&self, row: usize, message: impl Into<String>) -> CliError {
        CliError::Row {
            source_name: self.source_name.clone(),
            row: row + 1,
            line: self.lines.get(row).copied().unwrap_or(0),
            message: message.into(),
        }
    }

    /// Raw text of a cell; errors if the column is missing. `row` is 0-based.
    pub fn str(&self, row: usize, column: &str) -> Result<&str, CliError> {
        let c = self.column(column).ok_or_else(|| CliError::MissingColumn {
            source_name: self.source_name.clone(),
            column: column.to_string(),
            expected: self.headers.join(","),
        })?;
        Ok(self.rows[row][c].as_str())
    }

    /// A required finite-or-infinite number (NaN and empty cells are errors).
    pub fn f64(&self, row: usize, column: &str) -> Result<f64, CliError> {
        let s = self.str(row, column)?;
        if s.is_empty() {
            return Err(self.cell_error(row, column, "empty cell, a number is required"));
        }
        parse_number(s).map_err(|m| self.cell_error(row, column, m))
    }

    /// An optional number: `None` when the column is absent or the cell empty.
    pub fn opt_f64(&self, row: usize, column: &str) -> Result<Option<f64>, CliError> {
        match self.column(column) {
            None => Ok(None),
            Some(c) => {
                let s = self.rows[row][c].as_str();
                if s.is_empty() {
                    Ok(None)
                } else {
                    parse_number(s)
                        .map(Some)
                        .map_err(|m| self.cell_error(row, column, m))
                }
            }
        }
    }
}

/// Parse a number; accepts `inf`, `+inf`, `-inf`, `infinity` (any case).
pub fn parse_number(s: &str) -> Result<f64, String> {
    let v: f64 = s.parse().map_err(|_| format!("`{s}` is not a number"))?;
    if v.is_nan() {
        return Err(format!("`{s}` is not a number (NaN is not accepted)"));
    }
    Ok(v)
}

/// Format a number for output (shortest representation that round-trips).
pub fn fmt_f64(v: f64) -> String {
    format!("{v}")
}

/// Writes the output CSV: a header, then one record per row.
pub struct TableWriter {
    wtr: csv::Writer<Box<dyn Write>>,
    name: String,
}

impl TableWriter {
    /// Create a writer for `path` (`-` means stdout) and write the header.
    pub fn create(path: &str, headers: &[String]) -> Result<TableWriter, CliError> {
        let (sink, name): (Box<dyn Write>, String) = if path == "-" {
            (Box::new(std::io::stdout().lock()), "stdout".into())
        } else {
            let f = std::fs::File::create(path).map_err(|source| CliError::Io {
                context: format!("creating {path}"),
                source,
            })?;
            (Box::new(std::io::BufWriter::new(f)), path.to_string())
        };
        let mut w = TableWriter {
            wtr: csv::Writer::from_writer(sink),
            name,
        };
        w.write_row(headers)?;
        Ok(w)
    }

    /// Write one record.
    pub fn write_row<S: AsRef<str>>(&mut self, cells: &[S]) -> Result<(), CliError> {
        self.wtr
            .write_record(cells.iter().map(|c| c.as_ref()))
            .map_err(|source| CliError::Csv {
                context: format!("writing {}", self.name),
                source,
            })
    }

    /// Flush the output.
    pub fn finish(mut self) -> Result<(), CliError> {
        self.wtr.flush().map_err(|source| CliError::Io {
            context: format!("writing {}", self.name),
            source,
        })
    }
}

/// Output header: the input headers followed by `extra`.
pub fn output_headers(input: &Table, extra: &[&str]) -> Vec<String> {
    input
        .headers
        .iter()
        .cloned()
        .chain(extra.iter().map(|s| (*s).to_string()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_column_named_twice_is_refused() {
        let e = Table::parse("in.csv", "k,J1,k\n1,2,3\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "in.csv: header: column `k` appears more than once"
        );
        assert!(Table::parse("in.csv", "k,J1\n1,2\n").is_ok());
    }

    #[test]
    fn parses_comments_inf_and_names_bad_cells() {
        let t = Table::parse("t.csv", "# comment\na,b\n1,inf\n2,x\n").unwrap();
        assert_eq!(t.len(), 2);
        assert_eq!(t.f64(0, "b").unwrap(), f64::INFINITY);
        let e = t.f64(1, "b").unwrap_err().to_string();
        assert!(
            e.contains("row 2") && e.contains("`b`") && e.contains("line 4"),
            "{e}"
        );
        assert!(t.f64(0, "c").is_err());
        assert_eq!(t.opt_f64(0, "c").unwrap(), None);
    }

    #[test]
    fn nan_and_empty_are_rejected() {
        let t = Table::parse("t", "a,b\nNaN,\n").unwrap();
        assert!(t.f64(0, "a").is_err());
        assert!(t.f64(0, "b").is_err());
        assert_eq!(t.opt_f64(0, "b").unwrap(), None);
    }

    #[test]
    fn ragged_rows_are_an_error() {
        assert!(Table::parse("t", "a,b\n1\n").is_err());
    }
}
