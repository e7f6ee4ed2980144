//! Real roots of a polynomial of degree up to four within an interval, for the torus.
//!
//! Closed forms for the quartic (Ferrari, the ACM TOMS algorithms) lose roots to
//! cancellation where a ray grazes the surface, and Sturm sequences (POV-Ray's choice)
//! are slow. This isolates roots by the roots of the derivative instead (as Yuksel's
//! "High-Performance Polynomial Root Finding for Graphics", 2022): between two
//! consecutive critical points the polynomial is monotone, so it holds at most one root,
//! and a sign change brackets it. Each bracket is closed by Newton steps kept inside it.
//! A critical point where the value is within its rounding error of zero is a double
//! root: the ray touches the surface there.

/// The highest degree handled.
const MAX_DEGREE: usize = 4;
/// At most this many roots are kept: the degree, with room for a touch reported once.
pub(crate) const MAX_ROOTS: usize = MAX_DEGREE;

/// `c[0] + c[1] x + ... + c[degree] x^degree`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Polynomial {
    c: [f64; MAX_DEGREE + 1],
    degree: usize,
}

/// A root and how the polynomial behaves there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Root {
    /// Where.
    pub x: f64,
    /// Whether the polynomial touches zero without changing sign (a double root, within
    /// rounding): a ray tangent to the surface.
    pub touch: bool,
}

/// The roots found, ascending.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Roots {
    roots: [Option<Root>; MAX_ROOTS],
    len: usize,
}

impl Roots {
    fn push(&mut self, root: Root) {
        // More than the degree allows only from rounding at a cluster: keep the first.
        if self.len < MAX_ROOTS {
            self.roots[self.len] = Some(root);
            self.len += 1;
        }
    }

    /// The roots, ascending.
    pub fn iter(&self) -> impl Iterator<Item = Root> + '_ {
        self.roots[..self.len].iter().flatten().copied()
    }
}

impl Polynomial {
    /// The polynomial with coefficients `c`, lowest power first (at most five).
    pub fn new(c: &[f64]) -> Polynomial {
        debug_assert!(!c.is_empty() && c.len() <= MAX_DEGREE + 1);
        let mut coefficients = [0.0; MAX_DEGREE + 1];
        coefficients[..c.len()].copy_from_slice(c);
        Polynomial {
            c: coefficients,
            degree: c.len() - 1,
        }
    }

    /// The value at `x` (Horner's rule).
    #[inline]
    pub fn value(&self, x: f64) -> f64 {
        let mut v = self.c[self.degree];
        for i in (0..self.degree).rev() {
            v = v * x + self.c[i];
        }
        v
    }

    /// The value at `x` and a bound on its rounding error: Horner's rule errs by at most
    /// `gamma(2 n) sum |c_i| |x|^i`. (Plain products and sums: a fused multiply-add is a
    /// library call on the baseline x86-64 the release is built for.)
    #[inline]
    fn value_and_bound(&self, x: f64) -> (f64, f64) {
        let (mut v, mut magnitude) = (self.c[self.degree], self.c[self.degree].abs());
        for i in (0..self.degree).rev() {
            v = v * x + self.c[i];
            magnitude = magnitude * x.abs() + self.c[i].abs();
        }
        // The degree's roundings, and as many again for the coefficients' own.
        (v, super::hit::gamma(4 * self.degree as u32 + 2) * magnitude)
    }

    /// The derivative.
    fn derivative(&self) -> Polynomial {
        let mut c = [0.0; MAX_DEGREE + 1];
        for (i, slot) in c.iter_mut().enumerate().take(self.degree) {
            *slot = self.c[i + 1] * (i + 1) as f64;
        }
        Polynomial {
            c,
            degree: self.degree.saturating_sub(1),
        }
    }

    /// The real roots in `[lo, hi]`, ascending. A root within rounding of an end is
    /// reported at the end.
    pub fn roots_in(&self, lo: f64, hi: f64) -> Roots {
        let mut roots = Roots::default();
        self.visit_roots_in(lo, hi, &mut |root| {
            roots.push(root);
            false
        });
        roots
    }

