//! Moving a node to another place in the trees (the outliner's drag), keeping where it
//! is in the world and the material it shows.

use glam::DAffine3;

use super::Selection;
use super::tree_wrap::as_transform;
use crate::scene::Scene;
use crate::scene::Shape;
use crate::scene::tree_path::{
    effective_material, object_at, object_at_mut, siblings_mut, world_from_parent,
};

/// Moves the node at `from` into the tree node at `onto` (as its last child or
/// operand), or beside `onto` when that is a leaf (right after it), keeping where it is
/// in the world and the material it shows; one edit, one undo step. Selects it there.
pub(super) fn move_node(
    scene: &mut Scene,
    selection: &mut Selection,
    from: &[usize],
    onto: &[usize],
) -> Result<(), String> {
    if onto.starts_with(from) {
        return Err("a node cannot go inside itself".to_owned());
    }
    let target = object_at(&scene.objects, onto).ok_or("no such object")?;
    let (parent, index) = if target.shape.is_tree_node() {
        (onto.to_vec(), target.shape.children().len())
    } else {
        (onto[..onto.len() - 1].to_vec(), onto[onto.len() - 1] + 1)
    };
    let (old_parent, old_index) = from.split_at(from.len() - 1);
    if !old_parent.is_empty()
        && let Some(holder) = object_at(&scene.objects, old_parent)
        && matches!(holder.shape, Shape::Csg { .. })
        && holder.shape.children().len() == 1
    {
        return Err(format!(
            "\u{201c}{}\u{201d} needs at least one operand",
            holder.name
        ));
    }
    let mut node = object_at(&scene.objects, from)
        .ok_or("no such object")?
        .clone();
    // Same place in the world, same material, under the new parent.
    let world = world_from_parent(&scene.objects, from) * node.transform.world_from_object();
    let new_parent_world = match parent.as_slice() {
        [] => DAffine3::IDENTITY,
        _ => {
            world_from_parent(&scene.objects, &parent)
                * object_at(&scene.objects, &parent)
                    .ok_or("no such object")?
                    .transform
                    .world_from_object()
        }
    };
    let shown = effective_material(&scene.objects, from).map(str::to_owned);
    let inherited = effective_material(&scene.objects, &parent).map(str::to_owned);
    if node.material.is_empty() && (parent.is_empty() || shown != inherited) {
        node.material = shown.unwrap_or_default();
    }
    // Keep the numbers typed where the new parent places it as the old one did.
    if !new_parent_world.abs_diff_eq(world_from_parent(&scene.objects, from), 0.0) {
        node.transform = as_transform(&(new_parent_world.inverse() * world));
    }
    // Take it out, then find the destination again: taking it out shifts the indices
    // after it among its old siblings (and under them).
    let mut destination = parent.clone();
    let depth = old_parent.len();
    if destination.len() > depth
        && destination[..depth] == *old_parent
        && destination[depth] > old_index[0]
    {
        destination[depth] -= 1;
    }
    let mut index = index;
    if destination == old_parent && index > old_index[0] {
        index -= 1;
    }
    siblings_mut(&mut scene.objects, from)
        .ok_or("no such object")?
        .remove(old_index[0]);
    let list = match destination.as_slice() {
        [] => &mut scene.objects,
        _ => object_at_mut(&mut scene.objects, &destination)
            .and_then(|o| o.shape.children_mut())
            .ok_or("no such object")?,
    };
    let index = index.min(list.len());
    list.insert(index, node);
    destination.push(index);
    *selection = Selection::node(destination);
    Ok(())
}
