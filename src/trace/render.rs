//! Whole images: the frame cut into tiles, tiles traced in parallel with rayon. Progress
//! and cancellation are checked at tile boundaries.

use std::ops::Range;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use glam::{DVec2, DVec3, Vec3};
use rayon::prelude::*;

use super::camera::PinholeCamera;
use super::image::Image;
use super::isolation::assert_compiled_for;
use super::sampling::Strata;
use super::shade::{NoRecorder, RayCounts, Tracer};
use super::terms::{Isolation, TermSwitches, View};
use super::world::World;
use crate::scene::Scene;

/// Side of a square tile in pixels: small enough to balance two cores and to cancel
/// quickly, big enough that per-tile overhead is noise.
pub const TILE_SIZE: u32 = 16;

/// What to render.
#[derive(Clone, Debug, PartialEq, Eq)]
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
    /// Row-major indices (`y * width + x`) of the pixels with at least one non-finite
    /// sample, ascending, each once (should stay empty).
    pub non_finite_pixels: Vec<u32>,
}

impl SampleSums {
    /// Sums of no samples yet: black, nothing counted.
    #[must_use]
    pub fn zero(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            sums: vec![DVec3::ZERO; width as usize * height as usize],
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
                .iter()
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
    let mut sums = SampleSums::zero(options.width, options.height);
    render_samples_into(world, options, samples, &mut sums, progress)?;
    Some(sums)
}

/// Continues `sums` with the samples `samples` (of `options.samples_per_pixel`): each
/// pixel's sum goes on adding its samples in index order, so rendering `0..4` then `4..8`
/// gives exactly the numbers of `0..8` at once. Returns the rays of this batch (they are
/// also added to `sums.rays`), or `None` if cancelled, leaving `sums` untouched.
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
    let camera = PinholeCamera::new(&world.camera, width, height);
    let tracer = Tracer::new(world, options.switches, options.view);
    let tiles_x = width.div_ceil(TILE_SIZE);
    let tiles_y = height.div_ceil(TILE_SIZE);
    let tile_count = (tiles_x * tiles_y) as usize;
    progress.tiles_total.store(tile_count, Ordering::Relaxed);
    progress.tiles_done.store(0, Ordering::Relaxed);

    let before: &SampleSums = sums;
    let tiles: Vec<Option<Tile>> = (0..tile_count)
        .into_par_iter()
        .map(|index| {
            if progress.is_cancelled() {
                return None;
            }
            let x0 = (index as u32 % tiles_x) * TILE_SIZE;
            let y0 = (index as u32 / tiles_x) * TILE_SIZE;
            let tile = render_tile(&tracer, &camera, options, samples.clone(), before, x0, y0);
            progress.tiles_done.fetch_add(1, Ordering::Relaxed);
            Some(tile)
        })
        .collect();
    let tiles: Vec<Tile> = tiles.into_iter().collect::<Option<_>>()?;

    let mut rays = RayCounts::default();
    let mut new_pixels = Vec::new();
    for tile in tiles {
        rays.add(&tile.rays);
        sums.non_finite += tile.non_finite;
        new_pixels.extend(tile.non_finite_pixels);
        for (row, chunk) in tile.sums.chunks(tile.w as usize).enumerate() {
            let start = (tile.y0 as usize + row) * width as usize + tile.x0 as usize;
            sums.sums[start..start + chunk.len()].copy_from_slice(chunk);
        }
    }
    sums.rays.add(&rays);
    if !new_pixels.is_empty() {
        sums.non_finite_pixels.extend(new_pixels);
        sums.non_finite_pixels.sort_unstable();
        sums.non_finite_pixels.dedup();
    }
    Some(rays)
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

/// One finished tile.
struct Tile {
    x0: u32,
    y0: u32,
    w: u32,
    sums: Vec<DVec3>,
    rays: RayCounts,
    non_finite: u64,
    non_finite_pixels: Vec<u32>,
}

/// Renders one tile, each pixel's sum continuing from its sum in `before`.
fn render_tile(
    tracer: &Tracer,
    camera: &PinholeCamera,
    options: &RenderOptions,
    samples: Range<u32>,
    before: &SampleSums,
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
        non_finite_pixels: Vec::new(),
    };
    let strata = Strata::for_count(options.samples_per_pixel);
    for py in y0..y0 + h {
        for px in x0..x0 + w {
            let pixel = py * options.width + px;
            let mut sum = before.sums[pixel as usize];
            let mut finite = true;
            for index in samples.clone() {
                let offset = strata.sample(px, py, index);
                match trace_sample(tracer, camera, px, py, offset, &mut tile.rays) {
                    Some(colour) => sum += colour,
                    None => {
                        tile.non_finite += 1;
                        finite = false;
                    }
                }
            }
            if !finite {
                tile.non_finite_pixels.push(pixel);
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
