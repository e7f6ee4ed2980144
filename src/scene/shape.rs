//! What an object is: a unit shape, a mesh from a file, or a node of an object tree
//! (a CSG solid or a group). See the shape tables in SCENE_FORMAT.md.

use serde::{Deserialize, Serialize};

use super::model::Object;

/// An object's shape, in object space (see the tables in SCENE_FORMAT.md).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Shape {
    /// Centre at the origin, radius 1.
    Sphere,
    /// The two-sided square z = 0, -1 <= x, y <= 1.
    Plane,
    /// The cube [-1, 1]^3.
    Cube,
    /// x^2 + y^2 = 1 for -1 <= z <= 1, closed by disc caps.
    Cylinder,
    /// x^2 + y^2 = z^2 for 0 <= z <= 1, apex at the origin, capped at z = 1.
    Cone,
    /// The points within `minor` of the unit circle in z = 0 (axis z, major radius 1).
    Torus {
        /// Tube radius, > 0; from 1 on a horn or spindle torus.
        minor: f64,
    },
    /// The solid between the cylinders of radius `inner` and 1, -1 <= z <= 1, closed by
    /// flat rings.
    Tube {
        /// Radius of the hole, in (0, 1).
        inner: f64,
    },
    /// |x| + |y| + |z| <= 1.
    Octahedron,
    /// Triangles from a Wavefront OBJ file.
    Mesh {
        /// The file, relative to the scene file's folder.
        path: String,
    },
    /// A solid made of other solids.
    Csg {
        /// How the operands combine.
        op: CsgOp,
        /// The solids, each placed in this node's space.
        operands: Vec<Object>,
    },
    /// Objects placed together; placement only.
    Group {
        /// The objects, each placed in this group's space.
        children: Vec<Object>,
    },
}

/// How a [`Shape::Csg`] node combines its operands.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum CsgOp {
    /// Inside any operand.
    Union,
    /// Inside every operand.
    Intersection,
    /// Inside the first operand and none of the others.
    Difference,
}

impl CsgOp {
    /// Every operator, in menu order.
    pub const ALL: [CsgOp; 3] = [CsgOp::Union, CsgOp::Intersection, CsgOp::Difference];

    /// The name used in files and menus.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            CsgOp::Union => "Union",
            CsgOp::Intersection => "Intersection",
            CsgOp::Difference => "Difference",
        }
    }
}

impl Shape {
    /// The unit shapes the tracer draws, in menu order; the torus and the tube with the
    /// parameter a new one starts with.
    pub const ALL: [Shape; 8] = [
        Shape::Sphere,
        Shape::Plane,
        Shape::Cube,
        Shape::Cylinder,
        Shape::Cone,
        Shape::Torus { minor: 0.25 },
        Shape::Tube { inner: 0.5 },
        Shape::Octahedron,
    ];

    /// Whether this is one of [`Shape::ALL`]'s kinds, whatever its parameter: a leaf the
    /// tracer draws from its definition alone (not a mesh, whose file holds it, nor a
    /// tree).
    #[must_use]
    pub fn is_unit_shape(&self) -> bool {
        Shape::ALL.iter().any(|unit| unit.same_kind(self))
    }

    /// Whether both are the same kind of shape, parameters aside.
    #[must_use]
    pub fn same_kind(&self, other: &Shape) -> bool {
        std::mem::discriminant(self) == std::mem::discriminant(other)
    }

    /// The name used in files and menus.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Shape::Sphere => "Sphere",
            Shape::Plane => "Plane",
            Shape::Cube => "Cube",
            Shape::Cylinder => "Cylinder",
            Shape::Cone => "Cone",
            Shape::Torus { .. } => "Torus",
            Shape::Tube { .. } => "Tube",
            Shape::Octahedron => "Octahedron",
            Shape::Mesh { .. } => "Mesh",
            Shape::Csg { .. } => "Csg",
            Shape::Group { .. } => "Group",
        }
    }

    /// The objects this node holds: a CSG node's operands or a group's children; none
    /// for a leaf.
    #[must_use]
    pub fn children(&self) -> &[Object] {
        match self {
            Shape::Csg { operands, .. } => operands,
            Shape::Group { children } => children,
            _ => &[],
        }
    }

    /// The objects this node holds, to edit.
    pub fn children_mut(&mut self) -> Option<&mut Vec<Object>> {
        match self {
            Shape::Csg { operands, .. } => Some(operands),
            Shape::Group { children } => Some(children),
            _ => None,
        }
    }

    /// Whether this is a node of an object tree (CSG or group) rather than a leaf.
    #[must_use]
    pub fn is_tree_node(&self) -> bool {
        matches!(self, Shape::Csg { .. } | Shape::Group { .. })
    }
}
