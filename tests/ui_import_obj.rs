//! File > Import OBJ Mesh…: the file picked joins the scene as a Mesh object named after
//! it, in one undo step; the scene refers to the file relative to its own folder where
//! it can, in full otherwise (a scene never saved), and never rewrites it.

mod common;
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
    let before = harness.state().document().scene.clone();
    harness.state_mut().push(Command::ImportObjDialog);
    harness.run();
    step_until(&mut harness, "the import", |app| {
        app.document().scene.objects.len() == before.objects.len() + 1
    });
    assert_eq!(asked.lock().unwrap()[0].purpose, DialogPurpose::ImportObj);
    let added = harness
        .state()
        .document()
        .scene
        .objects
        .last()
        .unwrap()
        .clone();
    assert_eq!(added.name, "pyramid");
    // The default scene has no folder: the path is written in full.
    assert_eq!(
        added.shape,
        Shape::Mesh {
            path: obj.to_str().unwrap().to_owned()
        }
    );
    assert_eq!(
        &harness.state().document().selection,
        &raylab::ui::Selection::Object(before.objects.len())
    );
    harness.state_mut().push(Command::Undo);
    harness.run();
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "one undo takes it away"
    );
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
    let added = harness.state().document().scene.objects.last().unwrap();
    assert_eq!(
        added.shape,
        Shape::Mesh {
            path: "pyramid.obj".to_owned()
        }
    );
}

