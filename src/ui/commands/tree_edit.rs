//! Edits of object trees by node path: replace a node, group a node, ungroup a group,
//! add an operand, and delete or duplicate a node inside a tree. The selection follows
//! the node edited.

use glam::DAffine3;

use super::scene_edit::unique_name;
use super::{Selection, placement};
use crate::gizmo::trs::trs_from_matrix;
use crate::scene::tree_path::{object_at, object_at_mut, siblings_mut};
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

/// Puts the selected node into a new group in its place (the group at the identity, so
/// nothing moves), and selects the group.
pub(super) fn group_selected(scene: &mut Scene, selection: &mut Selection) -> Result<(), String> {
    let path = selection.node_path().ok_or("select an object to group")?;
    let siblings = siblings_mut(&mut scene.objects, &path).ok_or("no such object")?;
    let at = *path.last().expect("a node path is never empty");
    let node = siblings.get(at).ok_or("no such object")?.clone();
    let name = unique_name("group", siblings.iter().map(|o| &o.name));
    // A top-level group keeps the node's material, so its children can inherit it.
    let material = node.material.clone();
    siblings[at] = Object {
        name,
        shape: Shape::Group {
            children: vec![node],
        },
        transform: Transform::Trs(Trs::default()),
        material,
    };
    *selection = Selection::node(path);
    Ok(())
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
    let product = *outer * inner.world_from_object();
    let trs = trs_from_matrix(&product);
    let again = trs.world_from_object();
    if again.abs_diff_eq(
        product,
        1e-9 * (1.0 + product.translation.abs().max_element()),
    ) {
        Transform::Trs(trs)
    } else {
        Transform::Matrix(rows_from_affine(&product))
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
    children.push(Object {
        name,
        shape,
        transform: Transform::Trs(Trs::default()),
        // Inherits the node's material.
        material: String::new(),
    });
    let mut child = path;
    child.push(children.len() - 1);
    *selection = Selection::Part(child);
    Ok(())
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
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::scene::tree_path::world_from_parent;
    use crate::ui::commands::SceneEdit;

    /// The CSG example scene: its die is rotated, scaled and holds a nested node.
    fn csg_scene() -> Scene {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/csg.ron");
        crate::scene::load_scene(&path).expect("example")
    }

    fn die(scene: &Scene) -> usize {
        scene
            .objects
            .iter()
            .position(|o| o.name == "die")
            .expect("die")
    }

    /// Where each leaf of the scene is, in the world.
    fn leaf_placements(scene: &Scene) -> Vec<(String, DAffine3)> {
        let mut out = Vec::new();
        let mut work: Vec<(Vec<usize>, &Object)> = scene
            .objects
            .iter()
            .enumerate()
            .map(|(i, o)| (vec![i], o))
            .collect();
        while let Some((path, object)) = work.pop() {
            let children = object.shape.children();
            if children.is_empty() {
                let world =
                    world_from_parent(&scene.objects, &path) * object.transform.world_from_object();
                out.push((object.name.clone(), world));
            }
            for (k, child) in children.iter().enumerate() {
                let mut p = path.clone();
                p.push(k);
                work.push((p, child));
            }
        }
        out.sort_by(|a, b| a.0.cmp(&b.0));
        out
    }

    #[test]
    fn grouping_then_ungrouping_a_moved_group_leaves_every_leaf_where_it_was() {
        let mut scene = csg_scene();
        let before = leaf_placements(&scene);
        let mut selection = Selection::Object(die(&scene));
        SceneEdit::GroupSelected
            .apply(&mut scene, &mut selection)
            .unwrap();
        let group_path = selection.node_path().unwrap();
        let group = object_at(&scene.objects, &group_path).unwrap();
        assert!(matches!(group.shape, Shape::Group { .. }), "{selection:?}");
        assert_eq!(leaf_placements(&scene), before, "grouping moves nothing");
        // Move and turn the group; its leaves go with it.
        let mut moved = group.clone();
        moved.transform = Transform::Trs(Trs {
            translate: DVec3::new(1.0, 0.5, -2.0),
            rotate_deg: DVec3::new(0.0, 40.0, 10.0),
            scale: DVec3::splat(1.5),
        });
        SceneEdit::SetObject(group_path[0], moved)
            .apply(&mut scene, &mut selection)
            .unwrap();
        let grouped = leaf_placements(&scene);
        SceneEdit::UngroupSelected
            .apply(&mut scene, &mut selection)
            .unwrap();
        let die = object_at(&scene.objects, &selection.node_path().unwrap()).unwrap();
        assert_eq!(die.name, "die");
        assert!(
            matches!(die.transform, Transform::Trs(_)),
            "a uniform scale stays TRS"
        );
        for ((name, a), (_, b)) in grouped.iter().zip(leaf_placements(&scene)) {
            assert!(a.abs_diff_eq(b, 1e-9), "{name} moved: {a:?} against {b:?}");
        }
    }

    #[test]
    fn ungrouping_a_non_uniformly_scaled_group_of_a_turned_child_keeps_it_as_a_matrix() {
        let mut scene = csg_scene();
        let mut selection = Selection::Object(die(&scene));
        SceneEdit::GroupSelected
            .apply(&mut scene, &mut selection)
            .unwrap();
        let index = selection.node_path().unwrap()[0];
        if let Transform::Trs(trs) = &mut scene.objects[index].transform {
            trs.scale = DVec3::new(2.0, 1.0, 1.0);
        }
        let grouped = leaf_placements(&scene);
        SceneEdit::UngroupSelected
            .apply(&mut scene, &mut selection)
            .unwrap();
        let die = &scene.objects[index];
        // A sheared product has no scale-rotate-translate form.
        assert!(matches!(die.transform, Transform::Matrix(_)));
        for ((name, a), (_, b)) in grouped.iter().zip(leaf_placements(&scene)) {
            assert!(a.abs_diff_eq(b, 1e-9), "{name} moved");
        }
    }

    #[test]
    fn parts_are_added_duplicated_and_deleted_in_place_and_a_csg_keeps_one_operand() {
        let mut scene = csg_scene();
        let die = die(&scene);
        let operands = scene.objects[die].shape.children().len();
        let mut selection = Selection::Object(die);
        SceneEdit::AddOperand(Shape::Cube)
            .apply(&mut scene, &mut selection)
            .unwrap();
        assert_eq!(selection, Selection::Part(vec![die, operands]));
        let added = object_at(&scene.objects, &[die, operands]).unwrap();
        assert_eq!((added.name.as_str(), added.material.as_str()), ("Cube", ""));
        SceneEdit::DuplicateSelected
            .apply(&mut scene, &mut selection)
            .unwrap();
        assert_eq!(selection, Selection::Part(vec![die, operands + 1]));
        assert_eq!(
            object_at(&scene.objects, &[die, operands + 1])
                .unwrap()
                .name,
            "Cube 2"
        );
        SceneEdit::DeleteSelected
            .apply(&mut scene, &mut selection)
            .unwrap();
        SceneEdit::DeleteSelected
            .apply(&mut scene, &mut selection)
            .unwrap();
        assert_eq!(scene.objects[die].shape.children().len(), operands);
        // A CSG node of one operand keeps it.
        let lens = scene.objects.iter().position(|o| o.name == "lens").unwrap();
        let mut selection = Selection::Part(vec![lens, 0]);
        SceneEdit::DeleteSelected
            .apply(&mut scene, &mut selection)
            .unwrap();
        let mut selection = Selection::Part(vec![lens, 0]);
        let error = SceneEdit::DeleteSelected
            .apply(&mut scene, &mut selection)
            .unwrap_err();
        assert!(error.contains("at least one operand"), "{error}");
    }

    #[test]
    fn a_material_used_only_inside_a_tree_is_not_deleted_and_renames_reach_inside() {
        let mut scene = csg_scene();
        let mut selection = Selection::Material("pip".to_owned());
        let error = SceneEdit::DeleteSelected
            .apply(&mut scene, &mut selection)
            .unwrap_err();
        assert!(error.contains("pip"), "{error}");
        SceneEdit::RenameMaterial {
            from: "pip".to_owned(),
            to: "dot".to_owned(),
        }
        .apply(&mut scene, &mut selection)
        .unwrap();
        crate::scene::validate(&scene).expect("every reference renamed");
        let die = die(&scene);
        assert_eq!(
            object_at(&scene.objects, &[die, 1]).unwrap().material,
            "dot"
        );
    }
}