    /// Hands the real roots in `[lo, hi]` to `visit` in ascending order until it returns
    /// `true` (found what it wanted): the roots after that one are never computed.
    pub fn visit_roots_in(&self, lo: f64, hi: f64, visit: &mut impl FnMut(Root) -> bool) {
        // An empty or NaN interval, or a constant, has no roots to report.
        if lo.partial_cmp(&hi).is_none_or(|order| order.is_gt()) || self.degree == 0 {
            return;
        }
        if self.degree == 1 {
            let x = -self.c[0] / self.c[1];
            if self.c[1] != 0.0 && (lo..=hi).contains(&x) {
                visit(Root { x, touch: false });
            }
            return;
        }
        // The monotone pieces: split at the derivative's roots.
        let mut points = [(0.0, 0i8, 0.0); MAX_DEGREE + 1];
        let mut count = 0;
        let mut add = |x: f64| {
            if count < points.len() {
                let (v, bound) = self.value_and_bound(x);
                let sign = if v.abs() <= bound {
                    0
                } else {
                    v.signum() as i8
                };
                points[count] = (x, sign, v);
                count += 1;
            }
        };
        add(lo);
        for x in self.critical_points(lo, hi).into_iter().flatten() {
            if x > lo && x < hi {
                add(x);
            }
        }
        if hi > lo {
            add(hi);
        }
        let points = &points[..count];
        for (i, &(x, sign, v)) in points.iter().enumerate() {
            if sign == 0 {
                // A zero at a point: a crossing when the signs around it differ, else a
                // touch (an end counts as a crossing: the root lies at the boundary).
                let before = points[..i].iter().rev().map(|p| p.1).find(|&s| s != 0);
                let after = points[i + 1..].iter().map(|p| p.1).find(|&s| s != 0);
                let is_end = i == 0 || i == points.len() - 1;
                let touch = !is_end && before.is_some() && before == after;
                if visit(Root { x, touch }) {
                    return;
                }
            }
            if let Some(&(next, next_sign, next_v)) = points.get(i + 1)
                && i8::signum(sign) * next_sign < 0
            {
                let x = self.bracketed_root((x, v), (next, next_v));
                if visit(Root { x, touch: false }) {
                    return;
                }
            }
        }
    }

    /// The derivative's roots in `[lo, hi]`, ascending: in closed form where the
    /// derivative is a quadratic (the stable form, no cancellation between the roots),
    /// else by the same search one degree down.
    fn critical_points(&self, lo: f64, hi: f64) -> [Option<f64>; MAX_DEGREE] {
        let mut out = [None; MAX_DEGREE];
        let derivative = self.derivative();
        if derivative.degree == 2 {
            let [c, b, a, ..] = derivative.c;
            let roots = super::quadratic::solve_quadratic(a, 0.5 * b, c, 0.25 * b * b - a * c);
            if let Some([x0, x1]) = roots {
                out[0] = Some(x0);
                out[1] = (x1 != x0).then_some(x1);
            }
            return out;
        }
        let mut n = 0;
        derivative.visit_roots_in(lo, hi, &mut |root| {
            out[n] = Some(root.x);
            n += 1;
            n == out.len()
        });
        out
    }

