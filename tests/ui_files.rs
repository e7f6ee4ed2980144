//! Files through the editor, with no window: open (and its errors), save, save as, new,
//! dropped files, the close question, legacy import, recent files. Dialogs pick a path
//! and call what these commands call; the in-app dialog is driven in ui_dialogs.rs.

mod editor_harness;

use editor_harness::{close_window, drop_file, harness, select_red_ball, temp_dir};
use egui::{Key, Modifiers};
use egui_kittest::kittest::Queryable;
use raylab::scene::load_scene;
use raylab::ui::files::{default_scene, new_scene, open_scene, save_scene_to};
use raylab::ui::{Command, SceneEdit};

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
    let edited = harness.state().document().scene.clone();

    harness.state_mut().push(Command::Open(path.clone()));
    harness.run();
    // Unsaved changes: the editor asks first.
    harness.get_by_label("Discard").click();
    harness.run();

    assert_eq!(
        &harness.state().document().scene,
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
    assert!(harness.state().document().is_dirty());

    harness.state_mut().push(Command::SaveAs(path.clone()));
    harness.run();
    assert!(!harness.state().document().is_dirty());
    assert_eq!(harness.state().path(), Some(path.as_path()));
    assert_eq!(harness.state().title(), "edited.ron — raylab");
    assert_eq!(
        &load_scene(&path).unwrap(),
        &harness.state().document().scene
    );
    let Ok(raylab::ui::files::Opened::Scene(opened)) = open_scene(&path) else {
        panic!("a saved scene opens as a scene");
    };
    assert_eq!(opened.as_ref(), &harness.state().document().scene);
    assert_eq!(
        harness.state().recent().paths()[0],
        std::fs::canonicalize(&path).unwrap()
    );

    let saved = harness.state().document().scene.clone();
    let mut other = self::harness();
    other.state_mut().push(Command::Open(path.clone()));
    other.run();
    assert_eq!(&other.state().document().scene, &saved);
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
    assert!(harness.state().document().is_dirty());
    assert_eq!(harness.state().path(), None);
    assert!(save_scene_to(&harness.state().document().scene, &path).is_err());
    assert!(!path.exists());
}

#[test]
fn new_asks_before_dropping_changes() {
    let mut harness = harness();
    select_red_ball(&mut harness);
    harness.get_by_label("translate y").set_value_accesskit(3.0);
    harness.run();
    let edited = harness.state().document().scene.clone();

    harness.key_press_modifiers(Modifiers::COMMAND, Key::N);
    harness.run();
    harness.get_by_label("Cancel").click();
    harness.run();
    assert_eq!(&harness.state().document().scene, &edited);

    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label("New").click();
    harness.run();
    harness.get_by_label("Discard").click();
    harness.run();
    assert_eq!(&harness.state().document().scene, &new_scene());
    assert_eq!(harness.state().title(), "untitled — raylab");
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
    assert_eq!(&harness.state().document().scene, &default_scene());

    drop_file(&mut harness, &path);
    assert_eq!(&harness.state().document().scene, &scene);
    assert_eq!(harness.state().path(), Some(path.as_path()));
}

