//! The cache behind quick re-shading: the rays a pass traced, what each light gave each
//! hit, and the rule that says which pixels an edit leaves as they were, so a material or
//! switch edit re-shades the cached hits without tracing a ray.

mod cached_hit;
mod chains;
mod dependence;
mod hit_cache;
mod keep_rule;
mod light_factors;
mod object_materials;
mod pixel_colour;
mod pixel_rays;
mod quick_shade;
mod quick_tree;
mod ray_geometry;
mod tile_rays;

pub(crate) use chains::PixelEntries;
pub(crate) use dependence::{DependenceRule, TermDependence};
pub use hit_cache::{HitCache, MAX_CACHE_BYTES, RetraceReason, Reuse, cache_fits};
pub(crate) use pixel_colour::PixelColour;
pub(crate) use pixel_rays::PixelRays;
pub(crate) use quick_shade::QuickShade;
pub(crate) use tile_rays::{SlotColumns, TileRays};
