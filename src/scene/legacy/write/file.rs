//! Writing an export to disk: mesh paths moved to the file's folder, the text written
//! atomically (a refused export writes nothing).

use std::path::{Path, PathBuf};

use super::super::convert::Dialect;
use super::super::mesh_paths::rebase_mesh_paths;
use super::objects::year;
use super::problem::{CourseExportError, Problem};
use super::scene_text::write_course_scene;
use crate::scene::{Scene, write_atomically};

/// Why an export to a file did not happen.
#[derive(Debug, thiserror::Error)]
pub enum CourseExportFileError {
    /// The dialect cannot say the scene; nothing was written.
    #[error("{path}: not written, the {dialect} framework's dialect cannot say:\n{error}")]
    Refused {
        /// The file that was not written.
        path: PathBuf,
        /// "2016" or "2020".
        dialect: &'static str,
        /// Every refusal (and the warnings).
        error: CourseExportError,
    },
    /// The file could not be written.
    #[error("cannot write {path}: {source}")]
    Write {
        /// The file.
        path: PathBuf,
        /// The operating system's reason.
        source: std::io::Error,
    },
}

/// Writes `scene` (whose file is in `scene_folder`, where its mesh paths start) to
/// `output` in `dialect`, with mesh paths relative to `output`'s folder. Returns the
/// warnings.
///
/// # Errors
/// The refusals (nothing written), or the I/O error.
pub fn export_course_file(
    scene: &Scene,
    scene_folder: &Path,
    output: &Path,
    dialect: Dialect,
) -> Result<Vec<Problem>, CourseExportFileError> {
    let mut scene = scene.clone();
    let output_folder = output.parent().map(Path::to_path_buf).unwrap_or_default();
    rebase_mesh_paths(&mut scene, scene_folder, &output_folder);
    let written =
        write_course_scene(&scene, dialect).map_err(|error| CourseExportFileError::Refused {
            path: output.to_owned(),
            dialect: year(dialect),
            error,
        })?;
    write_atomically(output, written.text.as_bytes()).map_err(|source| {
        CourseExportFileError::Write {
            path: output.to_owned(),
            source,
        }
    })?;
    Ok(written.warnings)
}
