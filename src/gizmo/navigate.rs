//! Camera navigation in the viewport: orbit around the target, pan, zoom, and frame a
//! selection. Each returns a new camera; the editor makes a whole gesture one undo step.

use glam::{DMat3, DVec3};

use crate::scene::Camera;

/// Degrees of orbit per pixel of drag.
pub const ORBIT_DEG_PER_PX: f64 = 0.4;
/// Distance factor per wheel step (zooming in).
pub const ZOOM_PER_STEP: f64 = 0.9;

/// Orbits the camera around `look_at`: `dx` pixels turn about the up vector, `dy` pixels
/// tilt, never past straight up or down.
#[must_use]
pub fn orbit(camera: &Camera, dx_px: f64, dy_px: f64) -> Camera {
    let up = camera.up.normalize();
    let offset = camera.position - camera.look_at;
    let yaw = DMat3::from_axis_angle(up, (-dx_px * ORBIT_DEG_PER_PX).to_radians());
    let offset = yaw * offset;
    let right = up.cross(offset).normalize_or_zero();
    // Tilt, keeping the view direction at least 1 degree away from the up vector.
    let current = offset
        .normalize()
        .dot(up)
        .clamp(-1.0, 1.0)
        .acos()
        .to_degrees();
    let wanted = (current - dy_px * ORBIT_DEG_PER_PX).clamp(1.0, 179.0);
    let pitch = DMat3::from_axis_angle(right, (wanted - current).to_radians());
    let offset = if right == DVec3::ZERO {
        offset
    } else {
        pitch * offset
    };
    Camera {
        position: camera.look_at + offset,
        ..camera.clone()
    }
}

/// Pans: moves eye and target together so the scene under the cursor follows a drag of
/// `dx`, `dy` pixels in a viewport `height_px` tall (exact at the target's distance).
#[must_use]
pub fn pan(camera: &Camera, dx_px: f64, dy_px: f64, height_px: f64) -> Camera {
    let forward = (camera.look_at - camera.position).normalize();
    let right = forward.cross(camera.up).normalize();
    let up = right.cross(forward);
    let distance = (camera.look_at - camera.position).length();
    let units_per_px = 2.0 * distance * (camera.fov_deg.to_radians() * 0.5).tan() / height_px;
    let shift = (-dx_px * right + dy_px * up) * units_per_px;
    Camera {
        position: camera.position + shift,
        look_at: camera.look_at + shift,
        ..camera.clone()
    }
}

/// Zooms: `steps` wheel steps towards the target (negative steps away).
#[must_use]
pub fn zoom(camera: &Camera, steps: f64) -> Camera {
    let offset = camera.position - camera.look_at;
    let factor = ZOOM_PER_STEP.powf(steps);
    let offset = offset * factor;
    // Never onto the target: the camera needs a view direction.
    let offset = if offset.length() < 1e-9 {
        offset.normalize() * 1e-9
    } else {
        offset
    };
    Camera {
        position: camera.look_at + offset,
        ..camera.clone()
    }
}

/// Frames a sphere (`centre`, `radius`): looks at its centre from the same direction, at
/// the distance where it fills the narrower field of view with a small margin.
#[must_use]
pub fn frame(camera: &Camera, centre: DVec3, radius: f64) -> Camera {
    let direction = (camera.position - camera.look_at).normalize();
    let half_fov_y = (camera.fov_deg * 0.5).to_radians();
    let aspect = f64::from(camera.width) / f64::from(camera.height);
    let half_fov_x = (half_fov_y.tan() * aspect).atan();
    let half_fov = half_fov_y.min(half_fov_x);
    let distance = radius.max(1e-6) / half_fov.sin() * 1.1;
    Camera {
        position: centre + direction * distance,
        look_at: centre,
        ..camera.clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::PinholeCamera;
    use glam::DVec2;

    fn camera() -> Camera {
        Camera {
            position: DVec3::new(0.0, 2.0, 8.0),
            look_at: DVec3::new(0.0, 1.0, 0.0),
            up: DVec3::Y,
            fov_deg: 40.0,
            width: 400,
            height: 300,
        }
    }

    #[test]
    fn orbit_keeps_distance_and_target_and_never_flips() {
        let c = camera();
        let distance = (c.position - c.look_at).length();
        let turned = orbit(&c, 225.0, 0.0);
        assert!(((turned.position - turned.look_at).length() - distance).abs() < 1e-9);
        assert_eq!(turned.look_at, c.look_at);
        // 225 px * 0.4 = 90 degrees about +y: from +z to -x... direction check.
        let offset = (turned.position - turned.look_at).normalize();
        assert!(offset.x < -0.9, "{offset}");
        let over_the_top = orbit(&c, 0.0, 10_000.0);
        let angle = (over_the_top.position - c.look_at)
            .normalize()
            .dot(DVec3::Y)
            .acos()
            .to_degrees();
        assert!(
            (angle - 1.0).abs() < 1e-6 || (angle - 179.0).abs() < 1e-6,
            "{angle}"
        );
    }

    #[test]
    fn pan_moves_the_target_point_with_the_cursor() {
        let c = camera();
        let before = PinholeCamera::new(&c, 400, 300);
        let panned = pan(&c, 40.0, -25.0, 300.0);
        let after = PinholeCamera::new(&panned, 400, 300);
        // The old target is now 40 px right and 25 px up of the image centre.
        let moved = after.project(c.look_at).unwrap() - before.project(c.look_at).unwrap();
        assert!((moved - DVec2::new(40.0, -25.0)).length() < 1e-6, "{moved}");
    }

    #[test]
    fn zoom_scales_the_distance() {
        let c = camera();
        let d = (c.position - c.look_at).length();
        let closer = zoom(&c, 2.0);
        assert!(((closer.position - closer.look_at).length() - d * 0.81).abs() < 1e-9);
        assert!(zoom(&c, 1000.0).position != c.look_at);
    }

    #[test]
    fn frame_fits_the_sphere_in_view() {
        let c = camera();
        let framed = frame(&c, DVec3::new(5.0, 0.0, 0.0), 2.0);
        assert_eq!(framed.look_at, DVec3::new(5.0, 0.0, 0.0));
        let cam = PinholeCamera::new(&framed, 400, 300);
        // The sphere's top and bottom points project inside the image.
        for p in [DVec3::new(5.0, 2.0, 0.0), DVec3::new(5.0, -2.0, 0.0)] {
            let q = cam.project(p).unwrap();
            assert!(q.y > 0.0 && q.y < 300.0, "{q}");
        }
    }
}
