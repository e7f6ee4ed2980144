//! Shared by the re-shade tests: a scene and how it is rendered, the one-sample pass
//! traced from scratch or answered from a cache, and a chain of edits each checked bit
//! for bit against a full trace.
#![allow(dead_code)]

use glam::DVec3;
use raylab::scene::examples::EXAMPLE_SCENES;
use raylab::scene::{Light, LightSource, Scene, parse_scene};
use raylab::trace::{
    CachedPass, HitCache, RayCounts, RenderOptions, RenderProgress, SampleSums, World,
    render_one_sample_cached, render_samples,
};

/// Scenes with mirrors, every light kind, spots, shininess below 1, a sphere light and
/// glass (trees of rays, total internal reflection, a CSG lens, glass seen in a mirror).
pub const SCENES: [&str; 7] = [
    "default.ron",
    "spotlights.ron",
    "specular_exponents.ron",
    "mirror_cap.ron",
    "soft_spot.ron",
    "glass.ron",
    GLASS_TREES_NAME,
];

/// The name [`example`] knows [`GLASS_TREES`] by.
pub const GLASS_TREES_NAME: &str = "glass_trees (test)";

/// Trees of every shape, with the course's conventions (the mirror blended, each ray's
/// colour clamped): a glass ball without a mirror share (its rays a chain of transmitted
/// rays) seen directly and in a mirror ball, a tilted glass cube (total internal
/// reflection inside it, both rays from every hit) and a mirror behind it.
pub const GLASS_TREES: &str = r#"Scene(
    camera: (position: (0.0, 3.0, 6.0), look_at: (0.0, 0.7, 0.0), fov_deg: 45.0, width: 64, height: 48),
    render: (max_depth: 5, background: (0.3, 0.35, 0.5),
             conventions: (mirror: Blend, clamp: EachRay, quantise: Truncate)),
    materials: {
        "floor": (ambient: (0.1, 0.1, 0.1), diffuse: (0.6, 0.55, 0.5), specular: (0.2, 0.2, 0.2), shininess: 20.0),
        "mirror": (ambient: (0.0, 0.0, 0.0), diffuse: (0.05, 0.05, 0.05), specular: (0.6, 0.6, 0.6), shininess: 150.0, mirror: (0.85, 0.85, 0.85)),
        "clear": (diffuse: (0.0, 0.0, 0.0), specular: (0.9, 0.9, 0.9), shininess: 200.0, transmission: (0.95, 0.95, 0.95), ior: 1.3),
        "prism": (ambient: (0.02, 0.02, 0.05), diffuse: (0.05, 0.05, 0.1), specular: (0.7, 0.7, 0.7), shininess: 80.0,
                  mirror: (0.1, 0.1, 0.1), transmission: (0.85, 0.9, 0.95), ior: 1.5),
    },
    objects: [
        (name: "floor", shape: Plane, transform: (rotate_deg: (-90.0, 0.0, 0.0), scale: (10.0, 10.0, 1.0)), material: "floor"),
        (name: "mirror ball", shape: Sphere, transform: (translate: (-1.6, 0.9, -1.2), scale: (0.9, 0.9, 0.9)), material: "mirror"),
        (name: "clear ball", shape: Sphere, transform: (translate: (-0.3, 0.6, 0.8), scale: (0.6, 0.6, 0.6)), material: "clear"),
        (name: "prism", shape: Cube, transform: (translate: (1.3, 0.7, 0.2), rotate_deg: (30.0, 40.0, 10.0), scale: (0.6, 0.6, 0.6)), material: "prism"),
        (name: "back mirror", shape: Cube, transform: (translate: (1.0, 1.0, -2.5), scale: (1.5, 1.0, 0.1)), material: "mirror"),
    ],
    lights: [
        Ambient(colour: (0.2, 0.2, 0.2)),
        Point(position: (2.0, 5.0, 4.0), colour: (1.0, 1.0, 1.0), intensity: 40.0),
        Directional(direction: (-0.3, -1.0, -0.4), colour: (0.3, 0.3, 0.35), intensity: 1.0),
    ],
)"#;

