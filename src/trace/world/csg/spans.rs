//! Roth's interval arithmetic (Roth, "Ray casting for modeling solids", 1982): where a
//! line is inside each operand, as sorted spans of `t`, and the spans of a Union,
//! Intersection or Difference swept together from its operands'.

use crate::scene::CsgOp;
use crate::trace::shapes::ShapeHit;

/// One end of a span: the operand surface the line crosses there. Small (the sweep
/// copies it): the hit itself stays in the evaluation's list of crossings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Crossing {
    /// The ray parameter.
    pub t: f64,
    /// Index of the crossing's [`ShapeHit`] (in the leaf's object space) in the list
    /// the leaves' crossings were collected in, or a sphere's, cube's, cylinder's or
    /// cone's end to work out later (`eval::LATER`); `u32::MAX` for an unbounded end.
    pub hit: u32,
    /// Which leaf of the tree; `u32::MAX` for the open end of an unbounded span.
    pub leaf: u32,
    /// Whether the surface belongs to a subtracted operand (an odd number of times), so
    /// that the result lies on its outer side: a Difference's cut.
    pub cut: bool,
}

/// An interval of `t` where the line is inside a solid, with the surfaces at its ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Span {
    /// Where the line enters.
    pub enter: Crossing,
    /// Where it leaves.
    pub leave: Crossing,
}

impl Crossing {
    /// The open end of a span reaching to `t` = +-infinity (a half-space's).
    pub fn unbounded(t: f64) -> Self {
        Self {
            t,
            hit: u32::MAX,
            leaf: u32::MAX,
            cut: false,
        }
    }

    fn t(&self) -> f64 {
        self.t
    }
}

/// The spans of one leaf from its crossings (ascending `t`; the first one at index
/// `first` of the evaluation's list), starting inside or not at t = -infinity.
/// Crossings alternate between entering and leaving; spans of zero length (a line that
/// only touches the solid) are left out: the set operations are regularised, so a
/// touch is no surface.
pub(crate) fn leaf_spans(
    crossings: &[ShapeHit],
    first: usize,
    leaf: u32,
    starts_inside: bool,
    out: &mut Vec<Span>,
) {
    let crossing = |k: usize, hit: &ShapeHit| Crossing {
        t: hit.t,
        hit: u32::try_from(first + k).expect("under 2^32 crossings"),
        leaf,
        cut: false,
    };
    let mut open = starts_inside.then(|| Crossing::unbounded(f64::NEG_INFINITY));
    for (k, hit) in crossings.iter().enumerate() {
        match open.take() {
            None => open = Some(crossing(k, hit)),
            Some(enter) => {
                if hit.t > enter.t() {
                    out.push(Span {
                        enter,
                        leave: crossing(k, hit),
                    });
                }
            }
        }
    }
    if let Some(enter) = open {
        out.push(Span {
            enter,
            leave: Crossing::unbounded(f64::INFINITY),
        });
    }
}

/// Whether a point inside `a` (or not) and `b` (or not) is inside `a op b`.
fn inside(op: CsgOp, a: bool, b: bool) -> bool {
    match op {
        CsgOp::Union => a || b,
        CsgOp::Intersection => a && b,
        CsgOp::Difference => a && !b,
    }
}

/// The next boundary of a span list at or after the sweep position: the span index and
/// whether it is the span's leaving end.
struct Cursor<'a> {
    spans: &'a [Span],
    index: usize,
    leaving: bool,
}

impl Cursor<'_> {
    fn next(&self) -> Option<Crossing> {
        let span = self.spans.get(self.index)?;
        Some(if self.leaving { span.leave } else { span.enter })
    }

    fn advance(&mut self) {
        if self.leaving {
            self.index += 1;
        }
        self.leaving = !self.leaving;
    }

    /// Whether the sweep is inside a span (its entry passed, its exit not).
    fn is_inside(&self) -> bool {
        self.leaving
    }
}

/// The spans of `a op b`, appended to `out`. All boundaries at one `t` are passed
/// together, so coincident surfaces (a face shared by both operands) make no span of
/// zero length; where the result's inside begins or ends, the surface named is `a`'s if
/// `a` crosses there, else `b`'s (a subtracted one marked as a cut).
pub(crate) fn combine(op: CsgOp, a: &[Span], b: &[Span], out: &mut Vec<Span>) {
    match (a, b) {
        ([a], [b]) => combine_one(op, *a, *b, out),
        // Intersected with or cut by one span (a hollow solid's walls minus a window),
        // span by span: what the sweep gives, as long as `a`'s spans do not touch.
        (_, [b]) if op != CsgOp::Union && a.windows(2).all(|w| w[0].leave.t < w[1].enter.t) => {
            for a in a {
                combine_one(op, *a, *b, out);
            }
        }
        _ => sweep(op, a, b, out),
    }
}

