//! The students' extensions of the legacy format (issue 38): a scene file of each
//! framework's dialect, each extension and their combinations, the scene model each one
//! imports to, and the warnings it gives.

mod common;

use std::path::{Path, PathBuf};

use common::legacy::{assert_one_error, errors_of_text, import_text, trs};
use glam::DVec3;
use raylab::scene::legacy::{Dialect, LegacyImport, import_legacy, import_legacy_file};
use raylab::scene::{
    Conventions, CsgOp, Light, LightSource, Object, Shape, parse_scene, scene_to_ron,
};

fn ext_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/legacy_ext")
        .join(name)
}

fn import_ext(name: &str) -> LegacyImport {
    import_legacy_file(&ext_path(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Asserts the warnings are exactly these, in order: (line, fragment of the text).
fn assert_warnings(import: &LegacyImport, expected: &[(&str, &str)]) {
    assert_eq!(
        import.warnings.len(),
        expected.len(),
        "{:#?}",
        import.warnings
    );
    for (warning, (start, fragment)) in import.warnings.iter().zip(expected) {
        assert!(
            warning.starts_with(start) && warning.contains(fragment),
            "{warning:?} should start {start:?} and contain {fragment:?}"
        );
    }
}

fn leaf(name: &str, shape: Shape, material: &str) -> Object {
    Object {
        name: name.to_owned(),
        shape,
        transform: Default::default(),
        material: material.to_owned(),
    }
}

#[test]
fn the_2016_dialect_nested_csg_white_default_and_names_in_any_case() {
    let import = import_ext("snowman_2016.txt");
    assert_eq!(import.dialect.dialect, Dialect::Framework2016);
    assert!(
        import
            .summary()
            .starts_with("read as the 2016 framework's dialect (`Object CSG` at line 22)"),
        "{}",
        import.summary()
    );
    assert_warnings(
        &import,
        &[
            ("line 24: ", "material `SNOW` is taken to be `snow`"),
            ("line 32: ", "`Colour` on a CSG Union node does nothing"),
        ],
    );
    let scene = &import.scene;
    assert_eq!((scene.camera.width, scene.camera.height), (40, 30));
    assert_eq!(scene.render.samples_per_pixel, 4);
    assert_eq!(scene.render.conventions, Conventions::COURSE);
    // The 2016 framework's default material is white; Material blocks start from it.
    assert_eq!(scene.materials["default"].diffuse, DVec3::ONE);
    assert_eq!(scene.materials["snow"].diffuse, DVec3::new(0.9, 0.9, 1.0));
    let body = &scene.objects[0];
    assert_eq!(body.name, "Snowman's body");
    assert_eq!(body.transform, trs([0.0, 1.0, 0.0], [0.0; 3], [1.0; 3]));
    assert_eq!(body.material, "", "node material keywords are ignored");
    let small = Object {
        transform: trs([0.0, 1.3, 0.0], [0.0; 3], [0.6; 3]),
        ..leaf("Sphere 1", Shape::Sphere, "snow")
    };
    assert_eq!(
        body.shape,
        Shape::Csg {
            op: CsgOp::Union,
            operands: vec![leaf("Sphere 0", Shape::Sphere, "snow"), small],
        }
    );
    assert_eq!(scene.objects[1].name, "Hat");
    assert_eq!(scene.objects[1].material, "default");
}

#[test]
fn the_2016_snowman_renders_in_its_operands_material() {
    let scene = import_ext("snowman_2016.txt").scene;
    let image = common::legacy::render_scene(&scene);
    // The body's centre is in the middle of the picture: lit snow (0.9, 0.9, 1), not the
    // red the node's ignored `Colour` asks for, nor the background.
    let centre = image.get(scene.camera.width / 2, scene.camera.height / 2);
    assert!(centre.z > 0.2, "{centre}");
    assert!(
        centre.z >= centre.x && centre.y >= 0.8 * centre.x,
        "{centre}"
    );
}

#[test]
fn the_2020_dialect_with_every_students_extension() {
    let import = import_ext("workshop_2020.txt");
    assert_eq!(import.dialect.dialect, Dialect::Framework2020);
    assert!(
        import.summary().starts_with(
            "read as the 2020 framework's dialect (`Light AmbientLight` at line 13): 5 objects, 2 lights"
        ),
        "{}",
        import.summary()
    );
    assert_warnings(
        &import,
        &[
            ("line 6: ", "`renderNormals` is a debug view"),
            ("line 39: ", "`DisableBoundingBox` is a debug switch"),
            ("line 46: ", "`Object Parabaloid` is a stub"),
        ],
    );
    let scene = &import.scene;
    // renderSize 64 48, then scaleResolution 0.5; FSAA 3 is a 3 x 3 grid.
    assert_eq!((scene.camera.width, scene.camera.height), (32, 24));
    assert_eq!(scene.render.samples_per_pixel, 9);
    assert_eq!(
        scene.lights[1],
        Light::Point {
            position: DVec3::new(0.0, 4.0, -4.0),
            source: LightSource {
                colour: DVec3::splat(20.0),
                intensity: 1.0,
                radius: 0.5,
                samples: 16,
            },
        }
    );
    let glass = &scene.materials["glass"];
    assert_eq!(glass.transmission, DVec3::splat(0.8));
    assert_eq!(glass.ior, 1.5);
    assert_eq!(glass.mirror, DVec3::splat(0.1));
    let names: Vec<&str> = scene.objects.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(
        names,
        ["Ring", "Tube 1", "Octahedron 2", "Csg 3", "Group 4"]
    );
    // Torus 0.5: the unit torus of minor 0.5, scaled by R before the file's transforms.
    assert_eq!(scene.objects[0].shape, Shape::Torus { minor: 0.5 });
    assert_eq!(
        scene.objects[0].transform,
        trs([0.0, 0.25, 0.0], [0.0; 3], [0.5; 3])
    );
    // Tube 0.5: the hole's radius is sqrt(0.5 / 2) = 0.5.
    assert_eq!(scene.objects[1].shape, Shape::Tube { inner: 0.5 });
    assert_eq!(scene.objects[2].shape, Shape::Octahedron);
    // Top-level CSG: node transforms wherever they sit, composed in file order.
    let csg = &scene.objects[3];
    assert_eq!(csg.transform, trs([0.0, -0.5, 0.0], [0.0; 3], [0.5; 3]));
    let Shape::Csg { op, operands } = &csg.shape else {
        panic!("{csg:?}")
    };
    assert_eq!(*op, CsgOp::Difference);
    assert_eq!(operands[0], leaf("Cube 0", Shape::Cube, "default"));
    assert_eq!(operands[1].transform, trs([0.0; 3], [0.0; 3], [1.2; 3]));
    let Shape::Group { children } = &scene.objects[4].shape else {
        panic!("{:?}", scene.objects[4])
    };
    assert_eq!(children.len(), 2);
    assert_eq!(children[1], leaf("Cone 1", Shape::Cone, "default"));
    assert_eq!(
        scene.objects[4].transform,
        trs([0.0, 2.0, 0.0], [0.0; 3], [1.0; 3])
    );
}

#[test]
fn a_torus_in_a_2016_csg_in_a_group_with_supersampling_imports_to_its_ron() {
    let import = import_ext("combined.txt");
    let expected_text = std::fs::read_to_string(ext_path("combined.ron")).unwrap();
    let mut expected = parse_scene(&expected_text).unwrap();
    expected.camera = import.scene.camera.clone();
    assert_eq!(import.scene, expected);
    // Both dialects' constructs: read as 2020, and told.
    assert_eq!(import.dialect.dialect, Dialect::Framework2020);
    assert_warnings(
        &import,
        &[
            ("line 4: ", "`4` after `Supersampling` is skipped"),
            ("line 19: ", "also has an `ObjectGroup` (line 16)"),
        ],
    );
    // The RON written for it loads back to the same scene.
    assert_eq!(
        parse_scene(&scene_to_ron(&import.scene)).unwrap(),
        import.scene
    );
}

#[test]
fn meshes_are_found_beside_the_scene_as_written_or_lowercased() {
    let import = import_ext("mesh_scene.txt");
    let meshes: Vec<(&str, &Shape)> = import
        .scene
        .objects
        .iter()
        .map(|o| (o.name.as_str(), &o.shape))
        .collect();
    let mesh = |path: &str| Shape::Mesh { path: path.into() };
    assert_eq!(
        meshes,
        [
            ("Pyramid", &mesh("meshes/pyramid.obj")),
            ("Pyramid again", &mesh("../legacy_ext/meshes/pyramid.obj")),
        ]
    );
    assert_warnings(
        &import,
        &[("line 14: ", "Mesh `missing.obj`: no such file")],
    );
    // Text alone has no folder: paths are kept as written.
    let text = std::fs::read_to_string(ext_path("mesh_scene.txt")).unwrap();
    let import = import_legacy(&text).unwrap();
    assert_eq!(import.scene.objects.len(), 3);
}

#[test]
fn unknown_kinds_keywords_and_blocks_are_skipped_and_the_rest_imports() {
    for (text, line, fragment) in [
        (
            "Object Teapot Scale 2 End Object Sphere End",
            1,
            "unknown object type `Teapot`",
        ),
        (
            "Object Sphere\nShininess 30\nEnd",
            2,
            "unknown keyword `Shininess`",
        ),
        (
            "Lamp 1 2 End\nObject Sphere End",
            1,
            "unknown block type `Lamp`",
        ),
        ("Scene\nfsaa 300\nEnd Object Sphere End", 2, "at most 256"),
        (
            "Light PointLight Colour 1 1 1 Location 0 0 0\nSamples 1e9\nEnd Object Sphere End",
            2,
            "at most 1024",
        ),
    ] {
        let import = import_text(text);
        let warning = &import.warnings[0];
        assert!(
            warning.starts_with(&format!("line {line}: ")) && warning.contains(fragment),
            "{text:?}: {:?}",
            import.warnings
        );
        assert_eq!(import.scene.objects.len(), 1, "{text:?}");
    }
    assert_eq!(
        import_text("Scene FSAA 1e9 End")
            .scene
            .render
            .samples_per_pixel,
        65536
    );
    let light = &import_text(
        "Light SpotLight Colour 1 1 1 Location 0 0 0 Direction 0 0 1 Angle 9 Samples 1e9 End",
    )
    .scene
    .lights[0];
    assert!(
        matches!(
            light,
            Light::Spot {
                source: LightSource { samples: 1024, .. },
                ..
            }
        ),
        "{light:?}"
    );
}

#[test]
fn material_names_match_exactly_then_one_ignoring_case() {
    // Material names match exactly first, then ignoring case when only one matches
    // (the 2016 framework upper-cases lines), with a warning; several matches are an
    // error at the name.
    let import =
        import_text("Material Gold End Material GOLD End\nObject Sphere Material Gold End");
    assert_eq!(import.scene.objects[0].material, "Gold");
    assert!(
        !import.warnings.iter().any(|w| w.contains("material")),
        "{:?}",
        import.warnings
    );
    let import = import_text("Material Gold End\nObject Sphere Material gold End");
    assert_eq!(import.scene.objects[0].material, "Gold");
    assert!(
        import.warnings[0].starts_with("line 2: material `gold` is taken to be `Gold`"),
        "{:?}",
        import.warnings
    );
    let errors =
        errors_of_text("Material Gold End Material GOLD End\nObject Sphere Material gold End");
    assert_one_error(&errors, 2, "gold", "several match it ignoring case");
}

#[test]
fn tree_syntax_errors_refuse_the_file_at_their_line_and_token() {
    assert_one_error(
        &errors_of_text("Object CSG Union\nObject Sphere End\nObject Cube End\n"),
        1,
        "Object",
        "no `End`",
    );
    assert_one_error(
        &errors_of_text("Object CSG\nObject Sphere End End"),
        2,
        "Object",
        "Union, Intersection or Difference",
    );
    assert_one_error(
        &errors_of_text("ObjectGroup Object Sphere Scale 0 End End"),
        1,
        "0",
        "singular",
    );
}

#[test]
fn nesting_up_to_the_tree_limit_imports_and_deeper_is_an_error() {
    let depth = raylab::scene::legacy::MAX_NESTING;
    let nested = |levels: usize| {
        "ObjectGroup\n".repeat(levels) + "Object Sphere End\n" + &"End\n".repeat(levels)
    };
    // `levels` groups put the sphere at depth `levels`.
    let import = import_text(&nested(depth));
    let mut object = &import.scene.objects[0];
    let mut levels = 0;
    while let Some(child) = object.shape.children().first() {
        object = child;
        levels += 1;
    }
    assert_eq!(levels, depth);
    let errors = errors_of_text(&nested(depth + 1));
    assert_one_error(
        &errors,
        depth + 1,
        "ObjectGroup",
        &format!("more than {depth} levels"),
    );
}
