//! The legacy COSC342 importer: every keyword imported field by field, every kind of
//! error reported with its line and token, renders checked against hand-computed
//! pixels, a RON round trip, and `raylab import` on the command line.

use std::path::{Path, PathBuf};
use std::process::Command;

use glam::{DAffine3, DVec2, DVec3, Vec3};
use raylab::scene::legacy::{
    LegacyErrors, LegacyImport, LegacyImportFileError, import_legacy, import_legacy_file,
};
use raylab::scene::{
    Light, Material, Scene, Shape, Transform, Trs, load_scene, parse_scene, scene_to_ron, validate,
};
use raylab::trace::{Image, PinholeCamera, RenderOptions, RenderProgress, World, render};

fn legacy_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/legacy")
        .join(name)
}

fn import_file(name: &str) -> LegacyImport {
    match import_legacy_file(&legacy_path(name)) {
        Ok(import) => import,
        Err(e) => panic!("{name} should import: {e}"),
    }
}

fn import_text(text: &str) -> LegacyImport {
    import_legacy(text).unwrap_or_else(|e| panic!("should import:\n{e}"))
}

fn errors_of_text(text: &str) -> LegacyErrors {
    match import_legacy(text) {
        Ok(import) => panic!("should fail, imported {:?}", import.scene),
        Err(errors) => errors,
    }
}

fn errors_of_file(name: &str) -> LegacyErrors {
    match import_legacy_file(&legacy_path(name)) {
        Err(LegacyImportFileError::Legacy { errors, .. }) => errors,
        other => panic!("{name} should fail with legacy errors, got {other:?}"),
    }
}

/// Asserts exactly one error, at `line` on `token`, whose text contains `fragment`.
fn assert_one_error(errors: &LegacyErrors, line: usize, token: &str, fragment: &str) {
    assert_eq!(errors.0.len(), 1, "{errors}");
    let text = errors.to_string();
    assert!(
        text.starts_with(&format!("line {line}: `{token}`: ")),
        "{text}"
    );
    assert!(text.contains(fragment), "{text} lacks {fragment:?}");
}

fn assert_vec(actual: DVec3, expected: DVec3) {
    assert!(
        (actual - expected).abs().max_element() <= 1e-12 * expected.abs().max_element().max(1.0),
        "{actual} expected {expected}"
    );
}

fn trs(translate: [f64; 3], rotate_deg: [f64; 3], scale: [f64; 3]) -> Transform {
    Transform::Trs(Trs {
        translate: DVec3::from(translate),
        rotate_deg: DVec3::from(rotate_deg),
        scale: DVec3::from(scale),
    })
}

fn material(
    ambient: DVec3,
    diffuse: DVec3,
    specular: DVec3,
    shininess: f64,
    mirror: DVec3,
) -> Material {
    Material {
        ambient,
        diffuse,
        specular,
        shininess,
        mirror,
    }
}

fn magenta() -> Material {
    let m = DVec3::new(1.0, 0.0, 1.0);
    material(m, m, DVec3::ZERO, 1.0, DVec3::ZERO)
}

fn render_scene(scene: &Scene) -> Image {
    let world = World::new(scene).expect("imported scenes are valid");
    let options = RenderOptions::from_scene(scene);
    render(&world, &options, &RenderProgress::default())
        .expect("not cancelled")
        .0
}

// ---------------------------------------------------------------- field by field

#[test]
fn full_scene_render_settings_and_camera() {
    let scene = import_file("full.txt").scene;
    validate(&scene).expect("valid");
    assert_eq!(scene.format, 1);
    assert_eq!(scene.render.max_depth, 4);
    assert_eq!(scene.render.background, DVec3::new(0.1, 0.2, 0.3));
    assert_eq!(scene.render.samples_per_pixel, 1);
    let camera = &scene.camera;
    assert_eq!((camera.width, camera.height), (40, 30));
    // Rotate X 180 then Translate 0 1 10: at (0, 1, 10), looking down -Z, +Y up.
    assert_vec(camera.position, DVec3::new(0.0, 1.0, 10.0));
    assert_vec(camera.look_at, DVec3::new(0.0, 1.0, 9.0));
    assert_vec(camera.up, DVec3::new(0.0, 1.0, 0.0));
    // tan(fov / 2) = (30 / 40) / 2.
    let expected_fov = 2.0 * 0.375f64.atan().to_degrees();
    assert!(
        (camera.fov_deg - expected_fov).abs() < 1e-12,
        "{}",
        camera.fov_deg
    );
}

