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
