//! `diff` names an object raylab draws and the other picture does not (`missing-object`),
//! with where raylab draws it and with its shadows: the student's picture is the test
//! shader's render of the scene without the object, alone and with a second bug (no
//! specular term, no ambient term, the course's mirror blend, whose convention then
//! comes first). Also in a scene whose first object is a group (the worlds without each
//! object are per scene object). raylab's own picture, and pictures with only another
//! bug, get no missing-object verdict.

#[path = "compare/pixels.rs"]
mod pixels;
#[path = "compare/shader.rs"]
mod shader;

#[path = "compare/one_sample.rs"]
mod one_sample;

use one_sample::{diff, first_beyond_conventions};
use raylab::compare::{Comparison, ExplainedTerm};
use raylab::scene::{Scene, parse_scene};
use raylab::trace::Term;
use shader::{Bugs, lab_scene, render};

/// `scene` without its object named `name`.
fn without(scene: &Scene, name: &str) -> Scene {
    let mut scene = scene.clone();
    scene.objects.retain(|o| o.name != name);
    scene
}

fn index_of(scene: &Scene, name: &str) -> usize {
    scene.objects.iter().position(|o| o.name == name).unwrap()
}

/// Asserts that the first explanation other than the conventions' is `name` missing,
/// with raylab's box of it, and that it explains at least `share`.
fn assert_missing_first(scene: &Scene, c: &Comparison, name: &str, share: f64) {
    let (first, report) = first_beyond_conventions(c);
    assert_eq!(first.cause.name(), "missing-object", "{report}");
    assert_eq!(first.object_name.as_deref(), Some(name), "{report}");
    assert!(first.share >= share, "{report}");
    let expected = pixels::object_box(scene, index_of(scene, name));
    let found = first.bbox.unwrap_or_else(|| panic!("no box:\n{report}"));
    assert!(
        pixels::boxes_agree(found, expected, 1),
        "{found:?} against {expected:?}:\n{report}"
    );
    assert!(first.summary.contains("raylab draws it at"), "{report}");
}

fn assert_no_object_verdict(c: &Comparison) {
    let report = c.text_lines().join("\n");
    for e in &c.explanations {
        assert!(
            !matches!(e.cause.name(), "missing-object" | "extra-object"),
            "{report}"
        );
    }
}

#[test]
fn a_missing_ball_is_named_with_its_box_and_its_shadow() {
    let lab = lab_scene();
    let c = diff(
        &lab,
        &render(&without(&lab, "red ball"), 1, &Bugs::default()),
    );
    // Its shadow on the floor goes with it: no shadow factor is left over.
    assert_missing_first(&lab, &c, "red ball", 0.97);
    let report = c.text_lines().join("\n");
    assert!(
        c.explanations
            .iter()
            .all(|e| e.term != ExplainedTerm::Term(Term::Shadows)),
        "{report}"
    );
    let c = diff(
        &lab,
        &render(&without(&lab, "gold cone"), 1, &Bugs::default()),
    );
    assert_missing_first(&lab, &c, "gold cone", 0.9);
}

#[test]
fn a_missing_object_is_named_first_beside_a_second_bug() {
    let lab = lab_scene();
    let student = without(&lab, "red ball");
    for bugs in [
        Bugs {
            specular_off: true,
            ..Bugs::default()
        },
        Bugs {
            ambient_off: true,
            ..Bugs::default()
        },
    ] {
        let c = diff(&lab, &render(&student, 1, &bugs));
        assert_missing_first(&lab, &c, "red ball", 0.5);
        let report = c.text_lines().join("\n");
        assert!(
            c.explanations.len() >= 2,
            "{bugs:?}: the second bug\n{report}"
        );
    }
    // The course's mirror blend: its convention first, then the missing ball.
    let mut mirrored = lab.clone();
    mirrored.materials.get_mut("red").unwrap().mirror = glam::DVec3::splat(0.3);
    let blend = Bugs {
        mirror_blend: true,
        ..Bugs::default()
    };
    let c = diff(
        &mirrored,
        &render(&without(&mirrored, "gold cone"), 1, &blend),
    );
    assert_eq!(c.explanations[0].cause.name(), "mirror-blend");
    assert_missing_first(&mirrored, &c, "gold cone", 0.1);
}

