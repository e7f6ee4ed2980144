//! The editor through AccessKit, with no window: selection, inspector edits, undo and
//! redo, adding and deleting, renaming, picking in the viewport. Files, export and
//! recovery have their own files (ui_files.rs, ui_export.rs, ui_recovery.rs). The preview
//! worker is off here (it has its own tests), except where a test waits for its frame
//! deterministically.

mod editor_harness;

use editor_harness::{click_at, harness, harness_with, select_red_ball, step_until, temp_dir};
use egui::{Event, Key, Modifiers, PointerButton, Pos2, Vec2};
use egui_kittest::kittest::Queryable;
use glam::DVec3;
use raylab::scene::Transform;
use raylab::ui::files::{default_scene, new_scene, save_scene_to};
use raylab::ui::{Command, EditorApp, EditorOptions, Selection, VIEWPORT_LABEL};

fn translate(app: &EditorApp, index: usize) -> DVec3 {
    match app.document().scene.objects[index].transform {
        Transform::Trs(trs) => trs.translate,
        Transform::Matrix(_) => panic!("expected translate/rotate/scale"),
    }
}

#[test]
fn opens_the_default_scene_with_a_clean_title() {
    let harness = harness();
    assert_eq!(&harness.state().document().scene, &default_scene());
    assert!(!harness.state().document().is_dirty());
    assert_eq!(harness.state().title(), "default scene — raylab");
    harness.get_by_label("gold cone");
    harness.get_by_label("Spot light 4");
}

#[test]
fn clicking_an_outliner_row_selects_it_and_the_inspector_follows() {
    let mut harness = harness();
    select_red_ball(&mut harness);
    harness.get_by_label("translate x");
    harness.get_by_label("Camera").click();
    harness.run();
    assert_eq!(&harness.state().document().selection, &Selection::Camera);
    harness.get_by_label("fov");
    harness.get_by_label("Point light 2").click();
    harness.run();
    assert_eq!(&harness.state().document().selection, &Selection::Light(1));
    harness.get_by_label("intensity");
}

#[test]
fn an_inspector_edit_is_undone_and_redone_with_the_shortcuts() {
    let mut harness = harness();
    select_red_ball(&mut harness);
    let before = translate(harness.state(), 1);
    harness.get_by_label("translate x").set_value_accesskit(2.5);
    harness.run();
    assert_eq!(translate(harness.state(), 1).x, 2.5);
    assert!(harness.state().document().is_dirty());
    assert_eq!(harness.state().title(), "default scene* — raylab");

    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert_eq!(translate(harness.state(), 1), before);
    assert!(
        !harness.state().document().is_dirty(),
        "undo back to the file clears the marker"
    );

    harness.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::Z);
    harness.run();
    assert_eq!(translate(harness.state(), 1).x, 2.5);

    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Y);
    harness.run();
    assert_eq!(translate(harness.state(), 1).x, 2.5);
}

#[test]
fn a_whole_drag_is_one_undo_step() {
    let mut harness = harness();
    select_red_ball(&mut harness);
    let before = harness.state().document().scene.clone();
    let start = harness.get_by_label("scale y").rect().center();
    harness.event(Event::PointerMoved(start));
    harness.event(Event::PointerButton {
        pos: start,
        button: PointerButton::Primary,
        pressed: true,
        modifiers: Modifiers::NONE,
    });
    harness.step();
    for i in 1..=8 {
        harness.event(Event::PointerMoved(start + Vec2::new(6.0 * i as f32, 0.0)));
        harness.step();
    }
    let end = start + Vec2::new(48.0, 0.0);
    harness.event(Event::PointerButton {
        pos: end,
        button: PointerButton::Primary,
        pressed: false,
        modifiers: Modifiers::NONE,
    });
    harness.run();
    let dragged = harness.state().document().scene.clone();
    assert_ne!(dragged, before, "the drag changed the scale");

    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "one undo reverts the whole drag"
    );
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Y);
    harness.run();
    assert_eq!(&harness.state().document().scene, &dragged);
}

#[test]
fn objects_and_lights_are_added_duplicated_and_deleted() {
    let mut harness = harness();
    harness.get_by_label("+ Add object").click();
    harness.run();
    harness.get_by_label("Cone").click();
    harness.run();
    let objects = harness.state().document().scene.objects.len();
    assert_eq!(objects, 7);
    assert_eq!(&harness.state().document().selection, &Selection::Object(6));
    assert_eq!(harness.state().document().scene.objects[6].name, "Cone");

    harness.key_press_modifiers(Modifiers::COMMAND, Key::D);
    harness.run();
    assert_eq!(harness.state().document().scene.objects.len(), 8);
    harness.get_by_role_and_label(egui::Role::Button, "Cone 2");

    harness.key_press(Key::Delete);
    harness.run();
    harness.key_press(Key::Delete);
    harness.run();
    assert_eq!(harness.state().document().scene.objects.len(), 6);

    harness.get_by_label("+ Add light").click();
    harness.run();
    harness.get_by_label("Spot light").click();
    harness.run();
    assert_eq!(harness.state().document().scene.lights.len(), 5);
    harness.get_by_label("Spot light 5");
    harness.get_by_label("angle");

    harness.get_by_label("Edit").click();
    harness.run();
    harness.get_by_label("Delete").click();
    harness.run();
    assert_eq!(harness.state().document().scene.lights.len(), 4);

    // Every edit can be undone, back to the file as loaded.
    for _ in 0..8 {
        harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
        harness.run();
    }
    assert_eq!(&harness.state().document().scene, &default_scene());
}

