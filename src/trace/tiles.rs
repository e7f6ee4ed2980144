//! The frame cut into 16 x 16 tiles, traced in parallel with rayon. Inside a tile the
//! samples go in batches, one sample for every pixel of the tile at a time, and the
//! cancel flag is checked before each row of a batch: a cancelled render stops within one
//! row per tile whatever the sample count. Also the guard that keeps non-finite samples
//! out of the sums.

use std::ops::Range;
use std::sync::atomic::Ordering;

use glam::DVec3;
use rayon::prelude::*;

use super::render::{RenderProgress, SampleSums};
use super::shade::RayCounts;
use super::tile_placement::place_tiles;

/// Side of a square tile in pixels: small enough to balance two cores, big enough that
/// per-tile overhead is noise.
pub const TILE_SIZE: u32 = 16;

/// The colour of sample `index` of pixel `(px, py)`, unguarded (it may be non-finite),
/// adding the rays it cast to the tally. (The tests' form of [`TileWork::sample`].)
#[cfg(test)]
pub trait SampleColour: Fn(u32, u32, u32, &mut RayCounts) -> DVec3 + Sync {}

#[cfg(test)]
impl<F: Fn(u32, u32, u32, &mut RayCounts) -> DVec3 + Sync> SampleColour for F {}

/// A rectangle of the image, in pixels: left column, top row, width and height.
#[derive(Clone, Copy, Debug)]
pub(super) struct TileRect {
    pub x0: u32,
    pub y0: u32,
    pub w: u32,
    pub h: u32,
}

impl TileRect {
    /// Tile `index` (row-major) of an image `width` x `height`.
    fn of(index: u32, width: u32, height: u32) -> Self {
        let tiles_x = width.div_ceil(TILE_SIZE);
        let (x0, y0) = ((index % tiles_x) * TILE_SIZE, (index / tiles_x) * TILE_SIZE);
        Self {
            x0,
            y0,
            w: TILE_SIZE.min(width - x0),
            h: TILE_SIZE.min(height - y0),
        }
    }

    /// Pixels in the tile.
    pub fn pixel_count(self) -> usize {
        self.w as usize * self.h as usize
    }
}

/// Tiles of an image `width` x `height`.
pub(super) fn tile_count(width: u32, height: u32) -> u32 {
    width.div_ceil(TILE_SIZE) * height.div_ceil(TILE_SIZE)
}

/// One finished tile: the pixels' sums in row-major order within the tile.
struct Tile<S> {
    rect: TileRect,
    state: S,
    sums: Vec<DVec3>,
    rays: RayCounts,
    non_finite: u64,
    /// Image-wide row-major indices of the pixels with a non-finite sample, ascending.
    non_finite_pixels: Vec<u32>,
}

/// Continues `sums` with the samples `samples` of every pixel, each colour from
/// `sample`. Each pixel adds its samples in index order whatever the batching, so the
/// numbers do not depend on how a range is split. Returns the rays of this call (also
/// added to `sums.rays`), or `None` if cancelled, leaving `sums` untouched. The tests'
/// way in; the tracer's passes give a [`TileWork`] to [`render_tiles_with`].
#[cfg(test)]
pub(super) fn render_tiles(
    sums: &mut SampleSums,
    samples: Range<u32>,
    progress: &RenderProgress,
    sample: &impl SampleColour,
) -> Option<RayCounts> {
    let sample = |_: &mut (), px, py, index, rays: &mut RayCounts| sample(px, py, index, rays);
    let tile = TileWork {
        new_state: |_, _| (),
        whole: |_: &mut ()| None,
        batch: |_: &mut (), _| None,
        sample: &sample,
    };
    render_tiles_with(sums, samples, progress, &tile).map(|(rays, _)| rays)
}

