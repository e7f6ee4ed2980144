//! Nodes put into and taken out of the trees by path: insert, remove, delete (the
//! editor's: a CSG node keeps one operand, and something takes the deleted node's place)
//! and add a child to a tree node.

use super::path::{object_at, object_at_mut, siblings_mut};
use crate::scene::model::Object;
use crate::scene::shape::Shape;

/// Puts `node` into the trees so that it is at `path` (the nodes from there on in its
/// list move one down).
///
/// # Errors
/// When the list at `path` does not exist or ends before its last index.
pub fn insert_node(objects: &mut Vec<Object>, path: &[usize], node: Object) -> Result<(), String> {
    let &at = path.last().ok_or("no such object")?;
    let siblings = siblings_mut(objects, path).ok_or("no such object")?;
    if at > siblings.len() {
        return Err("no such object".to_owned());
    }
    siblings.insert(at, node);
    Ok(())
}

/// Takes the node at `path` out of its tree (a top-level object, a group's child or a
/// CSG operand), returning it; `None` when the path leads nowhere.
pub fn remove_node(objects: &mut Vec<Object>, path: &[usize]) -> Option<Object> {
    let &last = path.last()?;
    let siblings = siblings_mut(objects, path)?;
    (last < siblings.len()).then(|| siblings.remove(last))
}

/// Deletes the node at `path` and says which node takes its place: the next in its
/// list, else the previous, else its parent (`None` for the last top-level object).
///
/// # Errors
/// When the path leads nowhere, or the node is the last operand of a CSG node (which
/// needs one: delete the CSG node instead).
pub fn delete_node(
    objects: &mut Vec<Object>,
    path: &[usize],
) -> Result<Option<Vec<usize>>, String> {
    let (&at, parent) = path.split_last().ok_or("no such object")?;
    if let Some(holder) = (!parent.is_empty())
        .then(|| object_at(objects, parent))
        .flatten()
        && matches!(holder.shape, Shape::Csg { .. })
        && holder.shape.children().len() == 1
    {
        return Err(format!(
            "\u{201c}{}\u{201d} needs at least one operand; delete the CSG node instead",
            holder.name
        ));
    }
    remove_node(objects, path).ok_or("no such object")?;
    let left = siblings_len(objects, parent);
    Ok(match left {
        0 if parent.is_empty() => None,
        0 => Some(parent.to_vec()),
        left => Some([parent, &[at.min(left - 1)]].concat()),
    })
}

/// How many nodes the list under `parent` holds (the top level for `[]`).
fn siblings_len(objects: &[Object], parent: &[usize]) -> usize {
    match parent {
        [] => objects.len(),
        _ => object_at(objects, parent).map_or(0, |o| o.shape.children().len()),
    }
}

/// Adds `child` as the last child or operand of the tree node at `path` and returns its
/// path.
///
/// # Errors
/// When the path leads nowhere or to a leaf.
pub fn add_child(
    objects: &mut [Object],
    path: &[usize],
    child: Object,
) -> Result<Vec<usize>, String> {
    let node = object_at_mut(objects, path).ok_or("no such object")?;
    let children = node
        .shape
        .children_mut()
        .ok_or_else(|| format!("\u{201c}{}\u{201d} is not a CSG node or a group", node.name))?;
    children.push(child);
    Ok([path, &[children.len() - 1]].concat())
}

#[cfg(test)]
mod tests {
    use super::super::test_trees::{die_scene, leaf, names};
    use super::*;

    #[test]
    fn a_node_inserted_at_a_path_is_found_there_and_removed_from_there() {
        let mut scene = die_scene();
        insert_node(&mut scene.objects, &[1, 1, 1], leaf("pip 3", 3.0, "")).unwrap();
        assert_eq!(object_at(&scene.objects, &[1, 1, 1]).unwrap().name, "pip 3");
        assert_eq!(object_at(&scene.objects, &[1, 1, 2]).unwrap().name, "pip 2");
        insert_node(&mut scene.objects, &[3], leaf("last", 0.0, "")).unwrap();
        assert_eq!(scene.objects[3].name, "last");
        assert!(insert_node(&mut scene.objects, &[1, 1, 9], leaf("x", 0.0, "")).is_err());
        assert!(insert_node(&mut scene.objects, &[0, 0], leaf("x", 0.0, "")).is_err());
        assert_eq!(
            remove_node(&mut scene.objects, &[1, 1, 1]).unwrap().name,
            "pip 3"
        );
        assert_eq!(remove_node(&mut scene.objects, &[3]).unwrap().name, "last");
        assert!(remove_node(&mut scene.objects, &[1, 1, 2]).is_none());
        assert_eq!(scene, die_scene());
    }

    #[test]
    fn a_deleted_node_is_replaced_by_its_neighbour_or_its_parent() {
        let mut scene = die_scene();
        assert_eq!(
            delete_node(&mut scene.objects, &[1, 1, 1]),
            Ok(Some(vec![1, 1, 0]))
        );
        assert_eq!(
            delete_node(&mut scene.objects, &[1, 1, 0]),
            Ok(Some(vec![1, 1]))
        );
        assert_eq!(delete_node(&mut scene.objects, &[0]), Ok(Some(vec![0])));
        assert_eq!(names(&scene), ["die", "body", "pips", "lamp"]);
        assert_eq!(delete_node(&mut scene.objects, &[1]), Ok(Some(vec![0])));
        assert_eq!(
            delete_node(&mut scene.objects, &[0, 7]),
            Err("no such object".to_owned())
        );
    }

    #[test]
    fn a_csg_node_keeps_its_last_operand() {
        let mut scene = die_scene();
        delete_node(&mut scene.objects, &[1, 1]).unwrap();
        let refused = delete_node(&mut scene.objects, &[1, 0]).unwrap_err();
        assert!(refused.contains("die"), "{refused}");
        assert_eq!(object_at(&scene.objects, &[1, 0]).unwrap().name, "body");
        // A group may be emptied.
        let mut scene = die_scene();
        delete_node(&mut scene.objects, &[1, 1, 0]).unwrap();
        assert_eq!(
            delete_node(&mut scene.objects, &[1, 1, 0]),
            Ok(Some(vec![1, 1]))
        );
        assert!(
            object_at(&scene.objects, &[1, 1])
                .unwrap()
                .shape
                .children()
                .is_empty()
        );
        assert_eq!(delete_node(&mut scene.objects, &[0]), Ok(Some(vec![0])));
        delete_node(&mut scene.objects, &[0]).unwrap();
        assert_eq!(delete_node(&mut scene.objects, &[0]), Ok(None));
    }

    #[test]
    fn a_child_is_added_last_to_a_tree_node_only() {
        let mut scene = die_scene();
        let path = add_child(&mut scene.objects, &[1, 1], leaf("pip 3", 3.0, "")).unwrap();
        assert_eq!(path, [1, 1, 2]);
        assert_eq!(object_at(&scene.objects, &path).unwrap().name, "pip 3");
        let refused = add_child(&mut scene.objects, &[0], leaf("x", 0.0, "")).unwrap_err();
        assert!(refused.contains("ball"), "{refused}");
    }
}
