//! The editor through AccessKit, with no window: selection, inspector edits, undo and
//! redo, adding and deleting, file operations through the functions the dialogs call.
//! The preview worker is off here (it has its own tests), except where a test waits for
//! its frame deterministically.

mod editor_harness;

use std::path::Path;
use std::time::{Duration, Instant};

use editor_harness::{click_at, drop_file, editor_harness, temp_dir};
use egui::{Event, Key, Modifiers, PointerButton, Pos2, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use glam::DVec3;
use raylab::scene::{Transform, load_scene};
use raylab::ui::files::{default_scene, new_scene, open_scene, save_scene_to};
use raylab::ui::{Command, EditorApp, EditorOptions, SceneEdit, Selection, VIEWPORT_LABEL};

fn harness_with(options: EditorOptions) -> Harness<'static, EditorApp> {
    editor_harness(options, Vec2::new(1280.0, 800.0), 64)
}

fn harness() -> Harness<'static, EditorApp> {
    harness_with(EditorOptions::default())
}

fn translate(app: &EditorApp, index: usize) -> DVec3 {
    match app.scene().objects[index].transform {
        Transform::Trs(trs) => trs.translate,
        Transform::Matrix(_) => panic!("expected translate/rotate/scale"),
    }
}

fn select_red_ball(harness: &mut Harness<'_, EditorApp>) {
    harness.get_by_label("red ball").click();
    harness.run();
    assert_eq!(harness.state().selection(), &Selection::Object(1));
}

#[test]
fn opens_the_default_scene_with_a_clean_title() {
    let harness = harness();
    assert_eq!(harness.state().scene(), &default_scene());
    assert!(!harness.state().is_dirty());
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
    assert_eq!(harness.state().selection(), &Selection::Camera);
    harness.get_by_label("fov");
    harness.get_by_label("Point light 2").click();
    harness.run();
    assert_eq!(harness.state().selection(), &Selection::Light(1));
    harness.get_by_label("intensity");
}

#[test]
fn showing_every_item_in_the_inspector_changes_nothing() {
    let mut harness = harness();
    let scene = harness.state().scene().clone();
    let mut labels: Vec<String> = vec!["Camera".into(), "Render settings".into()];
    labels.extend(scene.objects.iter().map(|o| o.name.clone()));
    labels.extend(scene.materials.keys().cloned());
    labels.extend(
        scene
            .lights
            .iter()
            .enumerate()
            .map(|(i, l)| raylab::ui::light_label(l, i)),
    );
    for (position, label) in labels.iter().enumerate() {
        // "floor" is both an object and a material: take the row of this occurrence.
        let earlier = labels[..position].iter().filter(|l| *l == label).count();
        harness
            .get_all_by_role_and_label(egui::Role::Button, label)
            .nth(earlier)
            .expect("an outliner row")
            .click();
        harness.run();
        assert_ne!(harness.state().selection(), &Selection::None, "{label}");
        assert_eq!(
            harness.state().scene(),
            &scene,
            "showing {label} edited the scene"
        );
    }
}

#[test]
fn an_inspector_edit_is_undone_and_redone_with_the_shortcuts() {
    let mut harness = harness();
    select_red_ball(&mut harness);
    let before = translate(harness.state(), 1);
    harness.get_by_label("translate x").set_value_accesskit(2.5);
    harness.run();
    assert_eq!(translate(harness.state(), 1).x, 2.5);
    assert!(harness.state().is_dirty());
    assert_eq!(harness.state().title(), "default scene* — raylab");

    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert_eq!(translate(harness.state(), 1), before);
    assert!(
        !harness.state().is_dirty(),
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
    let before = harness.state().scene().clone();
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
    let dragged = harness.state().scene().clone();
    assert_ne!(dragged, before, "the drag changed the scale");

    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert_eq!(
        harness.state().scene(),
        &before,
        "one undo reverts the whole drag"
    );
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Y);
    harness.run();
    assert_eq!(harness.state().scene(), &dragged);
}

