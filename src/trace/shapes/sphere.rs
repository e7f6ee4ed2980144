//! The unit sphere: centre at the origin, radius 1.

use glam::DVec3;

use super::bounds::Aabb;
use super::hit::{ShapeHit, gamma, in_range};
use super::quadratic::unit_ball_roots;
use crate::trace::ray::Ray;

/// Object-space bounds.
pub fn bounds() -> Aabb {
    Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0))
}

/// Both roots of the ray with the sphere, if any (see `unit_ball_roots` for the
/// cancellation-free discriminant).
fn roots(ray: &Ray) -> Option<[f64; 2]> {
    unit_ball_roots(ray.origin, ray.dir)
}

/// The closest hit with `t` in (0, t_max).
pub fn intersect(ray: &Ray, t_max: f64) -> Option<ShapeHit> {
    let [t0, t1] = roots(ray)?;
    let t = if in_range(ray, t0, t_max) {
        t0
    } else if in_range(ray, t1, t_max) {
        t1
    } else {
        return None;
    };
    // Re-project onto the sphere: the error is then a few roundings of |p| = 1.
    let p = ray.at(t);
    let p = p / p.length();
    Some(ShapeHit {
        t,
        p,
        n: p,
        p_error: gamma(5) * p.abs(),
    })
}

/// Every crossing of the whole line (any `t`), ascending, with outward normals: the
/// entry and the exit, for CSG (see `super::crossings`).
pub(crate) fn crossings(ray: &Ray, out: &mut Vec<ShapeHit>) {
    if let Some(roots) = roots(ray) {
        out.extend(roots.map(|t| crossing_at(ray, t)));
    }
}

/// The ends of the whole line's span (`crossings`' two `t`s without their points), for
/// CSG leaves that work out a surface point only for the crossing a query answers with.
pub(crate) fn line_span(ray: &Ray) -> Option<[f64; 2]> {
    roots(ray)
}

/// The crossing at `t`, one of [`line_span`]'s, as [`crossings`] gives it.
pub(crate) fn crossing_at(ray: &Ray, t: f64) -> ShapeHit {
    let p = ray.at(t);
    let p = p / p.length();
    ShapeHit {
        t,
        p,
        n: p,
        p_error: gamma(5) * p.abs(),
    }
}

/// Whether any hit has `t` in (0, t_max).
pub fn occluded(ray: &Ray, t_max: f64) -> bool {
    roots(ray).is_some_and(|[t0, t1]| in_range(ray, t0, t_max) || in_range(ray, t1, t_max))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::shapes::test_support::assert_hit;

    #[test]
    fn hit_from_outside() {
        let ray = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        assert_hit(intersect(&ray, f64::INFINITY), &ray, 4.0, -DVec3::Z);
    }

    #[test]
    fn hit_from_inside_is_the_far_side() {
        let ray = Ray::new(DVec3::ZERO, DVec3::X * 2.0);
        assert_hit(intersect(&ray, f64::INFINITY), &ray, 0.5, DVec3::X);
    }

    #[test]
    fn miss_and_t_max() {
        let ray = Ray::new(DVec3::new(0.0, 1.5, -5.0), DVec3::Z);
        assert!(intersect(&ray, f64::INFINITY).is_none());
        let ray = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        assert!(intersect(&ray, 3.9).is_none());
        assert!(!occluded(&ray, 3.9));
        assert!(occluded(&ray, 4.1));
    }

    #[test]
    fn tangent_ray_touches_once() {
        let ray = Ray::new(DVec3::new(0.0, 1.0, -5.0), DVec3::Z);
        assert_hit(intersect(&ray, f64::INFINITY), &ray, 5.0, DVec3::Y);
    }

    #[test]
    fn far_away_ray_keeps_precision() {
        // From 1e8 away the naive discriminant cancels to garbage.
        let ray = Ray::new(DVec3::new(0.0, 0.5, -1e8), DVec3::Z);
        let hit = intersect(&ray, f64::INFINITY).unwrap();
        let expected = 1e8 - (0.75f64).sqrt();
        assert!((hit.t - expected).abs() < 1e-7, "{}", hit.t);
        assert!((hit.p.length() - 1.0).abs() < 1e-15);
    }
}
