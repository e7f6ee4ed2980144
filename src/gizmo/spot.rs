//! Aiming lights: the spotlight's tip handle (direction) and rim handle (half-angle), and
//! the directional light's aim handle.
//!
//! The cone is drawn with a constant slant length `L`: the tip handle sits at
//! `position + L axis`, rim points at `position + L (cos a axis + sin a radial)`.

use glam::DVec3;

use super::{closest_on_line_to_ray, ray_plane};
use crate::trace::Ray;

/// Smallest half-angle a rim drag can set, degrees (the contract needs > 0).
pub const MIN_ANGLE_DEG: f64 = 0.1;
/// Largest half-angle a rim drag can set, degrees: all the contract takes (beyond 90 the
/// light reaches behind itself; at 180 it lights every direction).
pub const MAX_ANGLE_DEG: f64 = crate::scene::MAX_SPOT_ANGLE_DEG;

/// Where the tip handle is.
#[must_use]
pub fn tip_point(position: DVec3, direction: DVec3, length: f64) -> DVec3 {
    position + direction.normalize() * length
}

/// A unit vector perpendicular to `axis`, stable as the axis turns a little.
#[must_use]
pub fn perpendicular(axis: DVec3) -> DVec3 {
    let axis = axis.normalize();
    let helper = if axis.y.abs() < 0.9 {
        DVec3::Y
    } else {
        DVec3::X
    };
    axis.cross(helper).normalize()
}

/// The radial direction of the rim handle: on the cone's silhouette as seen along
/// `view_dir`, so the plane a rim drag works in faces the camera.
#[must_use]
pub fn rim_radial(direction: DVec3, view_dir: DVec3) -> DVec3 {
    let radial = direction.cross(view_dir);
    if radial.length_squared() > 1e-12 * direction.length_squared() * view_dir.length_squared() {
        radial.normalize()
    } else {
        perpendicular(direction)
    }
}

/// The rim handle's position.
#[must_use]
pub fn rim_handle(
    position: DVec3,
    direction: DVec3,
    radial: DVec3,
    angle_deg: f64,
    length: f64,
) -> DVec3 {
    let (sin_a, cos_a) = angle_deg.to_radians().sin_cos();
    position + length * (direction.normalize() * cos_a + radial * sin_a)
}

/// Points of the rim circle (`count` of them) for drawing, and the rim handle is the first.
#[must_use]
pub fn rim_points(
    position: DVec3,
    direction: DVec3,
    angle_deg: f64,
    length: f64,
    count: usize,
) -> Vec<DVec3> {
    let axis = direction.normalize();
    let u = perpendicular(axis);
    let v = axis.cross(u);
    let (sin_a, cos_a) = angle_deg.to_radians().sin_cos();
    (0..count)
        .map(|i| {
            let phi = i as f64 * std::f64::consts::TAU / count as f64;
            let radial = u * phi.cos() + v * phi.sin();
            position + length * (axis * cos_a + radial * sin_a)
        })
        .collect()
}

/// The direction a tip drag aims at, from `position`: towards the point under the
/// cursor on the plane through `start_tip` (the tip where the drag started) that faces
/// `eye`. That point is under the cursor at any distance, so the tip (drawn there while
/// the drag lasts) follows the cursor everywhere, also off the sphere it is drawn on
/// between drags. Where that plane is edge-on or behind the eye, the tip stays on the
/// sphere of radius `|start_tip - position|` around the light: the nearer crossing, or
/// where the ray misses it, the sphere's point nearest the ray.
#[must_use]
pub fn aim_from_tip_drag(
    position: DVec3,
    start_tip: DVec3,
    eye: DVec3,
    ray: &Ray,
) -> Option<DVec3> {
    let dir = ray.dir.normalize();
    let facing = (eye - start_tip).normalize_or_zero();
    let across = dir.dot(facing);
    if across < -1e-6 {
        let t = (start_tip - ray.origin).dot(facing) / across;
        if t > 0.0 {
            let aim = ray.origin + dir * t - position;
            return (aim.length_squared() > 0.0).then(|| aim.normalize());
        }
    }
    aim_on_sphere(position, (start_tip - position).length(), ray)
}

/// The tip on the sphere of radius `length` around `position` under the cursor ray (the
/// nearer crossing; where the ray misses the sphere, the point nearest the ray).
fn aim_on_sphere(position: DVec3, length: f64, ray: &Ray) -> Option<DVec3> {
    let dir = ray.dir.normalize();
    let to_centre = position - ray.origin;
    let along = to_centre.dot(dir);
    let closest = ray.origin + dir * along;
    let miss_distance_sq = (position - closest).length_squared();
    let on_sphere = if miss_distance_sq <= length * length {
        let half_chord = (length * length - miss_distance_sq).sqrt();
        let t = if along - half_chord > 0.0 {
            along - half_chord
        } else {
            along + half_chord
        };
        if t <= 0.0 {
            return None;
        }
        ray.origin + dir * t
    } else {
        closest
    };
    let aim = on_sphere - position;
    (aim.length_squared() > 0.0).then(|| aim.normalize())
}

