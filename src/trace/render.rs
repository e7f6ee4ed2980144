//! Whole images: the frame cut into tiles, tiles traced in parallel with rayon. Progress
//! and cancellation are checked at tile boundaries.

use std::ops::Range;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use glam::{DVec2, DVec3, Vec3};
use rayon::prelude::*;

use super::camera::PinholeCamera;
use super::image::Image;
use super::sampling::Strata;
use super::shade::{NoRecorder, RayCounts, Tracer};
use super::terms::{TermSwitches, View};
use super::world::World;
use crate::scene::Scene;

/// Side of a square tile in pixels: small enough to balance two cores and to cancel
/// quickly, big enough that per-tile overhead is noise.
pub const TILE_SIZE: u32 = 16;

/// What to render.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderOptions {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Stratified samples per pixel.
    pub samples_per_pixel: u32,
    /// Term switches.
    pub switches: TermSwitches,
    /// Beauty or a debug view.
    pub view: View,
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
        }
    }
}

/// Shared between a render and whoever watches it: tiles done, and a cancel flag.
#[derive(Debug, Default)]
pub struct RenderProgress {
    /// Tiles finished so far.
    pub tiles_done: AtomicUsize,
    /// Tiles in the whole render (set when it starts).
    pub tiles_total: AtomicUsize,
    /// Set to stop the render at the next tile boundary.
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
        let total = self.tiles_total.load(Ordering::Relaxed);
        if total == 0 {
            0.0
        } else {
            self.tiles_done.load(Ordering::Relaxed) as f64 / total as f64
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
    let (width, height) = (options.width, options.height);
    let camera = PinholeCamera::new(&world.camera, width, height);
    let tracer = Tracer::new(world, options.switches, options.view);
    let tiles_x = width.div_ceil(TILE_SIZE);
    let tiles_y = height.div_ceil(TILE_SIZE);
    let tile_count = (tiles_x * tiles_y) as usize;
    progress.tiles_total.store(tile_count, Ordering::Relaxed);
    progress.tiles_done.store(0, Ordering::Relaxed);

    let tiles: Vec<Option<Tile>> = (0..tile_count)
        .into_par_iter()
        .map(|index| {
            if progress.is_cancelled() {
                return None;
            }
            let x0 = (index as u32 % tiles_x) * TILE_SIZE;
            let y0 = (index as u32 / tiles_x) * TILE_SIZE;
            let tile = render_tile(&tracer, &camera, options, samples.clone(), x0, y0);
            progress.tiles_done.fetch_add(1, Ordering::Relaxed);
            Some(tile)
        })
        .collect();

    let mut out = SampleSums {
        width,
        height,
        sums: vec![DVec3::ZERO; width as usize * height as usize],
        rays: RayCounts::default(),
        non_finite: 0,
    };
    for tile in tiles {
        let tile = tile?;
        out.rays.add(&tile.rays);
        out.non_finite += tile.non_finite;
        for (row, chunk) in tile.sums.chunks(tile.w as usize).enumerate() {
            let start = (tile.y0 as usize + row) * width as usize + tile.x0 as usize;
            out.sums[start..start + chunk.len()].copy_from_slice(chunk);
        }
    }
    Some(out)
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

impl SampleSums {
    /// The image these sums make when divided by `count` samples.
    #[must_use]
    pub fn average(&self, count: u32) -> Image {
        let scale = 1.0 / f64::from(count.max(1));
        Image {
            width: self.width,
            height: self.height,
            pixels: self
                .sums
                .iter()
                .map(|s| (*s * scale).as_vec3())
                .collect::<Vec<Vec3>>(),
        }
    }
}

/// One finished tile.
struct Tile {
    x0: u32,
    y0: u32,
    w: u32,
    sums: Vec<DVec3>,
    rays: RayCounts,
    non_finite: u64,
}

fn render_tile(
    tracer: &Tracer,
    camera: &PinholeCamera,
    options: &RenderOptions,
    samples: Range<u32>,
    x0: u32,
    y0: u32,
) -> Tile {
    let w = TILE_SIZE.min(options.width - x0);
    let h = TILE_SIZE.min(options.height - y0);
    let mut tile = Tile {
        x0,
        y0,
        w,
        sums: Vec::with_capacity((w * h) as usize),
        rays: RayCounts::default(),
        non_finite: 0,
    };
    let strata = Strata::for_count(options.samples_per_pixel);
    for py in y0..y0 + h {
        for px in x0..x0 + w {
            let mut sum = DVec3::ZERO;
            for index in samples.clone() {
                let offset = strata.sample(px, py, index);
                match trace_sample(tracer, camera, px, py, offset, &mut tile.rays) {
                    Some(colour) => sum += colour,
                    None => tile.non_finite += 1,
                }
            }
            tile.sums.push(sum);
        }
    }
    tile
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
    let point = DVec2::new(f64::from(px), f64::from(py)) + offset;
    let colour = tracer.trace_primary(&camera.ray(point), rays, &mut NoRecorder);
    colour.is_finite().then_some(colour)
}
