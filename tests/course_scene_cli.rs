//! Every command that takes a scene takes a course text scene too, told by its content
//! (not its name) as the editor's File > Open tells it; and a RON file nested too deep
//! is refused in the scene's words, not the parser's.

mod common;

use std::path::PathBuf;

use common::cli::{out_dir, raylab};
use common::legacy::{import_file, legacy_path, render_scene};

/// `tests/legacy/lit_sphere.txt` copied under a name that says nothing of its kind.
fn course_scene_named_plainly() -> PathBuf {
    let path = out_dir("course-scene").join("lit_sphere.scene");
    std::fs::copy(legacy_path("lit_sphere.txt"), &path).unwrap();
    path
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

#[test]
fn render_takes_a_course_scene_and_draws_what_the_import_draws() {
    for scene in [legacy_path("lit_sphere.txt"), course_scene_named_plainly()] {
        let output = out_dir("course-scene").join("lit_sphere.png");
        let _ = std::fs::remove_file(&output);
        let run = raylab(&[
            "render",
            scene.to_str().unwrap(),
            "-o",
            output.to_str().unwrap(),
        ]);
        let stderr = text(&run.stderr);
        assert!(run.status.success(), "{}: {stderr}", scene.display());
        assert!(
            stderr.contains("course scene, imported"),
            "says it imported: {stderr}"
        );
        let written = image::open(&output).unwrap().to_rgb8();
        let imported = import_file("lit_sphere.txt").scene;
        let quantise = imported.render.conventions.quantise;
        let expected = image::load_from_memory(&render_scene(&imported).png_bytes_as(quantise))
            .unwrap()
            .to_rgb8();
        assert_eq!(written, expected, "{}", scene.display());
    }
}

#[test]
fn inspect_takes_a_course_scene() {
    let scene = course_scene_named_plainly();
    let run = raylab(&[
        "inspect",
        scene.to_str().unwrap(),
        "--pixel",
        "10,10",
        "--json",
    ]);
    let stderr = text(&run.stderr);
    assert!(run.status.success(), "{stderr}");
    let report: serde_json::Value = serde_json::from_slice(&run.stdout).unwrap();
    // The file works out its centre pixel by hand: (0.8, 0.5, 0.35).
    let colour: Vec<f64> = report["colour"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_f64().unwrap())
        .collect();
    for (got, want) in colour.iter().zip([0.8, 0.5, 0.35]) {
        assert!((got - want).abs() < 1e-9, "{colour:?}");
    }
    assert_eq!(report["rays"][0]["hit"]["object"], "Sphere 0");
}

#[test]
fn diff_takes_a_course_scene_whatever_its_name() {
    let scene = course_scene_named_plainly();
    let other = out_dir("course-scene").join("other.png");
    let imported = import_file("lit_sphere.txt").scene;
    std::fs::write(&other, render_scene(&imported).png_bytes()).unwrap();
    let run = raylab(&["diff", scene.to_str().unwrap(), other.to_str().unwrap()]);
    assert!(run.status.success(), "{}", text(&run.stderr));
}

#[test]
fn a_ron_scene_nested_too_deep_is_refused_in_the_scenes_words() {
    let mut object = "(name: \"ball\", shape: Sphere, material: \"m\")".to_owned();
    for level in 0..2000 {
        object = format!("(name: \"l{level}\", shape: Csg(op: Union, operands: [{object}]))");
    }
    let deep = out_dir("course-scene").join("deep.ron");
    std::fs::write(
        &deep,
        format!(
            "Scene(camera: (position: (0.0, 0.0, 5.0), look_at: (0.0, 0.0, 0.0), \
             fov_deg: 40.0, width: 8, height: 6),\nmaterials: {{\"m\": (diffuse: (0.5, 0.5, 0.5))}},\n\
             lights: [],\nobjects: [{object}])"
        ),
    )
    .unwrap();
    for command in ["render", "inspect"] {
        let mut args = vec![command, deep.to_str().unwrap()];
        args.extend(if command == "render" {
            ["-o", "never.png"]
        } else {
            ["--pixel", "0,0"]
        });
        let run = raylab(&args);
        let stderr = text(&run.stderr);
        assert!(!run.status.success());
        assert!(
            stderr.contains("line 4")
                && stderr.contains("objects nested more than 1000 levels deep"),
            "{command}: {stderr}"
        );
        assert!(!stderr.contains("recursion_limit"), "{command}: {stderr}");
    }
}
