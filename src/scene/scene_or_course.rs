//! Reading a scene file of either kind raylab takes: a RON scene, or a course text scene
//! (told by its content, whatever its name, with [`looks_like_legacy`]) imported on the
//! fly. The editor's File > Open and every command that takes a scene read through
//! [`load_scene_or_course`], so they agree on what a file is.

use std::path::Path;

use super::legacy::{LegacyImport, LegacyImportFileError, import_legacy_file, looks_like_legacy};
use super::{Scene, SceneError, load_scene, read_text_file};

/// A scene file as read.
#[derive(Debug)]
pub enum SceneOrCourse {
    /// A RON scene.
    Ron(Box<Scene>),
    /// A course text scene, imported (with its dialect and warnings).
    Course(Box<LegacyImport>),
}

/// Why a scene file could not be read, in the words of the kind it was read as.
#[derive(Debug, thiserror::Error)]
pub enum SceneOrCourseError {
    /// It was read as a RON scene.
    #[error("{0}")]
    Ron(SceneError),
    /// It was read as a course text scene (the message names the file).
    #[error("{0}")]
    Course(LegacyImportFileError),
}

/// Reads `path` as a course text scene when its content reads like one, else as a RON
/// scene.
///
/// # Errors
/// The loader's or the importer's error; the importer's names the file, the loader's
/// does not (its callers add the name).
pub fn load_scene_or_course(path: &Path) -> Result<SceneOrCourse, SceneOrCourseError> {
    // Text that cannot be read is left to the RON loader, whose errors say why.
    let is_course = read_text_file(path).is_ok_and(|text| looks_like_legacy(&text));
    if is_course {
        import_legacy_file(path)
            .map(|import| SceneOrCourse::Course(Box::new(import)))
            .map_err(SceneOrCourseError::Course)
    } else {
        load_scene(path)
            .map(|scene| SceneOrCourse::Ron(Box::new(scene)))
            .map_err(SceneOrCourseError::Ron)
    }
}
