//! Dragging an object's translate, rotate and scale handles. Each function takes the
//! pointer's ray when the drag started and its ray now, and returns the change, so the
//! point under the cursor stays under the cursor.

use glam::{DMat3, DVec3};

use super::{closest_on_line_to_ray, ray_plane};
use crate::scene::transform::sin_cos_deg;
use crate::trace::Ray;

/// A handle of the translate gizmo.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TranslateHandle {
    /// Move along world axis 0, 1 or 2 (x, y, z).
    Axis(usize),
    /// Move in the plane whose normal is world axis 0, 1 or 2.
    Plane(usize),
}

/// The unit vector of world axis `index`.
#[must_use]
pub fn world_axis(index: usize) -> DVec3 {
    [DVec3::X, DVec3::Y, DVec3::Z][index % 3]
}

/// The world offset of a translate drag from `start` to `now`, for a gizmo at `origin`;
/// `None` when the drag is degenerate (the ray parallel to the axis or plane).
#[must_use]
pub fn translate_drag(
    handle: TranslateHandle,
    origin: DVec3,
    start: &Ray,
    now: &Ray,
) -> Option<DVec3> {
    match handle {
        TranslateHandle::Axis(i) => {
            let axis = world_axis(i);
            let s0 = closest_on_line_to_ray(origin, axis, start)?;
            let s1 = closest_on_line_to_ray(origin, axis, now)?;
            Some(axis * (s1 - s0))
        }
        TranslateHandle::Plane(i) => {
            let normal = world_axis(i);
            Some(ray_plane(now, origin, normal)? - ray_plane(start, origin, normal)?)
        }
    }
}

/// The three axes the rotate rings turn about, for Euler angles applied X, then Y, then
/// Z: changing angle z turns about world z, angle y about Rz y, angle x about Rz Ry x. So
/// dragging ring `i` by some degrees changes `rotate_deg[i]` by exactly that much.
#[must_use]
pub fn euler_ring_axes(rotate_deg: DVec3) -> [DVec3; 3] {
    let (sy, cy) = sin_cos_deg(rotate_deg.y);
    let (sz, cz) = sin_cos_deg(rotate_deg.z);
    let rz = DMat3::from_cols(DVec3::new(cz, sz, 0.0), DVec3::new(-sz, cz, 0.0), DVec3::Z);
    let ry = DMat3::from_cols(DVec3::new(cy, 0.0, -sy), DVec3::Y, DVec3::new(sy, 0.0, cy));
    [rz * ry * DVec3::X, rz * DVec3::Y, DVec3::Z]
}

/// The signed angle in degrees a rotate drag turns about `axis` (right-handed) through
/// `centre`; `None` when a ray misses the ring's plane or passes through the centre.
#[must_use]
pub fn rotate_drag(centre: DVec3, axis: DVec3, start: &Ray, now: &Ray) -> Option<f64> {
    let v0 = ray_plane(start, centre, axis)? - centre;
    let v1 = ray_plane(now, centre, axis)? - centre;
    if v0.length_squared() == 0.0 || v1.length_squared() == 0.0 {
        return None;
    }
    let axis = axis.normalize();
    Some(axis.dot(v0.cross(v1)).atan2(v0.dot(v1)).to_degrees())
}

