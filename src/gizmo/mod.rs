//! The math of the viewport gizmos and camera navigation, in plain functions over glam
//! types: no egui here, so every drag is unit-tested without a window. The editor's
//! viewport turns pointer positions into rays with [`crate::trace::PinholeCamera`] (the
//! tracer's own camera) and feeds them to these functions.

pub mod frustum;
pub mod gesture;
pub mod handle;
pub mod handles;
pub mod navigate;
pub mod ray_paths;
pub mod snap;
pub mod spot;
pub mod transform_drag;
pub mod view;

use glam::DVec3;

use crate::trace::Ray;

pub use handle::{GizmoMode, HandleId};

/// The point of the line `origin + s * axis` closest to `ray`, as the parameter `s`;
/// `None` when the ray is parallel to the line (no unique closest point).
#[must_use]
pub fn closest_on_line_to_ray(origin: DVec3, axis: DVec3, ray: &Ray) -> Option<f64> {
    // Minimise |origin + s axis - (ray.origin + t ray.dir)| over s and t.
    let w = origin - ray.origin;
    let (a, b, c) = (axis.dot(axis), axis.dot(ray.dir), ray.dir.dot(ray.dir));
    let (d, e) = (axis.dot(w), ray.dir.dot(w));
    let denominator = a * c - b * b;
    if denominator.abs() <= 1e-12 * a * c {
        return None;
    }
    Some((b * e - c * d) / denominator)
}

/// Where `ray` meets the plane through `point` with normal `normal`, ahead of its origin.
#[must_use]
pub fn ray_plane(ray: &Ray, point: DVec3, normal: DVec3) -> Option<DVec3> {
    let denominator = ray.dir.dot(normal);
    if denominator.abs() <= 1e-12 * ray.dir.length() * normal.length() {
        return None;
    }
    let t = (point - ray.origin).dot(normal) / denominator;
    (t > 0.0).then(|| ray.at(t))
}

/// The tests' camera: 400x300, 40 degrees, looking from `position` at (0, 1, 0).
#[cfg(test)]
pub(crate) fn test_camera(position: glam::DVec3) -> crate::scene::Camera {
    crate::scene::Camera {
        position,
        look_at: glam::DVec3::new(0.0, 1.0, 0.0),
        up: glam::DVec3::Y,
        fov_deg: 40.0,
        width: 400,
        height: 300,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closest_point_on_a_line_to_a_crossing_ray() {
        // The x axis and a ray going down the line x = 2, z = 1.
        let ray = Ray::new(DVec3::new(2.0, 5.0, 1.0), -DVec3::Y);
        assert_eq!(
            closest_on_line_to_ray(DVec3::ZERO, DVec3::X, &ray),
            Some(2.0)
        );
        let parallel = Ray::new(DVec3::new(0.0, 1.0, 0.0), DVec3::X);
        assert_eq!(
            closest_on_line_to_ray(DVec3::ZERO, DVec3::X, &parallel),
            None
        );
    }

    #[test]
    fn ray_meets_plane_ahead_only() {
        let ray = Ray::new(DVec3::new(1.0, 4.0, 2.0), -DVec3::Y);
        assert_eq!(
            ray_plane(&ray, DVec3::ZERO, DVec3::Y),
            Some(DVec3::new(1.0, 0.0, 2.0))
        );
        let away = Ray::new(DVec3::new(1.0, 4.0, 2.0), DVec3::Y);
        assert_eq!(ray_plane(&away, DVec3::ZERO, DVec3::Y), None);
    }
}
