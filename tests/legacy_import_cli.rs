//! `raylab import` on the command line: warnings on stderr and the scene written, or
//! every problem listed and nothing written.

mod common;

use std::path::Path;
use std::process::Command;

use common::legacy::{import_file, legacy_path};
use raylab::scene::load_scene;

fn raylab() -> Command {
    Command::new(env!("CARGO_BIN_EXE_raylab"))
}

#[test]
fn cli_imports_a_file_and_prints_its_summary() {
    let output = Path::new(env!("CARGO_TARGET_TMPDIR")).join("legacy_full.ron");
    let _ = std::fs::remove_file(&output);
    let run = raylab()
        .arg("import")
        .arg(legacy_path("full.txt"))
        .arg("-o")
        .arg(&output)
        .output()
        .expect("run raylab");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{stderr}");
    assert!(
        stderr.contains("imported 6 objects") && !stderr.contains("warning:"),
        "{stderr}"
    );
    let loaded = load_scene(&output).expect("the written scene loads");
    assert_eq!(loaded, import_file("full.txt").scene);
}

#[test]
fn cli_lists_every_problem_and_writes_nothing() {
    let output = Path::new(env!("CARGO_TARGET_TMPDIR")).join("legacy_many.ron");
    let _ = std::fs::remove_file(&output);
    let run = raylab()
        .arg("import")
        .arg(legacy_path("err_many.txt"))
        .arg("-o")
        .arg(&output)
        .output()
        .expect("run raylab");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(!run.status.success());
    for expected in [
        "line 3: `0`",
        "line 6: `W`",
        "line 9: `nowhere`",
        "line 10: `-1`",
        "line 12: `PointLight`",
    ] {
        assert!(
            stderr.contains(expected),
            "{expected} missing from:\n{stderr}"
        );
    }
    assert!(!output.exists());
}

#[test]
fn cli_says_which_dialect_it_read_and_keeps_mesh_paths_working_from_the_output() {
    let legacy = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/legacy_ext/mesh_scene.txt");
    let folder = Path::new(env!("CARGO_TARGET_TMPDIR")).join("legacy_mesh_out");
    std::fs::create_dir_all(&folder).unwrap();
    let output = folder.join("mesh_scene.ron");
    let run = raylab()
        .arg("import")
        .arg(&legacy)
        .arg("-o")
        .arg(&output)
        .output()
        .expect("run raylab");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{stderr}");
    assert!(
        stderr.contains("read as the 2020 framework's dialect")
            && stderr.contains("line 14: Mesh `missing.obj`"),
        "{stderr}"
    );
    let loaded = load_scene(&output).expect("the written scene loads");
    let raylab::scene::Shape::Mesh { path } = &loaded.objects[0].shape else {
        panic!("{loaded:?}")
    };
    assert!(
        folder.join(path).is_file(),
        "{path} is not found from {folder:?}"
    );
    raylab::scene::read_scene_meshes(&loaded, &folder).expect("the mesh reads");
}
