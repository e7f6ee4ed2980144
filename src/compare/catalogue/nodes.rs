//! The components of a comparison: the nodes of the scene's object trees. Every
//! top-level object is a node, and so is each child of a group and each operand of a CSG
//! node, to any depth. The *leaves* (a world object, or one operand leaf of a CSG world
//! object: a hit's `part`) carry the channels; an inner node stands for the leaves below
//! it, which are consecutive in tree order, so a node is a range of leaves. In a scene
//! without trees the nodes, the leaves and the scene's objects are one list.

use std::collections::BTreeSet;
use std::ops::Range;

use crate::scene::tree::{object_at, path_name};
use crate::scene::{CsgOp, Scene, Shape};
use crate::trace::World;

/// Label of a pixel (or a ray) that meets no leaf: its first sample hit nothing.
pub const MISS: u32 = u32::MAX;

/// Where a node sits in its parent, which says what taking it out does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// A scene object.
    TopLevel,
    /// A group's child.
    Child,
    /// Operand `index` of a CSG node combined by `op`.
    Operand {
        /// The parent's operator.
        op: CsgOp,
        /// Which operand.
        index: usize,
    },
}

/// One node of an object tree.
#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    /// The top-level object's index, then child and operand indices down to the node
    /// (as `World::node_path` and the editor's selection write them).
    pub path: Vec<usize>,
    /// Its names from the top level down, `"die/pip 1.1"`.
    pub name: String,
    /// The leaves below it (itself, for a leaf).
    pub leaves: Range<usize>,
    /// How it sits in its parent.
    pub place: Place,
    /// Whether a CSG node holds it: taking it out changes that CSG object's solid
    /// rather than taking world objects away.
    pub in_csg: bool,
}

impl Node {
    /// 0 for a top-level object, one more per level below.
    #[must_use]
    pub fn depth(&self) -> usize {
        self.path.len() - 1
    }

    /// The scene index of its top-level object.
    #[must_use]
    pub fn object(&self) -> usize {
        self.path[0]
    }
}

/// One leaf: where its channels' hits come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Leaf {
    /// Its node.
    pub node: usize,
    /// The world object it is, or lies in (a CSG object).
    pub world_object: usize,
    /// Its operand leaf in a CSG object (the hit's `part`); 0 otherwise.
    pub part: u32,
}

/// The nodes and leaves of a scene, in tree order.
#[derive(Clone, Debug, PartialEq)]
pub struct Nodes {
    /// Every node with a leaf below it, in tree order (a parent before its children).
    pub nodes: Vec<Node>,
    /// Every leaf, in tree order.
    pub leaves: Vec<Leaf>,
    /// Per world object, its first leaf.
    first_leaf: Vec<usize>,
    /// Per scene object, its node.
    top: Vec<usize>,
}

impl Nodes {
    /// The nodes of `scene`, compiled as `world` (every object shown).
    #[must_use]
    pub fn new(scene: &Scene, world: &World) -> Self {
        let mut leaf_paths = Vec::new();
        let mut first_leaf = Vec::with_capacity(world.objects.len());
        for (index, object) in world.objects.iter().enumerate() {
            first_leaf.push(leaf_paths.len());
            let mut path = vec![world.scene_object(index)];
            path.extend_from_slice(&world.object_tree_path[index]);
            match &object.csg {
                Some(tree) => leaf_paths.extend(tree.leaves.iter().enumerate().map(|(k, l)| {
                    let leaf_path = [path.as_slice(), &l.tree_path].concat();
                    (leaf_path, index, k as u32)
                })),
                None => leaf_paths.push((path, index, 0)),
            }
        }
        debug_assert!(leaf_paths.windows(2).all(|w| w[0].0 < w[1].0));
        // Every prefix of a leaf's path is a node; a Vec's order is tree order.
        let paths: BTreeSet<&[usize]> = leaf_paths
            .iter()
            .flat_map(|(path, ..)| (1..=path.len()).map(move |n| &path[..n]))
            .collect();
        let nodes: Vec<Node> = paths
            .into_iter()
            .map(|path| {
                let start = leaf_paths.partition_point(|(l, ..)| l.as_slice() < path);
                let end = leaf_paths
                    .partition_point(|(l, ..)| l.as_slice() < path || l.starts_with(path));
                let (place, in_csg) = place_of(scene, path);
                Node {
                    path: path.to_vec(),
                    name: path_name(&scene.objects, path),
                    leaves: start..end,
                    place,
                    in_csg,
                }
            })
            .collect();
        let mut leaves: Vec<Leaf> = leaf_paths
            .iter()
            .map(|&(_, world_object, part)| Leaf {
                node: 0,
                world_object,
                part,
            })
            .collect();
        let mut top = vec![0; scene.objects.len()];
        for (index, node) in nodes.iter().enumerate() {
            if node.leaves.len() == 1 && leaf_paths[node.leaves.start].0 == node.path {
                leaves[node.leaves.start].node = index;
            }
            if node.path.len() == 1 {
                top[node.object()] = index;
            }
        }
        Self {
            nodes,
            leaves,
            first_leaf,
            top,
        }
    }

    /// The leaf a hit on world object `world_object` at operand leaf `part` lies on.
    #[must_use]
    pub fn leaf(&self, world_object: usize, part: u32) -> usize {
        self.first_leaf[world_object] + part as usize
    }

