//! The unit shapes, in object space (the course's five, the octahedron, and the torus and
//! the tube with their parameter), and triangle meshes (`mesh`, `mesh_bvh`, `triangle`),
//! which carry their own data and are reached through their `TriangleMesh`. Each unit
//! shape's file has the same parts in the same order:
//! bounds, `intersect` (closest hit with its error bound) and `occluded` (any hit, for
//! shadow rays). One `match` here forwards to them.
//!
//! Every `intersect` returns the hit point re-projected onto the exact surface and a
//! per-component bound on its remaining distance from the surface (see docs/NUMERICS.md).

mod bounds;
mod caps;
mod cone;
mod cube;
mod cylinder;
mod hit;
mod mesh;
mod mesh_bvh;
mod mesh_solid;
mod octahedron;
mod plane;
mod polynomial;
pub(crate) mod quadratic;
mod slabs;
mod sphere;
mod torus;
mod triangle;
mod tube;

#[cfg(test)]
mod crossings_tests;

use glam::DVec3;

pub use self::bounds::{Aabb, BoundingSphere, largest_stretch};
use self::hit::ConvexSolid;
pub(crate) use self::hit::in_range;
pub use self::hit::{ShapeHit, gamma};
pub use self::mesh::{MeshStore, TriangleHit, TriangleMesh};
use crate::scene::Shape;
use crate::trace::ray::Ray;

/// The shapes the tracer intersects directly: the scene's leaf shapes in a `Copy` form
/// the hot loops can match on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Primitive {
    /// The unit sphere.
    Sphere,
    /// The two-sided unit square in z = 0.
    Plane,
    /// The cube [-1, 1]^3.
    Cube,
    /// The capped unit cylinder.
    Cylinder,
    /// The capped unit cone.
    Cone,
    /// The unit octahedron |x| + |y| + |z| <= 1.
    Octahedron,
    /// The torus around the unit circle in z = 0, with tube radius `minor`.
    Torus {
        /// The tube's radius.
        minor: f64,
    },
    /// The unit cylinder's solid with the hole of radius `inner` taken out.
    Tube {
        /// The hole's radius.
        inner: f64,
    },
    /// A triangle mesh: its triangles live in the object's `TriangleMesh`, so the free
    /// functions below see no surface for it (never `Primitive::of` a shape).
    Mesh,
}

impl Primitive {
    /// The primitive for a scene shape, or `None` where the tracer cannot draw it.
    #[must_use]
    pub fn of(shape: &Shape) -> Option<Primitive> {
        Some(match shape {
            Shape::Sphere => Primitive::Sphere,
            Shape::Plane => Primitive::Plane,
            Shape::Cube => Primitive::Cube,
            Shape::Cylinder => Primitive::Cylinder,
            Shape::Cone => Primitive::Cone,
            Shape::Octahedron => Primitive::Octahedron,
            Shape::Torus { minor } => Primitive::Torus { minor: *minor },
            Shape::Tube { inner } => Primitive::Tube { inner: *inner },
            _ => return None,
        })
    }

    /// The scene shape this primitive draws.
    #[must_use]
    pub fn shape(self) -> Shape {
        match self {
            Primitive::Sphere => Shape::Sphere,
            Primitive::Plane => Shape::Plane,
            Primitive::Cube => Shape::Cube,
            Primitive::Cylinder => Shape::Cylinder,
            Primitive::Cone => Shape::Cone,
            Primitive::Octahedron => Shape::Octahedron,
            Primitive::Torus { minor } => Shape::Torus { minor },
            Primitive::Tube { inner } => Shape::Tube { inner },
            // The path lives with the object, not the primitive.
            Primitive::Mesh => Shape::Mesh {
                path: String::new(),
            },
        }
    }

    /// Whether the surface bounds a convex solid or is flat, so a ray leaving it on its
    /// outer side cannot meet it again.
    #[must_use]
    pub fn is_convex(self) -> bool {
        !matches!(
            self,
            Primitive::Mesh | Primitive::Torus { .. } | Primitive::Tube { .. }
        )
    }
}

