//! The flat disc caps the cylinder and the cone share.

use glam::DVec3;

use super::hit::{ShapeHit, gamma, in_range};
use crate::trace::ray::Ray;

/// The hit on a flat disc cap `z = z_cap`, radius 1, with outward normal `(0, 0, z_cap)`
/// scaled to unit length; shared by the cylinder and the cone.
#[inline]
pub(crate) fn disc_cap(ray: &Ray, t_max: f64, z_cap: f64, normal_z: f64) -> Option<ShapeHit> {
    if ray.dir.z == 0.0 {
        return None;
    }
    let t = (z_cap - ray.origin.z) / ray.dir.z;
    if !in_range(ray, t, t_max) {
        return None;
    }
    cap_point_at(ray, t, z_cap, normal_z)
}

/// Where the line meets the disc cap `z = z_cap`, at any `t`, if it does on the disc
/// (its point, if needed, is [`cap_point_at`]'s).
#[inline]
pub(crate) fn cap_t(ray: &Ray, z_cap: f64) -> Option<f64> {
    if ray.dir.z == 0.0 {
        return None;
    }
    let t = (z_cap - ray.origin.z) / ray.dir.z;
    let p = ray.at(t);
    (p.x * p.x + p.y * p.y <= 1.0).then_some(t)
}

/// The point at `t` on the plane of a disc cap, if it lies on the disc.
#[inline(always)]
pub(crate) fn cap_point_at(ray: &Ray, t: f64, z_cap: f64, normal_z: f64) -> Option<ShapeHit> {
    let p = ray.at(t);
    if p.x * p.x + p.y * p.y > 1.0 {
        return None;
    }
    // On the plane exactly; x and y carry the error of one fma each.
    let p = DVec3::new(p.x, p.y, z_cap);
    Some(ShapeHit {
        t,
        p,
        n: DVec3::new(0.0, 0.0, normal_z),
        p_error: DVec3::new(gamma(3) * p.x.abs(), gamma(3) * p.y.abs(), 0.0),
    })
}
