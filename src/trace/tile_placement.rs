//! Putting the tiles' sums in their places in the frame's sums, which are row-major over
//! the whole image: in parallel, row by row of the image.

use glam::DVec3;
use rayon::prelude::*;

use super::render::{SampleSums, cleared};
use super::tiles::{TILE_SIZE, TileRect};

/// Puts each tile's sums in its place in `sums`, in parallel, row by row of the image;
/// `unsummed` sums are made first.
pub(super) fn place_tiles(sums: &mut SampleSums, tiles: &[(TileRect, Vec<DVec3>)], unsummed: bool) {
    let width = sums.width as usize;
    if width == 0 {
        return;
    }
    let tiles_x = sums.width.div_ceil(TILE_SIZE) as usize;
    let band = |y: usize| &tiles[y / TILE_SIZE as usize * tiles_x..][..tiles_x];
    let fill_row = |y: usize, row: &mut [DVec3]| {
        for (rect, tile_sums) in band(y) {
            let (x0, w) = (rect.x0 as usize, rect.w as usize);
            let start = (y - rect.y0 as usize) * w;
            row[x0..x0 + w].copy_from_slice(&tile_sums[start..start + w]);
        }
    };
    if unsummed {
        // Cleared first: the crate has no unsafe code to fill them uninitialised.
        sums.sums = cleared(width * sums.height as usize);
    }
    sums.sums
        .par_chunks_mut(width)
        .enumerate()
        .for_each(|(y, row)| fill_row(y, row));
}
