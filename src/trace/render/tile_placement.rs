//! Putting a band of tiles' sums (one row of tiles, each row-major within itself) in
//! their places in the frame's sums, which are row-major over the whole image.

use glam::DVec3;

use crate::trace::film::TileRect;

/// Copies each tile's sums into `band` (the frame's rows that the band covers, `width`
/// pixels each), and frees them as it goes.
pub(crate) fn place_band(
    band: &mut [DVec3],
    width: usize,
    tiles: impl IntoIterator<Item = (TileRect, Vec<DVec3>)>,
) {
    for (rect, tile_sums) in tiles {
        let (x0, w) = (rect.x0 as usize, rect.w as usize);
        for (row, tile_row) in band.chunks_mut(width).zip(tile_sums.chunks(w)) {
            row[x0..x0 + w].copy_from_slice(tile_row);
        }
    }
}
