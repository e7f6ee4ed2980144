//! The unit cone: x^2 + y^2 = z^2 for 0 <= z <= 1, apex at the origin, closed by a disc
//! cap of radius 1 at z = 1.

use glam::{DVec2, DVec3};

use super::bounds::Aabb;
use super::caps::{cap_point_at, cap_t, disc_cap};
use super::hit::{ConvexEnds, ConvexSolid, ShapeHit, gamma, in_range, nearer};
use super::quadratic::{difference_of_products, solve_quadratic, sorted};
use crate::trace::ray::Ray;

/// Object-space bounds.
pub fn bounds() -> Aabb {
    Aabb::new(DVec3::new(-1.0, -1.0, 0.0), DVec3::splat(1.0))
}

/// Roots with the double cone x^2 + y^2 - z^2 = 0.
///
/// a = dx^2 + dy^2 - dz^2 is zero for rays parallel to the side (the solver then treats
/// the equation as linear); each sum and the discriminant use fused multiply-adds so the
/// cancellation near that case loses as little as possible.
fn side_roots(ray: &Ray) -> Option<[f64; 2]> {
    let (o, d) = (ray.origin, ray.dir);
    let a = d.x.mul_add(d.x, difference_of_products(d.y, d.y, d.z, d.z));
    let h = o.x.mul_add(d.x, difference_of_products(o.y, d.y, o.z, d.z));
    let c = o.x.mul_add(o.x, difference_of_products(o.y, o.y, o.z, o.z));
    let magnitude = o.x * o.x + o.y * o.y + o.z * o.z;
    if c.abs() <= gamma(4) * magnitude && magnitude > 0.0 {
        // The origin is on the cone to within rounding: roots t = 0 and -2h/a.
        return (a != 0.0).then(|| sorted(0.0, -2.0 * h / a));
    }
    let mut disc = difference_of_products(h, h, a, c);
    // Every ray through the apex meets the cone in a double root there, where rounding
    // decides the sign of the discriminant; within its error bound it is zero.
    if disc < 0.0 && -disc <= gamma(8) * (h * h + (a * c).abs()) {
        disc = 0.0;
    }
    solve_quadratic(a, h, c, disc)
}

/// The outward normal at a point of the side: the gradient of x^2 + y^2 - z^2.
///
/// At the apex the gradient vanishes and every generator meets. There the normal is the
/// side's normal along the generator that rays next to this one hit, `(c, -1)` with `c`
/// the unit direction in the xy plane: against the ray's own xy direction for a ray
/// from outside (the generator facing it), along it for a ray from inside the cone
/// (the wall it runs into), and +x for a ray along the axis. So the apex is shaded like
/// the points around it, never with a normal (such as the axis) that no neighbour has.
fn side_normal(p: DVec3, ray: &Ray) -> DVec3 {
    let n = DVec3::new(p.x, p.y, -p.z);
    if n != DVec3::ZERO {
        return n;
    }
    let (o, d) = (ray.origin, ray.dir);
    let across = DVec2::new(d.x, d.y);
    let from_inside = o.z > 0.0 && o.x * o.x + o.y * o.y < o.z * o.z;
    let c = match across.try_normalize() {
        Some(c) if from_inside => c,
        Some(c) => -c,
        None => DVec2::X,
    };
    DVec3::new(c.x, c.y, -1.0)
}

/// The nearest side hit on the upper nappe, 0 <= z <= 1.
fn side_hit(ray: &Ray, t_max: f64) -> Option<ShapeHit> {
    let roots = side_roots(ray)?;
    let t = roots.into_iter().find(|&t| {
        let z = ray.at(t).z;
        in_range(ray, t, t_max) && (0.0..=1.0).contains(&z)
    })?;
    Some(side_point(ray, t))
}

/// The side hit at `t`, re-projected onto the line r = z in the point's half-plane: the
/// nearest point of the cone's generator is at r = z = (r + z) / 2.
fn side_point(ray: &Ray, t: f64) -> ShapeHit {
    let p = ray.at(t);
    let r = (p.x * p.x + p.y * p.y).sqrt();
    let s = (0.5 * (r + p.z)).clamp(0.0, 1.0);
    let p = if r > 0.0 {
        DVec3::new(p.x * (s / r), p.y * (s / r), s)
    } else {
        DVec3::ZERO // on the axis, a hit on the cone is the apex
    };
    ShapeHit {
        t,
        p,
        n: side_normal(p, ray),
        p_error: gamma(6) * p.abs() + DVec3::splat(gamma(6) * s),
    }
}

/// The unit cone as a convex solid: its crossings of a whole line, for CSG.
pub(crate) struct Cone;

impl ConvexSolid for Cone {
    const NAME: &'static str = "cone";

    /// Where the line enters and leaves, picked from where it meets each surface: the side's
    /// two roots on the upper nappe, then the cap on its disc.
    fn ends(ray: &Ray) -> ConvexEnds {
        let mut ts = [None; 3];
        if let Some(roots) = side_roots(ray) {
            for (slot, t) in ts.iter_mut().zip(roots) {
                *slot = (0.0..=1.0).contains(&ray.at(t).z).then_some(t);
            }
        }
        ts[2] = cap_t(ray, 1.0);
        ConvexEnds::of(&ts)
    }

    /// The surface point of candidate `k` of [`Self::ends`], at its `t`.
    fn candidate_hit(ray: &Ray, k: usize, t: f64) -> ShapeHit {
        if k < 2 {
            return side_point(ray, t);
        }
        cap_point_at(ray, t, 1.0, 1.0).expect("on the cap's disc, as `ends` found")
    }
}

