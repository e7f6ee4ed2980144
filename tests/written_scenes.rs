//! The writer's bytes: every example scene and the contract's light forms, loaded and
//! written again, give exactly the text in `tests/written_scenes/`. The snapshots were
//! written by the writer before the lights' shared fields moved into one struct, so a
//! change of representation that changes a byte of the files fails here. Bless new
//! snapshots (only for a deliberate format change) with
//! `RAYLAB_BLESS=1 cargo test --test written_scenes`.

use std::path::{Path, PathBuf};

use raylab::scene::{load_scene, parse_scene, scene_to_ron};

/// The contract's example (`SCENE_FORMAT.md`) with its light forms: each kind with and
/// without defaults, and the sphere lights of the soft-shadow section.
const CONTRACT_LIGHTS: &str = r#"
Scene(
    format: 1,
    materials: {
        "red plastic": (diffuse: (0.7, 0.1, 0.1)),
    },
    objects: [
        (name: "ball", shape: Sphere, material: "red plastic"),
    ],
    lights: [
        Ambient(colour: (0.1, 0.1, 0.1)),
        Ambient(colour: (0.1, 0.1, 0.1), intensity: 2.0),
        Point(position: (4.0, 6.0, 3.0), colour: (1.0, 1.0, 1.0), intensity: 40.0),
        Point(position: (4.0, 6.0, 3.0), colour: (1.0, 1.0, 1.0)),
        Point(position: (0.0, 2.0, 0.0), colour: (1.0, 0.5, 0.2), intensity: 3.0, radius: 0.2, samples: 16),
        Point(position: (0.0, 2.0, 0.0), colour: (1.0, 0.5, 0.2), radius: 0.2),
        Point(position: (0.0, 2.0, 0.0), colour: (1.0, 0.5, 0.2), samples: 4),
        Directional(direction: (-1.0, -2.0, -1.0), colour: (1.0, 1.0, 0.9), intensity: 0.8),
        Spot(position: (0.0, 5.0, 0.0), direction: (0.0, -1.0, 0.0), angle_deg: 20.0,
             colour: (1.0, 0.9, 0.8), intensity: 30.0),
        Spot(position: (0.0, 5.0, 0.0), direction: (0.0, -1.0, 0.0), angle_deg: 20.0,
             colour: (1.0, 0.9, 0.8), intensity: 30.0, radius: 0.5, samples: 9),
        Spot(position: (0.0, 5.0, 0.0), direction: (0.0, -1.0, 0.0), angle_deg: 180.0,
             colour: (1.0, 0.9, 0.8), samples: 2),
    ],
)
"#;

fn snapshot_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/written_scenes")
        .join(name)
}

/// Compares `written` with the snapshot `name`, or replaces the snapshot when blessing.
fn assert_matches_snapshot(name: &str, written: &str) {
    let path = snapshot_path(name);
    if std::env::var_os("RAYLAB_BLESS").is_some() {
        std::fs::write(&path, written).unwrap();
        return;
    }
    let expected = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("{}: {e} (bless with RAYLAB_BLESS=1)", path.display()));
    assert!(
        written == expected,
        "{name}: the writer's bytes changed\n--- snapshot\n{expected}\n--- written now\n{written}"
    );
}

#[test]
fn every_example_scene_is_written_as_before() {
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut checked = 0;
    for entry in std::fs::read_dir(scenes).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "ron") {
            continue; // the OBJ files of the mesh scene
        }
        let scene = load_scene(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let name = path.file_name().unwrap().to_str().unwrap();
        assert_matches_snapshot(name, &scene_to_ron(&scene));
        checked += 1;
    }
    assert!(checked >= 10, "only {checked} example scenes found");
}

#[test]
fn the_contract_light_forms_are_written_as_before() {
    let scene = parse_scene(CONTRACT_LIGHTS).unwrap();
    assert_matches_snapshot("contract_lights.ron", &scene_to_ron(&scene));
}

#[test]
fn written_scenes_read_back_to_the_same_bytes() {
    for entry in std::fs::read_dir(snapshot_path("")).unwrap() {
        let path = entry.unwrap().path();
        let written = std::fs::read_to_string(&path).unwrap();
        let scene = parse_scene(&written).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert_eq!(scene_to_ron(&scene), written, "{}", path.display());
    }
}
