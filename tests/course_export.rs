//! Export to the course's text format (`raylab export`, `write_course_scene`): every
//! example scene a dialect can hold comes back from the importer rendering a
//! byte-identical PNG, and passes a reader written from the course grammar; every scene
//! a dialect cannot hold is refused, naming what and why.

#[path = "common/course_grammar.rs"]
mod course_grammar;

use std::path::{Path, PathBuf};

use course_grammar::{Framework, check};
use raylab::scene::legacy::{Dialect, export_course_file, import_legacy_file};
use raylab::scene::{Conventions, Scene, load_scene, read_scene_meshes};
use raylab::trace::{MeshStore, RenderOptions, RenderProgress, World, render};

/// The example scenes, sorted by file name.
fn examples() -> Vec<PathBuf> {
    let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&folder)
        .unwrap()
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "ron"))
        .collect();
    paths.sort();
    paths
}

/// A fresh folder for one test's files.
fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "raylab-course-export-{name}-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The scene as the course renders it: the course's conventions (which the format
/// cannot say, so the export warns and an import sets them), at a fifth of its size to
/// keep the test quick.
fn as_the_course_renders(mut scene: Scene, dialect: Dialect) -> Scene {
    scene.render.conventions = Conventions::COURSE;
    if dialect == Dialect::Framework2016 {
        // The 2016 dialect has no anti-aliasing (the export warns).
        scene.render.samples_per_pixel = 1;
    }
    scene.camera.width = (scene.camera.width / 5).max(1);
    scene.camera.height = (scene.camera.height / 5).max(1);
    scene
}

/// The PNG raylab writes for `scene`, whose mesh paths start in `folder`: the render
/// path of `raylab render` (meshes read, world built, samples averaged, quantised by
/// the scene's convention).
fn png(scene: &Scene, folder: &Path) -> Vec<u8> {
    let meshes = MeshStore::build(&read_scene_meshes(scene, folder).expect("meshes read"));
    let world = World::with_meshes(scene, &meshes).expect("a valid scene");
    let options = RenderOptions::from_scene(scene);
    let (image, _) = render(&world, &options, &RenderProgress::default()).expect("not cancelled");
    image.png_bytes_as(scene.render.conventions.quantise)
}

fn framework(dialect: Dialect) -> Framework {
    match dialect {
        Dialect::Framework2016 => Framework::Y2016,
        Dialect::Framework2020 => Framework::Y2020,
    }
}

/// What the round trip of the examples found.
#[derive(Default)]
struct RoundTrip {
    /// The refused examples, by file stem, with the refusals' text.
    refused: Vec<(String, String)>,
    /// The examples whose import renders a different PNG only because the camera comes
    /// back to float noise (its angles pass through sine and cosine), not to the bit:
    /// with the exported scene's own camera they render the same PNG.
    camera_noise: Vec<String>,
}

/// Exports every example in `dialect`; each one written must pass the grammar and come
/// back rendering the same PNG (with its own camera, where the camera's float noise
/// changes pixels: those are listed).
fn round_trip_examples(dialect: Dialect, dir: &Path) -> RoundTrip {
    let mut found = RoundTrip::default();
    for path in examples() {
        let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
        let scene = as_the_course_renders(load_scene(&path).unwrap(), dialect);
        let folder = path.parent().unwrap();
        let output = dir.join(format!("{stem}.txt"));
        match export_course_file(&scene, folder, &output, dialect) {
            Err(error) => {
                assert!(!output.exists(), "{stem}: a refused export writes nothing");
                found.refused.push((stem, error.to_string()));
            }
            Ok(_warnings) => {
                let text = std::fs::read_to_string(&output).unwrap();
                check(&text, framework(dialect)).unwrap_or_else(|e| {
                    panic!("{stem}: the course grammar refuses it: {e}\n{text}")
                });
                let mut back = import_legacy_file(&output)
                    .unwrap_or_else(|e| panic!("{stem}: does not import: {e}"))
                    .scene;
                let expected = png(&scene, folder);
                if png(&back, dir) != expected {
                    let (b, s) = (&back.camera, &scene.camera);
                    let forward = |c: &raylab::scene::Camera| (c.look_at - c.position).normalize();
                    assert_eq!(b.position, s.position, "{stem}");
                    assert!((forward(b) - forward(s)).length() < 1e-14, "{stem}");
                    assert!((b.fov_deg - s.fov_deg).abs() < 1e-12, "{stem}");
                    back.camera = scene.camera.clone();
                    assert!(
                        png(&back, dir) == expected,
                        "{stem}: the export renders differently after import\n{text}"
                    );
                    found.camera_noise.push(stem);
                }
            }
        }
    }
    found
}

