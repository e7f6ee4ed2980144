//! What the recorder ([`super::recorder`]) needs to know about the world, prepared once
//! per comparison: the channel numbering, where each scene light is among the world's,
//! and the changed worlds it traces again (without an object, with a spot light's cone
//! bug).

use super::channels::ChannelSpace;
use super::spot_bugs::SpotWorld;
use crate::scene::Material;
use glam::DVec3;

use crate::trace::{NoRecorder, Ray, RayCounts, TermSwitches, Tracer, View, World};

/// What the recorder needs to know about the world, prepared once.
pub struct Context<'w> {
    /// The world traced.
    pub world: &'w World,
    /// The channel numbering.
    pub space: ChannelSpace,
    /// For each scene light index, its index among the world's non-ambient lights.
    pub world_light: Vec<Option<usize>>,
    /// For each scene object, the world without it (for the first few objects), to see
    /// what a ray would meet if the object were missing.
    pub without: Vec<Option<World>>,
    /// For each scene object, its world objects (a group's members are several).
    pub world_objects: Vec<std::ops::Range<usize>>,
    /// The worlds of the spot lights' cone bugs.
    pub spot: Vec<SpotWorld>,
}

impl<'w> Context<'w> {
    /// The context of `world` with `scene_lights` lights in the scene's list, one
    /// channel object per scene object, `without[o]` the world without scene object `o`
    /// (or `None` not to try it missing), and `spot` the worlds of the spot lights' cone
    /// bugs.
    #[must_use]
    pub fn new(
        world: &'w World,
        scene_lights: usize,
        without: Vec<Option<World>>,
        spot: Vec<SpotWorld>,
    ) -> Self {
        let mut world_light = vec![None; scene_lights];
        for (index, &scene_index) in world.light_scene_index.iter().enumerate() {
            world_light[scene_index] = Some(index);
        }
        let objects = without.len();
        // Scene order is kept, so a scene object's world objects are consecutive.
        let index = &world.object_scene_index;
        let world_objects = (0..objects)
            .map(|o| index.partition_point(|&s| s < o)..index.partition_point(|&s| s <= o))
            .collect();
        Self {
            world,
            space: ChannelSpace {
                lights: world.lights.len(),
                objects,
            },
            world_light,
            without,
            world_objects,
            spot,
        }
    }

    /// The index that world object `index` has in the world without scene object
    /// `removed` (`None` for one of the removed object's own).
    #[must_use]
    pub fn index_without(&self, removed: usize, index: usize) -> Option<usize> {
        let gone = &self.world_objects[removed];
        if gone.contains(&index) {
            None
        } else if index >= gone.end {
            Some(index - gone.len())
        } else {
            Some(index)
        }
    }

    /// The material of world object `object`.
    pub(super) fn material(&self, object: usize) -> &'w Material {
        &self.world.materials[self.world.objects[object].material]
    }
}

/// The colour a camera ray `ray` brings back in `world` (one of the changed worlds), as
/// raylab's picture of it would show.
#[must_use]
pub fn trace_again(world: &World, ray: &Ray) -> DVec3 {
    let tracer = Tracer::new(world, TermSwitches::ALL_ON, View::Beauty);
    tracer.trace_primary(ray, &mut RayCounts::default(), &mut NoRecorder)
}
