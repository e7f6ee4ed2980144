//! The unit cube [-1, 1]^3.

use glam::DVec3;

use super::bounds::Aabb;
use super::hit::{ShapeHit, gamma, in_range};
use super::slabs::{SlabSpan, slab_span};
use crate::trace::ray::Ray;

/// Object-space bounds.
pub fn bounds() -> Aabb {
    Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0))
}

/// The slab test over the three axes.
#[inline(always)]
fn span(ray: &Ray) -> Option<SlabSpan> {
    slab_span::<3>(ray, |v, axis| v[axis])
}

/// The closest hit with `t` in (0, t_max): the entry face, or the exit face from inside.
pub fn intersect(ray: &Ray, t_max: f64) -> Option<ShapeHit> {
    let s = span(ray)?;
    let (t, axis) = if in_range(ray, s.t_near, t_max) {
        (s.t_near, s.near_slab)
    } else if in_range(ray, s.t_far, t_max) {
        (s.t_far, s.far_slab)
    } else {
        return None;
    };
    // Re-project: the face coordinate is exactly +-1, the others are clamped into the face.
    let mut p = ray.at(t).clamp(DVec3::splat(-1.0), DVec3::splat(1.0));
    let side = if ray.at(t)[axis] >= 0.0 { 1.0 } else { -1.0 };
    p[axis] = side;
    let mut n = DVec3::ZERO;
    n[axis] = side;
    let mut p_error = gamma(3) * p.abs();
    p_error[axis] = 0.0;
    Some(ShapeHit { t, p, n, p_error })
}

/// Both crossings of the whole line (entry, exit), for CSG.
pub(crate) fn crossings(ray: &Ray, out: &mut Vec<ShapeHit>) {
    if let Some(s) = line_slabs(ray) {
        out.extend([crossing(ray, &s, 0), crossing(ray, &s, 1)]);
    }
}

/// The slab span of the whole line, if it crosses the cube (a zero direction does not).
fn line_slabs(ray: &Ray) -> Option<SlabSpan> {
    span(ray).filter(|s| s.t_near.is_finite() && s.t_far.is_finite())
}

/// The ends of the whole line's span (`crossings`' two `t`s without their points), for
/// CSG leaves that work out a surface point only for the crossing a query answers with.
pub(crate) fn line_span(ray: &Ray) -> Option<[f64; 2]> {
    line_slabs(ray).map(|s| [s.t_near, s.t_far])
}

/// Crossing `k` of the line (0 the entry, 1 the exit), as [`crossings`] gives it; the
/// line must cross the cube ([`line_span`] is `Some`).
pub(crate) fn crossing_of_line(ray: &Ray, k: usize) -> ShapeHit {
    let s = line_slabs(ray).expect("a crossing of a line that crosses the cube");
    crossing(ray, &s, k)
}

/// Crossing `k` (0 the entry, 1 the exit) of a line with slab span `s`.
fn crossing(ray: &Ray, s: &SlabSpan, k: usize) -> ShapeHit {
    let (t, axis, entering) = if k == 0 {
        (s.t_near, s.near_slab, true)
    } else {
        (s.t_far, s.far_slab, false)
    };
    // The entry face faces against the ray along its axis, the exit face with it.
    let along = if ray.dir[axis] > 0.0 { 1.0 } else { -1.0 };
    let side = if entering { -along } else { along };
    let mut p = ray.at(t).clamp(DVec3::splat(-1.0), DVec3::splat(1.0));
    p[axis] = side;
    let mut n = DVec3::ZERO;
    n[axis] = side;
    let mut p_error = gamma(3) * p.abs();
    p_error[axis] = 0.0;
    ShapeHit { t, p, n, p_error }
}

/// Whether any hit has `t` in (0, t_max).
pub fn occluded(ray: &Ray, t_max: f64) -> bool {
    span(ray).is_some_and(|s| in_range(ray, s.t_near, t_max) || in_range(ray, s.t_far, t_max))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::shapes::test_support::assert_hit;

    #[test]
    fn hits_each_face_from_outside() {
        for axis in 0..3 {
            for side in [-1.0, 1.0] {
                let mut o = DVec3::splat(0.25);
                o[axis] = 3.0 * side;
                let mut d = DVec3::ZERO;
                d[axis] = -side;
                let ray = Ray::new(o, d);
                let mut n = DVec3::ZERO;
                n[axis] = side;
                assert_hit(intersect(&ray, f64::INFINITY), &ray, 2.0, n);
            }
        }
    }

    #[test]
    fn from_inside_hits_the_exit_face() {
        let ray = Ray::new(DVec3::ZERO, DVec3::new(0.0, -0.5, 0.0));
        assert_hit(intersect(&ray, f64::INFINITY), &ray, 2.0, -DVec3::Y);
    }

    #[test]
    fn origin_on_a_face_plane_with_zero_direction_component_is_not_nan() {
        let ray = Ray::new(DVec3::new(1.0, 0.0, -3.0), DVec3::Z);
        assert_hit(intersect(&ray, f64::INFINITY), &ray, 2.0, -DVec3::Z);
        let ray = Ray::new(DVec3::new(1.5, 0.0, -3.0), DVec3::Z);
        assert!(intersect(&ray, f64::INFINITY).is_none());
    }

    #[test]
    fn exactly_through_an_edge() {
        let ray = Ray::new(DVec3::new(-3.0, -3.0, 0.5), DVec3::new(1.0, 1.0, 0.0));
        let hit = intersect(&ray, f64::INFINITY).unwrap();
        assert_eq!(hit.t, 2.0);
        assert_eq!(hit.p, DVec3::new(-1.0, -1.0, 0.5));
        assert_eq!(hit.n.length(), 1.0);
    }
}