    /// The scene index of leaf `leaf`'s top-level object.
    #[must_use]
    pub fn object_of_leaf(&self, leaf: usize) -> usize {
        self.nodes[self.leaves[leaf].node].object()
    }

    /// The node of scene object `object`.
    #[must_use]
    pub fn top(&self, object: usize) -> usize {
        self.top[object]
    }

    /// The nodes from leaf `leaf`'s top-level object down to the leaf.
    pub fn chain(&self, leaf: usize) -> impl Iterator<Item = usize> + '_ {
        let top = self.top[self.object_of_leaf(leaf)];
        (top..=self.leaves[leaf].node).filter(move |&n| self.nodes[n].leaves.contains(&leaf))
    }

    /// The deepest node holding all of `leaves` (their nearest common parent).
    #[must_use]
    pub fn holding(&self, leaves: Range<usize>) -> Option<usize> {
        let last = leaves.end.checked_sub(1)?;
        self.chain(leaves.start)
            .filter(|&n| self.nodes[n].leaves.contains(&last))
            .last()
    }

    /// The deepest node holding at least `share` of `energy` (per leaf), if one does.
    #[must_use]
    pub fn concentrated(&self, energy: &[f64], share: f64) -> Option<usize> {
        let total: f64 = energy.iter().sum();
        if total <= 0.0 {
            return None;
        }
        // The candidates nest (two disjoint nodes cannot both hold most of it), so the
        // last in tree order is the deepest.
        (0..self.nodes.len()).rev().find(|&n| {
            let held: f64 = energy[self.nodes[n].leaves.clone()].iter().sum();
            held >= share * total
        })
    }

    /// Whether another node holds the same leaves and lies below `node`: the same
    /// component, better named by that one (a group of one child).
    #[must_use]
    pub fn has_same_child(&self, node: usize) -> bool {
        self.nodes
            .get(node + 1)
            .is_some_and(|next| next.leaves == self.nodes[node].leaves)
    }
}

/// A node's place in its parent, and whether a CSG node holds it.
fn place_of(scene: &Scene, path: &[usize]) -> (Place, bool) {
    let Some((&index, parent)) = path.split_last().filter(|(_, p)| !p.is_empty()) else {
        return (Place::TopLevel, false);
    };
    let in_csg = (1..=parent.len()).any(|depth| {
        object_at(&scene.objects, &parent[..depth])
            .is_some_and(|o| matches!(o.shape, Shape::Csg { .. }))
    });
    let place = match object_at(&scene.objects, parent).map(|o| &o.shape) {
        Some(Shape::Csg { op, .. }) => Place::Operand { op: *op, index },
        _ => Place::Child,
    };
    (place, in_csg)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::parse_scene;

    const TREES: &str = r#"Scene(
        camera: (position: (0.0, 0.0, 5.0), look_at: (0.0, 0.0, 0.0), fov_deg: 45.0, width: 8, height: 6),
        materials: {"m": (diffuse: (0.5, 0.5, 0.5))},
        objects: [
            (name: "ball", shape: Sphere, material: "m"),
            (name: "die", shape: Csg(op: Difference, operands: [
                (name: "body", shape: Csg(op: Intersection, operands: [
                    (name: "cube", shape: Cube), (name: "round", shape: Sphere)])),
                (name: "pip", shape: Sphere),
            ]), material: "m"),
            (name: "pair", shape: Group(children: [
                (name: "left", shape: Sphere), (name: "right", shape: Cube)]), material: "m"),
        ],
    )"#;

    #[test]
    fn nodes_are_ranges_of_leaves_in_tree_order() {
        let scene = parse_scene(TREES).unwrap();
        let nodes = Nodes::new(&scene, &World::new(&scene).unwrap());
        let names: Vec<&str> = nodes.nodes.iter().map(|n| n.name.as_str()).collect();
        assert_eq!(
            names,
            [
                "ball",
                "die",
                "die/body",
                "die/body/cube",
                "die/body/round",
                "die/pip",
                "pair",
                "pair/left",
                "pair/right"
            ]
        );
        assert_eq!(nodes.leaves.len(), 6);
        assert_eq!(nodes.nodes[1].leaves, 1..4);
        assert_eq!(nodes.nodes[2].leaves, 1..3);
        // The pip is the die's third operand leaf; the pair's members are world objects.
        assert_eq!(nodes.leaf(1, 2), 3);
        assert_eq!(nodes.leaves[3].node, 5);
        assert_eq!(nodes.leaf(3, 0), 5);
        assert_eq!(nodes.object_of_leaf(5), 2);
        assert_eq!(nodes.chain(3).collect::<Vec<_>>(), [1, 5]);
        assert_eq!(nodes.chain(2).collect::<Vec<_>>(), [1, 2, 4]);
        assert_eq!(nodes.holding(1..3), Some(2));
        assert_eq!(nodes.holding(1..4), Some(1));
        let pip = &nodes.nodes[5];
        assert_eq!(
            pip.place,
            Place::Operand {
                op: CsgOp::Difference,
                index: 1
            }
        );
        assert!(pip.in_csg && !nodes.nodes[7].in_csg);
        assert_eq!(nodes.nodes[7].place, Place::Child);
        let mut energy = vec![0.0; 6];
        energy[3] = 1.0;
        assert_eq!(nodes.concentrated(&energy, 0.995), Some(5));
        energy[1] = 1.0;
        assert_eq!(nodes.concentrated(&energy, 0.995), Some(1));
    }
}
