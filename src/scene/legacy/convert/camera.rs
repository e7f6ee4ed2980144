//! The legacy pinhole camera as a scene camera.
//!
//! The legacy unit camera sits at the origin looking along +Z; the ray through pixel
//! (u, v) of a W x H image passes through (x, y, F) with x = -1 + (u + 0.5) 2/W and
//! y = -H/W + (v + 0.5) 2/W, v = 0 the top row, so image "up" is the camera's -Y. After
//! the camera's transform M:
//!
//! ```text
//! position = M (0, 0, 0)      forward = M (0, 0, 1) as a direction
//! up       = M (0, -1, 0) as a direction
//! tan(fov_y / 2) = (H / W) / F
//! look_at  = position + depth * forward / |forward|
//! ```
//!
//! The legacy camera has no target, so `depth` is where the content is: the mean depth
//! along the view direction of the objects' centres that are in view (else of those in
//! front of the camera), so that orbiting an imported scene turns around what it shows.
//! With nothing in front, the target is one step of `forward` ahead.
//!
//! That is exact when M is a rotation, a translation and a uniform scale; a non-uniform
//! scale, a shear or a mirror of the camera bends the legacy rays in ways a pinhole
//! camera cannot, which [`camera_distortion`] detects so the import can warn.
//!
//! Only the last Camera block counts; without one, the legacy unit camera is used.

use glam::{DAffine3, DVec3};

use super::super::syntax::{At, Item, TransformStep};
use super::converter::Converter;
use super::transform::compose;
use crate::scene::{Camera, Scene};

/// Focal length of the unit camera used when a file has no Camera block.
pub const DEFAULT_FOCAL_LENGTH: f64 = 1.0;

impl Converter<'_> {
    /// A Camera block; a later one replaces it, with a warning.
    pub(super) fn camera_block(
        &mut self,
        focal_length: f64,
        transforms: &[Item<TransformStep>],
        at: &At,
    ) {
        if let Some((_, _, previous)) = &self.camera {
            let line = previous.line;
            self.warn(
                at.line,
                format!("this Camera replaces the one at line {line}"),
            );
        }
        let world_from_camera = compose(transforms.iter().map(|t| &t.value));
        self.camera = Some((focal_length, world_from_camera, at.clone()));
    }

    /// The scene camera, with a warning for what a pinhole camera cannot reproduce.
    pub(super) fn camera(&mut self) -> Camera {
        let (width, height) = self.render_size;
        let content: Vec<DVec3> = self.objects.iter().map(|o| o.centre()).collect();
        let Some((focal_length, world_from_camera, at)) = self.camera.clone() else {
            self.errors.warn_file(
                "no Camera block: the legacy unit camera is used (at the origin, looking \
                 along +Z, focal length 1)",
            );
            return scene_camera(
                DEFAULT_FOCAL_LENGTH,
                &DAffine3::IDENTITY,
                (width, height),
                &content,
            );
        };
        if camera_distortion(&world_from_camera) {
            self.warn(
                at.line,
                "the camera's transform scales unevenly, shears or mirrors; the import keeps \
                 its position, view direction and up, so the picture may differ",
            );
        }
        let camera = scene_camera(focal_length, &world_from_camera, (width, height), &content);
        let fragment = Scene {
            camera: camera.clone(),
            ..Scene::empty()
        };
        self.check(&fragment, &at, "this camera cannot be imported");
        camera
    }
}

/// The scene camera for a legacy camera of focal length `focal_length`, placed by
/// `world_from_camera`, rendering `width` x `height` pixels, looking at the `content`
/// (the objects' centres) as the module says.
#[must_use]
pub fn scene_camera(
    focal_length: f64,
    world_from_camera: &DAffine3,
    (width, height): (u32, u32),
    content: &[DVec3],
) -> Camera {
    let position = world_from_camera.transform_point3(DVec3::ZERO);
    let forward = world_from_camera.transform_vector3(DVec3::Z);
    let up = world_from_camera.transform_vector3(DVec3::NEG_Y);
    let half_height = f64::from(height) / f64::from(width) / focal_length;
    // The image plane is 2 units wide at distance F: this is tan of the half-diagonal.
    let tan_half_diagonal = (1.0 / focal_length).hypot(half_height);
    let look_at = match content_depth(position, forward, tan_half_diagonal, content) {
        Some(depth) => position + forward.normalize() * depth,
        None => position + forward,
    };
    Camera {
        position,
        look_at,
        up,
        fov_deg: 2.0 * half_height.atan().to_degrees(),
        width,
        height,
    }
}