#[test]
fn objects_and_lights_are_added_duplicated_and_deleted() {
    let mut harness = harness();
    harness.get_by_label("+ Add object").click();
    harness.run();
    harness.get_by_label("Cone").click();
    harness.run();
    let objects = harness.state().scene().objects.len();
    assert_eq!(objects, 7);
    assert_eq!(harness.state().selection(), &Selection::Object(6));
    assert_eq!(harness.state().scene().objects[6].name, "Cone");

    harness.key_press_modifiers(Modifiers::COMMAND, Key::D);
    harness.run();
    assert_eq!(harness.state().scene().objects.len(), 8);
    harness.get_by_role_and_label(egui::Role::Button, "Cone 2");

    harness.key_press(Key::Delete);
    harness.run();
    harness.key_press(Key::Delete);
    harness.run();
    assert_eq!(harness.state().scene().objects.len(), 6);

    harness.get_by_label("+ Add light").click();
    harness.run();
    harness.get_by_label("Spot light").click();
    harness.run();
    assert_eq!(harness.state().scene().lights.len(), 5);
    harness.get_by_label("Spot light 5");
    harness.get_by_label("angle");

    harness.get_by_label("Edit").click();
    harness.run();
    harness.get_by_label("Delete").click();
    harness.run();
    assert_eq!(harness.state().scene().lights.len(), 4);

    // Every edit can be undone, back to the file as loaded.
    for _ in 0..8 {
        harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
        harness.run();
    }
    assert_eq!(harness.state().scene(), &default_scene());
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
    assert_eq!(harness.state().scene().objects.len(), 6);
    // Click elsewhere to leave the field; the rename is one undo step.
    harness.get_by_label("Camera").click();
    harness.run();
    assert_eq!(harness.state().scene().objects[1].name, "red ball!");
    harness.get_by_label("red ball!");
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert_eq!(harness.state().scene().objects[1].name, "red ball");
}

#[test]
fn a_file_that_fails_to_load_shows_its_line_and_keeps_the_scene() {
    let dir = temp_dir("broken");
    let path = dir.join("broken.ron");
    std::fs::write(
        &path,
        "Scene(\n    objects: [\n        (shape: Blob, material: \"x\"),\n    ],\n)\n",
    )
    .unwrap();
    let mut harness = harness();
    select_red_ball(&mut harness);
    harness
        .get_by_label("translate x")
        .set_value_accesskit(1.25);
    harness.run();
    let edited = harness.state().scene().clone();

    harness.state_mut().push(Command::Open(path.clone()));
    harness.run();
    // Unsaved changes: the editor asks first.
    harness.get_by_label("Discard changes").click();
    harness.run();

    assert_eq!(
        harness.state().scene(),
        &edited,
        "the open scene is untouched"
    );
    assert_eq!(harness.state().path(), None);
    let error = harness
        .state()
        .error()
        .expect("the error is shown")
        .to_owned();
    assert!(error.contains("line 3"), "{error}");
    harness.get_by_label_contains("line 3, column");
    harness.get_by_label("Dismiss").click();
    harness.run();
    assert!(harness.state().error().is_none());
}

#[test]
fn save_then_open_round_trips_and_clears_the_unsaved_marker() {
    let dir = temp_dir("save");
    let path = dir.join("edited.ron");
    let mut harness = harness();
    harness.state_mut().push(Command::Edit(SceneEdit::AddObject(
        raylab::scene::Shape::Cylinder,
    )));
    harness.run();
    assert!(harness.state().is_dirty());

    harness.state_mut().push(Command::SaveAs(path.clone()));
    harness.run();
    assert!(!harness.state().is_dirty());
    assert_eq!(harness.state().path(), Some(path.as_path()));
    assert_eq!(harness.state().title(), "edited.ron — raylab");
    assert_eq!(&load_scene(&path).unwrap(), harness.state().scene());
    assert_eq!(&open_scene(&path).unwrap(), harness.state().scene());
    assert_eq!(
        harness.state().recent().paths()[0],
        std::fs::canonicalize(&path).unwrap()
    );

    let saved = harness.state().scene().clone();
    let mut other = self::harness();
    other.state_mut().push(Command::Open(path.clone()));
    other.run();
    assert_eq!(other.state().scene(), &saved);
    assert_eq!(other.state().title(), "edited.ron — raylab");
}