/// How [`render_tiles_with`] renders a tile with a state of its own.
pub(super) struct TileWork<'s, N, W, B, F> {
    /// Makes the state from the tile's index (row-major, of [`tile_count`]) and rectangle.
    pub new_state: N,
    /// For a one-sample pass: every pixel's colour (row-major within the tile) and their
    /// rays at once, where the state can give them so; `None` to go pixel by pixel.
    pub whole: W,
    /// For each batch: sample `index` of every pixel (row-major within the tile) and
    /// their rays at once, where the state can give them so; `None` to go pixel by pixel.
    pub batch: B,
    /// One sample of one pixel, given the state (row-major in the tile, batch by batch).
    pub sample: &'s F,
}

/// As [`render_tiles`], each tile with a state of its own ([`TileWork`]); the states
/// come back in tile order with the rays.
pub(super) fn render_tiles_with<S, N, W, B, F>(
    sums: &mut SampleSums,
    samples: Range<u32>,
    progress: &RenderProgress,
    work: &TileWork<N, W, B, F>,
) -> Option<(RayCounts, Vec<S>)>
where
    S: Send,
    N: Fn(u32, TileRect) -> S + Sync,
    W: Fn(&mut S) -> Option<(Vec<DVec3>, RayCounts)> + Sync,
    B: Fn(&mut S, u32) -> Option<(Vec<DVec3>, RayCounts)> + Sync,
    F: Fn(&mut S, u32, u32, u32, &mut RayCounts) -> DVec3 + Sync,
{
    let (width, height) = (sums.width, sums.height);
    let tile_count = tile_count(width, height);
    let batches = tile_count as usize * samples.len();
    progress.batches_total.store(batches, Ordering::Relaxed);
    progress.batches_done.store(0, Ordering::Relaxed);

    // Sums with nothing summed yet ([`SampleSums::unsummed`]) are made from the tiles
    // alone: nothing to read before.
    let unsummed = sums.sums.is_empty();
    let before = (!unsummed).then_some(&*sums);
    // Into an `Option`: after a cancel, tiles not yet started are not even set up.
    let tiles: Option<Vec<Tile<S>>> = (0..tile_count)
        .into_par_iter()
        .map(|index| {
            let rect = TileRect::of(index, width, height);
            render_tile(
                rect,
                (work.new_state)(index, rect),
                width,
                before,
                samples.clone(),
                progress,
                work,
            )
        })
        .collect();
    let tiles = tiles?;

    let mut rays = RayCounts::default();
    let mut new_pixels = Vec::new();
    let mut states = Vec::with_capacity(tiles.len());
    let mut placed = Vec::with_capacity(tiles.len());
    for tile in tiles {
        states.push(tile.state);
        rays.add(&tile.rays);
        sums.non_finite += tile.non_finite;
        new_pixels.extend(tile.non_finite_pixels);
        placed.push((tile.rect, tile.sums));
    }
    place_tiles(sums, &placed, unsummed);
    sums.rays.add(&rays);
    if !new_pixels.is_empty() {
        sums.non_finite_pixels.extend(new_pixels);
        sums.non_finite_pixels.sort_unstable();
        sums.non_finite_pixels.dedup();
    }
    Some((rays, states))
}

/// The guard: adds `colour` to `sum` if it is finite; NaN or infinity never reaches a
/// pixel, and the caller counts it instead (`false`).
#[inline]
fn add_sample(sum: &mut DVec3, colour: DVec3) -> bool {
    let finite = colour.is_finite();
    if finite {
        *sum += colour;
    }
    finite
}

/// A tile of one sample per pixel from its pixels' `colours` (row-major), under the
/// same guard as [`render_tile`]'s.
fn whole_tile<S>(
    rect: TileRect,
    state: S,
    image_width: u32,
    mut colours: Vec<DVec3>,
    rays: RayCounts,
) -> Tile<S> {
    let mut non_finite_pixels = Vec::new();
    for (i, colour) in colours.iter_mut().enumerate() {
        let mut sum = DVec3::ZERO;
        if !add_sample(&mut sum, *colour) {
            let (x, y) = (i as u32 % rect.w, i as u32 / rect.w);
            non_finite_pixels.push((rect.y0 + y) * image_width + rect.x0 + x);
        }
        *colour = sum;
    }
    Tile {
        rect,
        state,
        sums: colours,
        rays,
        non_finite: non_finite_pixels.len() as u64,
        non_finite_pixels,
    }
}

