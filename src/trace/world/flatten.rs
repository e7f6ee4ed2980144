//! The scene's object trees flattened into world objects: a Group only places its
//! children (world = parent's world * child's, an empty material inherited), so each of
//! its leaves and CSG nodes becomes an object of its own; a CSG node becomes one object
//! whose shape is its tree. Each keeps the scene index of the top-level object it came
//! from (its id: hiding, picking and isolation act on whole top-level objects) and its
//! tree path as its name. A work list, not recursion, walks the trees.

use std::sync::Arc;

use glam::DAffine3;

use super::csg::CsgTree;
use super::object::{Body, WorldObject};
use crate::scene::{Object, Scene, SceneError, Shape};
use crate::trace::shapes::{MeshStore, Primitive};

/// A node still to compile: the object, its world placement, the material it inherits,
/// its tree path and the top-level object it belongs to.
struct Pending<'a> {
    object: &'a Object,
    world_from_parent: DAffine3,
    material: &'a str,
    path: String,
    top_level: usize,
    /// Child indices from the top-level object down to this one.
    below: Vec<usize>,
}

/// The world objects of `scene` in tree order, the scene index of each one's top-level
/// object, and the child indices from there down to it.
///
/// # Errors
/// A shape the tracer cannot draw, or a leaf without a material, by tree path.
pub(crate) fn flatten(
    scene: &Scene,
    material_names: &[String],
    meshes: &MeshStore,
) -> Result<Flattened, SceneError> {
    let material_index = |name: &str| {
        material_names
            .binary_search_by(|m| m.as_str().cmp(name))
            .ok()
    };
    let mut objects = Vec::with_capacity(scene.objects.len());
    let mut scene_index = Vec::with_capacity(scene.objects.len());
    let mut tree_paths = Vec::with_capacity(scene.objects.len());
    let mut work: Vec<Pending> = scene
        .objects
        .iter()
        .enumerate()
        .rev()
        .map(|(top_level, object)| Pending {
            object,
            world_from_parent: DAffine3::IDENTITY,
            material: &object.material,
            path: object.name.clone(),
            top_level,
            below: Vec::new(),
        })
        .collect();
    while let Some(node) = work.pop() {
        let object = node.object;
        let world_from_object = node.world_from_parent * object.transform.world_from_object();
        let (shape, body) = match &object.shape {
            Shape::Group { children } => {
                work.extend(children.iter().enumerate().rev().map(|(k, child)| Pending {
                    object: child,
                    world_from_parent: world_from_object,
                    material: if child.material.is_empty() {
                        node.material
                    } else {
                        &child.material
                    },
                    path: format!("{}/{}", node.path, child.name),
                    top_level: node.top_level,
                    below: [node.below.as_slice(), &[k]].concat(),
                }));
                continue;
            }
            Shape::Csg { op, operands } => {
                let tree = CsgTree::build(
                    *op,
                    operands,
                    node.material,
                    &node.path,
                    &material_index,
                    meshes,
                )?;
                (Primitive::Cube, Body::Csg(std::sync::Arc::new(tree)))
            }
            Shape::Mesh { path } => {
                let mesh = meshes.for_object(path, &node.path)?;
                (Primitive::Mesh, Body::Mesh(Arc::clone(mesh)))
            }
            leaf => (
                Primitive::of(leaf).ok_or_else(|| not_drawn(&node.path, leaf))?,
                Body::Primitive,
            ),
        };
        let material = match &body {
            Body::Csg(tree) => tree.leaves.first().map_or(0, |leaf| leaf.material),
            _ => material_index(node.material).ok_or_else(|| {
                SceneError::Invalid(format!(
                    "object \"{}\": no material (neither its own nor a parent's)",
                    node.path
                ))
            })?,
        };
        objects.push(WorldObject::new(
            node.path,
            shape,
            body,
            world_from_object,
            material,
        ));
        scene_index.push(node.top_level);
        tree_paths.push(node.below);
    }
    Ok((objects, scene_index, tree_paths))
}

/// What [`flatten`] makes: the world objects, the scene index of each one's top-level
/// object, and the child indices from there down to it.
pub(crate) type Flattened = (Vec<WorldObject>, Vec<usize>, Vec<Vec<usize>>);

/// The error for a shape the tracer cannot draw yet.
fn not_drawn(path: &str, shape: &Shape) -> SceneError {
    SceneError::Invalid(format!(
        "object \"{path}\": the tracer cannot draw a {} yet",
        shape.name()
    ))
}

/// `scene` without the tree node that became world object `world_index` of a world
/// compiled from it ([`crate::trace::World::new`], every object shown): a leaf, a CSG
/// node or, at the top level, the object. `None` past the last world object.
#[must_use]
pub fn scene_without_world_object(scene: &Scene, world_index: usize) -> Option<Scene> {
    // The same walk as `flatten`, keeping each node's child indices.
    let mut work: Vec<(&Object, Vec<usize>)> = scene
        .objects
        .iter()
        .enumerate()
        .rev()
        .map(|(i, o)| (o, vec![i]))
        .collect();
    let mut seen = 0;
    let path = loop {
        let (object, path) = work.pop()?;
        if let Shape::Group { children } = &object.shape {
            work.extend(children.iter().enumerate().rev().map(|(i, child)| {
                let mut child_path = path.clone();
                child_path.push(i);
                (child, child_path)
            }));
            continue;
        }
        if seen == world_index {
            break path;
        }
        seen += 1;
    };
    let mut without = scene.clone();
    let (&last, parents) = path.split_last()?;
    let mut list = &mut without.objects;
    for &i in parents {
        list = match &mut list[i].shape {
            Shape::Group { children } => children,
            _ => unreachable!("only groups are walked into"),
        };
    }
    list.remove(last);
    Some(without)
}
