//! Adaptive sampling: a few stratified samples everywhere, then the rest of the sample
//! budget where pixels vary. The error of a pixel's mean falls as sigma / sqrt(n); for a
//! fixed total, the sum of squared errors is smallest with n proportional to sigma, so
//! flat regions keep their pilot samples and edges, shadow boundaries and highlights get
//! the rest.

use glam::DVec3;
use rayon::prelude::*;

use super::camera::PinholeCamera;
use super::image::Image;
use super::render::{RenderOptions, RenderProgress, trace_sample};
use super::sampling::{Strata, sample_sequence};
use super::shade::{RayCounts, Tracer};
use super::world::World;

/// How to spend samples adaptively.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdaptiveOptions {
    /// Stratified samples every pixel gets first (used to estimate its variation).
    pub pilot_spp: u32,
    /// Average samples per pixel over the whole image, pilot included.
    pub mean_spp: f64,
    /// No pixel gets more than this.
    pub max_spp: u32,
}

/// An adaptive render.
#[derive(Clone, Debug)]
pub struct AdaptiveRender {
    /// The picture.
    pub image: Image,
    /// Rays cast.
    pub rays: RayCounts,
    /// Samples actually taken, over all pixels.
    pub samples: u64,
}

/// Per-pixel running sums of one pass.
#[derive(Clone, Copy, Default)]
struct PixelStats {
    sum: DVec3,
    sum_sq: DVec3,
    count: u32,
}

/// Renders with a pilot pass and then variance-driven extra samples; `None` if cancelled.
/// `options.samples_per_pixel` is ignored in favour of `adaptive`.
#[must_use]
pub fn render_adaptive(
    world: &World,
    options: &RenderOptions,
    adaptive: &AdaptiveOptions,
    progress: &RenderProgress,
) -> Option<AdaptiveRender> {
    super::isolation::assert_compiled_for(world, &options.isolation);
    let (width, height) = (options.width, options.height);
    let camera = PinholeCamera::new(&world.camera, width, height);
    let tracer = Tracer::new(world, options.switches, options.view);
    let pilot = adaptive.pilot_spp.max(1);
    let strata = Strata::for_count(pilot);

    // pilot: stratified samples in every pixel
    let (mut stats, mut rays) = rows_in_parallel(width, height, progress, |px, py, rays| {
        let mut s = PixelStats::default();
        for i in 0..pilot {
            add_sample(
                &mut s,
                trace_sample(&tracer, &camera, px, py, strata.sample(px, py, i), rays),
            );
        }
        s
    })?;

    // allocate the rest of the budget in proportion to each pixel's (dilated) deviation
    let deviation = dilated_deviation(&stats, width, height);
    let total: f64 = deviation.iter().sum();
    let pixel_count = f64::from(width) * f64::from(height);
    let budget = ((adaptive.mean_spp - f64::from(pilot)) * pixel_count).max(0.0);
    let cap = adaptive.max_spp.saturating_sub(pilot);
    let extra: Vec<u32> = deviation
        .iter()
        .map(|d| {
            if total > 0.0 {
                ((budget * d / total).round() as u32).min(cap)
            } else {
                0
            }
        })
        .collect();

    // extra samples from a low-discrepancy sequence, so any count is well spread
    let (more, more_rays) = rows_in_parallel(width, height, progress, |px, py, rays| {
        let mut s = PixelStats::default();
        for j in 0..extra[(py * width + px) as usize] {
            add_sample(
                &mut s,
                trace_sample(&tracer, &camera, px, py, sample_sequence(px, py, j), rays),
            );
        }
        s
    })?;
    rays.add(&more_rays);
    for (s, m) in stats.iter_mut().zip(&more) {
        s.sum += m.sum;
        s.count += m.count;
    }
    let samples = stats.iter().map(|s| u64::from(s.count)).sum();
    let image = Image {
        width,
        height,
        pixels: stats
            .iter()
            .map(|s| (s.sum / f64::from(s.count.max(1))).as_vec3())
            .collect(),
    };
    Some(AdaptiveRender {
        image,
        rays,
        samples,
    })
}

fn add_sample(stats: &mut PixelStats, sample: Option<DVec3>) {
    // A non-finite sample (never expected) is dropped rather than poisoning the pixel.
    if let Some(c) = sample {
        stats.sum += c;
        stats.sum_sq += c * c;
        stats.count += 1;
    }
}

/// Runs `pixel` over every pixel, rows in parallel; `None` if cancelled.
fn rows_in_parallel(
    width: u32,
    height: u32,
    progress: &RenderProgress,
    pixel: impl Fn(u32, u32, &mut RayCounts) -> PixelStats + Sync,
) -> Option<(Vec<PixelStats>, RayCounts)> {
    let rows: Vec<Option<(Vec<PixelStats>, RayCounts)>> = (0..height)
        .into_par_iter()
        .map(|py| {
            if progress.is_cancelled() {
                return None;
            }
            let mut rays = RayCounts::default();
            let row = (0..width).map(|px| pixel(px, py, &mut rays)).collect();
            Some((row, rays))
        })
        .collect();
    let mut all = Vec::with_capacity((width * height) as usize);
    let mut rays = RayCounts::default();
    for row in rows {
        let (row, row_rays) = row?;
        all.extend(row);
        rays.add(&row_rays);
    }
    Some((all, rays))
}

/// Each pixel's standard deviation (largest channel, colours clamped to [0, 1] as they
/// are displayed), then the maximum over its 3x3 neighbourhood: a pilot whose samples all
/// fell on one side of an edge still gets samples when its neighbour saw the edge.
fn dilated_deviation(stats: &[PixelStats], width: u32, height: u32) -> Vec<f64> {
    let deviation: Vec<f64> = stats
        .iter()
        .map(|s| {
            let n = f64::from(s.count.max(1));
            let mean = s.sum / n;
            let variance = (s.sum_sq / n - mean * mean).max(DVec3::ZERO);
            // Pixels beyond white vary invisibly: weigh by how much of the mean shows.
            let visible = if mean.min_element() >= 1.0 { 0.0 } else { 1.0 };
            variance.max_element().sqrt() * visible
        })
        .collect();
    let (w, h) = (width as i64, height as i64);
    (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| {
            let mut most: f64 = 0.0;
            for ny in (y - 1).max(0)..=(y + 1).min(h - 1) {
                for nx in (x - 1).max(0)..=(x + 1).min(w - 1) {
                    most = most.max(deviation[(ny * w + nx) as usize]);
                }
            }
            most
        })
        .collect()
}
