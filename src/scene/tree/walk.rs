//! Every object of a scene, trees included: a walk in scene order (a node, then its
//! children or operands), each node with the material it shows, and one that may edit
//! each node. Work lists, not recursion: trees may be deep.

use crate::scene::model::{Object, Scene};

/// One node met on a walk.
#[derive(Clone, Copy, Debug)]
pub struct Node<'a> {
    /// The object (a leaf, a group or a CSG node).
    pub object: &'a Object,
    /// The material its surfaces show: its own, or the nearest ancestor's where it names
    /// none (empty when no node up the tree names one).
    pub shown_material: &'a str,
}

impl Node<'_> {
    /// Whether nothing hangs below this node (a shape, or an empty group).
    #[must_use]
    pub fn is_leaf(&self) -> bool {
        self.object.shape.children().is_empty()
    }
}

/// The walk of [`Scene::nodes`].
#[derive(Clone, Debug)]
pub struct Nodes<'a> {
    /// Nodes still to visit, the next on top.
    work: Vec<Node<'a>>,
}

impl<'a> Nodes<'a> {
    fn push_reversed(&mut self, objects: &'a [Object], inherited: &'a str) {
        self.work.extend(objects.iter().rev().map(|object| Node {
            object,
            shown_material: if object.material.is_empty() {
                inherited
            } else {
                object.material.as_str()
            },
        }));
    }
}

impl<'a> Iterator for Nodes<'a> {
    type Item = Node<'a>;

    fn next(&mut self) -> Option<Node<'a>> {
        let node = self.work.pop()?;
        self.push_reversed(node.object.shape.children(), node.shown_material);
        Some(node)
    }
}

impl Scene {
    /// Every object, trees included, in scene order: each node before its children or
    /// operands, which come in their order.
    #[must_use]
    pub fn nodes(&self) -> Nodes<'_> {
        let mut nodes = Nodes { work: Vec::new() };
        nodes.push_reversed(&self.objects, "");
        nodes
    }

    /// Calls `edit` on every object, trees included, in scene order; a node's children
    /// are visited as `edit` leaves them.
    pub fn edit_nodes(&mut self, mut edit: impl FnMut(&mut Object)) {
        let mut work: Vec<&mut Object> = self.objects.iter_mut().rev().collect();
        while let Some(object) = work.pop() {
            edit(object);
            if let Some(children) = object.shape.children_mut() {
                work.extend(children.iter_mut().rev());
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_trees::{die_scene, names};
    use crate::scene::Scene;

    #[test]
    fn the_walk_meets_every_node_in_scene_order_with_the_material_it_shows() {
        let scene = die_scene();
        let met: Vec<(&str, &str, bool)> = scene
            .nodes()
            .map(|n| (n.object.name.as_str(), n.shown_material, n.is_leaf()))
            .collect();
        assert_eq!(
            met,
            [
                ("ball", "red", true),
                ("die", "ivory", false),
                ("body", "ivory", true),
                ("pips", "ivory", false),
                ("pip 1", "black", true),
                ("pip 2", "ivory", true),
                ("lamp", "", true),
            ]
        );
        assert_eq!(Scene::empty().nodes().count(), 0);
    }

    #[test]
    fn the_editing_walk_reaches_every_node_once() {
        let mut scene = die_scene();
        scene.edit_nodes(|object| object.name.push('!'));
        assert_eq!(
            names(&scene),
            [
                "ball!", "die!", "body!", "pips!", "pip 1!", "pip 2!", "lamp!"
            ]
        );
    }
}
