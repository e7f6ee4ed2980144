//! `diff` names each way a real tracer goes wrong: a second shader (tests/compare/
//! shader.rs) renders the test scene with one bug switched on, and the comparison must
//! put the right term, light and object in its top two explanations. An unperturbed
//! render must come out identical.

#[path = "compare/shader.rs"]
mod shader;

use raylab::compare::{Cause, CompareOptions, Comparison, ExplainedTerm, compare};
use raylab::scene::{Light, LightSource, Scene};
use raylab::trace::{RenderOptions, RenderProgress, Term, World, render};
use shader::{Bugs, lab_scene, render as render_with};

fn diff(bugs: &Bugs) -> Comparison {
    diff_of(&lab_scene(), bugs)
}

fn diff_of(scene: &Scene, bugs: &Bugs) -> Comparison {
    let scene = scene.clone();
    let other = render_with(&scene, 1, bugs);
    let options = CompareOptions {
        samples_per_pixel: Some(1),
    };
    compare(&scene, &other, &options, &RenderProgress::default()).unwrap()
}

fn object(name: &str) -> Option<usize> {
    lab_scene().objects.iter().position(|o| o.name == name)
}

/// Asserts that one of the top two explanations names `term`, `light` and `object`,
/// and returns it.
fn named(
    c: &Comparison,
    term: ExplainedTerm,
    light: Option<usize>,
    object: Option<usize>,
) -> raylab::compare::Explanation {
    let report = c.text_lines().join("\n");
    c.explanations
        .iter()
        .take(2)
        .find(|e| e.term == term && e.light == light && e.object == object)
        .unwrap_or_else(|| {
            panic!("no {term:?} light {light:?} object {object:?} in the top two:\n{report}")
        })
        .clone()
}

#[test]
fn the_test_shader_unperturbed_writes_raylabs_bytes() {
    let scene = lab_scene();
    let world = World::new(&scene).unwrap();
    let options = RenderOptions {
        samples_per_pixel: 2,
        ..RenderOptions::from_scene(&scene)
    };
    let (image, _) = render(&world, &options, &RenderProgress::default()).unwrap();
    let ours = render_with(&scene, 2, &Bugs::default());
    let raylab: Vec<[u8; 3]> = image
        .to_rgba8()
        .chunks(4)
        .map(|p| [p[0], p[1], p[2]])
        .collect();
    assert_eq!(ours.rgb, raylab);
}

#[test]
fn an_unperturbed_render_is_identical() {
    let c = diff(&Bugs::default());
    assert!(c.psnr_db >= 60.0, "{}", c.psnr_db);
    assert!(
        c.explanations.iter().all(|e| e.share < 0.05),
        "{:#?}",
        c.text_lines()
    );
    assert!(c.unexplained_share < 0.05);
}

#[test]
fn a_removed_light_is_named_with_factor_zero() {
    let c = diff(&Bugs {
        drop_light: Some(1),
        ..Bugs::default()
    });
    let e = named(&c, ExplainedTerm::Light, Some(1), None);
    assert!(e.factor < 0.05, "{}", e.factor);
    assert_eq!(e.cause, Cause::Factor);
}

#[test]
fn one_objects_halved_diffuse_is_named_with_factor_one_half() {
    let ball = object("red ball");
    let c = diff(&Bugs {
        diffuse_scale: Some((ball.unwrap(), 0.5)),
        ..Bugs::default()
    });
    let e = named(&c, ExplainedTerm::Term(Term::Diffuse), None, ball);
    assert!((e.factor - 0.5).abs() < 0.05, "{}", e.factor);
}

#[test]
fn specular_off_is_named_everywhere() {
    let c = diff(&Bugs {
        specular_off: true,
        ..Bugs::default()
    });
    let e = named(&c, ExplainedTerm::Term(Term::Specular), None, None);
    assert!(e.factor < 0.05, "{}", e.factor);
}

