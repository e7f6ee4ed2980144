//! What the inspector shows: nothing, the camera, the render settings, an object or a
//! part of a tree by path, several of them, a material or a light; and how a selection
//! that points at nothing any more is dropped.

use crate::scene::Scene;
use crate::scene::tree::object_at;

/// What the inspector shows.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub enum Selection {
    /// Nothing selected.
    #[default]
    None,
    /// The camera.
    Camera,
    /// The render settings.
    Render,
    /// A top-level object, by index.
    Object(usize),
    /// A node inside an object tree (a CSG operand, a group's child), by its path of
    /// indices from the top-level object down (two or more; see `Selection::node`).
    Part(Vec<usize>),
    /// Two or more objects or parts (Ctrl+click in the outliner), by path, in the
    /// order picked (see `Selection::several`).
    Several(Vec<Vec<usize>>),
    /// A material, by name.
    Material(String),
    /// A light, by index.
    Light(usize),
}

impl Selection {
    /// The selection of the node at `path`: an object for a top-level path, a part of a
    /// tree below.
    #[must_use]
    pub fn node(path: Vec<usize>) -> Selection {
        match path.as_slice() {
            [index] => Selection::Object(*index),
            _ => Selection::Part(path),
        }
    }

    /// The selection of the nodes at `paths`: several, one, or none.
    #[must_use]
    pub fn several(mut paths: Vec<Vec<usize>>) -> Selection {
        match paths.len() {
            0 => Selection::None,
            1 => Selection::node(paths.remove(0)),
            _ => Selection::Several(paths),
        }
    }

    /// The paths of every selected object or part (one, several or none).
    #[must_use]
    pub fn node_paths(&self) -> Vec<Vec<usize>> {
        match self {
            Selection::Several(paths) => paths.clone(),
            _ => self.node_path().into_iter().collect(),
        }
    }

    /// The path of the selected object or part, if one is selected.
    #[must_use]
    pub fn node_path(&self) -> Option<Vec<usize>> {
        match self {
            Selection::Object(index) => Some(vec![*index]),
            Selection::Part(path) => Some(path.clone()),
            _ => None,
        }
    }
}

/// Drops a selection that no longer points at anything (after undo, open, delete).
pub fn repair_selection(scene: &Scene, selection: &mut Selection) {
    let valid = match selection {
        Selection::Object(i) => *i < scene.objects.len(),
        Selection::Part(path) => object_at(&scene.objects, path).is_some(),
        Selection::Several(paths) => paths.iter().all(|p| object_at(&scene.objects, p).is_some()),
        Selection::Light(i) => *i < scene.lights.len(),
        Selection::Material(name) => scene.materials.contains_key(name),
        Selection::None | Selection::Camera | Selection::Render => true,
    };
    if !valid {
        *selection = Selection::None;
    }
}
