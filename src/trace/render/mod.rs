//! The render drivers: tiles in parallel, the tile pass with its culling, the adaptive
//! render and the cached pass that fills and reads the re-shade cache.

mod adaptive;
mod cached;
mod driver;
mod samples;
mod tile_pass;
mod tile_placement;
mod tiles;

pub use adaptive::{AdaptiveOptions, AdaptiveRender, render_adaptive};
pub use cached::{CachedPass, render_one_sample_cached};
pub use driver::{render, render_samples, render_samples_into};
