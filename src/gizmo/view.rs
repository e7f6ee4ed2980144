//! Sizing gizmos on screen and the shapes they frame: how many world units a pixel spans
//! at a point, an object's own axes, and the sphere around an object for framing.

use glam::DVec3;

use crate::scene::{Camera, Object, Trs};
use crate::trace::shapes::shape_bounds;

/// World units one pixel spans at the depth of `p_world`, in an image `height_px` tall,
/// so a handle can keep a constant size on screen. Never zero or negative: a point at or
/// behind the eye gets the size it would have at unit depth.
#[must_use]
pub fn world_per_pixel(camera: &Camera, p_world: DVec3, height_px: f64) -> f64 {
    let forward = (camera.look_at - camera.position).normalize_or_zero();
    let depth = (p_world - camera.position).dot(forward);
    let depth = if depth > 0.0 { depth } else { 1.0 };
    2.0 * depth * (camera.fov_deg.to_radians() * 0.5).tan() / height_px.max(1.0)
}

/// The object's own x, y and z axes in world space (unit length, without scale), for
/// a rotation of `rotate_deg` applied as in [`Trs`].
#[must_use]
pub fn object_axes(rotate_deg: DVec3) -> [DVec3; 3] {
    let rotation = Trs {
        rotate_deg,
        ..Trs::default()
    }
    .world_from_object()
    .matrix3;
    [rotation.x_axis, rotation.y_axis, rotation.z_axis]
}

/// The sphere (centre, radius) around an object's bounding box in world space.
#[must_use]
pub fn bounding_sphere(object: &Object) -> (DVec3, f64) {
    let bounds = shape_bounds(&object.shape).transformed(&object.transform.world_from_object());
    let centre = (bounds.min + bounds.max) * 0.5;
    (centre, (bounds.max - centre).length())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Shape, Transform};
    use crate::trace::PinholeCamera;

    fn camera() -> Camera {
        crate::gizmo::test_camera(DVec3::new(2.0, 3.0, 9.0))
    }

    #[test]
    fn a_pixel_sized_step_projects_to_one_pixel() {
        let c = camera();
        let cam = PinholeCamera::new(&c, 400, 300);
        let p = DVec3::new(0.5, 1.5, -1.0);
        let per_px = world_per_pixel(&c, p, 300.0);
        // 100 pixels' worth along the camera's right vector is 100 pixels on screen.
        let forward = (c.look_at - c.position).normalize();
        let right = forward.cross(c.up).normalize();
        let a = cam.project(p).unwrap();
        let b = cam.project(p + right * per_px * 100.0).unwrap();
        assert!(
            ((b - a).length() - 100.0).abs() < 1e-9,
            "{}",
            (b - a).length()
        );
        assert!(world_per_pixel(&c, c.position - forward, 300.0) > 0.0);
    }

    #[test]
    fn object_axes_are_the_rotated_unit_axes() {
        let axes = object_axes(DVec3::new(0.0, 90.0, 0.0));
        assert!((axes[0] - DVec3::new(0.0, 0.0, -1.0)).length() < 1e-12);
        assert!((axes[1] - DVec3::Y).length() < 1e-12);
        assert!((axes[2] - DVec3::X).length() < 1e-12);
    }

    #[test]
    fn bounding_sphere_holds_the_scaled_shape() {
        let object = Object {
            name: "ball".into(),
            shape: Shape::Sphere,
            transform: Transform::Trs(Trs {
                translate: DVec3::new(1.0, 2.0, 3.0),
                rotate_deg: DVec3::ZERO,
                scale: DVec3::splat(2.0),
            }),
            material: "m".into(),
        };
        let (centre, radius) = bounding_sphere(&object);
        assert!((centre - DVec3::new(1.0, 2.0, 3.0)).length() < 1e-9);
        // The box around a sphere of radius 2: half-diagonal 2 sqrt 3 (plus the margin).
        assert!(radius >= 2.0 * 3f64.sqrt() && radius < 2.0 * 3f64.sqrt() * 1.01);
    }
}
