//! The pixel inspector reports the tracer's own numbers: its terms add up to the pixel.

use std::path::Path;

use glam::DVec3;
use raylab::scene::load_scene;
use raylab::trace::{
    RenderOptions, RenderProgress, Term, TermSwitches, World, inspect_pixel, render,
};

fn default_world() -> (World, RenderOptions) {
    let scene =
        load_scene(&Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/default.ron")).unwrap();
    let world = World::new(&scene).unwrap();
    let options = RenderOptions {
        width: 80,
        height: 60,
        samples_per_pixel: 1,
        ..RenderOptions::from_scene(&scene)
    };
    (world, options)
}

#[test]
fn every_bounce_is_the_sum_of_its_terms_and_the_pixel_matches_the_render() {
    let (world, options) = default_world();
    for switches in [
        TermSwitches::ALL_ON,
        TermSwitches::ALL_ON.with_solo(Some(Term::Specular)),
    ] {
        let options = RenderOptions {
            switches,
            ..options.clone()
        };
        let (image, _) = render(&world, &options, &RenderProgress::default()).unwrap();
        let mut mirrors_seen = 0;
        for py in (0..60).step_by(3) {
            for px in (0..80).step_by(3) {
                let report = inspect_pixel(&world, &options, px, py);
                for bounce in &report.bounces {
                    let sum = bounce.sum_of_terms();
                    assert!(
                        (sum - bounce.colour).abs().max_element() < 1e-12,
                        "({px}, {py}) depth {}",
                        bounce.depth
                    );
                }
                assert_eq!(report.bounces[0].colour, report.unclamped);
                // One code path: the inspector's colour is the rendered pixel exactly.
                assert_eq!(report.unclamped.as_vec3(), image.get(px, py));
                assert_eq!(
                    report.clamped,
                    report.unclamped.clamp(DVec3::ZERO, DVec3::ONE)
                );
                if report.bounces.len() > 1 {
                    mirrors_seen += 1;
                    // Each bounce's colour is what the previous one reflected.
                    for pair in report.bounces.windows(2) {
                        assert_eq!(pair[0].reflection.unwrap().1, pair[1].colour);
                    }
                }
            }
        }
        let solo_without_mirror = switches.solo.is_some_and(|t| t != Term::Reflection);
        assert_eq!(mirrors_seen > 5, !solo_without_mirror, "{mirrors_seen}");
    }
}

#[test]
fn blocked_shadow_rays_name_the_blocker() {
    let (world, options) = default_world();
    let mut blocked = 0;
    for py in 0..60 {
        for px in 0..80 {
            let report = inspect_pixel(&world, &options, px, py);
            for light in &report.bounces[0].lights {
                if let Some(blocker) = light.blocked_by {
                    assert!(blocker < world.objects.len());
                    assert!(light.shadow_ray_cast && light.n_dot_l > 0.0);
                    assert_eq!(light.diffuse + light.specular, DVec3::ZERO);
                    blocked += 1;
                }
                if light.n_dot_l <= 0.0 {
                    assert!(
                        !light.shadow_ray_cast,
                        "no shadow ray for a light behind the surface"
                    );
                }
            }
        }
    }
    assert!(blocked > 20);
}
