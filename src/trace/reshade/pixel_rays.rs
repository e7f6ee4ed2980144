//! [`PixelRays`], the [`RaySource`] that answers a pixel's rays from its tile's cached
//! entries and light slots (`super::tile_rays`) and traces (and keeps) whatever they lack.

use super::cached_hit::{
    CachedHit, NOT_CAST, decode_blocker, decode_sphere, encode_blocker, encode_sphere,
};
use super::tile_rays::TileRays;
use crate::trace::ray::Ray;
use crate::trace::shade::{LitFactors, LiveRays, MakeRay, RayAt, RaySource, ShadowRequest};
use crate::trace::world::{SurfacePoint, World};

/// Answers one pixel's rays from its tile, tracing (and keeping) whatever it lacks, and
/// keeps what each light gives each hit.
pub(crate) struct PixelRays<'t, 'c, 's> {
    pub tile: &'t mut TileRays,
    /// What traces the rays the cache lacks (culled for the camera ray's tile).
    pub live: LiveRays<'c>,
    /// Per object, whether the light factors kept for its hits have a stale lobe: they
    /// are forgotten as the shader reaches the hit, and worked out again where it can.
    pub stale_lobes: &'s [bool],
}

impl RaySource for PixelRays<'_, '_, '_> {
    fn closest_hit(&mut self, world: &World, at: RayAt, ray: &Ray) -> Option<SurfacePoint> {
        let lights = self.tile.lights;
        if let Some(entry) = self.tile.entry_for(at) {
            let hit = self.tile.hit(entry).point();
            if hit.is_some_and(|h| self.stale_lobes.get(h.object).copied().unwrap_or(false)) {
                for slot in entry * lights..(entry + 1) * lights {
                    self.tile.slot_mut(slot).factors = LitFactors::UNKNOWN;
                }
            }
            return hit;
        }
        let traced = &mut self.tile.traced;
        match at.from {
            None => traced.primary += 1,
            Some((_, branch)) if branch.is_transmitted() => traced.transmission += 1,
            Some(_) => traced.reflection += 1,
        }
        let hit = self.live.closest_hit(world, at, ray);
        self.tile.push_entry(at, CachedHit::new(hit.as_ref()));
        hit
    }

    fn occluder(&mut self, world: &World, to: ShadowRequest, ray: impl MakeRay) -> Option<usize> {
        // One of a sphere light's rays: the slot keeps their count, not each answer (and
        // `sphere_rays_clear` counts them as traced).
        if to.off_centre {
            return self.live.occluder(world, to, ray);
        }
        let slot = self.tile.slot_index(to.node, to.light);
        let code = self.tile.slot(slot).shadow;
        if code != NOT_CAST {
            return decode_blocker(code);
        }
        self.tile.traced.shadow += 1;
        let blocked_by = self.live.occluder(world, to, ray);
        self.tile.slot_mut(slot).shadow = encode_blocker(blocked_by);
        blocked_by
    }

    /// A sphere light's count kept is valid (the column of a light placed anew, or made
    /// another size, was forgotten): only a missing one is cast and kept.
    fn sphere_rays_clear(
        &mut self,
        node: u32,
        light: usize,
        samples: u32,
        cast: impl FnOnce(&mut Self) -> (u32, Option<usize>),
    ) -> (u32, Option<usize>) {
        let slot = self.tile.slot_index(node, light);
        if let Some((clear, _)) = decode_sphere(self.tile.slot(slot).shadow) {
            return (clear, None);
        }
        let (clear, blocker) = cast(self);
        // Every ray counts as traced, those the point's cone found clear without casting
        // them too (as the render's own counts do).
        self.tile.traced.shadow += u64::from(samples);
        self.tile.slot_mut(slot).shadow = encode_sphere(clear, samples);
        (clear, blocker)
    }

    /// Factors kept are valid (those of a stale lobe or a light placed anew were
    /// forgotten): only unknown ones are worked out and kept.
    fn keep_light_factors(
        &mut self,
        node: u32,
        light: usize,
        factors: impl FnOnce() -> LitFactors,
    ) {
        let slot = self.tile.slot_index(node, light);
        let kept = self.tile.slot(slot).factors;
        if kept.is_unknown() {
            self.tile.slot_mut(slot).factors = factors();
        }
    }
}