/// The mean depth along `forward` of the points within the view cone of half-angle
/// `atan(tan_half_view)`, else of the points in front; `None` when none is in front (or
/// the mean is not a usable distance).
fn content_depth(
    position: DVec3,
    forward: DVec3,
    tan_half_view: f64,
    points: &[DVec3],
) -> Option<f64> {
    let axis = forward.normalize_or_zero();
    let in_front: Vec<(f64, bool)> = points
        .iter()
        .map(|&p| {
            let offset = p - position;
            let depth = offset.dot(axis);
            let off_axis = (offset - depth * axis).length();
            (depth, off_axis <= depth * tan_half_view)
        })
        .filter(|&(depth, _)| depth > 0.0)
        .collect();
    let mean = |depths: Vec<f64>| -> Option<f64> {
        let count = depths.len() as f64;
        let depth = depths.into_iter().sum::<f64>() / count;
        (depth.is_normal() && depth > 0.0).then_some(depth)
    };
    let in_view: Vec<f64> = in_front
        .iter()
        .filter(|(_, seen)| *seen)
        .map(|(depth, _)| *depth)
        .collect();
    if in_view.is_empty() {
        mean(in_front.into_iter().map(|(depth, _)| depth).collect())
    } else {
        mean(in_view)
    }
}

/// Whether the camera's transform is something other than rotation, translation and
/// uniform scale (a non-uniform scale, a shear or a mirror), to a relative 1e-9.
#[must_use]
pub fn camera_distortion(world_from_camera: &DAffine3) -> bool {
    let m = world_from_camera.matrix3;
    let axes = [m.x_axis, m.y_axis, m.z_axis];
    let size = m.x_axis.length();
    let tolerance = 1e-9 * size * size;
    let orthogonal = (0..3).all(|i| {
        (0..3).all(|j| {
            let expected = if i == j { size * size } else { 0.0 };
            (axes[i].dot(axes[j]) - expected).abs() <= tolerance
        })
    });
    !(orthogonal && m.determinant() > 0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_camera_looks_along_z_with_minus_y_up() {
        let camera = scene_camera(1.0, &DAffine3::IDENTITY, (800, 600), &[]);
        assert_eq!(camera.position, DVec3::ZERO);
        assert_eq!(camera.look_at, DVec3::Z);
        assert_eq!(camera.up, DVec3::NEG_Y);
        // tan(fov / 2) = 0.75.
        assert!((camera.fov_deg - 2.0 * 0.75f64.atan().to_degrees()).abs() < 1e-12);
    }

    #[test]
    fn the_target_is_the_mean_depth_of_what_is_in_view() {
        // Scaled by 2 and turned to look along +x from (1, 0, 0).
        let world_from_camera = DAffine3::from_translation(DVec3::X)
            * DAffine3::from_rotation_y(std::f64::consts::FRAC_PI_2)
            * DAffine3::from_scale(DVec3::splat(2.0));
        let in_view = [DVec3::new(5.0, 0.5, 0.0), DVec3::new(9.0, 0.0, -1.0)];
        let behind = DVec3::new(-20.0, 0.0, 0.0);
        let aside = DVec3::new(2.0, 0.0, 30.0);
        let camera = scene_camera(
            1.0,
            &world_from_camera,
            (800, 600),
            &[in_view[0], behind, aside, in_view[1]],
        );
        // Depths 4 and 8 are in view; the one behind and the one far aside do not count.
        assert!((camera.look_at - DVec3::new(7.0, 0.0, 0.0)).length() < 1e-12);
        // Only the one aside is in front: it sets the depth (1) instead.
        let camera = scene_camera(1.0, &world_from_camera, (800, 600), &[behind, aside]);
        assert!((camera.look_at - DVec3::new(2.0, 0.0, 0.0)).length() < 1e-12);
        // Nothing in front: one step of forward (length 2), as the legacy unit camera.
        let camera = scene_camera(1.0, &world_from_camera, (800, 600), &[behind]);
        assert!((camera.look_at - DVec3::new(3.0, 0.0, 0.0)).length() < 1e-12);
    }

    #[test]
    fn uniform_scale_is_not_a_distortion_but_a_mirror_is() {
        let turn = DAffine3::from_rotation_y(0.3) * DAffine3::from_scale(DVec3::splat(2.0));
        assert!(!camera_distortion(&turn));
        assert!(camera_distortion(&DAffine3::from_scale(DVec3::new(
            1.0, 1.0, -1.0
        ))));
        assert!(camera_distortion(&DAffine3::from_scale(DVec3::new(
            1.0, 2.0, 1.0
        ))));
    }
}
