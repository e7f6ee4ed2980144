//! Where a framing camera may stand: not inside a solid object, and not where a plane
//! hides what it looks at (under a floor seen from above, behind a wall).
//!
//! Planes are two-sided, so an eye on the far side of a floor sees the floor's underside
//! instead of the object on it. The rule is therefore about the line of sight: no plane
//! may cross the segment from the target to the eye. A plane the target lies on (framing
//! the floor itself) must be seen from the side the camera saw it from before.

use glam::{DAffine3, DVec3};

use crate::scene::{Object, Shape};

/// Relative distance under which the target counts as lying on a plane.
const ON_PLANE_TOLERANCE: f64 = 1e-9;

/// The objects an eye must keep clear of, placed once.
pub struct Obstacles {
    placed: Vec<Placed>,
}

/// One object: its shape and where it is.
struct Placed {
    shape: Shape,
    world_from_object: DAffine3,
    object_from_world: DAffine3,
}

impl Obstacles {
    /// The objects of a scene; any whose transform cannot be inverted is left out (a
    /// valid scene has none).
    #[must_use]
    pub fn new(objects: &[Object]) -> Self {
        let placed = objects
            .iter()
            .filter_map(|object| {
                let world_from_object = object.transform.world_from_object();
                let object_from_world = world_from_object.inverse();
                object_from_world.is_finite().then_some(Placed {
                    shape: object.shape.clone(),
                    world_from_object,
                    object_from_world,
                })
            })
            .collect();
        Self { placed }
    }

    /// Whether an eye at `eye_world` looking at `target_world` is outside every solid and
    /// has no plane in its line of sight; `previous_eye_world` is where the camera was,
    /// which decides the side from which a plane through the target is seen.
    #[must_use]
    pub fn is_clear(
        &self,
        target_world: DVec3,
        eye_world: DVec3,
        previous_eye_world: DVec3,
    ) -> bool {
        self.placed.iter().all(|object| {
            let eye = object.object_from_world.transform_point3(eye_world);
            match &object.shape {
                Shape::Plane => {
                    object.plane_leaves_view(target_world, eye_world, previous_eye_world)
                }
                solid => !contains(solid, eye),
            }
        })
    }
}

impl Placed {
    /// Whether the plane leaves the target in view from `eye_world`.
    fn plane_leaves_view(
        &self,
        target_world: DVec3,
        eye_world: DVec3,
        previous_world: DVec3,
    ) -> bool {
        let target = self.object_from_world.transform_point3(target_world);
        let eye = self.object_from_world.transform_point3(eye_world);
        let in_square = |p: DVec3| p.x.abs() <= 1.0 && p.y.abs() <= 1.0;
        if self.holds(target_world) && in_square(target) {
            // Framing the plane itself: from the side it was seen from, never edge-on.
            let previous = self.object_from_world.transform_point3(previous_world);
            let side = if previous.z == 0.0 { eye.z } else { previous.z };
            return eye.z * side > 0.0;
        }
        if target.z * eye.z >= 0.0 {
            return true; // both on one side: the segment cannot cross
        }
        let s = target.z / (target.z - eye.z);
        !in_square(target + s * (eye - target))
    }

    /// Whether the (infinite) plane passes through `p_world`, to a relative 1e-9.
    fn holds(&self, p_world: DVec3) -> bool {
        let origin = self.world_from_object.translation;
        let normal = self
            .object_from_world
            .matrix3
            .transpose()
            .mul_vec3(DVec3::Z)
            .normalize_or_zero();
        let size = p_world
            .abs()
            .max_element()
            .max(origin.abs().max_element())
            .max(1.0);
        normal.dot(p_world - origin).abs() <= ON_PLANE_TOLERANCE * size
    }
}

/// Whether an object-space point lies strictly inside a solid unit shape (the boundary
/// does not count). A plane has no inside.
#[must_use]
pub fn contains(shape: &Shape, p: DVec3) -> bool {
    let radial = p.x * p.x + p.y * p.y;
    match shape {
        Shape::Sphere => p.length_squared() < 1.0,
        Shape::Cube => p.abs().max_element() < 1.0,
        Shape::Cylinder => radial < 1.0 && p.z.abs() < 1.0,
        Shape::Cone => radial < p.z * p.z && p.z > 0.0 && p.z < 1.0,
        Shape::Torus { minor } => {
            let ring = radial.sqrt() - 1.0;
            ring * ring + p.z * p.z < minor * minor
        }
        Shape::Tube { inner } => radial < 1.0 && radial > inner * inner && p.z.abs() < 1.0,
        Shape::Octahedron => p.abs().element_sum() < 1.0,
        // Meshes and trees are not tested: the camera may stand inside them.
        Shape::Plane | Shape::Mesh { .. } | Shape::Csg { .. } | Shape::Group { .. } => false,
    }
}

