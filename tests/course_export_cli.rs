//! `raylab export SCENE -o FILE [--dialect 2020|2016]`: writes the course text, prints
//! each warning (naming what it is about) to stderr; a refused scene exits non-zero,
//! names every refusal and writes nothing.

mod common;

use std::path::Path;

use common::cli::{out_dir, raylab};
use raylab::scene::legacy::import_legacy_file;
use raylab::scene::load_scene;

fn example(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
        .display()
        .to_string()
}

#[test]
fn export_writes_the_course_text_and_prints_the_warnings() {
    let dir = out_dir("course-export-cli");
    let output = dir.join("spotlights.txt");
    let run = raylab(&[
        "export",
        &example("spotlights.ron"),
        "-o",
        &output.display().to_string(),
    ]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{stderr}");
    assert!(
        stderr.contains("warning: ") && stderr.contains("render settings: the render conventions"),
        "{stderr}"
    );
    let back = import_legacy_file(&output).expect("imports").scene;
    let scene = load_scene(Path::new(&example("spotlights.ron"))).unwrap();
    assert_eq!(back.objects.len(), scene.objects.len());
    assert_eq!(back.lights.len(), scene.lights.len());
}

#[test]
fn a_refused_export_exits_non_zero_names_each_refusal_and_writes_nothing() {
    let dir = out_dir("course-export-cli-refused");
    let output = dir.join("default.txt");
    let run = raylab(&[
        "export",
        &example("default.ron"),
        "-o",
        &output.display().to_string(),
        "--dialect",
        "2016",
    ]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(!run.status.success());
    assert!(
        stderr.contains("the 2016 framework's dialect cannot say"),
        "{stderr}"
    );
    assert!(
        stderr.contains("(Directional): the 2016 framework has point lights only"),
        "{stderr}"
    );
    assert!(
        stderr.contains("(Spot): the 2016 framework has point lights only"),
        "{stderr}"
    );
    assert!(!output.exists());
}
