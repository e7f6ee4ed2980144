//! What the converter keeps between blocks before the scene is assembled: the material
//! definitions in file order, and the objects whose materials are not named yet.

use glam::DVec3;

use super::super::syntax::At;
use crate::scene::{CsgOp, Material, Shape, Transform};

/// One Material block's result.
pub(super) struct Definition {
    pub(super) name: String,
    pub(super) material: Material,
    pub(super) line: usize,
    pub(super) used: bool,
}

/// Which material a leaf copied.
#[derive(Clone, Copy, Debug)]
pub(super) enum Base {
    Default,
    Definition(usize),
}

/// What a pending object is.
pub(super) enum PendingShape {
    /// A shape with its material: the one it copied, and its own changed copy if any.
    Leaf {
        shape: Shape,
        base: Base,
        own: Option<Material>,
    },
    /// A CSG node.
    Csg {
        op: CsgOp,
        operands: Vec<PendingObject>,
    },
    /// A group.
    Group(Vec<PendingObject>),
}

/// An object before materials are named.
pub(super) struct PendingObject {
    /// The name its comment gives it.
    pub(super) name: Option<String>,
    pub(super) shape: PendingShape,
    pub(super) transform: Transform,
    pub(super) at: At,
}

impl PendingObject {
    /// The centre of the object in its parent's space: a leaf's unit shape centre (the
    /// origin, but (0, 0, 0.5) for the cone, whose apex is at the origin), a tree's mean
    /// of its members' centres, placed by its transform.
    pub(super) fn centre(&self) -> DVec3 {
        let local = match &self.shape {
            PendingShape::Leaf {
                shape: Shape::Cone, ..
            } => DVec3::new(0.0, 0.0, 0.5),
            PendingShape::Leaf { .. } => DVec3::ZERO,
            PendingShape::Csg {
                operands: members, ..
            }
            | PendingShape::Group(members) => {
                let sum: DVec3 = members.iter().map(PendingObject::centre).sum();
                sum / members.len().max(1) as f64
            }
        };
        self.transform.world_from_object().transform_point3(local)
    }

    /// The shape's name in the scene format ("Sphere", "Csg", "Group"...).
    pub(super) fn kind_name(&self) -> &'static str {
        match &self.shape {
            PendingShape::Leaf { shape, .. } => shape.name(),
            PendingShape::Csg { .. } => "Csg",
            PendingShape::Group(_) => "Group",
        }
    }
}