/// Asserts the refused examples are exactly `expected` (stem and a fragment of why).
fn assert_refused(refused: &[(String, String)], expected: &[(&str, &str)]) {
    let stems: Vec<&str> = refused.iter().map(|(s, _)| s.as_str()).collect();
    let expected_stems: Vec<&str> = expected.iter().map(|(s, _)| *s).collect();
    assert_eq!(stems, expected_stems, "{refused:#?}");
    for ((stem, why), (_, fragment)) in refused.iter().zip(expected) {
        assert!(why.contains(fragment), "{stem}: {why}\nlacks {fragment:?}");
    }
}

#[test]
fn every_example_the_2020_dialect_holds_comes_back_rendering_the_same_png() {
    let dir = temp_dir("examples-2020");
    let found = round_trip_examples(Dialect::Framework2020, &dir);
    // A sphere light's penumbra: its many shadow rays graze edges, so the camera's
    // float noise moves some of them across.
    assert_eq!(found.camera_noise, ["soft_spot"]);
    assert_refused(
        &found.refused,
        &[
            // The die: a CSG inside a CSG, and a difference of 22 operands.
            ("csg", "object \"die\": its CSG Difference has 22 operands"),
            (
                "glass",
                "material \"glass\": its transmission 0.92 0.95 0.94 is coloured",
            ),
            ("mesh", "object \"knot\": the 2020 dialect has no Mesh"),
            ("more_shapes", "its torus has minor radius 0.25"),
        ],
    );
}

#[test]
fn every_example_the_2016_dialect_holds_comes_back_rendering_the_same_png() {
    let dir = temp_dir("examples-2016");
    let found = round_trip_examples(Dialect::Framework2016, &dir);
    assert!(found.camera_noise.is_empty(), "{:?}", found.camera_noise);
    let point_lights_only = "the 2016 framework has point lights only";
    assert_refused(
        &found.refused,
        &[
            ("default", point_lights_only),
            (
                "glass",
                "the 2016 dialect has no Opacity or RefractiveIndex",
            ),
            ("more_shapes", "the 2016 dialect has no Torus"),
            ("shapes", point_lights_only),
            ("soft_spot", point_lights_only),
            ("specular_exponents", point_lights_only),
            ("spotlights", point_lights_only),
        ],
    );
}

#[test]
fn the_grammar_checker_refuses_what_the_course_grammar_refuses() {
    let good = "Scene renderSize 8 6 End\nMaterial m Colour 1 .5 1. End\nObject Sphere Material m \
                Scale 2 Rotate Y -3e1 End";
    assert_eq!(check(good, Framework::Y2020), Ok(()));
    assert_eq!(check(good, Framework::Y2016), Ok(()));
    for (bad, framework) in [
        ("Object Sphere Translate 1,0 0 0 End", Framework::Y2020),
        ("Object Sphere End End", Framework::Y2020),
        ("Object Sphere Material m End", Framework::Y2020),
        ("Object Sphere", Framework::Y2020),
        ("Light SpotLight Colour 1 1 1 End", Framework::Y2016),
        ("Object Torus 1 End", Framework::Y2016),
        ("Object Mesh a.obj End", Framework::Y2020),
        ("CSG Union Object Sphere End End", Framework::Y2020),
        (
            "Object CSG Union Object Sphere End Object Cube End End",
            Framework::Y2020,
        ),
        ("Scene FSAA 2 End", Framework::Y2016),
        ("Object Sphere Rotate W 3 End", Framework::Y2020),
    ] {
        assert!(check(bad, framework).is_err(), "{bad}");
    }
    assert_eq!(
        check(
            "Object CSG Union Object Sphere End Object CSG Difference Object Cube End \
             Object Cone End End Translate 0 1 0 End",
            Framework::Y2016
        ),
        Ok(())
    );
}
