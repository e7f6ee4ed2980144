//! The lighting model of the contract, one ray at a time:
//!
//! ```text
//! colour = sum over ambient lights of ka * L
//!        + sum over other lights l of vis_l * L_l(p) * (kd * max(0, n.l) + ks * max(0, r.v)^s)
//!        + km * colour(reflected ray)          while depth < max_depth
//! ```
//!
//! This file holds the tracer and the mirror chain: a camera ray, then each mirror
//! bounce, followed in a loop so the stack stays the same size at any depth. One ray's
//! terms are in `lighting.rs`, its shadow rays in `shadows.rs`.
//!
//! Work is only done where a term can contribute: no shadow ray for a light behind the
//! surface, outside its spot cone, or for a material with no diffuse and no specular; no
//! mirror ray where km is zero. An optional [`Recorder`] sees every number the shader
//! uses, so the pixel inspector reports this very code path.

use glam::DVec3;

use super::depth_view::DepthRange;
use super::mirror_chain::{Chain, fold_back, returned};
use super::object_id::object_id_colour;
use super::ray_source::{LiveRays, RaySource};
use super::record::Recorder;
use crate::trace::ray::Ray;
use crate::trace::ray_counts::RayCounts;
use crate::trace::terms::{ActiveTerms, TermSwitches, View};
use crate::trace::world::World;

/// Traces rays through a world with a fixed set of switches and view.
#[derive(Clone, Copy, Debug)]
pub struct Tracer<'w> {
    pub(super) world: &'w World,
    /// The terms of camera rays.
    pub(super) primary: ActiveTerms,
    /// The terms of mirror rays (the background shows only to camera rays in a solo).
    pub(super) secondary: ActiveTerms,
    pub(super) view: View,
    /// The depth view's grey scale, found once per render.
    depth_range: Option<DepthRange>,
}

impl<'w> Tracer<'w> {
    /// A tracer for `world`. Solo `shadows` shows the shadow mask.
    #[must_use]
    pub fn new(world: &'w World, switches: TermSwitches, view: View) -> Self {
        let view = switches.shown_view(view);
        Self {
            world,
            primary: switches.primary(),
            secondary: switches.secondary(),
            view,
            depth_range: (view == View::Depth)
                .then(|| DepthRange::visible(world))
                .flatten(),
        }
    }

    /// The world traced.
    #[must_use]
    pub fn world(&self) -> &'w World {
        self.world
    }

    /// The terms of camera rays and of mirror rays, when the view is the lit picture.
    pub(crate) fn beauty_terms(&self) -> Option<(ActiveTerms, ActiveTerms)> {
        (self.view == View::Beauty).then_some((self.primary, self.secondary))
    }

    /// The colour of a camera ray, unclamped, as the view asks for it.
    pub fn trace_primary<R: Recorder>(
        &self,
        ray: &Ray,
        counts: &mut RayCounts,
        recorder: &mut R,
    ) -> DVec3 {
        self.trace_primary_from(ray, &mut LiveRays::all(), counts, recorder)
    }

    /// As [`Self::trace_primary`], each ray answered by `rays` (the world itself, or a
    /// cache of rays traced before: the shading arithmetic is the same).
    pub fn trace_primary_from<S: RaySource, R: Recorder>(
        &self,
        ray: &Ray,
        rays: &mut S,
        counts: &mut RayCounts,
        recorder: &mut R,
    ) -> DVec3 {
        counts.primary += 1;
        if self.view == View::Beauty {
            return self.radiance(ray, rays, counts, recorder);
        }
        let Some(hit) = rays.closest_hit(self.world, 0, ray) else {
            return DVec3::ZERO;
        };
        match self.view {
            View::Normal => hit.n * 0.5 + 0.5,
            View::Depth => DVec3::splat(self.depth_range.map_or(1.0, |range| range.grey(hit.t))),
            View::ObjectId => object_id_colour(self.world.scene_object(hit.object)),
            View::ShadowMask => DVec3::splat(self.shadow_mask(&hit, rays, counts)),
            View::Beauty => unreachable!("handled above"),
        }
    }

    /// The lit colour of a camera ray and its chain of mirror bounces.
    ///
    /// A loop, not a recursion, so any `max_depth` runs in constant stack: the chain is
    /// walked forward, keeping each ray's local colour and mirror weight, then folded back
    /// from the deepest ray as `colour(d) = local(d) + km(d) * colour(d + 1)` (as the
    /// scene's conventions combine and clamp). That is the same arithmetic, and the same
    /// recorder calls in the same order, as the recursive form (a ray's `reflection` and
    /// `result` after everything deeper).
    fn radiance(
        &self,
        ray: &Ray,
        rays: &mut impl RaySource,
        counts: &mut RayCounts,
        recorder: &mut impl Recorder,
    ) -> DVec3 {
        let (camera_bounce, mirror_ray) = self.shade(ray, 0, &self.primary, rays, counts, recorder);
        // Most camera rays meet no mirror: no chain to keep.
        let conventions = &self.world.conventions;
        let Some(mut ray) = mirror_ray else {
            return returned(0, &camera_bounce, None, conventions, recorder);
        };
        let mut chain = Chain::new();
        chain.push(camera_bounce);
        loop {
            let depth = chain.len() as u32;
            let (bounce, mirror_ray) =
                self.shade(&ray, depth, &self.secondary, rays, counts, recorder);
            chain.push(bounce);
            match mirror_ray {
                Some(next) => ray = next,
                None => break,
            }
        }
        fold_back(&chain, conventions, recorder)
    }
}
