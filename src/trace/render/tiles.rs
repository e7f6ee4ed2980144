//! The frame cut into 16 x 16 tiles, traced in parallel with rayon. Inside a tile the
//! samples go in batches, one sample for every pixel of the tile at a time, and the
//! cancel flag is checked before each row of a batch: a cancelled render stops within one
//! row per tile whatever the sample count. Also the guard that keeps non-finite samples
//! out of the sums.

use std::ops::Range;
use std::sync::atomic::Ordering;

use glam::DVec3;
use rayon::prelude::*;

use super::tile_placement::place_band;
use crate::trace::film::{
    RenderProgress, SampleSums, TILE_SIZE, TileRect, cleared_unless_cancelled, tile_count,
};
use crate::trace::ray_counts::RayCounts;

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

/// How [`render_tiles_with`] renders a tile with a state of its own.
pub(crate) struct TileWork<'s, N, W, B, F> {
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

/// Continues `sums` with the samples `samples` of every pixel, each tile with a state
/// of its own ([`TileWork`]). Each pixel adds its samples in index order whatever the
/// batching, so the numbers do not depend on how a range is split. Returns the rays of
/// this call (also added to `sums.rays`) and the states in tile order, or `None` if
/// cancelled, leaving `sums` untouched.
pub(crate) fn render_tiles_with<S, N, W, B, F>(
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

    // Sums with nothing summed yet ([`SampleSums::unsummed`]) have nothing to read
    // before.
    let unsummed = sums.sums.is_empty();
    let before = (!unsummed).then_some(&*sums);
    let tiles_x = width.div_ceil(TILE_SIZE);
    let band_len = (width * TILE_SIZE).max(1) as usize;
    // One band (a row of tiles), its tiles in parallel. Into an `Option`: after a
    // cancel, tiles not yet started are not even set up.
    let trace_band = |band: usize| -> Option<Vec<Tile<S>>> {
        let first = band as u32 * tiles_x;
        (first..first + tiles_x)
            .into_par_iter()
            .map(|index| {
                let rect = TileRect::of(index, width, height);
                let state = (work.new_state)(index, rect);
                render_tile(rect, state, width, before, samples.clone(), progress, work)
            })
            .collect()
    };
    let (new_frame, bands) = if unsummed {
        // Each band goes into a new frame as soon as its tiles are done, while their
        // sums are still in the cache; the frame replaces the sums only when all are.
        // Cleared first: the crate has no unsafe code to fill it uninitialised.
        let mut frame = cleared_unless_cancelled(width as usize * height as usize, progress)?;
        let bands: Option<Vec<Vec<Tile<S>>>> = frame
            .par_chunks_mut(band_len)
            .enumerate()
            .map(|(band, band_sums)| {
                let mut tiles = trace_band(band)?;
                place(band_sums, width, &mut tiles);
                Some(tiles)
            })
            .collect();
        (Some(frame), bands?)
    } else {
        // The tiles read the sums before while they run: placed in them when all are
        // done, so a cancel leaves them as they were, and no new frame is faulted in
        // for every anti-aliasing pass.
        let bands: Option<Vec<Vec<Tile<S>>>> = (0..height.div_ceil(TILE_SIZE) as usize)
            .into_par_iter()
            .map(trace_band)
            .collect();
        let mut bands = bands?;
        sums.sums
            .par_chunks_mut(band_len)
            .zip(bands.par_iter_mut())
            .for_each(|(band_sums, tiles)| place(band_sums, width, tiles));
        (None, bands)
    };

    let mut rays = RayCounts::default();
    let mut new_pixels = Vec::new();
    let mut states = Vec::with_capacity(tile_count as usize);
    for tile in bands.into_iter().flatten() {
        states.push(tile.state);
        rays.add(&tile.rays);
        sums.non_finite += tile.non_finite;
        new_pixels.extend(tile.non_finite_pixels);
    }
    if let Some(frame) = new_frame {
        sums.sums = frame;
    }
    sums.rays.add(&rays);
    if !new_pixels.is_empty() {
        sums.non_finite_pixels.extend(new_pixels);
        sums.non_finite_pixels.sort_unstable();
        sums.non_finite_pixels.dedup();
    }
    Some((rays, states))
}

/// Puts the sums of a band's `tiles` in `band_sums` (the frame's rows they cover, `width`
/// pixels each), freeing them.
fn place<S>(band_sums: &mut [DVec3], width: u32, tiles: &mut [Tile<S>]) {
    let placed = tiles
        .iter_mut()
        .map(|tile| (tile.rect, std::mem::take(&mut tile.sums)));
    place_band(band_sums, width as usize, placed);
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
/// soon as the render is found cancelled, before a batch or a row of one.
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
    // A first one-sample pass may give the whole tile at once, as a whole or as its one
    // batch: with no sums before to read, it needs none of the loop's set-up below.
    if samples.len() == 1
        && before.is_none()
        && let Some((colours, rays)) =
            (work.whole)(&mut state).or_else(|| (work.batch)(&mut state, samples.start))
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
mod tests;
