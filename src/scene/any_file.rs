//! A scene file as the command line takes it: RON, or a course `.txt` scene imported on
//! the fly, with the mesh files it refers to. `raylab diff`, `render`, `inspect` and
//! `class` read scenes through here, so a scene file means the same to each.

use std::collections::BTreeMap;
use std::path::Path;

use super::mesh_file::{MeshData, read_scene_meshes};
use super::model::Scene;
use super::scene_or_course::{SceneOrCourse, SceneOrCourseError, load_scene_or_course};

/// Reads a RON scene, or imports a course text scene (told by its content, through
/// [`load_scene_or_course`], as the editor and every command do); with the importer's
/// warnings, each naming the file.
///
/// # Errors
/// The loader's message, naming the file.
pub fn load_any_scene(path: &Path) -> Result<(Scene, Vec<String>), String> {
    match load_scene_or_course(path) {
        Ok(SceneOrCourse::Ron(scene)) => Ok((*scene, Vec::new())),
        Ok(SceneOrCourse::Course(import)) => {
            let warnings = import
                .warnings
                .iter()
                .map(|w| format!("{}: {w}", path.display()))
                .collect();
            Ok((import.scene, warnings))
        }
        Err(SceneOrCourseError::Ron(e)) => Err(format!("{}: {e}", path.display())),
        Err(error @ SceneOrCourseError::Course(_)) => Err(error.to_string()),
    }
}

/// The mesh files `scene` (read from `scene_path`) refers to, read from the scene's
/// folder, with the mesh reader's warnings.
///
/// # Errors
/// The first mesh file that cannot be read, named with its object and the scene file.
pub fn read_meshes_beside(
    scene: &Scene,
    scene_path: &Path,
) -> Result<(BTreeMap<String, MeshData>, Vec<String>), String> {
    let folder = scene_path.parent().unwrap_or(Path::new("."));
    let data =
        read_scene_meshes(scene, folder).map_err(|e| format!("{}: {e}", scene_path.display()))?;
    let warnings = data
        .values()
        .flat_map(|mesh| mesh.warnings.iter().cloned())
        .collect();
    Ok((data, warnings))
}
