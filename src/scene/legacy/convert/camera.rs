//! The legacy pinhole camera as a scene camera.
//!
//! The legacy unit camera sits at the origin looking along +Z; the ray through pixel
//! (u, v) of a W x H image passes through (x, y, F) with x = -1 + (u + 0.5) 2/W and
//! y = -H/W + (v + 0.5) 2/W, v = 0 the top row, so image "up" is the camera's -Y. After
//! the camera's transform M:
//!
//! ```text
//! position = M (0, 0, 0)      forward = M (0, 0, 1) as a direction
//! look_at  = position + forward
//! up       = M (0, -1, 0) as a direction
//! tan(fov_y / 2) = (H / W) / F
//! ```
//!
//! That is exact when M is a rotation, a translation and a uniform scale; a non-uniform
//! scale, a shear or a mirror of the camera bends the legacy rays in ways a pinhole
//! camera cannot, which [`camera_distortion`] detects so the import can warn.
//!
//! Only the last Camera block counts; without one, the legacy unit camera is used.

use glam::{DAffine3, DVec3};

use super::super::syntax::{At, Item, TransformStep};
use super::Converter;
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
        let Some((focal_length, world_from_camera, at)) = self.camera.clone() else {
            self.warnings.push(
                "no Camera block: the legacy unit camera is used (at the origin, looking \
                 along +Z, focal length 1)"
                    .to_owned(),
            );
            return scene_camera(DEFAULT_FOCAL_LENGTH, &DAffine3::IDENTITY, width, height);
        };
        if camera_distortion(&world_from_camera) {
            self.warn(
                at.line,
                "the camera's transform scales unevenly, shears or mirrors; the import keeps \
                 its position, view direction and up, so the picture may differ",
            );
        }
        let camera = scene_camera(focal_length, &world_from_camera, width, height);
        let fragment = Scene {
            camera: camera.clone(),
            ..Scene::empty()
        };
        self.check(&fragment, &at, "this camera cannot be imported");
        camera
    }
}

/// The scene camera for a legacy camera of focal length `focal_length`, placed by
/// `world_from_camera`, rendering `width` x `height` pixels.
#[must_use]
pub fn scene_camera(
    focal_length: f64,
    world_from_camera: &DAffine3,
    width: u32,
    height: u32,
) -> Camera {
    let position = world_from_camera.transform_point3(DVec3::ZERO);
    let forward = world_from_camera.transform_vector3(DVec3::Z);
    let up = world_from_camera.transform_vector3(DVec3::NEG_Y);
    let half_height = f64::from(height) / f64::from(width) / focal_length;
    Camera {
        position,
        look_at: position + forward,
        up,
        fov_deg: 2.0 * half_height.atan().to_degrees(),
        width,
        height,
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
        let camera = scene_camera(1.0, &DAffine3::IDENTITY, 800, 600);
        assert_eq!(camera.position, DVec3::ZERO);
        assert_eq!(camera.look_at, DVec3::Z);
        assert_eq!(camera.up, DVec3::NEG_Y);
        // tan(fov / 2) = 0.75.
        assert!((camera.fov_deg - 2.0 * 0.75f64.atan().to_degrees()).abs() < 1e-12);
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
