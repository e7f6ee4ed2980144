//! One compiled object: a placed primitive, or a CSG node whose tree is its shape.

use std::sync::Arc;

use glam::{DAffine3, DMat3, DVec3};

use super::csg::CsgTree;
use crate::trace::ray::Ray;
use crate::trace::shapes;
use crate::trace::shapes::{Aabb, BoundingSphere, Primitive, ShapeHit, TriangleMesh, gamma};

/// One object, placed and ready to intersect.
#[derive(Clone, Debug)]
pub struct WorldObject {
    /// Its tree path in the scene (its name at the top level, `"snowman/body"` below),
    /// for the inspector and errors.
    pub name: String,
    /// Which unit shape; for a CSG node (`csg` is set) `Primitive::Cube`, its tree being
    /// the shape.
    pub shape: Primitive,
    /// For a CSG node, its compiled tree (operands in the node's object space).
    pub csg: Option<Arc<CsgTree>>,
    /// For a mesh (`shape` is [`Primitive::Mesh`]): its triangles, shared with the store.
    pub mesh: Option<Arc<TriangleMesh>>,
    /// Object-to-world transform.
    pub world_from_object: DAffine3,
    /// World-to-object transform.
    pub object_from_world: DAffine3,
    /// Takes object-space normals to world space: the inverse transpose of the 3x3 part.
    pub normal_from_object: DMat3,
    /// World-space bounds, slightly padded.
    pub bounds: Aabb,
    /// Index into [`super::World::materials`]; for a CSG node its first leaf's (each
    /// surface point has its operand's: [`super::World::material_at`]).
    pub material: usize,
    /// For spheres, and CSG nodes held by one of their sphere leaves: a bounding sphere,
    /// tighter than the box and tested without transforming the ray.
    bounding_sphere: Option<BoundingSphere>,
    /// Component-wise absolute values of the two 3x3 parts, for the error bounds.
    abs_world_from_object: DMat3,
    abs_object_from_world: DMat3,
}

/// What an object is made of besides its placement.
pub(crate) enum Body {
    /// A unit shape alone.
    Primitive,
    /// A CSG node's tree.
    Csg(Arc<CsgTree>),
    /// A mesh's triangles.
    Mesh(Arc<TriangleMesh>),
}

/// An object's hit in its object space, and which leaf of a CSG node it is on (0 for a
/// primitive).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ObjectHit {
    pub hit: ShapeHit,
    pub part: u32,
}

impl WorldObject {
    /// A primitive, a CSG node with its tree or a mesh with its triangles, placed by
    /// `world_from_object`.
    pub(crate) fn new(
        name: String,
        shape: Primitive,
        body: Body,
        world_from_object: DAffine3,
        material: usize,
    ) -> Self {
        let object_from_world = world_from_object.inverse();
        let (csg, mesh) = match body {
            Body::Primitive => (None, None),
            Body::Csg(tree) => (Some(tree), None),
            Body::Mesh(mesh) => (None, Some(mesh)),
        };
        let bounds = match (&csg, &mesh) {
            (Some(tree), _) => tree.extent.world_bounds(&world_from_object),
            (_, Some(mesh)) => mesh.bounds().transformed(&world_from_object),
            _ => shapes::object_bounds(shape).transformed(&world_from_object),
        };
        Self {
            name,
            shape,
            world_from_object,
            object_from_world,
            normal_from_object: world_from_object.matrix3.inverse().transpose(),
            bounds,
            material,
            bounding_sphere: match &csg {
                None => (shape == Primitive::Sphere)
                    .then(|| BoundingSphere::around_unit_sphere(&world_from_object)),
                Some(tree) => tree.bounding_sphere.map(|node_from_sphere| {
                    BoundingSphere::around_unit_sphere(&(world_from_object * node_from_sphere))
                }),
            },
            csg,
            mesh,
            abs_world_from_object: abs_mat(&world_from_object.matrix3),
            abs_object_from_world: abs_mat(&object_from_world.matrix3),
        }
    }

    /// Whether a ray leaving the surface on its outer side can meet the object again
    /// (not for a single convex or flat primitive, nor a convex CSG node; possibly for
    /// a torus or a tube, whose far side lies across the hole, other CSG nodes and
    /// meshes).
    #[must_use]
    pub fn can_meet_itself(&self) -> bool {
        self.mesh.is_some()
            || !self.shape.is_convex()
            || self.csg.as_ref().is_some_and(|tree| !tree.convex)
    }

