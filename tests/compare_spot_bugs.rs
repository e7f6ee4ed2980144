//! `diff` names the spot-light bugs of students' tracers: a spot light with no cone, no
//! 1/d^2 fall-off, its angle in degrees used as radians, or its half angle taken as the
//! full angle. The student's picture is raylab's own render of the scene with the light
//! changed the way the bug says (the fall-off bug, which no scene can express, comes
//! from the test shader of tests/compare/shader.rs), and the first explanation must be
//! the bug, on the right light, also with a second, different bug in the picture (a
//! missing ambient term, a scaled diffuse colour, truncation, or the course's mirror
//! blend, whose convention is then named before it). raylab's own picture, and pictures
//! with only another bug, get no spot cause.

#[path = "compare/one_sample.rs"]
mod one_sample;
#[path = "compare/own_render.rs"]
mod own_render;
#[path = "compare/shader.rs"]
mod shader;

use glam::DVec3;
use one_sample::{diff as diff_with, first_beyond_conventions};
use own_render::own_render;
use raylab::compare::{Comparison, OtherImage};
use raylab::scene::{Light, LightSource, Scene, parse_scene};
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

/// The scene with a mirror ball, for the course's mirror blend.
fn mirrored() -> Scene {
    let mut scene = scene();
    scene.materials.get_mut("ball").unwrap().mirror = DVec3::splat(0.4);
    scene
}

fn diff(other: &OtherImage) -> Comparison {
    diff_with(&scene(), other)
}

/// The scene with spot light `index` changed by `change`.
fn with_spot(index: usize, change: impl FnOnce(&mut Light)) -> Scene {
    changed(scene(), index, change)
}

/// `scene` with light `index` changed by `change`.
fn changed(mut scene: Scene, index: usize, change: impl FnOnce(&mut Light)) -> Scene {
    change(&mut scene.lights[index]);
    scene
}

/// A spot light as a point light: the cone forgotten.
fn no_cone(light: &mut Light) {
    let Light::Spot {
        position,
        source: LightSource {
            colour, intensity, ..
        },
        ..
    } = *light
    else {
        panic!("not a spot light: {light:?}")
    };
    *light = Light::Point {
        position,
        source: LightSource::point(colour, intensity),
    };
}

/// The angle in degrees read as radians: the cone whose cosine is cos(angle radians).
fn angle_as_radians(light: &mut Light) {
    let angle = angle_of(light);
    *angle = angle.cos().acos().to_degrees();
}

/// The half angle taken as the full angle.
fn full_angle(light: &mut Light) {
    *angle_of(light) /= 2.0;
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
    assert_first_bug(c, cause, light);
    let first = &c.explanations[0];
    assert!(
        first.share > 0.8,
        "explains only {:.3}:\n{report}",
        first.share
    );
    assert!(
        first.factor.abs() < 0.1,
        "weight {}:\n{report}",
        1.0 - first.factor
    );
}

