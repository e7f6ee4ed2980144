//! The scene's object trees: a walk over every node, nodes addressed by path, and the
//! edits that put nodes in, take them out, move them and wrap or unwrap them, each
//! keeping every leaf where it is in the world. The editor's commands, the importer and
//! the mesh loader go through here.
//!
//! | file       | what                                                              |
//! |------------|-------------------------------------------------------------------|
//! | `walk`     | every node in scene order with the material it shows; an editing walk |
//! | `path`     | a node by its path of indices, its list, its parent's placement    |
//! | `names`    | a free name for a new node or material                            |
//! | `edit`     | insert, remove, delete (something takes the place), add a child   |
//! | `reparent` | a node moved elsewhere in the trees, staying where it is          |
//! | `wrap`     | nodes wrapped into a new group or CSG node; a group unwrapped     |

mod edit;
mod names;
mod path;
mod reparent;
mod walk;
mod wrap;

pub use edit::{add_child, delete_node, insert_node, remove_node};
pub use names::unique_name;
pub use path::{
    effective_material, object_at, object_at_mut, path_name, siblings_mut, world_from_parent,
};
pub use reparent::move_node;
pub use walk::{Node, Nodes};
pub use wrap::{unwrap_group, wrap_node, wrap_nodes};

#[cfg(test)]
mod test_trees;
