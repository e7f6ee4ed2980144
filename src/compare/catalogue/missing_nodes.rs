//! The nodes tried as missing, each with the world compiled without it: a scene object,
//! a group's child, a CSG operand that adds to its solid (a Union's) or cuts it (a
//! Difference's after the first: a die without one pip has that hole filled).
//! An Intersection's operands and a Difference's first are not tried: taking one out
//! grows the solid instead of leaving a part out.
//!
//! Each needs a world of its own, so at most [`MAX_MISSING_OBJECTS`] nodes are tried:
//! the largest first (every scene object, then their children, level by level).

use std::ops::Range;

use rayon::prelude::*;

use super::nodes::{Node, Nodes, Place};
use crate::scene::tree::{object_at, remove_node, world_from_parent};
use crate::scene::{CsgOp, Object, Scene, Shape};
use crate::trace::shapes::{Aabb, shape_bounds};
use crate::trace::{Ray, World};

/// Nodes beyond this many are not tried as missing (each needs a world of its own).
pub const MAX_MISSING_OBJECTS: usize = 32;

/// Where a tried node's channels are: a leaf's own ([`super::channels::Kind::Missing`]
/// and `ShadowCast` on the leaf), or an inner node's (`NodeMissing`, `NodeShadowCast` on
/// its slot).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Slot {
    /// The leaf's.
    Leaf(usize),
    /// Inner node slot.
    Inner(usize),
}

/// A node tried as missing, as the fit's groups see it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TriedNode {
    /// The node.
    pub node: usize,
    /// Where its channels are.
    pub slot: Slot,
}

/// A node tried as missing, with what the recorder needs to trace without it.
pub struct Tried {
    /// The node and its channels.
    pub tried: TriedNode,
    /// The world without it.
    pub world: World,
    /// The world objects taken out with it (none for a node inside a CSG object, whose
    /// solid changes instead).
    pub gone: Range<usize>,
    /// Below the top level, the world box it can change: where rays that do not hit it
    /// may meet a CSG object's solid once it is gone (a cut filled), and where a shadow
    /// ray it blocks passes. `None` for a top-level object, and where a CSG operand is
    /// unbounded (a plane, a mesh): every ray may then change.
    pub bounds: Option<Aabb>,
    /// Whether taking it out can only take solid away, so that a shadow it casts may
    /// clear (a cut filled only adds solid).
    pub shrinks: bool,
}

/// Every tried node.
pub struct MissingNodes {
    /// The tried nodes, largest first.
    pub tried: Vec<Tried>,
    /// Per leaf, the tried nodes on its chain (its top-level object's first).
    pub on_chain: Vec<Vec<usize>>,
    /// The tried nodes inside CSG objects.
    pub in_csg: Vec<usize>,
    /// Per scene object, the tried nodes of its tree.
    pub of_object: Vec<Vec<usize>>,
}

/// Whether taking the node out leaves a part out (rather than growing a solid).
fn can_leave_out(node: &Node) -> bool {
    match node.place {
        Place::TopLevel | Place::Child => true,
        Place::Operand { op, index } => {
            op == CsgOp::Union || (op == CsgOp::Difference && index > 0)
        }
    }
}

/// Whether taking the node out only takes solid away: an even number of cuts (a
/// Difference's later operands) on its way up, its own place counted.
fn shrinks(node: &Node, scene: &Scene) -> bool {
    let cuts = (1..node.path.len())
        .filter(|&depth| {
            let parent = object_at(&scene.objects, &node.path[..depth]);
            let index = node.path[depth];
            index > 0
                && parent.is_some_and(|p| {
                    matches!(
                        p.shape,
                        Shape::Csg {
                            op: CsgOp::Difference,
                            ..
                        }
                    )
                })
        })
        .count();
    cuts % 2 == 0
}

/// Whether a plane or a mesh is in the subtree: its solid has no box.
fn unbounded(object: &Object) -> bool {
    let mut work = vec![object];
    while let Some(o) = work.pop() {
        if matches!(o.shape, Shape::Plane | Shape::Mesh { .. }) {
            return true;
        }
        work.extend(o.shape.children());
    }
    false
}

/// The world box of the node's solid, `None` where it has none.
fn world_bounds(scene: &Scene, node: &Node) -> Option<Aabb> {
    let object = object_at(&scene.objects, &node.path)?;
    if unbounded(object) {
        return None;
    }
    let world_from_object =
        world_from_parent(&scene.objects, &node.path) * object.transform.world_from_object();
    Some(shape_bounds(&object.shape).transformed(&world_from_object))
}

