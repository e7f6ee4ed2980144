//! The five unit shapes, in object space. Each file has the same parts in the same order:
//! bounds, `intersect` (closest hit with its error bound) and `occluded` (any hit, for
//! shadow rays). One `match` here forwards to them.
//!
//! Every `intersect` returns the hit point re-projected onto the exact surface and a
//! per-component bound on its remaining distance from the surface (see docs/NUMERICS.md).

mod cone;
mod cube;
mod cylinder;
mod plane;
mod sphere;

use glam::DVec3;

use super::bounds::Aabb;
use super::ray::Ray;
use crate::scene::Shape;

/// A hit on a unit shape, all in object space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapeHit {
    /// Ray parameter of the hit.
    pub t: f64,
    /// The hit point, on the surface up to `p_error`.
    pub p: DVec3,
    /// Outward surface normal, not necessarily unit length.
    pub n: DVec3,
    /// Absolute bound on each component's distance of `p` from the exact surface.
    pub p_error: DVec3,
}

/// `gamma(n) = n u / (1 - n u)` with `u` the unit roundoff: bounds the relative error of
/// `n` chained floating-point operations.
#[must_use]
pub fn gamma(n: u32) -> f64 {
    let nu = f64::from(n) * (f64::EPSILON * 0.5);
    nu / (1.0 - nu)
}

/// Whether `t` lies in (0, t_max) and the hit is farther from the origin than the
/// rounding error of the origin itself: a ray that starts on a surface does not hit that
/// surface at t ~ 0. (Spawned rays start well outside this distance; see `spawn`.)
#[inline]
fn in_range(ray: &Ray, t: f64, t_max: f64) -> bool {
    if !(t > 0.0 && t < t_max) {
        return false;
    }
    let origin_rounding = gamma(8) * ray.origin.abs().max_element().max(1.0);
    t * t * ray.dir.length_squared() > origin_rounding * origin_rounding
}

/// The object-space bounding box of a unit shape.
#[must_use]
pub fn object_bounds(shape: Shape) -> Aabb {
    match shape {
        Shape::Sphere => sphere::bounds(),
        Shape::Plane => plane::bounds(),
        Shape::Cube => cube::bounds(),
        Shape::Cylinder => cylinder::bounds(),
        Shape::Cone => cone::bounds(),
    }
}

/// The closest hit of an object-space ray with `t` in (0, t_max).
#[must_use]
#[inline]
pub fn intersect(shape: Shape, ray: &Ray, t_max: f64) -> Option<ShapeHit> {
    match shape {
        Shape::Sphere => sphere::intersect(ray, t_max),
        Shape::Plane => plane::intersect(ray, t_max),
        Shape::Cube => cube::intersect(ray, t_max),
        Shape::Cylinder => cylinder::intersect(ray, t_max),
        Shape::Cone => cone::intersect(ray, t_max),
    }
}

/// Whether an object-space ray hits the shape with `t` in (0, t_max).
#[must_use]
#[inline]
pub fn occluded(shape: Shape, ray: &Ray, t_max: f64) -> bool {
    match shape {
        Shape::Sphere => sphere::occluded(ray, t_max),
        Shape::Plane => plane::occluded(ray, t_max),
        Shape::Cube => cube::occluded(ray, t_max),
        Shape::Cylinder => cylinder::occluded(ray, t_max),
        Shape::Cone => cone::occluded(ray, t_max),
    }
}

/// Picks the nearer of two optional hits.
#[inline]
fn nearer(a: Option<ShapeHit>, b: Option<ShapeHit>) -> Option<ShapeHit> {
    match (a, b) {
        (Some(a), Some(b)) => Some(if b.t < a.t { b } else { a }),
        (a, None) => a,
        (None, b) => b,
    }
}

/// The hit on a flat disc cap `z = z_cap`, radius 1, with outward normal `(0, 0, z_cap)`
/// scaled to unit length; shared by the cylinder and the cone.
#[inline]
fn disc_cap(ray: &Ray, t_max: f64, z_cap: f64, normal_z: f64) -> Option<ShapeHit> {
    if ray.dir.z == 0.0 {
        return None;
    }
    let t = (z_cap - ray.origin.z) / ray.dir.z;
    if !in_range(ray, t, t_max) {
        return None;
    }
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

#[cfg(test)]
pub(crate) mod test_support {
    //! Shared checks for the shape tests.
    use super::*;

    /// Asserts a hit at parameter `t` with the given unit outward normal.
    pub fn assert_hit(hit: Option<ShapeHit>, ray: &Ray, t: f64, normal: DVec3) {
        let hit = hit.unwrap_or_else(|| panic!("expected a hit at t = {t} for {ray:?}"));
        assert!(
            (hit.t - t).abs() <= 1e-12 * t.abs().max(1.0),
            "t = {} expected {t}",
            hit.t
        );
        assert!(
            (hit.n.normalize() - normal).length() < 1e-9,
            "normal {} expected {normal}",
            hit.n
        );
        assert!((hit.p - ray.at(hit.t)).length() < 1e-9);
        assert!(hit.p.is_finite() && hit.p_error.is_finite());
    }
}
