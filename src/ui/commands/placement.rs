//! Where new things land: an added object goes where the camera looks, upright (a
//! cylinder or cone stands on its cap), resting on the floor under that spot if there is
//! one; a duplicate moves aside along the camera's right, so it is seen next to the
//! original instead of hiding inside it.

use glam::{DAffine3, DQuat, DVec3};

use crate::scene::{Camera, Object, Scene, Shape, Transform, Trs};
use crate::trace::shapes::shape_bounds;

/// A floor is a plane whose normal is within this cosine of the camera's up.
const FLOOR_COS: f64 = 0.9;

/// The camera's frame: unit up (the scene's up, or +y if degenerate), forward and right.
struct Frame {
    up: DVec3,
    forward: DVec3,
    right: DVec3,
}

impl Frame {
    fn of(camera: &Camera) -> Self {
        let forward = (camera.look_at - camera.position).normalize_or(DVec3::NEG_Z);
        let up = camera.up.normalize_or(DVec3::Y);
        let right = forward.cross(up).normalize_or(DVec3::X);
        Self { up, forward, right }
    }
}

/// The size of a new unit shape for this scene: 1 for scenes viewed from a few units
/// away, a power of ten more or less for much larger or smaller scenes.
fn unit_size(camera: &Camera) -> f64 {
    let distance = (camera.look_at - camera.position).length();
    if !(distance.is_finite() && distance > 0.0) {
        return 1.0;
    }
    10f64.powi((distance / 6.0).log10().round() as i32)
}

/// The placement of a new `shape`: at the camera's target, or standing on the floor
/// under it; upright along the camera's up; a plane faces the camera.
#[must_use]
pub fn new_object_transform(scene: &Scene, shape: &Shape) -> Transform {
    let frame = Frame::of(&scene.camera);
    let size = unit_size(&scene.camera);
    // The object's +z: along up for a cylinder, down for a cone (cap below, apex up),
    // towards the camera for a plane.
    let axis = match shape {
        Shape::Cylinder | Shape::Tube { .. } | Shape::Torus { .. } => frame.up,
        Shape::Cone => -frame.up,
        Shape::Plane => -frame.forward,
        _ => DVec3::Z,
    };
    let rotation = DQuat::from_rotation_arc(DVec3::Z, axis);
    let target = scene.camera.look_at;
    let centre = match (shape, floor_under(scene, target, &frame)) {
        // Every upright unit shape reaches one unit below its origin.
        (
            Shape::Sphere
            | Shape::Cube
            | Shape::Cylinder
            | Shape::Cone
            | Shape::Tube { .. }
            | Shape::Octahedron,
            Some(floor),
        ) => floor + frame.up * size,
        _ => target,
    };
    let affine = DAffine3::from_scale_rotation_translation(DVec3::splat(size), rotation, centre);
    let mut trs = Trs::nearest(&affine);
    // Whole degrees stay whole in the inspector (no 89.99999999999999), and the scale and
    // position are the ones chosen, not their round trip through a matrix (a scale of 1
    // saved as 0.9999999999999998).
    trs.rotate_deg = (trs.rotate_deg * 1e9).round() / 1e9;
    trs.scale = DVec3::splat(size);
    trs.translate = centre;
    Transform::Trs(trs)
}

/// The highest floor plane under `target` (seen from above by the camera): the point on
/// it straight below (or above) `target`.
fn floor_under(scene: &Scene, target: DVec3, frame: &Frame) -> Option<DVec3> {
    scene
        .objects
        .iter()
        .filter(|o| o.shape == Shape::Plane)
        .filter_map(|plane| {
            let world_from_object = plane.transform.world_from_object();
            let normal =
                (world_from_object.matrix3.inverse().transpose() * DVec3::Z).normalize_or_zero();
            let facing = normal.dot(frame.up);
            if facing.abs() < FLOOR_COS {
                return None;
            }
            let origin = world_from_object.translation;
            let foot = target - frame.up * ((target - origin).dot(normal) / facing);
            let local = world_from_object.inverse().transform_point3(foot);
            let inside = local.x.abs() <= 1.0 && local.y.abs() <= 1.0;
            let seen_from_above = (scene.camera.position - foot).dot(frame.up) > 0.0;
            (inside && seen_from_above && foot.is_finite()).then_some(foot)
        })
        .max_by(|a, b| a.dot(frame.up).total_cmp(&b.dot(frame.up)))
}

/// How far a duplicate of an object moves: along the camera's right by its width seen
/// from the camera, and a quarter more, so the two do not overlap.
#[must_use]
pub fn duplicate_offset(scene: &Scene, shape: &Shape, transform: &Transform) -> DVec3 {
    let frame = Frame::of(&scene.camera);
    let bounds = shape_bounds(shape).transformed(&transform.world_from_object());
    let extent = bounds.max - bounds.min;
    let width = extent.dot(frame.right.abs());
    let width = if width.is_finite() && width > 0.0 {
        width
    } else {
        unit_size(&scene.camera)
    };
    frame.right * width * 1.25
}