/// The factor a scale drag along the world direction `axis` through `centre` multiplies
/// the scale by: how much farther from the centre the pointer is along the axis now.
/// `None` when the drag started at the centre or a ray is parallel to the axis.
#[must_use]
pub fn scale_drag(centre: DVec3, axis: DVec3, start: &Ray, now: &Ray) -> Option<f64> {
    let s0 = closest_on_line_to_ray(centre, axis, start)?;
    let s1 = closest_on_line_to_ray(centre, axis, now)?;
    (s0.abs() > 1e-9 * axis.length()).then(|| s1 / s0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gizmo::ray_plane;
    use crate::scene::{Camera, Trs};
    use crate::trace::PinholeCamera;

    fn camera() -> PinholeCamera {
        let camera = Camera {
            position: DVec3::new(3.0, 4.0, 8.0),
            look_at: DVec3::ZERO,
            up: DVec3::Y,
            fov_deg: 50.0,
            width: 400,
            height: 300,
        };
        PinholeCamera::new(&camera, 400, 300)
    }

    #[test]
    fn axis_drag_keeps_the_grabbed_point_under_the_cursor() {
        let cam = camera();
        let origin = DVec3::new(1.0, 0.5, -0.5);
        // Grab the x arrow at origin + 0.8 x, drag to where origin + 2.3 x projects.
        let a = cam.project(origin + DVec3::X * 0.8).unwrap();
        let b = cam.project(origin + DVec3::X * 2.3).unwrap();
        let offset =
            translate_drag(TranslateHandle::Axis(0), origin, &cam.ray(a), &cam.ray(b)).unwrap();
        assert!((offset - DVec3::X * 1.5).length() < 1e-9, "{offset}");
    }

    #[test]
    fn plane_drag_moves_by_the_world_offset_between_the_two_points() {
        let cam = camera();
        let origin = DVec3::new(0.0, 0.0, 0.0);
        let p0 = DVec3::new(0.3, 0.0, 0.2);
        let p1 = DVec3::new(-1.2, 0.0, 0.9);
        let (a, b) = (cam.project(p0).unwrap(), cam.project(p1).unwrap());
        let offset =
            translate_drag(TranslateHandle::Plane(1), origin, &cam.ray(a), &cam.ray(b)).unwrap();
        assert!((offset - (p1 - p0)).length() < 1e-9, "{offset}");
        // And the point grabbed is under the cursor after the move.
        let moved = ray_plane(&cam.ray(a), origin, DVec3::Y).unwrap() + offset;
        assert!((cam.project(moved).unwrap() - b).length() < 1e-6);
    }

    #[test]
    fn rotate_drag_measures_the_angle_swept_around_the_axis() {
        let cam = camera();
        let (p0, p1) = (DVec3::new(1.0, 0.0, 0.0), DVec3::new(0.0, 0.0, -1.0));
        let a = cam.ray(cam.project(p0).unwrap());
        let b = cam.ray(cam.project(p1).unwrap());
        // x towards -z is +90 degrees about +y (right-handed).
        let angle = rotate_drag(DVec3::ZERO, DVec3::Y, &a, &b).unwrap();
        assert!((angle - 90.0).abs() < 1e-7, "{angle}");
    }

    #[test]
    fn ring_axes_change_exactly_one_euler_angle() {
        let rotate_deg = DVec3::new(20.0, -35.0, 50.0);
        let axes = euler_ring_axes(rotate_deg);
        for (i, axis) in axes.iter().enumerate() {
            // Turning the object by 10 degrees about ring i's axis...
            let turned = glam::DMat3::from_axis_angle(*axis, 10f64.to_radians())
                * Trs {
                    rotate_deg,
                    ..Trs::default()
                }
                .world_from_object()
                .matrix3;
            // ...is the same as adding 10 to Euler angle i.
            let mut changed = rotate_deg;
            changed[i] += 10.0;
            let expected = Trs {
                rotate_deg: changed,
                ..Trs::default()
            }
            .world_from_object()
            .matrix3;
            assert!(turned.abs_diff_eq(expected, 1e-12), "ring {i}");
        }
    }

    #[test]
    fn scale_drag_is_the_ratio_of_distances_along_the_axis() {
        let cam = camera();
        let a = cam.ray(cam.project(DVec3::new(0.0, 0.0, 0.5)).unwrap());
        let b = cam.ray(cam.project(DVec3::new(0.0, 0.0, 1.5)).unwrap());
        let factor = scale_drag(DVec3::ZERO, DVec3::Z, &a, &b).unwrap();
        assert!((factor - 3.0).abs() < 1e-9, "{factor}");
        let centre = cam.ray(cam.project(DVec3::ZERO).unwrap());
        assert_eq!(scale_drag(DVec3::ZERO, DVec3::Z, &centre, &b), None);
    }
}
