//! The torus: the solid of points within `minor` of the unit circle x^2 + y^2 = 1, z = 0.
//!
//! Its surface solves (|p|^2 + 1 - r^2)^2 = 4 (x^2 + y^2), a quartic along a ray. Three
//! things keep that robust:
//! - **A well-placed origin.** The ray is written from its point nearest the torus's
//!   centre, along the unit direction: the quartic's coefficients then stay of the order
//!   of the torus's size for any distance (a far ray's raw coefficients would cancel), and
//!   a ray whose nearest point lies outside the bounding sphere is rejected early.
//! - **Isolated roots.** `polynomial::roots_in` brackets each root between critical
//!   points and reports a tangent ray as one touch.
//! - **The exact surface decides.** Each root is moved onto the surface along its
//!   distance to the circle (the hit's error is that of the move, not of the root), and a
//!   root of the quartic's "lemon" (inside a horn or spindle torus: points within `minor`
//!   of the circle's *far* side) is not a surface point. A first hit must enter from
//!   outside and leave from inside, which drops roots rounding put on the wrong side of an
//!   origin lying on the surface.

use glam::DVec3;

use super::bounds::Aabb;
use super::hit::{ShapeHit, gamma, in_range};
use super::polynomial::Polynomial;
use crate::trace::ray::Ray;

/// Object-space bounds.
pub fn bounds(minor: f64) -> Aabb {
    let r = 1.0 + minor;
    Aabb::new(DVec3::new(-r, -r, -minor), DVec3::new(r, r, minor))
}

/// The ray rewritten from its point nearest the centre, `t = (u + s0) / len` for the
/// quartic's parameter `u` along the unit direction.
struct Frame {
    origin: DVec3,
    dir: DVec3,
    s0: f64,
    len: f64,
}

impl Frame {
    /// The frame, or `None` when the line misses the bounding sphere.
    fn new(ray: &Ray, minor: f64) -> Option<Frame> {
        let len = ray.dir.length();
        if !(len > 0.0 && len.is_finite()) {
            return None;
        }
        let dir = ray.dir / len;
        let s0 = -ray.origin.dot(dir);
        let origin = ray.origin + dir * s0;
        let outer = 1.0 + minor;
        (origin.length_squared() <= outer * outer * (1.0 + 1e-9)).then_some(Frame {
            origin,
            dir,
            s0,
            len,
        })
    }

    /// The half-length of the chord through the bounding sphere, widened by rounding.
    fn half_chord(&self, minor: f64) -> f64 {
        let outer = 1.0 + minor;
        (outer * outer - self.origin.length_squared())
            .max(0.0)
            .sqrt()
            * (1.0 + 1e-9)
            + 1e-9 * outer
    }

    /// The quartic in `u`.
    fn quartic(&self, minor: f64) -> Polynomial {
        let (o, d) = (self.origin, self.dir);
        let k = o.dot(d); // ~0 by construction; kept for exactness
        let g = o.length_squared() + (1.0 - minor) * (1.0 + minor);
        let a = d.x * d.x + d.y * d.y;
        let b = 2.0 * (o.x * d.x + o.y * d.y);
        let c = o.x * o.x + o.y * o.y;
        // (u^2 + 2 k u + g)^2 - 4 (a u^2 + b u + c)
        Polynomial::new(&[
            g * g - 4.0 * c,
            4.0 * k * g - 4.0 * b,
            4.0 * k * k + 2.0 * g - 4.0 * a,
            4.0 * k,
            1.0,
        ])
    }

    /// The range of `u` between `t_lo` and `t_hi` (world `t`), clipped to the bounding
    /// sphere's chord and to the slab |z| <= minor; `None` when that leaves nothing.
    fn range(&self, minor: f64, t_lo: f64, t_hi: f64) -> Option<(f64, f64)> {
        let chord = self.half_chord(minor);
        let mut lo = (t_lo * self.len - self.s0).max(-chord);
        let mut hi = (t_hi * self.len - self.s0).min(chord);
        let slab = minor * (1.0 + 1e-9);
        if self.dir.z != 0.0 {
            let a = (-slab - self.origin.z) / self.dir.z;
            let b = (slab - self.origin.z) / self.dir.z;
            lo = lo.max(a.min(b));
            hi = hi.min(a.max(b));
        } else if self.origin.z.abs() > slab {
            return None;
        }
        (lo <= hi).then_some((lo, hi))
    }

    fn t(&self, u: f64) -> f64 {
        (u + self.s0) / self.len
    }
}

