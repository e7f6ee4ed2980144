//! Camera navigation in the viewport: orbit around the target, pan, zoom, and frame a
//! selection. Each returns a new camera; the editor makes a whole gesture one undo step.

mod clearance;

use glam::{DMat3, DVec3};

use crate::scene::{Camera, Scene};
use clearance::Obstacles;

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
/// the distance where it fills the narrower field of view with a small margin. It knows
/// nothing of other objects; [`frame_in_scene`] keeps clear of them.
#[must_use]
pub fn frame(camera: &Camera, centre: DVec3, radius: f64) -> Camera {
    let direction = (camera.position - camera.look_at).normalize();
    framed_from(camera, centre, direction, framing_distance(camera, radius))
}

/// Frames a sphere as [`frame`] does, but never leaves the eye inside an object or where
/// a plane hides the centre (under a floor seen from above). When the usual place is not
/// clear, the same distance is tried from directions tilted up, then down, then from
/// the side and behind; then closer. When nothing is clear the camera is left as it is.
#[must_use]
pub fn frame_in_scene(scene: &Scene, centre: DVec3, radius: f64) -> Camera {
    let camera = &scene.camera;
    let obstacles = Obstacles::new(&scene.objects);
    let distance = framing_distance(camera, radius);
    let directions = directions_to_try(camera);
    // Closer and closer, for a selection in a room whose walls are nearer than that.
    for scale in [1.0, 0.7, 0.5, 0.35, 0.25, 0.15, 0.1] {
        for &direction in &directions {
            let eye = centre + direction * (distance * scale);
            if obstacles.is_clear(centre, eye, camera.position) {
                return framed_from(camera, centre, direction, distance * scale);
            }
        }
    }
    camera.clone()
}

/// The distance at which a sphere of `radius` fills the narrower field of view, with a
/// 10% margin.
fn framing_distance(camera: &Camera, radius: f64) -> f64 {
    let half_fov_y = (camera.fov_deg * 0.5).to_radians();
    let aspect = f64::from(camera.width) / f64::from(camera.height);
    let half_fov_x = (half_fov_y.tan() * aspect).atan();
    let half_fov = half_fov_y.min(half_fov_x);
    radius.max(1e-6) / half_fov.sin() * 1.1
}

/// The camera looking at `centre` from `distance` along the unit `direction`.
fn framed_from(camera: &Camera, centre: DVec3, direction: DVec3, distance: f64) -> Camera {
    Camera {
        position: centre + direction * distance,
        look_at: centre,
        ..camera.clone()
    }
}

/// Unit directions from the target to the eye, in the order [`frame_in_scene`] tries
/// them: the camera's own, then tilted towards up in 15-degree steps (to 80 degrees of
/// elevation), then down, then the same from the left, the right and behind.
fn directions_to_try(camera: &Camera) -> Vec<DVec3> {
    let own = (camera.position - camera.look_at).normalize();
    let up = camera.up.normalize();
    let elevation = own.dot(up).clamp(-1.0, 1.0).asin().to_degrees();
    let level = (own - up * own.dot(up)).normalize_or(up.any_orthonormal_vector());
    let raised = (1..)
        .map(|step| elevation + 15.0 * f64::from(step))
        .take_while(|e| *e <= 80.0);
    let lowered = (1..)
        .map(|step| elevation - 15.0 * f64::from(step))
        .take_while(|e| *e >= -80.0);
    let elevations: Vec<f64> = std::iter::once(elevation.clamp(-80.0, 80.0))
        .chain(raised)
        .chain(lowered)
        .collect();
    let mut directions = vec![own];
    for turn_deg in [0.0, 90.0, -90.0, 180.0] {
        let heading = DMat3::from_axis_angle(up, f64::to_radians(turn_deg)) * level;
        for &elevation_deg in &elevations {
            let (sin_e, cos_e) = elevation_deg.to_radians().sin_cos();
            directions.push(heading * cos_e + up * sin_e);
        }
    }
    directions
}

#[cfg(test)]
mod tests {
    use super::clearance::test_objects::{floor, placed, plane};
    use super::*;
    use crate::scene::{Object, Shape};
    use crate::trace::PinholeCamera;
    use glam::DVec2;

