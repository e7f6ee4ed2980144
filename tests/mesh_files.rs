//! Reading OBJ files for `Shape::Mesh`: what a good file gives, and hostile files
//! (missing, huge, out-of-range indices, NaN or 1e300 coordinates, zero-area triangles,
//! garbage) refused with the file's name and line, or skipped with a warning.

mod common;

use std::path::PathBuf;

use raylab::scene::{Shape, load_obj, parse_scene, read_scene_meshes};

/// A fresh folder for one test's files.
fn folder(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raylab-mesh-files-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp folder");
    dir
}

fn write(test: &str, name: &str, text: &str) -> PathBuf {
    let path = folder(test).join(name);
    std::fs::write(&path, text).expect("write");
    path
}

fn error(test: &str, text: &str) -> String {
    let path = write(test, "bad.obj", text);
    load_obj(&path).expect_err("refused").to_string()
}

#[test]
fn the_example_pyramid_fans_its_quad_and_resolves_negative_indices() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes/pyramid.obj");
    let mesh = load_obj(&path).expect("loads");
    assert_eq!(mesh.triangles.len(), 6, "4 sides and a quad fanned into 2");
    assert!(mesh.normals.is_empty(), "the file has no normals");
    // The first side face is `f -5 -1 -4`: vertices 1, 5 and 2 of the file.
    let first = mesh.triangles[0].map(|i| mesh.positions[i as usize]);
    assert_eq!(
        first,
        [[-1.0, 0.0, -1.0], [0.0, 1.4, 0.0], [1.0, 0.0, -1.0]]
    );
    assert_eq!(mesh.warnings.len(), 1, "one warning: {:?}", mesh.warnings);
    assert!(mesh.warnings[0].contains("groups and materials"));
}

#[test]
fn vertex_normals_are_kept_per_vertex() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes/knot.obj");
    let mesh = load_obj(&path).expect("loads");
    assert_eq!(mesh.triangles.len(), 2 * 160 * 12);
    assert_eq!(mesh.normals.len(), mesh.positions.len());
    assert!(mesh.warnings.is_empty(), "{:?}", mesh.warnings);
}

#[test]
fn a_missing_file_is_named() {
    let path = folder("missing").join("nowhere.obj");
    let message = load_obj(&path).expect_err("refused").to_string();
    assert!(message.contains("nowhere.obj"), "{message}");
}

