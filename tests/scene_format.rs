//! The RON file contract: round trips, defaults, and every kind of bad input giving one
//! clear message.

use std::path::Path;

use raylab::scene::{
    Light, MAX_DEPTH, Scene, SceneError, Shape, Transform, load_scene, parse_scene, save_scene,
    scene_to_ron,
};

const EXAMPLE: &str = r#"
// a complete scene; every section but `objects` may be left out
Scene(
    format: 1,
    camera: (
        position: (0.0, 1.5, 6.0),
        look_at: (0.0, 0.5, 0.0),
        up: (0.0, 1.0, 0.0),
        fov_deg: 45.0,
        width: 800,
        height: 600,
    ),
    render: (
        max_depth: 5,
        background: (0.02, 0.02, 0.03),
        samples_per_pixel: 16,
    ),
    materials: {
        "red plastic": (
            ambient: (0.1, 0.0, 0.0),
            diffuse: (0.7, 0.1, 0.1),
            specular: (0.5, 0.5, 0.5),
            shininess: 32.0,
            mirror: (0.0, 0.0, 0.0),
        ),
    },
    objects: [
        (
            name: "ball",
            shape: Sphere,
            transform: (
                translate: (0.0, 1.0, 0.0),
                rotate_deg: (0.0, 0.0, 0.0),
                scale: (1.0, 1.0, 1.0),
            ),
            material: "red plastic",
        ),
    ],
    lights: [
        Ambient(colour: (0.1, 0.1, 0.1)),
        Point(position: (4.0, 6.0, 3.0), colour: (1.0, 1.0, 1.0), intensity: 40.0),
        Directional(direction: (-1.0, -2.0, -1.0), colour: (1.0, 1.0, 0.9), intensity: 0.8),
        Spot(position: (0.0, 5.0, 0.0), direction: (0.0, -1.0, 0.0), angle_deg: 20.0,
             colour: (1.0, 0.9, 0.8), intensity: 30.0),
    ],
)
"#;

/// The contract's example scene with one piece of text replaced.
fn example_with(from: &str, to: &str) -> String {
    assert!(
        EXAMPLE.contains(from),
        "test bug: {from:?} not in the example"
    );
    EXAMPLE.replacen(from, to, 1)
}

