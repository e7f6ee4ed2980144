//! A native file dialog does not freeze the window: while it is open the editor keeps
//! drawing and taking clicks, and the file is written once the user picks a name.
//!
//! The desktop's dialog is replaced by one that answers only when the test says so. Its
//! answer blocks whoever waits for it: were the editor to wait on the UI thread, the
//! click below would not be seen until the dialog gave up (and then with no file).

mod editor_harness;

use std::path::PathBuf;
use std::sync::mpsc;
use std::sync::{Arc, Mutex};
use std::time::Duration;

use editor_harness::{harness_with_file_dialog, step_until, temp_dir};
use egui::{Key, Modifiers};
use egui_kittest::kittest::Queryable;
use raylab::scene::{Shape, load_scene};
use raylab::trace::Term;
use raylab::ui::{
    Command, DialogPurpose, DialogRequest, EditorOptions, NativeDialog, NativeDialogs, SceneEdit,
};

/// How long the stand-in dialog waits for the test before it gives up (as a cancel).
const GIVE_UP: Duration = Duration::from_secs(20);

#[test]
fn the_window_keeps_working_while_a_native_save_dialog_is_open() {
    let dir = temp_dir("native-dialog");
    let (answer, answers) = mpsc::channel::<PathBuf>();
    let answers = Arc::new(Mutex::new(answers));
    let asked: Arc<Mutex<Vec<DialogRequest>>> = Arc::default();
    let dialog: NativeDialog = {
        let asked = asked.clone();
        Arc::new(move |request: &DialogRequest| {
            asked.lock().unwrap().push(request.clone());
            let answers = answers.clone();
            Box::pin(async move { answers.lock().unwrap().recv_timeout(GIVE_UP).ok() })
        })
    };
    let mut harness = harness_with_file_dialog(EditorOptions {
        native_dialogs: NativeDialogs::Given(dialog),
        dialog_folder: Some(dir.clone()),
        ..EditorOptions::default()
    });
    assert!(!harness.state().tools().file_dialogs.uses_in_app());
    harness.state_mut().push(Command::New);
    harness.run();
    harness
        .state_mut()
        .push(Command::Edit(SceneEdit::AddObject(Shape::Cube)));
    harness.run();

    harness.key_press_modifiers(Modifiers::COMMAND | Modifiers::SHIFT, Key::S);
    harness.run();
    assert_eq!(
        harness.state().tools().file_dialogs.open_purpose(),
        Some(DialogPurpose::SaveSceneAs)
    );
    assert_eq!(
        *asked.lock().unwrap(),
        vec![DialogRequest {
            purpose: DialogPurpose::SaveSceneAs,
            folder: dir.clone(),
            file_name: "untitled.ron".to_owned(),
        }]
    );

    // The dialog is open and has not answered: the editor still takes a click.
    assert!(
        harness
            .state()
            .view()
            .preview_settings
            .switches
            .is_on(Term::Diffuse)
    );
    harness
        .get_by_role_and_label(egui::accesskit::Role::Button, "diffuse")
        .click();
    harness.run();
    assert!(
        !harness
            .state()
            .view()
            .preview_settings
            .switches
            .is_on(Term::Diffuse),
        "the click reached the editor while the dialog was open"
    );
    assert!(
        harness
            .state()
            .tools()
            .file_dialogs
            .open_purpose()
            .is_some()
    );

    // The user picks a name: the scene is written there.
    let picked = dir.join("picked.ron");
    answer.send(picked.clone()).unwrap();
    step_until(&mut harness, "the save to the picked file", |app| {
        app.path() == Some(picked.as_path())
    });
    assert!(!harness.state().document().is_dirty());
    let saved = load_scene(&picked).unwrap();
    assert_eq!(saved.objects.len(), 1);
    assert_eq!(saved.objects[0].shape, Shape::Cube);
    assert_eq!(harness.state().tools().file_dialogs.open_purpose(), None);
}

#[test]
fn a_dialog_opens_in_the_folder_a_file_was_last_picked_from() {
    let start = temp_dir("dialog-start");
    let course = temp_dir("dialog-course");
    std::fs::copy(
        concat!(env!("CARGO_MANIFEST_DIR"), "/tests/legacy/full.txt"),
        course.join("full.txt"),
    )
    .unwrap();
    let picks = Arc::new(Mutex::new(vec![course.join("full.txt")]));
    let asked: Arc<Mutex<Vec<DialogRequest>>> = Arc::default();
    let dialog: NativeDialog = {
        let asked = asked.clone();
        let picks = picks.clone();
        Arc::new(move |request: &DialogRequest| {
            asked.lock().unwrap().push(request.clone());
            let pick = picks.lock().unwrap().pop();
            Box::pin(async move { pick })
        })
    };
    let mut harness = harness_with_file_dialog(EditorOptions {
        native_dialogs: NativeDialogs::Given(dialog),
        dialog_folder: Some(start.clone()),
        ..EditorOptions::default()
    });
    // An imported course scene has no file of its own: the next dialog opens where it
    // was picked, not in the start folder.
    harness.state_mut().push(Command::ImportLegacyDialog);
    harness.run();
    step_until(&mut harness, "the import", |app| {
        app.document().scene.objects.len() > 1 && app.tools().file_dialogs.open_purpose().is_none()
    });
    assert_eq!(harness.state().path(), None, "an import is untitled");
    harness.state_mut().push(Command::OpenDialog);
    harness.run();
    // The import is unsaved: the editor first asks what to do with it.
    if let Some(discard) = harness.query_by_label("Discard") {
        discard.click();
        harness.run();
    }
    let folders: Vec<PathBuf> = asked
        .lock()
        .unwrap()
        .iter()
        .map(|r| r.folder.clone())
        .collect();
    assert_eq!(folders, vec![start, course]);
}
