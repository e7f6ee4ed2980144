//! Reading and writing scene files (RON). Writes are atomic: a temporary file in the
//! same folder, flushed to disk, then renamed over the target.

use std::io::Write;
use std::path::{Path, PathBuf};

use ron::extensions::Extensions;
use serde::Deserialize;

use super::error::SceneError;
use super::model::Scene;
use super::text_file::{TextFileError, read_text_file};
use super::validate::validate;

/// Deepest RON nesting accepted in a scene file: enough for object trees of
/// [`super::MAX_TREE_DEPTH`] levels (each takes 7: the object, its shape, the operand
/// list, ...) and the scene around them; deeper text is a syntax error naming the
/// limit. The parser's stack grows on the heap as it nests (`serde_stacker`), so the
/// limit is about sense, not the thread's stack.
const RECURSION_LIMIT: usize = 8 * super::MAX_TREE_DEPTH + 64;

/// Parses and validates scene text.
///
/// # Errors
/// [`SceneError::Syntax`] with line and column for text that is not a scene,
/// [`SceneError::Invalid`] naming the field for a scene that cannot be rendered.
pub fn parse_scene(text: &str) -> Result<Scene, SceneError> {
    let options = ron::Options::default()
        .with_default_extension(Extensions::empty())
        .with_recursion_limit(RECURSION_LIMIT);
    let syntax = |e: ron::error::SpannedError| SceneError::Syntax {
        line: e.span.start.line,
        column: e.span.start.col,
        message: match e.code {
            // The parser's advice (raise its limit) is for programmers; the scene's
            // author nested objects too deep.
            ron::Error::ExceededRecursionLimit => format!(
                "objects nested more than {} levels deep (CSG operands or group children)",
                super::MAX_TREE_DEPTH
            ),
            code => code.to_string(),
        },
    };
    let mut deserializer =
        ron::Deserializer::from_str_with_options(text, &options).map_err(syntax)?;
    let parsed = Scene::deserialize(serde_stacker::Deserializer::new(&mut deserializer));
    let mut scene = parsed
        .and_then(|scene| deserializer.end().map(|()| scene))
        .map_err(|e| syntax(deserializer.span_error(e)))?;
    scene.fill_default_names();
    validate(&scene)?;
    Ok(scene)
}

/// Reads, parses and validates a scene file.
///
/// # Errors
/// As [`parse_scene`], plus [`SceneError::Read`] when the file cannot be read.
pub fn load_scene(path: &Path) -> Result<Scene, SceneError> {
    let text = read_text_file(path).map_err(|e| match e {
        TextFileError::NotUtf8 { line } => SceneError::Syntax {
            line,
            column: 1,
            message: "the file is not UTF-8 text".to_owned(),
        },
        TextFileError::TooLarge => SceneError::TooLarge {
            path: path.to_owned(),
        },
        TextFileError::Read(source) => SceneError::Read {
            path: path.to_owned(),
            source,
        },
    })?;
    parse_scene(&text)
}

/// The scene as RON text, in the layout of the contract (`Scene(...)`).
#[must_use]
pub fn scene_to_ron(scene: &Scene) -> String {
    let config = ron::ser::PrettyConfig::new()
        .indentor("    ")
        .struct_names(false);
    // Serialising plain data with finite numbers cannot fail.
    let body = ron::ser::to_string_pretty(scene, config).unwrap_or_else(|e| {
        unreachable!("scene serialisation failed: {e}");
    });
    format!("Scene{body}\n")
}

/// Validates and writes a scene atomically.
///
/// # Errors
/// [`SceneError::Invalid`] for a scene that would not load again, [`SceneError::Write`]
/// when the file cannot be written; the previous file is then untouched.
pub fn save_scene(scene: &Scene, path: &Path) -> Result<(), SceneError> {
    validate(scene)?;
    write_atomically(path, scene_to_ron(scene).as_bytes()).map_err(|source| SceneError::Write {
        path: path.to_owned(),
        source,
    })
}

/// Writes `bytes` to a temporary file beside `path`, syncs it, and renames it over `path`.
/// A crash at any point leaves either the old file or the new one, never a mix.
///
/// # Errors
/// The I/O error; the temporary file is removed on failure.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    write_atomically_with(path, bytes, || {})
}

/// [`write_atomically`] with a hook run after the temporary file is complete and synced,
/// just before the rename: the one moment a crash would matter, which tests use to kill
/// the process there.
///
/// # Errors
/// The I/O error; the temporary file is removed on failure.
pub fn write_atomically_with(
    path: &Path,
    bytes: &[u8],
    before_rename: impl FnOnce(),
) -> std::io::Result<()> {
    let temporary = temporary_path(path);
    let result = (|| {
        let mut file = std::fs::File::create(&temporary)?;
        file.write_all(bytes)?;
        file.sync_all()?;
        drop(file);
        before_rename();
        std::fs::rename(&temporary, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&temporary);
    }
    result
}

fn temporary_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    path.with_file_name(format!(".{name}.{}.tmp", std::process::id()))
}