/// [`combine`] for any span lists: one pass over both lists' boundaries in order.
fn sweep(op: CsgOp, a: &[Span], b: &[Span], out: &mut Vec<Span>) {
    let mut ca = Cursor {
        spans: a,
        index: 0,
        leaving: false,
    };
    let mut cb = Cursor {
        spans: b,
        index: 0,
        leaving: false,
    };
    let mut was_inside = false;
    let mut open: Option<Crossing> = None;
    loop {
        let t = match (ca.next(), cb.next()) {
            (None, None) => break,
            (Some(x), None) | (None, Some(x)) => x.t(),
            (Some(x), Some(y)) => x.t().min(y.t()),
        };
        let mut from_a = None;
        let mut from_b = None;
        while let Some(x) = ca.next().filter(|x| x.t() == t) {
            from_a = Some(x);
            ca.advance();
        }
        while let Some(mut x) = cb.next().filter(|x| x.t() == t) {
            if op == CsgOp::Difference {
                x.cut = !x.cut;
            }
            from_b = Some(x);
            cb.advance();
        }
        let now_inside = inside(op, ca.is_inside(), cb.is_inside());
        if now_inside == was_inside {
            continue;
        }
        was_inside = now_inside;
        let surface = from_a.or(from_b).expect("a boundary passed at t");
        match open.take() {
            None => open = Some(surface),
            Some(enter) => out.push(Span {
                enter,
                leave: surface,
            }),
        }
    }
    debug_assert!(open.is_none(), "every span list ends outside");
}

