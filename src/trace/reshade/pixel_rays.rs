//! [`PixelRays`], the [`RaySource`] that answers a pixel's rays from its tile's cached
//! chains and light slots (`super::tile_rays`) and traces (and keeps) whatever they lack.

use super::chains::{
    CachedHit, NOT_CAST, decode_blocker, decode_sphere, encode_blocker, encode_sphere,
};
use super::light_factors::LightSlot;
use super::tile_rays::TileRays;
use crate::trace::ray::Ray;
use crate::trace::shade::{LitFactors, LiveRays, MakeRay, RaySource, ShadowRequest};
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
    fn closest_hit(&mut self, world: &World, depth: u32, ray: &Ray) -> Option<SurfacePoint> {
        let chain = self.tile.chain();
        let depth = depth as usize;
        let lights = self.tile.lights;
        if depth < chain.len() {
            let entry = chain.start + depth;
            let hit = match &self.tile.grown {
                Some((chains, _)) => chains.hit(entry),
                None => self.tile.chains.hit(entry),
            };
            let hit = hit.point();
            if hit.is_some_and(|h| self.stale_lobes.get(h.object).copied().unwrap_or(false)) {
                for slot in entry * lights..(entry + 1) * lights {
                    self.tile.slot_mut(slot).factors = LitFactors::UNKNOWN;
                }
            }
            return hit;
        }
        // The chain is walked depth by depth: the missing entry is the next one.
        debug_assert_eq!(depth, chain.len());
        if depth == 0 {
            self.tile.traced.primary += 1;
        } else {
            self.tile.traced.reflection += 1;
        }
        let hit = self.live.closest_hit(world, depth as u32, ray);
        let (chains, slots) = self.tile.grow();
        chains.push(CachedHit::new(hit.as_ref()));
        slots.resize(slots.len() + lights, LightSlot::NOTHING);
        hit
    }

    fn occluder(&mut self, world: &World, to: ShadowRequest, ray: impl MakeRay) -> Option<usize> {
        // One of a sphere light's rays: the slot keeps their count, not each answer.
        if to.off_centre {
            self.tile.traced.shadow += 1;
            return self.live.occluder(world, to, ray);
        }
        let slot = self.tile.slot_index(to.depth, to.light);
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
        depth: u32,
        light: usize,
        cast: impl FnOnce(&mut Self) -> (u32, Option<usize>),
    ) -> (u32, Option<usize>) {
        let slot = self.tile.slot_index(depth, light);
        if let Some((clear, _)) = decode_sphere(self.tile.slot(slot).shadow) {
            return (clear, None);
        }
        let before = self.tile.traced.shadow;
        let (clear, blocker) = cast(self);
        // Each of the light's rays went through `occluder`, which counted it.
        let rays = u32::try_from(self.tile.traced.shadow - before).expect("a light's rays");
        self.tile.slot_mut(slot).shadow = encode_sphere(clear, rays);
        (clear, blocker)
    }

    /// Factors kept are valid (those of a stale lobe or a light placed anew were
    /// forgotten): only unknown ones are worked out and kept.
    fn keep_light_factors(
        &mut self,
        depth: u32,
        light: usize,
        factors: impl FnOnce() -> LitFactors,
    ) {
        let slot = self.tile.slot_index(depth, light);
        let kept = self.tile.slot(slot).factors;
        if kept.is_unknown() {
            self.tile.slot_mut(slot).factors = factors();
        }
    }
}
