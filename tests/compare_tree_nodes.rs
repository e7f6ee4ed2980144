//! `diff` names a part of an object's tree where the difference lies on it: the die of
//! `scenes/csg.ron` with one pip's colour changed, or rendered without that pip (the
//! student forgot it: its hole is not cut), names "die/pip 1.1", not 'die'; a snowman
//! group with one member's colour wrong names that member, and with all of it wrong the
//! group. raylab's own picture of the tree scene is identical, and a scene without trees
//! reads as it did (no tree path in its JSON). The other pictures are raylab's own
//! renders of the changed scenes.

#[path = "compare/one_sample.rs"]
mod one_sample;
#[path = "compare/own_render.rs"]
mod own_render;
#[path = "compare/shader.rs"]
mod shader;

use one_sample::diff;
use own_render::own_render;
use raylab::compare::{Comparison, ExplainedTerm, Explanation};
use raylab::scene::examples::EXAMPLE_SCENES;
use raylab::scene::tree::{object_at_mut, remove_node};
use raylab::scene::{Scene, parse_scene};
use raylab::trace::Term;
use shader::{Bugs, lab_scene, render};

/// The path of pip 1.1 in csg.ron: the die is object 2, the pip its second operand.
const PIP: [usize; 2] = [2, 1];

/// `scenes/csg.ron` at 240x180 (its aspect), to keep the test quick.
fn csg() -> Scene {
    let (_, ron) = EXAMPLE_SCENES
        .iter()
        .find(|(name, _)| *name == "csg.ron")
        .unwrap();
    let mut scene = parse_scene(ron).unwrap();
    (scene.camera.width, scene.camera.height) = (240, 180);
    scene
}

/// `scene` with the node at `path` given a copy of its material whose diffuse colour is
/// scaled by `scale`.
fn recoloured(scene: &Scene, path: &[usize], material: &str, scale: f64) -> Scene {
    let mut scene = scene.clone();
    let mut changed = scene.materials[material].clone();
    changed.diffuse *= scale;
    scene.materials.insert("changed".to_owned(), changed);
    object_at_mut(&mut scene.objects, path).unwrap().material = "changed".to_owned();
    scene
}

/// The first explanation, which must name the node at `path` by its tree path.
fn first_names<'c>(c: &'c Comparison, name: &str, path: &[usize]) -> &'c Explanation {
    let report = c.text_lines().join("\n");
    let first = c.explanations.first().unwrap_or_else(|| panic!("{report}"));
    assert_eq!(first.object_name.as_deref(), Some(name), "{report}");
    assert_eq!(first.node, path, "{report}");
    assert_eq!(first.object, Some(path[0]), "{report}");
    first
}

fn assert_factor(e: &Explanation, term: ExplainedTerm, factor: f64, report: &str) {
    assert_eq!(e.term, term, "{report}");
    assert_eq!(e.cause.name(), "factor", "{report}");
    assert!((e.factor - factor).abs() < 0.05, "{report}");
}

#[test]
fn a_pip_of_the_die_with_a_brighter_colour_is_named_by_its_path() {
    let scene = csg();
    let c = diff(&scene, &own_render(&recoloured(&scene, &PIP, "pip", 2.0)));
    let report = c.text_lines().join("\n");
    let first = first_names(&c, "die/pip 1.1", &PIP);
    assert_factor(first, ExplainedTerm::Term(Term::Diffuse), 2.0, &report);
    assert!(first.share > 0.9, "{report}");
    assert!(report.contains("object die/pip 1.1,"), "{report}");
    let json = c.to_json();
    assert!(json.contains("\"object\": \"die/pip 1.1\""), "{json}");
    assert!(
        json.contains("\"node\": [\n        2,\n        1\n      ]"),
        "{json}"
    );
}

#[test]
fn a_pip_left_out_of_the_die_is_missing_by_its_path() {
    let scene = csg();
    let mut forgot = scene.clone();
    remove_node(&mut forgot.objects, &PIP).unwrap();
    let c = diff(&scene, &own_render(&forgot));
    let report = c.text_lines().join("\n");
    let first = first_names(&c, "die/pip 1.1", &PIP);
    assert_eq!(first.cause.name(), "missing-object", "{report}");
    assert!(first.share > 0.9, "{report}");
    assert!(first.bbox.is_some(), "{report}");
    assert!(
        first.summary.starts_with("'die/pip 1.1' is not cut"),
        "{report}"
    );
}

