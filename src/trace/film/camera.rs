//! The pinhole camera: pixel coordinates to primary rays.

use glam::{DVec2, DVec3};

use crate::scene::Camera;
use crate::trace::ray::Ray;

/// A camera ready to generate rays for an image of a given size.
#[derive(Clone, Copy, Debug)]
pub struct PinholeCamera {
    position: DVec3,
    forward: DVec3,
    /// Image-plane vector from the centre to the right edge (at distance 1).
    right_half: DVec3,
    /// Image-plane vector from the centre to the top edge (at distance 1).
    up_half: DVec3,
    width: f64,
    height: f64,
}

impl PinholeCamera {
    /// A camera for a `width` x `height` image. `fov_deg` spans the image height.
    #[must_use]
    pub fn new(camera: &Camera, width: u32, height: u32) -> Self {
        let forward = (camera.look_at - camera.position).normalize();
        let right = forward.cross(camera.up).normalize();
        let up = right.cross(forward);
        let half_height = (camera.fov_deg.to_radians() * 0.5).tan();
        let half_width = half_height * f64::from(width) / f64::from(height);
        Self {
            position: camera.position,
            forward,
            right_half: right * half_width,
            up_half: up * half_height,
            width: f64::from(width),
            height: f64::from(height),
        }
    }

    /// The ray through image point `(x, y)` in pixels, `(0, 0)` the top-left corner;
    /// pixel `(u, v)`'s centre is `(u + 0.5, v + 0.5)`. The direction is unit length, so
    /// `t` is the distance from the eye.
    #[must_use]
    pub fn ray(&self, image_point: DVec2) -> Ray {
        Ray::new(self.position, self.film_direction(image_point).normalize())
    }

    /// The direction through image point `(x, y)` before it is normalised: affine in
    /// the image point, so the rays through a rectangle of the image lie in the pyramid
    /// spanned by its corners' film directions.
    #[must_use]
    #[inline]
    pub fn film_direction(&self, image_point: DVec2) -> DVec3 {
        let ndc_x = 2.0 * image_point.x / self.width - 1.0;
        let ndc_y = 1.0 - 2.0 * image_point.y / self.height;
        self.forward + ndc_x * self.right_half + ndc_y * self.up_half
    }

    /// Where every camera ray starts.
    #[must_use]
    pub fn position(&self) -> DVec3 {
        self.position
    }

    /// Unit view direction (the ray through the image centre).
    #[must_use]
    pub fn forward(&self) -> DVec3 {
        self.forward
    }

    /// Where a world point lands in the image, in pixels; `None` behind the eye.
    #[must_use]
    pub fn project(&self, p_world: DVec3) -> Option<DVec2> {
        let rel = p_world - self.position;
        let depth = rel.dot(self.forward);
        if depth <= 0.0 {
            return None;
        }
        let ndc_x = rel.dot(self.right_half) / (depth * self.right_half.length_squared());
        let ndc_y = rel.dot(self.up_half) / (depth * self.up_half.length_squared());
        Some(DVec2::new(
            (ndc_x + 1.0) * 0.5 * self.width,
            (1.0 - ndc_y) * 0.5 * self.height,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera() -> Camera {
        Camera {
            position: DVec3::new(1.0, 2.0, 3.0),
            look_at: DVec3::new(1.0, 2.0, -7.0),
            up: DVec3::Y,
            fov_deg: 90.0,
            width: 5,
            height: 3,
        }
    }

    #[test]
    fn centre_pixel_of_odd_image_looks_exactly_at_look_at() {
        let cam = PinholeCamera::new(&camera(), 5, 3);
        let ray = cam.ray(DVec2::new(2.5, 1.5));
        assert_eq!(ray.dir, -DVec3::Z);
    }

    #[test]
    fn fov_spans_the_height_and_top_row_looks_up() {
        let cam = PinholeCamera::new(&camera(), 5, 3);
        // Top edge at 45 degrees up for a 90 degree vertical fov.
        let top = cam.ray(DVec2::new(2.5, 0.0)).dir;
        assert!((top - DVec3::new(0.0, 1.0, -1.0).normalize()).length() < 1e-15);
        // Right edge: half-width = 5/3.
        let right = cam.ray(DVec2::new(5.0, 1.5)).dir;
        assert!((right - DVec3::new(5.0 / 3.0, 0.0, -1.0).normalize()).length() < 1e-15);
    }

    #[test]
    fn project_inverts_ray() {
        let cam = PinholeCamera::new(&camera(), 5, 3);
        let point = DVec2::new(0.7, 2.2);
        let p = cam.ray(point).at(4.0);
        let back = cam.project(p).unwrap();
        assert!((back - point).length() < 1e-12);
    }
}
