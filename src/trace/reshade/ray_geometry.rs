//! What a cached ray's answer depends on: the geometry ([`RayGeometry`]: image size,
//! camera, every object's shape and placement), for a shadow ray where its light is
//! ([`ShadowTarget`]), and for a transmitted ray (and every ray below it) its object's
//! `ior` too ([`bent_objects`]). Materials, switches and light colours decide only which
//! rays a pixel needs, never what a ray finds.

use std::sync::Arc;

use glam::{DAffine3, DVec3};

use super::object_materials::value_changed;
use crate::scene::{Camera, Material};
use crate::trace::shapes::Primitive;
use crate::trace::world::{CsgTree, SphereLight, World, WorldLight};

/// What a traced ray's answer depends on besides the light: the image size, the camera
/// and every object's shape and placement.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct RayGeometry {
    pub width: u32,
    pub height: u32,
    pub camera: Camera,
    /// Each object's shape, placement and (for a mesh) which triangles.
    objects: Vec<(Primitive, DAffine3, Option<u64>)>,
    /// The CSG trees, compared by value: a node's operands are its shape.
    trees: Vec<Option<Arc<CsgTree>>>,
    object_scene_index: Vec<usize>,
}

impl RayGeometry {
    pub fn of(world: &World, width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            camera: world.camera.clone(),
            objects: world
                .objects
                .iter()
                .map(|o| {
                    (
                        o.shape,
                        o.world_from_object,
                        o.mesh.as_ref().map(|m| m.id()),
                    )
                })
                .collect(),
            trees: world.objects.iter().map(|o| o.csg.clone()).collect(),
            object_scene_index: world.object_scene_index.clone(),
        }
    }
}

/// What a light's shadow rays depend on: where they go (bit for bit).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum ShadowTarget {
    /// To a point (point and spot lights).
    Position([u64; 3]),
    /// To a sphere (point and spot lights with a radius): its centre, its radius and
    /// how many rays aim at it.
    Sphere([u64; 3], u64, u32),
    /// Towards a light at infinity.
    Direction([u64; 3]),
}

impl ShadowTarget {
    fn of(light: &WorldLight, sphere: Option<SphereLight>) -> Self {
        let bits = |v: DVec3| v.to_array().map(f64::to_bits);
        match (*light, sphere) {
            (WorldLight::Point { position, .. } | WorldLight::Spot { position, .. }, None) => {
                Self::Position(bits(position))
            }
            (
                WorldLight::Point { position, .. } | WorldLight::Spot { position, .. },
                Some(sphere),
            ) => Self::Sphere(bits(position), sphere.radius.to_bits(), sphere.samples),
            (WorldLight::Directional { to_light, .. }, _) => Self::Direction(bits(to_light)),
        }
    }

    /// Per light of `world`, its target.
    pub fn all(world: &World) -> Vec<Self> {
        (world.lights.iter().zip(&world.light_spheres))
            .map(|(light, sphere)| Self::of(light, *sphere))
            .collect()
    }
}

/// Per object of `world`, whether the rays it transmits go another way than they did
/// with the materials `cached` (by world object): its `ior` is not, bit for bit, the one
/// they were traced with. Snell's law at a hit on the object uses that object's index
/// alone (objects do not nest media, so a ray inside it meets its inner surface with the
/// same index), so exactly the entries below such a transmitted ray are stale, and each
/// of them is; the object's mirror ray, its own hit, shadow rays and light factors stay
/// valid. A plane's transmitted ray goes straight on whatever its index.
pub(super) fn bent_objects(cached: &[Material], world: &World) -> Vec<bool> {
    value_changed(cached, world, |m| m.ior)
        .zip(&world.objects)
        .map(|(changed, object)| changed && object.shape != Primitive::Plane)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_new_index_bends_the_rays_of_its_objects_but_a_planes() {
        let text = r#"Scene(
            camera: (position: (0.0, 1.0, 5.0), look_at: (0.0, 0.0, 0.0), fov_deg: 40.0, width: 8, height: 6),
            materials: {
                "glass": (diffuse: (0.1, 0.1, 0.1), transmission: (0.9, 0.9, 0.9), ior: 1.5),
                "water": (diffuse: (0.1, 0.1, 0.1), transmission: (0.9, 0.9, 0.9), ior: 1.33),
            },
            objects: [
                (name: "window", shape: Plane, material: "glass"),
                (name: "ball", shape: Sphere, material: "glass"),
                (name: "pond", shape: Sphere, transform: (translate: (2.0, 0.0, 0.0)), material: "water"),
            ],
        )"#;
        let mut scene = crate::scene::parse_scene(text).unwrap();
        let world = World::new(&scene).unwrap();
        let cached: Vec<Material> = (world.objects.iter())
            .map(|o| world.materials[o.material].clone())
            .collect();
        assert_eq!(bent_objects(&cached, &world), [false; 3]);
        scene.materials.get_mut("glass").unwrap().ior = 1.6;
        let world = World::new(&scene).unwrap();
        assert_eq!(bent_objects(&cached, &world), [false, true, false]);
    }
}
