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

/// Something imported with a caveat, or skipped: told to the user, the rest imports.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Warning {
    /// 1-based line it is about, if it is about one.
    pub line: Option<usize>,
    /// What was skipped or changed, and why.
    pub message: String,
}

impl fmt::Display for Warning {
    /// `line N: message`, or the message alone.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(line) => write!(f, "line {line}: {}", self.message),
            None => f.write_str(&self.message),
        }
    }
}

/// What the stages found so far: errors refuse the whole file, warnings do not.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Diagnostics {
    /// Problems that stop the import.
    pub errors: Vec<LegacyError>,
    /// Things skipped or changed.
    pub warnings: Vec<Warning>,
}

impl Diagnostics {
    /// Records an error.
    pub fn push(&mut self, error: LegacyError) {
        self.errors.push(error);
    }

    /// Records a warning about `line`.
    pub fn warn(&mut self, line: usize, message: impl Into<String>) {
        self.warnings.push(Warning {
            line: Some(line),
            message: message.into(),
        });
    }

    /// Records a warning about the whole file.
    pub fn warn_file(&mut self, message: impl Into<String>) {
        self.warnings.push(Warning {
            line: None,
            message: message.into(),
        });
    }

    /// The warnings in line order (file-wide ones last), as the user reads them.
    #[must_use]
    pub fn warning_lines(&self) -> Vec<String> {
        let mut warnings = self.warnings.clone();
        warnings.sort_by_key(|w| w.line.unwrap_or(usize::MAX));
        warnings.iter().map(ToString::to_string).collect()
    }
}

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
