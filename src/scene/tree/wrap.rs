//! Wrapping nodes into a new group or CSG node (one, or several of one list) and
//! unwrapping a group, with every leaf left where it was in the world.

use glam::DAffine3;

use super::names::unique_name;
use super::path::{object_at, siblings_mut};
use crate::scene::model::Object;
use crate::scene::shape::{CsgOp, Shape};
use crate::scene::transform::{Transform, Trs, rows_from_affine};

/// Puts the node at `path` into a new group (`op` `None`) or CSG node (as its first
/// operand) in its place, and returns the new node's path (the same). The node stands
/// where the object stood, so nothing moves.
///
/// # Errors
/// When the path leads nowhere.
pub fn wrap_node(
    objects: &mut Vec<Object>,
    path: &[usize],
    op: Option<CsgOp>,
) -> Result<Vec<usize>, String> {
    let siblings = siblings_mut(objects, path).ok_or("no such object")?;
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
    Ok(path.to_vec())
}

/// Puts several nodes of one list into a new group or CSG node (the first in `paths`
/// as the first operand) where the first of them stood in the list; nothing moves.
/// Returns the new node's path.
///
/// # Errors
/// When the nodes are not all in one list, or a path leads nowhere.
pub fn wrap_nodes(
    objects: &mut Vec<Object>,
    paths: &[Vec<usize>],
    op: Option<CsgOp>,
) -> Result<Vec<usize>, String> {
    let first = paths.first().ok_or("no such object")?;
    let parent = &first[..first.len() - 1];
    if paths
        .iter()
        .any(|p| p.len() != first.len() || &p[..p.len() - 1] != parent)
    {
        return Err(
            "to combine objects, pick them in one list (all top-level, or all in one node)"
                .to_owned(),
        );
    }
    let picked: Vec<usize> = paths.iter().map(|p| p[p.len() - 1]).collect();
    let siblings = siblings_mut(objects, first).ok_or("no such object")?;
    if picked.iter().any(|&k| k >= siblings.len()) {
        return Err("no such object".to_owned());
    }
    let members: Vec<Object> = picked.iter().map(|&k| siblings[k].clone()).collect();
    let name = unique_name(base_name(op), siblings.iter().map(|o| &o.name));
    let material = members[0].material.clone();
    let shape = node_shape(op, members);
    let at = *picked.iter().min().expect("one or more picked");
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
    Ok([parent, &[at]].concat())
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

/// Puts the group's children at `path` in its place, each placed as it was (the group's
/// transform folded into theirs) and with the material it showed, and returns the path
/// of the first.
///
/// # Errors
/// When the path leads nowhere or not to a group, or the group is empty.
pub fn unwrap_group(objects: &mut Vec<Object>, path: &[usize]) -> Result<Vec<usize>, String> {
    let group = object_at(objects, path).ok_or("no such object")?.clone();
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
    let siblings = siblings_mut(objects, path).ok_or("no such object")?;
    let at = *path.last().expect("a node path is never empty");
    siblings.splice(at..=at, freed);
    Ok(path.to_vec())
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
    Transform::from_affine(&(*outer * inner.world_from_object()))
}

#[cfg(test)]
mod tests {
    use super::super::test_trees::{die_scene, leaf_placements, names};
    use super::*;

    #[test]
    fn wrapping_then_unwrapping_gives_back_the_numbers_typed() {
        let mut scene = die_scene();
        let before = scene.clone();
        let path = wrap_node(&mut scene.objects, &[2], None).unwrap();
        let group = object_at(&scene.objects, &path).unwrap();
        assert!(matches!(group.shape, Shape::Group { .. }));
        assert_eq!(group.name, "group");
        assert_eq!(names(&scene)[6..], ["group", "lamp"]);
        assert_eq!(leaf_placements(&scene), leaf_placements(&before));
        unwrap_group(&mut scene.objects, &path).unwrap();
        assert_eq!(scene, before);
    }

    #[test]
    fn unwrapping_a_turned_scaled_group_leaves_every_leaf_where_it_was() {
        let mut scene = die_scene();
        let before = leaf_placements(&scene);
        let csg = wrap_node(&mut scene.objects, &[1, 1], Some(CsgOp::Union)).unwrap();
        assert_eq!(object_at(&scene.objects, &csg).unwrap().name, "union");
        // The die is a Difference: turn it into a group to unwrap it.
        let die = &mut scene.objects[1];
        let Shape::Csg { operands, .. } = &die.shape else {
            panic!("the die")
        };
        die.shape = Shape::Group {
            children: operands.clone(),
        };
        let first = unwrap_group(&mut scene.objects, &[1]).unwrap();
        assert_eq!(first, [1]);
        assert_eq!(names(&scene)[..3], ["ball", "body", "union"]);
        assert_eq!(
            scene.objects[1].material, "ivory",
            "what it showed, now its own"
        );
        let after = leaf_placements(&scene);
        assert_eq!(after.len(), before.len());
        for ((name, a), (again, b)) in before.iter().zip(&after) {
            assert_eq!(name, again);
            assert!(a.abs_diff_eq(*b, 1e-9), "{name} moved: {a:?} vs {b:?}");
        }
        assert!(
            unwrap_group(&mut scene.objects, &[0]).is_err(),
            "a leaf is no group"
        );
    }

    #[test]
    fn several_nodes_of_one_list_are_wrapped_where_the_first_stood() {
        let mut scene = die_scene();
        let before = leaf_placements(&scene);
        let path = wrap_nodes(
            &mut scene.objects,
            &[vec![2], vec![0]],
            Some(CsgOp::Difference),
        )
        .unwrap();
        assert_eq!(path, [0]);
        let node = &scene.objects[0];
        assert_eq!(node.name, "difference");
        assert_eq!(node.material, "", "the first picked (the lamp) names none");
        assert_eq!(
            names(&scene),
            [
                "difference",
                "lamp",
                "ball",
                "die",
                "body",
                "pips",
                "pip 1",
                "pip 2"
            ]
        );
        let mut after = leaf_placements(&scene);
        let mut sorted = before.clone();
        after.sort_by(|a, b| a.0.cmp(&b.0));
        sorted.sort_by(|a, b| a.0.cmp(&b.0));
        assert_eq!(after, sorted);
        assert!(wrap_nodes(&mut scene.objects, &[vec![1], vec![1, 0]], None).is_err());
    }
}
