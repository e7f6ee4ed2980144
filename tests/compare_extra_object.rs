//! `diff` names an object the other picture draws and raylab does not (`extra-object`),
//! with its bounding box and a guess of its shape: the student's picture is the test
//! shader's render of the scene with one more object (a sphere, a cube), alone and with
//! a second bug (a ball's duller diffuse colour, a directional light that never lights,
//! the course's mirror blend, whose convention then comes first). Its pixels no longer bend the
//! factors of what lies behind it. raylab's own picture and pictures with only another
//! bug get no extra-object verdict (tests/compare_missing_object.rs checks those).

#[path = "compare/pixels.rs"]
mod pixels;
#[path = "compare/shader.rs"]
mod shader;

#[path = "compare/one_sample.rs"]
mod one_sample;

use one_sample::{diff, first_beyond_conventions};
use raylab::compare::ShapeGuess;
use raylab::compare::{Cause, Comparison, ExplainedTerm};
use raylab::scene::{Material, Object, Scene};
use raylab::trace::Term;
use shader::{Bugs, lab_scene, render};

/// The lab scene with a blue material no object of it uses.
fn lab() -> Scene {
    let mut scene = lab_scene();
    let blue = Material {
        ambient: glam::DVec3::new(0.02, 0.04, 0.15),
        diffuse: glam::DVec3::new(0.1, 0.2, 0.8),
        specular: glam::DVec3::splat(0.4),
        shininess: 30.0,
        ..Material::default()
    };
    scene.materials.insert("blue".to_owned(), blue);
    scene
}

/// `scene` with one more object, written in RON.
fn with(scene: &Scene, object: &str) -> Scene {
    let mut scene = scene.clone();
    scene.objects.push(ron::from_str::<Object>(object).unwrap());
    scene
}

const SPHERE: &str = r#"(name: "extra", shape: Sphere, transform: (translate: (0.9, 0.5, 1.8), scale: (0.5, 0.5, 0.5)), material: "blue")"#;
const LOW_SPHERE: &str = r#"(name: "extra", shape: Sphere, transform: (translate: (0.3, 0.35, 3.0), scale: (0.35, 0.35, 0.35)), material: "blue")"#;
const CUBE: &str = r#"(name: "extra", shape: Cube, transform: (translate: (-0.3, 0.4, 2.0), rotate_deg: (0.0, 20.0, 0.0), scale: (0.4, 0.4, 0.4)), material: "blue")"#;

/// Asserts that the first explanation other than the conventions' is an extra object
/// shaped `shape`, where the extra object of `student` (its last) is drawn, explaining
/// at least `share`.
fn assert_extra_first(student: &Scene, c: &Comparison, shape: ShapeGuess, share: f64) {
    let (first, report) = first_beyond_conventions(c);
    assert_eq!(first.cause, Cause::ExtraObject(shape), "{report}");
    assert_eq!(first.term, ExplainedTerm::Geometry, "{report}");
    assert!(first.share >= share, "{report}");
    let expected = pixels::object_box(student, student.objects.len() - 1);
    let found = first.bbox.unwrap_or_else(|| panic!("no box:\n{report}"));
    assert!(
        pixels::boxes_agree(found, expected, 2),
        "{found:?} against {expected:?}:\n{report}"
    );
    assert!(
        first.summary.contains("draws an object raylab does not"),
        "{report}"
    );
}

#[test]
fn an_extra_sphere_and_an_extra_cube_are_named_with_their_box_and_shape() {
    let scene = lab();
    let student = with(&scene, SPHERE);
    let c = diff(&scene, &render(&student, 1, &Bugs::default()));
    assert_extra_first(&student, &c, ShapeGuess::Sphere, 0.9);
    // No factor of the floor or wall behind it bends towards it.
    let report = c.text_lines().join("\n");
    assert!(
        c.explanations.iter().all(|e| e.cause != Cause::Factor),
        "{report}"
    );
    let student = with(&scene, CUBE);
    let c = diff(&scene, &render(&student, 1, &Bugs::default()));
    assert_extra_first(&student, &c, ShapeGuess::Cube, 0.9);
}

