//! The preview worker's meshes: files read and built on the worker (off the UI thread),
//! once each, and kept, so that an edit that touches no mesh compiles with the same
//! meshes and the hit cache re-shades instead of re-tracing.

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Arc;

use super::PreviewRequest;
use crate::scene::{load_obj, mesh_file::mesh_path, mesh_objects};
use crate::trace::{MeshStore, TriangleMesh};

/// Built meshes by file, kept across requests.
#[derive(Default)]
pub(super) struct MeshCache {
    by_file: HashMap<PathBuf, Arc<TriangleMesh>>,
}

impl MeshCache {
    /// The meshes for `request`: those it carries, else read from its scene's folder
    /// (or from the cache).
    ///
    /// # Errors
    /// A file that cannot be read, named with its object; or a mesh object whose path
    /// is relative in a scene that has no folder yet (never saved).
    pub(super) fn for_request(&mut self, request: &PreviewRequest) -> Result<MeshStore, String> {
        let mut store = (*request.meshes).clone();
        for (object, path) in mesh_objects(&request.scene) {
            if store.get(path).is_some() {
                continue;
            }
            // A path in full (a mesh imported into a scene never saved) needs no folder.
            let file = match &request.scene_folder {
                _ if std::path::Path::new(path).is_absolute() => PathBuf::from(path),
                Some(folder) => mesh_path(folder, path),
                None => {
                    return Err(format!(
                        "object \"{}\": save the scene first, so that \"{path}\" can be found beside it",
                        object.name
                    ));
                }
            };
            let mesh = match self.by_file.get(&file) {
                Some(mesh) => Arc::clone(mesh),
                None => {
                    let data =
                        load_obj(&file).map_err(|e| format!("object \"{}\": {e}", object.name))?;
                    let mesh = Arc::new(TriangleMesh::new(&data));
                    self.by_file.insert(file, Arc::clone(&mesh));
                    mesh
                }
            };
            store.insert(path.to_owned(), mesh);
        }
        Ok(store)
    }
}
