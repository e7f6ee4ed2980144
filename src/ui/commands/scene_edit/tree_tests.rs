//! Tree edits: group and ungroup (nothing moves), booleans, parts added, duplicated and
//! deleted in place, and materials named inside trees.

use glam::{DAffine3, DVec3};

use super::*;
use crate::scene::tree::world_from_parent;
use crate::scene::{Transform, Trs};

/// The CSG example scene: its die is rotated, scaled and holds a nested node.
fn csg_scene() -> Scene {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/csg.ron");
    crate::scene::load_scene(&path).expect("example")
}

/// Where the top-level object named `name` is in the scene's list.
fn index_of(scene: &Scene, name: &str) -> usize {
    scene
        .objects
        .iter()
        .position(|o| o.name == name)
        .unwrap_or_else(|| panic!("no {name}"))
}

fn die(scene: &Scene) -> usize {
    index_of(scene, "die")
}

/// Applies `edit`, which must succeed.
fn apply(edit: SceneEdit, scene: &mut Scene, selection: &mut Selection) {
    edit.apply(scene, selection).unwrap();
}

/// Applies `edit`, which must be refused with a message that says `why`.
fn assert_refused(edit: SceneEdit, scene: &mut Scene, selection: &mut Selection, why: &str) {
    let error = edit.apply(scene, selection).unwrap_err();
    assert!(error.contains(why), "{error}");
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
    apply(SceneEdit::GroupSelected, &mut scene, &mut selection);
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
    apply(
        SceneEdit::SetObject(group_path[0], moved),
        &mut scene,
        &mut selection,
    );
    let grouped = leaf_placements(&scene);
    apply(SceneEdit::UngroupSelected, &mut scene, &mut selection);
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
    apply(SceneEdit::GroupSelected, &mut scene, &mut selection);
    let index = selection.node_path().unwrap()[0];
    if let Transform::Trs(trs) = &mut scene.objects[index].transform {
        trs.scale = DVec3::new(2.0, 1.0, 1.0);
    }
    let grouped = leaf_placements(&scene);
    apply(SceneEdit::UngroupSelected, &mut scene, &mut selection);
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
    apply(
        SceneEdit::AddOperand(Shape::Cube),
        &mut scene,
        &mut selection,
    );
    assert_eq!(selection, Selection::Part(vec![die, operands]));
    let added = object_at(&scene.objects, &[die, operands]).unwrap();
    assert_eq!((added.name.as_str(), added.material.as_str()), ("Cube", ""));
    apply(SceneEdit::DuplicateSelected, &mut scene, &mut selection);
    assert_eq!(selection, Selection::Part(vec![die, operands + 1]));
    assert_eq!(
        object_at(&scene.objects, &[die, operands + 1])
            .unwrap()
            .name,
        "Cube 2"
    );
    apply(SceneEdit::DeleteSelected, &mut scene, &mut selection);
    apply(SceneEdit::DeleteSelected, &mut scene, &mut selection);
    assert_eq!(scene.objects[die].shape.children().len(), operands);
    // A CSG node of one operand keeps it.
    let lens = index_of(&scene, "lens");
    let mut selection = Selection::Part(vec![lens, 0]);
    apply(SceneEdit::DeleteSelected, &mut scene, &mut selection);
    let mut selection = Selection::Part(vec![lens, 0]);
    assert_refused(
        SceneEdit::DeleteSelected,
        &mut scene,
        &mut selection,
        "at least one operand",
    );
}

#[test]
fn a_material_used_only_inside_a_tree_is_not_deleted_and_renames_reach_inside() {
    let mut scene = csg_scene();
    let mut selection = Selection::Material("pip".to_owned());
    assert_refused(SceneEdit::DeleteSelected, &mut scene, &mut selection, "pip");
    apply(
        SceneEdit::RenameMaterial {
            from: "pip".to_owned(),
            to: "dot".to_owned(),
        },
        &mut scene,
        &mut selection,
    );
    crate::scene::validate(&scene).expect("every reference renamed");
    let die = die(&scene);
    assert_eq!(
        object_at(&scene.objects, &[die, 1]).unwrap().material,
        "dot"
    );
}

