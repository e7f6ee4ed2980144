//! The unit plane: the two-sided square z = 0, -1 <= x, y <= 1.

use glam::DVec3;

use super::bounds::Aabb;
use super::{ShapeHit, gamma, in_range};
use crate::trace::ray::Ray;

/// Object-space bounds (flat in z).
pub fn bounds() -> Aabb {
    Aabb::new(DVec3::new(-1.0, -1.0, 0.0), DVec3::new(1.0, 1.0, 0.0))
}

/// The ray parameter at z = 0, when that point lies inside the square.
fn hit_t(ray: &Ray, t_max: f64) -> Option<f64> {
    if ray.dir.z == 0.0 {
        return None; // parallel to the plane: no isolated hit
    }
    let t = -ray.origin.z / ray.dir.z;
    if !in_range(ray, t, t_max) {
        return None;
    }
    let p = ray.at(t);
    (p.x.abs() <= 1.0 && p.y.abs() <= 1.0).then_some(t)
}

/// The closest hit with `t` in (0, t_max). The normal is +z; the caller turns it to
/// face the ray, which is what makes the plane two-sided.
pub fn intersect(ray: &Ray, t_max: f64) -> Option<ShapeHit> {
    let t = hit_t(ray, t_max)?;
    let p = ray.at(t);
    // z is exactly 0 after re-projection; x and y carry a few roundings.
    Some(ShapeHit {
        t,
        p: DVec3::new(p.x, p.y, 0.0),
        n: DVec3::Z,
        p_error: DVec3::new(gamma(3) * p.x.abs(), gamma(3) * p.y.abs(), 0.0),
    })
}

/// The crossing of the whole line with z = 0, for CSG, where the plane is the half-space
/// z <= 0 (outward normal +z); none for a line parallel to it (see `super::crossings`
/// for which side such a line is on).
pub(crate) fn crossings(ray: &Ray, out: &mut Vec<ShapeHit>) {
    if ray.dir.z == 0.0 {
        return;
    }
    let t = -ray.origin.z / ray.dir.z;
    let p = ray.at(t);
    out.push(ShapeHit {
        t,
        p: DVec3::new(p.x, p.y, 0.0),
        n: DVec3::Z,
        p_error: DVec3::new(gamma(3) * p.x.abs(), gamma(3) * p.y.abs(), 0.0),
    });
}

/// Whether any hit has `t` in (0, t_max).
pub fn occluded(ray: &Ray, t_max: f64) -> bool {
    hit_t(ray, t_max).is_some()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::shapes::test_support::assert_hit;

    #[test]
    fn hits_both_sides() {
        let down = Ray::new(DVec3::new(0.2, 0.3, 2.0), -DVec3::Z);
        assert_hit(intersect(&down, f64::INFINITY), &down, 2.0, DVec3::Z);
        let up = Ray::new(DVec3::new(0.2, 0.3, -2.0), DVec3::Z);
        assert_hit(intersect(&up, f64::INFINITY), &up, 2.0, DVec3::Z);
    }

    #[test]
    fn misses_outside_the_square_and_parallel_rays() {
        let outside = Ray::new(DVec3::new(1.5, 0.0, 2.0), -DVec3::Z);
        assert!(intersect(&outside, f64::INFINITY).is_none());
        let parallel = Ray::new(DVec3::new(0.0, 0.0, 0.0), DVec3::X);
        assert!(intersect(&parallel, f64::INFINITY).is_none());
    }

    #[test]
    fn edge_is_inclusive() {
        let edge = Ray::new(DVec3::new(1.0, -1.0, 1.0), -DVec3::Z);
        assert_hit(intersect(&edge, f64::INFINITY), &edge, 1.0, DVec3::Z);
    }
}