#[test]
fn saving_into_a_missing_folder_shows_the_error_and_stays_unsaved() {
    let dir = temp_dir("unwritable");
    let path = dir.join("no such folder").join("scene.ron");
    let mut harness = harness();
    harness.state_mut().push(Command::Edit(SceneEdit::AddLight(
        raylab::ui::LightKind::Point,
    )));
    harness.run();
    harness.state_mut().push(Command::SaveAs(path.clone()));
    harness.run();
    let error = harness
        .state()
        .error()
        .expect("the error is shown")
        .to_owned();
    assert!(error.contains("cannot write"), "{error}");
    harness.get_by_label_contains("cannot write");
    assert!(harness.state().is_dirty());
    assert_eq!(harness.state().path(), None);
    assert!(save_scene_to(harness.state().scene(), &path).is_err());
    assert!(!path.exists());
}

#[test]
fn new_asks_before_dropping_changes() {
    let mut harness = harness();
    select_red_ball(&mut harness);
    harness.get_by_label("translate y").set_value_accesskit(3.0);
    harness.run();
    let edited = harness.state().scene().clone();

    harness.key_press_modifiers(Modifiers::COMMAND, Key::N);
    harness.run();
    harness.get_by_label("Cancel").click();
    harness.run();
    assert_eq!(harness.state().scene(), &edited);

    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label("New").click();
    harness.run();
    harness.get_by_label("Discard changes").click();
    harness.run();
    assert_eq!(harness.state().scene(), &new_scene());
    assert_eq!(harness.state().title(), "untitled — raylab");
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
    let scene = harness.state().scene();
    assert!(scene.materials.contains_key("gold leaf"));
    assert_eq!(scene.objects[5].material, "gold leaf");
}

/// Steps the harness until `done` holds, sleeping between steps (bounded).
fn step_until(harness: &mut Harness<'_, EditorApp>, what: &str, done: impl Fn(&EditorApp) -> bool) {
    let deadline = Instant::now() + Duration::from_secs(120);
    while !done(harness.state()) {
        assert!(Instant::now() < deadline, "timed out waiting for {what}");
        std::thread::sleep(Duration::from_millis(20));
        harness.step();
    }
    harness.run_ok();
}

#[test]
fn export_writes_a_png_and_keeps_the_render_when_the_file_cannot_be_written() {
    let dir = temp_dir("export");
    let mut harness = harness();
    harness.state_mut().push(Command::ShowExport);
    harness.run();
    harness
        .get_by_label("export width")
        .set_value_accesskit(64.0);
    harness
        .get_by_label("export height")
        .set_value_accesskit(48.0);
    harness
        .get_by_label("export samples")
        .set_value_accesskit(2.0);
    harness.run();

    let bad = dir.join("missing").join("out.png");
    set_export_path(&mut harness, &bad);
    harness.get_by_label("Render and save").click();
    harness.run_ok();
    step_until(&mut harness, "the export", |app| !app.export().is_running());
    let status = harness.state().export().status.clone().unwrap();
    assert!(
        status.as_ref().is_err_and(|e| e.contains("cannot write")),
        "{status:?}"
    );
    let kept = harness
        .state()
        .export()
        .kept_image()
        .expect("the render is kept");
    assert_eq!((kept.width, kept.height), (64, 48));

    let good = dir.join("out.png");
    set_export_path(&mut harness, &good);
    harness.get_by_label("Save kept render").click();
    harness.run();
    let png = image::open(&good).expect("a PNG was written");
    assert_eq!((png.width(), png.height()), (64, 48));
    assert!(harness.state().export().kept_image().is_none());
}