/// A group first (two small spheres), then a floor and a ball: the group's members are
/// world objects 0 and 1, so the ball is world object 3 but scene object 2.
const GROUPED: &str = r#"Scene(
    camera: (position: (0.0, 2.0, 7.0), look_at: (0.0, 0.6, 0.0), fov_deg: 45.0,
             width: 80, height: 60),
    render: (max_depth: 2, background: (0.05, 0.06, 0.09), samples_per_pixel: 1),
    materials: {
        "grey": (ambient: (0.2, 0.2, 0.2), diffuse: (0.5, 0.5, 0.5), specular: (0.2, 0.2, 0.2), shininess: 8.0),
        "teal": (ambient: (0.05, 0.15, 0.15), diffuse: (0.1, 0.6, 0.6), specular: (0.5, 0.5, 0.5), shininess: 30.0),
        "red": (ambient: (0.15, 0.03, 0.03), diffuse: (0.7, 0.1, 0.1), specular: (0.5, 0.5, 0.5), shininess: 20.0),
    },
    objects: [
        (name: "pair", shape: Group(children: [
            (name: "left", shape: Sphere, transform: (translate: (-1.6, 0.4, 0.0), scale: (0.4, 0.4, 0.4))),
            (name: "right", shape: Sphere, transform: (translate: (-0.7, 0.4, 0.0), scale: (0.4, 0.4, 0.4))),
        ]), material: "teal"),
        (name: "floor", shape: Plane, transform: (rotate_deg: (-90.0, 0.0, 0.0), scale: (6.0, 6.0, 1.0)), material: "grey"),
        (name: "ball", shape: Sphere, transform: (translate: (1.0, 0.7, 0.3), scale: (0.7, 0.7, 0.7)), material: "red"),
    ],
    lights: [
        Ambient(colour: (0.15, 0.15, 0.15)),
        Point(position: (-2.0, 5.0, 4.0), colour: (1.0, 1.0, 1.0), intensity: 30.0),
    ],
)"#;

#[test]
fn in_a_scene_with_a_group_the_missing_object_is_the_right_one() {
    let scene = parse_scene(GROUPED).unwrap();
    let c = diff(
        &scene,
        &render(&without(&scene, "ball"), 1, &Bugs::default()),
    );
    let report = c.text_lines().join("\n");
    let first = &c.explanations[0];
    assert_eq!(first.cause.name(), "missing-object", "{report}");
    assert_eq!(first.object_name.as_deref(), Some("ball"), "{report}");
    assert!(first.share > 0.9, "{report}");
    // The whole group missing is the group's verdict.
    let c = diff(
        &scene,
        &render(&without(&scene, "pair"), 1, &Bugs::default()),
    );
    let report = c.text_lines().join("\n");
    assert_eq!(c.explanations[0].cause.name(), "missing-object", "{report}");
    assert_eq!(
        c.explanations[0].object_name.as_deref(),
        Some("pair"),
        "{report}"
    );
}

#[test]
fn pictures_with_every_object_have_no_missing_or_extra_object() {
    let lab = lab_scene();
    assert_no_object_verdict(&diff(&lab, &render(&lab, 1, &Bugs::default())));
    for bugs in [
        Bugs {
            specular_off: true,
            ..Bugs::default()
        },
        Bugs {
            shadows_off: true,
            ..Bugs::default()
        },
        Bugs {
            ambient_off: true,
            ..Bugs::default()
        },
        Bugs {
            directional_never_lights: true,
            ..Bugs::default()
        },
        Bugs {
            one_sided_planes: true,
            ..Bugs::default()
        },
        Bugs {
            negated_reflection: true,
            truncate: true,
            ..Bugs::default()
        },
        Bugs {
            cone_normal_without_z: true,
            diffuse_scale: Some((2, 0.6)),
            ..Bugs::default()
        },
    ] {
        let c = diff(&lab, &render(&lab, 1, &bugs));
        assert!(!c.explanations.is_empty(), "{bugs:?}");
        assert_no_object_verdict(&c);
    }
}