/// The half-angle a rim drag sets: the rim follows the cursor in the plane through the
/// light that holds the axis and the rim handle's radial direction. Clamped to
/// [`MIN_ANGLE_DEG`, `MAX_ANGLE_DEG`]; a cursor behind the light gives an angle over 90.
#[must_use]
pub fn angle_from_rim_drag(
    position: DVec3,
    direction: DVec3,
    radial: DVec3,
    ray: &Ray,
) -> Option<f64> {
    let axis = direction.normalize();
    let normal = axis.cross(radial);
    let q = match ray_plane(ray, position, normal) {
        Some(q) => q,
        // Looking along the plane: use the ray's closest point to the radial line.
        None => position + radial * closest_on_line_to_ray(position, radial, ray)?,
    };
    let offset = q - position;
    let along = offset.dot(axis);
    let across = (offset - axis * along).length();
    let angle = across.atan2(along).to_degrees();
    Some(angle.clamp(MIN_ANGLE_DEG, MAX_ANGLE_DEG))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Camera;
    use crate::trace::PinholeCamera;

    fn camera() -> PinholeCamera {
        let camera = Camera {
            position: DVec3::new(0.0, 3.0, 10.0),
            look_at: DVec3::new(0.0, 2.0, 0.0),
            up: DVec3::Y,
            fov_deg: 45.0,
            width: 640,
            height: 480,
        };
        PinholeCamera::new(&camera, 640, 480)
    }

    #[test]
    fn tip_drag_aims_the_light_through_the_point_under_the_cursor_near_and_far() {
        let cam = camera();
        let eye = DVec3::new(0.0, 3.0, 10.0);
        let light = DVec3::new(0.0, 4.0, 0.0);
        let start_tip = light + DVec3::new(0.0, -1.5, 0.0);
        // The point under the cursor on the plane through the start tip facing the eye
        // lies on the new axis: near the start tip and far from it (off the sphere of
        // radius 1.5, where the old drag stopped following the cursor).
        let facing = (eye - start_tip).normalize();
        let (u, v) = facing.any_orthonormal_pair();
        for offset in [0.3 * u, 2.0 * u - 1.5 * v, 4.0 * v] {
            let under = start_tip + offset;
            let cursor = cam.project(under).unwrap();
            let aim = aim_from_tip_drag(light, start_tip, eye, &cam.ray(cursor)).unwrap();
            let wanted = (under - light).normalize();
            assert!((aim - wanted).length() < 1e-9, "{aim} vs {wanted}");
        }
    }

    #[test]
    fn an_edge_on_plane_falls_back_to_the_sphere_and_its_nearest_point() {
        let light = DVec3::ZERO;
        let start_tip = DVec3::Y;
        // The eye looks along the plane (the ray runs parallel to it).
        let eye = DVec3::new(5.0, 1.0, 0.0);
        let ray = Ray::new(DVec3::new(5.0, 3.0, 0.0), DVec3::new(-1.0, 0.0, 0.0));
        let aim = aim_from_tip_drag(light, start_tip, eye, &ray).unwrap();
        assert!((aim - DVec3::Y).length() < 1e-12);
    }

    #[test]
    fn rim_drag_sets_the_angle_of_the_point_under_the_cursor() {
        let cam = camera();
        let light = DVec3::new(0.0, 4.0, 0.0);
        let direction = DVec3::new(0.0, -1.0, 0.0);
        let view_dir = light - DVec3::new(0.0, 3.0, 10.0);
        let radial = rim_radial(direction, view_dir);
        for wanted in [5.0, 30.0, 60.0] {
            let rim = rim_handle(light, direction, radial, wanted, 2.0);
            let ray = cam.ray(cam.project(rim).unwrap());
            let angle = angle_from_rim_drag(light, direction, radial, &ray).unwrap();
            assert!((angle - wanted).abs() < 1e-7, "{angle} vs {wanted}");
        }
    }

    #[test]
    fn rim_drag_reaches_behind_the_light_up_to_the_contracts_widest_cone() {
        let light = DVec3::ZERO;
        let direction = -DVec3::Y;
        let radial = DVec3::X;
        // A point above the light and to the side (behind it): 135 degrees, not a cap at 90.
        let behind = Ray::new(DVec3::new(1.0, 1.0, 5.0), -DVec3::Z);
        let angle = angle_from_rim_drag(light, direction, radial, &behind).unwrap();
        assert!((angle - 135.0).abs() < 1e-9, "{angle}");
        // Straight above the light: the widest cone the contract takes.
        let above = Ray::new(DVec3::new(0.0, 2.0, 5.0), -DVec3::Z);
        assert_eq!(
            angle_from_rim_drag(light, direction, radial, &above),
            Some(crate::scene::MAX_SPOT_ANGLE_DEG)
        );
        // A point on the axis: the narrowest.
        let on_axis = Ray::new(DVec3::new(0.0, -3.0, 5.0), -DVec3::Z);
        assert_eq!(
            angle_from_rim_drag(light, direction, radial, &on_axis),
            Some(MIN_ANGLE_DEG)
        );
    }
}
