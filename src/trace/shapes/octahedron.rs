//! The unit octahedron |x| + |y| + |z| <= 1: the overlap of four slabs -1 <= s.p <= 1,
//! one for each pair of opposite faces (s a sign vector: (1, 1, 1), (1, 1, -1),
//! (1, -1, 1), (-1, 1, 1)). Tested like the cube, slab by slab, so shared edges and
//! vertices belong to both faces and no ray slips between them.

use glam::DVec3;

use super::bounds::Aabb;
use super::hit::{ShapeHit, gamma, in_range};
use super::slabs::{SlabSpan, slab_span};
use crate::trace::ray::Ray;

/// The four face normals (unnormalised), one per pair of opposite faces.
const SLABS: [DVec3; 4] = [
    DVec3::new(1.0, 1.0, 1.0),
    DVec3::new(1.0, 1.0, -1.0),
    DVec3::new(1.0, -1.0, 1.0),
    DVec3::new(-1.0, 1.0, 1.0),
];

/// Object-space bounds.
pub fn bounds() -> Aabb {
    Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0))
}

/// The slab test over the four pairs of opposite faces.
#[inline(always)]
fn span(ray: &Ray) -> Option<SlabSpan> {
    slab_span::<4>(ray, |v, slab| SLABS[slab].dot(v))
}

/// The hit at `t` on the face of `slab` on the side `side` (+1 or -1): the point moved
/// onto the face's plane along its normal, with the outward normal.
fn face_hit(ray: &Ray, t: f64, slab: usize, side: f64) -> ShapeHit {
    let normal = SLABS[slab] * side;
    let p = ray.at(t);
    // s.p = 1 on the face: move p by the residual along s (|s|^2 = 3).
    let p = p + normal * ((1.0 - normal.dot(p)) / 3.0);
    // The move and the dot product carry a few roundings of the largest coordinate.
    let p_error = DVec3::splat(gamma(7) * p.abs().max_element());
    ShapeHit {
        t,
        p,
        n: normal,
        p_error,
    }
}

/// Which side of its slab the ray meets at `t`: where s.p is positive, the + face.
fn side_at(ray: &Ray, t: f64, slab: usize) -> f64 {
    if SLABS[slab].dot(ray.at(t)) >= 0.0 {
        1.0
    } else {
        -1.0
    }
}

/// The closest hit with `t` in (0, t_max): the entry face, or the exit face from inside.
pub fn intersect(ray: &Ray, t_max: f64) -> Option<ShapeHit> {
    let s = span(ray)?;
    let (t, slab) = if in_range(ray, s.t_near, t_max) {
        (s.t_near, s.near_slab)
    } else if in_range(ray, s.t_far, t_max) {
        (s.t_far, s.far_slab)
    } else {
        return None;
    };
    Some(face_hit(ray, t, slab, side_at(ray, t, slab)))
}

/// Both crossings of the whole line (entry, exit), for CSG.
pub(crate) fn crossings(ray: &Ray, out: &mut Vec<ShapeHit>) {
    let Some(s) = span(ray) else { return };
    if !(s.t_near.is_finite() && s.t_far.is_finite()) {
        return;
    }
    for (t, slab, entering) in [(s.t_near, s.near_slab, true), (s.t_far, s.far_slab, false)] {
        // The entry face faces against the ray, the exit face with it.
        let along = if SLABS[slab].dot(ray.dir) > 0.0 {
            1.0
        } else {
            -1.0
        };
        let side = if entering { -along } else { along };
        out.push(face_hit(ray, t, slab, side));
    }
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
    fn a_ray_along_an_axis_meets_a_vertex() {
        let ray = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        let hit = intersect(&ray, f64::INFINITY).expect("the vertex (0, 0, -1)");
        assert!((hit.t - 4.0).abs() < 1e-12, "{}", hit.t);
        assert!((hit.p - DVec3::new(0.0, 0.0, -1.0)).length() < 1e-12);
    }

    #[test]
    fn a_face_is_hit_at_its_plane_with_its_normal() {
        // Towards the centre of the (+,+,+) face, (1/3, 1/3, 1/3).
        let target = DVec3::splat(1.0 / 3.0);
        let origin = target + DVec3::splat(2.0);
        let ray = Ray::new(origin, -DVec3::ONE);
        let t = 2.0;
        assert_hit(
            intersect(&ray, f64::INFINITY),
            &ray,
            t,
            DVec3::ONE.normalize(),
        );
    }

    #[test]
    fn from_inside_the_exit_face_and_a_miss_past_an_edge() {
        let ray = Ray::new(DVec3::ZERO, DVec3::X);
        assert_hit(
            intersect(&ray, f64::INFINITY),
            &ray,
            1.0,
            DVec3::new(1.0, 1.0, 1.0).normalize(),
        );
        // x + y = 1.2 > 1 at z = 0: outside, though inside the bounding cube.
        let ray = Ray::new(DVec3::new(0.6, 0.6, -5.0), DVec3::Z);
        assert!(intersect(&ray, f64::INFINITY).is_none());
        assert!(!occluded(&ray, f64::INFINITY));
    }

    #[test]
    fn rays_at_the_shared_edges_never_slip_through() {
        // Aimed at points on the edge between the (+,+,+) and (+,+,-) faces (z = 0,
        // x + y = 1), from several directions: each hits.
        for k in 0..=20 {
            let x = f64::from(k) / 20.0;
            let edge = DVec3::new(x, 1.0 - x, 0.0);
            for dir in [
                DVec3::new(-1.0, -1.0, 0.0),
                DVec3::new(-1.0, -0.3, 0.2),
                DVec3::NEG_X,
            ] {
                let ray = Ray::new(edge - dir * 3.0, dir);
                assert!(
                    occluded(&ray, f64::INFINITY),
                    "slipped past {edge} along {dir}"
                );
            }
        }
    }
}
