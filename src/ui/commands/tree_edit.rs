//! Edits of object trees by node path: replace a node, group a node, ungroup a group,
//! add an operand, and delete or duplicate a node inside a tree. The selection follows
//! the node edited.

use glam::DAffine3;

use super::scene_edit::unique_name;
use super::{Selection, placement};
use crate::gizmo::trs::trs_from_matrix;
use crate::scene::tree_path::{
    effective_material, object_at, object_at_mut, siblings_mut, world_from_parent,
};
use crate::scene::{CsgOp, Object, Scene, Shape, Transform, Trs, rows_from_affine};

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

/// Puts the selected node into a new group (`op` `None`) or CSG node (as its first
/// operand) in its place, at the identity so nothing moves, and selects the new node.
pub(super) fn wrap_selected(
    scene: &mut Scene,
    selection: &mut Selection,
    op: Option<CsgOp>,
) -> Result<(), String> {
    if let Selection::Several(paths) = selection.clone() {
        return combine(scene, selection, &paths, op);
    }
    let path = selection.node_path().ok_or("select an object first")?;
    let siblings = siblings_mut(&mut scene.objects, &path).ok_or("no such object")?;
    let at = *path.last().expect("a node path is never empty");
    let node = siblings.get(at).ok_or("no such object")?.clone();
    let (base, shape) = match op {
        None => (
            "group",
            Shape::Group {
                children: vec![node.clone()],
            },
        ),
        Some(op) => (
            match op {
                CsgOp::Union => "union",
                CsgOp::Intersection => "intersection",
                CsgOp::Difference => "difference",
            },
            Shape::Csg {
                op,
                operands: vec![node.clone()],
            },
        ),
    };
    let name = unique_name(base, siblings.iter().map(|o| &o.name));
    // The new node stands where the object stood (its gizmo there, operands added at
    // its centre), the object at the node's origin: the product is the same transform.
    let (outer, inner) = split_translation(&node.transform);
    let mut shape = shape;
    if let Some(children) = shape.children_mut() {
        children[0].transform = inner;
    }
    // The new node keeps the object's material, so what is added to it inherits that.
    siblings[at] = Object {
        name,
        shape,
        transform: outer,
        material: node.material,
    };
    *selection = Selection::node(path);
    Ok(())
}

/// Puts several nodes of one parent into a new group or CSG node (the first picked as
/// the first operand) where the first of them stood in the list; nothing moves. Selects
/// the new node.
fn combine(
    scene: &mut Scene,
    selection: &mut Selection,
    paths: &[Vec<usize>],
    op: Option<CsgOp>,
) -> Result<(), String> {
    let parent = &paths[0][..paths[0].len() - 1];
    if paths
        .iter()
        .any(|p| p.len() != paths[0].len() || &p[..p.len() - 1] != parent)
    {
        return Err(
            "to combine objects, pick them in one list (all top-level, or all in one node)"
                .to_owned(),
        );
    }
    let picked: Vec<usize> = paths.iter().map(|p| p[p.len() - 1]).collect();
    let siblings = siblings_mut(&mut scene.objects, &paths[0]).ok_or("no such object")?;
    if picked.iter().any(|&k| k >= siblings.len()) {
        return Err("no such object".to_owned());
    }
    let members: Vec<Object> = picked.iter().map(|&k| siblings[k].clone()).collect();
    let base = match op {
        None => "group",
        Some(CsgOp::Union) => "union",
        Some(CsgOp::Intersection) => "intersection",
        Some(CsgOp::Difference) => "difference",
    };
    let name = unique_name(base, siblings.iter().map(|o| &o.name));
    let material = members[0].material.clone();
    let shape = match op {
        None => Shape::Group { children: members },
        Some(op) => Shape::Csg {
            op,
            operands: members,
        },
    };
    let at = *picked.iter().min().expect("two or more picked");
    let mut gone = picked.clone();
    gone.sort_unstable();
    for &k in gone.iter().rev() {
        siblings.remove(k);
    }
    siblings.insert(
        at,
        Object {
            name,
            shape,
            transform: Transform::Trs(Trs::default()),
            material,
        },
    );
    *selection = Selection::node([parent, &[at]].concat());
    Ok(())
}

/// A transform as a translation, and what is left of it at the origin.
fn split_translation(transform: &Transform) -> (Transform, Transform) {
    match transform {
        Transform::Trs(trs) => (
            Transform::Trs(Trs {
                translate: trs.translate,
                ..Trs::default()
            }),
            Transform::Trs(Trs {
                translate: glam::DVec3::ZERO,
                ..*trs
            }),
        ),
        Transform::Matrix(_) => {
            let mut affine = transform.world_from_object();
            let translate = affine.translation;
            affine.translation = glam::DVec3::ZERO;
            (
                Transform::Trs(Trs {
                    translate,
                    ..Trs::default()
                }),
                Transform::Matrix(rows_from_affine(&affine)),
            )
        }
    }
}

