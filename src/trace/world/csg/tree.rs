//! The compiled CSG node: its operand leaves placed in the node's own object space, and
//! its operators as a post-order program. A ray runs the program (`super::eval`), which
//! sweeps the leaves' spans together (`super::spans`) with explicit stacks, so a tree
//! 1,000 levels deep needs no deeper call stack than a flat one; `super::query` answers
//! from the spans.

use std::sync::Arc;

use glam::{DAffine3, DMat3, DVec3};

use crate::scene::CsgOp;
use crate::trace::shapes::{self, Aabb, Primitive, ShapeHit, TriangleMesh};

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
    pub(super) normal_from_leaf: DMat3,
    pub(super) abs_node_from_leaf: DMat3,
    pub(super) abs_leaf_from_node: DMat3,
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
    /// Whether the node is an Intersection of spheres, cubes, cylinders and cones,
    /// answered in closed form (`super::convex`) rather than by its program.
    pub(super) closed_form: bool,
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
