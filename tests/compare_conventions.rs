//! `raylab diff` and the course's conventions: a picture that blends mirrors or clamps
//! each ray is named by that convention first (not as a scatter of per-object factors),
//! a truncating one as `truncate`, and a picture that follows the scene's own
//! conventions, the course's included, is explained by nothing.

#[path = "compare/one_sample.rs"]
mod one_sample;

use std::path::Path;

use one_sample::diff;
use raylab::compare::{Comparison, ExplainedTerm, OtherImage};
use raylab::scene::{
    ClampConvention, Conventions, Light, LightSource, MirrorConvention, Scene, load_scene,
};
use raylab::trace::{RenderOptions, RenderProgress, World, render};

fn small_default() -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/default.ron");
    let mut scene = load_scene(&path).unwrap();
    scene.camera.width = 96;
    scene.camera.height = 72;
    scene
}

/// The other picture: raylab's render of `scene` under `conventions` (one sample per
/// pixel), written as bytes the way `conventions.quantise` says.
fn rendered_under(scene: &Scene, conventions: Conventions) -> OtherImage {
    let mut varied = scene.clone();
    varied.render.conventions = conventions;
    let world = World::new(&varied).unwrap();
    let options = RenderOptions {
        samples_per_pixel: 1,
        ..RenderOptions::from_scene(&varied)
    };
    let (image, _) = render(&world, &options, &RenderProgress::default()).unwrap();
    let png = image.png_bytes_as(conventions.quantise);
    OtherImage::from_bytes(&png, Path::new("other.png")).unwrap()
}

fn first_cause(c: &Comparison) -> (&'static str, f64) {
    let first = &c.explanations[0];
    (first.cause.name(), first.share)
}

#[test]
fn mirrors_blended_as_the_skeleton_does_are_named_mirror_blend() {
    let scene = small_default();
    let blend = Conventions {
        mirror: MirrorConvention::Blend,
        ..Conventions::default()
    };
    let c = diff(&scene, &rendered_under(&scene, blend));
    let report = c.text_lines().join("\n");
    let (cause, share) = first_cause(&c);
    assert_eq!(cause, "mirror-blend", "{report}");
    assert!(share > 0.8, "{report}");
    assert_eq!(c.explanations[0].term, ExplainedTerm::Conventions);
}

#[test]
fn every_ray_clamped_as_the_skeleton_does_is_named_clamp_each_ray() {
    // Bright lights, so rays seen in the mirror ball carry colours above 1.
    let mut scene = small_default();
    for light in &mut scene.lights {
        match light {
            Light::Point {
                source: LightSource { intensity, .. },
                ..
            }
            | Light::Spot {
                source: LightSource { intensity, .. },
                ..
            } => *intensity *= 4.0,
            _ => {}
        }
    }
    let each_ray = Conventions {
        clamp: ClampConvention::EachRay,
        ..Conventions::default()
    };
    let c = diff(&scene, &rendered_under(&scene, each_ray));
    let report = c.text_lines().join("\n");
    assert_eq!(first_cause(&c).0, "clamp-each-ray", "{report}");
}

#[test]
fn the_course_skeleton_in_a_contract_scene_is_named_truncate_and_its_conventions() {
    let scene = small_default();
    let skeleton = Conventions {
        mirror: MirrorConvention::Blend,
        ..Conventions::COURSE
    };
    let c = diff(&scene, &rendered_under(&scene, skeleton));
    let report = c.text_lines().join("\n");
    let causes: Vec<&str> = c.explanations.iter().map(|e| e.cause.name()).collect();
    assert_eq!(causes[0], "mirror-blend-clamp-each-ray", "{report}");
    assert!(causes.contains(&"truncate"), "{report}");
}

#[test]
fn a_picture_that_follows_the_scenes_conventions_is_explained_by_nothing() {
    for conventions in [Conventions::default(), Conventions::COURSE] {
        let mut scene = small_default();
        scene.render.conventions = conventions;
        let c = diff(&scene, &rendered_under(&scene, conventions));
        assert!(
            c.explanations.iter().all(|e| e.share < 0.05),
            "{conventions:?}: {:#?}",
            c.text_lines()
        );
        assert!(
            !c.explanations
                .iter()
                .any(|e| matches!(e.term, ExplainedTerm::Conventions | ExplainedTerm::Encoding)),
            "{conventions:?}: no convention or encoding verdict: {:#?}",
            c.text_lines()
        );
    }
}

#[test]
fn rays_bouncing_past_the_depth_limit_are_named_no_depth_limit_alone_and_with_truncation() {
    // The scene stops at one bounce; the other tracer has no limit.
    let mut scene = small_default();
    scene.render.max_depth = 1;
    let mut unlimited = scene.clone();
    unlimited.render.max_depth = 48;
    for quantise in [
        raylab::scene::Quantise::Round,
        raylab::scene::Quantise::Truncate,
    ] {
        let conventions = Conventions {
            quantise,
            ..Conventions::default()
        };
        let c = diff(&scene, &rendered_under(&unlimited, conventions));
        let report = c.text_lines().join("\n");
        let causes: Vec<&str> = c.explanations.iter().map(|e| e.cause.name()).collect();
        let depth = causes
            .iter()
            .position(|&n| n == "no-depth-limit")
            .unwrap_or_else(|| panic!("not named:\n{report}"));
        // First, or right after the encoding's verdict where the picture truncates.
        let before: Vec<&str> = causes[..depth].to_vec();
        assert!(before.iter().all(|&n| n == "truncate"), "{report}");
        assert!(c.explanations[depth].share > 0.5, "{report}");
    }
    // A picture that keeps the limit gets no such verdict.
    let own = diff(&scene, &rendered_under(&scene, Conventions::default()));
    assert!(
        own.explanations
            .iter()
            .all(|e| e.cause.name() != "no-depth-limit")
    );
}
