//! A plain render's one-sample pass over a tile with its camera rays' closest hits found
//! at once ([`World::intersect_batch`]: the tile's objects outer, its rays inner), then
//! each pixel shaded as before from its known first hit. Each batch answer is the single
//! query's bit for bit, so the colours are the pixel-by-pixel path's (tested below).
//!
//! The first stage of tracing a tile's rays together rather than one pixel's whole path
//! at a time. It runs more instructions (the batch's bookkeeping), yet the frame is
//! faster: an object's test over neighbouring rays branches alike. Casting the first
//! shadow rays the same way was tried and lost that gain, since each light had to be
//! sampled twice (docs/BENCHMARKS.md).

use glam::{DVec2, DVec3};

use super::camera::PinholeCamera;
use super::ray::Ray;
use super::ray_source::{LiveRays, RaySource, ShadowQuery};
use super::render::{camera_sample, sample_point};
use super::shade::{RayCounts, Tracer};
use super::tile_cull::TileCull;
use super::tiles::TileRect;
use super::world::{SurfacePoint, World};

/// Answers the camera ray from the hit the tile found, every other ray live.
struct FirstHitKnown<'c> {
    camera_ray: Ray,
    first: Option<SurfacePoint>,
    live: LiveRays<'c>,
}

impl RaySource for FirstHitKnown<'_> {
    #[inline]
    fn closest_hit(&mut self, world: &World, depth: u32, ray: &Ray) -> Option<SurfacePoint> {
        if depth == 0 {
            debug_assert_eq!(*ray, self.camera_ray, "the first hit is this ray's");
            self.first
        } else {
            self.live.closest_hit(world, depth, ray)
        }
    }

    #[inline]
    fn occluder(
        &mut self,
        world: &World,
        depth: u32,
        light: usize,
        query: impl FnOnce() -> ShadowQuery,
    ) -> Option<usize> {
        self.live.occluder(world, depth, light, query)
    }
}

/// What a plain render's tiles share.
pub(super) struct TilePass<'a> {
    pub tracer: &'a Tracer<'a>,
    pub camera: &'a PinholeCamera,
    pub cull: &'a TileCull,
    /// The one sample's index, and the pixel's sample count it is one of.
    pub index: u32,
    pub count: u32,
}

impl TilePass<'_> {
    /// Every pixel's colour of `rect` (row-major) and the rays traced, or `None` where
    /// the tile's camera rays do not share one culled set (then it goes pixel by pixel).
    pub fn tile(&self, rect: TileRect) -> Option<(Vec<DVec3>, RayCounts)> {
        let points: Vec<DVec2> = (rect.y0..rect.y0 + rect.h)
            .flat_map(|py| (rect.x0..rect.x0 + rect.w).map(move |px| (px, py)))
            .map(|(px, py)| sample_point(px, py, self.index, self.count))
            .collect();
        let among = self.cull.candidates(*points.first()?).camera;
        if points
            .iter()
            .any(|&point| self.cull.candidates(point).camera != among)
        {
            return None;
        }
        let rays: Vec<Ray> = points.iter().map(|&point| self.camera.ray(point)).collect();
        let firsts = self.tracer.world().intersect_batch(&rays, among);
        let mut counts = RayCounts::default();
        let colours = points
            .iter()
            .zip(rays)
            .zip(firsts)
            .map(|((&point, camera_ray), first)| {
                let mut source = FirstHitKnown {
                    camera_ray,
                    first,
                    live: LiveRays::among(self.cull.candidates(point)),
                };
                camera_sample(self.tracer, self.camera, point, &mut source, &mut counts)
            })
            .collect();
        Some((colours, counts))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::examples::EXAMPLE_SCENES;
    use crate::trace::render::{RenderOptions, RenderProgress, render_samples};
    use crate::trace::terms::{Term, TermSwitches, View};

    /// The one-sample pass (tile by tile) against each pixel traced alone, with the
    /// same culling, for every example scene, view and a solo switch.
    #[test]
    fn a_tile_pass_colours_every_pixel_as_the_pixel_by_pixel_path() {
        let solo_specular = TermSwitches::ALL_ON.with_solo(Some(Term::Specular));
        for (name, text) in EXAMPLE_SCENES {
            let scene = crate::scene::parse_scene(text).unwrap();
            let world = World::new(&scene).unwrap();
            let views = [View::Beauty, View::Normal, View::ShadowMask, View::Depth];
            let modes = views
                .map(|view| (TermSwitches::ALL_ON, view))
                .into_iter()
                .chain([(solo_specular, View::Beauty)]);
            for (switches, view) in modes {
                let options = RenderOptions {
                    width: 53,
                    height: 37,
                    samples_per_pixel: 3,
                    switches,
                    view,
                    ..RenderOptions::from_scene(&scene)
                };
                let progress = RenderProgress::default();
                let sums = render_samples(&world, &options, 1..2, &progress).unwrap();
                let camera = PinholeCamera::new(&world.camera, 53, 37);
                let tracer = Tracer::new(&world, switches, view);
                let cull = TileCull::new(&world, &camera, 53, 37);
                let mut rays = RayCounts::default();
                for (i, sum) in sums.sums.iter().enumerate() {
                    let (px, py) = (i as u32 % 53, i as u32 / 53);
                    let point = sample_point(px, py, 1, 3);
                    let mut live = LiveRays::among(cull.candidates(point));
                    let alone = camera_sample(&tracer, &camera, point, &mut live, &mut rays);
                    assert_eq!(*sum, alone, "{name} {view:?} pixel ({px}, {py})");
                }
                assert_eq!(sums.rays, rays, "{name} {view:?}: the same rays counted");
            }
        }
    }
}