fn set_export_path(harness: &mut Harness<'_, EditorApp>, path: &Path) {
    harness.get_by_label("export path").focus();
    harness.run();
    harness.key_combination_modifiers(Modifiers::COMMAND, &[Key::A]);
    harness
        .get_by_label("export path")
        .type_text(&path.display().to_string());
    harness.run();
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
    let scene = harness.state().scene().clone();
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
        harness.state().selection(),
        &Selection::Object(3),
        "the blue box"
    );
    click_at(
        &mut harness,
        picture.min + Vec2::new(picture.width() * 0.5, 4.0),
    );
    assert_eq!(harness.state().selection(), &Selection::None, "the sky");
}

#[test]
fn dropping_a_ron_file_opens_it_and_other_files_are_refused() {
    let dir = temp_dir("drop");
    let path = dir.join("dropped.ron");
    let mut scene = new_scene();
    scene.camera.fov_deg = 50.0;
    save_scene_to(&scene, &path).unwrap();
    let mut harness = harness();

    // (A .png or .ppm is compared with: tests/ui_compare.rs.)
    drop_file(&mut harness, &dir.join("notes.txt"));
    assert!(harness.state().error().unwrap().contains(".ron"));
    assert_eq!(harness.state().scene(), &default_scene());

    drop_file(&mut harness, &path);
    assert_eq!(harness.state().scene(), &scene);
    assert_eq!(harness.state().path(), Some(path.as_path()));
}

#[test]
fn closing_the_window_with_unsaved_changes_asks_first() {
    let mut harness = harness();
    harness.state_mut().push(Command::Edit(SceneEdit::AddObject(
        raylab::scene::Shape::Cube,
    )));
    harness.run();
    let close = |harness: &mut Harness<'_, EditorApp>| {
        harness
            .input_mut()
            .viewports
            .entry(egui::ViewportId::ROOT)
            .or_default()
            .events
            .push(egui::ViewportEvent::Close);
        harness.run();
    };
    close(&mut harness);
    assert_eq!(
        harness.state().pending_discard(),
        Some(&raylab::ui::DiscardAction::Quit)
    );
    harness.get_by_label("Cancel").click();
    harness.run();
    assert_eq!(harness.state().pending_discard(), None);
    assert_eq!(
        harness.state().scene().objects.len(),
        7,
        "nothing was dropped"
    );

    // Without unsaved changes the window closes without asking.
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert!(!harness.state().is_dirty());
    close(&mut harness);
    assert_eq!(harness.state().pending_discard(), None);
}

#[test]
fn import_legacy_goes_through_the_adapter_and_keeps_the_scene_on_failure() {
    let dir = temp_dir("legacy");
    let path = dir.join("old.txt");
    std::fs::write(&path, "this is not a legacy scene\n").unwrap();
    let mut harness = harness();
    harness
        .state_mut()
        .push(Command::ImportLegacy(path.clone()));
    harness.run();
    let expected = raylab::ui::files::import_legacy(&path);
    match expected {
        Ok((scene, _)) => assert_eq!(harness.state().scene(), &scene),
        Err(error) => {
            assert_eq!(harness.state().scene(), &default_scene());
            let shown = harness.state().error().expect("the error is shown");
            assert!(shown.contains(&error), "{shown}");
        }
    }
}

#[test]
fn import_legacy_replaces_the_scene_with_the_imported_one() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/legacy/full.txt");
    let imported = raylab::scene::legacy::import_legacy_file(&path).unwrap();
    let mut harness = harness();
    harness.state_mut().push(Command::ImportLegacy(path));
    harness.run();
    assert_eq!(harness.state().scene(), &imported.scene);
    // full.txt has an octahedron, which the importer skips with a warning: it is shown.
    assert!(!imported.warnings.is_empty());
    let shown = harness.state().error().expect("the warnings are shown");
    assert!(shown.contains("Octahedron"), "{shown}");
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
    let before = harness.state().scene().objects[0]
        .transform
        .world_from_object();
    harness
        .get_by_label("Reset to translate/rotate/scale")
        .click();
    harness.run();
    let transform = harness.state().scene().objects[0].transform;
    assert!(matches!(transform, Transform::Trs(_)));
    assert!(transform.world_from_object().abs_diff_eq(before, 1e-12));
    harness.get_by_label("translate x");
}