#[test]
fn a_large_mesh_shows_its_reading_in_the_status_bar_and_cancel_stops_it_with_a_message() {
    use egui_kittest::kittest::Queryable;
    // About 50 MB of quads: reading it takes long enough to be seen and stopped.
    let dir = std::env::temp_dir().join(format!("raylab-ui-obj-cancel-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let text = common::obj::sheet(1000, false);
    let obj = dir.join("sheet.obj");
    std::fs::write(&obj, text).unwrap();
    let mut harness = harness_with_preview();
    harness.state_mut().push(Command::ImportObj(obj));
    harness.run_ok();
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(60);
    while harness.query_by_label("reading sheet.obj").is_none() {
        assert!(
            std::time::Instant::now() < deadline,
            "the reading never showed"
        );
        harness.step();
    }
    harness.get_by_label("Cancel").click();
    step_until(&mut harness, "the cancel", |_| true);
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(60);
    while harness
        .query_by_label_contains("loading was cancelled")
        .is_none()
    {
        assert!(
            std::time::Instant::now() < deadline,
            "no message after the cancel"
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
        harness.step();
    }
    let message = format!(
        "{:?}",
        harness.get_by_label_contains("loading was cancelled")
    );
    assert!(
        message.contains("object \\\"sheet\\\"") && message.contains("undo"),
        "{message}"
    );
    assert!(harness.query_by_label("reading sheet.obj").is_none());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_inspector_shows_a_read_mesh_s_file_triangles_and_bounds() {
    use egui_kittest::kittest::Queryable;
    let mut harness = harness_with_preview();
    harness
        .state_mut()
        .push(Command::ImportObj(scenes().join("pyramid.obj")));
    harness.run_ok();
    // Selected on import; the file's facts come once the preview has read it.
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(60);
    while harness
        .query_by_label_contains("closed (a solid)")
        .is_none()
    {
        assert!(
            std::time::Instant::now() < deadline,
            "the facts never showed"
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
        harness.step();
    }
    // Four sides and a quad base fanned into two.
    harness.get_by_label("6 · closed (a solid)");
    harness.get_by_label("pyramid.obj");
    let bounds = format!("{:?}", harness.get_by_label_contains("x -1.000…1.000"));
    assert!(
        bounds.contains("y 0.000…1.400") && bounds.contains("z -1.000…1.000"),
        "{bounds}"
    );
}

/// The editor on the default scene with its preview running.
fn harness_with_preview() -> egui_kittest::Harness<'static, raylab::ui::EditorApp> {
    let mut harness = editor_harness::editor_harness(
        EditorOptions {
            preview: true,
            ..EditorOptions::default()
        },
        egui::Vec2::new(1280.0, 800.0),
        64,
    );
    harness.run_ok();
    harness
}

/// The object added last, as its translate/rotate/scale.
fn last_trs(app: &raylab::ui::EditorApp) -> raylab::scene::Trs {
    match app.document().scene.objects.last().unwrap().transform {
        raylab::scene::Transform::Trs(trs) => trs,
        raylab::scene::Transform::Matrix(_) => panic!("an import places by translate/rotate/scale"),
    }
}

#[test]
fn an_imported_obj_gets_a_material_of_its_own() {
    let mut harness = harness_with_preview();
    let before = harness.state().document().scene.clone();
    harness
        .state_mut()
        .push(Command::ImportObj(scenes().join("pyramid.obj")));
    harness.run();
    let scene = &harness.state().document().scene;
    let added = scene.objects.last().unwrap();
    assert!(
        !before.materials.contains_key(&added.material),
        "a new material, not the first in the list ({})",
        added.material
    );
    let users = scene
        .objects
        .iter()
        .filter(|o| o.material == added.material)
        .count();
    assert_eq!(users, 1, "recolouring the mesh recolours nothing else");
}

#[test]
fn an_imported_obj_is_fitted_to_a_unit_box_as_its_own_undo_step() {
    use egui_kittest::kittest::Queryable;
    let mut harness = harness_with_preview();
    harness
        .state_mut()
        .push(Command::ImportObj(scenes().join("pyramid.obj")));
    harness.run_ok();
    // The pyramid is 2 wide and deep, 1.4 tall: its largest side becomes 1.
    let half = glam::DVec3::splat(0.5);
    step_until(&mut harness, "the fit", |app| last_trs(app).scale == half);
    let fitted = last_trs(harness.state());
    harness.get_by_label_contains("2.00 × 1.40 × 2.00");
    harness.get_by_label("2.000 × 1.400 × 2.000"); // the inspector's Size row
    let objects = harness.state().document().scene.objects.len();
    harness.state_mut().push(Command::Undo);
    harness.run();
    let placed = last_trs(harness.state());
    assert_eq!(
        harness.state().document().scene.objects.len(),
        objects,
        "the mesh stays"
    );
    assert_ne!(placed.scale, half, "Undo gives back the file's size");
    assert_eq!(
        fitted.translate, placed.translate,
        "the fit keeps its place"
    );
    harness.state_mut().push(Command::Redo);
    harness.run();
    assert_eq!(last_trs(harness.state()), fitted);
}

#[test]
fn with_the_fit_off_an_imported_obj_keeps_its_files_size() {
    use egui_kittest::kittest::Queryable;
    let mut harness = harness_with_preview();
    harness.get_by_label("File").click();
    harness.run();
    harness
        .get_by_label("Fit Imported Meshes to a Unit Box")
        .click();
    harness.run();
    harness
        .state_mut()
        .push(Command::ImportObj(scenes().join("pyramid.obj")));
    harness.run_ok();
    let placed = last_trs(harness.state());
    // Once the inspector shows the file's size, the preview has read it: no fit came.
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(60);
    while harness.query_by_label("2.000 × 1.400 × 2.000").is_none() {
        assert!(
            std::time::Instant::now() < deadline,
            "the facts never showed"
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
        harness.step();
    }
    harness.run_ok();
    assert_eq!(last_trs(harness.state()), placed);
}

#[test]
fn a_mesh_imported_before_the_first_save_is_saved_relative_to_the_scene() {
    let dir = std::env::temp_dir().join(format!("raylab-ui-obj-relative-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("models")).unwrap();
    let obj = dir.join("models").join("pyramid.obj");
    std::fs::copy(scenes().join("pyramid.obj"), &obj).unwrap();
    let (dialog, _) = dialog_picking(obj.clone());
    let mut harness = harness_with_file_dialog(EditorOptions {
        native_dialogs: NativeDialogs::Given(dialog),
        ..EditorOptions::default()
    });
    harness.state_mut().push(Command::ImportObj(obj.clone()));
    harness.run();
    let Shape::Mesh { path } = &harness
        .state()
        .document()
        .scene
        .objects
        .last()
        .unwrap()
        .shape
    else {
        panic!("a mesh");
    };
    assert_eq!(path, obj.to_str().unwrap(), "no folder yet: in full");
    let saved = dir.join("scene.ron");
    harness.state_mut().push(Command::SaveAs(saved.clone()));
    harness.run();
    let loaded = raylab::scene::load_scene(&saved).unwrap();
    assert_eq!(
        loaded.objects.last().unwrap().shape,
        Shape::Mesh {
            path: "models/pyramid.obj".to_owned()
        }
    );
    assert!(
        !harness.state().document().is_dirty(),
        "the scene is what was saved"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
