//! A plain render's batch (one sample of every pixel of a tile), traced depth by depth
//! instead of one pixel's whole path at a time: the closest hits of all the tile's
//! camera rays at once ([`World::intersect_batch`]: the tile's objects outer, its rays
//! inner), then each pixel shaded from its hit by the shader's own code (lights and
//! shadow rays as before); then the mirror and transmitted rays that shading cast, the
//! same way, and so on down the trees, which are folded back at the end. Each batch answer is the single
//! query's bit for bit, so the colours are the pixel-by-pixel path's (tested below).
//!
//! The batches run more instructions (their bookkeeping), yet the frame is faster: an
//! object's test over neighbouring rays branches alike. Staging each light's samples and
//! shadow rays the same way lost more to the bookkeeping than it gained, and so did SIMD
//! lanes for the batches' tests (docs/PERFORMANCE_HISTORY.md, "tiles traced depth by depth").

use glam::{DVec2, DVec3};

use super::samples::{camera_sample, sample_point};
use super::spawn_filter::{SpawnFilter, TraceAll};
use super::tile_shadows::TileShadows;
use crate::trace::cull::{Candidates, TileCull};
use crate::trace::film::{PinholeCamera, RenderOptions, TileRect};
use crate::trace::ray::Ray;
use crate::trace::ray_counts::RayCounts;
use crate::trace::shade::{
    Bounce, Branch, BroughtBack, LiveRays, MakeRay, NoRecorder, RayAt, RaySource, ShadowRequest,
    Tracer,
};
use crate::trace::terms::ActiveTerms;
use crate::trace::world::{ObjectSet, SurfacePoint, World};

/// One depth of a tile's ray trees.
struct Level {
    /// Per ray below the camera rays: its parent's slot in the level before, and which of
    /// the parent's rays it is (empty for the camera rays).
    parents: Vec<(usize, Branch)>,
    /// What each ray adds.
    bounces: Vec<Bounce>,
    /// The rays of this level whose mirror or transmitted ray was left out
    /// ([`SpawnFilter`]): they fold back as if it had returned black.
    left_out: Vec<(usize, Branch)>,
}

/// Answers the closest hit of the ray at `depth` from the batch that found it, every
/// other ray live, and the shadow rays through the batch's [`TileShadows`]. One per
/// batch, told each ray in turn ([`Self::answer`]).
struct KnownHit<'c> {
    depth: u32,
    ray: Ray,
    hit: Option<SurfacePoint>,
    live: LiveRays<'c>,
    shadows: TileShadows<'c>,
}

impl<'c> KnownHit<'c> {
    /// A batch's source, the rays asked of the world among `among`, the tile's culled
    /// sets (as [`LiveRays`] would for any of its pixels), in a world of `lights` lights.
    fn new(among: Candidates<'c>, lights: usize) -> Self {
        Self {
            depth: 0,
            ray: Ray::new(glam::DVec3::ZERO, glam::DVec3::ZERO),
            hit: None,
            live: LiveRays::among(among),
            shadows: TileShadows::new(among, lights),
        }
    }

    /// From now on `hit` is the answer for `ray` at `depth`.
    fn answer(&mut self, depth: u32, ray: Ray, hit: Option<SurfacePoint>) -> &mut Self {
        (self.depth, self.ray, self.hit) = (depth, ray, hit);
        self
    }
}

impl RaySource for KnownHit<'_> {
    #[inline]
    fn closest_hit(&mut self, world: &World, at: RayAt, ray: &Ray) -> Option<SurfacePoint> {
        if at.depth == self.depth {
            debug_assert_eq!(*ray, self.ray, "the batch's hit is this ray's");
            self.hit
        } else {
            self.live.closest_hit(world, at, ray)
        }
    }

    #[inline]
    fn occluder(&mut self, world: &World, to: ShadowRequest, ray: impl MakeRay) -> Option<usize> {
        self.shadows.occluder(world, to, ray)
    }
}

/// What a render's tiles share: its camera, shader and culled sets, and where its samples
/// fall; the full render and the pruned one trace through the same one.
pub(crate) struct TilePass<'w> {
    tracer: Tracer<'w>,
    camera: PinholeCamera,
    cull: TileCull,
    /// The pixel's sample count (where its samples fall).
    count: u32,
}

impl<'w> TilePass<'w> {
    /// The pass of a render of `options` (size, sample count, switches and view) of `world`.
    pub fn new(world: &'w World, options: &RenderOptions) -> Self {
        let (width, height) = (options.width, options.height);
        let camera = PinholeCamera::new(&world.camera, width, height);
        Self {
            tracer: Tracer::new(world, options.switches, options.view),
            cull: TileCull::new(world, &camera, width, height),
            camera,
            count: options.samples_per_pixel,
        }
    }

