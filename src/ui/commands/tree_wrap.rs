//! Wrapping nodes into a new group or CSG node (one, or several of one list) and
//! unwrapping a group, with every leaf left where it was in the world.

use glam::DAffine3;

use super::Selection;
use super::scene_edit::unique_name;
use crate::gizmo::trs::trs_from_matrix;
use crate::scene::tree_path::{object_at, siblings_mut};
use crate::scene::{CsgOp, Object, Scene, Shape, Transform, Trs, rows_from_affine};

/// Puts the selected node into a new group (`op` `None`) or CSG node (as its first
/// operand) in its place, and selects the new node. The node stands where the object
/// stood, so nothing moves.
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
    let mut member = siblings.get(at).ok_or("no such object")?.clone();
    // The new node stands where the object stood (its gizmo there, operands added at
    // its centre), the object at the node's origin: the product is the same transform.
    let (outer, inner) = split_translation(&member.transform);
    member.transform = inner;
    // The new node keeps the object's material, so what is added to it inherits that.
    let material = member.material.clone();
    siblings[at] = Object {
        name: unique_name(base_name(op), siblings.iter().map(|o| &o.name)),
        shape: node_shape(op, vec![member]),
        transform: outer,
        material,
    };
    *selection = Selection::node(path);
    Ok(())
}

/// The name a new node starts from: "group", "union", "intersection", "difference".
fn base_name(op: Option<CsgOp>) -> &'static str {
    match op {
        None => "group",
        Some(CsgOp::Union) => "union",
        Some(CsgOp::Intersection) => "intersection",
        Some(CsgOp::Difference) => "difference",
    }
}

/// A group of `members`, or a CSG node of `op` with them as operands.
fn node_shape(op: Option<CsgOp>, members: Vec<Object>) -> Shape {
    match op {
        None => Shape::Group { children: members },
        Some(op) => Shape::Csg {
            op,
            operands: members,
        },
    }
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
    let name = unique_name(base_name(op), siblings.iter().map(|o| &o.name));
    let material = members[0].material.clone();
    let shape = node_shape(op, members);
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
pub(super) fn as_transform(affine: &DAffine3) -> Transform {
    let trs = trs_from_matrix(affine);
    let again = trs.world_from_object();
    let tolerance = 1e-9 * (1.0 + affine.translation.abs().max_element());
    if again.abs_diff_eq(*affine, tolerance) {
        Transform::Trs(trs)
    } else {
        Transform::Matrix(rows_from_affine(affine))
    }
}