#[test]
fn an_index_out_of_range_names_file_and_line() {
    let message = error("range", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n");
    assert!(
        message.contains("bad.obj") && message.contains("line 5"),
        "{message}"
    );
    let message = error("range-negative", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -7\n");
    assert!(message.contains("line 4"), "{message}");
}

#[test]
fn nan_and_huge_coordinates_name_file_and_line() {
    for (test, bad) in [
        ("nan", "v nan 0 0"),
        ("huge", "v 0 1e300 0"),
        ("big", "v 0 0 -3e13"),
    ] {
        let message = error(test, &format!("v 0 0 0\nv 1 0 0\n{bad}\nf 1 2 3\n"));
        assert!(
            message.contains("bad.obj") && message.contains("line 3"),
            "{test}: {message}"
        );
    }
}

#[test]
fn garbage_names_its_line() {
    let message = error("garbage", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf one two three\n");
    assert!(
        message.contains("bad.obj") && message.contains("line 4"),
        "{message}"
    );
}

#[test]
fn zero_area_triangles_are_skipped_with_a_warning() {
    let path = write(
        "zero",
        "z.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\nf 1 1 3\n",
    );
    let mesh = load_obj(&path).expect("loads the good triangle");
    assert_eq!(mesh.triangles, vec![[0, 1, 2]]);
    assert!(
        mesh.warnings
            .iter()
            .any(|w| w.contains("2 triangle(s) with zero area"))
    );
    let message = error("all-zero", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    assert!(message.contains("no triangles with area"), "{message}");
}

#[test]
fn a_file_over_the_limit_is_refused_before_reading() {
    let path = folder("huge-file").join("huge.obj");
    let file = std::fs::File::create(&path).expect("create");
    // Sparse: no disk is used, and nothing is read.
    file.set_len(raylab::scene::mesh_file::MAX_OBJ_FILE_BYTES + 1)
        .expect("sparse file");
    let message = load_obj(&path).expect_err("refused").to_string();
    let _ = std::fs::remove_file(&path);
    assert!(
        message.contains("huge.obj") && message.contains("limit"),
        "{message}"
    );
}

#[test]
fn a_scene_names_the_object_whose_file_is_bad_and_the_scene_is_untouched() {
    let dir = folder("scene");
    std::fs::write(dir.join("good.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    let text = r#"Scene(
        camera: (position: (0.0, 0.0, 5.0), look_at: (0.0, 0.0, 0.0), fov_deg: 40.0, width: 64, height: 48),
        materials: { "m": (diffuse: (0.5, 0.5, 0.5)) },
        objects: [
            (name: "good", shape: Mesh(path: "good.obj"), material: "m"),
            (name: "teapot", shape: Mesh(path: "missing.obj"), material: "m"),
        ],
        lights: [],
    )"#;
    let scene = parse_scene(text).expect("parses");
    let before = scene.clone();
    let message = read_scene_meshes(&scene, &dir)
        .expect_err("refused")
        .to_string();
    assert!(
        message.contains("\"teapot\"") && message.contains("missing.obj"),
        "{message}"
    );
    assert_eq!(scene, before);
    let only_good = raylab::scene::Scene {
        objects: vec![scene.objects[0].clone()],
        ..scene
    };
    let meshes = read_scene_meshes(&only_good, &dir).expect("reads");
    assert_eq!(meshes.len(), 1);
    assert!(
        matches!(&only_good.objects[0].shape, Shape::Mesh { path } if meshes.contains_key(path))
    );
}

#[test]
fn normals_indexed_apart_from_positions_get_a_vertex_per_pair() {
    // Two triangles sharing an edge, the shared corners with different normals in each.
    let path = write(
        "normal-indices",
        "n.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nvn 0 1 1\n\
         f 1//1 2//1 3//1\nf 2//2 4//2 3//2\n",
    );
    let mesh = load_obj(&path).expect("loads");
    assert_eq!(mesh.triangles.len(), 2);
    assert_eq!(
        mesh.positions.len(),
        6,
        "corners 2 and 3 split by their normals"
    );
    assert_eq!(mesh.normals.len(), mesh.positions.len());
    for (triangle, normal) in mesh
        .triangles
        .iter()
        .zip([[0.0, 0.0, 1.0], [0.0, 1.0, 1.0]])
    {
        for &corner in triangle {
            assert_eq!(mesh.normals[corner as usize], normal);
        }
    }
}

#[test]
fn a_watched_read_reports_the_whole_file_and_a_cancelled_one_stops_clearly() {
    use raylab::scene::{LoadWatch, load_obj_watched};
    let path = write("watched", "grid.obj", &common::obj::sheet(40, false));
    let watch = LoadWatch::default();
    assert_eq!(watch.fraction(), 0.0);
    load_obj_watched(&path, &watch).expect("reads");
    assert!(
        (watch.fraction() - 1.0).abs() < 1e-12,
        "{}",
        watch.fraction()
    );

    let cancelled = LoadWatch::default();
    cancelled.cancel();
    let message = load_obj_watched(&path, &cancelled)
        .expect_err("cancelled")
        .to_string();
    assert!(
        message.contains("grid.obj") && message.contains("cancelled"),
        "{message}"
    );
}

#[test]
fn a_read_cancelled_half_way_stops_before_the_end() {
    use raylab::scene::{LoadWatch, load_obj_watched};
    use std::sync::Arc;
    // About 12 MB: reading it takes far longer than the watcher's first look.
    let path = write("half-way", "grid.obj", &common::obj::sheet(600, false));
    let watch = Arc::new(LoadWatch::default());
    let watcher = {
        let watch = Arc::clone(&watch);
        std::thread::spawn(move || {
            while watch.fraction() == 0.0 {
                std::thread::yield_now();
            }
            watch.cancel();
        })
    };
    let result = load_obj_watched(&path, &watch);
    watcher.join().expect("watcher");
    let message = result.expect_err("cancelled while reading").to_string();
    assert!(message.contains("cancelled"), "{message}");
    assert!(watch.fraction() < 1.0, "stopped before the end");
}
