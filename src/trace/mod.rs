//! The tracer: pure functions from a compiled [`World`] and a ray to a colour, and from
//! a world to an image. No threads of its own beyond rayon's, no I/O, no UI.
//!
//! In folders by stage, each depending only on the ones before it:
//!
//! | folder | what it holds |
//! |---|---|
//! | `ray`, `terms`, `ray_counts` | rays, the term switches and views, ray counts |
//! | [`shapes`] | the unit shapes, their bounds and the quadratic they share |
//! | `world` | the compiled scene: objects, hierarchies, lights, isolation, spawning |
//! | `film` | camera, samples, tile grid, frame options and sums, image |
//! | `cull` | what each tile's camera and shadow rays can meet |
//! | `shade` | the lighting model, the ray source it asks, the recorder |
//! | `reshade` | the cache that re-shades an edit without tracing |
//! | `render` | the drivers: tiles, the tile pass, adaptive, cached and pruned passes |
//! | `inspect` | one pixel taken apart, and its tree of rays |

mod cull;
mod film;
mod inspect;
mod ray;
mod ray_counts;
mod render;
mod reshade;
mod shade;
pub mod shapes;
mod terms;
mod world;

pub use film::{
    Image, PinholeCamera, RenderOptions, RenderProgress, SampleSums, TILE_SIZE, encode,
    encode_linear, sample_in_pixel,
};
pub use inspect::{
    BounceReport, HitSurface, PixelOutside, PixelReport, RayHit, RayKind, TracedRay, inspect_pixel,
    pick, switches_text, traced_rays, try_inspect_pixel,
};
pub use ray::Ray;
pub use ray_counts::RayCounts;
pub use render::{
    AdaptiveOptions, AdaptiveRender, CachedPass, PRUNE_BUDGET, PrunedRender, Variant, render,
    render_adaptive, render_one_sample_cached, render_pruned, render_samples, render_samples_into,
    render_variants,
};
pub use reshade::{HitCache, MAX_CACHE_BYTES, RetraceReason, Reuse, cache_fits};
pub use shade::{
    Branch, LightOutcome, LightRecord, LightSkip, LocalLight, NoRecorder, Recorder, ShadowRay,
    SkippedLight, SubtreeBound, Tracer, object_id_colour, phong_power,
};
pub use shapes::{MeshStore, TriangleHit, TriangleMesh};
pub use terms::{Isolation, Term, TermSwitches, View};
pub use world::{
    Acceleration, BVH_MIN_OBJECTS, CsgHit, CsgLeaf, CsgTree, Extent, IsolationError, LightSample,
    SurfacePoint, World, WorldLight, WorldObject, check_indices, scene_without_world_object,
    spawn_ray, spawn_ray_to,
};
