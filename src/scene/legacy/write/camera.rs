//! The scene camera as the course's `Camera PinholeCamera F`: the exact inverse of the
//! importer's conversion (`convert/camera.rs`).
//!
//! The course's unit camera sits at the origin looking along +Z with image "up" its -Y,
//! and its image plane is 2 units wide at distance F. raylab's camera renders with
//! `forward = normalise(look_at - position)`, `right = normalise(forward x up)` and the
//! true up `right x forward`. So the course camera's transform is the rotation whose
//! columns are `right`, `-(true up)` and `forward` (right-handed: right = (-up) x
//! forward), written as `Rotate X`, `Rotate Y`, `Rotate Z` (decomposed as the importer
//! decomposes objects), then `Translate position`; and `F = (H / W) / tan(fov / 2)`.
//!
//! Importing that gives back the same position, a view direction and up equal to
//! float noise (the Euler angles go through sine and cosine), and the same field of
//! view to float noise; the importer places `look_at` where the scene's content is, on
//! the same line of sight, so `look_at` itself (a point raylab only orbits about) comes
//! back elsewhere on that line. Every camera the scene rules accept has this form; none
//! is refused.

use glam::{DAffine3, DMat3};

use super::super::convert::as_trs;
use super::numbers::number;
use super::steps::{Step, trs_steps};
use crate::scene::{Camera, Trs};

/// The focal length of the course camera with `camera`'s field of view and size.
#[must_use]
pub fn focal_length(camera: &Camera) -> f64 {
    let aspect = f64::from(camera.height) / f64::from(camera.width);
    aspect / (camera.fov_deg.to_radians() * 0.5).tan()
}

/// The course camera's transform: its rotation and translation, as steps.
#[must_use]
pub fn camera_steps(camera: &Camera) -> Vec<Step> {
    let forward = (camera.look_at - camera.position).normalize();
    let right = forward.cross(camera.up).normalize();
    let up = right.cross(forward);
    let world_from_camera = DAffine3 {
        matrix3: DMat3::from_cols(right, -up, forward),
        translation: camera.position,
    };
    // An orthonormal matrix always decomposes; the fallback is never taken, but keeps
    // the camera's place if it were.
    let trs = as_trs(&world_from_camera).unwrap_or(Trs {
        translate: camera.position,
        ..Trs::default()
    });
    // The scale is 1 to float noise: the course camera is a rotation and a translation;
    // the position goes out as it is (the decomposition may round it to a short decimal).
    trs_steps(&Trs {
        scale: glam::DVec3::ONE,
        translate: camera.position,
        ..trs
    })
}

/// The Camera block.
#[must_use]
pub fn camera_block(camera: &Camera) -> String {
    let mut text = format!("Camera PinholeCamera {}\n", number(focal_length(camera)));
    for step in camera_steps(camera) {
        text.push_str(&format!("  {step}\n"));
    }
    text.push_str("End\n");
    text
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;

    #[test]
    fn the_unit_camera_has_no_steps_and_focal_length_one() {
        // Looking along +z with -y up: the course's unit camera at 90 degrees across.
        let camera = Camera {
            position: DVec3::ZERO,
            look_at: DVec3::Z,
            up: DVec3::NEG_Y,
            fov_deg: 2.0 * 0.75f64.atan().to_degrees(),
            width: 800,
            height: 600,
        };
        assert!(camera_steps(&camera).is_empty());
        assert!((focal_length(&camera) - 1.0).abs() < 1e-15);
    }

    #[test]
    fn a_camera_looking_down_minus_z_turns_half_way_about_x() {
        let camera = Camera {
            position: DVec3::new(0.0, 1.0, 5.0),
            look_at: DVec3::new(0.0, 1.0, 0.0),
            up: DVec3::Y,
            fov_deg: 45.0,
            width: 80,
            height: 60,
        };
        let text: Vec<String> = camera_steps(&camera)
            .iter()
            .map(ToString::to_string)
            .collect();
        assert_eq!(text, ["Rotate X 180", "Translate 0 1 5"]);
    }
}
