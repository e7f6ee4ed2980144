//! Import of the legacy COSC342 text scene format (`shared/COSC342_FORMAT.md`) into a
//! [`Scene`], and export back to it (`write`, in either framework's dialect, refusing or
//! warning by name about what a dialect cannot say).
//!
//! The text goes through three stages: `lexer` (tokens with line numbers, comments
//! dropped), `parser` (blocks of typed keywords, numbers checked) and `convert`
//! (materials resolved in file order, transforms composed, camera and lights converted).
//! Every stage collects its errors instead of stopping, so a broken file reports all of
//! its problems at once, each with its line and token, and nothing is imported from it.
//!
//! Both course frameworks' dialects are read (the 2016 one and the 2020 one with its
//! students' extensions: CSG, groups, torus, tube, octahedron, meshes, refraction,
//! supersampling, sphere lights); which one a file is in is read off its content and
//! told in [`LegacyImport::summary`]. An unknown block, object kind or keyword is skipped
//! with a warning; a syntax error refuses the file.
//!
//! Imports set `samples_per_pixel: 1` unless the file asks for `Supersampling` or
//! `FSAA N`, as the legacy renderer has no anti-aliasing otherwise, and carry the course's
//! conventions (`Conventions::COURSE`), so an imported scene renders the legacy picture.

mod convert;
mod error;
mod lexer;
mod mesh_paths;
mod parser;
mod syntax;
mod write;

use std::path::{Path, PathBuf};

pub use convert::{Detected, Dialect};
pub use error::{LegacyError, LegacyErrors, LegacyImportFileError, Warning};
pub use mesh_paths::rebase_mesh_paths;
pub use parser::MAX_NESTING;
pub use write::{
    CourseExportError, CourseExportFileError, CourseScene, Problem, Subject, export_course_file,
    write_course_scene, year,
};

use crate::scene::{Scene, TextFileError, read_text_file};

/// A successful import: the scene, the dialect it was read in, and warnings about what
/// was skipped or changed.
#[derive(Clone, Debug, PartialEq)]
pub struct LegacyImport {
    /// The imported scene; it passes [`crate::scene::validate`].
    pub scene: Scene,
    /// The framework dialect the file was read in, and the constructs that told.
    pub dialect: Detected,
    /// One line each, "line N: ...", in line order, for the user to read.
    pub warnings: Vec<String>,
}

impl LegacyImport {
    /// One line for the user: what was read and how, for example "read as the 2016
    /// framework's dialect (`Object CSG` at line 3): 4 objects, 1 light, 2 materials".
    #[must_use]
    pub fn summary(&self) -> String {
        let count = |n: usize, what: &str| {
            let plural = if n == 1 { "" } else { "s" };
            format!("{n} {what}{plural}")
        };
        format!(
            "read as {}: {}, {}, {}",
            self.dialect.describe(),
            count(self.scene.objects.len(), "object"),
            count(self.scene.lights.len(), "light"),
            count(self.scene.materials.len(), "material")
        )
    }
}

/// Whether `text` reads like a course scene rather than a RON one: its first line that
/// is neither blank nor a comment starts with one of the course format's block words
/// (`Scene`, `Camera`, `Light`, `Material`, `Object`, `CSG`, `ObjectGroup`, in any case,
/// as the 2016 framework upper-cases lines) followed by a space or the line's end, not
/// by a parenthesis as RON's `Scene(` is. Decides by content, whatever the file's name.
#[must_use]
pub fn looks_like_legacy(text: &str) -> bool {
    let Some(line) = text
        .lines()
        .map(str::trim)
        .find(|l| !l.is_empty() && !l.starts_with('#') && !l.starts_with("//"))
    else {
        return false;
    };
    let word = line
        .split(|c: char| c.is_whitespace() || c == '(')
        .next()
        .unwrap_or("");
    let after = &line[word.len()..];
    parser::BLOCK_WORDS
        .iter()
        .any(|block| block.eq_ignore_ascii_case(word))
        && (after.is_empty() || after.starts_with(char::is_whitespace))
}

/// Imports legacy scene text. `Mesh` paths are kept as written (there is no folder to
/// look in); [`import_legacy_file`] checks them.
///
/// # Errors
/// Every problem in the text, in line order, each with its line and token.
pub fn import_legacy(text: &str) -> Result<LegacyImport, LegacyErrors> {
    import_text(text, None)
}

fn import_text(text: &str, folder: Option<PathBuf>) -> Result<LegacyImport, LegacyErrors> {
    let tokens = lexer::tokenize(text);
    let comments = lexer::Comments::of(text);
    let mut diagnostics = error::Diagnostics::default();
    let blocks = parser::parse(&tokens, &comments, &mut diagnostics);
    let converted = convert::convert(&blocks, folder, &mut diagnostics);
    if diagnostics.errors.is_empty() {
        Ok(LegacyImport {
            scene: converted.scene,
            dialect: converted.dialect,
            warnings: diagnostics.warning_lines(),
        })
    } else {
        let mut errors = diagnostics.errors;
        errors.sort_by_key(|e| e.line);
        Err(LegacyErrors(errors))
    }
}

/// Reads and imports a legacy scene file. `Mesh` paths are looked up in the file's
/// folder and kept relative to it (a scene written elsewhere needs them rebased: see
/// [`rebase_mesh_paths`]).
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
    let folder = path.parent().map(Path::to_path_buf).unwrap_or_default();
    import_text(&text, Some(folder)).map_err(|errors| LegacyImportFileError::Legacy {
        path: path.to_owned(),
        errors,
    })
}

#[cfg(test)]
mod sniff_tests {
    use super::looks_like_legacy;

    #[test]
    fn course_scenes_are_told_from_ron_ones_by_their_first_word() {
        assert!(looks_like_legacy(
            "# a comment\n\nScene\n  renderSize 80 60\nEnd\n"
        ));
        assert!(looks_like_legacy("OBJECT SPHERE\nEND"));
        assert!(looks_like_legacy("Camera PinholeCamera 1\nEnd"));
        assert!(!looks_like_legacy("// RON\nScene(\n  camera: (),\n)"));
        assert!(!looks_like_legacy("(camera: ())"));
        assert!(!looks_like_legacy(
            "# raylab\n\nThis README explains the scenes."
        ));
        assert!(!looks_like_legacy(""));
        assert!(!looks_like_legacy("Scenery is nice"));
    }
}
