//! The CLI's error type: every failure names what went wrong and where.

/// A CLI failure. Displayed on stderr as `error: ...` with a non-zero exit.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum CliError {
    /// Reading or writing a file or stream failed (the I/O error is the source).
    #[error("{context}")]
    Io {
        /// What was being read or written.
        context: String,
        /// The underlying error.
        source: std::io::Error,
    },
    /// The CSV could not be parsed at all (bad quoting, ragged rows, ...); the
    /// CSV error is the source.
    #[error("{context}")]
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
    /// Wrap a model error as a [`CliError::Model`], with its sources ([`chain`]).
    pub fn model(e: impl std::error::Error) -> Self {
        CliError::Model(chain(&e))
    }
}

/// Library advice that names a Rust API, and what the CLI calls the same thing.
const CLI_WORDS: [(&str, &str); 1] = [(
    "use Policy::Extrapolate to get a flagged extrapolation",
    "use --envelope extrapolate for a flagged extrapolation or --envelope clamp",
)];

/// `text` with the library's API names replaced by the CLI options that do the
/// same ([`CLI_WORDS`]).
pub fn cli_words(text: &str) -> String {
    CLI_WORDS
        .iter()
        .fold(text.to_string(), |t, (api, cli)| t.replace(api, cli))
}

/// An error and its sources joined by `": "`
/// ([`traction_contact::error_chain`]), as the command prints it, in the CLI's
/// words ([`cli_words`]).
pub fn chain(e: &dyn std::error::Error) -> String {
    cli_words(&traction_contact::error_chain(e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, thiserror::Error)]
    #[error("inner")]
    struct Inner;

    #[derive(Debug, thiserror::Error)]
    enum Outer {
        #[error("outer")]
        Sourced(#[source] Inner),
        #[error("outer: {0}")]
        Repeating(#[from] Inner),
    }

    #[test]
    fn chain_prints_each_source_once() {
        assert_eq!(chain(&Outer::Sourced(Inner)), "outer: inner");
        assert_eq!(chain(&Outer::Repeating(Inner)), "outer: inner");
        let io = CliError::Io {
            context: "reading x.csv".into(),
            source: std::io::Error::other("gone"),
        };
        assert_eq!(chain(&io), "reading x.csv: gone");
        let row = CliError::Usage(
            "U = 99 is outside the data envelope [10, 80] of S50 μ; use Policy::Extrapolate to get a flagged extrapolation".into(),
        );
        let t = chain(&row);
        assert!(
            t.contains("--envelope extrapolate") && !t.contains("Policy::"),
            "{t}"
        );
    }
}
