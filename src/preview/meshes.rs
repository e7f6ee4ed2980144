//! The preview worker's meshes: files read and built on the worker (off the UI thread),
//! once each, and kept, so that an edit that touches no mesh compiles with the same
//! meshes and the hit cache re-shades instead of re-tracing. Each read reports its
//! progress through a [`LoadWatch`] that the editor shows, with a cancel button.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::PreviewRequest;
use crate::scene::{LoadWatch, Scene, load_obj_watched, mesh_file::mesh_path, mesh_objects};
use crate::trace::shapes::Aabb;
use crate::trace::{MeshStore, TriangleMesh};

/// What the editor shows of a mesh the preview has read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshFacts {
    /// Its triangles.
    pub triangles: usize,
    /// Its box in object space.
    pub bounds: Aabb,
    /// Whether it bounds a solid (so it may be a CSG operand).
    pub closed: bool,
}

impl MeshFacts {
    /// The facts of a built mesh.
    #[must_use]
    pub fn of(mesh: &TriangleMesh) -> Self {
        Self {
            triangles: mesh.triangle_count(),
            bounds: mesh.bounds(),
            closed: mesh.is_closed(),
        }
    }
}

/// Built meshes by file, kept across requests. The preview worker and the Export PNG
/// job both read a scene's meshes through [`MeshCache::read`], so a scene that previews
/// also exports.
#[derive(Default)]
pub struct MeshCache {
    by_file: HashMap<PathBuf, Arc<TriangleMesh>>,
}

impl MeshCache {
    /// The meshes for `request`: those it carries, else read from its scene's folder
    /// (or from the cache), as [`MeshCache::read`].
    ///
    /// # Errors
    /// As [`MeshCache::read`].
    pub(super) fn for_request(
        &mut self,
        request: &PreviewRequest,
        watch_read: &mut dyn FnMut(&str) -> Arc<LoadWatch>,
    ) -> Result<MeshStore, String> {
        self.read(
            &request.scene,
            request.scene_folder.as_deref(),
            &request.meshes,
            watch_read,
        )
    }

    /// The meshes `scene` refers to: those in `carried`, else read from `folder` (the
    /// scene file's; a path in full needs none) or taken from the cache. Each file read
    /// is announced to `watch_read` (with the path as the scene writes it), which hands
    /// back the watch to report to.
    ///
    /// # Errors
    /// A file that cannot be read (or whose reading was cancelled), named with its
    /// object; or a mesh object whose path is relative in a scene that has no folder
    /// yet (never saved).
    pub fn read(
        &mut self,
        scene: &Scene,
        folder: Option<&Path>,
        carried: &MeshStore,
        watch_read: &mut dyn FnMut(&str) -> Arc<LoadWatch>,
    ) -> Result<MeshStore, String> {
        let mut store = carried.clone();
        for (object, path) in mesh_objects(scene) {
            if store.get(path).is_some() {
                continue;
            }
            // A path in full (a mesh imported into a scene never saved) needs no folder.
            let file = match folder {
                _ if Path::new(path).is_absolute() => PathBuf::from(path),
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
                    let watch = watch_read(path);
                    let data = load_obj_watched(&file, &watch).map_err(|e| {
                        let mut message = format!("object \"{}\": {e}", object.name);
                        if watch.is_cancelled() {
                            message.push_str(
                                " (undo removes the object; any other edit reads the file again)",
                            );
                        }
                        message
                    })?;
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