    /// Sample `index` of pixel `(px, py)` traced alone, its whole tree: the path of the
    /// pixels a tile batch does not take, and of the pixels traced again in full.
    pub fn sample(&self, px: u32, py: u32, index: u32, rays: &mut RayCounts) -> DVec3 {
        let point = sample_point(px, py, index, self.count);
        let mut live = LiveRays::among(self.cull.candidates(point));
        camera_sample(&self.tracer, &self.camera, point, &mut live, rays)
    }

    /// Sample `index` of every pixel of `rect` (row-major) and the rays traced, or `None`
    /// where the samples do not share one culled set (then they go pixel by pixel).
    pub fn tile(&self, rect: TileRect, index: u32) -> Option<(Vec<DVec3>, RayCounts)> {
        self.tile_with(rect, index, &mut TraceAll)
    }

    /// As [`Self::tile`], the rays below the camera rays traced only where `filter`
    /// keeps them.
    pub fn tile_with(
        &self,
        rect: TileRect,
        index: u32,
        filter: &mut impl SpawnFilter,
    ) -> Option<(Vec<DVec3>, RayCounts)> {
        let points: Vec<DVec2> = (rect.y0..rect.y0 + rect.h)
            .flat_map(|py| (rect.x0..rect.x0 + rect.w).map(move |px| (px, py)))
            .map(|(px, py)| sample_point(px, py, index, self.count))
            .collect();
        let among = self.cull.candidates(*points.first()?);
        let lights = self.tracer.world().lights.len();
        let same = |other: Candidates| {
            other.camera == among.camera && (0..lights).all(|l| other.shadow(l) == among.shadow(l))
        };
        if !points
            .iter()
            .all(|&point| same(self.cull.candidates(point)))
        {
            return None;
        }
        let rays: Vec<Ray> = points.iter().map(|&point| self.camera.ray(point)).collect();
        let mut counts = RayCounts::default();
        let colours = match self.tracer.beauty_terms() {
            Some(terms) => self.lit(rays, among, terms, filter, &mut counts),
            None => self.view(&points, rays, among, &mut counts),
        };
        Some((colours, counts))
    }

    /// The lit picture: each depth of the tile's ray trees found and shaded, the trees
    /// folded back as [`Tracer::trace_primary_from`] folds one.
    fn lit(
        &self,
        rays: Vec<Ray>,
        among: Candidates,
        (primary, secondary): (ActiveTerms, ActiveTerms),
        filter: &mut impl SpawnFilter,
        counts: &mut RayCounts,
    ) -> Vec<DVec3> {
        let world = self.tracer.world();
        let count = rays.len();
        counts.primary += count as u64;
        filter.camera_rays(count);
        // Per depth, what each ray adds and (below the camera rays, which are the pixels
        // in order) its parent's slot in the level before and which of its rays it is.
        let mut levels: Vec<Level> = Vec::new();
        let mut parents: Vec<(usize, Branch)> = Vec::new();
        let mut rays = rays;
        let mut depth = 0;
        let mut source = KnownHit::new(among, world.lights.len());
        while !rays.is_empty() {
            // As `LiveRays`: camera rays test the tile's culled set, the others all.
            let (terms, objects) = if depth == 0 {
                (&primary, among.camera)
            } else {
                (&secondary, ObjectSet::ALL)
            };
            let hits = world.intersect_batch(&rays, objects);
            let mut bounces = Vec::with_capacity(rays.len());
            let (mut next_parents, mut next_rays) = (Vec::new(), Vec::new());
            let mut left_out = Vec::new();
            for (slot, (ray, hit)) in rays.iter().zip(hits).enumerate() {
                let source = source.answer(depth, *ray, hit);
                // No recorder and no cache here: only the depth is needed, not the
                // ray's place in its tree.
                let at = RayAt {
                    depth,
                    node: 0,
                    from: None,
                };
                let (bounce, spawned) =
                    self.tracer
                        .shade(ray, at, terms, source, counts, &mut NoRecorder);
                // `shade` counted the rays it started; one left out is never cast.
                if let Some(mirror) = spawned.mirror {
                    if filter.keep(slot, depth + 1, bounce.km) {
                        next_parents.push((slot, Branch::Mirror));
                        next_rays.push(mirror);
                    } else {
                        counts.reflection -= 1;
                        left_out.push((slot, Branch::Mirror));
                    }
                }
                if let Some((transmitted, branch)) = spawned.transmitted {
                    if filter.keep(slot, depth + 1, bounce.kt) {
                        next_parents.push((slot, branch));
                        next_rays.push(transmitted);
                    } else {
                        counts.transmission -= 1;
                        left_out.push((slot, branch));
                    }
                }
                bounces.push(bounce);
            }
            levels.push(Level {
                parents,
                bounces,
                left_out,
            });
            filter.next_level();
            (parents, rays) = (next_parents, next_rays);
            depth += 1;
        }
        // Deepest first, through the shader's own step (`Bounce::returns`): each ray's
        // colour goes to its parent's slot; the camera rays' colours are the pixels'.
        let conventions = &world.conventions;
        let mut brought_back: Vec<BroughtBack> = Vec::new();
        let returns = |brought_back: &[BroughtBack], slot: usize, bounce: &Bounce| {
            let own = brought_back.get(slot).copied().unwrap_or_default();
            bounce.returns(own, conventions)
        };
        for (index, level) in levels.iter().enumerate().rev() {
            // A ray left out returned black: its parent still blends with it.
            if !level.left_out.is_empty() {
                brought_back.resize(level.bounces.len(), BroughtBack::default());
                for &(slot, branch) in &level.left_out {
                    let black = Some(DVec3::ZERO);
                    if branch.is_transmitted() {
                        brought_back[slot].transmitted = black;
                    } else {
                        brought_back[slot].reflected = black;
                    }
                }
            }
            if index == 0 {
                break;
            }
            let mut up = vec![BroughtBack::default(); levels[index - 1].bounces.len()];
            for (slot, (bounce, &(parent, branch))) in
                level.bounces.iter().zip(&level.parents).enumerate()
            {
                let colour = Some(returns(&brought_back, slot, bounce));
                if branch.is_transmitted() {
                    up[parent].transmitted = colour;
                } else {
                    up[parent].reflected = colour;
                }
            }
            brought_back = up;
        }
        let camera_rays = levels.first().map_or(&[][..], |level| &level.bounces[..]);
        (0..count)
            .map(|pixel| returns(&brought_back, pixel, &camera_rays[pixel]))
            .collect()
    }

