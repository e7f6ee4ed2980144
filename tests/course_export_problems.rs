//! Each thing a course dialect cannot say, refused or warned by name: the error or
//! warning names the object, light, material or setting, and what is lost. A refused
//! export writes nothing; a warned one still reads back.

use raylab::scene::legacy::{
    CourseExportError, CourseScene, Dialect, Problem, Subject, import_legacy, write_course_scene,
};
use raylab::scene::{Scene, parse_scene};

const D2016: Dialect = Dialect::Framework2016;
const D2020: Dialect = Dialect::Framework2020;

/// A scene with the materials "grey", "glass" and "Grey Paint", the objects `objects`
/// (RON), the lights `lights` (RON) and the render settings `render` (RON).
fn scene(objects: &str, lights: &str, render: &str) -> Scene {
    let text = format!(
        r#"Scene(
            camera: (position: (0, 0, 5), look_at: (0, 0, 0), fov_deg: 40, width: 8, height: 6),
            render: ({render}),
            materials: {{
                "grey": (ambient: (0.1, 0.1, 0.1), diffuse: (0.5, 0.5, 0.5)),
                "glass": (transmission: (0.9, 0.9, 0.9), ior: 1.5),
                "Grey Paint": (diffuse: (0.4, 0.4, 0.4)),
            }},
            objects: [{objects}],
            lights: [{lights}],
        )"#
    );
    parse_scene(&text).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

fn objects(objects: &str) -> Scene {
    scene(
        objects,
        "",
        "samples_per_pixel: 1, conventions: (mirror: Add, clamp: EachRay, quantise: Truncate)",
    )
}

fn refused(scene: &Scene, dialect: Dialect) -> CourseExportError {
    match write_course_scene(scene, dialect) {
        Ok(written) => panic!("should be refused, wrote:\n{}", written.text),
        Err(error) => error,
    }
}

fn written(scene: &Scene, dialect: Dialect) -> CourseScene {
    write_course_scene(scene, dialect).unwrap_or_else(|e| panic!("should be written: {e}"))
}

/// Asserts `problems` has one about `subject` whose message contains `fragment`.
fn assert_named(problems: &[Problem], subject: &Subject, fragment: &str) {
    assert!(
        problems
            .iter()
            .any(|p| &p.subject == subject && p.message.contains(fragment)),
        "no problem about {subject} containing {fragment:?} in {problems:#?}"
    );
}

fn object(path: &str) -> Subject {
    Subject::Object(path.to_owned())
}

#[test]
fn shapes_a_dialect_lacks_are_refused_by_name() {
    let mesh = objects(r#"(name: "teapot", shape: Mesh(path: "teapot.obj"), material: "grey")"#);
    assert_named(
        &refused(&mesh, D2020).refusals,
        &object("teapot"),
        "the 2020 dialect has no Mesh",
    );
    for (shape, word) in [
        ("Torus(minor: 0.5)", "Torus"),
        ("Tube(inner: 0.5)", "Tube"),
        ("Octahedron", "Octahedron"),
    ] {
        let scene = objects(&format!(
            r#"(name: "it", shape: {shape}, material: "grey")"#
        ));
        assert_named(
            &refused(&scene, D2016).refusals,
            &object("it"),
            &format!("the 2016 dialect has no {word}"),
        );
        // The 2020 dialect's students' extensions have them.
        written(&scene, D2020);
    }
    let thin = objects(r#"(name: "ring", shape: Torus(minor: 0.25), material: "grey")"#);
    assert_named(
        &refused(&thin, D2020).refusals,
        &object("ring"),
        "minor radius 0.25",
    );
}

#[test]
fn a_sheared_matrix_is_refused_and_a_rotation_matrix_written() {
    let sheared = objects(
        r#"(name: "leaning", shape: Cube, material: "grey",
            transform: Matrix(((1, 0.5, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0))))"#,
    );
    for dialect in [D2016, D2020] {
        assert_named(
            &refused(&sheared, dialect).refusals,
            &object("leaning"),
            "shear",
        );
    }
    let turned = objects(
        r#"(name: "turned", shape: Cube, material: "grey",
            transform: Matrix(((0, -1, 0, 1), (1, 0, 0, 2), (0, 0, 1, 3))))"#,
    );
    let text = written(&turned, D2020).text;
    assert!(text.contains("Rotate Z 90\n  Translate 1 2 3\n"), "{text}");
}

