//! Shadow rays: which object a shadow ray cannot meet, the ray itself (spawned once, in
//! `world::spawn`), the object blocking it as the ray source answers, and the shadow-mask
//! view (the fraction of reaching lights whose shadow ray is clear).

use super::ray_source::{RaySource, ShadowQuery, ShadowRequest};
use super::tracer::Tracer;
use crate::trace::ray_counts::RayCounts;
use crate::trace::shapes::Primitive;
use crate::trace::world::{LightSample, SurfacePoint, spawn_ray, spawn_ray_to};

/// Which light a shadow ray goes to, from the hit at which depth of the mirror chain.
#[derive(Clone, Copy, Debug)]
pub(super) struct LightAt {
    pub depth: u32,
    pub index: usize,
}

impl Tracer<'_> {
    /// The object blocking the shadow ray from `hit` (at `to.depth`) to light
    /// `to.index`, if any. The ray itself is made only if `rays` has to cast it.
    #[inline]
    pub(super) fn shadow_blocker(
        &self,
        hit: &SurfacePoint,
        sample: &LightSample,
        to: LightAt,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
    ) -> Option<usize> {
        counts.shadow += 1;
        let except = self.shadow_except(hit, sample);
        let target = ShadowRequest {
            depth: to.depth,
            light: to.index,
            except,
        };
        rays.occluder(self.world, target, || self.shadow_query(hit, sample))
    }

    /// The object a shadow ray from `hit` to the light of `sample` cannot meet: every
    /// shape is convex or flat, so a shadow ray leaving a solid on its outer side, or
    /// leaving a plane, cannot meet the surface it starts on.
    #[inline]
    fn shadow_except(&self, hit: &SurfacePoint, sample: &LightSample) -> Option<usize> {
        let object = &self.world.objects[hit.object];
        let leaves_outward = !object.can_meet_itself()
            && (object.shape == Primitive::Plane || hit.n_outward.dot(sample.to_light) > 0.0);
        leaves_outward.then_some(hit.object)
    }

    /// The shadow ray from `hit` to the light of `sample`.
    #[inline]
    pub(super) fn shadow_query(&self, hit: &SurfacePoint, sample: &LightSample) -> ShadowQuery {
        let (ray, t_max) = match sample.light_position {
            Some(position) => spawn_ray_to(hit, position),
            None => (spawn_ray(hit, sample.to_light), f64::INFINITY),
        };
        ShadowQuery { ray, t_max }
    }

    /// Fraction of the lights that reach `hit` (in front, inside any spot cone) whose
    /// shadow ray is clear; 0 where no light reaches.
    pub(super) fn shadow_mask(
        &self,
        hit: &SurfacePoint,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
    ) -> f64 {
        let mut reaching = 0u32;
        let mut visible = 0u32;
        for (index, light) in self.world.lights.iter().enumerate() {
            let Some(sample) = light.sample(hit.p) else {
                continue;
            };
            if hit.n.dot(sample.to_light) <= 0.0 {
                continue;
            }
            reaching += 1;
            let to = LightAt { depth: 0, index };
            if !self.primary.shadows
                || self
                    .shadow_blocker(hit, &sample, to, rays, counts)
                    .is_none()
            {
                visible += 1;
            }
        }
        if reaching == 0 {
            0.0
        } else {
            f64::from(visible) / f64::from(reaching)
        }
    }
}
