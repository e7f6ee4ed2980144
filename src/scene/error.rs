//! Errors from reading, checking and writing scene files.

use std::path::PathBuf;

/// Why a scene could not be loaded or saved. Each variant's message names the problem.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The text is not a valid scene file (RON syntax, unknown field, wrong type...).
    #[error("line {line}, column {column}: {message}")]
    Syntax {
        /// 1-based line of the problem.
        line: usize,
        /// 1-based column of the problem.
        column: usize,
        /// What is wrong.
        message: String,
    },
    /// The file parsed but describes an impossible scene; the text names the field.
    #[error("{0}")]
    Invalid(String),
    /// The file could not be read.
    #[error("cannot read {path}: {source}")]
    Read {
        /// The file.
        path: PathBuf,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// The file is over the size limit for scene files.
    #[error("cannot read {path}: the file is larger than {} MiB, the limit for scene files", super::text_file::MAX_SCENE_FILE_BYTES >> 20)]
    TooLarge {
        /// The file.
        path: PathBuf,
    },
    /// The file could not be written; the previous file, if any, is intact.
    #[error("cannot write {path}: {source}")]
    Write {
        /// The file.
        path: PathBuf,
        /// The operating system's reason.
        source: std::io::Error,
    },
}