/// The closest hit with `t` in (0, t_max): side or cap. At the cap rim both agree.
pub fn intersect(ray: &Ray, t_max: f64) -> Option<ShapeHit> {
    let side = side_hit(ray, t_max);
    let cap = disc_cap(ray, side.map_or(t_max, |h| h.t), 1.0, 1.0);
    nearer(side, cap)
}

/// Whether any hit has `t` in (0, t_max).
pub fn occluded(ray: &Ray, t_max: f64) -> bool {
    side_hit(ray, t_max).is_some() || disc_cap(ray, t_max, 1.0, 1.0).is_some()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::shapes::test_support::assert_hit;
    use std::f64::consts::FRAC_1_SQRT_2;

    #[test]
    fn side_from_outside() {
        // At z = 0.5 the radius is 0.5; normal (1, 0, -1)/sqrt(2) on the -x side flipped.
        let ray = Ray::new(DVec3::new(-3.0, 0.0, 0.5), DVec3::X);
        let n = DVec3::new(-FRAC_1_SQRT_2, 0.0, -FRAC_1_SQRT_2);
        assert_hit(intersect(&ray, f64::INFINITY), &ray, 2.5, n);
    }

    #[test]
    fn from_inside_hits_the_far_side() {
        let ray = Ray::new(DVec3::new(0.0, 0.0, 0.5), DVec3::Y);
        let n = DVec3::new(0.0, FRAC_1_SQRT_2, -FRAC_1_SQRT_2);
        assert_hit(intersect(&ray, f64::INFINITY), &ray, 0.5, n);
    }

    #[test]
    fn along_the_axis_from_above_hits_the_cap_then_from_below_the_apex() {
        let down = Ray::new(DVec3::new(0.0, 0.0, 3.0), -DVec3::Z);
        assert_hit(intersect(&down, f64::INFINITY), &down, 2.0, DVec3::Z);
        let up = Ray::new(DVec3::new(0.0, 0.0, -2.0), DVec3::Z);
        let hit = intersect(&up, f64::INFINITY).unwrap();
        assert_eq!(hit.t, 2.0);
        assert_eq!(hit.p, DVec3::ZERO);
        // The side's normal along the +x generator, as at the points next to the apex.
        assert_eq!(hit.n, DVec3::new(1.0, 0.0, -1.0));
    }

    #[test]
    fn the_apex_normal_is_the_side_normal_of_a_neighbouring_generator() {
        // From outside, slanting towards +x: the generator on the -x side faces the ray.
        let outside = Ray::new(DVec3::new(-2.0, 0.0, -1.0), DVec3::new(2.0, 0.0, 1.0));
        let hit = intersect(&outside, f64::INFINITY).unwrap();
        assert_eq!(hit.p, DVec3::ZERO);
        assert_eq!(hit.n, DVec3::new(-1.0, 0.0, -1.0));
        let nearby = Ray::new(DVec3::new(-2.0, 0.0, -1.0 + 1e-6), outside.dir);
        let near_n = intersect(&nearby, f64::INFINITY).unwrap().n.normalize();
        assert!((near_n - hit.n.normalize()).length() < 1e-5, "{near_n}");
        // From inside, down towards -y: the wall on the -y side.
        let inside = Ray::new(DVec3::new(0.0, 0.5, 1.0), DVec3::new(0.0, -0.5, -1.0));
        let hit = intersect(&inside, f64::INFINITY).unwrap();
        assert_eq!(hit.p, DVec3::ZERO);
        assert_eq!(hit.n, DVec3::new(0.0, -1.0, -1.0));
        assert!(
            hit.n.dot(inside.dir) > 0.0,
            "the outward normal, seen from inside"
        );
    }

    #[test]
    fn through_the_apex_at_an_angle() {
        let ray = Ray::new(DVec3::new(-2.0, 0.0, -1.0), DVec3::new(2.0, 0.0, 1.0));
        let hit = intersect(&ray, f64::INFINITY).unwrap();
        assert!((hit.t - 1.0).abs() < 1e-12, "{}", hit.t);
        assert!(hit.p.length() < 1e-12 && hit.n.is_finite() && hit.n != DVec3::ZERO);
    }

    #[test]
    fn parallel_to_the_side() {
        // Direction (1, 0, 1) is parallel to the generator x = z: a == 0, one root.
        let ray = Ray::new(DVec3::new(-0.5, 0.0, 0.0), DVec3::new(1.0, 0.0, 1.0));
        let hit = intersect(&ray, f64::INFINITY).unwrap();
        // (t - 0.5)^2 = t^2 gives t = 0.25: the point (-0.25, 0, 0.25) on the generator x = -z.
        assert!((hit.t - 0.25).abs() < 1e-15, "{}", hit.t);
        assert!((hit.p - DVec3::new(-0.25, 0.0, 0.25)).length() < 1e-15);
    }

    #[test]
    fn lower_nappe_is_not_part_of_the_cone() {
        let ray = Ray::new(DVec3::new(-3.0, 0.0, -0.5), DVec3::X);
        assert!(intersect(&ray, f64::INFINITY).is_none());
    }

    #[test]
    fn exactly_through_the_cap_rim() {
        let ray = Ray::new(DVec3::new(1.0, 0.0, 3.0), -DVec3::Z);
        let hit = intersect(&ray, f64::INFINITY).unwrap();
        assert_eq!(hit.t, 2.0);
        assert_eq!(hit.p, DVec3::new(1.0, 0.0, 1.0));
    }
}
