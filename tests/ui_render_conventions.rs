//! The course conventions in the editor's render settings: each choice is one click, one
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
    assert!(harness.state().scene().render.conventions.is_default());
    harness.get_by_label_contains("local + km * reflected (the contract)");

    harness.get_by_label("Blend").click();
    harness.run();
    let conventions = harness.state().scene().render.conventions;
    assert_eq!(conventions.mirror, MirrorConvention::Blend);
    harness.get_by_label_contains("(1 - km) * local + km * reflected");

    harness.get_by_label("Each ray").click();
    harness.run();
    harness.get_by_label("Truncate").click();
    harness.run();
    let conventions = harness.state().scene().render.conventions;
    assert_eq!(conventions.clamp, ClampConvention::EachRay);
    assert_eq!(conventions.quantise, Quantise::Truncate);
    harness.get_by_label_contains("floor(255 c)");

    // One undo step per click.
    harness.state_mut().push(Command::Undo);
    harness.run();
    assert_eq!(
        harness.state().scene().render.conventions.quantise,
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
        harness.state().scene().render.conventions,
        Conventions::COURSE
    );
    harness.get_by_label("Contract").click();
    harness.run();
    assert!(harness.state().scene().render.conventions.is_default());
}
