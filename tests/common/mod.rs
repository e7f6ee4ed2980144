//! Helpers shared by the integration tests: small scenes built in code, and single rays;
//! `cli` for running the binary; `legacy` for the legacy importer's tests; `obj` for
//! OBJ text.
#![allow(dead_code)]

pub mod cli;
pub mod legacy;
pub mod obj;

use std::collections::BTreeMap;

use glam::DVec3;
use raylab::scene::{
    Camera, Light, LightSource, Material, Object, RenderSettings, Scene, Shape, Transform, Trs,
};
use raylab::trace::{NoRecorder, Ray, RayCounts, TermSwitches, Tracer, View, World};

/// A 33 x 33 view of a unit sphere with a point light 1e-7 above the surface point under
/// the centre pixel: each of colour and intensity is finite and so is their product, but
/// divided by d^2 = 1e-14 the light's strength there is infinite.
pub const LIGHT_ON_THE_SURFACE: &str = r#"
Scene(
    camera: (position: (0.0, 0.0, 5.0), look_at: (0.0, 0.0, 0.0), fov_deg: 40.0,
             width: 33, height: 33),
    render: (samples_per_pixel: 1),
    materials: { "white": (ambient: (0.1, 0.1, 0.1), diffuse: (0.8, 0.8, 0.8)) },
    objects: [(shape: Sphere, material: "white")],
    lights: [
        Ambient(colour: (1.0, 1.0, 1.0)),
        Point(position: (0.0, 0.0, 1.0000001), colour: (1.0, 1.0, 1.0), intensity: 1e300),
    ],
)
"#;

/// A scene with one material "m", no objects, no lights and a camera on +z.
pub fn bare_scene(material: Material) -> Scene {
    Scene {
        format: 1,
        camera: Camera {
            position: DVec3::new(0.0, 0.0, 5.0),
            look_at: DVec3::ZERO,
            up: DVec3::Y,
            fov_deg: 40.0,
            width: 33,
            height: 33,
        },
        render: RenderSettings {
            max_depth: 5,
            background: DVec3::ZERO,
            samples_per_pixel: 1,
            conventions: Default::default(),
        },
        materials: BTreeMap::from([("m".to_owned(), material)]),
        objects: Vec::new(),
        lights: Vec::new(),
    }
}

/// An object of `shape` with material "m".
pub fn object(shape: Shape, translate: DVec3, rotate_deg: DVec3, scale: DVec3) -> Object {
    Object {
        name: format!("{} test", shape.name()),
        shape,
        transform: Transform::Trs(Trs {
            translate,
            rotate_deg,
            scale,
        }),
        material: "m".to_owned(),
    }
}

/// A floor: the unit plane turned to face +y, scaled by `half_size`, at height `y`.
pub fn floor(y: f64, half_size: f64) -> Object {
    object(
        Shape::Plane,
        DVec3::new(0.0, y, 0.0),
        DVec3::new(-90.0, 0.0, 0.0),
        DVec3::new(half_size, half_size, 1.0),
    )
}

/// A point light.
pub fn point_light(position: DVec3, intensity: f64) -> Light {
    Light::Point {
        position,
        source: LightSource::point(DVec3::ONE, intensity),
    }
}

/// The colour of one ray through a scene, with the given switches.
pub fn trace(scene: &Scene, ray: Ray, switches: TermSwitches) -> DVec3 {
    let world = World::new(scene).expect("valid test scene");
    Tracer::new(&world, switches, View::Beauty).trace_primary(
        &ray,
        &mut RayCounts::default(),
        &mut NoRecorder,
    )
}

/// Asserts two colours agree to a relative 1e-12.
pub fn assert_colour(actual: DVec3, expected: DVec3) {
    let scale = expected.abs().max_element().max(1e-300);
    assert!(
        (actual - expected).abs().max_element() <= 1e-12 * scale.max(1.0),
        "colour {actual} expected {expected}"
    );
}

/// A reproducible stream of numbers in [0, 1) from `seed` (xorshift64; a seed of 0 is
/// made odd), for tests that want many varied inputs without a random crate.
pub fn unit_random(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed | 1;
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    }
}
