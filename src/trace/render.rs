//! Whole images: what to render, its progress and cancel flag, and the sums of samples a
//! render adds up (tiles and batches in [`super::tiles`]).

use std::ops::Range;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use glam::{DVec2, DVec3, Vec3};
use rayon::prelude::*;

use super::camera::PinholeCamera;
use super::image::Image;
use super::isolation::assert_compiled_for;
use super::ray_source::{LiveRays, RaySource};
use super::sampling::sample_in_pixel;
use super::shade::{NoRecorder, RayCounts, Tracer};
use super::terms::{Isolation, TermSwitches, View};
use super::tile_cull::TileCull;
use super::tile_pass::TilePass;
use super::tiles::{TileRect, TileWork, render_tiles_with};
use super::world::World;
use crate::scene::Scene;

/// What to render.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RenderOptions {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Anti-aliasing samples per pixel (see [`super::sampling`]).
    pub samples_per_pixel: u32,
    /// Term switches.
    pub switches: TermSwitches,
    /// Beauty or a debug view.
    pub view: View,
    /// Lights muted or solo, objects hidden: the world must be compiled with them
    /// ([`World::isolated`]).
    pub isolation: Isolation,
}

impl RenderOptions {
    /// The scene's own size and samples, everything on.
    #[must_use]
    pub fn from_scene(scene: &Scene) -> Self {
        Self {
            width: scene.camera.width,
            height: scene.camera.height,
            samples_per_pixel: scene.render.samples_per_pixel,
            switches: TermSwitches::ALL_ON,
            view: View::Beauty,
            isolation: Isolation::NONE,
        }
    }
}

/// Shared between a render and whoever watches it: batches of samples done, and a cancel
/// flag. A batch is one sample for every pixel of a tile (see [`render_samples_into`]).
#[derive(Debug, Default)]
pub struct RenderProgress {
    /// Batches finished so far.
    pub batches_done: AtomicUsize,
    /// Batches in the whole render (set when it starts).
    pub batches_total: AtomicUsize,
    /// Set to stop the render before its next batch.
    pub cancel: AtomicBool,
}

impl RenderProgress {
    /// Asks the render to stop.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    /// Whether a stop was asked for.
    #[must_use]
    pub fn is_cancelled(&self) -> bool {
        self.cancel.load(Ordering::Relaxed)
    }

    /// Fraction done, 0 to 1.
    #[must_use]
    pub fn fraction(&self) -> f64 {
        let total = self.batches_total.load(Ordering::Relaxed);
        if total == 0 {
            0.0
        } else {
            self.batches_done.load(Ordering::Relaxed) as f64 / total as f64
        }
    }
}

/// Summed samples of a render pass, not yet divided by the sample count.
#[derive(Clone, Debug)]
pub struct SampleSums {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Sum of the samples of each pixel.
    pub sums: Vec<DVec3>,
    /// Rays cast.
    pub rays: RayCounts,
    /// Samples that came out non-finite and were replaced by black (should stay 0).
    pub non_finite: u64,
    /// Row-major indices (`y * width + x`) of the pixels with at least one non-finite
    /// sample, ascending, each once (should stay empty).
    pub non_finite_pixels: Vec<u32>,
}

/// `pixels` zero sums, cleared in parallel: one thread took a millisecond on an 800x600
/// frame, in which an edit waited for the pass it cancelled.
pub(super) fn cleared(pixels: usize) -> Vec<DVec3> {
    rayon::iter::repeat_n(DVec3::ZERO, pixels).collect()
}

/// As [`cleared`], in parts with a look at the cancel flag between them (`None` once
/// cancelled): a pass that clears its frame first is often cancelled right then, by the
/// edit that follows the frame before it, and that edit would wait for the whole clear
/// (about half a millisecond at 800x600).
pub(super) fn cleared_unless_cancelled(
    pixels: usize,
    progress: &RenderProgress,
) -> Option<Vec<DVec3>> {
    // Parts of at least 64 Ki pixels: a small frame clears at once, as each part
    // costs a round trip through the thread pool.
    let parts = (pixels / 65_536).clamp(1, 8);
    let mut sums = Vec::with_capacity(pixels);
    for part in 0..parts {
        if progress.is_cancelled() {
            return None;
        }
        let end = pixels * (part + 1) / parts;
        sums.par_extend(rayon::iter::repeat_n(DVec3::ZERO, end - sums.len()));
    }
    Some(sums)
}

impl SampleSums {
    /// Sums of no samples yet: black, nothing counted.
    #[must_use]
    pub fn zero(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            sums: cleared(width as usize * height as usize),
            rays: RayCounts::default(),
            non_finite: 0,
            non_finite_pixels: Vec::new(),
        }
    }

    /// Sums of no samples yet, to be made by the first render into them: no pixel held
    /// while that render runs, and none read before its tiles are placed.
    #[must_use]
    pub(super) fn unsummed(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            sums: Vec::new(),
            rays: RayCounts::default(),
            non_finite: 0,
            non_finite_pixels: Vec::new(),
        }
    }

    /// The image these sums make when divided by `count` samples.
    #[must_use]
    pub fn average(&self, count: u32) -> Image {
        let scale = 1.0 / f64::from(count.max(1));
        Image {
            width: self.width,
            height: self.height,
            pixels: self
                .sums
                .par_iter()
                .map(|s| (*s * scale).as_vec3())
                .collect::<Vec<Vec3>>(),
        }
    }
}

