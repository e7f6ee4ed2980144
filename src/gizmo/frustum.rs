//! The scene camera as the viewport draws it from another view: its eye, and its image
//! rectangle at a chosen depth, with the corners found by the tracer's own camera rays
//! so the drawn rectangle is exactly what the camera sees.

use glam::{DVec2, DVec3};

use crate::scene::Camera;
use crate::trace::PinholeCamera;

/// A camera's eye and its image rectangle at some depth.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frustum {
    /// The eye.
    pub eye: DVec3,
    /// The image rectangle's corners: top-left, top-right, bottom-right, bottom-left.
    pub corners: [DVec3; 4],
    /// The tip of the triangle over the top edge that shows which way is up.
    pub up_tip: DVec3,
}

/// The frustum of `camera` with its image rectangle `depth` in front of the eye (along
/// the view direction).
#[must_use]
pub fn frustum(camera: &Camera, depth: f64) -> Frustum {
    let (w, h) = (camera.width.max(1), camera.height.max(1));
    let pinhole = PinholeCamera::new(camera, w, h);
    let forward = (camera.look_at - camera.position).normalize_or_zero();
    let at_depth = |x: f64, y: f64| {
        let ray = pinhole.ray(DVec2::new(x, y));
        ray.origin + ray.dir * (depth / ray.dir.dot(forward))
    };
    let (w, h) = (f64::from(w), f64::from(h));
    let corners = [
        at_depth(0.0, 0.0),
        at_depth(w, 0.0),
        at_depth(w, h),
        at_depth(0.0, h),
    ];
    // A tip above the middle of the top edge, a fifth of the height up.
    let up_tip = at_depth(w * 0.5, -h * 0.2);
    Frustum {
        eye: camera.position,
        corners,
        up_tip,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rectangle_is_what_the_camera_sees_at_that_depth() {
        let camera = Camera {
            position: DVec3::new(1.0, 2.0, 3.0),
            look_at: DVec3::new(0.0, 1.0, -2.0),
            up: DVec3::Y,
            fov_deg: 50.0,
            width: 320,
            height: 200,
        };
        let f = frustum(&camera, 2.0);
        let pinhole = PinholeCamera::new(&camera, 320, 200);
        let forward = (camera.look_at - camera.position).normalize();
        let expected = [(0.0, 0.0), (320.0, 0.0), (320.0, 200.0), (0.0, 200.0)];
        for (corner, (x, y)) in f.corners.iter().zip(expected) {
            assert!(((*corner - camera.position).dot(forward) - 2.0).abs() < 1e-12);
            let back = pinhole.project(*corner).unwrap();
            assert!((back - DVec2::new(x, y)).length() < 1e-9, "{back}");
        }
        // The rectangle's aspect is the image's.
        let width = (f.corners[1] - f.corners[0]).length();
        let height = (f.corners[3] - f.corners[0]).length();
        assert!((width / height - 1.6).abs() < 1e-12);
        assert!(
            (f.up_tip - camera.position).dot(camera.up)
                > (f.corners[0] - camera.position).dot(camera.up)
        );
    }
}