#[test]
fn a_cube_becomes_a_die_by_subtracting_added_spheres_and_the_scene_still_renders() {
    let mut scene = crate::ui::document::files::default_scene();
    let cube = index_of(&scene, "blue box");
    let box_before = scene.objects[cube].clone();
    let mut selection = Selection::Object(cube);
    apply(
        SceneEdit::CsgSelected(CsgOp::Difference),
        &mut scene,
        &mut selection,
    );
    assert_eq!(selection, Selection::Object(cube));
    let node = &scene.objects[cube];
    assert_eq!(node.name, "difference");
    // The node stands where the box stood; the box, at its origin, has not moved.
    let Transform::Trs(placed) = (&node.transform, &box_before.transform).1 else {
        panic!("the box has a TRS");
    };
    assert_eq!(
        node.transform.world_from_object().translation,
        placed.translate
    );
    let inner = &node.shape.children()[0];
    let world = node.transform.world_from_object() * inner.transform.world_from_object();
    assert!(world.abs_diff_eq(box_before.transform.world_from_object(), 1e-12));
    assert_eq!(
        (inner.name.as_str(), &inner.shape),
        ("blue box", &Shape::Cube)
    );
    for _ in 0..2 {
        let mut at_node = Selection::Object(cube);
        apply(
            SceneEdit::AddOperand(Shape::Sphere),
            &mut scene,
            &mut at_node,
        );
    }
    let operands = scene.objects[cube].shape.children();
    assert_eq!(operands.len(), 3);
    // Added on the box's +x face at half its size: a bite that shows.
    let Transform::Trs(bite) = operands[1].transform else {
        panic!("a TRS");
    };
    let face = operands[0]
        .transform
        .world_from_object()
        .transform_point3(DVec3::X);
    assert!((bite.translate - face).length() < 1e-12);
    assert!((bite.scale.x - placed.scale.x * 0.5).abs() < 1e-12);
    crate::scene::validate(&scene).expect("valid");
    crate::trace::World::new(&scene).expect("compiles");
}

/// Where the leaf named `name` is in the world, and the material it shows.
fn placed(scene: &Scene, name: &str) -> (DAffine3, String) {
    let mut work: Vec<Vec<usize>> = (0..scene.objects.len()).map(|i| vec![i]).collect();
    while let Some(path) = work.pop() {
        let object = object_at(&scene.objects, &path).unwrap();
        if object.name == name {
            let world =
                world_from_parent(&scene.objects, &path) * object.transform.world_from_object();
            let material = crate::scene::tree::effective_material(&scene.objects, &path);
            return (world, material.unwrap_or_default().to_owned());
        }
        for k in 0..object.shape.children().len() {
            work.push([path.as_slice(), &[k]].concat());
        }
    }
    panic!("no {name}");
}

#[test]
fn a_dragged_node_moves_into_a_tree_or_beside_a_leaf_and_stays_where_it_was() {
    let mut scene = csg_scene();
    let die = die(&scene);
    let pip = object_at(&scene.objects, &[die, 5]).unwrap().name.clone();
    let before = placed(&scene, &pip);
    let mut selection = Selection::None;
    // Out of the turned, scaled die, beside the floor at the top level.
    apply(
        SceneEdit::MoveNode {
            from: vec![die, 5],
            onto: vec![0],
        },
        &mut scene,
        &mut selection,
    );
    assert_eq!(selection, Selection::Object(1));
    assert_eq!(scene.objects[1].name, pip);
    let after = placed(&scene, &pip);
    assert!(
        after.0.abs_diff_eq(before.0, 1e-9),
        "{:?} {:?}",
        after.0,
        before.0
    );
    assert_eq!(after.1, before.1, "the material it showed, now its own");
    crate::scene::validate(&scene).expect("a top-level object has a material");
    // And back into the die (now one further down the list), as its last operand.
    let die = die + 1;
    let operands = scene.objects[die].shape.children().len();
    apply(
        SceneEdit::MoveNode {
            from: vec![1],
            onto: vec![die],
        },
        &mut scene,
        &mut selection,
    );
    assert_eq!(selection, Selection::Part(vec![die - 1, operands]));
    assert!(placed(&scene, &pip).0.abs_diff_eq(before.0, 1e-9));
    crate::trace::World::new(&scene).expect("compiles");
}

