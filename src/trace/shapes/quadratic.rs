//! The cancellation-free quadratic solver shared by the curved shapes.

/// The real roots of `a t^2 + 2 h t + c = 0`, smaller first, given the quarter
/// discriminant `disc = h^2 - a c` computed by the caller in its most accurate form.
///
/// Uses q = -(h + sign(h) sqrt(disc)), t = q / a and t = c / q, so neither root is the
/// difference of two nearly equal numbers. When `a == 0` the equation is linear and its
/// one root is returned twice. Returns `None` when there is no real root; roots may be
/// infinite only when the equation degenerates (the caller filters by range).
#[must_use]
pub fn solve_quadratic(a: f64, h: f64, c: f64, disc: f64) -> Option<[f64; 2]> {
    if disc < 0.0 || disc.is_nan() {
        return None;
    }
    if a == 0.0 {
        // Linear: 2 h t + c = 0.
        if h == 0.0 {
            return None;
        }
        let t = -c / (2.0 * h);
        return Some([t, t]);
    }
    let root = disc.sqrt();
    let q = -(h + root.copysign(h));
    if q == 0.0 {
        // h == 0 and disc == 0: a double root at t = 0.
        return Some([0.0, 0.0]);
    }
    Some(sorted(q / a, c / q))
}

/// A vector of the space a unit ball lives in: 3D for the sphere, the xy plane for the
/// cylinder's side.
pub trait RadialVector:
    Copy + std::ops::Sub<Output = Self> + std::ops::Mul<f64, Output = Self>
{
    /// The dot product.
    fn dot(self, other: Self) -> f64;
    /// The squared length.
    fn length_squared(self) -> f64;
}

impl RadialVector for glam::DVec2 {
    fn dot(self, other: Self) -> f64 {
        glam::DVec2::dot(self, other)
    }
    fn length_squared(self) -> f64 {
        glam::DVec2::length_squared(self)
    }
}

impl RadialVector for glam::DVec3 {
    fn dot(self, other: Self) -> f64 {
        glam::DVec3::dot(self, other)
    }
    fn length_squared(self) -> f64 {
        glam::DVec3::length_squared(self)
    }
}

/// Both roots of `|o + t d|^2 = 1`, smaller first: the ray from `o` along `d` crossing the
/// unit ball's boundary. `None` when it misses or does not move (`d == 0`).
///
/// The quarter discriminant is computed as a (1 - |o - (o.d / a) d|^2): the squared
/// distance from the centre to the ray's closest point, which does not cancel for rays
/// far from the ball the way (o.d)^2 - a (|o|^2 - 1) does. An origin on the boundary to
/// within rounding gives the root t = 0 exactly and the other at -2h/a.
#[must_use]
pub fn unit_ball_roots<V: RadialVector>(o: V, d: V) -> Option<[f64; 2]> {
    let a = d.length_squared();
    if a == 0.0 {
        return None;
    }
    let h = o.dot(d);
    let c = o.length_squared() - 1.0;
    if c.abs() <= super::hit::gamma(3) * (c + 1.0) {
        return Some(sorted(0.0, -2.0 * h / a));
    }
    // A clear miss, found without the division below (its latency is most of a missing
    // ray's cost): h^2 - a c is the same quarter discriminant, and both it and `disc`
    // round by less than 1e-14 of a + |a c| + h^2, so far below -1e-6 of that `disc` is
    // negative too and the answer is the same `None`.
    if h * h - a * c < -1e-6 * (a + (a * c).abs() + h * h) {
        return None;
    }
    let closest = o - d * (h / a);
    let disc = a * (1.0 - closest.length_squared());
    solve_quadratic(a, h, c, disc)
}

/// Two roots, smaller first.
#[must_use]
pub fn sorted(t0: f64, t1: f64) -> [f64; 2] {
    if t0 <= t1 { [t0, t1] } else { [t1, t0] }
}

/// `a * b - c * d` with one rounding error, using fused multiply-add (Kahan's algorithm).
#[must_use]
pub fn difference_of_products(a: f64, b: f64, c: f64, d: f64) -> f64 {
    let cd = c * d;
    let error = (-c).mul_add(d, cd);
    let dop = a.mul_add(b, -cd);
    dop + error
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_well_conditioned_quadratic() {
        // (t - 1)(t - 3) = t^2 - 4t + 3: h = -2.
        let roots = solve_quadratic(1.0, -2.0, 3.0, 4.0 - 3.0).unwrap();
        assert_eq!(roots, [1.0, 3.0]);
    }

    #[test]
    fn small_root_keeps_full_precision_when_roots_differ_hugely() {
        // t^2 - 2e8 t + 1 = 0: roots ~ 5e-9 and 2e8; the naive formula loses the small one.
        let h = -1e8;
        let roots = solve_quadratic(1.0, h, 1.0, h * h - 1.0).unwrap();
        let expected_small = 1.0 / 2e8;
        assert!((roots[0] - expected_small).abs() <= 1e-15 * expected_small * 4.0);
    }

    #[test]
    fn linear_and_degenerate_cases() {
        assert_eq!(solve_quadratic(0.0, 1.0, -4.0, 1.0), Some([2.0, 2.0]));
        assert_eq!(solve_quadratic(0.0, 0.0, 1.0, 0.0), None);
        assert_eq!(solve_quadratic(1.0, 0.0, 0.0, 0.0), Some([0.0, 0.0]));
        assert_eq!(solve_quadratic(1.0, 0.0, 1.0, -1.0), None);
    }

    #[test]
    fn difference_of_products_is_exact_where_naive_cancels() {
        let (a, b) = (1.0 + 2f64.powi(-30), 1.0 - 2f64.powi(-30));
        // a * b = 1 - 2^-60 exactly, which rounds to 1: the naive difference is 0.
        assert_eq!(a * b - 1.0, 0.0);
        assert_eq!(difference_of_products(a, b, 1.0, 1.0), -(2f64.powi(-60)));
    }
}
