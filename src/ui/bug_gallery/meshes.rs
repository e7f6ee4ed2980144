//! The meshes a gallery is rendered with: read from the scene's folder as the preview
//! reads them (a path in full needs no folder; a relative one needs a saved scene).

use std::collections::BTreeMap;
use std::path::Path;

use crate::scene::{Scene, load_obj, mesh_file::mesh_path, mesh_objects};
use crate::trace::MeshStore;

/// Reads and builds the meshes of `scene`, whose file is in `folder` (none: never saved).
/// Runs on the gallery's thread, never the UI's.
///
/// # Errors
/// A file that cannot be read, or a relative path in a scene that has no folder, named
/// with its object.
pub fn read_meshes(scene: &Scene, folder: Option<&Path>) -> Result<MeshStore, String> {
    let mut data = BTreeMap::new();
    for (object, path) in mesh_objects(scene) {
        if data.contains_key(path) {
            continue;
        }
        let file = match folder {
            _ if Path::new(path).is_absolute() => Path::new(path).to_owned(),
            Some(folder) => mesh_path(folder, path),
            None => {
                return Err(format!(
                    "object \"{}\": save the scene first, so that \"{path}\" can be found beside it",
                    object.name
                ));
            }
        };
        let mesh = load_obj(&file).map_err(|e| format!("object \"{}\": {e}", object.name))?;
        data.insert(path.to_owned(), mesh);
    }
    Ok(MeshStore::build(&data))
}
