//! Scenes with known ray paths, shared by the inspect and ray-path tests.
#![allow(dead_code)]

use std::collections::BTreeMap;

use glam::DVec3;
use raylab::scene::{Light, LightSource, Material, Scene, Shape};

use crate::common::{bare_scene, object, point_light};

/// A unit mirror square at the origin facing the camera (on +z, 33 x 33 pixels), a
/// "target" ball behind the camera that only the mirror shows, a point light beyond the
/// ball, and a spotlight that points away from everything.
pub fn mirror_scene() -> Scene {
    let mut scene = bare_scene(Material::default());
    scene.materials = BTreeMap::from([
        (
            "mirror".to_owned(),
            Material {
                diffuse: DVec3::splat(0.5),
                mirror: DVec3::splat(0.5),
                ..Material::default()
            },
        ),
        (
            "matte".to_owned(),
            Material {
                diffuse: DVec3::splat(0.8),
                ..Material::default()
            },
        ),
    ]);
    let mut mirror = object(Shape::Plane, DVec3::ZERO, DVec3::ZERO, DVec3::ONE);
    mirror.name = "mirror".to_owned();
    mirror.material = "mirror".to_owned();
    let mut target = object(
        Shape::Sphere,
        DVec3::new(0.0, 0.0, 8.0),
        DVec3::ZERO,
        DVec3::ONE,
    );
    target.name = "target".to_owned();
    target.material = "matte".to_owned();
    scene.objects = vec![mirror, target];
    scene.lights = vec![
        Light::Ambient {
            colour: DVec3::splat(0.1),
            intensity: 1.0,
        },
        point_light(DVec3::new(0.0, 0.0, 20.0), 100.0),
        Light::Spot {
            position: DVec3::new(0.0, 0.0, 3.0),
            direction: DVec3::Y,
            angle_deg: 10.0,
            source: LightSource::point(DVec3::ONE, 10.0),
        },
    ];
    scene.render.background = DVec3::new(0.1, 0.2, 0.3);
    scene
}
