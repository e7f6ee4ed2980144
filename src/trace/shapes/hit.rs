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

/// A convex solid's entry and exit along a whole line, picked from its candidate surface
/// points: per surface (a side root, a cap) the `t` where the line meets it, or `None`.
/// They are the smallest and largest `t` (the earlier candidate where two tie), and only
/// those two ever get a surface point: the cylinder's and the cone's `crossings`, and
/// the two-`t` spans of CSG leaves, all read them from here (through [`ConvexSolid`]).
pub(crate) struct ConvexEnds {
    /// The entry's and the exit's candidate and `t`, if the line meets the solid.
    ends: Option<[(usize, f64); 2]>,
}

impl ConvexEnds {
    #[inline]
    pub fn of(candidates: &[Option<f64>]) -> Self {
        let mut ends: Option<[(usize, f64); 2]> = None;
        for (k, t) in candidates.iter().enumerate() {
            let Some(t) = *t else { continue };
            ends = Some(match ends {
                None => [(k, t); 2],
                Some([first, last]) => [
                    if t < first.1 { (k, t) } else { first },
                    if t > last.1 { (k, t) } else { last },
                ],
            });
        }
        Self { ends }
    }

    /// End `k` (0 the entry, 1 the exit): its candidate and `t`.
    #[inline]
    pub fn end(&self, k: usize) -> Option<(usize, f64)> {
        self.ends.map(|ends| ends[k])
    }

    /// The entry's and the exit's `t`.
    #[inline]
    pub fn span(&self) -> Option<[f64; 2]> {
        self.ends.map(|[first, last]| [first.1, last.1])
    }

    /// Appends the entry and the exit, `point(candidate, t)` making each surface point.
    pub fn crossings(&self, point: impl Fn(usize, f64) -> ShapeHit, out: &mut Vec<ShapeHit>) {
        if let Some(ends) = self.ends {
            out.extend(ends.map(|(c, t)| point(c, t)));
        }
    }
}

/// A convex solid whose line crossings are picked by [`ConvexEnds`] from a few candidate
/// surfaces (the cylinder's and the cone's side and caps): it says where the line meets
/// each surface and makes the surface point of one; the three ways CSG asks for its
/// crossings follow from those two, the same for every such solid.
pub(crate) trait ConvexSolid {
    /// What the solid is called in the panic of a line that misses it.
    const NAME: &'static str;

    /// Where the line enters and leaves, picked from where it meets each surface.
    fn ends(ray: &Ray) -> ConvexEnds;

    /// The surface point of candidate `k` of [`Self::ends`], at its `t`.
    fn candidate_hit(ray: &Ray, k: usize, t: f64) -> ShapeHit;

    /// Both crossings of the whole line (entry, exit), for CSG: the solid is convex, so
    /// they are the first and last of its surface points along the line (one point twice
    /// where the line only touches it).
    fn crossings(ray: &Ray, out: &mut Vec<ShapeHit>) {
        Self::ends(ray).crossings(|k, t| Self::candidate_hit(ray, k, t), out);
    }

    /// The ends of the whole line's span (`crossings`' two `t`s without their points),
    /// for CSG leaves that work out a surface point only for the crossing a query
    /// answers with.
    #[inline]
    fn line_span(ray: &Ray) -> Option<[f64; 2]> {
        Self::ends(ray).span()
    }

    /// Crossing `k` of the line (0 the entry, 1 the exit), as [`Self::crossings`] gives
    /// it; the line must cross the solid ([`Self::line_span`] is `Some`).
    fn crossing_of_line(ray: &Ray, k: usize) -> ShapeHit {
        let Some((which, t)) = Self::ends(ray).end(k) else {
            panic!("a line that crosses the {}", Self::NAME);
        };
        Self::candidate_hit(ray, which, t)
    }
}
