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
