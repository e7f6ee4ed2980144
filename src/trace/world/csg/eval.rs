//! Running a CSG node's program along a ray: each leaf's spans, combined by the
//! node's operators on an explicit stack of span lists, in per-thread buffers so a ray
//! allocates nothing once warm.

use std::cell::RefCell;

use super::spans::{self, Crossing, Span};
use super::tree::{CsgTree, Step};
use crate::scene::CsgOp;
use crate::trace::ray::Ray;
use crate::trace::shapes::{self, ShapeHit};

/// Marks a [`Crossing::hit`] whose surface point is not in the list of crossings but
/// worked out when a query needs it (a sphere's, cube's, cylinder's or cone's: the
/// shapes most CSG leaves are, and most crossings a sweep passes are never answered
/// with). The low bit is which end of the leaf's span. Lists never grow this long.
pub(super) const LATER: u32 = 1 << 31;

/// Per-thread buffers, so a ray allocates nothing once warm.
#[derive(Default)]
pub(super) struct Scratch {
    pub(super) crossings: Vec<ShapeHit>,
    /// The ray in each leaf's space (valid for the leaves that have crossings).
    pub(super) leaf_rays: Vec<Ray>,
    /// The span lists of the evaluation stack, one after another.
    pub(super) arena: Vec<Span>,
    /// Where each list on the stack starts in `arena`.
    pub(super) starts: Vec<usize>,
    pub(super) combined: Vec<Span>,
    pub(super) swap: Vec<Span>,
}

thread_local! {
    static SCRATCH: RefCell<Scratch> = RefCell::new(Scratch::default());
}

impl CsgTree {
    /// The spans of the whole node along a node-space ray, for the part of the line in
    /// [0, t_max], handed to `answer` (leaves whose bounds the ray misses there count as
    /// empty: they cannot change the result in that range).
    pub(super) fn with_spans<R>(
        &self,
        ray: &Ray,
        t_max: f64,
        answer: impl FnOnce(&Scratch) -> R,
    ) -> R {
        SCRATCH.with(|cell| {
            let mut guard = cell.borrow_mut();
            let s = &mut *guard;
            s.arena.clear();
            s.starts.clear();
            s.crossings.clear();
            if s.leaf_rays.len() < self.leaves.len() {
                s.leaf_rays.resize(self.leaves.len(), *ray);
            }
            let inv_dir = ray.dir.recip();
            let mut pc = 0;
            while let Some(step) = self.steps.get(pc) {
                pc += 1;
                match *step {
                    Step::SkipIfMissed {
                        bounds,
                        lists,
                        skip_to,
                    } => {
                        if !bounds.hit_by(ray, inv_dir, t_max) {
                            let end = s.arena.len();
                            s.starts.extend(std::iter::repeat_n(end, lists as usize));
                            pc = skip_to as usize;
                        }
                    }
                    Step::SkipIfEmpty { skip_to } => {
                        // Empty along [0, t_max] is as good as empty: the node lies in
                        // its first operand, and no query answers with a surface outside
                        // (0, t_max), which a set changed only outside it cannot move (a
                        // shadow ray leaving a die passes its pips by this way).
                        let start = *s.starts.last().expect("the first operand's list");
                        let first = &s.arena[start..];
                        if first.iter().all(|x| x.leave.t <= 0.0 || x.enter.t >= t_max) {
                            s.arena.truncate(start);
                            pc = skip_to as usize;
                        }
                    }
                    Step::Leaf(index) => {
                        s.starts.push(s.arena.len());
                        let leaf = &self.leaves[index as usize];
                        if leaf.bounds.is_some_and(|b| !b.hit_by(ray, inv_dir, t_max)) {
                            continue;
                        }
                        let leaf_ray = ray.transformed(&leaf.leaf_from_node);
                        s.leaf_rays[index as usize] = leaf_ray;
                        if leaf.mesh.is_none()
                            && let Some(line) = shapes::line_span(leaf.shape, &leaf_ray)
                        {
                            // A sphere's, cube's, cylinder's or cone's span, its surface
                            // points worked out later for the one crossing answered with.
                            if let Some([t0, t1]) = line.filter(|[t0, t1]| t1 > t0) {
                                let end = |t, k| Crossing {
                                    t,
                                    hit: LATER | k,
                                    leaf: index,
                                    cut: false,
                                };
                                s.arena.push(Span {
                                    enter: end(t0, 0),
                                    leave: end(t1, 1),
                                });
                            }
                            continue;
                        }
                        let first = s.crossings.len();
                        let inside = if let Some(mesh) = &leaf.mesh {
                            mesh.crossings(&leaf_ray, &mut s.crossings);
                            // A closed surface's crossings alternate: the ray starts
                            // inside where the first one leaves.
                            s.crossings[first..]
                                .first()
                                .is_some_and(|c| c.n.dot(leaf_ray.dir) > 0.0)
                        } else {
                            shapes::crossings(leaf.shape, &leaf_ray, &mut s.crossings);
                            shapes::starts_inside(leaf.shape, &leaf_ray)
                        };
                        let own = &s.crossings[first..];
                        spans::leaf_spans(own, first, index, inside, &mut s.arena);
                    }
                    Step::Combine { operands: 0, .. } => s.starts.push(s.arena.len()),
                    Step::Combine { op, operands } => {
                        let first = s.starts.len() - operands as usize;
                        let base = s.starts[first];
                        let end_of = |k: usize, s: &Scratch| {
                            s.starts.get(k + 1).copied().unwrap_or(s.arena.len())
                        };
                        // The result so far: the first list where it lies (no copy) until
                        // a sweep makes a new one in `combined`.
                        let mut first_end = end_of(first, s);
                        let mut in_place = true;
                        for k in first + 1..s.starts.len() {
                            let operand = s.starts[k]..end_of(k, s);
                            let acc_empty = if in_place {
                                first_end == base
                            } else {
                                s.combined.is_empty()
                            };
                            // Empty sides settle most combinations without a sweep (a
                            // die's pips miss most rays).
                            match (op, acc_empty, operand.is_empty()) {
                                (CsgOp::Intersection | CsgOp::Difference, true, _) => break,
                                (CsgOp::Union | CsgOp::Difference, _, true) => continue,
                                (CsgOp::Intersection, _, true) => {
                                    first_end = base;
                                    in_place = true;
                                    break;
                                }
                                _ => {}
                            }
                            let acc = if in_place {
                                &s.arena[base..first_end]
                            } else {
                                &s.combined[..]
                            };
                            s.swap.clear();
                            spans::combine(op, acc, &s.arena[operand], &mut s.swap);
                            std::mem::swap(&mut s.combined, &mut s.swap);
                            in_place = false;
                        }
                        s.starts.truncate(first + 1);
                        if in_place {
                            s.arena.truncate(first_end);
                        } else {
                            s.arena.truncate(base);
                            s.arena.extend_from_slice(&s.combined);
                        }
                    }
                }
            }
            answer(s)
        })
    }
}