/// Traces one tile batch by batch, each pixel's sum continuing from `before`; `None` as
/// soon as a row of a batch finds the render cancelled.
fn render_tile<S, N, W, B, F>(
    rect: TileRect,
    mut state: S,
    image_width: u32,
    before: Option<&SampleSums>,
    samples: Range<u32>,
    progress: &RenderProgress,
    work: &TileWork<N, W, B, F>,
) -> Option<Tile<S>>
where
    W: Fn(&mut S) -> Option<(Vec<DVec3>, RayCounts)>,
    B: Fn(&mut S, u32) -> Option<(Vec<DVec3>, RayCounts)>,
    F: Fn(&mut S, u32, u32, u32, &mut RayCounts) -> DVec3,
{
    if progress.is_cancelled() {
        return None;
    }
    // A first one-sample pass may give the whole tile at once.
    if samples.len() == 1
        && before.is_none()
        && let Some((colours, rays)) = (work.whole)(&mut state)
    {
        progress.batches_done.fetch_add(1, Ordering::Relaxed);
        return Some(whole_tile(rect, state, image_width, colours, rays));
    }
    let pixels: Vec<(u32, u32)> = (rect.y0..rect.y0 + rect.h)
        .flat_map(|py| (rect.x0..rect.x0 + rect.w).map(move |px| (px, py)))
        .collect();
    let mut sums: Vec<DVec3> = match before {
        Some(before) => pixels
            .iter()
            .map(|&(px, py)| before.sums[(py * image_width + px) as usize])
            .collect(),
        None => vec![DVec3::ZERO; pixels.len()],
    };
    let mut finite = vec![true; pixels.len()];
    let mut rays = RayCounts::default();
    let mut non_finite = 0;
    let w = rect.w as usize;
    for index in samples {
        if progress.is_cancelled() {
            return None;
        }
        if let Some((colours, batch_rays)) = (work.batch)(&mut state, index) {
            rays.add(&batch_rays);
            for ((sum, finite), colour) in sums.iter_mut().zip(&mut finite).zip(colours) {
                if !add_sample(sum, colour) {
                    non_finite += 1;
                    *finite = false;
                }
            }
            progress.batches_done.fetch_add(1, Ordering::Relaxed);
            continue;
        }
        let rows = pixels
            .chunks(w)
            .zip(sums.chunks_mut(w))
            .zip(finite.chunks_mut(w));
        for ((row, row_sums), row_finite) in rows {
            // Row by row: an edit need not wait for a tile of many-sample pixels.
            if progress.is_cancelled() {
                return None;
            }
            for ((&(px, py), sum), finite) in row.iter().zip(row_sums).zip(row_finite) {
                if !add_sample(sum, (work.sample)(&mut state, px, py, index, &mut rays)) {
                    non_finite += 1;
                    *finite = false;
                }
            }
        }
        progress.batches_done.fetch_add(1, Ordering::Relaxed);
    }
    let non_finite_pixels = pixels
        .iter()
        .zip(&finite)
        .filter(|(_, finite)| !**finite)
        .map(|(&(px, py), _)| py * image_width + px)
        .collect();
    Some(Tile {
        rect,
        state,
        sums,
        rays,
        non_finite,
        non_finite_pixels,
    })
}

#[cfg(test)]
mod tests {
    use std::sync::atomic::AtomicU64;

    use super::*;