fn error_of(text: &str) -> String {
    match parse_scene(text) {
        Ok(_) => panic!("expected an error for:\n{text}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn the_contract_example_loads_with_every_field() {
    let scene = parse_scene(EXAMPLE).unwrap();
    assert_eq!(scene.camera.width, 800);
    assert_eq!(scene.render.samples_per_pixel, 16);
    assert_eq!(scene.materials["red plastic"].shininess, 32.0);
    assert_eq!(scene.objects[0].shape, Shape::Sphere);
    assert_eq!(scene.lights.len(), 4);
    assert!(matches!(scene.lights[3], Light::Spot { angle_deg, .. } if angle_deg == 20.0));
}

#[test]
fn only_objects_is_required_and_defaults_apply() {
    let scene =
        parse_scene("Scene(materials: {\"m\": ()}, objects: [(shape: Cube, material: \"m\")])")
            .unwrap();
    assert_eq!(scene.format, 1);
    assert_eq!(scene.render.max_depth, 5);
    assert_eq!(scene.render.samples_per_pixel, 16);
    assert_eq!(scene.objects[0].name, "Cube 0");
    assert_eq!(scene.objects[0].transform, Transform::default());
    assert_eq!(scene.materials["m"].shininess, 1.0);
    let minimal = parse_scene("(objects: [])").unwrap();
    assert!(minimal.objects.is_empty() && minimal.lights.is_empty());
}

#[test]
fn intensity_defaults_to_one() {
    let scene = parse_scene(
        "Scene(objects: [], lights: [Point(position: (0.0, 1.0, 0.0), colour: (0.5, 0.5, 0.5))])",
    )
    .unwrap();
    assert_eq!(scene.lights[0].intensity(), 1.0);
}

#[test]
fn save_then_load_gives_an_equal_scene() {
    let mut scene = parse_scene(EXAMPLE).unwrap();
    scene.objects.push(raylab::scene::Object {
        name: "sheared".into(),
        shape: Shape::Cone,
        transform: Transform::Matrix([
            [1.0, 0.5, 0.0, 1.0],
            [0.0, 2.0, 0.0, -1.0],
            [0.0, 0.0, 1.0, 0.25],
        ]),
        material: "red plastic".into(),
    });
    let text = scene_to_ron(&scene);
    assert!(text.starts_with("Scene("), "{text}");
    assert!(text.contains("Matrix("), "{text}");
    assert_eq!(parse_scene(&text).unwrap(), scene);

    let dir = tempdir();
    let path = dir.join("scene.ron");
    save_scene(&scene, &path).unwrap();
    assert_eq!(load_scene(&path).unwrap(), scene);
    // Saving again over the file replaces it; no temporary file is left behind.
    save_scene(&scene, &path).unwrap();
    let leftovers: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
    assert_eq!(leftovers.len(), 1);
}

#[test]
fn every_example_scene_round_trips() {
    for entry in std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "ron") {
            continue; // the OBJ files of the mesh scene
        }
        let scene = load_scene(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert_eq!(
            parse_scene(&scene_to_ron(&scene)).unwrap(),
            scene,
            "{}",
            path.display()
        );
    }
}

#[test]
fn matrix_transform_reads_the_contract_form() {
    let text = example_with(
        "transform: (\n                translate: (0.0, 1.0, 0.0),\n                rotate_deg: (0.0, 0.0, 0.0),\n                scale: (1.0, 1.0, 1.0),\n            ),",
        "transform: Matrix(((2.0, 0.0, 0.0, 1.0), (0.0, 1.0, 0.0, 2.0), (0.0, 0.0, 1.0, 3.0))),",
    );
    let scene = parse_scene(&text).unwrap();
    let m = scene.objects[0].transform.world_from_object();
    assert_eq!(
        m.transform_point3(glam::DVec3::X),
        glam::DVec3::new(3.0, 2.0, 3.0)
    );
}

#[test]
fn syntax_errors_name_line_and_column() {
    let text = example_with("fov_deg: 45.0,", "fov_deg: 45.0,,");
    let error = parse_scene(&text).unwrap_err();
    let SceneError::Syntax { line, column, .. } = error else {
        panic!("expected a syntax error, got {error}");
    };
    assert_eq!(line, 9);
    assert!(column > 1);
    assert!(error.to_string().starts_with("line 9, column"), "{error}");
}

#[test]
fn unknown_fields_are_rejected_with_their_name_and_place() {
    let message = error_of(&example_with("fov_deg: 45.0,", "fov_deg: 45.0, zoom: 2.0,"));
    assert!(
        message.contains("zoom") && message.contains("line 9"),
        "{message}"
    );
    let message = error_of(&example_with("rotate_deg:", "rotate:"));
    assert!(
        message.contains("rotate") && message.contains("rotate_deg"),
        "{message}"
    );
    let message = error_of(&example_with(
        "shininess: 32.0,",
        "shininess: 32.0, glow: 1.0,",
    ));
    assert!(message.contains("glow"), "{message}");
    let message = error_of(&example_with(
        "angle_deg: 20.0,",
        "angle_deg: 20.0, softness: 2.0,",
    ));
    assert!(message.contains("softness"), "{message}");
}

#[test]
fn unknown_material_names_the_object_and_the_material() {
    let message = error_of(&example_with(
        "material: \"red plastic\"",
        "material: \"blue\"",
    ));
    assert!(
        message.contains("\"blue\"") && message.contains("\"ball\""),
        "{message}"
    );
}

#[test]
fn non_finite_numbers_are_rejected() {
    for (from, to) in [
        ("fov_deg: 45.0", "fov_deg: inf"),
        ("position: (0.0, 1.5, 6.0)", "position: (0.0, NaN, 6.0)"),
        ("shininess: 32.0", "shininess: NaN"),
        ("intensity: 40.0", "intensity: inf"),
        ("translate: (0.0, 1.0, 0.0)", "translate: (0.0, -inf, 0.0)"),
    ] {
        let message = error_of(&example_with(from, to));
        assert!(message.contains("finite"), "{to}: {message}");
    }
}

#[test]
fn zero_scale_is_a_singular_transform() {
    let message = error_of(&example_with(
        "scale: (1.0, 1.0, 1.0)",
        "scale: (1.0, 0.0, 1.0)",
    ));
    assert!(
        message.contains("singular") && message.contains("ball"),
        "{message}"
    );
    let message = error_of(&example_with(
        "scale: (1.0, 1.0, 1.0)",
        "scale: (-0.0, 1.0, 1.0)",
    ));
    assert!(message.contains("singular"), "{message}");
}

#[test]
fn singular_matrix_is_rejected() {
    let message = error_of(&example_with(
        "transform: (\n                translate: (0.0, 1.0, 0.0),\n                rotate_deg: (0.0, 0.0, 0.0),\n                scale: (1.0, 1.0, 1.0),\n            ),",
        "transform: Matrix(((1.0, 1.0, 0.0, 0.0), (1.0, 1.0, 0.0, 0.0), (0.0, 0.0, 1.0, 0.0))),",
    ));
    assert!(message.contains("singular"), "{message}");
}

#[test]
fn zero_light_direction_is_rejected() {
    let message = error_of(&example_with(
        "direction: (-1.0, -2.0, -1.0)",
        "direction: (0.0, 0.0, 0.0)",
    ));
    assert!(
        message.contains("direction")
            && message.contains("zero")
            && message.contains("Directional"),
        "{message}"
    );
    let message = error_of(&example_with(
        "direction: (0.0, -1.0, 0.0)",
        "direction: (0.0, 0.0, 0.0)",
    ));
    assert!(message.contains("Spot"), "{message}");
}

#[test]
fn spot_angle_may_be_anything_in_zero_to_180() {
    for bad in ["0.0", "-5.0", "180.5", "1000.0"] {
        let message = error_of(&example_with(
            "angle_deg: 20.0",
            &format!("angle_deg: {bad}"),
        ));
        assert!(
            message.contains("angle_deg") && message.contains("(0, 180]"),
            "{message}"
        );
    }
    for good in ["0.001", "90.0", "120.0", "180.0"] {
        let text = example_with("angle_deg: 20.0", &format!("angle_deg: {good}"));
        let scene = parse_scene(&text).unwrap_or_else(|e| panic!("{good}: {e}"));
        let angle: f64 = good.parse().unwrap();
        assert!(matches!(scene.lights[3], Light::Spot { angle_deg, .. } if angle_deg == angle));
    }
}

#[test]
fn shininess_may_be_zero_but_not_negative() {
    let scene = parse_scene(&example_with("shininess: 32.0", "shininess: 0.0")).unwrap();
    assert_eq!(scene.materials["red plastic"].shininess, 0.0);
    let message = error_of(&example_with("shininess: 32.0", "shininess: -0.5"));
    assert!(
        message.contains("red plastic") && message.contains("cannot be negative"),
        "{message}"
    );
}

#[test]
fn max_depth_goes_up_to_the_public_limit() {
    let limit = format!("max_depth: {MAX_DEPTH}");
    let scene = parse_scene(&example_with("max_depth: 5", &limit)).unwrap();
    assert_eq!(scene.render.max_depth, MAX_DEPTH);
    const { assert!(MAX_DEPTH >= 1000, "the contract asks for at least 1000") };
    let over = format!("max_depth: {}", MAX_DEPTH + 1);
    let message = error_of(&example_with("max_depth: 5", &over));
    assert!(
        message.contains("render.max_depth") && message.contains(&MAX_DEPTH.to_string()),
        "{message}"
    );
}

#[test]
fn image_size_must_be_between_one_and_16384() {
    for (from, to) in [
        ("width: 800", "width: 0"),
        ("height: 600", "height: 0"),
        ("width: 800", "width: 16385"),
        ("height: 600", "height: 100000"),
    ] {
        let message = error_of(&example_with(from, to));
        assert!(
            message.contains("16384") && message.contains("camera."),
            "{message}"
        );
    }
    assert!(parse_scene(&example_with("width: 800", "width: 16384")).is_ok());
}

#[test]
fn negative_size_is_a_syntax_error_not_a_panic() {
    let message = error_of(&example_with("width: 800", "width: -3"));
    assert!(message.contains("line"), "{message}");
}

#[test]
fn missing_file_and_non_utf8_give_clear_errors() {
    let dir = tempdir();
    let message = load_scene(&dir.join("nope.ron")).unwrap_err().to_string();
    assert!(
        message.contains("cannot read") && message.contains("nope.ron"),
        "{message}"
    );
    let path = dir.join("binary.ron");
    std::fs::write(&path, b"Scene(\n\xff\xfe)").unwrap();
    let message = load_scene(&path).unwrap_err().to_string();
    assert!(
        message.contains("UTF-8") && message.contains("line 2"),
        "{message}"
    );
}

#[test]
fn saving_into_a_missing_folder_fails_and_leaves_nothing() {
    let scene = parse_scene(EXAMPLE).unwrap();
    let dir = tempdir();
    let error = save_scene(&scene, &dir.join("missing").join("scene.ron")).unwrap_err();
    assert!(matches!(error, SceneError::Write { .. }), "{error}");
}

#[test]
fn saving_an_invalid_scene_is_refused() {
    let mut scene: Scene = parse_scene(EXAMPLE).unwrap();
    scene.objects[0].material = "gone".into();
    let dir = tempdir();
    let path = dir.join("scene.ron");
    assert!(matches!(
        save_scene(&scene, &path),
        Err(SceneError::Invalid(_))
    ));
    assert!(!path.exists());
}

/// A fresh empty folder under the target directory.
fn tempdir() -> std::path::PathBuf {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    let dir = std::env::temp_dir().join(format!(
        "raylab-test-{}-{}",
        std::process::id(),
        NEXT.fetch_add(1, Ordering::Relaxed)
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
