//! A scene file as the command line takes it: RON, or a course `.txt` scene imported on
//! the fly, with the mesh files it refers to. `raylab diff`, `render`, `inspect` and
//! `class` read scenes through here, so a scene file means the same to each.

use std::collections::BTreeMap;
use std::path::Path;

use super::file::load_scene;
use super::legacy::import_legacy_file;
use super::mesh_file::{MeshData, read_scene_meshes};
use super::model::Scene;

/// Reads a RON scene, or imports a course `.txt` scene (by its extension); with the
/// importer's warnings, each naming the file.
///
/// # Errors
/// The loader's message, naming the file.
pub fn load_any_scene(path: &Path) -> Result<(Scene, Vec<String>), String> {
    if path
        .extension()
        .is_some_and(|x| x.eq_ignore_ascii_case("txt"))
    {
        let import = import_legacy_file(path).map_err(|e| e.to_string())?;
        let warnings = import
            .warnings
            .iter()
            .map(|w| format!("{}: {w}", path.display()))
            .collect();
        Ok((import.scene, warnings))
    } else {
        let scene = load_scene(path).map_err(|e| format!("{}: {e}", path.display()))?;
        Ok((scene, Vec::new()))
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
