//! File > Export Course Scene… in the editor, through the in-app file dialog: the scene
//! is written in the course's text format (and imports back), what the dialect loses is
//! shown as a warning, and a scene the 2016 dialect cannot say shows each refusal as the
//! error and writes nothing.

mod editor_harness;

use std::path::Path;

use editor_harness::{harness_with_file_dialog, temp_dir};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use raylab::scene::Shape;
use raylab::scene::legacy::{Dialect, import_legacy_file};
use raylab::ui::{
    Command, DialogPurpose, EditorApp, EditorOptions, LightKind, NativeDialogs, SceneEdit,
};

/// The editor on a desktop with no native file dialog; dialogs open in `dir`.
fn harness_in(dir: &Path) -> Harness<'static, EditorApp> {
    harness_with_file_dialog(EditorOptions {
        native_dialogs: NativeDialogs::Unavailable,
        dialog_folder: Some(dir.to_owned()),
        ..EditorOptions::default()
    })
}

fn menu(harness: &mut Harness<'_, EditorApp>, entry: &str) {
    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label(entry).click();
    harness.run();
}

#[test]
fn export_course_scene_writes_the_course_format_and_shows_what_is_lost() {
    let dir = temp_dir("course-export");
    let mut harness = harness_in(&dir);
    harness.state_mut().push(Command::New);
    harness.run();
    harness
        .state_mut()
        .push(Command::Edit(SceneEdit::AddObject(Shape::Cone)));
    harness
        .state_mut()
        .push(Command::Edit(SceneEdit::AddLight(LightKind::Spot)));
    harness.run();
    let path = dir.join("untitled.txt");

    // The 2016 framework has point lights only: refused by name, nothing written.
    menu(&mut harness, "Export Course Scene (2016)…");
    assert_eq!(
        harness.state().tools().file_dialogs.open_purpose(),
        Some(DialogPurpose::ExportCourse(Dialect::Framework2016))
    );
    harness.get_by_label("Save").click();
    harness.run();
    harness.get_by_label_contains("light 2 (Spot): the 2016 framework has point lights only");
    assert!(!path.exists());
    harness.get_by_label("Dismiss").click();
    harness.run();

    // The 2020 dialect says it all, but not the render conventions: a warning says so.
    menu(&mut harness, "Export Course Scene…");
    assert_eq!(
        harness.state().tools().file_dialogs.open_purpose(),
        Some(DialogPurpose::ExportCourse(Dialect::Framework2020))
    );
    harness.get_by_label("Save").click();
    harness.run();
    harness
        .get_by_label_contains("Exported with warnings: render settings: the render conventions");
    let back = import_legacy_file(&path).expect("the export imports").scene;
    let scene = &harness.state().document().scene;
    assert_eq!(back.objects, scene.objects);
    assert_eq!(back.materials, scene.materials);
    assert_eq!(back.lights.len(), scene.lights.len());
    assert_eq!(back.objects.len(), 1);
    assert_eq!(
        harness.state().path(),
        None,
        "the export is not the scene's file"
    );
}
