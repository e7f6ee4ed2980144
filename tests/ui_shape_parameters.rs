//! The torus's and the tube's parameter in the object inspector: a field that shows the
//! value without changing it, takes what the validator takes and refuses the rest, and
//! survives choosing the kind the object already is.

mod editor_harness;

use editor_harness::harness;
use egui_kittest::kittest::Queryable;
use raylab::scene::Shape;
use raylab::ui::Command;

fn shape_of(harness: &egui_kittest::Harness<'_, raylab::ui::EditorApp>, name: &str) -> Shape {
    let scene = &harness.state().document().scene;
    let object = scene.objects.iter().find(|o| o.name == name).unwrap();
    object.shape.clone()
}

fn open_more_shapes() -> egui_kittest::Harness<'static, raylab::ui::EditorApp> {
    editor_harness::harness_on_example("more_shapes.ron")
}

#[test]
fn a_torus_minor_radius_is_a_field_held_to_the_validators_rule() {
    let mut harness = open_more_shapes();
    let before = harness.state().document().scene.clone();
    harness.get_by_label("spindle").click();
    harness.run();
    harness.get_by_label("minor radius");
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "showing is not editing"
    );

    harness
        .get_by_label("minor radius")
        .set_value_accesskit(0.5);
    harness.run();
    assert_eq!(shape_of(&harness, "spindle"), Shape::Torus { minor: 0.5 });
    // Zero is refused (no tube at all): the field keeps its value.
    harness
        .get_by_label("minor radius")
        .set_value_accesskit(0.0);
    harness.run();
    assert_eq!(shape_of(&harness, "spindle"), Shape::Torus { minor: 0.5 });
    harness.state_mut().push(Command::Undo);
    harness.run();
    assert_eq!(shape_of(&harness, "spindle"), Shape::Torus { minor: 1.3 });
}

#[test]
fn a_tube_inner_radius_stays_inside_the_outer_one() {
    let mut harness = open_more_shapes();
    harness.get_by_label("pipe").click();
    harness.run();
    harness
        .get_by_label("inner radius")
        .set_value_accesskit(1.0);
    harness.run();
    assert_eq!(
        shape_of(&harness, "pipe"),
        Shape::Tube { inner: 0.7 },
        "1 leaves no wall"
    );
    harness
        .get_by_label("inner radius")
        .set_value_accesskit(0.3);
    harness.run();
    assert_eq!(shape_of(&harness, "pipe"), Shape::Tube { inner: 0.3 });
    assert!(harness.query_by_label("minor radius").is_none());
}

#[test]
fn choosing_the_kind_an_object_is_keeps_its_parameter_and_another_kind_starts_fresh() {
    let mut harness = open_more_shapes();
    harness.get_by_label("spindle").click();
    harness.run();
    harness.get_by_label("shape").click();
    harness.run();
    harness.get_by_label("Torus").click();
    harness.run();
    assert_eq!(shape_of(&harness, "spindle"), Shape::Torus { minor: 1.3 });
    harness.get_by_label("shape").click();
    harness.run();
    harness.get_by_label("Tube").click();
    harness.run();
    assert_eq!(shape_of(&harness, "spindle"), Shape::Tube { inner: 0.5 });
    harness.get_by_label("inner radius");
}

#[test]
fn the_add_menu_offers_all_eight_unit_shapes() {
    let mut harness = harness();
    let count = harness.state().document().scene.objects.len();
    harness.get_by_label("+ Add object").click();
    harness.run();
    for shape in Shape::ALL {
        harness.get_by_label(shape.name());
    }
    harness.get_by_label("Torus").click();
    harness.run();
    let scene = &harness.state().document().scene;
    assert_eq!(scene.objects.len(), count + 1);
    assert_eq!(scene.objects[count].shape, Shape::Torus { minor: 0.25 });
}