#[test]
fn the_tree_scenes_own_picture_is_identical() {
    let scene = csg();
    let c = diff(&scene, &own_render(&scene));
    assert!(c.explanations.is_empty(), "{}", c.text_lines().join("\n"));
    assert!(c.psnr_db >= 100.0);
}

/// A floor, a snowman (a group of three spheres of one material, which it gives them)
/// and a ball, under an ambient and a point light.
const SNOWMAN: &str = r#"Scene(
    camera: (position: (0.0, 2.0, 7.0), look_at: (0.0, 1.0, 0.0), fov_deg: 45.0,
             width: 120, height: 90),
    render: (max_depth: 2, background: (0.05, 0.06, 0.09), samples_per_pixel: 1),
    materials: {
        "grey": (ambient: (0.2, 0.2, 0.2), diffuse: (0.4, 0.4, 0.4), specular: (0.1, 0.1, 0.1), shininess: 8.0),
        "snow": (ambient: (0.1, 0.1, 0.12), diffuse: (0.3, 0.3, 0.33), specular: (0.2, 0.2, 0.2), shininess: 20.0),
        "red": (ambient: (0.15, 0.03, 0.03), diffuse: (0.4, 0.1, 0.1), specular: (0.3, 0.3, 0.3), shininess: 20.0),
    },
    objects: [
        (name: "floor", shape: Plane, transform: (rotate_deg: (-90.0, 0.0, 0.0), scale: (6.0, 6.0, 1.0)), material: "grey"),
        (name: "snowman", shape: Group(children: [
            (name: "body", shape: Sphere, transform: (translate: (0.0, 0.6, 0.0), scale: (0.6, 0.6, 0.6))),
            (name: "middle", shape: Sphere, transform: (translate: (0.0, 1.45, 0.0), scale: (0.42, 0.42, 0.42))),
            (name: "head", shape: Sphere, transform: (translate: (0.0, 2.05, 0.0), scale: (0.28, 0.28, 0.28))),
        ]), transform: (translate: (-0.8, 0.0, 0.0)), material: "snow"),
        (name: "ball", shape: Sphere, transform: (translate: (1.3, 0.5, 0.5), scale: (0.5, 0.5, 0.5)), material: "red"),
    ],
    lights: [
        Ambient(colour: (0.2, 0.2, 0.2)),
        Point(position: (-3.0, 5.0, 5.0), colour: (1.0, 1.0, 1.0), intensity: 30.0),
    ],
)"#;

#[test]
fn a_snowman_member_of_another_colour_is_named_and_a_snowman_all_of_it_is_the_group() {
    let scene = parse_scene(SNOWMAN).unwrap();
    let head = [1, 2];
    let c = diff(&scene, &own_render(&recoloured(&scene, &head, "snow", 1.5)));
    let report = c.text_lines().join("\n");
    let first = first_names(&c, "snowman/head", &head);
    assert_factor(first, ExplainedTerm::Term(Term::Diffuse), 1.5, &report);
    // Every member's colour: the group, not one member (nor three explanations).
    let mut all = scene.clone();
    all.materials.get_mut("snow").unwrap().diffuse *= 1.5;
    let c = diff(&scene, &own_render(&all));
    let report = c.text_lines().join("\n");
    let first = first_names(&c, "snowman", &[1]);
    assert_factor(first, ExplainedTerm::Term(Term::Diffuse), 1.5, &report);
    assert!(first.share > 0.9, "{report}");
    // A member left out: that member, with its shadow on the one below.
    let mut forgot = scene.clone();
    remove_node(&mut forgot.objects, &head).unwrap();
    let c = diff(&scene, &own_render(&forgot));
    let report = c.text_lines().join("\n");
    let first = first_names(&c, "snowman/head", &head);
    assert_eq!(first.cause.name(), "missing-object", "{report}");
    assert!(first.share > 0.9, "{report}");
    assert!(
        c.explanations
            .iter()
            .all(|e| e.term != ExplainedTerm::Term(Term::Shadows)),
        "{report}"
    );
}

#[test]
fn a_scene_without_trees_names_objects_as_before() {
    let lab = lab_scene();
    let ball = lab
        .objects
        .iter()
        .position(|o| o.name == "red ball")
        .unwrap();
    let bugs = Bugs {
        diffuse_scale: Some((ball, 0.5)),
        ..Bugs::default()
    };
    let c = diff(&lab, &render(&lab, 1, &bugs));
    let report = c.text_lines().join("\n");
    let first = first_names(&c, "red ball", &[ball]);
    assert_factor(first, ExplainedTerm::Term(Term::Diffuse), 0.5, &report);
    let json = c.to_json();
    assert!(!json.contains("\"node\""), "{json}");
}
