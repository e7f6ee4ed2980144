//! Compiling one scene object into a [`WorldObject`]: its primitive (or mesh), its
//! transforms and their absolute values for the error bounds, and its world bounds.

use std::sync::Arc;

use glam::DMat3;

use super::compiled::WorldObject;
use crate::scene::{Object, SceneError, Shape};
use crate::trace::shapes::{self, BoundingSphere, MeshStore, Primitive};

/// One scene object, placed and bounded, with `material` its index.
pub(super) fn compile_object(
    object: &Object,
    material: usize,
    meshes: &MeshStore,
) -> Result<WorldObject, SceneError> {
    let (shape, mesh) = match &object.shape {
        Shape::Mesh { path } => {
            let mesh = meshes.get(path).ok_or_else(|| {
                SceneError::Invalid(format!(
                    "object \"{}\": the mesh file \"{path}\" is not loaded",
                    object.name
                ))
            })?;
            (Primitive::Mesh, Some(Arc::clone(mesh)))
        }
        other => (Primitive::of(other).ok_or_else(|| not_drawn(object))?, None),
    };
    let world_from_object = object.transform.world_from_object();
    let object_from_world = world_from_object.inverse();
    let object_bounds = mesh
        .as_ref()
        .map_or_else(|| shapes::object_bounds(shape), |mesh| mesh.bounds());
    Ok(WorldObject {
        name: object.name.clone(),
        shape,
        world_from_object,
        object_from_world,
        normal_from_object: world_from_object.matrix3.inverse().transpose(),
        bounds: object_bounds.transformed(&world_from_object),
        material,
        mesh,
        bounding_sphere: (shape == Primitive::Sphere)
            .then(|| BoundingSphere::around_unit_sphere(&world_from_object)),
        abs_world_from_object: abs_mat(&world_from_object.matrix3),
        abs_object_from_world: abs_mat(&object_from_world.matrix3),
    })
}

/// The error for an object the tracer cannot draw yet.
fn not_drawn(object: &Object) -> SceneError {
    SceneError::Invalid(format!(
        "object \"{}\": the tracer cannot draw a {} yet",
        object.name,
        object.shape.name()
    ))
}

/// Component-wise absolute values of a matrix.
fn abs_mat(m: &DMat3) -> DMat3 {
    DMat3::from_cols(m.x_axis.abs(), m.y_axis.abs(), m.z_axis.abs())
}
