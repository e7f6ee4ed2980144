//! Hostile input: the RON loader and the legacy importer survive anything, with a clear
//! error or a correct load, never a panic, a hang or unbounded allocation.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use raylab::scene::legacy::{import_legacy, import_legacy_file};
use raylab::scene::{SceneError, load_scene, parse_scene};
use raylab::trace::{RenderOptions, RenderProgress, World, render_samples};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

fn temp_file(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raylab-hostile-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// Renders a tiny image of a loaded scene and checks every sample was finite.
fn renders_cleanly(text: &str) {
    if let Ok(scene) = parse_scene(text) {
        let world = World::new(&scene).expect("a loaded scene compiles");
        let options = RenderOptions {
            width: 8,
            height: 6,
            samples_per_pixel: 1,
            ..RenderOptions::from_scene(&scene)
        };
        let sums = render_samples(&world, &options, 0..1, &RenderProgress::default()).unwrap();
        assert_eq!(sums.non_finite, 0);
        assert!(sums.sums.iter().all(|s| s.is_finite()));
    }
}

#[test]
fn random_bytes_are_an_error_not_a_panic() {
    let mut state = 0x1234_5678_9abc_def0u64;
    for length in [0usize, 1, 7, 100, 5000] {
        let bytes: Vec<u8> = (0..length)
            .map(|_| {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                state as u8
            })
            .collect();
        let text = String::from_utf8_lossy(&bytes);
        assert!(parse_scene(&text).is_err());
        let _ = import_legacy(&text); // an error or (for empty input) an empty import
        let path = temp_file("random.ron");
        std::fs::write(&path, &bytes).unwrap();
        assert!(load_scene(&path).is_err());
        let _ = import_legacy_file(&path);
    }
}

#[test]
fn every_truncation_of_an_example_fails_cleanly_or_loads() {
    let text = std::fs::read_to_string(root().join("scenes/default.ron")).unwrap();
    for end in (0..text.len()).step_by(7) {
        if !text.is_char_boundary(end) {
            continue;
        }
        match parse_scene(&text[..end]) {
            Ok(_) => renders_cleanly(&text[..end]),
            Err(e) => assert!(!e.to_string().is_empty()),
        }
    }
    let legacy = std::fs::read_to_string(root().join("tests/legacy/full.txt")).unwrap();
    for end in (0..legacy.len()).step_by(5) {
        if legacy.is_char_boundary(end) {
            let _ = import_legacy(&legacy[..end]);
        }
    }
}

#[test]
fn deep_nesting_is_refused_with_a_position() {
    let text = format!("Scene(objects: [{}", "(".repeat(200_000));
    let error = parse_scene(&text).unwrap_err();
    assert!(matches!(error, SceneError::Syntax { .. }), "{error}");
    assert!(error.to_string().contains("line 1"), "{error}");
}

#[test]
fn a_file_over_the_size_limit_is_refused_before_reading_it_all() {
    let path = temp_file("huge.ron");
    let file = std::fs::File::create(&path).unwrap();
    file.set_len(raylab::scene::MAX_SCENE_FILE_BYTES + 1)
        .unwrap(); // sparse: instant
    let message = load_scene(&path).unwrap_err().to_string();
    assert!(message.contains("larger than 64 MiB"), "{message}");
    let message = import_legacy_file(&path).err().unwrap().to_string();
    assert!(message.contains("larger than 64 MiB"), "{message}");
    std::fs::remove_file(&path).unwrap();
}

#[test]
fn a_fifty_megabyte_scene_with_many_objects_loads() {
    // 50 MB: 100,000 objects plus a long comment.
    let mut text = String::from(
        "Scene(\n    materials: {\"m\": (diffuse: (0.5, 0.5, 0.5))},\n    objects: [\n",
    );
    for i in 0..100_000 {
        let (x, z) = (f64::from(i % 400) * 0.1, f64::from(i / 400) * 0.1);
        writeln!(text, "        (shape: Sphere, transform: (translate: ({x}, 0.0, {z}), scale: (0.04, 0.04, 0.04)), material: \"m\"),").unwrap();
    }
    text.push_str("    ],\n    lights: [Directional(direction: (0.0, -1.0, 0.0), colour: (1.0, 1.0, 1.0))],\n)\n");
    text.push_str("//");
    text.push_str(&"x".repeat(50_000_000 - text.len()));
    let path = temp_file("fifty.ron");
    std::fs::write(&path, &text).unwrap();
    let scene = load_scene(&path).unwrap();
    assert_eq!(scene.objects.len(), 100_000);
    assert_eq!(scene.objects[99_999].name, "Sphere 99999");
    std::fs::remove_file(&path).unwrap();
}

#[test]
fn extreme_numbers_load_or_fail_with_the_field_named() {
    let with = |field: &str| {
        format!(
            "Scene(camera: (position: (0.0, 0.0, 5.0), look_at: (0.0, 0.0, 0.0), fov_deg: 45.0, width: 32, height: 24), \
             materials: {{\"m\": (diffuse: (1.0, 1.0, 1.0))}}, objects: [(shape: Sphere, {field} material: \"m\")], \
             lights: [Point(position: (1.0, 2.0, 3.0), colour: (1.0, 1.0, 1.0))])"
        )
    };
    // Loads: -0.0, subnormal positions, huge but invertible scales.
    for ok in [
        "transform: (translate: (-0.0, -0.0, -0.0)),",
        "transform: (translate: (5e-324, 0.0, 0.0)),",
        "transform: (scale: (1e100, 1e100, 1e100)),",
        "transform: (scale: (1e-100, 1e-100, 1e-100)),",
        "transform: (translate: (1e308, 0.0, 0.0)),",
    ] {
        let text = with(ok);
        parse_scene(&text).unwrap_or_else(|e| panic!("{ok}: {e}"));
        renders_cleanly(&text);
    }
    // Refused, naming the problem.
    for (bad, expect) in [
        ("transform: (scale: (5e-324, 1.0, 1.0)),", "transform"),
        (
            "transform: (scale: (1e300, 1e300, 1e300)),",
            "cannot be inverted",
        ),
        (
            "transform: (scale: (1e-300, 1e-300, 1e-300)),",
            "cannot be inverted",
        ),
        ("transform: (translate: (NaN, 0.0, 0.0)),", "finite"),
        ("transform: (translate: (1e309, 0.0, 0.0)),", "finite"),
    ] {
        let message = parse_scene(&with(bad)).unwrap_err().to_string();
        assert!(message.contains(expect), "{bad}: {message}");
    }
    let huge_width = "Scene(camera: (position: (0.0, 0.0, 5.0), look_at: (0.0, 0.0, 0.0), fov_deg: 45.0, width: 1000000000, height: 24), objects: [])";
    assert!(
        parse_scene(huge_width)
            .unwrap_err()
            .to_string()
            .contains("16384")
    );
    let float_width = "Scene(camera: (position: (0.0, 0.0, 5.0), look_at: (0.0, 0.0, 0.0), fov_deg: 45.0, width: 1e9, height: 24), objects: [])";
    assert!(
        parse_scene(float_width)
            .unwrap_err()
            .to_string()
            .contains("line 1")
    );
    let far_camera = "Scene(camera: (position: (1e308, 0.0, 5.0), look_at: (-1e308, 0.0, 0.0), fov_deg: 45.0, width: 4, height: 4), objects: [])";
    assert!(
        parse_scene(far_camera)
            .unwrap_err()
            .to_string()
            .contains("camera")
    );
}

#[test]
fn ten_thousand_materials_load() {
    let mut text = String::from("Scene(materials: {");
    for i in 0..10_000 {
        write!(text, "\"m{i}\": (diffuse: (0.5, 0.5, 0.5)),").unwrap();
    }
    text.push_str("}, objects: [(shape: Cube, material: \"m9999\")])");
    let scene = parse_scene(&text).unwrap();
    assert_eq!(scene.materials.len(), 10_000);
    renders_cleanly(&text);
}

#[test]
fn non_utf8_bytes_name_their_line() {
    let path = temp_file("latin1.txt");
    std::fs::write(&path, b"Scene\n  renderSize 10 10\nEnd\n# caf\xe9\n").unwrap();
    let message = import_legacy_file(&path).err().unwrap().to_string();
    assert!(
        message.contains("line 4") && message.contains("UTF-8"),
        "{message}"
    );
}
