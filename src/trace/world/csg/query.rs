//! The queries a CSG node answers along a ray, from the spans its program leaves
//! (`super::eval`) or, for an Intersection of convex primitives, its one span
//! (`super::convex`): the nearest surface, whether any surface is in range, and every
//! surface for the pixel inspector, each carried into the node's space facing out of the
//! result.

use super::eval::{LATER, Scratch};
use super::spans::Crossing;
use super::tree::{CsgHit, CsgTree};
use crate::trace::ray::Ray;
use crate::trace::shapes::{self, ShapeHit, gamma};

impl CsgTree {
    /// Whether a crossing lies in (0, t_max), clear of its leaf ray's origin rounding.
    #[inline]
    fn in_range(s: &Scratch, crossing: &Crossing, t_max: f64) -> bool {
        crossing.leaf != u32::MAX
            && shapes::in_range(&s.leaf_rays[crossing.leaf as usize], crossing.t, t_max)
    }

    /// The nearest surface of the node along a node-space ray with `t` in (0, t_max).
    #[must_use]
    pub fn intersect(&self, ray: &Ray, t_max: f64) -> Option<CsgHit> {
        if self.closed_form {
            let ends = self.closed_form_span(ray, t_max)?;
            for (end, entering) in ends.iter().zip([true, false]) {
                let c = &end.crossing;
                if c.t >= t_max {
                    return None;
                }
                if shapes::in_range(&end.leaf_ray, c.t, t_max) {
                    let shape = self.leaves[c.leaf as usize].shape;
                    let hit =
                        shapes::line_crossing(shape, &end.leaf_ray, (c.hit & 1) as usize, c.t);
                    return Some(self.node_hit(ray, c, &hit, entering));
                }
            }
            return None;
        }
        self.with_spans(ray, t_max, |s| {
            for span in &s.arena {
                for (c, entering) in [(&span.enter, true), (&span.leave, false)] {
                    if c.t >= t_max {
                        return None;
                    }
                    if Self::in_range(s, c, t_max) {
                        let hit = self.shape_hit(s, c);
                        return Some(self.node_hit(ray, c, &hit, entering));
                    }
                }
            }
            None
        })
    }

    /// Whether any surface of the node lies along the ray with `t` in (0, t_max).
    #[must_use]
    pub fn occluded(&self, ray: &Ray, t_max: f64) -> bool {
        if self.closed_form {
            return self.closed_form_span(ray, t_max).is_some_and(|ends| {
                // The exit counts only where the entry lies before t_max.
                let c = |k: usize| &ends[k].crossing;
                let in_range = |k: usize| shapes::in_range(&ends[k].leaf_ray, c(k).t, t_max);
                c(0).t < t_max && (in_range(0) || (c(1).t < t_max && in_range(1)))
            });
        }
        self.with_spans(ray, t_max, |s| {
            for span in &s.arena {
                for c in [&span.enter, &span.leave] {
                    if c.t >= t_max {
                        return false;
                    }
                    if Self::in_range(s, c, t_max) {
                        return true;
                    }
                }
            }
            false
        })
    }

    /// Every surface of the node along the line, in order, for the pixel inspector:
    /// each with whether the ray enters the result there.
    #[must_use]
    pub fn surfaces(&self, ray: &Ray) -> Vec<(CsgHit, bool)> {
        self.with_spans(ray, f64::INFINITY, |s| {
            s.arena
                .iter()
                .flat_map(|s| [(s.enter, true), (s.leave, false)])
                .filter(|(c, _)| (c.leaf as usize) < self.leaves.len())
                .map(|(c, entering)| {
                    (
                        self.node_hit(ray, &c, &self.shape_hit(s, &c), entering),
                        entering,
                    )
                })
                .collect()
        })
    }

    /// A crossing's surface point in its leaf's space: from the list of crossings, or
    /// worked out now for a sphere's, cube's, cylinder's or cone's (see [`LATER`]).
    fn shape_hit(&self, s: &Scratch, crossing: &Crossing) -> ShapeHit {
        if crossing.hit & LATER == 0 {
            return s.crossings[crossing.hit as usize];
        }
        let leaf = crossing.leaf as usize;
        let k = (crossing.hit & 1) as usize;
        shapes::line_crossing(self.leaves[leaf].shape, &s.leaf_rays[leaf], k, crossing.t)
    }

    /// A crossing in the node's space: the point and normal carried through the leaf's
    /// placement (its rounding added to the error bound, as `World` does for objects),
    /// the normal turned to face out of the result (against the ray where it enters).
    fn node_hit(&self, ray: &Ray, crossing: &Crossing, h: &ShapeHit, entering: bool) -> CsgHit {
        let leaf = &self.leaves[crossing.leaf as usize];
        let p = leaf.node_from_leaf.transform_point3(h.p);
        let mut n = leaf.normal_from_leaf * h.n;
        if (n.dot(ray.dir) > 0.0) == entering {
            n = -n;
        }
        let m = leaf.abs_node_from_leaf;
        let carried = m * h.p_error;
        let forward = gamma(3) * (m * h.p.abs() + leaf.node_from_leaf.translation.abs());
        let back =
            gamma(3) * (leaf.abs_leaf_from_node * p.abs() + leaf.leaf_from_node.translation.abs());
        CsgHit {
            hit: ShapeHit {
                t: h.t,
                p,
                n,
                p_error: carried + forward + m * back,
            },
            leaf: crossing.leaf,
            cut: crossing.cut,
        }
    }
}
