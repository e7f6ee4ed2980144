//! What the recorder adds for the objects that might be missing: each ray traced again
//! in the world without the object it hit, and the light the object's shadows take
//! away where no other object blocks it (the shadow ray cast again without it).

use glam::DVec3;

use super::{Bounce, SampleRecorder};
use crate::compare::bugs::Part;
use crate::compare::channels::Kind;
use crate::compare::components::MISS;
use crate::compare::record_context::trace_again;
use crate::trace::shapes::Primitive;
use crate::trace::{LightRecord, LightSample, SurfacePoint};

impl SampleRecorder<'_, '_> {
    /// What the ray of `bounce` would return if the object it hit were missing (traced
    /// again in the world without it), as a change of the pixel; for the camera ray
    /// (`primary`), also the scene object it would meet then ([`Self::behind`]).
    pub(super) fn missing(&mut self, bounce: &Bounce, colour: DVec3, primary: bool) {
        let Some(hit) = bounce.hit else { return };
        let Some(Some(world)) = self.ctx.without.get(hit.object) else {
            return;
        };
        if primary {
            // The world without scene object o numbers the later objects one less.
            let removed = hit.object;
            self.behind = world
                .intersect(&bounce.ray, f64::INFINITY)
                .map_or(MISS, |h| {
                    let s = world.scene_object(h.object);
                    (if s >= removed { s + 1 } else { s }) as u32
                });
        }
        let seen = trace_again(world, &bounce.ray);
        if seen.is_finite()
            && let Some(world_object) = bounce.world_object
        {
            // A group is missing whole: its members' parts are not the object's.
            let part = if self.ctx.world_objects[hit.object].len() == 1 {
                Part::at(&self.ctx.world.objects[world_object], &hit, bounce.ray_dir)
            } else {
                Part::Whole
            };
            let channel = self.channel(Kind::Missing(part), hit.object);
            self.tally.add(channel, bounce.throughput * (seen - colour));
        }
    }

    /// Where one object's shadow hides a light from the point `hit` (of world object
    /// `world_object`), the light `unshadowed` it would add were that object missing:
    /// when the shadow ray, cast again in the world without it, is clear.
    pub(super) fn shadow_cast(
        &mut self,
        record: &LightRecord,
        hit: &SurfacePoint,
        sample: &LightSample,
        world_object: usize,
        unshadowed: DVec3,
    ) {
        let (Some(blocker), Some(shadow)) = (record.blocked_by, record.shadow_ray) else {
            return;
        };
        // An object shadowing itself: its own pixels are its missing picture already.
        let Some(Some(without)) = self
            .ctx
            .without
            .get(blocker)
            .filter(|_| blocker != hit.object)
        else {
            return;
        };
        // The shader's rule: a ray leaving a convex solid or a plane outward cannot meet
        // the surface it starts on.
        let object = &self.ctx.world.objects[world_object];
        let leaves_outward = !object.can_meet_itself()
            && (object.shape == Primitive::Plane || hit.n_outward.dot(sample.to_light) > 0.0);
        let except = self
            .ctx
            .index_without(blocker, world_object)
            .filter(|_| leaves_outward);
        if without
            .occluder_except(&shadow.ray, shadow.t_max, except)
            .is_none()
        {
            let channel = self.channel(Kind::ShadowCast, blocker);
            self.tally.add(channel, unshadowed);
        }
    }
}
