//! The image cut into square tiles: the unit of parallel work, culling and caching.

/// Side of a square tile in pixels: small enough to balance two cores, big enough that
/// per-tile overhead is noise.
pub const TILE_SIZE: u32 = 16;

/// A rectangle of the image, in pixels: left column, top row, width and height.
#[derive(Clone, Copy, Debug)]
pub(crate) struct TileRect {
    pub x0: u32,
    pub y0: u32,
    pub w: u32,
    pub h: u32,
}

impl TileRect {
    /// Tile `index` (row-major) of an image `width` x `height`.
    pub(crate) fn of(index: u32, width: u32, height: u32) -> Self {
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
pub(crate) fn tile_count(width: u32, height: u32) -> u32 {
    width.div_ceil(TILE_SIZE) * height.div_ceil(TILE_SIZE)
}
