//! The in-app file dialog, as a person on a desktop without a native one (no xdg portal,
//! no zenity) meets it: Save As of an untitled scene writes the file, the unsaved-changes
//! question offers Save, Open and Export's Browse go through the same dialog, and a
//! cancelled dialog does nothing.

mod editor_harness;

use std::path::Path;

use editor_harness::{close_window, harness_with_file_dialog, temp_dir};
use egui::{Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use raylab::scene::{Shape, load_scene};
use raylab::ui::files::{new_scene, save_scene_to};
use raylab::ui::{Command, DialogPurpose, EditorApp, EditorOptions, NativeDialogs, SceneEdit};

/// The editor on a desktop with no native file dialog; dialogs open in `dir`.
fn harness_in(dir: &Path) -> Harness<'static, EditorApp> {
    harness_with_file_dialog(EditorOptions {
        native_dialogs: NativeDialogs::Unavailable,
        dialog_folder: Some(dir.to_owned()),
        ..EditorOptions::default()
    })
}

/// An untitled scene with one unsaved edit.
fn untitled_and_edited(harness: &mut Harness<'_, EditorApp>) {
    harness.state_mut().push(Command::New);
    harness.run();
    harness
        .state_mut()
        .push(Command::Edit(SceneEdit::AddObject(Shape::Sphere)));
    harness.run();
    assert!(harness.state().document().is_dirty());
    assert_eq!(harness.state().path(), None);
}

/// The dialog's file name field, holding the suggested name (its text run holds it too).
fn file_name_field<'h>(harness: &'h Harness<'_, EditorApp>) -> egui_kittest::Node<'h> {
    harness.get_by(|node| {
        node.role() == egui::accesskit::Role::TextInput
            && node.value().as_deref() == Some("untitled.ron")
    })
}

fn menu(harness: &mut Harness<'_, EditorApp>, entry: &str) {
    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label(entry).click();
    harness.run();
}

#[test]
fn save_as_of_an_untitled_scene_without_native_dialogs_writes_the_file() {
    let dir = temp_dir("dialog-save-as");
    let mut harness = harness_in(&dir);
    assert!(harness.state().tools().file_dialogs.uses_in_app());
    untitled_and_edited(&mut harness);
    menu(&mut harness, "Save As…");
    assert_eq!(
        harness.state().tools().file_dialogs.open_purpose(),
        Some(DialogPurpose::SaveSceneAs)
    );
    // The name is suggested; the user types another one, without the extension.
    file_name_field(&harness).focus();
    harness.run();
    harness.key_combination_modifiers(Modifiers::COMMAND, &[Key::A]);
    file_name_field(&harness).type_text("my scene");
    harness.run();
    harness.get_by_label("Save").click();
    harness.run();

    let path = dir.join("my scene.ron");
    assert_eq!(
        &load_scene(&path).unwrap(),
        &harness.state().document().scene
    );
    assert_eq!(harness.state().path(), Some(path.as_path()));
    assert!(!harness.state().document().is_dirty());
    assert_eq!(harness.state().title(), "my scene.ron — raylab");
    assert_eq!(harness.state().tools().file_dialogs.open_purpose(), None);
}

#[test]
fn save_in_the_quit_question_saves_an_untitled_scene_then_quits() {
    let dir = temp_dir("dialog-quit-save");
    let mut harness = harness_in(&dir);
    untitled_and_edited(&mut harness);
    close_window(&mut harness);
    harness.get_by_label("Save").click();
    harness.run();
    // No file yet: the dialog asks for one; the window closes once it is written.
    assert!(!harness.state().is_closing());
    harness.get_by_label("Save").click();
    harness.run();
    let path = dir.join("untitled.ron");
    assert_eq!(
        &load_scene(&path).unwrap(),
        &harness.state().document().scene
    );
    assert!(harness.state().is_closing());
}

#[test]
fn a_cancelled_save_dialog_cancels_the_quit() {
    let dir = temp_dir("dialog-quit-cancel");
    let mut harness = harness_in(&dir);
    untitled_and_edited(&mut harness);
    close_window(&mut harness);
    harness.get_by_label("Save").click();
    harness.run();
    harness.get_by_label("Cancel").click();
    harness.run();
    assert!(!harness.state().is_closing());
    assert!(harness.state().document().is_dirty());
    assert_eq!(harness.state().error(), None);
    assert!(
        std::fs::read_dir(&dir).unwrap().next().is_none(),
        "nothing written"
    );
}

