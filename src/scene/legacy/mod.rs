//! Import of the legacy COSC342 text scene format (`shared/COSC342_FORMAT.md`) into a
//! [`Scene`].
//!
//! The text goes through three stages: `lexer` (tokens with line numbers, comments
//! dropped), `parser` (blocks of typed keywords, numbers checked) and `convert`
//! (materials resolved in file order, transforms composed, camera and lights converted).
//! Every stage collects its errors instead of stopping, so a broken file reports all of
//! its problems at once, each with its line and token, and nothing is imported from it.
//!
//! Imports set `samples_per_pixel: 1`, as the legacy renderer has no anti-aliasing, so
//! an imported scene renders the legacy picture (the editor can raise it).

mod convert;
mod error;
mod lexer;
mod parser;
mod syntax;

use std::path::Path;

pub use error::{LegacyError, LegacyErrors, LegacyImportFileError};

use crate::scene::{Scene, TextFileError, read_text_file};

/// A successful import: the scene, and warnings about what was skipped or changed.
#[derive(Clone, Debug, PartialEq)]
pub struct LegacyImport {
    /// The imported scene; it passes [`crate::scene::validate`].
    pub scene: Scene,
    /// One line each, "line N: ...", for the user to read.
    pub warnings: Vec<String>,
}

/// Imports legacy scene text.
///
/// # Errors
/// Every problem in the text, in line order, each with its line and token.
pub fn import_legacy(text: &str) -> Result<LegacyImport, LegacyErrors> {
    let tokens = lexer::tokenize(text);
    let mut errors = Vec::new();
    let blocks = parser::parse(&tokens, &mut errors);
    let converted = convert::convert(&blocks, &mut errors);
    if errors.is_empty() {
        Ok(LegacyImport {
            scene: converted.scene,
            warnings: converted.warnings,
        })
    } else {
        errors.sort_by_key(|e| e.line);
        Err(LegacyErrors(errors))
    }
}

/// Reads and imports a legacy scene file.
///
/// # Errors
/// [`LegacyImportFileError::Read`] when the file cannot be read,
/// [`LegacyImportFileError::NotText`] when it is not UTF-8, and
/// [`LegacyImportFileError::Legacy`] with every problem in the text.
pub fn import_legacy_file(path: &Path) -> Result<LegacyImport, LegacyImportFileError> {
    let text = read_text_file(path).map_err(|e| match e {
        TextFileError::Read(source) => LegacyImportFileError::Read {
            path: path.to_owned(),
            source,
        },
        TextFileError::TooLarge => LegacyImportFileError::TooLarge {
            path: path.to_owned(),
        },
        TextFileError::NotUtf8 { line } => LegacyImportFileError::NotText {
            path: path.to_owned(),
            line,
        },
    })?;
    import_legacy(&text).map_err(|errors| LegacyImportFileError::Legacy {
        path: path.to_owned(),
        errors,
    })
}