#[test]
fn renaming_an_object_in_the_inspector() {
    let mut harness = harness();
    select_red_ball(&mut harness);
    let name = harness.get_by_label("object name");
    name.focus();
    name.type_text("!");
    harness.run();
    // While typing, Delete belongs to the text field, not to the selection.
    harness.key_press(Key::Delete);
    harness.run();
    assert_eq!(harness.state().document().scene.objects.len(), 6);
    // Click elsewhere to leave the field; the rename is one undo step.
    harness.get_by_label("Camera").click();
    harness.run();
    assert_eq!(
        harness.state().document().scene.objects[1].name,
        "red ball!"
    );
    harness.get_by_label("red ball!");
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert_eq!(harness.state().document().scene.objects[1].name, "red ball");
}

#[test]
fn an_object_cannot_be_renamed_to_nothing_and_says_so() {
    let mut harness = harness();
    select_red_ball(&mut harness);
    let name = harness.get_by_label("object name");
    name.focus();
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.key_press(Key::Backspace);
    harness.run();
    // While typing, the field may be empty; the object keeps its name.
    assert_eq!(harness.state().document().scene.objects[1].name, "red ball");
    harness.get_by_label("object name").type_text("blue ball");
    harness.run();
    assert_eq!(
        harness.state().document().scene.objects[1].name,
        "blue ball"
    );
    // Emptied and left: the name stays, and the status line says why.
    harness.get_by_label("object name").focus();
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.key_press(Key::Backspace);
    harness.run();
    harness.get_by_label("Camera").click();
    harness.run();
    assert_eq!(
        harness.state().document().scene.objects[1].name,
        "blue ball"
    );
    harness.get_by_label_contains("An object needs a name");
}

#[test]
fn f1_lists_the_shortcuts() {
    let mut harness = harness();
    harness.key_press(Key::F1);
    harness.run();
    assert!(harness.get_all_by_label("Keyboard shortcuts").count() >= 1);
    harness.get_by_label("Duplicate selection");
    harness.get_by_label("Delete selection");
}

#[test]
fn a_material_rename_follows_its_objects() {
    let mut harness = harness();
    harness.get_by_label("gold").click();
    harness.run();
    let name = harness.get_by_label("material name");
    name.focus();
    name.type_text(" leaf");
    harness.run();
    harness.get_by_label("Camera").click();
    harness.run();
    let scene = &harness.state().document().scene;
    assert!(scene.materials.contains_key("gold leaf"));
    assert_eq!(scene.objects[5].material, "gold leaf");
}

#[test]
fn a_matrix_transform_is_read_only_until_reset_to_translate_rotate_scale() {
    let dir = temp_dir("matrix");
    let path = dir.join("matrix.ron");
    let mut scene = new_scene();
    scene.objects.push(raylab::scene::Object {
        name: "tilted".to_owned(),
        shape: raylab::scene::Shape::Cube,
        transform: Transform::Matrix([
            [0.0, -2.0, 0.0, 1.0],
            [1.0, 0.0, 0.0, 2.0],
            [0.0, 0.0, 0.5, -3.0],
        ]),
        material: "default".to_owned(),
    });
    save_scene_to(&scene, &path).unwrap();
    let mut harness = harness();
    harness.state_mut().push(Command::Open(path));
    harness.run();
    harness.get_by_label("tilted").click();
    harness.run();
    assert!(
        harness.query_by_label("translate x").is_none(),
        "no editable fields"
    );
    let before = harness.state().document().scene.objects[0]
        .transform
        .world_from_object();
    harness
        .get_by_label("Reset to translate/rotate/scale")
        .click();
    harness.run();
    let transform = harness.state().document().scene.objects[0].transform;
    assert!(matches!(transform, Transform::Trs(_)));
    assert!(transform.world_from_object().abs_diff_eq(before, 1e-12));
    harness.get_by_label("translate x");
}

#[test]
fn clicking_the_viewport_picks_the_object_under_the_cursor() {
    let mut harness = harness_with(EditorOptions {
        preview: true,
        ..EditorOptions::default()
    });
    // The preview arrives in the background; wait for the full-resolution frame.
    step_until(&mut harness, "the preview", |app| {
        app.preview().is_some_and(|p| p.shows_full_resolution())
    });
    let picture = harness.get_by_label(VIEWPORT_LABEL).rect();
    let scene = harness.state().document().scene.clone();
    let camera =
        raylab::trace::PinholeCamera::new(&scene.camera, scene.camera.width, scene.camera.height);
    let centre = scene.objects[3].transform.world_from_object().translation;
    let p = camera.project(centre).unwrap();
    let pos = Pos2::new(
        picture.min.x + (p.x / f64::from(scene.camera.width)) as f32 * picture.width(),
        picture.min.y + (p.y / f64::from(scene.camera.height)) as f32 * picture.height(),
    );
    click_at(&mut harness, pos);
    assert_eq!(
        &harness.state().document().selection,
        &Selection::Object(3),
        "the blue box"
    );
    click_at(
        &mut harness,
        picture.min + Vec2::new(picture.width() * 0.5, 4.0),
    );
    assert_eq!(
        &harness.state().document().selection,
        &Selection::None,
        "the sky"
    );
}