#[test]
fn an_extra_object_is_named_first_beside_a_second_bug() {
    let scene = lab();
    let student = with(&scene, SPHERE);
    let duller_ball = Bugs {
        diffuse_scale: Some((2, 0.7)),
        ..Bugs::default()
    };
    let c = diff(&scene, &render(&student, 1, &duller_ball));
    assert_extra_first(&student, &c, ShapeGuess::Sphere, 0.3);
    let report = c.text_lines().join("\n");
    let ball = c
        .explanations
        .iter()
        .find(|e| e.term == ExplainedTerm::Term(Term::Diffuse));
    let factor = ball.unwrap_or_else(|| panic!("{report}")).factor;
    assert!(
        (factor - 0.7).abs() < 0.05,
        "the ball's diffuse factor is found too, as without the sphere:\n{report}"
    );
    let student = with(&scene, CUBE);
    let no_directional = Bugs {
        directional_never_lights: true,
        ..Bugs::default()
    };
    let c = diff(&scene, &render(&student, 1, &no_directional));
    let report = c.text_lines().join("\n");
    // The missing light is the larger difference; the cube is named right after it.
    assert_eq!(c.explanations[0].light, Some(2), "{report}");
    let cube = c
        .explanations
        .iter()
        .find(|e| matches!(e.cause, Cause::ExtraObject(_)))
        .unwrap_or_else(|| panic!("{report}"));
    assert_eq!(cube.cause, Cause::ExtraObject(ShapeGuess::Cube), "{report}");
    // The course's mirror blend, with two more mirrors (a red and a gold one, whose
    // local colours the blend dims) so that the blend is not a small part of the
    // difference (docs/COMPARE.md, Limits), and the sphere in front of the floor: the
    // convention first, then the sphere.
    let mut scene = scene;
    for material in ["red", "gold"] {
        scene.materials.get_mut(material).unwrap().mirror = glam::DVec3::splat(0.5);
    }
    let blend = Bugs {
        mirror_blend: true,
        ..Bugs::default()
    };
    let student = with(&scene, LOW_SPHERE);
    let c = diff(&scene, &render(&student, 1, &blend));
    let report = c.text_lines().join("\n");
    assert_eq!(c.explanations[0].cause.name(), "mirror-blend", "{report}");
    assert_extra_first(&student, &c, ShapeGuess::Sphere, 0.3);
}

#[test]
fn an_extra_object_of_a_neighbours_material_is_said_to_look_like_it() {
    // A gold sphere beside the gold cone: an extra object, or the cone drawn elsewhere.
    let scene = lab();
    let gold = SPHERE.replace("blue", "gold");
    let student = with(&scene, &gold);
    let c = diff(&scene, &render(&student, 1, &Bugs::default()));
    assert_extra_first(&student, &c, ShapeGuess::Sphere, 0.9);
    let report = c.text_lines().join("\n");
    assert_eq!(
        c.explanations[0].object_name.as_deref(),
        Some("gold cone"),
        "{report}"
    );
    assert!(
        c.explanations[0].summary.contains("those of 'gold cone'"),
        "{report}"
    );
}

#[test]
fn the_json_has_the_box_and_the_shape() {
    let scene = lab();
    let student = with(&scene, CUBE);
    let c = diff(&scene, &render(&student, 1, &Bugs::default()));
    let json: serde_json::Value = serde_json::from_str(&c.to_json()).unwrap();
    let first = &json["explanations"][0];
    assert_eq!(first["cause"], "extra-object");
    assert_eq!(first["shape"], "cube");
    let bbox = c.explanations[0].bbox.unwrap();
    assert_eq!(
        first["bbox"],
        serde_json::json!([bbox.x0, bbox.y0, bbox.x1, bbox.y1])
    );
}

#[test]
fn an_extra_ball_and_a_missing_cone_are_both_named_and_nothing_else() {
    // The second worked example of docs/COMPARE.md (480x360): the ball's shadow falls
    // where the cone was, on the floor raylab shows behind the cone.
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/compare/example.ron");
    let mut scene = raylab::scene::load_scene(std::path::Path::new(path)).unwrap();
    scene
        .materials
        .insert("blue".to_owned(), lab().materials["blue"].clone());
    let mut student = with(&scene, SPHERE);
    student.objects.retain(|o| o.name != "gold cone");
    let c = diff(&scene, &render(&student, 1, &Bugs::default()));
    let report = c.text_lines().join("\n");
    let causes: Vec<&str> = c.explanations.iter().map(|e| e.cause.name()).collect();
    assert_eq!(causes, ["extra-object", "missing-object"], "{report}");
    assert_eq!(c.explanations[1].object_name.as_deref(), Some("gold cone"));
    assert!(c.unexplained_share < 0.02, "{report}");
}
