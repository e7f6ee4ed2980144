//! Materials shared between objects: the object inspector says so and offers the object
//! a copy of its own, in one undo step.

mod editor_harness;

use egui_kittest::kittest::Queryable;
use raylab::ui::Command;

fn open_more_shapes() -> egui_kittest::Harness<'static, raylab::ui::EditorApp> {
    editor_harness::harness_on_example("more_shapes.ron")
}

#[test]
fn a_shared_material_says_so_and_can_be_made_unique_in_one_undo_step() {
    let mut harness = open_more_shapes();
    // "clay" is used by the sphere, the cylinder and the pipe.
    harness.get_by_label("pipe").click();
    harness.run();
    harness.get_by_label_contains("\u{201c}clay\u{201d} is shared by 3 objects");
    let before = harness.state().document().scene.clone();
    harness.get_by_label("Make unique").click();
    harness.run();
    let scene = &harness.state().document().scene;
    let pipe = scene.objects.iter().find(|o| o.name == "pipe").unwrap();
    assert_eq!(pipe.material, "clay (pipe)");
    assert_eq!(scene.materials["clay (pipe)"], scene.materials["clay"]);
    assert!(
        harness.query_by_label("Make unique").is_none(),
        "no longer shared"
    );
    harness.state_mut().push(Command::Undo);
    harness.run();
    assert_eq!(&harness.state().document().scene, &before);
    // A material only one object uses (the floor's) says nothing.
    harness
        .state_mut()
        .push(Command::Select(raylab::ui::Selection::Object(0)));
    harness.run();
    assert!(harness.query_by_label_contains("is shared by").is_none());
    assert!(harness.query_by_label("Make unique").is_none());
}

#[test]
fn undo_keeps_the_selection_where_the_item_still_is() {
    let mut harness = open_more_shapes();
    harness.get_by_label("pipe").click();
    harness.run();
    let selected = harness.state().document().selection.clone();
    harness.get_by_label("translate x").set_value_accesskit(1.5);
    harness.run();
    harness.state_mut().push(Command::Undo);
    harness.run();
    assert_eq!(
        &harness.state().document().selection,
        &selected,
        "undo of a move"
    );
    harness.get_by_label("Make unique").click();
    harness.run();
    harness.state_mut().push(Command::Undo);
    harness.run();
    assert_eq!(
        &harness.state().document().selection,
        &selected,
        "undo of make unique"
    );
}