/// The object-space bounding box of a unit shape (empty for a mesh: see
/// [`TriangleMesh::bounds`]).
#[must_use]
pub fn object_bounds(shape: Primitive) -> Aabb {
    match shape {
        Primitive::Sphere => sphere::bounds(),
        Primitive::Plane => plane::bounds(),
        Primitive::Cube => cube::bounds(),
        Primitive::Cylinder => cylinder::bounds(),
        Primitive::Cone => cone::bounds(),
        Primitive::Octahedron => octahedron::bounds(),
        Primitive::Torus { minor } => torus::bounds(minor),
        Primitive::Tube { .. } => tube::bounds(),
        Primitive::Mesh => Aabb::new(DVec3::INFINITY, DVec3::NEG_INFINITY),
    }
}

/// The object-space bounds of any scene shape, for framing, placement and gizmos: a
/// tree's are its children's placed bounds joined (a Difference's, its first operand's);
/// a mesh's, which need its file, stand as the unit cube until the mesh is loaded.
#[must_use]
pub fn shape_bounds(shape: &Shape) -> Aabb {
    use crate::scene::CsgOp;
    let unit_cube = Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0));
    match shape {
        Shape::Mesh { .. } => unit_cube,
        // A Difference lies within its first operand; the others within all operands.
        Shape::Csg { op, operands } => {
            let take = if *op == CsgOp::Difference {
                1
            } else {
                operands.len()
            };
            placed_union(&operands[..take.min(operands.len())]).unwrap_or(unit_cube)
        }
        Shape::Group { children } => placed_union(children).unwrap_or(unit_cube),
        leaf => object_bounds(Primitive::of(leaf).expect("every other shape is a primitive")),
    }
}

/// The box around `objects`, each placed by its transform; `None` for none.
fn placed_union(objects: &[crate::scene::Object]) -> Option<Aabb> {
    objects
        .iter()
        .map(|o| shape_bounds(&o.shape).transformed(&o.transform.world_from_object()))
        .reduce(|a, b| a.union(&b))
}

/// The closest hit of an object-space ray with `t` in (0, t_max) (none for a mesh: see
/// [`TriangleMesh::intersect`]).
#[must_use]
#[inline]
pub fn intersect(shape: Primitive, ray: &Ray, t_max: f64) -> Option<ShapeHit> {
    match shape {
        Primitive::Sphere => sphere::intersect(ray, t_max),
        Primitive::Plane => plane::intersect(ray, t_max),
        Primitive::Cube => cube::intersect(ray, t_max),
        Primitive::Cylinder => cylinder::intersect(ray, t_max),
        Primitive::Cone => cone::intersect(ray, t_max),
        Primitive::Octahedron => octahedron::intersect(ray, t_max),
        Primitive::Torus { minor } => torus::intersect(ray, t_max, minor),
        Primitive::Tube { inner } => tube::intersect(ray, t_max, inner),
        Primitive::Mesh => None,
    }
}

/// Whether an object-space ray hits the shape with `t` in (0, t_max) (never for a mesh:
/// see [`TriangleMesh::occluded`]).
#[must_use]
#[inline]
pub fn occluded(shape: Primitive, ray: &Ray, t_max: f64) -> bool {
    match shape {
        Primitive::Sphere => sphere::occluded(ray, t_max),
        Primitive::Plane => plane::occluded(ray, t_max),
        Primitive::Cube => cube::occluded(ray, t_max),
        Primitive::Cylinder => cylinder::occluded(ray, t_max),
        Primitive::Cone => cone::occluded(ray, t_max),
        Primitive::Octahedron => octahedron::occluded(ray, t_max),
        Primitive::Torus { minor } => torus::occluded(ray, t_max, minor),
        Primitive::Tube { inner } => tube::occluded(ray, t_max, inner),
        Primitive::Mesh => false,
    }
}

