//! The tube: the solid between the cylinders of radius `inner` and 1, -1 <= z <= 1,
//! closed by flat rings at z = -1 and z = 1.
//!
//! Along a line it is the outer cylinder's span with the hole's span taken out: at most
//! two pieces. Working with spans rather than with the six surfaces one by one keeps a
//! ray through a rim (where a barrel meets a ring) from counting the rim twice.

use glam::{DVec2, DVec3};

use super::bounds::Aabb;
use super::hit::{ShapeHit, gamma, in_range};
use super::quadratic::unit_ball_roots;
use crate::trace::ray::Ray;

/// Object-space bounds.
pub fn bounds() -> Aabb {
    Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0))
}

/// The `t` range where the line is within the infinite cylinder of `radius`.
fn barrel_span(ray: &Ray, radius: f64) -> Option<[f64; 2]> {
    let o = DVec2::new(ray.origin.x, ray.origin.y) / radius;
    let d = DVec2::new(ray.dir.x, ray.dir.y) / radius;
    if d == DVec2::ZERO {
        // Along the axis: inside for ever, or never.
        return (o.length_squared() <= 1.0).then_some([f64::NEG_INFINITY, f64::INFINITY]);
    }
    unit_ball_roots(o, d)
}

/// The `t` range where the line is within the slab -1 <= z <= 1.
fn slab_span(ray: &Ray) -> Option<[f64; 2]> {
    if ray.dir.z == 0.0 {
        return (ray.origin.z.abs() <= 1.0).then_some([f64::NEG_INFINITY, f64::INFINITY]);
    }
    let a = (-1.0 - ray.origin.z) / ray.dir.z;
    let b = (1.0 - ray.origin.z) / ray.dir.z;
    Some(if a <= b { [a, b] } else { [b, a] })
}

/// The surface point at `t`, which bounds the solid where `part` says.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Part {
    /// The outer barrel, or the inner one (its normal facing into the hole).
    Barrel { radius: f64, outward: f64 },
    /// A ring at z = `z`.
    Ring { z: f64 },
}

/// The hit at `t` on `part`, moved onto it exactly.
fn point(ray: &Ray, t: f64, part: Part) -> ShapeHit {
    let p = ray.at(t);
    match part {
        Part::Barrel { radius, outward } => {
            let r = (p.x * p.x + p.y * p.y).sqrt();
            let (x, y) = if r > 0.0 {
                (p.x / r * radius, p.y / r * radius)
            } else {
                (radius, 0.0)
            };
            let p = DVec3::new(x, y, p.z.clamp(-1.0, 1.0));
            ShapeHit {
                t,
                p,
                n: DVec3::new(x, y, 0.0) * outward,
                p_error: DVec3::new(gamma(6) * x.abs(), gamma(6) * y.abs(), gamma(3) * p.z.abs()),
            }
        }
        Part::Ring { z } => ShapeHit {
            t,
            p: DVec3::new(p.x, p.y, z),
            n: DVec3::new(0.0, 0.0, z),
            p_error: DVec3::new(gamma(3) * p.x.abs(), gamma(3) * p.y.abs(), 0.0),
        },
    }
}

/// The outer cylinder's part where its span begins (`entering`) or ends: the barrel
/// where the barrel's span is the tighter one, else a ring.
fn outer_part(ray: &Ray, barrel: [f64; 2], slab: [f64; 2], entering: bool) -> Part {
    let on_barrel = if entering {
        barrel[0] >= slab[0]
    } else {
        barrel[1] <= slab[1]
    };
    if on_barrel {
        Part::Barrel {
            radius: 1.0,
            outward: 1.0,
        }
    } else {
        // Entering upwards meets the bottom ring; leaving upwards, the top one.
        let up = ray.dir.z > 0.0;
        Part::Ring {
            z: if up == entering { -1.0 } else { 1.0 },
        }
    }
}

/// Crossings of the whole line, ascending, in entry and exit pairs: at most two pairs.
#[derive(Clone, Copy, Debug, Default)]
struct Crossings {
    points: [Option<(f64, Part)>; 4],
}

impl Crossings {
    fn iter(&self) -> impl Iterator<Item = (f64, Part)> + '_ {
        self.points.iter().flatten().copied()
    }
}

/// The outer cylinder's span with the hole's taken out.
fn line_crossings(ray: &Ray, inner: f64) -> Crossings {
    let mut out = Crossings::default();
    let (Some(barrel), Some(slab)) = (barrel_span(ray, 1.0), slab_span(ray)) else {
        return out;
    };
    let (enter, exit) = (barrel[0].max(slab[0]), barrel[1].min(slab[1]));
    if !(enter <= exit && enter.is_finite() && exit.is_finite()) {
        return out;
    }
    let first = (enter, outer_part(ray, barrel, slab, true));
    let last = (exit, outer_part(ray, barrel, slab, false));
    let hole_side = Part::Barrel {
        radius: inner,
        outward: -1.0,
    };
    // A line only touching the hole's barrel does not open it.
    let hole = barrel_span(ray, inner).filter(|[h0, h1]| h0 < h1 && *h1 > enter && *h0 < exit);
    out.points = match hole {
        None => [Some(first), Some(last), None, None],
        Some([h0, h1]) => {
            let before = (h0 > enter).then_some([Some(first), Some((h0, hole_side))]);
            let after = (h1 < exit).then_some([Some((h1, hole_side)), Some(last)]);
            match (before, after) {
                (Some([a, b]), Some([c, d])) => [a, b, c, d],
                (Some([a, b]), None) | (None, Some([a, b])) => [a, b, None, None],
                (None, None) => [None; 4],
            }
        }
    };
    out
}