#[test]
fn a_node_cannot_go_inside_itself_and_a_csg_keeps_its_last_operand() {
    let mut scene = csg_scene();
    let die = die(&scene);
    let mut selection = Selection::None;
    assert_refused(
        SceneEdit::MoveNode {
            from: vec![die],
            onto: vec![die, 0],
        },
        &mut scene,
        &mut selection,
        "inside itself",
    );
    let lens = index_of(&scene, "lens");
    apply(
        SceneEdit::MoveNode {
            from: vec![lens, 1],
            onto: vec![die],
        },
        &mut scene,
        &mut selection,
    );
    assert_refused(
        SceneEdit::MoveNode {
            from: vec![lens, 0],
            onto: vec![die],
        },
        &mut scene,
        &mut selection,
        "at least one operand",
    );
}

#[test]
fn several_objects_of_one_list_combine_into_one_node_where_the_first_stood() {
    let mut scene = csg_scene();
    let die = die(&scene);
    let lens = index_of(&scene, "lens");
    let before_die = placed(&scene, "pip 6.1");
    let count = scene.objects.len();
    // Picked die first: it is the first operand.
    let mut selection = Selection::several(vec![vec![die], vec![lens]]);
    apply(
        SceneEdit::CsgSelected(CsgOp::Difference),
        &mut scene,
        &mut selection,
    );
    assert_eq!(scene.objects.len(), count - 1);
    let at = die.min(lens);
    assert_eq!(selection, Selection::Object(at));
    let Shape::Csg { op, operands } = &scene.objects[at].shape else {
        panic!("a CSG node");
    };
    assert_eq!(*op, CsgOp::Difference);
    let names: Vec<&str> = operands.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["die", "lens"]);
    assert!(placed(&scene, "pip 6.1").0.abs_diff_eq(before_die.0, 1e-12));
    crate::trace::World::new(&scene).expect("compiles");
    // Nodes from different lists are not combined.
    let mut mixed = Selection::several(vec![vec![0], vec![at, 0, 1]]);
    assert_refused(SceneEdit::GroupSelected, &mut scene, &mut mixed, "one list");
}

#[test]
fn a_material_is_used_by_the_leaves_that_show_it_not_by_the_nodes_around_them() {
    let mut scene = crate::ui::document::files::default_scene();
    let cube = index_of(&scene, "blue box");
    let before = crate::ui::commands::material_users(&scene, "blue satin");
    let mut selection = Selection::Object(cube);
    apply(SceneEdit::GroupSelected, &mut scene, &mut selection);
    apply(
        SceneEdit::AddOperand(Shape::Sphere),
        &mut scene,
        &mut Selection::Object(cube),
    );
    // The group names it too, but only the box and the sphere that inherits it show it.
    assert_eq!(
        crate::ui::commands::material_users(&scene, "blue satin"),
        before + 1
    );
}

#[test]
fn several_picked_objects_are_deleted_together_or_not_at_all() {
    let mut scene = csg_scene();
    let die = die(&scene);
    let lens = index_of(&scene, "lens");
    let count = scene.objects.len();
    let pips = scene.objects[die].shape.children().len();
    let mut selection = Selection::several(vec![vec![lens], vec![die, 2], vec![die, 3]]);
    apply(SceneEdit::DeleteSelected, &mut scene, &mut selection);
    assert_eq!(selection, Selection::None);
    assert_eq!(scene.objects.len(), count - 1);
    let die = index_of(&scene, "die");
    assert_eq!(scene.objects[die].shape.children().len(), pips - 2);
    // Both halves of a lens cannot go: the lens keeps its last operand, and nothing is
    // deleted.
    let mut scene = csg_scene();
    let before = scene.clone();
    let mut both = Selection::several(vec![vec![lens, 0], vec![lens, 1]]);
    assert_refused(
        SceneEdit::DeleteSelected,
        &mut scene,
        &mut both,
        "at least one operand",
    );
    assert_eq!(scene, before);
}