#[test]
fn full_scene_lights_in_file_order_with_intensity_one() {
    let scene = import_file("full.txt").scene;
    assert_eq!(
        scene.lights,
        [
            Light::Ambient {
                colour: DVec3::splat(0.2),
                intensity: 1.0
            },
            Light::Point {
                position: DVec3::new(1.0, 5.0, -2.0),
                colour: DVec3::splat(10.0),
                intensity: 1.0
            },
            Light::Directional {
                direction: DVec3::new(0.0, -1.0, 0.0),
                colour: DVec3::splat(0.5),
                intensity: 1.0
            },
            Light::Spot {
                position: DVec3::new(0.0, 5.0, 0.0),
                direction: DVec3::new(0.0, -1.0, 1e-3),
                angle_deg: 30.0,
                colour: DVec3::new(20.0, 18.0, 16.0),
                intensity: 1.0
            },
        ]
    );
}

#[test]
fn full_scene_materials_overrides_and_default() {
    let scene = import_file("full.txt").scene;
    let names: Vec<&str> = scene.materials.keys().map(String::as_str).collect();
    assert_eq!(
        names,
        ["Red", "Red (Cone 4)", "default", "red#1", "red#1 (Cube 2)"]
    );
    let red = DVec3::X;
    assert_eq!(
        scene.materials["red#1"],
        material(red, red, DVec3::splat(0.5), 32.0, DVec3::splat(0.25))
    );
    assert_eq!(
        scene.materials["Red"],
        material(
            DVec3::new(0.1, 0.0, 0.0),
            DVec3::new(0.7, 0.0, 0.0),
            DVec3::ZERO,
            1.0,
            DVec3::ZERO
        )
    );
    // The cube's copy of red#1 with Colour 0 1 0: ambient and diffuse change.
    assert_eq!(
        scene.materials["red#1 (Cube 2)"],
        material(
            DVec3::Y,
            DVec3::Y,
            DVec3::splat(0.5),
            32.0,
            DVec3::splat(0.25)
        )
    );
    // The cone's copy of Red with every field overridden, in file order.
    assert_eq!(
        scene.materials["Red (Cone 4)"],
        material(
            DVec3::new(0.0, 0.0, 0.1),
            DVec3::new(0.0, 0.0, 0.7),
            DVec3::ONE,
            8.0,
            DVec3::splat(0.5)
        )
    );
    assert_eq!(scene.materials["default"], magenta());
}

#[test]
fn full_scene_objects_and_transforms() {
    let import = import_file("full.txt");
    let objects = &import.scene.objects;
    let summary: Vec<(&str, Shape, &str)> = objects
        .iter()
        .map(|o| (o.name.as_str(), o.shape, o.material.as_str()))
        .collect();
    assert_eq!(
        summary,
        [
            ("Sphere 0", Shape::Sphere, "red#1"),
            ("Plane 1", Shape::Plane, "Red"),
            ("Cube 2", Shape::Cube, "red#1 (Cube 2)"),
            ("Cylinder 3", Shape::Cylinder, "default"),
            ("Cone 4", Shape::Cone, "Red (Cone 4)"),
        ]
    );
    // Scale 2, then Translate 0 -2 0.
    assert_eq!(
        objects[0].transform,
        trs([0.0, -2.0, 0.0], [0.0; 3], [2.0; 3])
    );
    assert_eq!(
        objects[1].transform,
        trs([0.0, -1.0, 0.0], [-90.0, 0.0, 0.0], [10.0, 10.0, 1.0])
    );
    assert_eq!(
        objects[2].transform,
        trs([3.0, 0.0, 0.0], [0.0, 0.0, 45.0], [1.0; 3])
    );
    assert_eq!(
        objects[4].transform,
        trs([-3.0, 0.0, 0.0], [0.0; 3], [1.0, -1.0, 1.0])
    );
    // Rotate X 30 then Scale3 1 2 1 is S * Rx: a shear, kept as a matrix.
    let (s, c) = 30f64.to_radians().sin_cos();
    let Transform::Matrix(rows) = objects[3].transform else {
        panic!("expected a matrix, got {:?}", objects[3].transform);
    };
    let expected = [
        [1.0, 0.0, 0.0, 0.0],
        [0.0, 2.0 * c, -2.0 * s, 0.0],
        [0.0, s, c, 0.0],
    ];
    for (row, want) in rows.iter().zip(expected) {
        for (x, y) in row.iter().zip(want) {
            assert!((x - y).abs() < 1e-15, "{rows:?}");
        }
    }
}