/// Puts the selected group's children in its place, each placed as it was (the group's
/// transform folded into theirs) and with the material it showed, and selects the first.
pub(super) fn ungroup_selected(scene: &mut Scene, selection: &mut Selection) -> Result<(), String> {
    let path = selection.node_path().ok_or("select a group to ungroup")?;
    let group = object_at(&scene.objects, &path)
        .ok_or("no such object")?
        .clone();
    let Shape::Group { children } = &group.shape else {
        return Err(format!("\u{201c}{}\u{201d} is not a group", group.name));
    };
    if children.is_empty() {
        return Err(format!(
            "group \u{201c}{}\u{201d} has nothing to ungroup",
            group.name
        ));
    }
    let outer = group.transform.world_from_object();
    let freed: Vec<Object> = children
        .iter()
        .map(|child| {
            let mut child = child.clone();
            child.transform = folded(&outer, &child.transform);
            if child.material.is_empty() {
                child.material.clone_from(&group.material);
            }
            child
        })
        .collect();
    let siblings = siblings_mut(&mut scene.objects, &path).ok_or("no such object")?;
    let at = *path.last().expect("a node path is never empty");
    siblings.splice(at..=at, freed);
    *selection = Selection::node(path);
    Ok(())
}

/// `outer` applied after `inner`: as scale, rotation and translation where that holds
/// the product exactly (to rounding), else as a matrix.
fn folded(outer: &DAffine3, inner: &Transform) -> Transform {
    if *outer == DAffine3::IDENTITY {
        return *inner;
    }
    // A node that only moves its children (as a fresh group does): add the offset, so
    // grouping and ungrouping give back exactly the numbers typed.
    if let Transform::Trs(trs) = inner
        && outer.matrix3 == glam::DMat3::IDENTITY
    {
        return Transform::Trs(Trs {
            translate: trs.translate + outer.translation,
            ..*trs
        });
    }
    as_transform(&(*outer * inner.world_from_object()))
}

/// A placement as scale, rotation and translation where that holds it exactly (to
/// rounding), else as a matrix (a shear).
fn as_transform(affine: &DAffine3) -> Transform {
    let trs = trs_from_matrix(affine);
    let again = trs.world_from_object();
    let tolerance = 1e-9 * (1.0 + affine.translation.abs().max_element());
    if again.abs_diff_eq(*affine, tolerance) {
        Transform::Trs(trs)
    } else {
        Transform::Matrix(rows_from_affine(affine))
    }
}

/// Adds a unit shape as the last operand (or child) of the selected tree node, placed
/// at the node's origin, and selects it.
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

/// Moves the node at `from` into the tree node at `onto` (as its last child or
/// operand), or beside `onto` when that is a leaf (right after it), keeping where it is
/// in the world and the material it shows; one edit, one undo step. Selects it there.
pub(super) fn move_node(
    scene: &mut Scene,
    selection: &mut Selection,
    from: &[usize],
    onto: &[usize],
) -> Result<(), String> {
    if onto.starts_with(from) {
        return Err("a node cannot go inside itself".to_owned());
    }
    let target = object_at(&scene.objects, onto).ok_or("no such object")?;
    let (parent, index) = if target.shape.is_tree_node() {
        (onto.to_vec(), target.shape.children().len())
    } else {
        (onto[..onto.len() - 1].to_vec(), onto[onto.len() - 1] + 1)
    };
    let (old_parent, old_index) = from.split_at(from.len() - 1);
    if !old_parent.is_empty()
        && let Some(holder) = object_at(&scene.objects, old_parent)
        && matches!(holder.shape, Shape::Csg { .. })
        && holder.shape.children().len() == 1
    {
        return Err(format!(
            "\u{201c}{}\u{201d} needs at least one operand",
            holder.name
        ));
    }
    let mut node = object_at(&scene.objects, from)
        .ok_or("no such object")?
        .clone();
    // Same place in the world, same material, under the new parent.
    let world = world_from_parent(&scene.objects, from) * node.transform.world_from_object();
    let new_parent_world = match parent.as_slice() {
        [] => DAffine3::IDENTITY,
        _ => {
            world_from_parent(&scene.objects, &parent)
                * object_at(&scene.objects, &parent)
                    .ok_or("no such object")?
                    .transform
                    .world_from_object()
        }
    };
    let shown = effective_material(&scene.objects, from).map(str::to_owned);
    let inherited = effective_material(&scene.objects, &parent).map(str::to_owned);
    if node.material.is_empty() && (parent.is_empty() || shown != inherited) {
        node.material = shown.unwrap_or_default();
    }
    // Keep the numbers typed where the new parent places it as the old one did.
    if !new_parent_world.abs_diff_eq(world_from_parent(&scene.objects, from), 0.0) {
        node.transform = as_transform(&(new_parent_world.inverse() * world));
    }
    // Take it out, then find the destination again: taking it out shifts the indices
    // after it among its old siblings (and under them).
    let mut destination = parent.clone();
    let depth = old_parent.len();
    if destination.len() > depth
        && destination[..depth] == *old_parent
        && destination[depth] > old_index[0]
    {
        destination[depth] -= 1;
    }
    let mut index = index;
    if destination == old_parent && index > old_index[0] {
        index -= 1;
    }
    siblings_mut(&mut scene.objects, from)
        .ok_or("no such object")?
        .remove(old_index[0]);
    let list = match destination.as_slice() {
        [] => &mut scene.objects,
        _ => object_at_mut(&mut scene.objects, &destination)
            .and_then(|o| o.shape.children_mut())
            .ok_or("no such object")?,
    };
    let index = index.min(list.len());
    list.insert(index, node);
    destination.push(index);
    *selection = Selection::node(destination);
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