/// [`combine`] for one span on each side (a convex leaf against a convex leaf, the
/// usual case), in closed form; the same spans and surfaces as the sweep, ties included:
/// a boundary both sides share at one `t` is `a`'s.
fn combine_one(op: CsgOp, a: Span, b: Span, out: &mut Vec<Span>) {
    let earlier = |x: Crossing, y: Crossing| if y.t < x.t { y } else { x };
    let later = |x: Crossing, y: Crossing| if y.t > x.t { y } else { x };
    let cut = |mut x: Crossing| {
        x.cut = !x.cut;
        x
    };
    let apart = b.leave.t < a.enter.t || a.leave.t < b.enter.t;
    match op {
        CsgOp::Intersection => {
            let (enter, leave) = (later(a.enter, b.enter), earlier(a.leave, b.leave));
            if enter.t < leave.t {
                out.push(Span { enter, leave });
            }
        }
        // Spans that only touch join into one.
        CsgOp::Union if apart => {
            let (first, second) = if b.leave.t < a.enter.t {
                (b, a)
            } else {
                (a, b)
            };
            out.extend([first, second]);
        }
        CsgOp::Union => out.push(Span {
            enter: earlier(a.enter, b.enter),
            leave: later(a.leave, b.leave),
        }),
        CsgOp::Difference if b.leave.t <= a.enter.t || a.leave.t <= b.enter.t => out.push(a),
        CsgOp::Difference => {
            if a.enter.t < b.enter.t {
                out.push(Span {
                    enter: a.enter,
                    leave: cut(b.enter),
                });
            }
            if b.leave.t < a.leave.t {
                out.push(Span {
                    enter: cut(b.leave),
                    leave: a.leave,
                });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spans(ends: &[(f64, f64)], leaf: u32) -> Vec<Span> {
        let hits: Vec<ShapeHit> = ends
            .iter()
            .flat_map(|&(a, b)| [a, b])
            .map(|t| ShapeHit {
                t,
                p: glam::DVec3::ZERO,
                n: glam::DVec3::X,
                p_error: glam::DVec3::ZERO,
            })
            .collect();
        let mut out = Vec::new();
        leaf_spans(&hits, 0, leaf, false, &mut out);
        out
    }

    fn ends(op: CsgOp, a: &[(f64, f64)], b: &[(f64, f64)]) -> Vec<(f64, f64, u32, u32)> {
        let mut out = Vec::new();
        combine(op, &spans(a, 0), &spans(b, 1), &mut out);
        out.iter()
            .map(|s| (s.enter.t(), s.leave.t(), s.enter.leaf, s.leave.leaf))
            .collect()
    }

    #[test]
    fn the_three_operators_on_overlapping_spans() {
        let (a, b) = ([(0.0, 2.0), (5.0, 6.0)], [(1.0, 3.0)]);
        assert_eq!(
            ends(CsgOp::Union, &a, &b),
            [(0.0, 3.0, 0, 1), (5.0, 6.0, 0, 0)]
        );
        assert_eq!(ends(CsgOp::Intersection, &a, &b), [(1.0, 2.0, 1, 0)]);
        assert_eq!(
            ends(CsgOp::Difference, &a, &b),
            [(0.0, 1.0, 0, 1), (5.0, 6.0, 0, 0)]
        );
    }

    #[test]
    fn shared_boundaries_make_no_empty_span() {
        // b covers a's far end exactly: a - b ends at b's entry, with nothing at 2.
        assert_eq!(
            ends(CsgOp::Difference, &[(0.0, 2.0)], &[(1.0, 2.0)]),
            [(0.0, 1.0, 0, 1)]
        );
        // Touching spans: the union is one span, the intersection none.
        assert_eq!(
            ends(CsgOp::Union, &[(0.0, 1.0)], &[(1.0, 2.0)]),
            [(0.0, 2.0, 0, 1)]
        );
        assert!(ends(CsgOp::Intersection, &[(0.0, 1.0)], &[(1.0, 2.0)]).is_empty());
        // Equal spans: a - a is empty.
        assert!(ends(CsgOp::Difference, &[(0.0, 1.0)], &[(0.0, 1.0)]).is_empty());
    }

    #[test]
    fn one_span_each_gives_what_the_sweep_gives_ties_included() {
        // Every pair of spans with ends on a small grid (so that ends coincide in every
        // way), unbounded ends too, under each operator.
        let ends = [f64::NEG_INFINITY, 0.0, 1.0, 2.0, 3.0, f64::INFINITY];
        let span = |enter: f64, leave: f64, leaf: u32| Span {
            enter: Crossing {
                t: enter,
                hit: 2 * leaf,
                leaf,
                cut: false,
            },
            leave: Crossing {
                t: leave,
                hit: 2 * leaf + 1,
                leaf,
                cut: leaf == 1,
            },
        };
        let pairs: Vec<(f64, f64)> = ends
            .iter()
            .flat_map(|&x| ends.iter().map(move |&y| (x, y)))
            .filter(|(x, y)| x < y)
            .collect();
        let mut compared = 0;
        for op in [CsgOp::Union, CsgOp::Intersection, CsgOp::Difference] {
            for &(a0, a1) in &pairs {
                for &(b0, b1) in &pairs {
                    let (a, b) = ([span(a0, a1, 0)], [span(b0, b1, 1)]);
                    let (mut quick, mut swept) = (Vec::new(), Vec::new());
                    combine_one(op, a[0], b[0], &mut quick);
                    sweep(op, &a, &b, &mut swept);
                    assert_eq!(quick, swept, "{op:?} {a:?} {b:?}");
                    compared += 1;
                }
            }
        }
        assert_eq!(compared, 3 * 15 * 15);
    }

    #[test]
    fn several_spans_against_one_give_what_the_sweep_gives() {
        // Two spans against one, ends on a grid: every way the three can meet.
        let ends = [f64::NEG_INFINITY, 0.0, 1.0, 2.0, 3.0, 4.0, f64::INFINITY];
        let span = |enter: f64, leave: f64, leaf: u32, hit: u32| Span {
            enter: Crossing {
                t: enter,
                hit,
                leaf,
                cut: false,
            },
            leave: Crossing {
                t: leave,
                hit: hit + 1,
                leaf,
                cut: false,
            },
        };
        let n = ends.len();
        let mut compared = 0;
        for op in [CsgOp::Union, CsgOp::Intersection, CsgOp::Difference] {
            for (i, j, k, l) in (0..n).flat_map(|i| {
                (i + 1..n).flat_map(move |j| {
                    (j..n).flat_map(move |k| (k + 1..n).map(move |l| (i, j, k, l)))
                })
            }) {
                let a = [span(ends[i], ends[j], 0, 0), span(ends[k], ends[l], 0, 2)];
                for (x, y) in (0..n).flat_map(|x| (x + 1..n).map(move |y| (x, y))) {
                    let b = [span(ends[x], ends[y], 1, 4)];
                    let (mut quick, mut swept) = (Vec::new(), Vec::new());
                    combine(op, &a, &b, &mut quick);
                    sweep(op, &a, &b, &mut swept);
                    assert_eq!(quick, swept, "{op:?} {a:?} {b:?}");
                    compared += 1;
                }
            }
        }
        assert!(compared > 1000, "{compared}");
    }

    #[test]
    fn a_cut_is_marked_and_a_touch_is_no_span() {
        let mut out = Vec::new();
        combine(
            CsgOp::Difference,
            &spans(&[(0.0, 2.0)], 0),
            &spans(&[(1.0, 3.0)], 1),
            &mut out,
        );
        assert!(!out[0].enter.cut && out[0].leave.cut);
        assert!(spans(&[(1.0, 1.0)], 0).is_empty());
    }
}