    /// The one root in `(a, b)` of a polynomial monotone there, whose values at the ends
    /// differ in sign: Newton steps from the secant's root, bisecting whenever a step
    /// leaves the bracket.
    fn bracketed_root(&self, (mut a, value_a): (f64, f64), (mut b, value_b): (f64, f64)) -> f64 {
        let derivative = self.derivative();
        let rising = value_b > value_a;
        let secant = a + (b - a) * (value_a / (value_a - value_b));
        let mut x = if secant > a && secant < b {
            secant
        } else {
            0.5 * (a + b)
        };
        for _ in 0..100 {
            let v = self.value(x);
            if v == 0.0 {
                return x;
            }
            if (v < 0.0) == rising {
                a = x;
            } else {
                b = x;
            }
            let newton = x - v / derivative.value(x);
            let next = if newton > a && newton < b {
                newton
            } else {
                0.5 * (a + b)
            };
            // Converged: the step is down to rounding, or the bracket to an ulp.
            let scale = a.abs().max(b.abs());
            if (next - x).abs() <= 4.0 * f64::EPSILON * scale || b - a <= f64::EPSILON * scale {
                return next;
            }
            x = next;
        }
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn xs(roots: Roots) -> Vec<(f64, bool)> {
        roots.iter().map(|r| (r.x, r.touch)).collect()
    }

    /// `(x - a)(x - b)(x - c)(x - d)`, expanded.
    fn from_roots(r: [f64; 4]) -> Polynomial {
        let [a, b, c, d] = r;
        let e1 = a + b + c + d;
        let e2 = a * b + a * c + a * d + b * c + b * d + c * d;
        let e3 = a * b * c + a * b * d + a * c * d + b * c * d;
        let e4 = a * b * c * d;
        Polynomial::new(&[e4, -e3, e2, -e1, 1.0])
    }

    #[test]
    fn four_simple_roots_in_order() {
        let p = from_roots([-2.0, -0.5, 0.25, 3.0]);
        let found = xs(p.roots_in(-10.0, 10.0));
        assert_eq!(found.len(), 4, "{found:?}");
        for ((x, touch), expected) in found.into_iter().zip([-2.0, -0.5, 0.25, 3.0]) {
            assert!((x - expected).abs() < 1e-14, "{x} != {expected}");
            assert!(!touch);
        }
    }

    #[test]
    fn only_the_roots_inside_the_interval() {
        let p = from_roots([-2.0, -0.5, 0.25, 3.0]);
        let found = xs(p.roots_in(-1.0, 1.0));
        assert_eq!(found.len(), 2, "{found:?}");
        assert!((found[0].0 + 0.5).abs() < 1e-14 && (found[1].0 - 0.25).abs() < 1e-14);
    }

    #[test]
    fn a_double_root_is_one_touch() {
        // (x - 1)^2 (x + 2)(x - 4): the ray tangent at x = 1.
        let p = from_roots([1.0, 1.0, -2.0, 4.0]);
        let found = xs(p.roots_in(-10.0, 10.0));
        assert_eq!(found.len(), 3, "{found:?}");
        assert!((found[1].0 - 1.0).abs() < 1e-7 && found[1].1, "{found:?}");
        assert!(!found[0].1 && !found[2].1);
    }

    #[test]
    fn no_real_roots() {
        // (x^2 + 1)(x^2 + 4)
        let p = Polynomial::new(&[4.0, 0.0, 5.0, 0.0, 1.0]);
        assert_eq!(p.roots_in(-100.0, 100.0).iter().count(), 0);
    }

    #[test]
    fn close_roots_stay_apart() {
        // Two roots 1e-6 apart: a ray nearly grazing; both are found, not one touch.
        let p = from_roots([1.0, 1.0 + 1e-6, 5.0, 7.0]);
        let found = xs(p.roots_in(0.0, 10.0));
        assert_eq!(found.len(), 4, "{found:?}");
        assert!((found[1].0 - found[0].0 - 1e-6).abs() < 1e-9, "{found:?}");
    }

    #[test]
    fn a_root_at_the_end_is_reported_there() {
        let p = from_roots([0.0, 1.0, 2.0, 3.0]);
        let found = xs(p.roots_in(0.0, 1.5));
        assert_eq!(found.len(), 2, "{found:?}");
        assert_eq!(found[0], (0.0, false));
        assert!((found[1].0 - 1.0).abs() <= 2.0 * f64::EPSILON && !found[1].1);
    }

    #[test]
    fn lower_degrees() {
        let quadratic = Polynomial::new(&[-4.0, 0.0, 1.0]);
        assert_eq!(
            xs(quadratic.roots_in(-5.0, 5.0)),
            vec![(-2.0, false), (2.0, false)]
        );
        let line = Polynomial::new(&[-1.0, 2.0]);
        assert_eq!(xs(line.roots_in(0.0, 1.0)), vec![(0.5, false)]);
    }
}
