//! The object list and its trees: each object's shape parameters, transform and
//! material, named by its tree path (`"snowman/body"`) in every message.

use std::collections::BTreeMap;

use super::failure::{invalid, list_or_none, prefixed};
use crate::scene::error::SceneError;
use crate::scene::model::{Material, Object};
use crate::scene::shape::Shape;
use crate::scene::transform::Transform;

/// The deepest object tree accepted: a root object and up to this many levels of
/// CSG operands or group children below it. Checks walk trees with work lists, so depth
/// costs no stack here; the limit bounds what the RON reader and the editor must nest.
pub const MAX_TREE_DEPTH: usize = 1000;

/// An object waiting to be checked, with what it inherits from its ancestors.
struct Pending<'a> {
    object: &'a Object,
    /// `objects[3] "snowman/body"`, for messages.
    at: String,
    /// The tree path so far (`snowman/body`).
    path: String,
    /// The nearest ancestor's material, if any names one.
    inherited_material: Option<&'a str>,
    depth: usize,
}

/// Checks every object of the scene and every object below it.
pub(super) fn check_objects(
    objects: &[Object],
    materials: &BTreeMap<String, Material>,
) -> Result<(), SceneError> {
    let mut pending: Vec<Pending> = objects
        .iter()
        .enumerate()
        .rev()
        .map(|(index, object)| Pending {
            object,
            at: format!("objects[{index}] \"{}\"", object.name),
            path: object.name.clone(),
            inherited_material: None,
            depth: 0,
        })
        .collect();
    while let Some(item) = pending.pop() {
        check_object(&item, materials)?;
        let own = Some(item.object.material.as_str()).filter(|m| !m.is_empty());
        let inherited_material = own.or(item.inherited_material);
        for child in item.object.shape.children().iter().rev() {
            let path = format!("{}/{}", item.path, child.name);
            pending.push(Pending {
                object: child,
                at: format!("object \"{path}\""),
                path,
                inherited_material,
                depth: item.depth + 1,
            });
        }
    }
    Ok(())
}

fn check_object(item: &Pending, materials: &BTreeMap<String, Material>) -> Result<(), SceneError> {
    let object = item.object;
    let at = &item.at;
    if item.depth > MAX_TREE_DEPTH {
        return invalid(format!(
            "{at}: the object tree is more than {MAX_TREE_DEPTH} levels deep"
        ));
    }
    check_material_name(object, item.inherited_material, materials).map_err(|e| prefixed(at, e))?;
    check_transform(&object.transform).map_err(|e| prefixed(at, e))?;
    check_shape(&object.shape).map_err(|e| prefixed(at, e))
}

/// A named material must exist; a leaf needs one of its own or from an ancestor.
fn check_material_name(
    object: &Object,
    inherited: Option<&str>,
    materials: &BTreeMap<String, Material>,
) -> Result<(), SceneError> {
    let known = |name: &str| materials.contains_key(name);
    if object.material.is_empty() {
        if object.shape.is_tree_node() || inherited.is_some_and(known) {
            return Ok(());
        }
        let defined = list_or_none(materials.keys());
        return invalid(format!(
            "no material (name one of: {defined}; inside a tree a parent's applies)"
        ));
    }
    if matches!(object.shape, Shape::Group { .. }) && !known(&object.material) {
        return invalid(format!(
            "unknown material \"{}\" on a group (a group's material applies to children \
             that name none; defined: {})",
            object.material,
            list_or_none(materials.keys())
        ));
    }
    if !known(&object.material) {
        return invalid(format!(
            "unknown material \"{}\" (defined: {})",
            object.material,
            list_or_none(materials.keys())
        ));
    }
    Ok(())
}

/// The parameters of shapes that have them, and a CSG node's operands.
fn check_shape(shape: &Shape) -> Result<(), SceneError> {
    match shape {
        Shape::Torus { minor } if !(minor.is_finite() && *minor > 0.0) => {
            return invalid(format!(
                "Torus minor is {minor}; the tube radius must be a finite number above 0"
            ));
        }
        Shape::Tube { inner } if !(inner.is_finite() && *inner > 0.0 && *inner < 1.0) => {
            return invalid(format!(
                "Tube inner is {inner}; the hole's radius must be between 0 and 1"
            ));
        }
        Shape::Mesh { path } if path.trim().is_empty() => {
            return invalid("Mesh path is empty; name an OBJ file".to_owned());
        }
        Shape::Csg { op, operands } if operands.is_empty() => {
            return invalid(format!(
                "Csg {} has no operands; it needs at least one solid",
                op.name()
            ));
        }
        _ => {}
    }
    Ok(())
}

fn check_transform(transform: &Transform) -> Result<(), SceneError> {
    if let Some(bad) = transform.numbers().into_iter().find(|x| !x.is_finite()) {
        return invalid(format!(
            "transform contains {bad}, which is not a finite number"
        ));
    }
    match transform {
        Transform::Trs(trs) => {
            if trs.scale.min_element().abs() == 0.0 || trs.scale.abs().min_element() == 0.0 {
                return invalid(format!(
                    "transform scale {} has a zero component, so the transform is singular",
                    trs.scale
                ));
            }
        }
        Transform::Matrix(_) => {
            let m = transform.world_from_object().matrix3;
            let size = m.x_axis.length() * m.y_axis.length() * m.z_axis.length();
            // Written so that a NaN determinant counts as singular too.
            let invertible = m.determinant().abs() > 1e-12 * size;
            if !invertible || size == 0.0 {
                return invalid(
                    "transform matrix is singular (its 3x3 part has no inverse)".to_owned(),
                );
            }
        }
    }
    let m = transform.world_from_object();
    if !m.inverse().is_finite() {
        return invalid("transform cannot be inverted in double precision".to_owned());
    }
    Ok(())
}