#[test]
fn discard_in_the_new_question_drops_the_changes() {
    let dir = temp_dir("dialog-new-discard");
    let mut harness = harness_in(&dir);
    harness
        .state_mut()
        .push(Command::Edit(SceneEdit::AddObject(Shape::Cube)));
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::N);
    harness.run();
    harness.get_by_label("Save");
    harness.get_by_label("Discard").click();
    harness.run();
    assert_eq!(&harness.state().document().scene, &new_scene());
}

#[test]
fn open_and_export_browse_use_the_in_app_dialog() {
    let dir = temp_dir("dialog-open");
    let mut scene = new_scene();
    scene.camera.fov_deg = 61.0;
    save_scene_to(&scene, &dir.join("other.ron")).unwrap();
    let mut harness = harness_in(&dir);
    menu(&mut harness, "Open…");
    harness.get_by_label_contains("other.ron").click();
    harness.run();
    harness.get_by_label("Open").click();
    harness.run();
    assert_eq!(&harness.state().document().scene, &scene);
    assert_eq!(
        harness.state().path(),
        Some(dir.join("other.ron").as_path())
    );

    harness.state_mut().push(Command::ShowExport);
    harness.run();
    harness.get_by_label("Browse…").click();
    harness.run();
    assert_eq!(
        harness.state().tools().file_dialogs.open_purpose(),
        Some(DialogPurpose::ExportPng)
    );
    harness.get_by_label("Save").click();
    harness.run();
    // The export proposes the scene's name in the last export folder, else the user's
    // pictures or home folder: never beside the scene (issue 51, point 5).
    let proposed = std::path::PathBuf::from(&harness.state().tools().export.path);
    assert_eq!(
        proposed.file_name(),
        Some(std::ffi::OsStr::new("other.png"))
    );
    assert_ne!(
        proposed.parent(),
        Some(dir.as_path()),
        "{}",
        proposed.display()
    );
}

#[test]
fn compare_with_images_browse_uses_the_in_app_dialog_and_fills_the_path() {
    let dir = temp_dir("dialog-compare");
    image::RgbImage::new(4, 3)
        .save(dir.join("theirs.png"))
        .unwrap();
    let mut harness = harness_in(&dir);
    harness.state_mut().push(Command::ShowCompare);
    harness.run();
    harness.get_by_label("Browse…").click();
    harness.run();
    assert_eq!(
        harness.state().tools().file_dialogs.open_purpose(),
        Some(DialogPurpose::CompareImage),
        "never a blocking native call that may show nothing"
    );
    harness.get_by_label_contains("theirs.png").click();
    harness.run();
    harness.get_by_label("Open").click();
    harness.run();
    assert_eq!(
        harness.state().tools().compare.path_text,
        dir.join("theirs.png").display().to_string()
    );
}

/// The in-app dialog's file name field (the other text field holds a folder path).
fn name_field<'h>(harness: &'h Harness<'_, EditorApp>) -> egui_kittest::Node<'h> {
    harness.get_by(|node| {
        node.role() == egui::accesskit::Role::TextInput
            && !node.value().unwrap_or_default().contains('/')
    })
}

/// Replaces the file name field's text with `name`, as a person selecting it all and
/// typing would.
fn type_name(harness: &mut Harness<'_, EditorApp>, name: &str) {
    name_field(harness).focus();
    harness.run();
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    harness.run();
    name_field(harness).type_text(name);
    harness.run();
}

#[test]
fn a_file_name_typed_into_the_open_dialog_is_the_file_opened() {
    let dir = temp_dir("dialog-typed");
    let mut scene = new_scene();
    scene.camera.fov_deg = 47.0;
    save_scene_to(&scene, &dir.join("typed.ron")).unwrap();
    save_scene_to(&new_scene(), &dir.join("clicked.ron")).unwrap();
    let mut harness = harness_in(&dir);
    menu(&mut harness, "Open…");
    // A file clicked in the list, then another name typed: the typed one opens.
    harness.get_by_label_contains("clicked.ron").click();
    harness.run();
    type_name(&mut harness, "typed.ron");
    harness.get_by_label("Open").click();
    harness.run();
    assert_eq!(
        harness.state().path(),
        Some(dir.join("typed.ron").as_path())
    );
    assert_eq!(&harness.state().document().scene, &scene);
    // A typed name that is not there: a message, and the open scene stays.
    menu(&mut harness, "Open…");
    type_name(&mut harness, "nothing.ron");
    harness.get_by_label("Open").click();
    harness.run();
    assert_eq!(
        harness.state().path(),
        Some(dir.join("typed.ron").as_path())
    );
    let error = harness.state().error().unwrap_or_default().to_owned();
    assert!(error.contains("nothing.ron"), "{error}");
}
