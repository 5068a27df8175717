//! The CLI's error type: every failure names what went wrong and where.

use std::fmt;

/// A CLI failure. Displayed on stderr as `error: ...` with a non-zero exit.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum CliError {
    /// Reading or writing a file or stream failed.
    #[error("{context}: {source}")]
    Io {
        /// What was being read or written.
        context: String,
        /// The underlying error.
        source: std::io::Error,
    },
    /// The CSV could not be parsed at all (bad quoting, ragged rows, ...).
    #[error("{context}: {source}")]
    Csv {
        /// What was being read or written.
        context: String,
        /// The underlying error.
        source: csv::Error,
    },
    /// A required column is missing from the input header.
    #[error("{source_name}: missing column `{column}` (expected columns: {expected})")]
    MissingColumn {
        /// Input name (file path or `stdin`).
        source_name: String,
        /// The missing column.
        column: String,
        /// The columns the command expects.
        expected: String,
    },
    /// One cell of one row is malformed or out of range.
    #[error("{source_name}: row {row} (line {line}), column `{column}`: {message}")]
    Cell {
        /// Input name (file path or `stdin`).
        source_name: String,
        /// 1-based data row (header excluded).
        row: usize,
        /// 1-based line in the input.
        line: u64,
        /// Column name.
        column: String,
        /// What is wrong with it.
        message: String,
    },
    /// A row parsed but the model rejected it.
    #[error("{source_name}: row {row} (line {line}): {message}")]
    Row {
        /// Input name (file path or `stdin`).
        source_name: String,
        /// 1-based data row (header excluded).
        row: usize,
        /// 1-based line in the input.
        line: u64,
        /// The model's error, which names the quantity.
        message: String,
    },
    /// Invalid command-line usage not caught by the argument parser.
    #[error("{0}")]
    Usage(String),
    /// A model error outside any CSV row (single-value commands).
    #[error("{0}")]
    Model(String),
}

impl CliError {
    /// Wrap a model error (anything displayable) as a [`CliError::Model`].
    pub fn model(e: impl fmt::Display) -> Self {
        CliError::Model(e.to_string())
    }
}
