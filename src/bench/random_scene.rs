//! Random scenes of the course's kind for measuring `raylab diff` on scenes it was not
//! tuned on: a floor, two to five objects of every shape on or above it (some mirrors,
//! some glass), an ambient light and one to three lights of every kind, a camera that
//! sees them all. Each scene is a function of its seed alone.

use std::collections::BTreeMap;

use glam::DVec3;

use crate::scene::{
    Camera, Light, LightSource, Material, Object, RenderSettings, Scene, Shape, Transform, Trs,
};

/// The random scene of `seed`, `width` x `height` pixels.
#[must_use]
pub fn random_scene(seed: u64, width: u32, height: u32) -> Scene {
    let mut rng = fastrand::Rng::with_seed(seed);
    let mut scene = Scene::empty();
    scene.camera = Camera {
        position: DVec3::new(
            rng.f64() * 4.0 - 2.0,
            2.0 + rng.f64() * 2.0,
            7.0 + rng.f64() * 2.0,
        ),
        look_at: DVec3::new(0.0, 0.7, 0.0),
        up: DVec3::Y,
        fov_deg: 40.0 + rng.f64() * 15.0,
        width,
        height,
    };
    scene.render = RenderSettings {
        max_depth: 1 + rng.u32(0..5),
        background: colour(&mut rng, 0.0, 0.15),
        samples_per_pixel: 1,
        ..RenderSettings::default()
    };
    let mut materials = BTreeMap::new();
    materials.insert(
        "floor".to_owned(),
        Material {
            ambient: DVec3::splat(0.2),
            diffuse: colour(&mut rng, 0.3, 0.7),
            specular: DVec3::splat(0.2 * rng.f64()),
            shininess: 5.0 + 20.0 * rng.f64(),
            mirror: if rng.u32(0..4) == 0 {
                DVec3::splat(0.3)
            } else {
                DVec3::ZERO
            },
            ..Material::default()
        },
    );
    scene.objects.push(Object {
        name: "floor".to_owned(),
        shape: Shape::Plane,
        transform: trs(
            DVec3::ZERO,
            DVec3::new(-90.0, 0.0, 0.0),
            DVec3::new(6.0, 6.0, 1.0),
        ),
        material: "floor".to_owned(),
    });
    let shapes = [
        Shape::Sphere,
        Shape::Cube,
        Shape::Cylinder,
        Shape::Cone,
        Shape::Torus { minor: 0.4 },
        Shape::Octahedron,
    ];
    let count = 2 + rng.usize(0..4);
    for i in 0..count {
        let shape = shapes[rng.usize(0..shapes.len())].clone();
        let name = format!("object {i}");
        let kind = rng.u32(0..10);
        let diffuse = colour(&mut rng, 0.1, 0.9);
        let material = Material {
            ambient: diffuse * 0.2,
            diffuse,
            specular: DVec3::splat(rng.f64() * 0.8),
            shininess: [2.0, 10.0, 30.0, 80.0][rng.usize(0..4)],
            mirror: if kind < 2 {
                DVec3::splat(0.5 + 0.4 * rng.f64())
            } else {
                DVec3::ZERO
            },
            transmission: if kind == 2 {
                DVec3::splat(0.7)
            } else {
                DVec3::ZERO
            },
            ior: if kind == 2 { 1.5 } else { 1.0 },
        };
        materials.insert(name.clone(), material);
        let size = 0.4 + 0.5 * rng.f64();
        // Spread over a ring so that objects rarely hide each other entirely.
        let angle = (i as f64 + rng.f64() * 0.6) / count as f64 * std::f64::consts::TAU;
        let radius = 1.0 + 1.5 * rng.f64();
        let centre = DVec3::new(
            radius * angle.cos(),
            size * (1.0 + rng.f64()),
            radius * angle.sin() - 0.5,
        );
        let rotate = DVec3::new(rng.f64() * 360.0, rng.f64() * 360.0, rng.f64() * 360.0);
        let stretch = DVec3::new(1.0, 1.0 + rng.f64() * 0.5, 1.0);
        scene.objects.push(Object {
            name: name.clone(),
            shape,
            transform: trs(centre, rotate, stretch * size),
            material: name,
        });
    }
    scene.materials = materials;
    scene.lights.push(Light::Ambient {
        colour: colour(&mut rng, 0.05, 0.25),
        intensity: 1.0,
    });
    let lights = 1 + rng.usize(0..3);
    for _ in 0..lights {
        let position = DVec3::new(
            rng.f64() * 8.0 - 4.0,
            3.0 + rng.f64() * 4.0,
            rng.f64() * 6.0 - 1.0,
        );
        let light = match rng.u32(0..3) {
            0 => Light::Point {
                position,
                source: LightSource::point(
                    colour(&mut rng, 0.5, 1.0),
                    position.length_squared() * (0.4 + 0.6 * rng.f64()),
                ),
            },
            1 => Light::Directional {
                direction: DVec3::new(rng.f64() - 0.5, -1.0, rng.f64() - 0.5),
                colour: colour(&mut rng, 0.3, 0.8),
                intensity: 1.0,
            },
            _ => Light::Spot {
                position,
                direction: DVec3::new(0.0, 0.7, 0.0) - position,
                angle_deg: 15.0 + 35.0 * rng.f64(),
                source: LightSource::point(
                    colour(&mut rng, 0.5, 1.0),
                    position.length_squared() * (0.5 + rng.f64()),
                ),
            },
        };
        scene.lights.push(light);
    }
    scene
}

fn trs(translate: DVec3, rotate_deg: DVec3, scale: DVec3) -> Transform {
    Transform::Trs(Trs {
        translate,
        rotate_deg,
        scale,
    })
}

fn colour(rng: &mut fastrand::Rng, lo: f64, hi: f64) -> DVec3 {
    DVec3::new(
        lo + (hi - lo) * rng.f64(),
        lo + (hi - lo) * rng.f64(),
        lo + (hi - lo) * rng.f64(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scenes_are_valid_and_a_function_of_their_seed() {
        for seed in 0..20 {
            let scene = random_scene(seed, 64, 48);
            assert_eq!(scene, random_scene(seed, 64, 48));
            crate::trace::World::new(&scene).unwrap_or_else(|e| panic!("seed {seed}: {e}"));
            assert!(scene.objects.len() >= 3 && scene.lights.len() >= 2);
        }
        assert_ne!(random_scene(1, 64, 48), random_scene(2, 64, 48));
    }
}