#[test]
fn glass_needs_the_extension_keywords_and_a_grey_transmission() {
    let glass = objects(r#"(name: "lens", shape: Sphere, material: "glass")"#);
    assert_named(
        &refused(&glass, D2016).refusals,
        &Subject::Material("glass".into()),
        "no Opacity or RefractiveIndex",
    );
    let text = written(&glass, D2020).text;
    assert!(
        text.contains("Opacity 0.09999999999999998") || text.contains("Opacity 0.1"),
        "{text}"
    );
    assert!(text.contains("RefractiveIndex 1.5"), "{text}");
    // A glass no object uses is written without its transmission, with a warning.
    let unused = objects(r#"(name: "ball", shape: Sphere, material: "grey")"#);
    assert_named(
        &written(&unused, D2016).warnings,
        &Subject::Material("glass".into()),
        "no object uses it, so it is written without its transmission",
    );
    let mut tinted = glass.clone();
    tinted.materials.get_mut("glass").unwrap().transmission.x = 0.5;
    assert_named(
        &refused(&tinted, D2020).refusals,
        &Subject::Material("glass".into()),
        "is coloured",
    );
}

#[test]
fn the_2016_dialect_refuses_directional_and_spot_lights_by_index() {
    let lit = scene(
        "",
        "Directional(direction: (0, -1, 0), colour: (1, 1, 1)),
         Point(position: (0, 2, 0), colour: (1, 1, 1)),
         Spot(position: (0, 2, 0), direction: (0, -1, 0), angle_deg: 20, colour: (1, 1, 1))",
        "",
    );
    let error = refused(&lit, D2016);
    assert_named(
        &error.refusals,
        &Subject::Light {
            index: 0,
            kind: "Directional",
        },
        "point lights only",
    );
    assert_named(
        &error.refusals,
        &Subject::Light {
            index: 2,
            kind: "Spot",
        },
        "point lights only",
    );
    assert_eq!(error.refusals.len(), 2, "{error}");
    // The message names them as the user reads it.
    assert!(error.to_string().contains("light 2 (Spot): "), "{error}");
}

#[test]
fn csg_trees_the_dialect_cannot_nest_are_refused_and_wide_ones_nested_in_2016() {
    let nested = objects(
        r#"(name: "outer", shape: Csg(op: Difference, operands: [
              (name: "inner", shape: Csg(op: Union, operands: [(shape: Cube), (shape: Sphere)])),
              (name: "hole", shape: Cylinder),
           ]), material: "grey")"#,
    );
    assert_named(
        &refused(&nested, D2020).refusals,
        &object("outer"),
        "its operand \"inner\" is a tree",
    );
    written(&nested, D2016);

    let wide = objects(
        r#"(name: "die", shape: Csg(op: Difference, operands: [
              (shape: Cube), (shape: Sphere), (shape: Cone), (shape: Cylinder),
           ]), material: "grey")"#,
    );
    assert_named(
        &refused(&wide, D2020).refusals,
        &object("die"),
        "has 4 operands",
    );
    let nested_2016 = written(&wide, D2016);
    assert_named(
        &nested_2016.warnings,
        &object("die"),
        "the first minus the union of the others",
    );
    // It reads back as a difference of the first and a union of the rest.
    let back = import_legacy(&nested_2016.text).unwrap().scene;
    let raylab::scene::Shape::Csg { op, operands } = &back.objects[0].shape else {
        panic!("{:?}", back.objects[0])
    };
    assert_eq!(*op, raylab::scene::CsgOp::Difference);
    assert!(matches!(
        &operands[1].shape,
        raylab::scene::Shape::Csg {
            op: raylab::scene::CsgOp::Union,
            ..
        }
    ));

    let grouped = objects(
        r#"(name: "cut", shape: Csg(op: Union, operands: [
              (name: "pair", shape: Group(children: [(shape: Cube)])), (shape: Sphere),
           ]), material: "grey")"#,
    );
    assert_named(
        &refused(&grouped, D2016).refusals,
        &object("cut/pair"),
        "not groups",
    );
    assert_named(
        &refused(&grouped, D2020).refusals,
        &object("cut"),
        "its operand \"pair\" is a tree",
    );
}