#[test]
fn octahedron_is_skipped_with_the_only_warning() {
    let import = import_file("full.txt");
    assert_eq!(import.warnings.len(), 1, "{:?}", import.warnings);
    assert!(
        import.warnings[0].starts_with("line 83: "),
        "{:?}",
        import.warnings
    );
    assert!(import.warnings[0].contains("Octahedron"));
}

#[test]
fn older_files_put_the_ambient_light_in_the_scene_block() {
    let import = import_file("old_ambient.txt");
    assert!(import.warnings.is_empty(), "{:?}", import.warnings);
    let scene = import.scene;
    assert_eq!(
        scene.lights,
        [Light::Ambient {
            colour: DVec3::splat(0.3),
            intensity: 1.0
        }]
    );
    // Legacy defaults: 800 x 600, three bounces, black background.
    assert_eq!((scene.camera.width, scene.camera.height), (800, 600));
    assert_eq!(scene.render.max_depth, 3);
    assert_eq!(scene.render.background, DVec3::ZERO);
    // No Material: the default magenta, added because it is used.
    assert_eq!(scene.materials.len(), 1);
    assert_eq!(scene.materials["default"], magenta());
    assert_eq!(scene.objects[0].material, "default");
    assert_eq!(
        scene.objects[0].transform,
        trs([0.0, 0.0, 5.0], [0.0; 3], [1.0; 3])
    );
}

#[test]
fn the_default_material_is_added_only_when_used_and_never_clashes() {
    let scene = import_file("lit_sphere.txt").scene;
    assert_eq!(scene.materials.keys().collect::<Vec<_>>(), ["clay"]);

    let scene = import_text(
        "Material default Colour 0 1 0 End \
         Object Sphere Material default End \
         Object Cube End",
    )
    .scene;
    assert_eq!(scene.materials["default"].diffuse, DVec3::Y);
    assert_eq!(scene.objects[1].material, "default 2");
    assert_eq!(scene.materials["default 2"], magenta());
}

#[test]
fn overriding_the_default_material_names_the_object() {
    let scene = import_text("Object Sphere Mirror 1 1 1 End").scene;
    assert_eq!(scene.objects[0].material, "default (Sphere 0)");
    assert_eq!(scene.materials.len(), 1);
    assert_eq!(scene.materials["default (Sphere 0)"].mirror, DVec3::ONE);
}

#[test]
fn objects_copy_a_material_as_it_is_when_they_use_it() {
    let import = import_text(
        "Material m Colour 1 0 0 End Camera PinholeCamera 1 End\n\
         Object Sphere Material m End\n\
         Material m Colour 0 0 1 End\n\
         Object Cube Material m End",
    );
    assert_eq!(import.scene.objects[0].material, "m (line 1)");
    assert_eq!(import.scene.materials["m (line 1)"].diffuse, DVec3::X);
    assert_eq!(import.scene.objects[1].material, "m");
    assert_eq!(import.scene.materials["m"].diffuse, DVec3::Z);
    assert_eq!(import.warnings.len(), 1, "{:?}", import.warnings);
    assert!(import.warnings[0].starts_with("line 3: material `m` is defined again"));
}

