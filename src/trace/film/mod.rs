//! What an image is made of: the pinhole camera, sample positions, the tile grid, the
//! frame a render fills (options, progress, per-pixel sums) and the finished image.

mod camera;
mod frame;
mod image;
mod sampling;
mod tiles;

pub use camera::PinholeCamera;
pub(crate) use frame::cleared_unless_cancelled;
pub use frame::{RenderOptions, RenderProgress, SampleSums};
pub use image::{Image, encode, encode_linear};
pub use sampling::{sample_in_pixel, sequence_sample};
pub use tiles::TILE_SIZE;
pub(crate) use tiles::{TileRect, tile_count};