#[test]
fn groups_are_flattened_with_a_warning_where_the_dialect_has_none() {
    let groups = objects(
        r#"(name: "snowman", shape: Group(children: [
              (name: "body", shape: Sphere),
              (name: "hat", shape: Group(children: [(name: "brim", shape: Cylinder)]),
               transform: (translate: (0, 2, 0))),
           ]), transform: (translate: (3, 0, 0)), material: "grey")"#,
    );
    let in_2016 = written(&groups, D2016);
    assert_named(
        &in_2016.warnings,
        &object("snowman"),
        "the 2016 framework has no ObjectGroup",
    );
    let in_2020 = written(&groups, D2020);
    assert_named(
        &in_2020.warnings,
        &object("snowman/hat"),
        "a group inside a group",
    );
    // The brim lands where it was: 2 up inside the hat, 3 along with the snowman.
    for text in [&in_2016.text, &in_2020.text] {
        assert!(text.contains("# brim"), "{text}");
        assert!(
            text.contains("Translate 0 2 0\n") && text.contains("Translate 3 0 0\n"),
            "{text}"
        );
    }
    let csg_in_group = objects(
        r#"(name: "g", shape: Group(children: [
              (name: "c", shape: Csg(op: Union, operands: [(shape: Cube), (shape: Sphere)])),
           ]), material: "grey")"#,
    );
    assert_named(
        &refused(&csg_in_group, D2020).refusals,
        &object("g/c"),
        "a CSG inside an ObjectGroup",
    );
}

#[test]
fn what_does_not_change_the_geometry_is_written_with_a_warning() {
    // The render conventions, and a sample count with no FSAA form.
    let plain = scene(
        r#"(name: "ball", shape: Sphere, material: "grey")"#,
        "",
        "samples_per_pixel: 8",
    );
    let warned = written(&plain, D2020);
    assert_named(
        &warned.warnings,
        &Subject::Render,
        "the render conventions (mirror: Add, clamp: Pixel, quantise: Round)",
    );
    assert_named(
        &warned.warnings,
        &Subject::Render,
        "written as FSAA 3 (9 samples)",
    );
    assert_named(
        &written(&plain, D2016).warnings,
        &Subject::Render,
        "no anti-aliasing",
    );

    // A material name that is not one word, and an object name no comment gives back.
    let names = objects(r#"(name: "Mirror ball", shape: Sphere, material: "Grey Paint")"#);
    let warned = written(&names, D2020);
    assert_named(
        &warned.warnings,
        &Subject::Material("Grey Paint".into()),
        "written as `Grey_Paint`",
    );
    assert_named(
        &warned.warnings,
        &object("Mirror ball"),
        "comes back with the default name",
    );

    // 2016: several ambient lights become one colour; a sphere light becomes a point.
    let lights = scene(
        "",
        "Ambient(colour: (0.1, 0.1, 0.1)), Ambient(colour: (0.2, 0.2, 0.2)),
         Point(position: (0, 2, 0), colour: (1, 1, 1), radius: 0.5, samples: 8)",
        "",
    );
    let warned = written(&lights, D2016);
    assert_named(
        &warned.warnings,
        &Subject::Light {
            index: 1,
            kind: "Ambient",
        },
        "added into the Scene block's ambientLight",
    );
    assert_named(
        &warned.warnings,
        &Subject::Light {
            index: 2,
            kind: "Point",
        },
        "soft shadows become hard",
    );
    assert!(
        warned
            .text
            .contains("ambientLight 0.30000000000000004 0.30000000000000004 0.30000000000000004"),
        "{}",
        warned.text
    );
    // 2020 says both.
    let text = written(&lights, D2020).text;
    assert!(text.contains("Radius 0.5\n  Samples 8\n"), "{text}");

    // 2016: a mesh path with capitals is lowercased by the framework; an unused ior.
    let mut mesh = objects(r#"(name: "pot", shape: Mesh(path: "Teapot.obj"), material: "grey")"#);
    mesh.materials.get_mut("grey").unwrap().ior = 1.3;
    let warned = written(&mesh, D2016);
    assert_named(&warned.warnings, &object("pot"), "it opens \"teapot.obj\"");
    assert_named(
        &warned.warnings,
        &Subject::Material("grey".into()),
        "ior 1.3 is not written",
    );
}

#[test]
fn names_go_out_as_comments_the_importer_reads_back() {
    let named = objects(
        r#"(name: "Snowman's body", shape: Sphere, material: "grey"),
           (name: "lens", shape: Csg(op: Intersection, operands: [
              (name: "front", shape: Sphere), (name: "back", shape: Sphere),
           ]), material: "grey"),
           (shape: Cube, material: "grey")"#,
    );
    for dialect in [D2016, D2020] {
        let back = import_legacy(&written(&named, dialect).text).unwrap().scene;
        let names: Vec<&str> = back.objects.iter().map(|o| o.name.as_str()).collect();
        assert_eq!(names, ["Snowman's body", "lens", "Cube 2"]);
        let operands: Vec<&str> = back.objects[1]
            .shape
            .children()
            .iter()
            .map(|o| o.name.as_str())
            .collect();
        assert_eq!(operands, ["front", "back"]);
    }
}