    /// Where the object is a round ball (a sphere scaled alike on every axis), its centre
    /// and radius.
    #[must_use]
    pub fn ball(&self) -> Option<(DVec3, f64)> {
        if self.shape != Primitive::Sphere || self.csg.is_some() || self.mesh.is_some() {
            return None;
        }
        let m = self.world_from_object.matrix3;
        let lengths = DVec3::new(m.x_axis.length(), m.y_axis.length(), m.z_axis.length());
        let (shortest, longest) = (lengths.min_element(), lengths.max_element());
        let skew = m.x_axis.dot(m.y_axis).abs()
            + m.y_axis.dot(m.z_axis).abs()
            + m.z_axis.dot(m.x_axis).abs();
        (longest - shortest <= 1e-12 * longest && skew <= 1e-12 * longest * longest)
            .then_some((self.world_from_object.translation, longest))
    }

    /// A ball holding the whole object, by centre and radius: its bounding sphere where
    /// it has one, otherwise the ball round its box.
    #[must_use]
    pub fn bounding_ball(&self) -> (DVec3, f64) {
        match &self.bounding_sphere {
            Some(sphere) => (sphere.centre, sphere.radius_sq.sqrt()),
            None => (
                (self.bounds.min + self.bounds.max) * 0.5,
                (self.bounds.max - self.bounds.min).length() * 0.5,
            ),
        }
    }

    /// The bounds test: whether the ray may meet the object before `t_max`.
    #[inline]
    fn may_be_hit(&self, ray: &Ray, inv_dir: DVec3, t_max: f64) -> bool {
        match &self.bounding_sphere {
            Some(sphere) => sphere.hit_by(ray, t_max),
            None => self.bounds.hit_by(ray, inv_dir, t_max),
        }
    }

    /// The closest hit of a world ray with `t` in (0, t_max), in object space.
    #[inline(always)]
    pub(crate) fn hit(&self, ray: &Ray, inv_dir: DVec3, t_max: f64) -> Option<ObjectHit> {
        if !self.may_be_hit(ray, inv_dir, t_max) {
            return None;
        }
        self.hit_unbounded(&ray.transformed(&self.object_from_world), t_max)
    }

    /// The closest hit of an object-space ray, without the bounds test.
    #[inline(always)]
    pub(crate) fn hit_unbounded(&self, ray: &Ray, t_max: f64) -> Option<ObjectHit> {
        if let Some(mesh) = &self.mesh {
            return mesh
                .intersect(ray, t_max)
                .map(|hit| ObjectHit { hit, part: 0 });
        }
        if let Some(tree) = &self.csg {
            return tree_hit(tree, ray, t_max);
        }
        shapes::intersect(self.shape, ray, t_max).map(|hit| ObjectHit { hit, part: 0 })
    }

    /// Whether a world ray meets the object with `t` in (0, t_max).
    #[inline(always)]
    pub(crate) fn blocks(&self, ray: &Ray, inv_dir: DVec3, t_max: f64) -> bool {
        if !self.may_be_hit(ray, inv_dir, t_max) {
            return false;
        }
        let ray = ray.transformed(&self.object_from_world);
        if let Some(mesh) = &self.mesh {
            return mesh.occluded(&ray, t_max);
        }
        if let Some(tree) = &self.csg {
            return tree_blocks(tree, &ray, t_max);
        }
        shapes::occluded(self.shape, &ray, t_max)
    }

    /// Bound on the world hit point's distance from the surface: the object-space error
    /// carried through the matrix, the rounding of the transform itself, and the rounding
    /// a spawned ray suffers on its way back to object space (mapped to world units).
    /// Inlined into every hit record: as a call it ran 1.1% more instructions a frame.
    #[inline(always)]
    pub(crate) fn world_error(&self, hit: &ShapeHit, p_world: DVec3) -> DVec3 {
        let m = self.abs_world_from_object;
        let inv = self.abs_object_from_world;
        let carried = m * hit.p_error;
        let forward = gamma(3) * (m * hit.p.abs() + self.world_from_object.translation.abs());
        let back_in_object =
            gamma(3) * (inv * p_world.abs() + self.object_from_world.translation.abs());
        carried + forward + m * back_in_object
    }
}

/// A CSG object's hit, out of line: the primitives' path stays small where it is inlined.
#[cold]
#[inline(never)]
fn tree_hit(tree: &CsgTree, ray: &Ray, t_max: f64) -> Option<ObjectHit> {
    tree.intersect(ray, t_max).map(|h| ObjectHit {
        hit: h.hit,
        part: h.leaf,
    })
}

/// Whether a CSG object blocks a ray, out of line as [`tree_hit`].
#[cold]
#[inline(never)]
fn tree_blocks(tree: &CsgTree, ray: &Ray, t_max: f64) -> bool {
    tree.occluded(ray, t_max)
}

fn abs_mat(m: &DMat3) -> DMat3 {
    DMat3::from_cols(m.x_axis.abs(), m.y_axis.abs(), m.z_axis.abs())
}