#[test]
fn closing_the_window_with_unsaved_changes_asks_first() {
    let mut harness = harness();
    harness.state_mut().push(Command::Edit(SceneEdit::AddObject(
        raylab::scene::Shape::Cube,
    )));
    harness.run();
    close_window(&mut harness);
    assert_eq!(
        harness.state().pending_discard(),
        Some(&raylab::ui::DiscardAction::Quit)
    );
    harness.get_by_label("Cancel").click();
    harness.run();
    assert_eq!(harness.state().pending_discard(), None);
    assert_eq!(
        harness.state().document().scene.objects.len(),
        7,
        "nothing was dropped"
    );

    // Without unsaved changes the window closes without asking.
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
    assert!(!harness.state().document().is_dirty());
    close_window(&mut harness);
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
        Ok((scene, _, _)) => assert_eq!(&harness.state().document().scene, &scene),
        Err(error) => {
            assert_eq!(&harness.state().document().scene, &default_scene());
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
    assert_eq!(&harness.state().document().scene, &imported.scene);
    // The status line names the imported file, not the last file saved.
    harness.get_by_label_contains("full.txt (not saved yet)");
    // ... and which framework's dialect was read.
    harness.get_by_label_contains("read as the 2020 framework's dialect");
    // full.txt imports cleanly (its octahedron too); a file with something to warn about
    // shows it as a warning, in its own banner, not as a failure.
    assert!(imported.warnings.is_empty(), "{:?}", imported.warnings);
    let mut harness = self::harness();
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/legacy/spot_without_angle.txt");
    harness.state_mut().push(Command::ImportLegacy(path));
    harness.run();
    assert_eq!(harness.state().error(), None, "a warning is not an error");
    let shown = harness.state().warning().expect("the warnings are shown");
    assert!(shown.contains("without `Angle`"), "{shown}");
    harness.get_by_label_contains("without `Angle`");
    harness.get_by_label("Dismiss warning").click();
    harness.run();
    assert_eq!(harness.state().warning(), None);
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
    assert!(harness.state().document().is_dirty());
    harness.key_press_modifiers(Modifiers::COMMAND, Key::S);
    harness.run();
    assert!(!harness.state().document().is_dirty());
    assert_eq!(
        &load_scene(&path).unwrap(),
        &harness.state().document().scene
    );

    // File > New, then File > Open Recent > scene.ron brings it back.
    harness.state_mut().push(Command::New);
    harness.run();
    assert_eq!(&harness.state().document().scene, &new_scene());
    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label("Open Recent").click();
    harness.run();
    harness.get_by_label("scene.ron").click();
    harness.run();
    assert_eq!(
        &load_scene(&path).unwrap(),
        &harness.state().document().scene
    );
}

#[test]
fn a_recent_file_that_fails_to_open_stays_in_the_list_marked() {
    let dir = temp_dir("recent-gone");
    let path = dir.join("away.ron");
    save_scene_to(&default_scene(), &path).unwrap();
    let mut harness = harness();
    harness.state_mut().push(Command::Open(path.clone()));
    harness.run();
    let listed = std::fs::canonicalize(&path).unwrap();
    // The file goes away (an unplugged drive, a share that is down) and the open fails.
    std::fs::remove_file(&path).unwrap();
    harness.state_mut().push(Command::Open(path.clone()));
    harness.run();
    assert!(harness.state().error().is_some(), "the failure is shown");
    assert_eq!(
        harness.state().recent().paths(),
        std::slice::from_ref(&listed)
    );
    assert!(harness.state().recent().has_failed(&listed));
    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label("Open Recent").click();
    harness.run();
    harness.get_by_label("away.ron (could not open)");

    // Back again: it opens from the list and loses its mark.
    save_scene_to(&new_scene(), &path).unwrap();
    harness.get_by_label("away.ron (could not open)").click();
    harness.run();
    assert_eq!(&harness.state().document().scene, &new_scene());
    assert!(!harness.state().recent().has_failed(&listed));
}

#[test]
fn open_on_a_course_text_scene_imports_it_and_other_files_get_a_plain_message() {
    // Ctrl+O, as a newcomer does, on the course's .txt (and on one renamed .scene: the
    // content decides, not the name).
    let source = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/legacy/full.txt");
    let imported = raylab::scene::legacy::import_legacy_file(&source).unwrap();
    let dir = temp_dir("open_txt");
    let renamed = dir.join("full.scene");
    std::fs::copy(&source, &renamed).unwrap();
    for path in [source.clone(), renamed] {
        let mut harness = harness();
        harness.state_mut().push(Command::Open(path.clone()));
        harness.run();
        assert_eq!(harness.state().error(), None);
        assert_eq!(
            harness.state().document().scene.objects,
            imported.scene.objects
        );
        harness.get_by_label_contains("(not saved yet)");
    }
    // A README is neither: the message says what raylab opens, not a parser's words alone.
    let readme = dir.join("README.md");
    std::fs::write(&readme, "# My tracer\n\nRun make, then ./ray scene.txt\n").unwrap();
    let mut harness = harness();
    harness.state_mut().push(Command::Open(readme));
    harness.run();
    let error = harness
        .state()
        .error()
        .expect("an error is shown")
        .to_owned();
    assert!(
        error.contains("is neither a raylab scene nor a course text scene"),
        "{error}"
    );
    assert!(
        error.contains("it starts \u{201c}# My tracer\u{201d}"),
        "{error}"
    );
    assert!(
        !error.contains("enable"),
        "no RON parser words for a file that is not RON: {error}"
    );
    assert!(error.contains("File > Import Legacy"), "{error}");
}
