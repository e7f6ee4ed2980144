//! The editor's preview worker with a mesh scene: it reads the mesh files from the
//! scene's folder itself (off the UI thread), keeps them, and so re-shades a material
//! edit without tracing again; a scene never saved has no folder and is refused clearly.

mod common;
mod worker_harness;

use std::path::Path;

use glam::DVec3;
use raylab::preview::{Pass, PreviewRequest};
use raylab::scene::load_scene;
use worker_harness::{next, until_final, worker_with_counter};

fn mesh_request(generation: u64, folder: Option<&Path>) -> PreviewRequest {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut scene = load_scene(&dir.join("mesh.ron")).expect("example");
    scene.camera.width = 320;
    scene.camera.height = 240;
    scene.render.samples_per_pixel = 4;
    PreviewRequest {
        scene_folder: folder.map(Path::to_path_buf),
        ..PreviewRequest::for_scene(generation, scene)
    }
}

#[test]
fn the_worker_reads_meshes_beside_the_scene_and_re_shades_a_material_edit() {
    let (mut worker, _) = worker_with_counter();
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let first = mesh_request(1, Some(&dir));
    worker.submit(first.clone());
    let frames = until_final(&mut worker, 1);
    let passes: Vec<Pass> = frames
        .iter()
        .map(|m| m.result.as_ref().expect("renders").pass)
        .collect();
    assert!(matches!(passes[0], Pass::Coarse { .. }), "{passes:?}");

    let mut edited = (*first.scene).clone();
    edited.materials.get_mut("gold").expect("gold").diffuse = DVec3::new(0.2, 0.2, 0.9);
    let second = PreviewRequest {
        scene: std::sync::Arc::new(edited),
        generation: 2,
        ..first
    };
    worker.submit(second);
    let frames = until_final(&mut worker, 2);
    let first_pass = frames[0].result.as_ref().expect("renders").pass;
    assert!(
        matches!(first_pass, Pass::Full { .. }),
        "the same meshes: re-shaded, not traced coarse first ({first_pass:?})"
    );
}

#[test]
fn a_scene_without_a_folder_is_refused_naming_the_mesh() {
    let (mut worker, _) = worker_with_counter();
    worker.submit(mesh_request(1, None));
    let message = next(&mut worker);
    let error = message.result.expect_err("refused");
    assert!(
        error.contains("\"knot\"") && error.contains("knot.obj"),
        "{error}"
    );
}

#[test]
fn the_worker_shows_the_file_it_reads_and_a_cancel_stops_it_with_a_clear_error() {
    // A mesh file large enough (about 20 MB) that its reading can be seen and stopped.
    let dir = std::env::temp_dir().join(format!("raylab-mesh-cancel-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("folder");
    let text = common::obj::sheet(800, true);
    std::fs::write(dir.join("sheet.obj"), text).expect("write");
    let mut request = mesh_request(1, Some(&dir));
    let mut scene = (*request.scene).clone();
    for object in &mut scene.objects {
        if let raylab::scene::Shape::Mesh { path } = &mut object.shape {
            "sheet.obj".clone_into(path);
        }
    }
    request.scene = std::sync::Arc::new(scene);
    let (mut worker, _) = worker_with_counter();
    worker.submit(request);
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(30);
    let (file, _) = loop {
        if let Some(loading) = worker.loading() {
            break loading;
        }
        assert!(std::time::Instant::now() < deadline, "never seen reading");
        std::thread::yield_now();
    };
    assert_eq!(file, "sheet.obj");
    worker.cancel_loading();
    let error = next(&mut worker).result.expect_err("cancelled");
    assert!(
        error.contains("\"knot\"") && error.contains("sheet.obj") && error.contains("cancelled"),
        "{error}"
    );
    assert!(worker.loading().is_none(), "reading is over");
    let _ = std::fs::remove_dir_all(&dir);
}
