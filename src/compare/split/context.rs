//! What the recorder ([`super::recorder::SampleRecorder`]) needs to know about the world, prepared once
//! per comparison: the channel numbering, where each scene light is among the world's,
//! and the changed worlds it traces again (without a tree node, with a spot light's
//! cone bug).

use crate::compare::catalogue::{ChannelSpace, MissingNodes, Nodes, SpotWorld};
use crate::scene::Material;
use crate::trace::World;

/// What the recorder needs to know about the world, prepared once.
pub struct Context<'w> {
    /// The world traced.
    pub world: &'w World,
    /// The channel numbering.
    pub space: ChannelSpace,
    /// For each scene light index, its index among the world's non-ambient lights.
    pub world_light: Vec<Option<usize>>,
    /// The nodes of the scene's trees: channels are per leaf.
    pub nodes: &'w Nodes,
    /// The nodes tried as missing, each with the world without it, to see what a ray
    /// would meet if the node were missing.
    pub missing: MissingNodes,
    /// The worlds of the spot lights' cone bugs.
    pub spot: Vec<SpotWorld>,
    /// Per world of [`Self::spot`]: whether it is `world` with only its spot light
    /// changed (the same other lights, ambient and spheres), so that a camera ray whose
    /// hits all get the same sample of that light there brings back the same colour.
    pub spot_alike: Vec<bool>,
}

impl<'w> Context<'w> {
    /// The context of `world` with `scene_lights` lights in the scene's list, channels
    /// per leaf of `nodes`, the nodes `missing` tried as missing, and `spot` the worlds
    /// of the spot lights' cone bugs.
    #[must_use]
    pub fn new(
        world: &'w World,
        scene_lights: usize,
        nodes: &'w Nodes,
        missing: MissingNodes,
        spot: Vec<SpotWorld>,
    ) -> Self {
        let mut world_light = vec![None; scene_lights];
        for (index, &scene_index) in world.light_scene_index.iter().enumerate() {
            world_light[scene_index] = Some(index);
        }
        let spot_alike = spot
            .iter()
            .map(|w| {
                let (changed, light) = (&w.world, w.light);
                changed.lights.len() == world.lights.len()
                    && changed.ambient == world.ambient
                    && changed.light_spheres == world.light_spheres
                    && (0..world.lights.len())
                        .all(|i| i == light || changed.lights[i] == world.lights[i])
            })
            .collect();
        Self {
            world,
            space: ChannelSpace {
                lights: world.lights.len(),
                objects: nodes.leaves.len(),
                nodes: missing.inner_slots(),
            },
            world_light,
            nodes,
            missing,
            spot,
            spot_alike,
        }
    }

    /// The material of world object `object`.
    pub(super) fn material(&self, object: usize) -> &'w Material {
        &self.world.materials[self.world.objects[object].material]
    }
}
