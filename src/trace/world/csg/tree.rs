//! The compiled CSG node and its queries: its operand leaves placed in the node's own
//! object space, and its operators as a post-order program. A ray is answered by
//! running the program (`super::eval`), which sweeps the leaves' spans together
//! (`super::spans`) with explicit stacks, so a tree 1,000 levels deep needs no deeper
//! call stack than a flat one.

use std::sync::Arc;

use glam::{DAffine3, DMat3, DVec3};

use super::eval::{LATER, Scratch};
use super::spans::Crossing;
use crate::scene::CsgOp;
use crate::trace::ray::Ray;
use crate::trace::shapes::{self, Aabb, Primitive, ShapeHit, TriangleMesh, gamma};

/// One operand leaf of a CSG node.
#[derive(Clone, Debug, PartialEq)]
pub struct CsgLeaf {
    /// Which unit shape ([`Primitive::Mesh`] for a closed mesh).
    pub shape: Primitive,
    /// A mesh leaf's triangles (a closed surface), shared with the mesh store.
    pub mesh: Option<Arc<TriangleMesh>>,
    /// Its tree path below the scene's top level, `"die/pip 3"`.
    pub path: String,
    /// Operand (or child) indices from the CSG node down to this leaf.
    pub tree_path: Vec<usize>,
    /// Index into [`crate::trace::World::materials`] (inherited where it names none).
    pub material: usize,
    /// Leaf-to-node transform (the node's object space, not the world).
    pub node_from_leaf: DAffine3,
    pub(super) leaf_from_node: DAffine3,
    normal_from_leaf: DMat3,
    abs_node_from_leaf: DMat3,
    abs_leaf_from_node: DMat3,
    /// Node-space bounds; `None` for a plane, the half-space z <= 0 in a CSG.
    pub(super) bounds: Option<Aabb>,
}

/// One instruction of the post-order program.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Step {
    /// Push the spans of this leaf.
    Leaf(u32),
    /// Pop the top `operands` span lists and push them combined by `op`, left to right.
    Combine { op: CsgOp, operands: u32 },
    /// After an Intersection's or Difference's first operand: if its list is empty (in
    /// the query's range), so is the node's, and the program goes on at `skip_to` (past
    /// the node's Combine).
    SkipIfEmpty { skip_to: u32 },
    /// Before a run of `lists` leaves whose boxes lie in `bounds`: a ray that misses the
    /// box pushes an empty list for each and goes on at `skip_to`.
    SkipIfMissed {
        bounds: Aabb,
        lists: u32,
        skip_to: u32,
    },
}

/// How far a node's solid can reach, in the node's space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Extent {
    /// Nowhere (an empty Intersection).
    Empty,
    /// Within this box.
    Box(Aabb),
    /// Without bound (a half-space).
    Unbounded,
}

/// A compiled CSG node.
#[derive(Clone, Debug, PartialEq)]
pub struct CsgTree {
    /// The operand leaves, in tree order.
    pub leaves: Vec<CsgLeaf>,
    pub(super) steps: Vec<Step>,
    /// Where the solid can be, in the node's space: Union joins its operands' extents,
    /// Intersection overlaps them, Difference keeps the first's.
    pub extent: Extent,
    /// The placement, in the node's space, of a sphere leaf that holds the whole solid
    /// (as a lens's spheres, a rounded die's), for a tighter bounds test than the box.
    pub bounding_sphere: Option<DAffine3>,
    /// Whether the solid is known to be convex (an Intersection of primitives, which
    /// are all convex): then a ray leaving it outward cannot meet it again.
    pub convex: bool,
}

/// A hit on a CSG node: the surface point in the node's space, facing out of the result.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CsgHit {
    /// The point, its outward normal (out of the result) and error bound, in node space.
    pub hit: ShapeHit,
    /// Which leaf's surface ([`CsgTree::leaves`]).
    pub leaf: u32,
    /// Whether the surface is a subtracted operand's (a Difference's cut).
    pub cut: bool,
}

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
    /// worked out now for a sphere's, a cube's or a cylinder's (see [`LATER`]).
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

impl CsgLeaf {
    /// A leaf of a unit shape, or of a closed mesh (`mesh`, with `shape` then
    /// [`Primitive::Mesh`]), placed in the node's space.
    pub(super) fn new(
        shape: Primitive,
        mesh: Option<Arc<TriangleMesh>>,
        path: String,
        material: usize,
        node_from_leaf: DAffine3,
    ) -> Self {
        let leaf_from_node = node_from_leaf.inverse();
        let abs = |m: &DMat3| DMat3::from_cols(m.x_axis.abs(), m.y_axis.abs(), m.z_axis.abs());
        let bounds = match &mesh {
            Some(mesh) => Some(mesh.bounds().transformed(&node_from_leaf)),
            None => (shape != Primitive::Plane)
                .then(|| shapes::object_bounds(shape).transformed(&node_from_leaf)),
        };
        Self {
            shape,
            mesh,
            path,
            tree_path: Vec::new(),
            material,
            node_from_leaf,
            leaf_from_node,
            normal_from_leaf: node_from_leaf.matrix3.inverse().transpose(),
            abs_node_from_leaf: abs(&node_from_leaf.matrix3),
            abs_leaf_from_node: abs(&leaf_from_node.matrix3),
            bounds,
        }
    }
}

/// The extent of a node from its operands'.
pub(super) fn combine_extents(op: CsgOp, operands: &[Extent]) -> Extent {
    let Some((&first, rest)) = operands.split_first() else {
        return Extent::Empty;
    };
    match op {
        CsgOp::Difference => first,
        CsgOp::Union => rest.iter().fold(first, |a, &b| match (a, b) {
            (Extent::Unbounded, _) | (_, Extent::Unbounded) => Extent::Unbounded,
            (Extent::Empty, x) | (x, Extent::Empty) => x,
            (Extent::Box(a), Extent::Box(b)) => Extent::Box(a.union(&b)),
        }),
        CsgOp::Intersection => rest.iter().fold(first, |a, &b| match (a, b) {
            (Extent::Empty, _) | (_, Extent::Empty) => Extent::Empty,
            (Extent::Unbounded, x) | (x, Extent::Unbounded) => x,
            (Extent::Box(a), Extent::Box(b)) => {
                let (min, max) = (a.min.max(b.min), a.max.min(b.max));
                if min.cmple(max).all() {
                    Extent::Box(Aabb::new(min, max))
                } else {
                    Extent::Empty
                }
            }
        }),
    }
}

/// Far enough to stand for "without bound" in world bounds, small enough that boxes
/// built from it stay finite through transforms.
pub const UNBOUNDED: f64 = 1e30;

impl Extent {
    /// World bounds for an object placed by `world_from_node`; an empty node gets a
    /// point at its origin (its tree answers no ray anyway).
    #[must_use]
    pub fn world_bounds(&self, world_from_node: &DAffine3) -> Aabb {
        match self {
            Extent::Box(b) => b.transformed(world_from_node),
            Extent::Unbounded => Aabb::new(DVec3::splat(-UNBOUNDED), DVec3::splat(UNBOUNDED)),
            Extent::Empty => {
                let o = world_from_node.translation;
                Aabb::new(o, o)
            }
        }
    }
}
