//! Edits of object trees by node path: selections of nodes, replace a node, add an
//! operand, and delete or duplicate a node inside a tree (wrapping and unwrapping are
//! in `tree_wrap`, moves in `tree_move`). The selection follows the node edited.

use super::scene_edit::unique_name;
use super::{Selection, placement};
use crate::scene::tree_path::{object_at, object_at_mut, siblings_mut};
use crate::scene::{CsgOp, Object, Scene, Shape, Transform, Trs};

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

/// Replaces the node at `path`.
pub(super) fn set_node(scene: &mut Scene, path: &[usize], node: Object) -> Result<(), String> {
    *object_at_mut(&mut scene.objects, path).ok_or("no such object")? = node;
    Ok(())
}

/// Adds a unit shape as the last operand (or child) of the selected tree node, placed
/// beside its first operand (see `beside_first`), and selects it.
pub(super) fn add_operand(
    scene: &mut Scene,
    selection: &mut Selection,
    shape: Shape,
) -> Result<(), String> {
    let path = selection
        .node_path()
        .ok_or("select a CSG node or a group")?;
    let node = object_at_mut(&mut scene.objects, &path).ok_or("no such object")?;
    let name = unique_name(shape.name(), node.shape.children().iter().map(|o| &o.name));
    let children = node
        .shape
        .children_mut()
        .ok_or_else(|| format!("\u{201c}{}\u{201d} is not a CSG node or a group", node.name))?;
    let transform = beside_first(children.first());
    children.push(Object {
        name,
        shape,
        transform,
        // Inherits the node's material.
        material: String::new(),
    });
    let mut child = path;
    child.push(children.len() - 1);
    *selection = Selection::Part(child);
    Ok(())
}

/// Where a new operand goes: half the size of the node's first operand, centred on that
/// one's +x face, so it shows at once (a bite of a Difference, a bump of a Union);
/// unit size at the origin in an empty node.
fn beside_first(first: Option<&Object>) -> Transform {
    let Some(Transform::Trs(first)) = first.map(|o| &o.transform) else {
        return Transform::Trs(Trs::default());
    };
    let size = first.scale.abs().element_sum() / 3.0;
    let face = first.world_from_object().transform_point3(glam::DVec3::X);
    Transform::Trs(Trs {
        translate: face,
        rotate_deg: glam::DVec3::ZERO,
        scale: glam::DVec3::splat(size * 0.5),
    })
}

/// Deletes the selected part of a tree (a CSG node keeps at least one operand), and
/// selects its neighbour, or its parent if it was the only one.
pub(super) fn delete_part(
    scene: &mut Scene,
    path: &[usize],
    selection: &mut Selection,
) -> Result<(), String> {
    let parent = object_at(&scene.objects, &path[..path.len() - 1]).ok_or("no such object")?;
    if matches!(parent.shape, Shape::Csg { .. }) && parent.shape.children().len() == 1 {
        return Err(format!(
            "\u{201c}{}\u{201d} needs at least one operand; delete the CSG node instead",
            parent.name
        ));
    }
    let siblings = siblings_mut(&mut scene.objects, path).ok_or("no such object")?;
    let at = *path.last().expect("a part's path has two indices or more");
    if at >= siblings.len() {
        return Err("no such object".to_owned());
    }
    siblings.remove(at);
    let mut next = path.to_vec();
    if siblings.is_empty() {
        next.pop();
    } else {
        *next.last_mut().expect("not empty") = at.min(siblings.len() - 1);
    }
    *selection = Selection::node(next);
    Ok(())
}

/// Duplicates the selected part of a tree beside it (moved aside, so both are seen),
/// and selects the copy.
pub(super) fn duplicate_part(
    scene: &mut Scene,
    path: &[usize],
    selection: &mut Selection,
) -> Result<(), String> {
    let original = object_at(&scene.objects, path).ok_or("no such object")?;
    let mut copy = original.clone();
    let offset = placement::duplicate_offset(scene, &copy.shape, &copy.transform);
    copy.transform = placement::moved(&copy.transform, offset);
    let siblings = siblings_mut(&mut scene.objects, path).ok_or("no such object")?;
    copy.name = unique_name(&copy.name, siblings.iter().map(|o| &o.name));
    let at = *path.last().expect("a part's path has two indices or more");
    siblings.insert(at + 1, copy);
    let mut next = path.to_vec();
    *next.last_mut().expect("not empty") = at + 1;
    *selection = Selection::Part(next);
    Ok(())
}

/// Whether a path still leads to a node of `scene`.
#[must_use]
pub fn part_exists(scene: &Scene, path: &[usize]) -> bool {
    object_at(&scene.objects, path).is_some()
}

/// The operators offered for a CSG node, with a line on what each keeps.
pub const CSG_OPS: [(CsgOp, &str); 3] = [
    (CsgOp::Union, "inside any operand"),
    (CsgOp::Intersection, "inside every operand"),
    (
        CsgOp::Difference,
        "inside the first operand and none of the others",
    ),
];

#[cfg(test)]
#[path = "tree_edit_tests.rs"]
mod tests;
