//! File > Import OBJ Mesh…: the file picked joins the scene as a Mesh object named after
//! it, in one undo step; the scene refers to the file relative to its own folder where
//! it can, in full otherwise (a scene never saved), and never rewrites it.

mod editor_harness;

use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use editor_harness::{harness_with_file_dialog, step_until};
use raylab::scene::Shape;
use raylab::ui::{
    Command, DialogPurpose, DialogRequest, EditorOptions, NativeDialog, NativeDialogs,
};

/// A desktop dialog that picks `file` and records what it was asked.
fn dialog_picking(file: PathBuf) -> (NativeDialog, Arc<Mutex<Vec<DialogRequest>>>) {
    let asked: Arc<Mutex<Vec<DialogRequest>>> = Arc::default();
    let recorded = asked.clone();
    let dialog: NativeDialog = Arc::new(move |request: &DialogRequest| {
        recorded.lock().unwrap().push(request.clone());
        let file = file.clone();
        Box::pin(async move { Some(file) })
    });
    (dialog, asked)
}

fn scenes() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes")
}

#[test]
fn an_imported_obj_is_a_mesh_object_named_after_its_file_in_one_undo_step() {
    let obj = scenes().join("pyramid.obj");
    let (dialog, asked) = dialog_picking(obj.clone());
    let mut harness = harness_with_file_dialog(EditorOptions {
        native_dialogs: NativeDialogs::Given(dialog),
        ..EditorOptions::default()
    });
    let before = harness.state().scene().clone();
    harness.state_mut().push(Command::ImportObjDialog);
    harness.run();
    step_until(&mut harness, "the import", |app| {
        app.scene().objects.len() == before.objects.len() + 1
    });
    assert_eq!(asked.lock().unwrap()[0].purpose, DialogPurpose::ImportObj);
    let added = harness.state().scene().objects.last().unwrap().clone();
    assert_eq!(added.name, "pyramid");
    // The default scene has no folder: the path is written in full.
    assert_eq!(
        added.shape,
        Shape::Mesh {
            path: obj.to_str().unwrap().to_owned()
        }
    );
    assert_eq!(
        harness.state().selection(),
        &raylab::ui::Selection::Object(before.objects.len())
    );
    harness.state_mut().push(Command::Undo);
    harness.run();
    assert_eq!(harness.state().scene(), &before, "one undo takes it away");
}

#[test]
fn a_mesh_beside_the_scene_is_written_relative_to_the_scenes_folder() {
    let (dialog, _) = dialog_picking(scenes().join("pyramid.obj"));
    let mut harness = harness_with_file_dialog(EditorOptions {
        native_dialogs: NativeDialogs::Given(dialog),
        ..EditorOptions::default()
    });
    harness
        .state_mut()
        .push(Command::Open(scenes().join("glass.ron")));
    harness.run();
    harness
        .state_mut()
        .push(Command::ImportObj(scenes().join("pyramid.obj")));
    harness.run();
    let added = harness.state().scene().objects.last().unwrap();
    assert_eq!(
        added.shape,
        Shape::Mesh {
            path: "pyramid.obj".to_owned()
        }
    );
}
