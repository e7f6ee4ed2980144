//! Camera navigation in the viewport: orbit (drag on empty space, or Alt+drag), pan
//! (middle drag or Shift+drag), zoom (wheel) and frame the selection (F). Every gesture
//! pushes [`SceneEdit::SetCamera`] commands computed from the camera at its start, so a
//! drag is one undo step (the app records none while a button is down) and a burst of
//! wheel steps is one too ([`zoom_in_progress`] holds the undo point back).

use egui::{Id, MouseWheelUnit, Pos2, Vec2};

use crate::gizmo::navigate::{frame_in_scene, orbit, pan, zoom};
use crate::gizmo::view::bounding_sphere;
use crate::scene::{Camera, Light, Scene};
use crate::ui::commands::{Command, SceneEdit, Selection};
use crate::ui::gizmo::projection::cone_length;

/// Seconds after the last wheel step during which the zoom is one gesture.
const ZOOM_GESTURE_SECONDS: f64 = 0.35;

/// A camera drag: what it does and the camera when it started.
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

/// Pushes the camera of a drag from `start` to `now`.
pub fn drag_camera(
    drag: &CameraDrag,
    start: Pos2,
    now: Pos2,
    height_points: f32,
    commands: &mut Vec<Command>,
) {
    let camera = drag.camera(now - start, height_points);
    push_camera(camera, commands);
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

/// Zooms by the wheel steps of this frame, if any, and starts or extends the gesture.
pub fn zoom_with_wheel(ctx: &egui::Context, scene: &Scene, commands: &mut Vec<Command>) {
    let steps = wheel_steps(ctx);
    if steps == 0.0 || !steps.is_finite() {
        return;
    }
    push_camera(zoom(&scene.camera, steps), commands);
    let now = ctx.input(|i| i.time);
    ctx.data_mut(|d| d.insert_temp(zoom_id(), now));
}

fn zoom_id() -> Id {
    Id::unique("raylab zoom gesture")
}

/// Whether a wheel zoom is still going on (a step came in the last moments): the app
/// records no undo point until it is over, so a zoom is one step.
#[must_use]
pub fn zoom_in_progress(ctx: &egui::Context) -> bool {
    let Some(last) = ctx.data(|d| d.get_temp::<f64>(zoom_id())) else {
        return false;
    };
    let going_on = ctx.input(|i| i.time) - last < ZOOM_GESTURE_SECONDS;
    if going_on {
        // Keep frames coming so the gesture ends (and is recorded) without new input.
        ctx.request_repaint();
    } else {
        ctx.data_mut(|d| d.remove::<f64>(zoom_id()));
    }
    going_on
}

/// The sphere to frame for the selection: an object's bounds, a point light's
/// surroundings, a spotlight's drawn cone; `None` for what has no place.
#[must_use]
pub fn selection_sphere(scene: &Scene, selection: &Selection) -> Option<(glam::DVec3, f64)> {
    let length = cone_length(scene);
    match selection {
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

/// Pushes the camera that frames the selection, if it has a place.
pub fn frame_selection(scene: &Scene, selection: &Selection, commands: &mut Vec<Command>) {
    if let Some((centre, radius)) = selection_sphere(scene, selection)
        && centre.is_finite()
        && radius.is_finite()
    {
        push_camera(frame_in_scene(scene, centre, radius), commands);
    }
}

/// Pushes a camera edit, unless a degenerate camera (eye on its target) made it NaN.
fn push_camera(camera: Camera, commands: &mut Vec<Command>) {
    if camera.position.is_finite() && camera.look_at.is_finite() {
        commands.push(Command::Edit(SceneEdit::SetCamera(camera)));
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
        let (centre, radius) = selection_sphere(&scene, &selection).unwrap();
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
        frame_selection(&scene, &selection, &mut commands);
        let [Command::Edit(SceneEdit::SetCamera(camera))] = commands.as_slice() else {
            panic!("one camera edit, got {commands:?}");
        };
        assert!(
            (camera.look_at - centre).length() < 1e-9,
            "aimed at the selection"
        );
        let inside_wall = (camera.position - blocked_eye).abs().max_element() < half_size;
        assert!(!inside_wall, "eye {} is inside the box", camera.position);
    }
}
