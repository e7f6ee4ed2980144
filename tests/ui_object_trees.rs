//! Object trees in the editor: the outliner folds a CSG node or group open to its parts,
//! a part is selected and edited in the inspector (in its parent's space, one undo step),
//! its breadcrumb selects its parent, and Ctrl+G / Ungroup wrap and unwrap an object.

mod editor_harness;

use editor_harness::harness_on_example;
use egui::{Key, Modifiers};
use egui_kittest::kittest::Queryable;
use raylab::scene::Shape;
use raylab::scene::tree::object_at;
use raylab::ui::{Command, Selection};

fn die_index(harness: &egui_kittest::Harness<'_, raylab::ui::EditorApp>) -> usize {
    harness
        .state()
        .document()
        .scene
        .objects
        .iter()
        .position(|o| o.name == "die")
        .expect("the die")
}

#[test]
fn a_part_is_shown_selected_edited_and_undone_and_its_breadcrumb_selects_the_parent() {
    let mut harness = harness_on_example("csg.ron");
    let die = die_index(&harness);
    // Parts are folded away until their node opens.
    assert!(harness.query_by_label("pip 6.1").is_none());
    harness
        .state_mut()
        .push(Command::Select(Selection::Part(vec![die, 2])));
    harness.run();
    // The node holding the selection opens, and the part's row is there to click.
    harness.get_by_role_and_label(egui::Role::Button, "pip 6.1");
    harness
        .get_by_role_and_label(egui::Role::Button, "pip 6.2")
        .click();
    harness.run();
    assert_eq!(
        &harness.state().document().selection,
        &Selection::Part(vec![die, 3])
    );
    harness.get_by_label("in its parent's space");
    let before = harness.state().document().scene.clone();
    harness.get_by_label("object name").focus();
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.key_press(Key::Backspace);
    harness.run();
    harness.get_by_label("object name").type_text("six two");
    harness.run();
    harness.get_by_label("Camera").click();
    harness.run();
    harness
        .state_mut()
        .push(Command::Select(Selection::Part(vec![die, 3])));
    harness.run();
    let scene = &harness.state().document().scene;
    assert_eq!(
        object_at(&scene.objects, &[die, 3]).unwrap().name,
        "six two"
    );
    assert_eq!(scene.objects.len(), before.objects.len());
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert_eq!(&harness.state().document().scene, &before, "one undo step");
    // The breadcrumb's link selects the parent.
    harness
        .get_by_role_and_label(egui::Role::Link, "die")
        .click();
    harness.run();
    assert_eq!(
        &harness.state().document().selection,
        &Selection::Object(die)
    );
    harness.get_by_label("operator");
}

#[test]
fn ctrl_g_groups_the_selected_object_and_ungroup_puts_it_back() {
    let mut harness = harness_on_example("csg.ron");
    let die = die_index(&harness);
    let before = harness.state().document().scene.clone();
    harness
        .state_mut()
        .push(Command::Select(Selection::Object(die)));
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::G);
    harness.run();
    let scene = &harness.state().document().scene;
    let Shape::Group { children } = &scene.objects[die].shape else {
        panic!("grouped: {:?}", scene.objects[die].shape);
    };
    // The group stands where the die stood; the die, at its origin, has not moved.
    let placed = scene.objects[die].transform.world_from_object()
        * children[0].transform.world_from_object();
    assert!(placed.abs_diff_eq(before.objects[die].transform.world_from_object(), 1e-12));
    assert_eq!(children[0].shape, before.objects[die].shape);
    assert_eq!(
        &harness.state().document().selection,
        &Selection::Object(die)
    );
    harness.get_by_label("Ungroup").click();
    harness.run();
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "the group at rest unwraps exactly"
    );
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert!(matches!(
        harness.state().document().scene.objects[die].shape,
        Shape::Group { .. }
    ));
}

#[test]
fn ctrl_click_picks_several_objects_and_subtract_makes_one_csg_of_them() {
    let mut harness = harness_on_example("csg.ron");
    let names = |h: &egui_kittest::Harness<'_, raylab::ui::EditorApp>| -> Vec<String> {
        h.state()
            .document()
            .scene
            .objects
            .iter()
            .map(|o| o.name.clone())
            .collect()
    };
    assert_eq!(names(&harness), ["floor", "lens", "die", "hollow cube"]);
    harness
        .get_by_role_and_label(egui::Role::Button, "hollow cube")
        .click();
    harness.run();
    harness
        .get_by_role_and_label(egui::Role::Button, "lens")
        .click_modifiers(Modifiers::COMMAND);
    harness.run();
    assert_eq!(
        &harness.state().document().selection,
        &Selection::Several(vec![vec![3], vec![1]])
    );
    harness.get_by_label("2 objects");
    harness.get_by_label("hollow cube  (first)");
    harness.get_by_label("Subtract").click();
    harness.run();
    assert_eq!(names(&harness), ["floor", "difference", "die"]);
    let Shape::Csg { operands, .. } = &harness.state().document().scene.objects[1].shape else {
        panic!("a CSG node");
    };
    assert_eq!(operands[0].name, "hollow cube");
    assert_eq!(operands[1].name, "lens");
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert_eq!(names(&harness), ["floor", "lens", "die", "hollow cube"]);
}

#[test]
fn a_part_is_hidden_from_its_own_row_and_the_toolbar_names_it() {
    let mut harness = harness_on_example("csg.ron");
    let die = die_index(&harness);
    harness
        .state_mut()
        .push(Command::Select(Selection::Part(vec![die, 2])));
    harness.run();
    harness.get_by_label("hide pip 6.1").click();
    harness.run();
    let isolation = harness.state().view().isolation.clone();
    assert_eq!(
        isolation.hidden_parts,
        std::collections::BTreeSet::from([vec![die, 2]])
    );
    assert!(isolation.hidden_objects.is_empty());
    assert!(
        !harness.state().document().is_dirty(),
        "hiding is not a scene edit"
    );
    harness.get_by_label_contains("hidden die/pip 6.1");
    harness.get_by_label("hide pip 6.1").click();
    harness.run();
    assert!(harness.state().view().isolation.is_none());
}