/// Objects for the framing tests.
#[cfg(test)]
pub(super) mod test_objects {
    use glam::DVec3;

    use crate::scene::{Object, Shape, Transform, Trs};

    /// An object of `shape` placed by a translate / rotate / scale.
    pub fn placed(shape: Shape, translate: DVec3, rotate_deg: DVec3, scale: DVec3) -> Object {
        Object {
            name: shape.name().to_owned(),
            shape,
            transform: Transform::Trs(Trs {
                translate,
                rotate_deg,
                scale,
            }),
            material: "m".to_owned(),
        }
    }

    /// A square plane of half-size `half_size` at `centre`, turned by `rotate_deg`.
    pub fn plane(centre: DVec3, rotate_deg: DVec3, half_size: f64) -> Object {
        placed(
            Shape::Plane,
            centre,
            rotate_deg,
            DVec3::new(half_size, half_size, 1.0),
        )
    }

    /// A floor at y = 0, 20 units wide, facing +y.
    pub fn floor() -> Object {
        plane(DVec3::ZERO, DVec3::new(-90.0, 0.0, 0.0), 10.0)
    }
}

#[cfg(test)]
mod tests {
    use super::test_objects::{floor, placed};
    use super::*;

    #[test]
    fn solids_contain_their_inside_only() {
        assert!(contains(&Shape::Sphere, DVec3::new(0.5, 0.5, 0.5)));
        assert!(!contains(&Shape::Sphere, DVec3::new(0.6, 0.6, 0.6)));
        assert!(contains(&Shape::Cube, DVec3::new(0.9, -0.9, 0.9)));
        assert!(!contains(&Shape::Cube, DVec3::new(1.0, 0.0, 0.0)));
        assert!(contains(&Shape::Cylinder, DVec3::new(0.0, 0.9, -0.9)));
        assert!(!contains(&Shape::Cylinder, DVec3::new(0.0, 0.0, 1.1)));
        assert!(contains(&Shape::Cone, DVec3::new(0.1, 0.1, 0.5)));
        assert!(!contains(&Shape::Cone, DVec3::new(0.5, 0.5, 0.5)));
        assert!(
            !contains(&Shape::Cone, DVec3::new(0.0, 0.0, -0.5)),
            "the mirror cone"
        );
        assert!(!contains(&Shape::Plane, DVec3::ZERO));
    }

    #[test]
    fn an_eye_under_the_floor_or_inside_a_solid_is_not_clear() {
        let ball = placed(
            Shape::Sphere,
            DVec3::new(3.0, 1.0, 0.0),
            DVec3::ZERO,
            DVec3::ONE,
        );
        let obstacles = Obstacles::new(&[floor(), ball]);
        let target = DVec3::new(0.0, 1.0, 0.0);
        let above = DVec3::new(0.0, 4.0, 8.0);
        assert!(obstacles.is_clear(target, above, above));
        assert!(
            !obstacles.is_clear(target, DVec3::new(0.0, -2.0, 8.0), above),
            "under"
        );
        // Beyond the floor's edge the line of sight passes it by.
        assert!(obstacles.is_clear(target, DVec3::new(0.0, -2.0, 36.0), above));
        assert!(
            !obstacles.is_clear(target, DVec3::new(3.2, 1.1, 0.0), above),
            "in the ball"
        );
    }

    #[test]
    fn the_floor_itself_is_framed_from_the_side_it_was_seen_from() {
        let obstacles = Obstacles::new(&[floor()]);
        let centre = DVec3::ZERO;
        let above = DVec3::new(0.0, 5.0, 5.0);
        let below = DVec3::new(0.0, -5.0, 5.0);
        assert!(obstacles.is_clear(centre, DVec3::new(1.0, 3.0, 2.0), above));
        assert!(!obstacles.is_clear(centre, DVec3::new(1.0, -3.0, 2.0), above));
        assert!(obstacles.is_clear(centre, DVec3::new(1.0, -3.0, 2.0), below));
        assert!(
            !obstacles.is_clear(centre, DVec3::new(1.0, 0.0, 2.0), above),
            "edge-on"
        );
    }
}
