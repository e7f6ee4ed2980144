//! The command line with a mesh scene: `raylab render` reads the scene's OBJ files from
//! its folder, `raylab inspect` names the triangle a ray met, and a scene whose mesh file
//! is missing is refused naming the object and the file.

use std::path::PathBuf;
use std::process::{Command, Output};

fn raylab() -> Command {
    Command::new(env!("CARGO_BIN_EXE_raylab"))
}

/// Runs `command` and asserts it succeeded, showing its stderr if not.
fn succeeds(command: &mut Command) -> Output {
    let run = command.output().expect("runs");
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    run
}

fn example() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes/mesh.ron")
}

#[test]
fn render_reads_the_meshes_beside_the_scene() {
    let out = std::env::temp_dir().join(format!("raylab-mesh-cli-{}.png", std::process::id()));
    let run = succeeds(
        raylab()
            .arg("render")
            .arg(example())
            .args(["--width", "64", "-o"])
            .arg(&out),
    );
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(
        stderr.matches("groups and materials").count(),
        1,
        "{stderr}"
    );
    let image = image::open(&out).expect("a PNG").to_rgb8();
    let _ = std::fs::remove_file(&out);
    assert_eq!(image.width(), 64);
    // The gold knot is left of centre: some pixel there is clearly gold (red > blue).
    let gold = (0..image.height())
        .flat_map(|y| (0..32).map(move |x| (x, y)))
        .any(|(x, y)| {
            let [r, _, b] = image.get_pixel(x, y).0;
            r > 120 && i32::from(r) - i32::from(b) > 60
        });
    assert!(gold, "no gold pixel in the knot's half");
}

#[test]
fn inspect_names_the_triangle_and_its_barycentrics() {
    let run = succeeds(
        raylab()
            .arg("inspect")
            .arg(example())
            .args(["--pixel", "140,200"]),
    );
    let text = String::from_utf8_lossy(&run.stdout);
    assert!(text.contains("hits knot"), "{text}");
    let line = text
        .lines()
        .find(|l| l.contains("triangle") && l.contains("barycentric"))
        .unwrap_or_else(|| panic!("no triangle line in {text}"));
    let numbers: Vec<f64> = line
        .split(['(', ')', ','])
        .filter_map(|w| w.trim().parse().ok())
        .collect();
    assert_eq!(numbers.len(), 3, "{line}");
    assert!((numbers.iter().sum::<f64>() - 1.0).abs() < 1e-3, "{line}");
}

#[test]
fn a_missing_mesh_file_names_the_object_and_the_file() {
    let dir = std::env::temp_dir().join(format!("raylab-mesh-cli-missing-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("folder");
    let text = std::fs::read_to_string(example()).expect("example");
    std::fs::write(dir.join("scene.ron"), text).expect("write");
    let run = raylab()
        .arg("render")
        .arg(dir.join("scene.ron"))
        .arg("-o")
        .arg(dir.join("out.png"))
        .output()
        .expect("runs");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(!run.status.success());
    assert!(
        stderr.contains("\"knot\"") && stderr.contains("knot.obj"),
        "{stderr}"
    );
    assert!(!dir.join("out.png").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn diff_names_a_mesh_left_out_of_the_other_image() {
    let dir = std::env::temp_dir().join(format!("raylab-mesh-cli-diff-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("folder");
    let other = dir.join("no-knot.png");
    succeeds(
        raylab()
            .arg("render")
            .arg(example())
            .args(["--hide", "knot", "-o"])
            .arg(&other),
    );
    let diff = raylab()
        .arg("diff")
        .arg(example())
        .arg(&other)
        .output()
        .expect("runs");
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        diff.status.success(),
        "{}",
        String::from_utf8_lossy(&diff.stderr)
    );
    let text = String::from_utf8_lossy(&diff.stdout);
    let first = text.lines().nth(1).unwrap_or_default();
    assert!(
        first.contains("object knot") && first.contains("missing"),
        "{text}"
    );
}
