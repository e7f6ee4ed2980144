//! Where a BVH starts to pay: the same crowd of objects rendered with the flat list and
//! with the hierarchy, for growing object counts.

use std::time::Instant;

use glam::DVec3;
use serde::Serialize;

use crate::scene::{Light, LightSource, Material, Object, Scene, Shape, Transform, Trs};
use crate::trace::{Acceleration, RenderOptions, RenderProgress, World, render};

/// One object count, both ways.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct CrossoverPoint {
    /// Objects in the scene (plus a floor).
    pub objects: usize,
    /// Frame time with the flat list, ms.
    pub flat_ms: f64,
    /// Frame time with the BVH, ms.
    pub bvh_ms: f64,
}

/// A floor and `count` objects of every shape on a jittered grid, lit by a point light.
#[must_use]
pub fn crowd(count: usize) -> Scene {
    let mut scene = Scene::empty();
    scene.materials.insert(
        "m".to_owned(),
        Material {
            ambient: DVec3::splat(0.1),
            diffuse: DVec3::splat(0.7),
            specular: DVec3::splat(0.3),
            shininess: 20.0,
            ..Material::default()
        },
    );
    let place = |translate, rotate_deg, scale| {
        Transform::Trs(Trs {
            translate,
            rotate_deg,
            scale,
        })
    };
    scene.objects.push(Object {
        name: "floor".to_owned(),
        shape: Shape::Plane,
        transform: place(
            DVec3::ZERO,
            DVec3::new(-90.0, 0.0, 0.0),
            DVec3::new(20.0, 20.0, 1.0),
        ),
        material: "m".to_owned(),
    });
    let side = (count as f64).sqrt().ceil().max(1.0);
    for i in 0..count {
        let (gx, gz) = ((i as f64 % side), (i as f64 / side).floor());
        let spacing = 8.0 / side;
        let translate = DVec3::new(
            -4.0 + (gx + 0.5) * spacing,
            0.4,
            -4.0 + (gz + 0.5) * spacing,
        );
        scene.objects.push(Object {
            name: format!("object {i}"),
            shape: Shape::ALL[i % 5].clone(),
            transform: place(
                translate,
                DVec3::new(0.0, i as f64 * 37.0, 0.0),
                DVec3::splat(spacing * 0.3),
            ),
            material: "m".to_owned(),
        });
    }
    scene.lights = vec![
        Light::Ambient {
            colour: DVec3::splat(0.2),
            intensity: 1.0,
        },
        Light::Point {
            position: DVec3::new(3.0, 8.0, 6.0),
            source: LightSource::point(DVec3::ONE, 80.0),
        },
    ];
    scene.camera.position = DVec3::new(0.0, 7.0, 9.0);
    scene.camera.look_at = DVec3::ZERO;
    scene
}

/// Frame times of the crowd at each count, flat and BVH, best of `runs`.
///
/// # Errors
/// Only if a generated scene were invalid.
pub fn bvh_crossover(
    counts: &[usize],
    width: u32,
    height: u32,
    runs: u32,
) -> Result<Vec<CrossoverPoint>, String> {
    counts
        .iter()
        .map(|&count| {
            let scene = crowd(count);
            let mut world = World::new(&scene).map_err(|e| e.to_string())?;
            let options = RenderOptions {
                width,
                height,
                samples_per_pixel: 1,
                ..RenderOptions::from_scene(&scene)
            };
            let mut time = |acceleration| {
                world.set_acceleration(acceleration);
                (0..runs.max(1))
                    .map(|_| {
                        let started = Instant::now();
                        let _ = render(&world, &options, &RenderProgress::default());
                        started.elapsed().as_secs_f64() * 1e3
                    })
                    .fold(f64::INFINITY, f64::min)
            };
            let flat_ms = time(Acceleration::Flat);
            let bvh_ms = time(Acceleration::Bvh);
            Ok(CrossoverPoint {
                objects: count,
                flat_ms,
                bvh_ms,
            })
        })
        .collect()
}
