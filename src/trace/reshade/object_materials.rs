//! The materials the cache keys its rays by: each world object's, and, per object,
//! whether one of its values is no longer, bit for bit, the one the cache was made with
//! (a new shininess makes the cached lobes stale, a new index of refraction the rays
//! below its transmitted ones).

use crate::scene::Material;
use crate::trace::world::World;

/// Each object's material, by world object index.
pub(super) fn object_materials(world: &World) -> Vec<Material> {
    world
        .objects
        .iter()
        .map(|o| world.materials[o.material].clone())
        .collect()
}

/// Per object of `world`, whether `value` of its material differs, bit for bit, from
/// that of its material in `cached` (an object `cached` lacks counts as changed).
pub(super) fn value_changed(
    cached: &[Material],
    world: &World,
    value: impl Fn(&Material) -> f64,
) -> impl Iterator<Item = bool> {
    world.objects.iter().enumerate().map(move |(i, object)| {
        let now = value(&world.materials[object.material]);
        cached
            .get(i)
            .is_none_or(|m| value(m).to_bits() != now.to_bits())
    })
}