/// The closest hit with `t` in (0, t_max).
pub fn intersect(ray: &Ray, t_max: f64, inner: f64) -> Option<ShapeHit> {
    line_crossings(ray, inner)
        .iter()
        .find(|&(t, _)| in_range(ray, t, t_max))
        .map(|(t, part)| point(ray, t, part))
}

/// Whether any hit has `t` in (0, t_max).
pub fn occluded(ray: &Ray, t_max: f64, inner: f64) -> bool {
    line_crossings(ray, inner)
        .iter()
        .any(|(t, _)| in_range(ray, t, t_max))
}

/// Every crossing of the whole line, for CSG.
pub(crate) fn crossings(ray: &Ray, out: &mut Vec<ShapeHit>, inner: f64) {
    out.extend(
        line_crossings(ray, inner)
            .iter()
            .map(|(t, part)| point(ray, t, part)),
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::shapes::test_support::assert_hit;

    const INNER: f64 = 0.5;

    #[test]
    fn through_the_wall_from_outside_and_from_the_hole() {
        let ray = Ray::new(DVec3::new(-3.0, 0.0, 0.0), DVec3::X);
        assert_hit(intersect(&ray, f64::INFINITY, INNER), &ray, 2.0, -DVec3::X);
        let mut out = Vec::new();
        crossings(&ray, &mut out, INNER);
        let ts: Vec<f64> = out.iter().map(|h| h.t).collect();
        assert_eq!(ts, vec![2.0, 2.5, 3.5, 4.0]);
        // The inner barrel's normal faces into the hole.
        assert!(out[1].n.x > 0.0 && out[2].n.x < 0.0);
        let from_hole = Ray::new(DVec3::ZERO, DVec3::Y);
        assert_hit(
            intersect(&from_hole, f64::INFINITY, INNER),
            &from_hole,
            0.5,
            -DVec3::Y,
        );
    }

    #[test]
    fn down_the_hole_misses_and_onto_a_ring_hits() {
        let down = Ray::new(DVec3::new(0.2, 0.1, 5.0), -DVec3::Z);
        assert!(intersect(&down, f64::INFINITY, INNER).is_none());
        let onto_ring = Ray::new(DVec3::new(0.75, 0.0, 5.0), -DVec3::Z);
        assert_hit(
            intersect(&onto_ring, f64::INFINITY, INNER),
            &onto_ring,
            4.0,
            DVec3::Z,
        );
        // Out of the wall through the bottom ring.
        let in_wall = Ray::new(DVec3::new(0.0, -0.75, 0.0), -DVec3::Z);
        assert_hit(
            intersect(&in_wall, f64::INFINITY, INNER),
            &in_wall,
            1.0,
            -DVec3::Z,
        );
    }

    #[test]
    fn into_the_hole_through_its_opening() {
        // Slanting in through the top opening, then into the inner barrel.
        let ray = Ray::new(DVec3::new(0.0, 0.0, 2.0), DVec3::new(0.25, 0.0, -1.0));
        let hit = intersect(&ray, f64::INFINITY, INNER).unwrap();
        assert!((hit.t - 2.0).abs() < 1e-12, "{}", hit.t);
        assert!((hit.p - DVec3::new(0.5, 0.0, 0.0)).length() < 1e-12);
        assert!(hit.n.x < 0.0);
    }

    #[test]
    fn through_a_rim_counts_once() {
        // Down the line x = 1 onto the outer rim of the top ring.
        let ray = Ray::new(DVec3::new(1.0, 0.0, 5.0), -DVec3::Z);
        let mut out = Vec::new();
        crossings(&ray, &mut out, INNER);
        assert_eq!(out.len() % 2, 0);
        let hit = intersect(&ray, f64::INFINITY, INNER).unwrap();
        assert_eq!(hit.t, 4.0);
        assert!(hit.n.is_finite());
    }

    #[test]
    fn tangent_to_the_hole_passes_through_the_wall_whole() {
        // Along y at x = inner: inside the wall but for one point of the inner barrel.
        let ray = Ray::new(DVec3::new(INNER, -3.0, 0.0), DVec3::Y);
        let mut out = Vec::new();
        crossings(&ray, &mut out, INNER);
        assert_eq!(out.len(), 2, "{out:?}");
    }
}