#[test]
fn shadows_off_are_named() {
    let c = diff(&Bugs {
        shadows_off: true,
        ..Bugs::default()
    });
    let e = named(&c, ExplainedTerm::Term(Term::Shadows), None, None);
    assert!(e.factor < 0.1, "{}", e.factor);
}

#[test]
fn the_wrong_reflected_vector_is_named() {
    let c = diff(&Bugs {
        negated_reflection: true,
        ..Bugs::default()
    });
    let e = named(&c, ExplainedTerm::Term(Term::Specular), None, None);
    assert_eq!(e.cause.name(), "reflected-vector-negated");
}

#[test]
fn the_n_minus_l_reflected_vector_is_named_alone_and_beside_a_missing_ambient() {
    for ambient_off in [false, true] {
        let c = diff(&Bugs {
            n_minus_l: true,
            ambient_off,
            ..Bugs::default()
        });
        let e = named(&c, ExplainedTerm::Term(Term::Specular), None, None);
        assert_eq!(
            e.cause.name(),
            "reflected-vector-n-minus-l",
            "ambient off: {ambient_off}"
        );
    }
    // The other reflected-vector bug is not taken for this one.
    let c = diff(&Bugs {
        negated_reflection: true,
        ..Bugs::default()
    });
    assert_ne!(
        named(&c, ExplainedTerm::Term(Term::Specular), None, None)
            .cause
            .name(),
        "reflected-vector-n-minus-l"
    );
}

#[test]
fn a_cone_normal_without_its_z_part_is_named() {
    let c = diff(&Bugs {
        cone_normal_without_z: true,
        ..Bugs::default()
    });
    let e = named(
        &c,
        ExplainedTerm::Term(Term::Diffuse),
        None,
        object("gold cone"),
    );
    assert_eq!(e.cause.name(), "normal-without-z");
}

#[test]
fn colour_clamped_before_the_reflection_is_named_as_the_course_clamp_where_they_agree() {
    // A brighter point light, so the mirror ball sees surfaces brighter than 1.
    let mut scene = lab_scene();
    if let Light::Point {
        source: LightSource { intensity, .. },
        ..
    } = &mut scene.lights[1]
    {
        *intensity *= 2.5;
    }
    let bugs = Bugs {
        clamp_before_reflection: true,
        ..Bugs::default()
    };
    let c = diff_of(&scene, &bugs);
    // Here clamping the local colour before the reflection and the course's clamp of
    // every ray give the same picture (the rays the mirror sees stay below 1): the
    // course's convention, the likelier habit, is named, and it explains it all.
    let first = &c.explanations[0];
    assert_eq!(
        first.term,
        ExplainedTerm::Conventions,
        "{:#?}",
        c.text_lines()
    );
    assert_eq!(first.cause.name(), "clamp-each-ray");
    assert!(
        first.share > 0.95 && first.pixels.len() > 50,
        "{:#?}",
        c.text_lines()
    );
}

#[test]
fn truncation_instead_of_rounding_is_named_and_explains_everything() {
    let c = diff(&Bugs {
        truncate: true,
        ..Bugs::default()
    });
    let e = named(&c, ExplainedTerm::Encoding, None, None);
    assert_eq!(e.cause.name(), "truncate");
    assert!(
        e.share > 0.95 && c.unexplained_share < 0.05,
        "{:#?}",
        c.text_lines()
    );
}

#[test]
fn a_one_sided_plane_is_named_as_geometry() {
    let c = diff(&Bugs {
        one_sided_planes: true,
        ..Bugs::default()
    });
    let e = named(&c, ExplainedTerm::Geometry, None, object("wall"));
    assert_eq!(e.cause.name(), "one-sided");
}

#[test]
fn a_directional_light_that_never_lights_is_named() {
    let c = diff(&Bugs {
        directional_never_lights: true,
        ..Bugs::default()
    });
    let e = named(&c, ExplainedTerm::Light, Some(2), None);
    assert!(e.factor < 0.05, "{}", e.factor);
}
