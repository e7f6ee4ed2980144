//! A render whose written bytes are the full trace's, traced with fewer rays (issue 50):
//! a first pass leaves out each mirror or transmitted ray whose whole subtree provably
//! adds less than a budget to its pixel ([`SubtreeBound`], [`PruneBelow`]) and keeps, per
//! pixel, the sum of those bounds; then every pixel whose interval
//! `[traced, traced + left out]` reaches past one byte of the PNG
//! ([`byte_interval::same_bytes`]) is traced again in full, sample by sample as the
//! full render adds them.
//!
//! The bytes are the full trace's for every scene, conventions and sample count; the
//! float sums are not (a pixel kept from the first pass is a little darker than the full
//! trace's), so only writers of 8-bit pictures call this: `raylab render`. The editor's
//! preview and export, `inspect`, `diff` and the adaptive render trace in full.

use glam::DVec3;
use rayon::prelude::*;

use super::byte_interval::same_bytes;
use super::driver::render_samples;
use super::spawn_filter::PruneBelow;
use super::tile_pass::TilePass;
use super::tiles::{TileWork, render_tiles_with};
use crate::trace::film::{RenderOptions, RenderProgress, SampleSums, TileRect, tile_count};
use crate::trace::ray_counts::RayCounts;
use crate::trace::shade::SubtreeBound;
use crate::trace::terms::View;
use crate::trace::world::{World, assert_compiled_for};

/// What a sample may leave out, in all, in a pixel's units: a tenth of a byte's step.
/// Each pixel it touches is traced again with a chance of about its share of a step per
/// channel it moves (measured in docs/BENCHMARKS.md, "Glass pruned").
pub const PRUNE_BUDGET: f64 = 0.1 / 255.0;

/// A pruned render's sums and what the pruning did.
#[derive(Clone, Debug)]
pub struct PrunedRender {
    /// The sums of every sample: the bytes they write are the full trace's.
    pub sums: SampleSums,
    /// Pixels where at least one ray was left out in the first pass.
    pub pruned_pixels: u64,
    /// Of those, the pixels traced again in full.
    pub retraced_pixels: u64,
}

/// Renders all `options.samples_per_pixel` samples of every pixel, leaving out rays that
/// cannot change a written byte (`budget` per sample: [`PRUNE_BUDGET`]); `None` if
/// cancelled. A debug view, a world with no proven bound, or a first pass with any
/// non-finite sample is rendered in full instead.
///
/// # Panics
/// When `world` was compiled for other isolation switches than `options.isolation`.
#[must_use]
pub fn render_pruned(
    world: &World,
    options: &RenderOptions,
    budget: f64,
    progress: &RenderProgress,
) -> Option<PrunedRender> {
    assert_compiled_for(world, &options.isolation);
    let count = options.samples_per_pixel;
    let full = |progress: &RenderProgress| {
        render_samples(world, options, 0..count, progress).map(|sums| PrunedRender {
            sums,
            pruned_pixels: 0,
            retraced_pixels: 0,
        })
    };
    let bound = (options.view == View::Beauty)
        .then(|| SubtreeBound::new(world))
        .flatten();
    let Some(bound) = bound else {
        return full(progress);
    };
    let (width, height) = (options.width, options.height);
    // The full render's pass: a sample traced alone is its pixel-by-pixel path.
    let pass = TilePass::new(world, options);
    let work = TileWork {
        new_state: |_, rect: TileRect| {
            let pixels = (rect.w * rect.h) as usize;
            (rect, vec![DVec3::ZERO; pixels])
        },
        whole: |_: &mut (TileRect, Vec<DVec3>)| None,
        batch: |(rect, left_out): &mut (TileRect, Vec<DVec3>), index| {
            pass.tile_with(*rect, index, &mut PruneBelow::new(&bound, budget, left_out))
        },
        sample: &|_: &mut (TileRect, Vec<DVec3>), px, py, index, rays: &mut RayCounts| {
            pass.sample(px, py, index, rays)
        },
    };
    let mut sums = SampleSums::unsummed(width, height);
    let (_, tiles) = render_tiles_with(&mut sums, 0..count, progress, &work)?;
    debug_assert_eq!(tiles.len(), tile_count(width, height) as usize);
    if sums.non_finite > 0 {
        // Never expected; the full render counts them exactly.
        return full(progress);
    }
    let quantise = world.conventions.quantise;
    let mut pruned_pixels = 0;
    let mut again = Vec::new();
    for (rect, left_out) in &tiles {
        for (i, left_out) in left_out.iter().enumerate() {
            if *left_out == DVec3::ZERO {
                continue;
            }
            pruned_pixels += 1;
            let (px, py) = (rect.x0 + i as u32 % rect.w, rect.y0 + i as u32 / rect.w);
            let at = (py * width + px) as usize;
            if !same_bytes(sums.sums[at], *left_out, count, quantise) {
                again.push((px, py));
            }
        }
    }
    if progress.is_cancelled() {
        return None;
    }
    // Each pixel's samples added in index order from zero, as the full render adds them.
    let retraced: Vec<(DVec3, RayCounts)> = again
        .par_iter()
        .map(|&(px, py)| {
            let mut rays = RayCounts::default();
            let mut sum = DVec3::ZERO;
            for index in 0..count {
                sum += pass.sample(px, py, index, &mut rays);
            }
            (sum, rays)
        })
        .collect();
    if retraced.iter().any(|(sum, _)| !sum.is_finite()) {
        return full(progress);
    }
    for (&(px, py), (sum, rays)) in again.iter().zip(&retraced) {
        sums.sums[(py * width + px) as usize] = *sum;
        sums.rays.add(rays);
    }
    Some(PrunedRender {
        sums,
        pruned_pixels,
        retraced_pixels: again.len() as u64,
    })
}
