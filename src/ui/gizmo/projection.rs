//! Between the world, the shown camera's image pixels and the screen: projecting points
//! onto the picture and turning screen points back into the tracer's primary rays, plus
//! where the light gizmos anchor in the world. The shown camera is whichever camera the
//! viewport looks through: the view camera, or the scene camera in camera view.

use egui::emath::RectTransform;
use egui::{Pos2, Rect, Vec2};
use glam::{DAffine3, DVec2, DVec3};

use crate::gizmo::view::world_per_pixel;
use crate::scene::Camera;
use crate::trace::{PinholeCamera, Ray};

/// Length of a directional light's arrow, in screen points.
const SUN_ARROW_PX: f64 = 70.0;
/// The spotlight cone's slant length, as a fraction of the shown camera's distance to its
/// target (constant while the light is aimed, so handles do not run from the cursor).
const CONE_FRACTION: f64 = 0.3;

/// Maps between the world, the shown camera's image pixels and the screen.
#[derive(Clone, Debug)]
pub struct ViewMapping {
    /// The camera the viewport shows, with the size of the image it renders.
    pub shown: Camera,
    /// The tracer's camera for that image.
    pub camera: PinholeCamera,
    /// Image pixels to screen points (the picture).
    pub screen_from_image: RectTransform,
    /// Screen points to image pixels.
    pub image_from_screen: RectTransform,
    /// The image height over the picture's height on screen.
    pub image_px_per_point: f64,
    /// The space the points given to `project` and `world_per_point` are in, as a
    /// transform to the world: the identity, or a tree node's parent space, for drawing
    /// a part's gizmo along its parent's axes ([`ViewMapping::framed`]).
    frame: DAffine3,
}

impl ViewMapping {
    /// The mapping for `shown` (its `width` x `height` is the rendered image) drawn in
    /// `picture`.
    #[must_use]
    pub fn new(shown: &Camera, picture: Rect) -> Self {
        let (width, height) = (shown.width.max(1), shown.height.max(1));
        let image = Rect::from_min_size(Pos2::ZERO, Vec2::new(width as f32, height as f32));
        let screen_from_image = RectTransform::from_to(image, picture);
        Self {
            shown: shown.clone(),
            camera: PinholeCamera::new(shown, width, height),
            image_from_screen: screen_from_image.inverse(),
            screen_from_image,
            image_px_per_point: f64::from(height) / f64::from(picture.height().max(1.0)),
            frame: DAffine3::IDENTITY,
        }
    }

    /// This mapping for points given in another space (`world_from_local`): what
    /// `project` and `world_per_point` take. Rays and the light anchors stay in the world.
    #[must_use]
    pub fn framed(&self, world_from_local: DAffine3) -> Self {
        Self {
            frame: world_from_local,
            ..self.clone()
        }
    }

    /// Where a world point (a point of the frame's space, when framed) is on screen;
    /// `None` behind the eye.
    #[must_use]
    pub fn project(&self, p_world: DVec3) -> Option<Pos2> {
        let p = self.camera.project(self.frame.transform_point3(p_world))?;
        let pos = self
            .screen_from_image
            .transform_pos(Pos2::new(p.x as f32, p.y as f32));
        pos.is_finite().then_some(pos)
    }

    /// The primary ray through a screen point.
    #[must_use]
    pub fn ray(&self, pos: Pos2) -> Ray {
        let p = self.image_from_screen.transform_pos(pos);
        self.camera.ray(DVec2::new(f64::from(p.x), f64::from(p.y)))
    }

    /// The screen point of an image point (pixels, fractional).
    #[must_use]
    pub fn screen_of_image(&self, image_point: DVec2) -> Pos2 {
        self.screen_from_image
            .transform_pos(Pos2::new(image_point.x as f32, image_point.y as f32))
    }

    /// The image point (pixels, fractional) under a screen point.
    #[must_use]
    pub fn image_of_screen(&self, pos: Pos2) -> DVec2 {
        let p = self.image_from_screen.transform_pos(pos);
        DVec2::new(f64::from(p.x), f64::from(p.y))
    }

    /// The ray through the centre of the image pixel under a screen point (as the
    /// renderer's one-sample pass casts it), or `None` off the image.
    #[must_use]
    pub fn pixel_ray(&self, pos: Pos2) -> Option<Ray> {
        let p = self.image_of_screen(pos);
        let (w, h) = (f64::from(self.shown.width), f64::from(self.shown.height));
        (p.x >= 0.0 && p.y >= 0.0 && p.x < w && p.y < h)
            .then(|| self.camera.ray(p.floor() + DVec2::splat(0.5)))
    }

    /// The shown camera's eye.
    #[must_use]
    pub fn eye(&self) -> DVec3 {
        self.shown.position
    }

    /// World units (the frame's units, when framed: by its mean scale) per screen point
    /// at `p_world`.
    #[must_use]
    pub fn world_per_point(&self, p_world: DVec3) -> f64 {
        let at = self.frame.transform_point3(p_world);
        let scale = self.frame.matrix3.determinant().abs().cbrt();
        let scale = if scale.is_normal() { scale } else { 1.0 };
        world_per_pixel(&self.shown, at, f64::from(self.shown.height.max(1)))
            * self.image_px_per_point
            / scale
    }

    /// The slant length of a spotlight's drawn cone.
    #[must_use]
    pub fn cone_length(&self) -> f64 {
        (self.shown.position - self.shown.look_at).length() * CONE_FRACTION
    }

    /// Where a directional light's arrow points to, and its length in world units.
    #[must_use]
    pub fn sun_anchor(&self) -> (DVec3, f64) {
        let anchor = self.shown.look_at;
        (anchor, self.world_per_point(anchor) * SUN_ARROW_PX)
    }
}

/// The tail of a directional light's arrow (its aim handle).
#[must_use]
pub fn sun_tail(anchor: DVec3, length: f64, direction: DVec3) -> DVec3 {
    anchor - direction.normalize_or_zero() * length
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ray_through_a_projected_point_passes_through_it() {
        let scene = crate::ui::files::default_scene();
        let picture = Rect::from_min_size(Pos2::new(100.0, 50.0), Vec2::new(400.0, 300.0));
        let view = ViewMapping::new(&scene.camera, picture);
        for p in [DVec3::new(0.3, 1.2, -0.5), DVec3::new(-2.0, 0.1, 1.5)] {
            let pos = view.project(p).unwrap();
            assert!(view.screen_from_image.to().contains(pos), "{pos:?}");
            let ray = view.ray(pos);
            let to_p = p - ray.origin;
            let miss = (to_p - ray.dir * to_p.dot(ray.dir)).length();
            assert!(miss < 1e-5 * to_p.length(), "{miss}");
        }
    }
}