impl MissingNodes {
    /// The tried nodes of `scene` (compiled as `world`, its nodes `nodes`).
    #[must_use]
    pub fn new(scene: &Scene, world: &World, nodes: &Nodes) -> Self {
        let mut order: Vec<usize> = (0..nodes.nodes.len())
            .filter(|&n| {
                let node = &nodes.nodes[n];
                can_leave_out(node) && (node.depth() == 0 || !nodes.has_same_child(n))
            })
            .collect();
        // Stable: tree order within a level.
        order.sort_by_key(|&n| nodes.nodes[n].depth());
        order.truncate(MAX_MISSING_OBJECTS);
        let mut tried: Vec<Tried> = order
            .into_par_iter()
            .filter_map(|index| {
                let node = &nodes.nodes[index];
                let mut without = scene.clone();
                remove_node(&mut without.objects, &node.path)?;
                let world_without = World::with_meshes(&without, &world.meshes).ok()?;
                let gone = if node.in_csg {
                    0..0
                } else {
                    let leaves = &nodes.leaves[node.leaves.clone()];
                    leaves[0].world_object..leaves[leaves.len() - 1].world_object + 1
                };
                let bounds = if node.in_csg {
                    world_bounds(scene, node)
                } else {
                    world.objects[gone.clone()]
                        .iter()
                        .map(|o| o.bounds)
                        .reduce(|a, b| a.union(&b))
                        .filter(|_| node.depth() > 0)
                };
                Some(Tried {
                    tried: TriedNode {
                        node: index,
                        slot: Slot::Leaf(0),
                    },
                    world: world_without,
                    gone,
                    bounds,
                    shrinks: shrinks(node, scene),
                })
            })
            .collect();
        let mut inner = 0;
        for t in &mut tried {
            let leaves = &nodes.nodes[t.tried.node].leaves;
            t.tried.slot = if nodes.leaves[leaves.start].node == t.tried.node {
                Slot::Leaf(leaves.start)
            } else {
                inner += 1;
                Slot::Inner(inner - 1)
            };
        }
        let mut on_chain = vec![Vec::new(); nodes.leaves.len()];
        let mut of_object = vec![Vec::new(); scene.objects.len()];
        let mut in_csg = Vec::new();
        for (index, t) in tried.iter().enumerate() {
            let node = &nodes.nodes[t.tried.node];
            for chain in &mut on_chain[node.leaves.clone()] {
                chain.push(index);
            }
            of_object[node.object()].push(index);
            if node.in_csg {
                in_csg.push(index);
            }
        }
        for (leaf, chain) in on_chain.iter_mut().enumerate() {
            chain.sort_by_key(|&t| nodes.nodes[tried[t].tried.node].depth());
            debug_assert!(
                chain
                    .iter()
                    .all(|&t| { nodes.nodes[tried[t].tried.node].leaves.contains(&leaf) })
            );
        }
        Self {
            tried,
            on_chain,
            in_csg,
            of_object,
        }
    }

    /// The tried nodes as the fit's groups see them.
    #[must_use]
    pub fn tried_nodes(&self) -> Vec<TriedNode> {
        self.tried.iter().map(|t| t.tried).collect()
    }

    /// How many inner nodes are tried (the slots of their channels).
    #[must_use]
    pub fn inner_slots(&self) -> usize {
        self.tried
            .iter()
            .filter(|t| matches!(t.tried.slot, Slot::Inner(_)))
            .count()
    }

    /// The index that world object `index` has in the world without tried node `tried`
    /// (`None` for one taken out with it).
    #[must_use]
    pub fn index_without(&self, tried: usize, index: usize) -> Option<usize> {
        let gone = &self.tried[tried].gone;
        if gone.contains(&index) {
            None
        } else if index >= gone.end {
            Some(index - gone.len())
        } else {
            Some(index)
        }
    }

    /// Whether a ray that does not hit tried node `tried` (inside a CSG object) may meet
    /// its solid before `t_max` once it is gone.
    #[must_use]
    pub fn may_change(&self, tried: usize, ray: &Ray, t_max: f64) -> bool {
        self.tried[tried]
            .bounds
            .is_none_or(|b| b.hit_by(ray, ray.dir.recip(), t_max))
    }
}
