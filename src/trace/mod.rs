//! The tracer: pure functions from a compiled [`World`] and a ray to a colour, and from
//! a world to an image. No threads of its own beyond rayon's, no I/O, no UI.

pub mod adaptive;
pub mod bounds;
pub mod bvh;
pub mod camera;
mod chains;
mod dependence;
pub mod depth_view;
pub mod hit_cache;
pub mod image;
pub mod inspect;
pub mod isolation;
mod keep_rule;
pub mod light_factors;
pub mod lights;
mod mirror_chain;
pub mod object_id;
pub mod object_set;
pub mod phong;
pub mod quadratic;
mod quick_shade;
pub mod ray;
pub mod ray_counts;
pub mod ray_source;
pub mod ray_tree;
pub mod record;
pub mod render;
pub mod reshade;
pub mod sampling;
pub mod shade;
pub mod shadow_cull;
pub mod shapes;
pub mod spawn;
pub mod terms;
pub mod tile_cull;
mod tile_pass;
mod tile_placement;
mod tile_rays;
pub mod tiles;
pub mod world;
mod world_batch;
mod world_trees;

pub use adaptive::{AdaptiveOptions, AdaptiveRender, render_adaptive};
pub use camera::PinholeCamera;
pub use hit_cache::{HitCache, MAX_CACHE_BYTES, RetraceReason, Reuse, cache_fits};
pub use image::Image;
pub use inspect::{
    BounceReport, PixelOutside, PixelReport, inspect_pixel, pick, switches_text, try_inspect_pixel,
};
pub use isolation::IsolationError;
pub use ray::Ray;
pub use ray_tree::{RayHit, RayKind, TracedRay, traced_rays};
pub use record::{LightOutcome, LightSkip, ShadowRay, SkippedLight};
pub use render::{
    RenderOptions, RenderProgress, SampleSums, render, render_samples, render_samples_into,
};
pub use reshade::{CachedPass, render_one_sample_cached};
pub use shade::{LightRecord, NoRecorder, RayCounts, Recorder, Tracer};
pub use shapes::Primitive;
pub use terms::{Isolation, Term, TermSwitches, View};
pub use tiles::TILE_SIZE;
pub use world::{Acceleration, BVH_MIN_OBJECTS, SurfacePoint, World};
