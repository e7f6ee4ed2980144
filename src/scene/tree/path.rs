//! Nodes of object trees by path: the index of a top-level object, then of a child or
//! operand at each level below (`[2, 0, 3]`: the fourth child of the first child of the
//! third object). The editor selects, edits and moves nodes by these paths.

use glam::DAffine3;

use crate::scene::model::Object;

/// The object at `path` among `objects` (and their children); `None` past the tree.
#[must_use]
pub fn object_at<'a>(objects: &'a [Object], path: &[usize]) -> Option<&'a Object> {
    let (&first, rest) = path.split_first()?;
    let mut object = objects.get(first)?;
    for &index in rest {
        object = object.shape.children().get(index)?;
    }
    Some(object)
}

/// The object at `path`, to edit.
pub fn object_at_mut<'a>(objects: &'a mut [Object], path: &[usize]) -> Option<&'a mut Object> {
    let (&first, rest) = path.split_first()?;
    let mut object = objects.get_mut(first)?;
    for &index in rest {
        object = object.shape.children_mut()?.get_mut(index)?;
    }
    Some(object)
}

/// The list holding the node at `path` (the scene's objects, or its parent's children
/// or operands), to edit; `None` when the path leads nowhere.
pub fn siblings_mut<'a>(
    objects: &'a mut Vec<Object>,
    path: &[usize],
) -> Option<&'a mut Vec<Object>> {
    match path.split_last()? {
        (_, []) => Some(objects),
        (_, parent) => object_at_mut(objects, parent)?.shape.children_mut(),
    }
}

/// The transform from the space the node at `path` is placed in (its parent's object
/// space) to the world: the identity for a top-level object.
#[must_use]
pub fn world_from_parent(objects: &[Object], path: &[usize]) -> DAffine3 {
    let mut placed = DAffine3::IDENTITY;
    for depth in 1..path.len() {
        match object_at(objects, &path[..depth]) {
            Some(node) => placed *= node.transform.world_from_object(),
            None => break,
        }
    }
    placed
}

/// The node's names from the top level down, joined by `/` (`"die/pip 3"`), as
/// validation errors and `--hide` write them.
#[must_use]
pub fn path_name(objects: &[Object], path: &[usize]) -> String {
    (1..=path.len())
        .filter_map(|depth| object_at(objects, &path[..depth]).map(|o| o.name.as_str()))
        .collect::<Vec<_>>()
        .join("/")
}

/// The material a node's surfaces show: its own, or the nearest ancestor's where it
/// names none.
#[must_use]
pub fn effective_material<'a>(objects: &'a [Object], path: &[usize]) -> Option<&'a str> {
    (1..=path.len())
        .rev()
        .filter_map(|depth| object_at(objects, &path[..depth]))
        .map(|o| o.material.as_str())
        .find(|m| !m.is_empty())
}

#[cfg(test)]
mod tests {
    use super::super::test_trees::leaf;
    use super::*;
    use crate::scene::{CsgOp, Shape, Transform, Trs};
    use glam::DVec3;

    fn die() -> Vec<Object> {
        vec![
            leaf("ball", 0.0, ""),
            Object {
                name: "die".to_owned(),
                shape: Shape::Csg {
                    op: CsgOp::Difference,
                    operands: vec![
                        leaf("body", 0.0, ""),
                        leaf("pip 1", 1.0, ""),
                        leaf("pip 2", 2.0, ""),
                    ],
                },
                transform: Transform::Trs(Trs {
                    translate: DVec3::new(0.0, 5.0, 0.0),
                    ..Trs::default()
                }),
                material: "ivory".to_owned(),
            },
        ]
    }

    #[test]
    fn paths_find_nodes_their_names_their_placement_and_their_material() {
        let mut objects = die();
        assert_eq!(object_at(&objects, &[1, 2]).unwrap().name, "pip 2");
        assert!(object_at(&objects, &[1, 3]).is_none());
        assert!(
            object_at(&objects, &[0, 0]).is_none(),
            "a leaf has no children"
        );
        assert!(object_at(&objects, &[]).is_none());
        assert_eq!(path_name(&objects, &[1, 2]), "die/pip 2");
        assert_eq!(effective_material(&objects, &[1, 2]), Some("ivory"));
        assert_eq!(effective_material(&objects, &[0]), None);
        let placed = world_from_parent(&objects, &[1, 2]);
        assert_eq!(placed.translation, DVec3::new(0.0, 5.0, 0.0));
        assert_eq!(world_from_parent(&objects, &[1]), DAffine3::IDENTITY);
        object_at_mut(&mut objects, &[1, 0]).unwrap().name = "cube".to_owned();
        assert_eq!(path_name(&objects, &[1, 0]), "die/cube");
        assert_eq!(siblings_mut(&mut objects, &[1, 0]).unwrap().len(), 3);
        assert_eq!(siblings_mut(&mut objects, &[1]).unwrap().len(), 2);
        assert!(
            siblings_mut(&mut objects, &[0, 0]).is_none(),
            "a leaf holds no list"
        );
    }
}
