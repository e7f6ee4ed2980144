//! `diff` names the spot-light bugs of students' tracers: a spot light with no cone, no
//! 1/d^2 fall-off, its angle in degrees used as radians, or its half angle taken as the
//! full angle. The student's picture is raylab's own render of the scene with the light
//! changed the way the bug says (the fall-off bug, which no scene can express, comes
//! from the test shader of tests/compare/shader.rs), and the first explanation must be
//! the bug, on the right light. raylab's own picture, and one whose only difference is
//! the specular term, get no spot cause.

#[path = "compare/shader.rs"]
mod shader;

use raylab::compare::{CompareOptions, Comparison, OtherImage, compare};
use raylab::scene::{Light, Scene, parse_scene};
use raylab::trace::{RenderOptions, RenderProgress, World, render};
use shader::{Bugs, render as render_with};

/// A floor, a ball, and two spot lights (scene indices 1 and 2) after an ambient light.
const SCENE: &str = r#"Scene(
    camera: (position: (0.0, 3.0, 7.0), look_at: (0.0, 0.5, 0.0), fov_deg: 45.0,
             width: 80, height: 60),
    render: (max_depth: 2, background: (0.05, 0.05, 0.08), samples_per_pixel: 1),
    materials: {
        "floor": (ambient: (0.3, 0.3, 0.3), diffuse: (0.5, 0.5, 0.5), specular: (0.2, 0.2, 0.2), shininess: 8.0),
        "ball": (ambient: (0.2, 0.1, 0.1), diffuse: (0.6, 0.3, 0.2), specular: (0.6, 0.6, 0.6), shininess: 20.0),
    },
    objects: [
        (name: "floor", shape: Plane, transform: (rotate_deg: (-90.0, 0.0, 0.0), scale: (6.0, 6.0, 1.0)), material: "floor"),
        (name: "ball", shape: Sphere, transform: (translate: (0.3, 0.8, 0.0), scale: (0.8, 0.8, 0.8)), material: "ball"),
    ],
    lights: [
        Ambient(colour: (0.15, 0.15, 0.15)),
        Spot(position: (-1.0, 3.0, 1.0), direction: (0.2, -1.0, -0.1), angle_deg: 50.0,
             colour: (1.0, 0.95, 0.9), intensity: 12.0),
        Spot(position: (1.5, 3.0, 0.5), direction: (-0.3, -1.0, -0.4), angle_deg: 45.0,
             colour: (0.9, 0.9, 1.0), intensity: 1.6),
    ],
)"#;

fn scene() -> Scene {
    parse_scene(SCENE).unwrap()
}

/// raylab's render of `scene`, written as raylab writes it.
fn raylab_render(scene: &Scene) -> OtherImage {
    let world = World::new(scene).unwrap();
    let options = RenderOptions {
        samples_per_pixel: 1,
        ..RenderOptions::from_scene(scene)
    };
    let (image, _) = render(&world, &options, &RenderProgress::default()).unwrap();
    let rgb = image
        .to_rgba8()
        .chunks(4)
        .map(|p| [p[0], p[1], p[2]])
        .collect();
    OtherImage::new(scene.camera.width, scene.camera.height, rgb)
}

fn diff(other: &OtherImage) -> Comparison {
    let options = CompareOptions {
        samples_per_pixel: Some(1),
    };
    compare(&scene(), other, &options, &RenderProgress::default()).unwrap()
}

/// The scene with spot light `index` changed by `change`.
fn with_spot(index: usize, change: impl FnOnce(&mut Light)) -> Scene {
    let mut scene = scene();
    change(&mut scene.lights[index]);
    scene
}

fn angle_of(light: &mut Light) -> &mut f64 {
    match light {
        Light::Spot { angle_deg, .. } => angle_deg,
        other => panic!("not a spot light: {other:?}"),
    }
}

/// Asserts that the first explanation is `cause` on `light`, explaining most of the
/// difference with a weight near 1.
fn assert_first(c: &Comparison, cause: &str, light: usize) {
    let report = c.text_lines().join("\n");
    let first = c.explanations.first().unwrap_or_else(|| panic!("{report}"));
    assert_eq!(first.cause.name(), cause, "{report}");
    assert_eq!(first.light, Some(light), "{report}");
    assert!(first.share > 0.8, "explains only {:.3}:\n{report}", first.share);
    assert!((first.factor - 0.0).abs() < 0.1, "weight {}:\n{report}", 1.0 - first.factor);
    assert!(first.summary.contains(&format!("light {light}")), "{report}");
}

fn assert_no_spot_cause(c: &Comparison) {
    let report = c.text_lines().join("\n");
    assert!(
        c.explanations
            .iter()
            .all(|e| !e.cause.name().starts_with("spot-")),
        "{report}"
    );
}

#[test]
fn a_spot_light_with_no_cone_is_named_with_its_index() {
    let student = with_spot(2, |light| {
        let Light::Spot {
            position,
            colour,
            intensity,
            ..
        } = *light
        else {
            unreachable!()
        };
        *light = Light::Point {
            position,
            colour,
            intensity,
            radius: 0.0,
            samples: 1,
        };
    });
    assert_first(&diff(&raylab_render(&student)), "spot-no-cone", 2);
}

#[test]
fn a_spot_light_with_no_falloff_is_named_with_its_index() {
    let student = render_with(
        &scene(),
        1,
        &Bugs {
            spot_no_falloff: Some(2),
            ..Bugs::default()
        },
    );
    assert_first(&diff(&student), "spot-no-falloff", 2);
}

#[test]
fn a_spot_angle_used_as_radians_is_named_with_its_index() {
    // cos(50 radians) = cos(15.2 degrees): a narrower cone.
    let student = with_spot(1, |light| {
        let angle = angle_of(light);
        *angle = angle.cos().acos().to_degrees();
    });
    assert_first(&diff(&raylab_render(&student)), "spot-angle-radians", 1);
}

#[test]
fn a_half_angle_taken_as_the_full_angle_is_named_with_its_index() {
    let student = with_spot(1, |light| *angle_of(light) /= 2.0);
    assert_first(&diff(&raylab_render(&student)), "spot-full-angle", 1);
    let student = with_spot(2, |light| *angle_of(light) /= 2.0);
    assert_first(&diff(&raylab_render(&student)), "spot-full-angle", 2);
}

#[test]
fn raylabs_own_picture_has_no_spot_cause() {
    let c = diff(&raylab_render(&scene()));
    assert!(c.psnr_db >= 60.0, "{}", c.psnr_db);
    assert_no_spot_cause(&c);
}

#[test]
fn a_picture_without_specular_has_no_spot_cause() {
    let student = render_with(
        &scene(),
        1,
        &Bugs {
            specular_off: true,
            ..Bugs::default()
        },
    );
    let c = diff(&student);
    let report = c.text_lines().join("\n");
    let first = c.explanations.first().unwrap_or_else(|| panic!("{report}"));
    assert_eq!(first.cause.name(), "factor", "{report}");
    assert_no_spot_cause(&c);
}
