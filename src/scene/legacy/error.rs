//! Import errors: every problem in a legacy file, each with its line and token, and the
//! error of importing a file from disk.

use std::fmt;
use std::path::PathBuf;

/// One problem in a legacy file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LegacyError {
    /// 1-based line of the offending token.
    pub line: usize,
    /// The offending token, as written in the file (empty only for an empty file).
    pub token: String,
    /// What is wrong, and what was expected.
    pub message: String,
}

impl LegacyError {
    /// An error at `line` about `token`.
    #[must_use]
    pub fn new(line: usize, token: &str, message: impl Into<String>) -> Self {
        Self {
            line,
            token: token.to_owned(),
            message: message.into(),
        }
    }
}

impl fmt::Display for LegacyError {
    /// `line N: `token`: message`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: `{}`: {}", self.line, self.token, self.message)
    }
}

impl std::error::Error for LegacyError {}

/// Every problem found in a legacy file, in line order. Never empty when returned.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LegacyErrors(pub Vec<LegacyError>);

impl fmt::Display for LegacyErrors {
    /// One error per line.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (index, error) in self.0.iter().enumerate() {
            if index > 0 {
                writeln!(f)?;
            }
            write!(f, "{error}")?;
        }
        Ok(())
    }
}

impl std::error::Error for LegacyErrors {}

/// Why a legacy file on disk could not be imported.
#[derive(Debug, thiserror::Error)]
pub enum LegacyImportFileError {
    /// The file could not be read.
    #[error("cannot read {path}: {source}")]
    Read {
        /// The file.
        path: PathBuf,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// The file is over the size limit for scene files.
    #[error("cannot read {path}: the file is larger than {} MiB, the limit for scene files", crate::scene::MAX_SCENE_FILE_BYTES >> 20)]
    TooLarge {
        /// The file.
        path: PathBuf,
    },
    /// The file is not UTF-8 text.
    #[error("{path}: line {line}: the file is not UTF-8 text")]
    NotText {
        /// The file.
        path: PathBuf,
        /// 1-based line of the first byte that is not UTF-8.
        line: usize,
    },
    /// The text has problems; every one is listed.
    #[error("{path}: the legacy scene has errors:\n{errors}")]
    Legacy {
        /// The file.
        path: PathBuf,
        /// Every problem, with its line and token.
        errors: LegacyErrors,
    },
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_display_one_per_line_with_line_and_token() {
        let errors = LegacyErrors(vec![
            LegacyError::new(3, "Colr", "unknown keyword"),
            LegacyError::new(7, "1,0", "not a number"),
        ]);
        assert_eq!(
            errors.to_string(),
            "line 3: `Colr`: unknown keyword\nline 7: `1,0`: not a number"
        );
    }
}