#[test]
fn overrides_before_material_are_replaced_by_the_copy_with_a_warning() {
    let import = import_text(
        "Material m Colour 1 0 0 End Camera PinholeCamera 1 End\nObject Sphere\n Colour 0 1 0\n Material m\nEnd",
    );
    assert_eq!(import.scene.objects[0].material, "m");
    assert_eq!(import.warnings.len(), 1, "{:?}", import.warnings);
    assert!(
        import.warnings[0].starts_with("line 3: "),
        "{:?}",
        import.warnings
    );
}

#[test]
fn case_rules_comments_and_number_forms() {
    let scene = import_text(
        "#comment at the start\r\nsCeNe rendersize 8 6 RAYDEPTH 0 eNd\r\n\
         MATERIAL Mat#1 colour .5 1. 1e-1 END # trailing\r\n\
         oBjEcT sPhErE mAtErIaL Mat#1 rOtAtE z -3 tRaNsLaTe +1 -2 3. EnD",
    )
    .scene;
    assert_eq!((scene.camera.width, scene.camera.height), (8, 6));
    assert_eq!(scene.render.max_depth, 0);
    assert_eq!(scene.materials["Mat#1"].diffuse, DVec3::new(0.5, 1.0, 0.1));
    assert_eq!(
        scene.objects[0].transform,
        trs([1.0, -2.0, 3.0], [0.0, 0.0, -3.0], [1.0; 3])
    );
    // Material names are case-sensitive.
    let errors = errors_of_text("Material Gold End Object Sphere Material gold End");
    assert_one_error(&errors, 1, "gold", "never defined");
}

#[test]
fn light_keywords_a_kind_does_not_use_are_ignored_with_a_warning() {
    let import = import_text(
        "Camera PinholeCamera 1 End Light PointLight\n Colour 1 1 1\n Location 0 0 0\n Angle 10\nEnd",
    );
    assert_eq!(import.warnings.len(), 1, "{:?}", import.warnings);
    assert!(import.warnings[0].starts_with("line 4: `Angle` has no effect"));
}

#[test]
fn a_file_without_a_camera_gets_the_unit_camera_and_a_warning() {
    let import = import_text("Object Sphere Translate 0 0 5 End");
    assert_eq!(import.scene.camera.position, DVec3::ZERO);
    assert_eq!(import.scene.camera.look_at, DVec3::Z);
    assert_eq!(import.warnings.len(), 1);
    assert!(import.warnings[0].contains("no Camera"));
}

#[test]
fn a_distorting_camera_transform_is_warned_about() {
    let import = import_text("Camera PinholeCamera 1\n Scale3 1 2 1\nEnd");
    assert_eq!(import.warnings.len(), 1, "{:?}", import.warnings);
    assert!(import.warnings[0].starts_with("line 1: the camera's transform"));
}

// ---------------------------------------------------------------- errors

#[test]
fn unknown_block() {
    let errors = errors_of_file("err_unknown_block.txt");
    assert_one_error(&errors, 5, "Objekt", "unknown block type");
}

#[test]
fn unknown_keyword() {
    let errors = errors_of_file("err_unknown_keyword.txt");
    assert_one_error(&errors, 3, "Shininess", "unknown keyword");
}

#[test]
fn bad_number() {
    let errors = errors_of_file("err_bad_number.txt");
    assert_one_error(&errors, 2, "1,0", "not a number");
}

#[test]
fn wrong_count_of_numbers() {
    let errors = errors_of_file("err_wrong_count.txt");
    assert_one_error(&errors, 2, "Translate", "found 2");
}

#[test]
fn missing_end_at_the_end_of_the_file() {
    let errors = errors_of_file("err_missing_end.txt");
    assert_one_error(&errors, 5, "Object", "no `End`");
}

#[test]
fn missing_end_before_the_next_block() {
    let errors = errors_of_file("err_missing_end_inside.txt");
    assert_one_error(
        &errors,
        4,
        "Object",
        "`End` of the Object block at line 1 missing",
    );
}

