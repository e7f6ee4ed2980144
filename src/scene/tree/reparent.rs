//! Moving a node to another place in the trees (the outliner's drag), keeping where it
//! is in the world and the material it shows.

use glam::DAffine3;

use super::path::{effective_material, object_at, object_at_mut, siblings_mut, world_from_parent};
use crate::scene::model::Object;
use crate::scene::shape::Shape;
use crate::scene::transform::Transform;

/// Moves the node at `from` into the tree node at `onto` (as its last child or
/// operand), or beside `onto` when that is a leaf (right after it), keeping where it is
/// in the world and the material it shows. Returns its new path.
///
/// # Errors
/// When a path leads nowhere, the node would go inside itself, or it is the last operand
/// of a CSG node.
pub fn move_node(
    objects: &mut Vec<Object>,
    from: &[usize],
    onto: &[usize],
) -> Result<Vec<usize>, String> {
    if onto.starts_with(from) {
        return Err("a node cannot go inside itself".to_owned());
    }
    let target = object_at(objects, onto).ok_or("no such object")?;
    let (parent, index) = if target.shape.is_tree_node() {
        (onto.to_vec(), target.shape.children().len())
    } else {
        (onto[..onto.len() - 1].to_vec(), onto[onto.len() - 1] + 1)
    };
    let (old_parent, old_index) = from.split_at(from.len() - 1);
    if !old_parent.is_empty()
        && let Some(holder) = object_at(objects, old_parent)
        && matches!(holder.shape, Shape::Csg { .. })
        && holder.shape.children().len() == 1
    {
        return Err(format!(
            "\u{201c}{}\u{201d} needs at least one operand",
            holder.name
        ));
    }
    let mut node = object_at(objects, from).ok_or("no such object")?.clone();
    // Same place in the world, same material, under the new parent.
    let world = world_from_parent(objects, from) * node.transform.world_from_object();
    let new_parent_world = match parent.as_slice() {
        [] => DAffine3::IDENTITY,
        _ => {
            world_from_parent(objects, &parent)
                * object_at(objects, &parent)
                    .ok_or("no such object")?
                    .transform
                    .world_from_object()
        }
    };
    let shown = effective_material(objects, from).map(str::to_owned);
    let inherited = effective_material(objects, &parent).map(str::to_owned);
    if node.material.is_empty() && (parent.is_empty() || shown != inherited) {
        node.material = shown.unwrap_or_default();
    }
    // Keep the numbers typed where the new parent places it as the old one did.
    if !new_parent_world.abs_diff_eq(world_from_parent(objects, from), 0.0) {
        node.transform = Transform::from_affine(&(new_parent_world.inverse() * world));
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
    siblings_mut(objects, from)
        .ok_or("no such object")?
        .remove(old_index[0]);
    let list = match destination.as_slice() {
        [] => objects,
        _ => object_at_mut(objects, &destination)
            .and_then(|o| o.shape.children_mut())
            .ok_or("no such object")?,
    };
    let index = index.min(list.len());
    list.insert(index, node);
    destination.push(index);
    Ok(destination)
}

#[cfg(test)]
mod tests {
    use super::super::test_trees::{die_scene, leaf_placements, names};
    use super::*;

    /// Where the leaf called `name` is in the world.
    fn placed(scene: &crate::scene::Scene, name: &str) -> DAffine3 {
        leaf_placements(scene)
            .into_iter()
            .find(|(n, _)| n == name)
            .expect(name)
            .1
    }

    #[test]
    fn a_node_moved_into_a_turned_tree_stays_where_it_was_and_keeps_its_material() {
        let mut scene = die_scene();
        let before = placed(&scene, "ball");
        let path = move_node(&mut scene.objects, &[0], &[1, 1]).unwrap();
        assert_eq!(
            path,
            [0, 1, 2],
            "the die moved up when the ball left the top"
        );
        let ball = object_at(&scene.objects, &path).unwrap();
        assert_eq!(ball.name, "ball");
        assert_eq!(ball.material, "red");
        assert!(placed(&scene, "ball").abs_diff_eq(before, 1e-9));
        assert!(
            !matches!(ball.transform, Transform::Trs(t) if t.translate.x == -3.0),
            "its numbers are in the die's space now"
        );
    }

    #[test]
    fn a_node_dropped_on_a_leaf_goes_right_after_it_and_shows_what_it_showed() {
        let mut scene = die_scene();
        let before = placed(&scene, "pip 2");
        let path = move_node(&mut scene.objects, &[1, 1, 1], &[0]).unwrap();
        assert_eq!(path, [1]);
        assert_eq!(names(&scene)[..3], ["ball", "pip 2", "die"]);
        assert_eq!(scene.objects[1].material, "ivory", "inherited, now its own");
        assert!(placed(&scene, "pip 2").abs_diff_eq(before, 1e-9));
    }

    #[test]
    fn a_node_cannot_go_inside_itself_and_a_csg_keeps_its_last_operand() {
        let mut scene = die_scene();
        assert!(move_node(&mut scene.objects, &[1], &[1, 1]).is_err());
        move_node(&mut scene.objects, &[1, 1], &[2]).unwrap();
        assert!(move_node(&mut scene.objects, &[1, 0], &[0]).is_err());
        assert_eq!(
            names(&scene),
            ["ball", "die", "body", "lamp", "pips", "pip 1", "pip 2"]
        );
    }
}