#[test]
fn ctrl_s_saves_to_the_open_file_and_recent_files_reopen_it() {
    let dir = temp_dir("ctrl-s");
    let path = dir.join("scene.ron");
    save_scene_to(&default_scene(), &path).unwrap();
    let mut harness = harness();
    harness.state_mut().push(Command::Open(path.clone()));
    harness.run();
    select_red_ball(&mut harness);
    harness.get_by_label("scale x").set_value_accesskit(1.5);
    harness.run();
    assert!(harness.state().is_dirty());
    harness.key_press_modifiers(Modifiers::COMMAND, Key::S);
    harness.run();
    assert!(!harness.state().is_dirty());
    assert_eq!(&load_scene(&path).unwrap(), harness.state().scene());

    // File > New, then File > Open Recent > scene.ron brings it back.
    harness.state_mut().push(Command::New);
    harness.run();
    assert_eq!(harness.state().scene(), &new_scene());
    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label("Open Recent").click();
    harness.run();
    harness.get_by_label("scene.ron").click();
    harness.run();
    assert_eq!(&load_scene(&path).unwrap(), harness.state().scene());
}

#[test]
fn a_running_export_can_be_cancelled_and_writes_nothing() {
    let dir = temp_dir("export-cancel");
    let path = dir.join("big.png");
    let mut harness = harness();
    harness.state_mut().push(Command::ShowExport);
    harness.run();
    // Far too much work to finish before the click below.
    harness
        .get_by_label("export width")
        .set_value_accesskit(4000.0);
    harness
        .get_by_label("export height")
        .set_value_accesskit(3000.0);
    harness
        .get_by_label("export samples")
        .set_value_accesskit(4096.0);
    harness.run();
    set_export_path(&mut harness, &path);
    harness.get_by_label("Render and save").click();
    harness.run_ok();
    assert!(harness.state().export().is_running());
    harness.get_by_label("Cancel").click();
    harness.run_ok();
    step_until(&mut harness, "the cancel", |app| !app.export().is_running());
    let status = harness.state().export().status.clone();
    assert_eq!(status, Some(Err("export cancelled".to_owned())));
    assert!(!path.exists());
}

#[test]
fn unsaved_work_of_a_killed_editor_is_offered_and_restored() {
    use raylab::recovery::RecoveryStore;
    let dir = temp_dir("recovery");
    // An editor that died (a pid that cannot be running) left its unsaved scene.
    let mut lost = default_scene();
    lost.objects[0].name = "edited before the crash".to_owned();
    RecoveryStore::with_pid(dir.clone(), u32::MAX - 7)
        .save(&lost, None)
        .unwrap();
    let mut harness = harness_with(EditorOptions {
        recovery: Some(RecoveryStore::new(dir.clone())),
        ..EditorOptions::default()
    });
    assert!(harness.state().has_restore_offer());
    harness.get_by_label("Restore").click();
    harness.run();
    assert!(!harness.state().has_restore_offer());
    assert_eq!(harness.state().scene(), &lost);
    assert!(harness.state().is_dirty(), "restored edits are unsaved");
    // The offer was used up: a new editor in the same folder offers nothing.
    assert!(RecoveryStore::new(dir).orphans().is_empty());
}

#[test]
fn unsaved_edits_reach_the_recovery_file_and_leave_it_on_save() {
    use raylab::recovery::RecoveryStore;
    let dir = temp_dir("autosave");
    let store = RecoveryStore::new(dir.clone());
    let own = store.own_path();
    let mut harness = harness_with(EditorOptions {
        recovery: Some(store),
        ..EditorOptions::default()
    });
    assert!(!own.exists());
    harness.get_by_label("red ball").click();
    harness.run();
    harness.key_press(Key::Delete);
    harness.run();
    assert!(harness.state().is_dirty());
    assert!(own.exists(), "the unsaved edit was written at once");
    harness
        .state_mut()
        .push(Command::SaveAs(dir.join("saved.ron")));
    harness.run();
    harness.run();
    assert!(!harness.state().is_dirty());
    assert!(!own.exists(), "nothing left to recover after a save");
}
