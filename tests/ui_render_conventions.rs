//! The render settings and object panels on the new scene features. The course
//! conventions in the render settings: each choice is one click, one
//! undo step, and says in one line what it does; the presets switch all three.

mod editor_harness;

use editor_harness::harness;
use egui_kittest::kittest::Queryable;
use raylab::scene::{ClampConvention, Conventions, MirrorConvention, Quantise};
use raylab::ui::Command;

#[test]
fn each_convention_is_a_click_with_a_line_saying_what_it_does() {
    let mut harness = harness();
    harness.get_by_label("Render settings").click();
    harness.run();
    assert!(
        harness
            .state()
            .document()
            .scene
            .render
            .conventions
            .is_default()
    );
    harness.get_by_label_contains("local + km * reflected (the contract)");

    harness.get_by_label("Blend").click();
    harness.run();
    let conventions = harness.state().document().scene.render.conventions;
    assert_eq!(conventions.mirror, MirrorConvention::Blend);
    harness.get_by_label_contains("(1 - km) * local + km * reflected");

    harness.get_by_label("Each ray").click();
    harness.run();
    harness.get_by_label("Truncate").click();
    harness.run();
    let conventions = harness.state().document().scene.render.conventions;
    assert_eq!(conventions.clamp, ClampConvention::EachRay);
    assert_eq!(conventions.quantise, Quantise::Truncate);
    harness.get_by_label_contains("floor(255 c)");

    // One undo step per click.
    harness.state_mut().push(Command::Undo);
    harness.run();
    assert_eq!(
        harness.state().document().scene.render.conventions.quantise,
        Quantise::Round
    );
}

#[test]
fn the_presets_set_all_three() {
    let mut harness = harness();
    harness.get_by_label("Render settings").click();
    harness.run();
    harness.get_by_label("Course").click();
    harness.run();
    assert_eq!(
        harness.state().document().scene.render.conventions,
        Conventions::COURSE
    );
    harness.get_by_label("Contract").click();
    harness.run();
    assert!(
        harness
            .state()
            .document()
            .scene
            .render
            .conventions
            .is_default()
    );
}

#[test]
fn a_tree_object_shows_what_it_holds_and_offers_no_shape_to_switch_to() {
    let mut harness = editor_harness::harness_on_example("csg.ron");
    let before = harness.state().document().scene.clone();
    harness.get_by_label("die").click();
    harness.run();
    harness.get_by_label_contains("Csg Difference of");
    assert!(
        harness.query_by_label("shape").is_none(),
        "a CSG object must not offer a unit shape in its place"
    );
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "showing is not editing"
    );
    // A unit shape still has its shape menu.
    // "floor" names the object and, after it in the outliner, a material.
    harness.get_all_by_label("floor").next().unwrap().click();
    harness.run();
    harness.get_by_label("shape");
}
