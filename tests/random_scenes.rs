//! The tracer on random valid scenes (every shape and light kind, extreme transforms):
//! no panic and no non-finite sample, in every view and with every switch.

mod common;

use common::*;
use glam::DVec3;
use proptest::prelude::*;
use raylab::scene::{Light, LightSource, Material, Scene, Shape};
use raylab::trace::{
    RenderOptions, RenderProgress, Term, TermSwitches, View, World, render_samples,
};

fn vec3(range: std::ops::Range<f64>) -> impl Strategy<Value = DVec3> + Clone {
    (range.clone(), range.clone(), range).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn log_scale() -> impl Strategy<Value = f64> {
    (-6.0..6.0f64, any::<bool>())
        .prop_map(|(e, negative)| 10f64.powf(e) * if negative { -1.0 } else { 1.0 })
}

fn object_strategy() -> impl Strategy<Value = raylab::scene::Object> {
    (
        prop::sample::select(Shape::ALL.to_vec()),
        vec3(-5.0..5.0),
        vec3(-360.0..360.0),
        (log_scale(), log_scale(), log_scale()),
    )
        .prop_map(|(shape, translate, rotate, (sx, sy, sz))| {
            object(shape, translate, rotate, DVec3::new(sx, sy, sz))
        })
}

fn light_strategy() -> impl Strategy<Value = Light> {
    let colour = vec3(0.0..2.0);
    prop_oneof![
        colour.clone().prop_map(|colour| Light::Ambient {
            colour,
            intensity: 1.0
        }),
        (vec3(-8.0..8.0), colour.clone(), 0.0..100.0f64).prop_map(
            |(position, colour, intensity)| Light::Point {
                position,
                source: LightSource::point(colour, intensity),
            }
        ),
        (vec3(-1.0..1.0), colour.clone()).prop_filter_map(
            "zero direction",
            |(direction, colour)| {
                (direction.length() > 1e-3).then_some(Light::Directional {
                    direction,
                    colour,
                    intensity: 1.0,
                })
            }
        ),
        (vec3(-8.0..8.0), vec3(-1.0..1.0), 0.01..90.0f64, colour).prop_filter_map(
            "zero direction",
            |(position, direction, angle_deg, colour)| {
                (direction.length() > 1e-3).then_some(Light::Spot {
                    position,
                    direction,
                    angle_deg,
                    source: LightSource::point(colour, 20.0),
                })
            }
        ),
    ]
}

fn scene_strategy() -> impl Strategy<Value = Scene> {
    (
        prop::collection::vec(object_strategy(), 0..6),
        prop::collection::vec(light_strategy(), 0..5),
        (
            vec3(0.0..1.0),
            vec3(0.0..1.0),
            vec3(0.0..1.0),
            vec3(0.0..1.0),
            0.1..600.0f64,
        ),
        0u32..6,
    )
        .prop_map(
            |(objects, lights, (ka, kd, ks, km, shininess), max_depth)| {
                let mut scene = bare_scene(Material {
                    ambient: ka,
                    diffuse: kd,
                    specular: ks,
                    shininess,
                    mirror: km,
                    transmission: DVec3::ZERO,
                    ior: 1.0,
                });
                scene.objects = objects;
                scene.lights = lights;
                scene.render.max_depth = max_depth;
                scene.render.background = DVec3::new(0.1, 0.2, 0.3);
                scene
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

    #[test]
    fn random_scenes_render_finite_pixels_in_every_view(scene in scene_strategy(), solo in 0usize..6) {
        let world = World::new(&scene).unwrap();
        let switches = TermSwitches::ALL_ON.with_solo(Term::ALL.get(solo).copied());
        for view in View::ALL {
            let options = RenderOptions {
                width: 12,
                height: 9,
                samples_per_pixel: 2,
                switches,
                view,
                isolation: Default::default(),
            };
            let sums = render_samples(&world, &options, 0..2, &RenderProgress::default()).unwrap();
            prop_assert_eq!(sums.non_finite, 0);
            prop_assert!(sums.sums.iter().all(|s| s.is_finite() && s.min_element() >= 0.0));
        }
    }
}