    /// A sample colour that depends on the pixel and index only; counts its calls and
    /// cancels `progress` on call number `cancel_at` (counting from 1).
    fn cancelling(
        calls: &AtomicU64,
        cancel_at: u64,
        progress: &RenderProgress,
    ) -> impl Fn(u32, u32, u32, &mut RayCounts) -> DVec3 + Sync {
        move |px, py, index, _| {
            if calls.fetch_add(1, Ordering::SeqCst) + 1 == cancel_at {
                progress.cancel();
            }
            DVec3::new(f64::from(px), f64::from(py), f64::from(index))
        }
    }

    #[test]
    fn a_cancel_inside_a_tile_stops_it_at_the_end_of_that_row() {
        // One 16 x 16 tile on one thread, 64 samples a pixel; the 300th sample (the
        // third row of the second batch) cancels: one batch and three rows are traced.
        let progress = RenderProgress::default();
        let calls = AtomicU64::new(0);
        let cancel_at = 300;
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        let mut sums = SampleSums::zero(16, 16);
        let sample = cancelling(&calls, cancel_at, &progress);
        let outcome = pool.install(|| render_tiles(&mut sums, 0..64, &progress, &sample));
        assert!(outcome.is_none());
        let batch = u64::from(TILE_SIZE * TILE_SIZE);
        assert_eq!(
            calls.load(Ordering::SeqCst),
            batch + 3 * u64::from(TILE_SIZE)
        );
        assert!(
            sums.sums.iter().all(|s| *s == DVec3::ZERO),
            "a cancelled render leaves the sums untouched"
        );
    }

    #[test]
    fn after_a_cancel_each_running_tile_traces_at_most_one_more_batch() {
        // 96 x 64 pixels (24 tiles) at 1024 samples on 2 threads: a cancel after the
        // 1000th sample lets at most one batch per tile in flight finish.
        let threads = 2;
        let progress = RenderProgress::default();
        let calls = AtomicU64::new(0);
        let cancel_at = 1000;
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let mut sums = SampleSums::zero(96, 64);
        let sample = cancelling(&calls, cancel_at, &progress);
        let outcome = pool.install(|| render_tiles(&mut sums, 0..1024, &progress, &sample));
        assert!(outcome.is_none());
        let after = calls.load(Ordering::SeqCst) - cancel_at;
        let batch = u64::from(TILE_SIZE * TILE_SIZE);
        assert!(
            after <= threads as u64 * batch,
            "{after} samples traced after the cancel"
        );
    }

    #[test]
    fn a_non_finite_sample_is_counted_listed_and_kept_out_of_the_sum() {
        // 20 x 18 pixels (four tiles, one partial); sample 2 of pixel (17, 3) is NaN and
        // sample 0 of pixel (4, 16) is infinite.
        let progress = RenderProgress::default();
        let mut sums = SampleSums::zero(20, 18);
        let sample = |px: u32, py: u32, index: u32, rays: &mut RayCounts| {
            rays.primary += 1;
            match (px, py, index) {
                (17, 3, 2) => DVec3::new(0.5, f64::NAN, 0.5),
                (4, 16, 0) => DVec3::splat(f64::INFINITY),
                _ => DVec3::splat(0.25),
            }
        };
        render_tiles(&mut sums, 0..2, &progress, &sample).unwrap();
        render_tiles(&mut sums, 2..4, &progress, &sample).unwrap();
        assert_eq!(sums.non_finite, 2);
        assert_eq!(sums.non_finite_pixels, vec![3 * 20 + 17, 16 * 20 + 4]);
        assert_eq!(sums.rays.primary, 20 * 18 * 4);
        assert_eq!(
            sums.sums[3 * 20 + 17],
            DVec3::splat(0.75),
            "three samples kept"
        );
        assert_eq!(sums.sums[16 * 20 + 4], DVec3::splat(0.75));
        assert_eq!(sums.sums[0], DVec3::splat(1.0));
        assert!(sums.sums.iter().all(|s| s.is_finite()));
        assert_eq!(progress.fraction(), 1.0);
    }
}
