//! What every shape's tests return and share: the hit record with its error bound, the
//! error factor `gamma`, the range check that keeps a ray off the surface it starts on,
//! and picking among candidate hits.

use glam::DVec3;

use crate::trace::ray::Ray;

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
pub(crate) fn in_range(ray: &Ray, t: f64, t_max: f64) -> bool {
    if !(t > 0.0 && t < t_max) {
        return false;
    }
    let origin_rounding = gamma(8) * ray.origin.abs().max_element().max(1.0);
    t * t * ray.dir.length_squared() > origin_rounding * origin_rounding
}

/// Picks the nearer of two optional hits.
#[inline]
pub(crate) fn nearer(a: Option<ShapeHit>, b: Option<ShapeHit>) -> Option<ShapeHit> {
    match (a, b) {
        (Some(a), Some(b)) => Some(if b.t < a.t { b } else { a }),
        (a, None) => a,
        (None, b) => b,
    }
}

/// Which of a convex solid's candidate surface points along a line (`t` where the line
/// meets that surface, `None` where it does not) are its entry and exit: the smallest
/// and largest `t`, the earlier candidate where two tie, as [`first_and_last`] picks.
pub(crate) fn first_and_last_of(candidates: &[Option<f64>]) -> Option<(usize, usize)> {
    let mut span: Option<(usize, usize)> = None;
    for (k, t) in candidates.iter().enumerate() {
        let Some(t) = *t else { continue };
        let t_of = |i: usize| candidates[i].expect("a chosen candidate");
        span = Some(match span {
            None => (k, k),
            Some((first, last)) => (
                if t < t_of(first) { k } else { first },
                if t > t_of(last) { k } else { last },
            ),
        });
    }
    span
}

/// Appends the first and the last of a convex solid's surface points along a line: its
/// entry and exit.
pub(crate) fn first_and_last(candidates: impl Iterator<Item = ShapeHit>, out: &mut Vec<ShapeHit>) {
    let mut span: Option<(ShapeHit, ShapeHit)> = None;
    for hit in candidates {
        span = Some(match span {
            None => (hit, hit),
            Some((first, last)) => (
                if hit.t < first.t { hit } else { first },
                if hit.t > last.t { hit } else { last },
            ),
        });
    }
    if let Some((first, last)) = span {
        out.extend([first, last]);
    }
}