    fn camera() -> Camera {
        crate::gizmo::test_camera(DVec3::new(0.0, 2.0, 8.0))
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

    fn scene_with(camera: Camera, objects: Vec<Object>) -> Scene {
        Scene {
            camera,
            objects,
            ..Scene::empty()
        }
    }

    fn looking(position: DVec3, look_at: DVec3) -> Camera {
        Camera {
            position,
            look_at,
            ..camera()
        }
    }

    #[test]
    fn framing_never_goes_under_the_floor() {
        // Looking up at a ball on the floor from low down: plain framing would put the
        // eye under the floor, which hides the ball.
        let camera = looking(DVec3::new(0.0, 0.5, 8.0), DVec3::new(0.0, 4.0, 0.0));
        let ball = placed(Shape::Sphere, DVec3::Y, DVec3::ZERO, DVec3::ONE);
        let scene = scene_with(camera.clone(), vec![floor(), ball]);
        let (centre, radius) = (DVec3::Y, 1.8);
        assert!(frame(&camera, centre, radius).position.y < 0.0);
        let framed = frame_in_scene(&scene, centre, radius);
        assert!(framed.position.y > 0.0, "{}", framed.position);
        assert_eq!(framed.look_at, centre);
        let distance = (framed.position - centre).length();
        assert!((distance - framing_distance(&camera, radius)).abs() < 1e-9);
    }

    #[test]
    fn a_floor_is_framed_from_above_when_it_was_seen_from_above() {
        // The eye is above the floor but looks upwards, so the plain direction goes under.
        let camera = looking(DVec3::new(0.0, 2.0, 8.0), DVec3::new(0.0, 4.0, 0.0));
        let scene = scene_with(camera.clone(), vec![floor()]);
        assert!(frame(&camera, DVec3::ZERO, 14.2).position.y < 0.0);
        let framed = frame_in_scene(&scene, DVec3::ZERO, 14.2);
        assert!(framed.position.y > 0.0, "{}", framed.position);
    }

    #[test]
    fn framing_never_ends_inside_an_object() {
        let camera = camera();
        let centre = DVec3::new(1.0, 0.0, 0.0);
        let plain = frame(&camera, centre, 1.0).position;
        // A pillar exactly where plain framing puts the eye.
        let pillar = placed(
            Shape::Cylinder,
            plain,
            DVec3::new(90.0, 0.0, 0.0),
            DVec3::new(0.5, 0.5, 3.0),
        );
        let scene = scene_with(camera.clone(), vec![pillar.clone()]);
        let framed = frame_in_scene(&scene, centre, 1.0);
        let eye_in_pillar = pillar
            .transform
            .world_from_object()
            .inverse()
            .transform_point3(framed.position);
        assert!(clearance::contains(
            &Shape::Cylinder,
            pillar
                .transform
                .world_from_object()
                .inverse()
                .transform_point3(plain)
        ));
        assert!(
            !clearance::contains(&Shape::Cylinder, eye_in_pillar),
            "{}",
            framed.position
        );
        let distance = (framed.position - centre).length();
        assert!((distance - framing_distance(&camera, 1.0)).abs() < 1e-9);
    }

    #[test]
    fn in_a_small_room_the_eye_comes_closer_and_stays_inside() {
        let h = 2.0;
        let walls = vec![
            plane(DVec3::new(0.0, -h, 0.0), DVec3::new(-90.0, 0.0, 0.0), h),
            plane(DVec3::new(0.0, h, 0.0), DVec3::new(90.0, 0.0, 0.0), h),
            plane(DVec3::new(-h, 0.0, 0.0), DVec3::new(0.0, 90.0, 0.0), h),
            plane(DVec3::new(h, 0.0, 0.0), DVec3::new(0.0, -90.0, 0.0), h),
            plane(DVec3::new(0.0, 0.0, -h), DVec3::ZERO, h),
            plane(DVec3::new(0.0, 0.0, h), DVec3::ZERO, h),
        ];
        let camera = looking(DVec3::new(0.5, 0.5, 1.5), DVec3::ZERO);
        let scene = scene_with(camera.clone(), walls);
        let framed = frame_in_scene(&scene, DVec3::ZERO, 1.0);
        assert!(
            framed.position.abs().max_element() < h,
            "{}",
            framed.position
        );
        assert!(framed.position.length() < framing_distance(&camera, 1.0));
        assert_eq!(framed.look_at, DVec3::ZERO);
    }

    #[test]
    fn with_nowhere_clear_the_camera_stays() {
        // The target is deep inside a huge ball: every eye near it is inside too.
        let camera = camera();
        let ball = placed(
            Shape::Sphere,
            DVec3::ZERO,
            DVec3::ZERO,
            DVec3::splat(1000.0),
        );
        let scene = scene_with(camera.clone(), vec![ball]);
        assert_eq!(frame_in_scene(&scene, DVec3::ZERO, 1.0), camera);
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