#[test]
fn tokens_after_the_last_end() {
    let errors = errors_of_file("err_after_last_end.txt");
    assert_one_error(&errors, 4, "Scale", "unexpected end of file");
}

#[test]
fn material_used_before_it_is_defined() {
    let errors = errors_of_file("err_material_before_definition.txt");
    assert_one_error(
        &errors,
        2,
        "gold",
        "before it is defined (its definition is at line 5)",
    );
}

#[test]
fn spot_light_without_angle() {
    let errors = errors_of_file("err_spot_without_angle.txt");
    assert_one_error(&errors, 1, "SpotLight", "needs an `Angle`");
}

#[test]
fn zero_scale() {
    let errors = errors_of_file("err_zero_scale.txt");
    assert_one_error(&errors, 2, "0", "singular");
}

#[test]
fn every_error_is_reported_in_line_order() {
    let errors = errors_of_file("err_many.txt");
    let summary: Vec<(usize, &str)> = errors
        .0
        .iter()
        .map(|e| (e.line, e.token.as_str()))
        .collect();
    assert_eq!(
        summary,
        [
            (3, "0"),
            (6, "W"),
            (9, "nowhere"),
            (10, "-1"),
            (12, "PointLight")
        ],
        "{errors}"
    );
    assert_eq!(errors.to_string().lines().count(), 5);
}

#[test]
fn values_the_scene_format_cannot_hold_are_errors_at_their_token() {
    let cases: &[(&str, usize, &str, &str)] = &[
        ("Scene\nrayDepth 2.5\nEnd", 2, "2.5", "whole number"),
        (
            "Scene\nrayDepth 65\nEnd",
            2,
            "65",
            "whole number from 0 to 64",
        ),
        ("Scene\nbackgroundColour 0 0 -1\nEnd", 2, "-1", "negative"),
        (
            "Camera PinholeCamera 0\nEnd",
            1,
            "0",
            "focal length must be positive",
        ),
        ("Camera PinholeCamera\nEnd", 1, "PinholeCamera", "found 0"),
        ("Camera Fisheye 1\nEnd", 1, "Fisheye", "unknown camera type"),
        ("Light NeonLight\nEnd", 1, "NeonLight", "unknown light type"),
        ("Object Torus\nEnd", 1, "Torus", "unknown object type"),
        ("Object Sphere 2\nEnd", 1, "2", "takes no numbers"),
        ("Light\nEnd", 1, "Light", "needs a light type"),
        (
            "Light DirectionalLight Colour 1 1 1\nDirection 0 0 0\nEnd",
            2,
            "Direction",
            "zero",
        ),
        (
            "Light DirectionalLight\nColour 1 1 1\nEnd",
            1,
            "DirectionalLight",
            "needs a `Direction`",
        ),
        (
            "Light PointLight\nLocation 1 1 1\nEnd",
            1,
            "PointLight",
            "needs a `Colour`",
        ),
        (
            "Light SpotLight Colour 1 1 1 Location 0 0 0 Direction 0 0 1\nAngle 91\nEnd",
            2,
            "91",
            "at most 90",
        ),
        (
            "Material m\nSpecular 1 1 1 0\nEnd",
            2,
            "0",
            "exponent must be positive",
        ),
        ("Object Sphere\nMaterial\nEnd", 2, "Material", "takes NAME"),
        (
            "Object Sphere\nRotate 30\nEnd",
            2,
            "Rotate",
            "an axis and a number",
        ),
        (
            "Object Sphere\nScale 1e999\nEnd",
            2,
            "1e999",
            "out of range",
        ),
        (
            "Scene\nrenderSize 20000 10\nEnd",
            2,
            "20000",
            "from 1 to 16384",
        ),
        ("Object Sphere End\nEnd", 2, "End", "no block before it"),
        (
            "Object Sphere\nScale 1e-200\nScale 1e-200\nEnd",
            1,
            "Sphere",
            "cannot be imported",
        ),
        (
            "Camera PinholeCamera 1e-300\nEnd",
            1,
            "PinholeCamera",
            "camera cannot be imported",
        ),
    ];
    for &(text, line, token, fragment) in cases {
        let errors = errors_of_text(text);
        assert_eq!(errors.0.len(), 1, "{text:?}: {errors}");
        let message = errors.to_string();
        assert!(
            message.starts_with(&format!("line {line}: `{token}`: ")) && message.contains(fragment),
            "{text:?}: {message}"
        );
    }
}