    /// A debug view: the camera rays' hits found at once, each pixel's view from its hit.
    fn view(
        &self,
        points: &[DVec2],
        rays: Vec<Ray>,
        among: Candidates,
        counts: &mut RayCounts,
    ) -> Vec<DVec3> {
        let world = self.tracer.world();
        let hits = world.intersect_batch(&rays, among.camera);
        let mut source = KnownHit::new(among, world.lights.len());
        points
            .iter()
            .zip(rays)
            .zip(hits)
            .map(|((&point, ray), hit)| {
                let source = source.answer(0, ray, hit);
                camera_sample(&self.tracer, &self.camera, point, source, counts)
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::examples::EXAMPLE_SCENES;
    use crate::trace::film::RenderProgress;
    use crate::trace::render::{render_samples, render_samples_into};
    use crate::trace::terms::{Term, TermSwitches, View};

    /// Batches (tile by tile) against each pixel traced alone, with the same culling,
    /// for every example scene, view and a solo switch: a one-sample pass, and samples
    /// summed onto sums from before.
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
                // One batch alone (a one-sample pass), then two summed after a first.
                let one = render_samples(&world, &options, 1..2, &progress).unwrap();
                let mut three = render_samples(&world, &options, 0..1, &progress).unwrap();
                render_samples_into(&world, &options, 1..3, &mut three, &progress).unwrap();
                let pass = TilePass::new(&world, &options);
                let mut rays = [RayCounts::default(), RayCounts::default()];
                for (i, (one, three)) in one.sums.iter().zip(&three.sums).enumerate() {
                    let (px, py) = (i as u32 % 53, i as u32 / 53);
                    let mut sum = DVec3::ZERO;
                    for index in 0..3 {
                        let counts = &mut rays[usize::from(index == 1)];
                        let alone = pass.sample(px, py, index, counts);
                        if index == 1 {
                            assert_eq!(*one, alone, "{name} {view:?} pixel ({px}, {py})");
                        }
                        sum += alone;
                    }
                    assert_eq!(*three, sum, "{name} {view:?} pixel ({px}, {py}), 3 samples");
                }
                assert_eq!(one.rays, rays[1], "{name} {view:?}: the same rays counted");
                let mut all = rays[0];
                all.add(&rays[1]);
                assert_eq!(three.rays, all, "{name} {view:?}: the same rays, 3 samples");
            }
        }
    }
}
