//! Where two explanations fit alike, `diff` prefers the most specific and says the
//! other fits as well: in a scene whose only light (besides the ambient) is one
//! directional light, a picture without it reads as "light N contributes nothing"
//! (the likelier bug), with "the diffuse term of every light" as fitting as well; in a
//! scene with two lights the light alone is named, with no such note.

#[path = "compare/shader.rs"]
mod shader;

#[path = "compare/one_sample.rs"]
mod one_sample;

use one_sample::diff;
use raylab::compare::{Cause, Comparison, ExplainedTerm};
use raylab::scene::{Light, Scene};
use raylab::trace::Term;
use shader::{Bugs, lab_scene, render};

/// The lab scene with only the lights `keep` says (by kind) besides the ambient.
fn lit_by(keep: fn(&Light) -> bool) -> Scene {
    let mut scene = lab_scene();
    scene
        .lights
        .retain(|l| matches!(l, Light::Ambient { .. }) || keep(l));
    scene
}

/// Asserts that the first explanation is `term` of `light` at factor 0 (`Light`: the
/// light itself, its diffuse and specular terms both missing).
fn assert_light_first(c: &Comparison, term: ExplainedTerm, light: usize) {
    let report = c.text_lines().join("\n");
    let first = &c.explanations[0];
    assert_eq!(first.term, term, "{report}");
    assert_eq!(first.cause, Cause::Factor, "{report}");
    assert_eq!(first.light, Some(light), "{report}");
    assert!(first.factor < 0.02, "{report}");
}

#[test]
fn the_only_light_that_never_lights_is_named_before_the_whole_term() {
    let scene = lit_by(|l| matches!(l, Light::Directional { .. }));
    assert_eq!(scene.lights.len(), 2);
    let bugs = Bugs {
        directional_never_lights: true,
        ..Bugs::default()
    };
    let c = diff(&scene, &render(&scene, 1, &bugs));
    assert_light_first(&c, ExplainedTerm::Light, 1);
    let report = c.text_lines().join("\n");
    let first = &c.explanations[0];
    assert!(
        first
            .fits_as_well
            .contains(&"the diffuse term of every light".to_owned()),
        "{report}"
    );
    assert!(first.summary.contains("Fits as well: "), "{report}");
    let json: serde_json::Value = serde_json::from_str(&c.to_json()).unwrap();
    let listed = &json["explanations"][0]["fits_as_well"];
    assert!(
        listed
            .as_array()
            .is_some_and(|a| a.iter().any(|v| v == "the diffuse term of every light")),
        "{json}"
    );
    // Its specular part too, where it has one.
    assert!(
        c.explanations
            .iter()
            .filter(|e| e.term == ExplainedTerm::Term(Term::Specular))
            .all(|e| e.light == Some(1)),
        "{report}"
    );
}

#[test]
fn a_dropped_point_light_alone_in_its_scene_is_named_as_the_light() {
    let scene = lit_by(|l| matches!(l, Light::Point { .. }));
    let bugs = Bugs {
        drop_light: Some(1),
        ..Bugs::default()
    };
    let c = diff(&scene, &render(&scene, 1, &bugs));
    assert_light_first(&c, ExplainedTerm::Light, 1);
}

#[test]
fn with_two_lights_the_light_is_named_without_a_like_reading() {
    let scene = lab_scene();
    let bugs = Bugs {
        directional_never_lights: true,
        ..Bugs::default()
    };
    let c = diff(&scene, &render(&scene, 1, &bugs));
    assert_light_first(&c, ExplainedTerm::Light, 2);
    let report = c.text_lines().join("\n");
    assert!(c.explanations[0].fits_as_well.is_empty(), "{report}");
    // And a term missing for every light stays the whole term.
    let bugs = Bugs {
        specular_off: true,
        ..Bugs::default()
    };
    let c = diff(&scene, &render(&scene, 1, &bugs));
    let report = c.text_lines().join("\n");
    assert_eq!(
        c.explanations[0].term,
        ExplainedTerm::Term(Term::Specular),
        "{report}"
    );
    assert_eq!(c.explanations[0].light, None, "{report}");
}
