//! Camera navigation in the viewport: orbit (drag on empty space, or Alt+drag), pan
//! (middle drag or Shift+drag), zoom (wheel) and frame the selection (F). Every gesture
//! moves the view camera ([`Command::SetView`]), never the scene's: it is computed from
//! the shown camera at the gesture's start, so from camera view it starts at the scene
//! camera's pose and leaves camera view. Looking around is no edit and no undo step.

use egui::{MouseWheelUnit, Pos2, Vec2};

use crate::gizmo::navigate::{frame_in_scene, orbit, pan, zoom};
use crate::gizmo::view::bounding_sphere;
use crate::scene::{Camera, Light, Scene};
use crate::ui::commands::{Command, Selection};
use crate::ui::gizmo::projection::ViewMapping;
use crate::ui::state::ViewCamera;

/// A camera drag: what it does and the shown camera when it started.
#[derive(Clone, Debug, PartialEq)]
pub enum CameraDrag {
    /// Turn about the target.
    Orbit(Camera),
    /// Move eye and target together.
    Pan(Camera),
}

impl CameraDrag {
    /// The camera after dragging by `total` screen points from the start, in a picture
    /// `height_points` tall.
    #[must_use]
    pub fn camera(&self, total: Vec2, height_points: f32) -> Camera {
        let (dx, dy) = (f64::from(total.x), f64::from(total.y));
        match self {
            CameraDrag::Orbit(start) => orbit(start, dx, dy),
            CameraDrag::Pan(start) => pan(start, dx, dy, f64::from(height_points.max(1.0))),
        }
    }
}

/// Pushes the view of a drag from `start` to `now`.
pub fn drag_camera(
    drag: &CameraDrag,
    start: Pos2,
    now: Pos2,
    height_points: f32,
    commands: &mut Vec<Command>,
) {
    let camera = drag.camera(now - start, height_points);
    push_view(&camera, commands);
}

/// Wheel steps this frame (one per notch; trackpads give fractions), positive towards
/// the scene.
#[must_use]
pub fn wheel_steps(ctx: &egui::Context) -> f64 {
    ctx.input(|input| {
        input
            .events
            .iter()
            .map(|event| match event {
                egui::Event::MouseWheel { unit, delta, .. } => {
                    let per_step = match unit {
                        MouseWheelUnit::Point => 50.0,
                        MouseWheelUnit::Line => 1.0,
                        MouseWheelUnit::Page => 0.1,
                    };
                    f64::from(delta.y) / per_step
                }
                _ => 0.0,
            })
            .sum()
    })
}

/// Zooms the shown camera by the wheel steps of this frame, if any.
pub fn zoom_with_wheel(ctx: &egui::Context, shown: &Camera, commands: &mut Vec<Command>) {
    let steps = wheel_steps(ctx);
    if steps == 0.0 || !steps.is_finite() {
        return;
    }
    push_view(&zoom(shown, steps), commands);
}

/// The sphere to frame for the selection: an object's bounds, a point light's
/// surroundings, a spotlight's drawn cone (as `view` draws it), the scene camera's eye;
/// `None` for what has no place.
#[must_use]
pub fn selection_sphere(
    scene: &Scene,
    selection: &Selection,
    view: &ViewMapping,
) -> Option<(glam::DVec3, f64)> {
    let length = view.cone_length();
    match selection {
        Selection::Camera => Some((
            scene.camera.position,
            (scene.camera.look_at - scene.camera.position).length() * 0.25,
        )),
        Selection::Object(i) => scene.objects.get(*i).map(bounding_sphere),
        Selection::Light(i) => match scene.lights.get(*i)? {
            Light::Point { position, .. } => Some((*position, length * 0.5)),
            Light::Spot {
                position,
                direction,
                ..
            } => Some((
                *position + direction.normalize_or_zero() * length * 0.5,
                length * 0.7,
            )),
            Light::Ambient { .. } | Light::Directional { .. } => None,
        },
        _ => None,
    }
}

/// Pushes the view that frames the selection, if it has a place.
pub fn frame_selection(
    scene: &Scene,
    selection: &Selection,
    view: &ViewMapping,
    commands: &mut Vec<Command>,
) {
    if let Some((centre, radius)) = selection_sphere(scene, selection, view)
        && centre.is_finite()
        && radius.is_finite()
    {
        // Framed from the shown camera, with the eye kept out of the scene's solids.
        let seen_from = Scene {
            camera: view.shown.clone(),
            ..scene.clone()
        };
        push_view(&frame_in_scene(&seen_from, centre, radius), commands);
    }
}

/// Pushes the free view at `camera`'s pose, unless a degenerate camera (eye on its
/// target) made it unusable.
fn push_view(camera: &Camera, commands: &mut Vec<Command>) {
    let view = ViewCamera::free(camera);
    if view.is_usable() {
        commands.push(Command::SetView(view));
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::scene::{Object, Shape, Transform, Trs};

    #[test]
    fn frame_selection_keeps_the_eye_out_of_a_solid_where_plain_framing_would_put_it() {
        let mut scene = crate::scene::examples::default_scene();
        let selection = Selection::Object(1);
        let picture = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(800.0, 600.0));
        let view = ViewMapping::new(&scene.camera, picture);
        let (centre, radius) = selection_sphere(&scene, &selection, &view).unwrap();
        // A box around the eye that framing along the current view direction would give.
        let blocked_eye = crate::gizmo::navigate::frame(&scene.camera, centre, radius).position;
        let half_size = 0.5 * (blocked_eye - centre).length();
        scene.objects.push(Object {
            name: "wall".into(),
            shape: Shape::Cube,
            transform: Transform::Trs(Trs {
                translate: blocked_eye,
                rotate_deg: DVec3::ZERO,
                scale: DVec3::splat(half_size),
            }),
            material: scene.objects[0].material.clone(),
        });
        let mut commands = Vec::new();
        let view = ViewMapping::new(&scene.camera, picture);
        frame_selection(&scene, &selection, &view, &mut commands);
        let [Command::SetView(moved)] = commands.as_slice() else {
            panic!("one view move, got {commands:?}");
        };
        let camera = moved.as_scene_camera(&scene.camera);
        assert!(
            (camera.look_at - centre).length() < 1e-9,
            "aimed at the selection"
        );
        let inside_wall = (camera.position - blocked_eye).abs().max_element() < half_size;
        assert!(!inside_wall, "eye {} is inside the box", camera.position);
    }
}