/// An example scene (or [`GLASS_TREES`]) at 64 x 48.
pub fn example(name: &str) -> Scene {
    let text = if name == GLASS_TREES_NAME {
        GLASS_TREES
    } else {
        EXAMPLE_SCENES.iter().find(|(n, _)| *n == name).unwrap().1
    };
    let mut scene = parse_scene(text).unwrap();
    scene.camera.width = 64;
    scene.camera.height = 48;
    scene
}

/// A scene and how it is rendered: the state before or after an edit.
#[derive(Clone)]
pub struct Shot {
    pub scene: Scene,
    pub options: RenderOptions,
}

impl Shot {
    pub fn of(scene: Scene) -> Self {
        let options = RenderOptions::from_scene(&scene);
        Self { scene, options }
    }

    pub fn world(&self) -> World {
        World::isolated(&self.scene, &self.options.isolation).unwrap()
    }

    /// The one-sample pass traced from scratch, as `raylab render` does it.
    pub fn traced(&self) -> SampleSums {
        let options = RenderOptions {
            samples_per_pixel: 1,
            ..self.options.clone()
        };
        render_samples(&self.world(), &options, 0..1, &RenderProgress::default()).unwrap()
    }

    /// The one-sample pass answered from `cache` where it can.
    pub fn cached(&self, cache: Option<&HitCache>) -> CachedPass {
        let world = self.world();
        render_one_sample_cached(&world, &self.options, cache, &RenderProgress::default()).unwrap()
    }

    pub fn edited(&self, edit: impl FnOnce(&mut Scene, &mut RenderOptions)) -> Self {
        let mut next = self.clone();
        edit(&mut next.scene, &mut next.options);
        next
    }
}

/// Every sum's bits, the guard's counts and the modelled rays are the same.
pub fn assert_same_pass(reshaded: &SampleSums, traced: &SampleSums, what: &str) {
    let bits = |s: &SampleSums| -> Vec<[u64; 3]> {
        s.sums
            .iter()
            .map(|v| v.to_array().map(f64::to_bits))
            .collect()
    };
    assert!(bits(reshaded) == bits(traced), "{what}: pixels differ");
    assert_eq!(reshaded.non_finite, traced.non_finite, "{what}");
    assert_eq!(
        reshaded.non_finite_pixels, traced.non_finite_pixels,
        "{what}: non-finite pixels"
    );
    assert_eq!(reshaded.rays, traced.rays, "{what}: rays modelled");
}

/// Renders `before` (filling a cache), then each edit in turn from the cache the one
/// before left; checks every re-shaded pass against a full trace and returns the rays
/// each one traced.
pub fn edit_chain(before: &Shot, edits: &[Shot], what: &str) -> Vec<CachedPass> {
    let first = before.cached(None);
    assert_same_pass(&first.sums, &before.traced(), what);
    assert!(!first.reused);
    assert_eq!(
        first.traced, first.sums.rays,
        "{what}: no cache traces everything"
    );
    let mut cache = first.cache;
    let mut passes = Vec::new();
    for (step, shot) in edits.iter().enumerate() {
        let pass = shot.cached(Some(&cache));
        assert_same_pass(&pass.sums, &shot.traced(), &format!("{what}, edit {step}"));
        cache = pass.cache.clone();
        passes.push(pass);
    }
    passes
}

pub const NOTHING: RayCounts = RayCounts {
    primary: 0,
    shadow: 0,
    reflection: 0,
    transmission: 0,
};

/// Sets any light's colour.
pub fn set_colour(light: &mut Light, to: DVec3) {
    match light {
        Light::Ambient { colour, .. }
        | Light::Point {
            source: LightSource { colour, .. },
            ..
        }
        | Light::Directional { colour, .. }
        | Light::Spot {
            source: LightSource { colour, .. },
            ..
        } => *colour = to,
    }
}
