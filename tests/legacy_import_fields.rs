//! The legacy COSC342 importer, field by field: render settings, camera, lights,
//! materials and their names, objects and transforms, and the warnings for what is
//! skipped or imported with a caveat.

mod common;

use common::legacy::{
    assert_one_error, assert_vec, errors_of_text, import_file, import_text, legacy_text, magenta,
    material, trs,
};
use glam::DVec3;
use raylab::scene::{Light, LightSource, MAX_DEPTH, Shape, Transform, validate};

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
    // Rotate X 180 then Translate 0 1 10: at (0, 1, 10), looking down -Z, +Y up. All
    // six objects are in view, five centred at depth 10 and the cone at 9.5 (its
    // bounds' centre is (-3, 0, 0.5)): the target is at their mean depth, 9 + 11/12.
    assert_vec(camera.position, DVec3::new(0.0, 1.0, 10.0));
    assert_vec(camera.look_at, DVec3::new(0.0, 1.0, 1.0 / 12.0));
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
                source: LightSource::point(DVec3::splat(10.0), 1.0),
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
                source: LightSource::point(DVec3::new(20.0, 18.0, 16.0), 1.0),
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
        .map(|o| (o.name.as_str(), o.shape.clone(), o.material.as_str()))
        .collect();
    assert_eq!(
        summary,
        [
            ("Sphere 0", Shape::Sphere, "red#1"),
            ("Plane 1", Shape::Plane, "Red"),
            ("Cube 2", Shape::Cube, "red#1 (Cube 2)"),
            ("Cylinder 3", Shape::Cylinder, "default"),
            ("Cone 4", Shape::Cone, "Red (Cone 4)"),
            ("Octahedron 5", Shape::Octahedron, "Red"),
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
fn an_octahedron_is_imported_as_students_tracers_draw_it() {
    let import = import_file("full.txt");
    assert!(import.warnings.is_empty(), "{:?}", import.warnings);
    assert!(
        import
            .scene
            .objects
            .iter()
            .any(|o| o.shape == Shape::Octahedron),
        "{:?}",
        import.scene.objects
    );
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
    // Matching names ignoring case: see legacy_import_extensions.rs.
    let errors = errors_of_text("Material Gold End Object Sphere Material silver End");
    assert_one_error(&errors, 1, "silver", "never defined");
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
    // Looking along +Z, at the sphere.
    assert_eq!(import.scene.camera.look_at, DVec3::new(0.0, 0.0, 5.0));
    assert_eq!(import.warnings.len(), 1);
    assert!(import.warnings[0].contains("no Camera"));
}

#[test]
fn a_distorting_camera_transform_is_warned_about() {
    let import = import_text("Camera PinholeCamera 1\n Scale3 1 2 1\nEnd");
    assert_eq!(import.warnings.len(), 1, "{:?}", import.warnings);
    assert!(import.warnings[0].starts_with("line 1: the camera's transform"));
}

#[test]
fn the_camera_looks_at_the_content_not_one_unit_ahead() {
    let import = import_file("camera_target.txt");
    assert!(import.warnings.is_empty(), "{:?}", import.warnings);
    let camera = &import.scene.camera;
    // Hand-computed in the file: the mean depth of the sphere and the cone in view.
    assert_vec(camera.position, DVec3::new(0.0, 1.0, 10.0));
    assert_vec(camera.look_at, DVec3::new(0.0, 1.0, -2.25));
    // Without a camera block the same rule applies to the unit camera.
    let scene =
        import_text("Object Sphere Translate 1 0 4 End Object Cube Translate -1 0 8 End").scene;
    assert_vec(scene.camera.look_at, DVec3::new(0.0, 0.0, 6.0));
    // With nothing in front, one step ahead as before.
    let scene = import_text("Camera PinholeCamera 1 End Object Sphere Translate 0 0 -5 End").scene;
    assert_vec(scene.camera.look_at, DVec3::Z);
}

#[test]
fn a_spot_light_without_angle_is_an_unlit_spot_with_a_warning() {
    let import = import_file("spot_without_angle.txt");
    assert_eq!(import.warnings.len(), 1, "{:?}", import.warnings);
    assert!(
        import.warnings[0].starts_with("line 22: a SpotLight without `Angle`")
            && import.warnings[0].contains("lights nothing"),
        "{:?}",
        import.warnings
    );
    let spot = &import.scene.lights[1];
    assert_eq!(
        *spot,
        Light::Spot {
            position: DVec3::new(0.0, 3.0, 0.0),
            direction: DVec3::NEG_Y,
            angle_deg: 45.0,
            source: LightSource::point(DVec3::splat(50.0), 0.0),
        }
    );
    validate(&import.scene).expect("valid");
}

#[test]
fn wide_spot_angles_and_a_zero_exponent_import_as_written() {
    for angle in ["120", "180", "90.5"] {
        let text = legacy_text("spot_wide.txt").replace("Angle 120", &format!("Angle {angle}"));
        let scene = import_text(&text).scene;
        let expected: f64 = angle.parse().unwrap();
        assert!(
            matches!(scene.lights[0], Light::Spot { angle_deg, source: LightSource { intensity, .. }, .. } if angle_deg == expected && intensity == 1.0),
            "{:?}",
            scene.lights
        );
    }
    let scene = import_file("shininess_zero.txt").scene;
    assert_eq!(scene.materials["satin"].shininess, 0.0);
    assert_eq!(scene.materials["satin"].specular, DVec3::ONE);
}

#[test]
fn any_ray_depth_imports_and_beyond_the_limit_is_capped_with_a_warning() {
    let import = import_file("mirrors_depth_100.txt");
    assert!(import.warnings.is_empty(), "{:?}", import.warnings);
    assert_eq!(import.scene.render.max_depth, 100);
    let at_limit = import_text(&format!(
        "Camera PinholeCamera 1 End Scene rayDepth {MAX_DEPTH} End"
    ));
    assert_eq!(at_limit.scene.render.max_depth, MAX_DEPTH);
    assert!(at_limit.warnings.is_empty(), "{:?}", at_limit.warnings);
    for huge in ["10001", "1000000", "1e30"] {
        let import = import_text(&format!(
            "Camera PinholeCamera 1 End\nScene\n rayDepth {huge}\nEnd"
        ));
        assert_eq!(import.scene.render.max_depth, MAX_DEPTH, "{huge}");
        assert_eq!(import.warnings.len(), 1, "{:?}", import.warnings);
        assert!(
            import.warnings[0].starts_with("line 3: rayDepth ")
                && import.warnings[0].contains(&format!("at most {MAX_DEPTH}")),
            "{:?}",
            import.warnings
        );
    }
}
