//! Adaptive sampling: a few stratified samples everywhere, then the rest of the sample
//! budget where pixels vary. Pilot and extra samples are one prefix of each pixel's
//! sequence (`sampling::sequence_sample`), so whatever count a pixel ends with, its
//! samples are well spread. The error of a pixel's mean falls as sigma / sqrt(n); for a
//! fixed total, the sum of squared errors is smallest with n proportional to sigma, so
//! flat regions keep their pilot samples and edges, shadow boundaries and highlights get
//! the rest.

use glam::DVec3;
use rayon::prelude::*;

use super::samples::trace_sample;
use crate::trace::film::{Image, PinholeCamera, RenderOptions, RenderProgress, sequence_sample};
use crate::trace::ray_counts::RayCounts;
use crate::trace::shade::Tracer;
use crate::trace::world::World;

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
    crate::trace::world::assert_compiled_for(world, &options.isolation);
    let (width, height) = (options.width, options.height);
    let camera = PinholeCamera::new(&world.camera, width, height);
    let tracer = Tracer::new(world, options.switches, options.view);
    let pilot = adaptive.pilot_spp.max(1);

    // pilot: stratified samples in every pixel
    let (mut stats, mut rays) = rows_in_parallel(width, height, progress, |px, py, rays| {
        let mut s = PixelStats::default();
        for i in 0..pilot {
            add_sample(
                &mut s,
                trace_sample(&tracer, &camera, px, py, sequence_sample(px, py, i), rays),
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

    // extra samples continue each pixel's sequence after its pilot
    let (more, more_rays) = rows_in_parallel(width, height, progress, |px, py, rays| {
        let mut s = PixelStats::default();
        for j in pilot..pilot + extra[(py * width + px) as usize] {
            add_sample(
                &mut s,
                trace_sample(&tracer, &camera, px, py, sequence_sample(px, py, j), rays),
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::{TermSwitches, View, render, render_samples};

    fn world_and_options() -> (World, RenderOptions) {
        let scene = crate::scene::examples::default_scene();
        let options = RenderOptions {
            width: 64,
            height: 48,
            samples_per_pixel: 1,
            switches: TermSwitches::ALL_ON,
            view: View::Beauty,
            isolation: crate::trace::Isolation::NONE,
        };
        (World::new(&scene).unwrap(), options)
    }

    /// RMSE of the clamped values of two images of the same size.
    fn rmse(a: &Image, b: &Image) -> f64 {
        let clamp = |v: glam::Vec3| v.clamp(glam::Vec3::ZERO, glam::Vec3::ONE);
        let sum: f64 = a
            .pixels
            .iter()
            .zip(&b.pixels)
            .map(|(x, y)| f64::from((clamp(*x) - clamp(*y)).length_squared()))
            .sum();
        (sum / (3.0 * a.pixels.len() as f64)).sqrt()
    }

    #[test]
    fn with_no_budget_beyond_the_pilot_it_is_the_uniform_render() {
        let (world, options) = world_and_options();
        let adaptive = AdaptiveOptions {
            pilot_spp: 4,
            mean_spp: 4.0,
            max_spp: 64,
        };
        let progress = RenderProgress::default();
        let result = render_adaptive(&world, &options, &adaptive, &progress).unwrap();
        let uniform = RenderOptions {
            samples_per_pixel: 4,
            ..options
        };
        let (image, rays) = render(&world, &uniform, &progress).unwrap();
        assert_eq!(result.image.pixels, image.pixels);
        assert_eq!(result.rays, rays);
        assert_eq!(result.samples, 4 * 64 * 48);
    }

    #[test]
    fn the_budget_is_spent_where_pixels_vary_and_beats_uniform_at_the_pilot_count() {
        let (world, options) = world_and_options();
        let pixels = 64.0 * 48.0;
        let adaptive = AdaptiveOptions {
            pilot_spp: 4,
            mean_spp: 16.0,
            max_spp: 256,
        };
        let progress = RenderProgress::default();
        let result = render_adaptive(&world, &options, &adaptive, &progress).unwrap();
        // Each pixel's share is rounded, so the total is the budget within half a sample a
        // pixel.
        let mean = result.samples as f64 / pixels;
        assert!((mean - 16.0).abs() <= 0.5, "mean {mean} samples a pixel");
        // The reference uses samples 256..512, disjoint from the adaptive ones.
        let reference_options = RenderOptions {
            samples_per_pixel: 512,
            ..options.clone()
        };
        let reference = render_samples(&world, &reference_options, 256..512, &progress)
            .unwrap()
            .average(256);
        let uniform = |spp| {
            let options = RenderOptions {
                samples_per_pixel: spp,
                ..options.clone()
            };
            render(&world, &options, &progress).unwrap().0
        };
        let adaptive_error = rmse(&result.image, &reference);
        let pilot_error = rmse(&uniform(4), &reference);
        let uniform_error = rmse(&uniform(16), &reference);
        assert!(
            adaptive_error < 0.7 * pilot_error,
            "adaptive {adaptive_error}, pilot alone {pilot_error}"
        );
        assert!(
            adaptive_error < 1.1 * uniform_error,
            "adaptive {adaptive_error}, uniform at the same mean {uniform_error}"
        );
    }

    #[test]
    fn a_cancelled_render_returns_nothing() {
        let (world, options) = world_and_options();
        let progress = RenderProgress::default();
        progress.cancel();
        let adaptive = AdaptiveOptions {
            pilot_spp: 2,
            mean_spp: 8.0,
            max_spp: 32,
        };
        assert!(render_adaptive(&world, &options, &adaptive, &progress).is_none());
    }
}