/// A light's position moves aside by one unit of the scene's size.
#[must_use]
pub fn duplicate_light_offset(scene: &Scene) -> DVec3 {
    Frame::of(&scene.camera).right * unit_size(&scene.camera)
}

/// `transform` moved by `offset` in world space.
#[must_use]
pub fn moved(transform: &Transform, offset: DVec3) -> Transform {
    match *transform {
        Transform::Trs(trs) => Transform::Trs(Trs {
            translate: trs.translate + offset,
            ..trs
        }),
        Transform::Matrix(mut rows) => {
            for (row, delta) in rows.iter_mut().zip(offset.to_array()) {
                row[3] += delta;
            }
            Transform::Matrix(rows)
        }
    }
}

/// Where a new operand goes: half the size of the node's first operand, centred on that
/// one's +x face, so it shows at once (a bite of a Difference, a bump of a Union);
/// unit size at the origin in an empty node.
pub fn beside_first(first: Option<&Object>) -> Transform {
    let Some(Transform::Trs(first)) = first.map(|o| &o.transform) else {
        return Transform::Trs(Trs::default());
    };
    let size = first.scale.abs().element_sum() / 3.0;
    let face = first.world_from_object().transform_point3(glam::DVec3::X);
    Transform::Trs(Trs {
        translate: face,
        rotate_deg: glam::DVec3::ZERO,
        scale: glam::DVec3::splat(size * 0.5),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::PinholeCamera;

    fn world_bounds(shape: Shape, transform: &Transform) -> crate::trace::shapes::Aabb {
        shape_bounds(&shape).transformed(&transform.world_from_object())
    }

    #[test]
    fn a_new_cylinder_or_cone_stands_on_the_floor_in_view() {
        let scene = crate::scene::examples::default_scene();
        let camera = PinholeCamera::new(&scene.camera, scene.camera.width, scene.camera.height);
        for shape in [Shape::Cylinder, Shape::Cone, Shape::Cube, Shape::Sphere] {
            let transform = new_object_transform(&scene, &shape);
            let m = transform.world_from_object();
            let bounds = world_bounds(shape.clone(), &transform);
            // The default scene's floor is the plane y = 0.
            assert!(
                bounds.min.y.abs() < 1e-6,
                "{shape:?} rests on y = 0: {bounds:?}"
            );
            let p = camera
                .project(m.translation)
                .expect("in front of the camera");
            assert!(p.x > 0.0 && p.x < 800.0 && p.y > 0.0 && p.y < 600.0, "{p}");
            let axis = m.transform_vector3(DVec3::Z).normalize();
            match shape {
                Shape::Cylinder => assert!(axis.dot(DVec3::Y) > 0.999999, "upright"),
                Shape::Cone => assert!(axis.dot(DVec3::Y) < -0.999999, "on its cap"),
                _ => {}
            }
        }
    }

    #[test]
    fn without_a_floor_a_new_object_goes_to_the_cameras_target() {
        let scene = crate::ui::document::files::new_scene();
        let transform = new_object_transform(&scene, &Shape::Sphere);
        let centre = transform.world_from_object().translation;
        assert!(centre.abs_diff_eq(scene.camera.look_at, 1e-12), "{centre}");
    }

    #[test]
    fn a_new_object_carries_its_chosen_scale_and_place_exactly_not_float_noise() {
        let scene = crate::scene::examples::default_scene();
        for shape in Shape::ALL {
            let Transform::Trs(trs) = new_object_transform(&scene, &shape) else {
                panic!("a new object has a translate/rotate/scale");
            };
            let size = unit_size(&scene.camera);
            assert_eq!(trs.scale, DVec3::splat(size), "{shape:?}");
            // Saved, the numbers read as typed: no 0.9999999999999998.
            let text = ron::to_string(&trs.scale).unwrap();
            assert!(!text.contains("99999999"), "{shape:?}: {text}");
        }
    }

    #[test]
    fn a_duplicate_moves_aside_without_overlapping() {
        let scene = crate::scene::examples::default_scene();
        for object in &scene.objects[1..] {
            let offset = duplicate_offset(&scene, &object.shape, &object.transform);
            let copy = moved(&object.transform, offset);
            let a = world_bounds(object.shape.clone(), &object.transform);
            let b = world_bounds(object.shape.clone(), &copy);
            let apart = (0..3).any(|i| a.max[i] < b.min[i] || b.max[i] < a.min[i]);
            assert!(apart, "{}: {a:?} vs {b:?}", object.name);
        }
    }
}
