//! The render drivers: tiles in parallel, the tile pass with its culling, the adaptive
//! render, the cached pass that fills and reads the re-shade cache, and the pruned
//! render that writes the full trace's bytes with fewer rays, and one trace folded
//! under several conventions.

mod adaptive;
mod byte_interval;
mod cached;
mod driver;
mod pruned;
mod samples;
mod spawn_filter;
mod tile_pass;
mod tile_placement;
mod tile_shadows;
mod tiles;
mod variants;

pub use adaptive::{AdaptiveOptions, AdaptiveRender, render_adaptive};
pub use cached::{CachedPass, render_one_sample_cached};
pub use driver::{render, render_samples, render_samples_into};
pub use pruned::{PRUNE_BUDGET, PrunedRender, render_pruned};
pub use variants::{Variant, render_variants};