/// Every crossing of an object-space ray's whole line (any `t`, negative too) with the
/// shape's solid, in ascending `t`, with outward normals, appended to `out`: what CSG
/// combines (see `crate::trace::world` for the trees). Bounded solids give entry, exit
/// pairs (a line that only touches one gives the point twice); the plane, the half-space
/// z <= 0 here, gives one crossing, and [`starts_inside`] says which side the line
/// starts on.
#[inline]
pub(crate) fn crossings(shape: Primitive, ray: &Ray, out: &mut Vec<ShapeHit>) {
    match shape {
        Primitive::Sphere => sphere::crossings(ray, out),
        Primitive::Plane => plane::crossings(ray, out),
        Primitive::Cube => cube::crossings(ray, out),
        Primitive::Cylinder => cylinder::Cylinder::crossings(ray, out),
        Primitive::Cone => cone::Cone::crossings(ray, out),
        Primitive::Octahedron => octahedron::crossings(ray, out),
        Primitive::Torus { minor } => torus::crossings(ray, out, minor),
        Primitive::Tube { inner } => tube::crossings(ray, out, inner),
        // A mesh's crossings need its triangles: `TriangleMesh::crossings`. CSG trees
        // are built from unit shapes only (see `world::csg`), so none reaches here.
        Primitive::Mesh => {}
    }
}

/// The ends of the whole line's span through a unit sphere, cube, cylinder or cone
/// (`crossings`' two `t`s, without their surface points): `Some(None)` where the line
/// misses; `None` for the other shapes, whose crossings are worked out in full.
#[must_use]
#[inline(always)]
pub(crate) fn line_span(shape: Primitive, ray: &Ray) -> Option<Option<[f64; 2]>> {
    match shape {
        Primitive::Sphere => Some(sphere::line_span(ray)),
        Primitive::Cube => Some(cube::line_span(ray)),
        Primitive::Cylinder => Some(cylinder::Cylinder::line_span(ray)),
        Primitive::Cone => Some(cone::Cone::line_span(ray)),
        _ => None,
    }
}

/// Crossing `k` (0 the entry, 1 the exit) of a line through a sphere, cube, cylinder or
/// cone whose [`line_span`] is some span, exactly as [`crossings`] would list it.
#[must_use]
pub(crate) fn line_crossing(shape: Primitive, ray: &Ray, k: usize, t: f64) -> ShapeHit {
    match shape {
        Primitive::Sphere => sphere::crossing_at(ray, t),
        Primitive::Cube => cube::crossing_of_line(ray, k),
        Primitive::Cylinder => cylinder::Cylinder::crossing_of_line(ray, k),
        Primitive::Cone => cone::Cone::crossing_of_line(ray, k),
        _ => unreachable!("line_span is None for {shape:?}"),
    }
}

/// Whether the line of an object-space ray is inside the solid before its first crossing
/// (at t = -infinity): only ever for the half-space of a plane, which a line going up
/// leaves, and a line parallel to it never crosses.
#[must_use]
#[inline]
pub(crate) fn starts_inside(shape: Primitive, ray: &Ray) -> bool {
    match shape {
        Primitive::Plane if ray.dir.z == 0.0 => ray.origin.z <= 0.0,
        Primitive::Plane => ray.dir.z > 0.0,
        _ => false,
    }
}

#[cfg(test)]
pub(crate) mod test_support {
    //! Shared checks for the shape tests.
    use super::*;

    /// Asserts a hit at parameter `t` with the given unit outward normal.
    pub fn assert_hit(hit: Option<ShapeHit>, ray: &Ray, t: f64, normal: DVec3) {
        let hit = hit.unwrap_or_else(|| panic!("expected a hit at t = {t} for {ray:?}"));
        assert!(
            (hit.t - t).abs() <= 1e-12 * t.abs().max(1.0),
            "t = {} expected {t}",
            hit.t
        );
        assert!(
            (hit.n.normalize() - normal).length() < 1e-9,
            "normal {} expected {normal}",
            hit.n
        );
        assert!((hit.p - ray.at(hit.t)).length() < 1e-9);
        assert!(hit.p.is_finite() && hit.p_error.is_finite());
    }
}
