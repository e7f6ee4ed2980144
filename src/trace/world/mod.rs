//! The compiled scene: objects placed and bounded, the hierarchies over them, lights in
//! unit form, what isolation left out, and the one place secondary rays are spawned.

mod any_blocker;
mod batch;
mod bvh;
mod bvh_split;
mod compiled;
mod csg;
mod flatten;
mod isolation;
mod light_cone;
mod lights;
mod object;
mod object_set;
mod spawn;
mod sphere_light;
mod trees;

pub use compiled::{Acceleration, BVH_MIN_OBJECTS, SurfacePoint, World, WorldObject};
pub use csg::{CsgHit, CsgLeaf, CsgTree, Extent};
pub use flatten::scene_without_world_object;
pub(crate) use isolation::assert_compiled_for;
pub use isolation::{IsolationError, check_indices};
pub use light_cone::LightCone;
pub use lights::{LightSample, WorldLight, falloff};
pub use object_set::ObjectSet;
pub use spawn::{spawn_ray, spawn_ray_to};
pub use sphere_light::{SobolScramble, SphereLight, shading_seed};