/// Asserts that the first explanation after the conventions' (which, when another
/// convention fits, comes first by design) is `cause` on `light`, in its summary too.
fn assert_first_bug(c: &Comparison, cause: &str, light: usize) {
    let (first, report) = first_beyond_conventions(c);
    let expected = format!("{cause} on light {light}:\n{report}");
    assert_eq!(first.cause.name(), cause, "{expected}");
    assert_eq!(first.light, Some(light), "{expected}");
    let named = format!("Light {light} ");
    assert!(first.summary.starts_with(&named), "{expected}");
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

/// The test shader's picture of `scene` with `bugs`.
fn shaded(scene: &Scene, bugs: Bugs) -> OtherImage {
    render_with(scene, 1, &bugs)
}

/// A cone bug planted on a light: the light's scene index, the change, its cause.
type ConeCase = (usize, fn(&mut Light), &'static str);

/// The test shader's bugs with no ambient term.
fn no_ambient() -> Bugs {
    Bugs {
        ambient_off: true,
        ..Bugs::default()
    }
}

#[test]
fn a_spot_light_with_no_cone_is_named_with_its_index() {
    let student = with_spot(2, no_cone);
    assert_first(&diff(&own_render(&student)), "spot-no-cone", 2);
}

#[test]
fn a_spot_light_with_no_falloff_is_named_with_its_index() {
    let student = shaded(
        &scene(),
        Bugs {
            spot_no_falloff: Some(2),
            ..Bugs::default()
        },
    );
    assert_first(&diff(&student), "spot-no-falloff", 2);
}

#[test]
fn a_spot_angle_used_as_radians_is_named_with_its_index() {
    // cos(50 radians) = cos(15.2 degrees): a narrower cone.
    let student = with_spot(1, angle_as_radians);
    assert_first(&diff(&own_render(&student)), "spot-angle-radians", 1);
}

#[test]
fn a_half_angle_taken_as_the_full_angle_is_named_with_its_index() {
    let student = with_spot(1, full_angle);
    assert_first(&diff(&own_render(&student)), "spot-full-angle", 1);
    let student = with_spot(2, full_angle);
    assert_first(&diff(&own_render(&student)), "spot-full-angle", 2);
}

#[test]
fn each_spot_bug_is_named_first_beside_a_missing_ambient_term() {
    let falloff = Bugs {
        spot_no_falloff: Some(2),
        ..no_ambient()
    };
    assert_first_bug(&diff(&shaded(&scene(), falloff)), "spot-no-falloff", 2);
    // The bright light's cone: the spot bug is the larger part of the difference.
    let cases: [ConeCase; 3] = [
        (1, no_cone, "spot-no-cone"),
        (1, angle_as_radians, "spot-angle-radians"),
        (1, full_angle, "spot-full-angle"),
    ];
    for (light, bug, cause) in cases {
        let student = shaded(&with_spot(light, bug), no_ambient());
        assert_first_bug(&diff(&student), cause, light);
    }
}

#[test]
fn each_spot_bug_is_named_first_beside_another_bug() {
    // A ball with a duller diffuse colour, truncation, no specular term.
    let student = shaded(
        &with_spot(2, no_cone),
        Bugs {
            diffuse_scale: Some((1, 0.8)),
            ..Bugs::default()
        },
    );
    assert_first_bug(&diff(&student), "spot-no-cone", 2);
    let student = shaded(
        &with_spot(1, full_angle),
        Bugs {
            truncate: true,
            ..Bugs::default()
        },
    );
    assert_first_bug(&diff(&student), "spot-full-angle", 1);
    let student = shaded(
        &with_spot(1, angle_as_radians),
        Bugs {
            specular_off: true,
            ..Bugs::default()
        },
    );
    assert_first_bug(&diff(&student), "spot-angle-radians", 1);
    let student = shaded(
        &scene(),
        Bugs {
            spot_no_falloff: Some(1),
            specular_off: true,
            ..Bugs::default()
        },
    );
    assert_first_bug(&diff(&student), "spot-no-falloff", 1);
}

#[test]
fn each_spot_bug_is_named_beside_the_courses_mirror_blend() {
    let blend = Bugs {
        mirror_blend: true,
        ..Bugs::default()
    };
    let falloff = Bugs {
        spot_no_falloff: Some(2),
        ..blend.clone()
    };
    let c = diff_with(&mirrored(), &shaded(&mirrored(), falloff));
    assert_first_bug(&c, "spot-no-falloff", 2);
    let cases: [ConeCase; 3] = [
        (2, no_cone, "spot-no-cone"),
        (1, angle_as_radians, "spot-angle-radians"),
        (1, full_angle, "spot-full-angle"),
    ];
    for (light, bug, cause) in cases {
        let student = shaded(&changed(mirrored(), light, bug), blend.clone());
        assert_first_bug(&diff_with(&mirrored(), &student), cause, light);
    }
}

#[test]
fn raylabs_own_picture_has_no_spot_cause() {
    let c = diff(&own_render(&scene()));
    assert!(c.psnr_db >= 60.0, "{}", c.psnr_db);
    assert_no_spot_cause(&c);
    let c = diff_with(&mirrored(), &own_render(&mirrored()));
    assert!(c.psnr_db >= 60.0, "{}", c.psnr_db);
    assert_no_spot_cause(&c);
}

#[test]
fn a_picture_without_specular_has_no_spot_cause() {
    let student = shaded(
        &scene(),
        Bugs {
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

#[test]
fn pictures_with_only_other_bugs_have_no_spot_cause() {
    let others = [
        no_ambient(),
        Bugs {
            diffuse_scale: Some((1, 0.8)),
            ..Bugs::default()
        },
        Bugs {
            truncate: true,
            ..Bugs::default()
        },
        Bugs {
            shadows_off: true,
            ..Bugs::default()
        },
    ];
    for bugs in others {
        let c = diff(&shaded(&scene(), bugs.clone()));
        assert!(!c.explanations.is_empty(), "{bugs:?}");
        assert_no_spot_cause(&c);
    }
    let blend = Bugs {
        mirror_blend: true,
        ..Bugs::default()
    };
    let c = diff_with(&mirrored(), &shaded(&mirrored(), blend));
    assert_eq!(c.explanations[0].cause.name(), "mirror-blend");
    assert_no_spot_cause(&c);
}