/// The surface point near `p` and its outward normal: `p` moved along its direction from
/// the nearest point of the circle to distance `minor`. `None` for a root of the
/// quartic's lemon, which lies inside the solid.
fn on_surface(p: DVec3, minor: f64, ray: &Ray) -> Option<(DVec3, DVec3, DVec3)> {
    let radial = (p.x * p.x + p.y * p.y).sqrt();
    let near = (radial - 1.0) * (radial - 1.0) + p.z * p.z - minor * minor;
    let far = (radial + 1.0) * (radial + 1.0) + p.z * p.z - minor * minor;
    if far.abs() < near.abs() {
        return None;
    }
    let bound = |q: DVec3| DVec3::splat(gamma(12) * (1.0 + minor).max(q.abs().max_element()));
    if radial == 0.0 {
        // On the axis: a spindle torus's tip, or a horn torus's pinch at the centre.
        let tip = (minor * minor - 1.0).max(0.0).sqrt();
        let q = DVec3::new(0.0, 0.0, tip.copysign(p.z));
        let n = if tip > 0.0 {
            DVec3::new(0.0, 0.0, 1f64.copysign(p.z))
        } else {
            -ray.dir
        };
        return Some((q, n, bound(q)));
    }
    let centre = DVec3::new(p.x / radial, p.y / radial, 0.0);
    let n = (p - centre).normalize_or(DVec3::Z);
    let q = centre + n * minor;
    Some((q, n, bound(q)))
}

/// The hit at root `u`, if it is a surface point.
fn hit_at(ray: &Ray, frame: &Frame, u: f64, minor: f64) -> Option<ShapeHit> {
    let t = frame.t(u);
    let (p, n, p_error) = on_surface(ray.at(t), minor, ray)?;
    Some(ShapeHit { t, p, n, p_error })
}

/// Whether the ray starts inside the solid (by the origin's distance to the circle); an
/// origin on the surface to within rounding counts as inside when the ray heads in.
fn starts_inside(ray: &Ray, minor: f64) -> bool {
    let o = ray.origin;
    let radial = (o.x * o.x + o.y * o.y).sqrt();
    let from_circle = (radial - 1.0).hypot(o.z);
    if (from_circle - minor).abs() > gamma(8) * (1.0 + minor) {
        return from_circle < minor;
    }
    let centre = if radial > 0.0 {
        DVec3::new(o.x / radial, o.y / radial, 0.0)
    } else {
        DVec3::ZERO
    };
    (o - centre).dot(ray.dir) < 0.0
}

/// The closest hit with `t` in (0, t_max). A first hit that would enter from inside or
/// leave from outside is rounding at an origin on the surface, and is passed over.
pub fn intersect(ray: &Ray, t_max: f64, minor: f64) -> Option<ShapeHit> {
    let frame = Frame::new(ray, minor)?;
    let (lo, hi) = frame.range(minor, 0.0, t_max)?;
    let mut origin_inside = None;
    let mut found = None;
    frame.quartic(minor).visit_roots_in(lo, hi, &mut |root| {
        let Some(hit) = hit_at(ray, &frame, root.x, minor) else {
            return false;
        };
        if !in_range(ray, hit.t, t_max) {
            return false;
        }
        let inside = *origin_inside.get_or_insert_with(|| starts_inside(ray, minor));
        let leaving = hit.n.dot(ray.dir) > 0.0;
        if root.touch || leaving == inside {
            found = Some(hit);
        }
        found.is_some()
    });
    found
}

/// Whether any hit has `t` in (0, t_max).
pub fn occluded(ray: &Ray, t_max: f64, minor: f64) -> bool {
    intersect(ray, t_max, minor).is_some()
}

/// Every crossing of the whole line, ascending, in entry and exit pairs; a touch gives
/// its point twice.
pub(crate) fn crossings(ray: &Ray, out: &mut Vec<ShapeHit>, minor: f64) {
    let Some(frame) = Frame::new(ray, minor) else {
        return;
    };
    let start = out.len();
    let Some((lo, hi)) = frame.range(minor, f64::NEG_INFINITY, f64::INFINITY) else {
        return;
    };
    for root in frame.quartic(minor).roots_in(lo, hi).iter() {
        if let Some(hit) = hit_at(ray, &frame, root.x, minor) {
            out.push(hit);
            if root.touch {
                out.push(hit);
            }
        }
    }
    // Rounding can leave an odd count at a cluster of roots: an unpaired crossing
    // would turn the rest of the line inside out, so keep whole pairs only.
    if (out.len() - start) % 2 == 1 {
        out.pop();
    }
}

#[cfg(test)]
mod tests;