#[test]
fn a_wrong_keyword_is_not_also_reported_missing_but_other_missing_ones_are() {
    let errors =
        errors_of_text("Light SpotLight\nColour 1 x 1\nLocation 0 0 0\nDirection 0 0 1\nEnd");
    let summary: Vec<(usize, &str)> = errors
        .0
        .iter()
        .map(|e| (e.line, e.token.as_str()))
        .collect();
    // `Colour 1` has one number, then `x` is an unknown keyword; the missing Angle counts,
    // the wrong Colour is not reported a second time as missing.
    assert_eq!(
        summary,
        [(1, "SpotLight"), (2, "Colour"), (2, "x")],
        "{errors}"
    );
    assert!(errors.0[0].message.contains("`Angle`"), "{errors}");
}

#[test]
fn unreadable_and_non_utf8_files_are_errors() {
    let missing = import_legacy_file(&legacy_path("no such file.txt"));
    assert!(
        matches!(missing, Err(LegacyImportFileError::Read { .. })),
        "{missing:?}"
    );

    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("legacy_latin1.txt");
    std::fs::write(&path, b"Material caf\xe9\nEnd\n").expect("write temp file");
    match import_legacy_file(&path) {
        Err(LegacyImportFileError::NotText { line, .. }) => assert_eq!(line, 1),
        other => panic!("expected NotText, got {other:?}"),
    }
}

#[test]
fn arbitrary_bytes_never_panic() {
    // A handful of nasty inputs: every one either imports or reports errors.
    for text in [
        "",
        "End",
        "End End",
        "#",
        "Scene",
        "Object",
        "Object Sphere Material",
        "Rotate X",
        "Camera PinholeCamera 1 Rotate",
        "Object Sphere Scale3 1e308 1e308 1e308 Scale 1e308 End",
        "Light SpotLight Angle nan End",
        "\u{feff}Scene End",
        "Object Sphere Translate - + . End",
    ] {
        if let Ok(import) = import_legacy(text) {
            validate(&import.scene).unwrap_or_else(|e| panic!("{text:?}: {e}"));
        }
    }
}

// ---------------------------------------------------------------- renders

#[test]
fn imported_camera_rays_are_the_legacy_rays() {
    // The legacy ray through pixel (u, v) is M (x, y, F) with x = -1 + (u + 0.5) 2/W and
    // y = -H/W + (v + 0.5) 2/W, M the camera's transform in file order.
    let cases: [(&str, DAffine3); 3] = [
        ("", DAffine3::IDENTITY),
        (
            "Rotate Y 30 Rotate Z -20 Translate 1 2 3",
            DAffine3::from_translation(DVec3::new(1.0, 2.0, 3.0))
                * DAffine3::from_rotation_z((-20f64).to_radians())
                * DAffine3::from_rotation_y(30f64.to_radians()),
        ),
        (
            "Scale 2 Rotate X 180 Rotate Y 90 Translate -4 0 1",
            DAffine3::from_translation(DVec3::new(-4.0, 0.0, 1.0))
                * DAffine3::from_rotation_y(90f64.to_radians())
                * DAffine3::from_rotation_x(180f64.to_radians())
                * DAffine3::from_scale(DVec3::splat(2.0)),
        ),
    ];
    let (width, height, focal) = (7u32, 5u32, 1.5);
    for (steps, world_from_camera) in cases {
        let text = format!(
            "Scene renderSize {width} {height} End Camera PinholeCamera {focal} {steps} End"
        );
        let scene = import_text(&text).scene;
        let camera = PinholeCamera::new(&scene.camera, width, height);
        for v in 0..height {
            for u in 0..width {
                let x = -1.0 + (f64::from(u) + 0.5) * 2.0 / f64::from(width);
                let y = -f64::from(height) / f64::from(width)
                    + (f64::from(v) + 0.5) * 2.0 / f64::from(width);
                let legacy = world_from_camera
                    .transform_vector3(DVec3::new(x, y, focal))
                    .normalize();
                let ray = camera.ray(DVec2::new(f64::from(u) + 0.5, f64::from(v) + 0.5));
                assert!(
                    (ray.dir - legacy).length() < 1e-12,
                    "{steps}: pixel ({u}, {v}): {} vs {legacy}",
                    ray.dir
                );
                assert!((ray.origin - world_from_camera.translation).length() < 1e-12);
            }
        }
    }
}

