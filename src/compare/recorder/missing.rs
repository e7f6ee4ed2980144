//! What the recorder adds for the tree nodes that might be missing: each ray traced
//! again in the world without each tried node it may show (the nodes on the way down to
//! the leaf it hit, and nodes inside CSG objects whose solid it passes: a cut filled),
//! and the light a node's shadows take away where no other object blocks it (the shadow
//! ray cast again without it).

use glam::DVec3;

use super::{Bounce, SampleRecorder};
use crate::compare::bugs::Part;
use crate::compare::channels::Kind;
use crate::compare::components::MISS;
use crate::compare::missing_nodes::Slot;
use crate::compare::record_context::trace_again;
use crate::trace::shapes::Primitive;
use crate::trace::{LightRecord, LightSample, SurfacePoint};

impl SampleRecorder<'_, '_> {
    /// What the ray of `bounce` would return without each tried node it may show (traced
    /// again in the world without it), as changes of the pixel; for the camera ray
    /// (`primary`), also the scene object it would meet without the one it hit
    /// ([`Self::behind`]).
    pub(super) fn missing(&mut self, bounce: &Bounce, colour: DVec3, primary: bool) {
        let ctx = self.ctx;
        let missing = &ctx.missing;
        let chain: &[usize] = bounce.leaf.map_or(&[], |leaf| &missing.on_chain[leaf]);
        let t_hit = bounce.hit.map_or(f64::INFINITY, |h| h.t);
        let near = missing
            .in_csg
            .iter()
            .copied()
            .filter(|t| !chain.contains(t) && missing.may_change(*t, &bounce.ray, t_hit));
        for t in chain.iter().copied().chain(near) {
            let tried = &missing.tried[t];
            if primary
                && let Some(hit) = bounce.hit
                && ctx.nodes.nodes[tried.tried.node].depth() == 0
                && chain.contains(&t)
            {
                // The world without scene object o numbers the later objects one less.
                let removed = hit.object;
                self.behind = tried
                    .world
                    .intersect(&bounce.ray, f64::INFINITY)
                    .map_or(MISS, |h| {
                        let s = tried.world.scene_object(h.object);
                        (if s >= removed { s + 1 } else { s }) as u32
                    });
            }
            let seen = trace_again(&tried.world, &bounce.ray);
            if !seen.is_finite() {
                continue;
            }
            let channel = match tried.tried.slot {
                Slot::Leaf(leaf) => {
                    let part = self.part_hit(bounce, leaf);
                    self.channel(Kind::Missing(part), leaf)
                }
                Slot::Inner(slot) => ctx.space.id(Kind::NodeMissing, Some(slot)),
            };
            self.tally.add(channel, bounce.throughput * (seen - colour));
        }
    }

    /// The part of leaf `leaf` the ray of `bounce` hit: a world object of its own has
    /// parts (a plane's back, a cylinder's caps); an operand of a CSG object, or a leaf
    /// the ray did not hit, is whole.
    fn part_hit(&self, bounce: &Bounce, leaf: usize) -> Part {
        match (bounce.hit, bounce.world_object) {
            (Some(hit), Some(world_object))
                if bounce.leaf == Some(leaf)
                    && self.ctx.world.objects[world_object].csg.is_none() =>
            {
                Part::at(&self.ctx.world.objects[world_object], &hit, bounce.ray_dir)
            }
            _ => Part::Whole,
        }
    }

    /// Where a node's shadow hides a light from the point `hit` (of world object
    /// `world_object`, leaf `leaf`), the light `unshadowed` it would add were that node
    /// missing: when the shadow ray, cast again in the world without it, is clear.
    pub(super) fn shadow_cast(
        &mut self,
        record: &LightRecord,
        (hit, world_object, leaf): (&SurfacePoint, usize, usize),
        sample: &LightSample,
        unshadowed: DVec3,
    ) {
        let (Some(blocker), Some(shadow)) = (record.blocked_by, record.shadow_ray) else {
            return;
        };
        let ctx = self.ctx;
        // The shader's rule: a ray leaving a convex solid or a plane outward cannot meet
        // the surface it starts on.
        let object = &ctx.world.objects[world_object];
        let leaves_outward = !object.can_meet_itself()
            && (object.shape == Primitive::Plane || hit.n_outward.dot(sample.to_light) > 0.0);
        for &t in &ctx.missing.of_object[blocker] {
            let tried = &ctx.missing.tried[t];
            let node = &ctx.nodes.nodes[tried.tried.node];
            // A node shadowing itself: its own pixels are its missing picture already.
            // A cut filled only adds solid: it clears no shadow. Below the top level,
            // only a shadow ray through the node's box can clear without it.
            if node.leaves.contains(&leaf)
                || !tried.shrinks
                || (node.depth() > 0 && !ctx.missing.may_change(t, &shadow.ray, shadow.t_max))
            {
                continue;
            }
            let except = ctx
                .missing
                .index_without(t, world_object)
                .filter(|_| leaves_outward);
            if tried
                .world
                .occluder_except(&shadow.ray, shadow.t_max, except)
                .is_none()
            {
                let channel = match tried.tried.slot {
                    Slot::Leaf(leaf) => self.channel(Kind::ShadowCast, leaf),
                    Slot::Inner(slot) => ctx.space.id(Kind::NodeShadowCast, Some(slot)),
                };
                self.tally.add(channel, unshadowed);
            }
        }
    }
}