/// Renders the samples `samples` (of `options.samples_per_pixel`) of every pixel and
/// returns their sums, or `None` if cancelled.
#[must_use]
pub fn render_samples(
    world: &World,
    options: &RenderOptions,
    samples: Range<u32>,
    progress: &RenderProgress,
) -> Option<SampleSums> {
    let mut sums = SampleSums::unsummed(options.width, options.height);
    render_samples_into(world, options, samples, &mut sums, progress)?;
    Some(sums)
}

/// Continues `sums` with the samples `samples` (of `options.samples_per_pixel`): each
/// pixel's sum goes on adding its samples in index order, so rendering `0..4` then `4..8`
/// gives exactly the numbers of `0..8` at once. Returns the rays of this batch (they are
/// also added to `sums.rays`), or `None` if cancelled, leaving `sums` untouched. A cancel
/// stops every tile within one batch (one sample for each of its pixels).
///
/// # Panics
/// When `sums` is not `options.width` x `options.height`, or `world` was compiled for
/// other isolation switches than `options.isolation`.
pub fn render_samples_into(
    world: &World,
    options: &RenderOptions,
    samples: Range<u32>,
    sums: &mut SampleSums,
    progress: &RenderProgress,
) -> Option<RayCounts> {
    let (width, height) = (options.width, options.height);
    assert_eq!(
        (sums.width, sums.height),
        (width, height),
        "sums of another size"
    );
    assert_compiled_for(world, &options.isolation);
    if progress.is_cancelled() {
        // Not even the culling set up (half a millisecond at 800x600).
        return None;
    }
    let camera = PinholeCamera::new(&world.camera, width, height);
    let tracer = Tracer::new(world, options.switches, options.view);
    let count = options.samples_per_pixel;
    let cull = TileCull::new(world, &camera, width, height);
    let sample = |_: &mut TileRect, px: u32, py: u32, index: u32, rays: &mut RayCounts| {
        let point = sample_point(px, py, index, count);
        camera_sample(
            &tracer,
            &camera,
            point,
            &mut LiveRays::among(cull.candidates(point)),
            rays,
        )
    };
    // Each batch (one sample of every pixel of a tile) traced depth by depth.
    let pass = TilePass {
        tracer: &tracer,
        camera: &camera,
        cull: &cull,
        count,
    };
    let work = TileWork {
        new_state: |_, rect| rect,
        whole: |_: &mut TileRect| None,
        batch: |rect: &mut TileRect, index| pass.tile(*rect, index),
        sample: &sample,
    };
    render_tiles_with(sums, samples, progress, &work).map(|(rays, _)| rays)
}

/// Renders a whole image with all of `options.samples_per_pixel`; `None` if cancelled.
#[must_use]
pub fn render(
    world: &World,
    options: &RenderOptions,
    progress: &RenderProgress,
) -> Option<(Image, RayCounts)> {
    let sums = render_samples(world, options, 0..options.samples_per_pixel, progress)?;
    let image = sums.average(options.samples_per_pixel);
    Some((image, sums.rays))
}

/// One camera sample at `offset` (in [0, 1)^2) within pixel `(px, py)`. `None` when the
/// colour came out non-finite: the guard that keeps NaN and infinity out of every pixel
/// (the caller counts these; they should never happen).
#[inline]
pub fn trace_sample(
    tracer: &Tracer,
    camera: &PinholeCamera,
    px: u32,
    py: u32,
    offset: DVec2,
    rays: &mut RayCounts,
) -> Option<DVec3> {
    let colour = trace_colour(tracer, camera, film_point(px, py, offset), rays);
    colour.is_finite().then_some(colour)
}

/// The film point of the sample at `offset` within pixel `(px, py)`.
#[inline]
fn film_point(px: u32, py: u32, offset: DVec2) -> DVec2 {
    DVec2::new(f64::from(px), f64::from(py)) + offset
}

/// The unguarded colour of the camera ray through film point `point` (may be non-finite).
#[inline]
fn trace_colour(
    tracer: &Tracer,
    camera: &PinholeCamera,
    point: DVec2,
    rays: &mut RayCounts,
) -> DVec3 {
    camera_sample(tracer, camera, point, &mut LiveRays::all(), rays)
}

/// The unguarded colour of the camera ray through film point `point`, its rays answered
/// by `source`: the one path from a film point to a colour, traced or re-shaded.
#[inline]
pub(super) fn camera_sample(
    tracer: &Tracer,
    camera: &PinholeCamera,
    point: DVec2,
    source: &mut impl RaySource,
    rays: &mut RayCounts,
) -> DVec3 {
    tracer.trace_primary_from(&camera.ray(point), source, rays, &mut NoRecorder)
}

/// The film point of sample `index` of `count` within pixel `(px, py)`.
#[inline]
pub(super) fn sample_point(px: u32, py: u32, index: u32, count: u32) -> DVec2 {
    film_point(px, py, sample_in_pixel(px, py, index, count))
}
