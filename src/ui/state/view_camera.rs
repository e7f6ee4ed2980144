//! The view camera: the editor's own eye on the scene, apart from the scene's camera.
//! Orbit, pan, zoom and F move it; it is never part of the scene, so looking around never
//! marks the file modified or changes what Export writes. "Camera view" looks through
//! the scene camera instead: its exact framing and resolution, so the final frame equals
//! `raylab render`.

use std::borrow::Cow;

use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::scene::{Camera, Scene};

/// The longest side the viewport renders at when it shows the view camera.
pub const MAX_VIEW_LONG_SIDE: u32 = 1280;

/// The view camera's pose and field of view, and whether the viewport looks through the
/// scene camera instead.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ViewCamera {
    /// Eye position in world space.
    pub position: DVec3,
    /// The point the view turns about and looks at.
    pub look_at: DVec3,
    /// Which way is up.
    pub up: DVec3,
    /// Vertical field of view in degrees.
    pub fov_deg: f64,
    /// "Camera view": the viewport shows the scene camera, not this pose.
    pub through_scene_camera: bool,
}

impl ViewCamera {
    /// Looking through `camera`, with the view's own pose starting at it.
    #[must_use]
    pub fn through(camera: &Camera) -> Self {
        Self {
            through_scene_camera: true,
            ..Self::free(camera)
        }
    }

    /// A free view at the pose of `camera`.
    #[must_use]
    pub fn free(camera: &Camera) -> Self {
        Self {
            position: camera.position,
            look_at: camera.look_at,
            up: camera.up,
            fov_deg: camera.fov_deg,
            through_scene_camera: false,
        }
    }

    /// The view's own pose as a camera rendering `width` x `height`.
    #[must_use]
    pub fn pose(&self, width: u32, height: u32) -> Camera {
        Camera {
            position: self.position,
            look_at: self.look_at,
            up: self.up,
            fov_deg: self.fov_deg,
            width,
            height,
        }
    }

    /// The camera the viewport shows: the scene's own in camera view, else this pose at
    /// `free_size` (the viewport's size in pixels).
    #[must_use]
    pub fn shown(&self, scene_camera: &Camera, free_size: (u32, u32)) -> Camera {
        if self.through_scene_camera {
            scene_camera.clone()
        } else {
            self.pose(free_size.0, free_size.1)
        }
    }

    /// The scene camera set from this view: its pose and field of view, the scene
    /// camera's output size.
    #[must_use]
    pub fn as_scene_camera(&self, scene_camera: &Camera) -> Camera {
        self.pose(scene_camera.width, scene_camera.height)
    }

    /// Whether the pose can make rays: finite, the eye off its target.
    #[must_use]
    pub fn is_usable(&self) -> bool {
        self.position.is_finite()
            && self.look_at.is_finite()
            && self.up.is_finite()
            && self.fov_deg.is_finite()
            && (self.look_at - self.position).length_squared() > 0.0
    }
}

/// The scene as the viewport renders it: the scene itself in camera view, else a copy
/// whose camera is the view camera at `free_size`.
#[must_use]
pub fn shown_scene<'s>(
    scene: &'s Scene,
    view: &ViewCamera,
    free_size: (u32, u32),
) -> Cow<'s, Scene> {
    if view.through_scene_camera {
        Cow::Borrowed(scene)
    } else {
        let mut shown = scene.clone();
        shown.camera = view.shown(&scene.camera, free_size);
        Cow::Owned(shown)
    }
}

/// The pixel size to render a free view shown `width_points` x `height_points` on a
/// screen of `pixels_per_point`: the screen's pixels, the long side at most
/// [`MAX_VIEW_LONG_SIDE`], each side at least 1.
#[must_use]
pub fn free_render_size(
    width_points: f32,
    height_points: f32,
    pixels_per_point: f32,
) -> (u32, u32) {
    let (w, h) = (
        f64::from(width_points * pixels_per_point).max(1.0),
        f64::from(height_points * pixels_per_point).max(1.0),
    );
    let scale = (f64::from(MAX_VIEW_LONG_SIDE) / w.max(h)).min(1.0);
    let side = |s: f64| ((s * scale).round() as u32).max(1);
    (side(w), side(h))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn camera_view_shows_the_scene_camera_and_a_free_view_its_own_pose() {
        let scene = crate::ui::document::files::default_scene();
        let mut view = ViewCamera::through(&scene.camera);
        assert_eq!(view.shown(&scene.camera, (300, 200)), scene.camera);
        assert!(matches!(
            shown_scene(&scene, &view, (300, 200)),
            Cow::Borrowed(_)
        ));
        view.through_scene_camera = false;
        view.position += DVec3::X;
        let shown = shown_scene(&scene, &view, (300, 200));
        assert_eq!((shown.camera.width, shown.camera.height), (300, 200));
        assert_eq!(shown.camera.position, scene.camera.position + DVec3::X);
        assert_eq!(shown.objects, scene.objects, "only the camera differs");
        let set = view.as_scene_camera(&scene.camera);
        assert_eq!(
            (set.width, set.height),
            (scene.camera.width, scene.camera.height)
        );
        assert_eq!(set.position, view.position);
    }

    #[test]
    fn a_free_view_renders_the_screen_pixels_capped() {
        assert_eq!(free_render_size(400.0, 300.0, 2.0), (800, 600));
        assert_eq!(free_render_size(2000.0, 1000.0, 1.0), (1280, 640));
        assert_eq!(free_render_size(0.0, 0.0, 1.0), (1, 1));
    }
}
