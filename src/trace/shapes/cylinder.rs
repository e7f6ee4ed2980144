//! The unit cylinder: x^2 + y^2 = 1 for -1 <= z <= 1, closed by disc caps at z = +-1.

use glam::{DVec2, DVec3};

use super::bounds::Aabb;
use super::caps::{cap_point_at, cap_t, disc_cap};
use super::hit::{ConvexEnds, ConvexSolid, ShapeHit, gamma, in_range, nearer};
use super::quadratic::unit_ball_roots;
use crate::trace::ray::Ray;

/// Object-space bounds.
pub fn bounds() -> Aabb {
    Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0))
}

/// Roots with the infinite side x^2 + y^2 = 1: the unit disc's boundary in the xy plane.
/// A ray along the axis (no xy motion) has none.
fn side_roots(ray: &Ray) -> Option<[f64; 2]> {
    let o = DVec2::new(ray.origin.x, ray.origin.y);
    let d = DVec2::new(ray.dir.x, ray.dir.y);
    unit_ball_roots(o, d)
}

/// The nearest side hit within the height range.
fn side_hit(ray: &Ray, t_max: f64) -> Option<ShapeHit> {
    let roots = side_roots(ray)?;
    let t = roots
        .into_iter()
        .find(|&t| in_range(ray, t, t_max) && ray.at(t).z.abs() <= 1.0)?;
    Some(side_point(ray, t))
}

/// The side hit at `t`, re-projected radially onto the unit circle; z is unchanged.
fn side_point(ray: &Ray, t: f64) -> ShapeHit {
    let p = ray.at(t);
    let r = (p.x * p.x + p.y * p.y).sqrt();
    let p = DVec3::new(p.x / r, p.y / r, p.z);
    ShapeHit {
        t,
        p,
        n: DVec3::new(p.x, p.y, 0.0),
        p_error: DVec3::new(
            gamma(5) * p.x.abs(),
            gamma(5) * p.y.abs(),
            gamma(3) * p.z.abs(),
        ),
    }
}

/// The unit cylinder as a convex solid: its crossings of a whole line, for CSG.
pub(crate) struct Cylinder;

impl ConvexSolid for Cylinder {
    const NAME: &'static str = "cylinder";

    /// Where the line enters and leaves, picked from where it meets each surface: the side's
    /// two roots within the height range, then the top and the bottom cap on their discs.
    fn ends(ray: &Ray) -> ConvexEnds {
        let mut ts = [None; 4];
        if let Some(roots) = side_roots(ray) {
            for (slot, t) in ts.iter_mut().zip(roots) {
                *slot = (ray.at(t).z.abs() <= 1.0).then_some(t);
            }
        }
        ts[2] = cap_t(ray, 1.0);
        ts[3] = cap_t(ray, -1.0);
        ConvexEnds::of(&ts)
    }

    /// The surface point of candidate `k` of [`Self::ends`], at its `t`.
    fn candidate_hit(ray: &Ray, k: usize, t: f64) -> ShapeHit {
        let (z_cap, normal_z) = match k {
            0 | 1 => return side_point(ray, t),
            2 => (1.0, 1.0),
            _ => (-1.0, -1.0),
        };
        cap_point_at(ray, t, z_cap, normal_z).expect("on the cap's disc, as `ends` found")
    }
}

/// The closest hit with `t` in (0, t_max): side or either cap. At a cap rim both agree.
pub fn intersect(ray: &Ray, t_max: f64) -> Option<ShapeHit> {
    let side = side_hit(ray, t_max);
    let t_limit = side.map_or(t_max, |h| h.t);
    let top = disc_cap(ray, t_limit, 1.0, 1.0);
    let bottom = disc_cap(ray, t_limit, -1.0, -1.0);
    nearer(side, nearer(top, bottom))
}

/// Whether any hit has `t` in (0, t_max).
pub fn occluded(ray: &Ray, t_max: f64) -> bool {
    side_hit(ray, t_max).is_some()
        || disc_cap(ray, t_max, 1.0, 1.0).is_some()
        || disc_cap(ray, t_max, -1.0, -1.0).is_some()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::shapes::test_support::assert_hit;

    #[test]
    fn side_from_outside_and_inside() {
        let ray = Ray::new(DVec3::new(-3.0, 0.0, 0.5), DVec3::X);
        assert_hit(intersect(&ray, f64::INFINITY), &ray, 2.0, -DVec3::X);
        let inside = Ray::new(DVec3::new(0.0, 0.0, 0.5), DVec3::Y);
        assert_hit(intersect(&inside, f64::INFINITY), &inside, 1.0, DVec3::Y);
    }

    #[test]
    fn along_the_axis_hits_a_cap() {
        let ray = Ray::new(DVec3::new(0.0, 0.0, 5.0), -DVec3::Z);
        assert_hit(intersect(&ray, f64::INFINITY), &ray, 4.0, DVec3::Z);
        let inside = Ray::new(DVec3::ZERO, -DVec3::Z);
        assert_hit(intersect(&inside, f64::INFINITY), &inside, 1.0, -DVec3::Z);
    }

    #[test]
    fn misses_above_and_beside() {
        let above = Ray::new(DVec3::new(-3.0, 0.0, 1.5), DVec3::X);
        assert!(intersect(&above, f64::INFINITY).is_none());
        let beside = Ray::new(DVec3::new(0.0, 1.5, 5.0), -DVec3::Z);
        assert!(intersect(&beside, f64::INFINITY).is_none());
    }

    #[test]
    fn exactly_through_the_cap_rim() {
        // Down the line x = 1, y = 0: touches the rim of the top cap at t = 4.
        let ray = Ray::new(DVec3::new(1.0, 0.0, 5.0), -DVec3::Z);
        let hit = intersect(&ray, f64::INFINITY).unwrap();
        assert_eq!(hit.t, 4.0);
        assert_eq!(hit.p, DVec3::new(1.0, 0.0, 1.0));
        // Diagonally through the rim from outside: enters exactly at the rim.
        let ray = Ray::new(DVec3::new(2.0, 0.0, 2.0), DVec3::new(-1.0, 0.0, -1.0));
        let hit = intersect(&ray, f64::INFINITY).unwrap();
        assert!((hit.t - 1.0).abs() < 1e-15 && hit.n.is_finite());
    }

    #[test]
    fn tangent_to_the_side() {
        let ray = Ray::new(DVec3::new(-3.0, 1.0, 0.0), DVec3::X);
        assert_hit(intersect(&ray, f64::INFINITY), &ray, 3.0, DVec3::Y);
    }
}
