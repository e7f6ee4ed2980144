//! The one place that starts secondary rays (shadow and mirror) and so owns the
//! self-intersection offset. There is no fixed epsilon: the origin moves off the surface
//! by the hit point's own error bound, to the side the new ray leaves on.

use glam::DVec3;

use super::compiled::SurfacePoint;
use crate::trace::ray::Ray;

/// How many times the error bound the origin is moved; the bound is already conservative,
/// this covers the rounding of the intersection arithmetic of the new ray.
const SAFETY: f64 = 2.0;

/// Shadow rays to a point light stop this fraction short of it, so a light sitting on a
/// surface is not shadowed by that surface.
pub const SHADOW_STOP_SHORT: f64 = 1e-9;

/// The origin for a ray leaving `hit` in direction `dir`.
#[must_use]
pub fn offset_origin(hit: &SurfacePoint, dir: DVec3) -> DVec3 {
    let n = hit.n_outward;
    let distance = n.abs().dot(hit.p_error) * SAFETY;
    let offset = if dir.dot(n) >= 0.0 {
        n * distance
    } else {
        -n * distance
    };
    let moved = hit.p + offset;
    // Round away from the surface so the offset survives the addition.
    DVec3::from_array(std::array::from_fn(|i| {
        if offset[i] > 0.0 {
            moved[i].next_up()
        } else if offset[i] < 0.0 {
            moved[i].next_down()
        } else {
            moved[i]
        }
    }))
}

/// A ray leaving `hit` in direction `dir` (a mirror ray, or a shadow ray to infinity).
#[must_use]
pub fn spawn_ray(hit: &SurfacePoint, dir: DVec3) -> Ray {
    Ray::new(offset_origin(hit, dir), dir)
}

/// A shadow ray from `hit` towards `target`, with the `t_max` that stops it just short
/// of the target. `t` runs from 0 at the origin to 1 at the target.
#[must_use]
pub fn spawn_ray_to(hit: &SurfacePoint, target: DVec3) -> (Ray, f64) {
    let origin = offset_origin(hit, target - hit.p);
    (Ray::new(origin, target - origin), 1.0 - SHADOW_STOP_SHORT)
}
