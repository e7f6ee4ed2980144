//! Whole images: what to render, its progress and cancel flag, and the sums of samples a
//! render adds up (tiles and batches in [`super::tiles`]).

use std::ops::Range;

use super::tile_pass::TilePass;
use super::tiles::{TileWork, render_tiles_with};
use crate::trace::film::{Image, RenderOptions, RenderProgress, SampleSums, TileRect};
use crate::trace::ray_counts::RayCounts;
use crate::trace::world::{World, assert_compiled_for};

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
    // Each batch (one sample of every pixel of a tile) traced depth by depth.
    let pass = TilePass::new(world, options);
    let work = TileWork {
        new_state: |_, rect| rect,
        whole: |_: &mut TileRect| None,
        batch: |rect: &mut TileRect, index| pass.tile(*rect, index),
        sample: &|_: &mut TileRect, px, py, index, rays: &mut RayCounts| {
            pass.sample(px, py, index, rays)
        },
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