#[test]
fn a_sphere_at_a_known_place_lands_on_the_expected_pixel() {
    let scene = import_file("camera_pixel.txt").scene;
    // Hand-computed in the file: pixel (30, 10) looks at (3.625, 3.125, -7).
    let camera = PinholeCamera::new(&scene.camera, 40, 30);
    let centre = camera
        .project(DVec3::new(3.625, 3.125, -7.0))
        .expect("in front");
    assert!(
        (centre - DVec2::new(30.5, 10.5)).length() < 1e-9,
        "{centre}"
    );

    let image = render_scene(&scene);
    let magenta = Vec3::new(1.0, 0.0, 1.0);
    let background = Vec3::new(0.0, 0.5, 0.0);
    assert_eq!(image.get(30, 10), magenta);
    for (x, y) in [
        (29, 10),
        (31, 10),
        (30, 9),
        (30, 11),
        (9, 19),
        (0, 0),
        (39, 29),
    ] {
        assert_eq!(image.get(x, y), background, "pixel ({x}, {y})");
    }
    let lit = image.pixels.iter().filter(|&&p| p == magenta).count();
    assert_eq!(lit, 1);
}

#[test]
fn a_lit_sphere_matches_the_hand_computed_colour() {
    let scene = import_file("lit_sphere.txt").scene;
    let image = render_scene(&scene);
    let centre = image.get(10, 10);
    let expected = Vec3::new(0.8, 0.5, 0.35);
    assert!(
        (centre - expected).abs().max_element() < 1e-6,
        "{centre} expected {expected}"
    );
    assert_eq!(image.get(0, 0), Vec3::ZERO);
}

#[test]
fn ray_depth_counts_mirror_bounces() {
    let text = std::fs::read_to_string(legacy_path("mirror.txt")).expect("read mirror.txt");
    let one_bounce = import_text(&text).scene;
    assert_eq!(one_bounce.render.max_depth, 1);
    let centre = render_scene(&one_bounce).get(10, 10);
    let expected = Vec3::new(0.3, 0.1, 0.2);
    assert!(
        (centre - expected).abs().max_element() < 1e-6,
        "{centre} expected {expected}"
    );

    let no_bounce = import_text(&text.replace("rayDepth 1", "rayDepth 0")).scene;
    assert_eq!(no_bounce.render.max_depth, 0);
    assert_eq!(render_scene(&no_bounce).get(10, 10), Vec3::ZERO);
}

#[test]
fn round_trip_through_ron_renders_identical_pixels() {
    for name in [
        "full.txt",
        "camera_pixel.txt",
        "lit_sphere.txt",
        "mirror.txt",
    ] {
        let imported = import_file(name).scene;
        let text = scene_to_ron(&imported);
        let loaded = parse_scene(&text).unwrap_or_else(|e| panic!("{name}: {e}\n{text}"));
        assert_eq!(loaded, imported, "{name}");
        let direct = render_scene(&imported);
        let again = render_scene(&loaded);
        assert_eq!(direct.pixels, again.pixels, "{name}");
    }
}

// ---------------------------------------------------------------- command line

fn raylab() -> Command {
    Command::new(env!("CARGO_BIN_EXE_raylab"))
}

#[test]
fn cli_imports_a_file_and_prints_warnings() {
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
        stderr.contains("warning:") && stderr.contains("Octahedron"),
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
