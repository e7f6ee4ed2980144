//! The scene camera seen from the view camera: its frustum (eye, lines to the image
//! rectangle's corners, the rectangle and an up triangle), selectable by a click like a
//! light marker. Not drawn when the viewport looks through the scene camera.

use egui::{Color32, Pos2};

use super::element::{Element, Part, dot, line};
use super::projection::ViewMapping;
use crate::gizmo::HandleId;
use crate::gizmo::frustum::frustum;
use crate::scene::Camera;

/// The frustum's colour.
pub const CAMERA_COLOUR: Color32 = Color32::from_rgb(150, 200, 255);
/// The image rectangle's height on screen, in points (about; it is drawn at one depth).
const RECTANGLE_PX: f64 = 90.0;

/// Whether the viewport shows another camera than the scene's, so the scene camera has a
/// place on screen.
#[must_use]
pub fn shows_scene_camera(view: &ViewMapping, scene_camera: &Camera) -> bool {
    view.shown != *scene_camera
}

/// The scene camera's frustum; `selected` draws it brighter.
pub fn camera_elements(
    out: &mut Vec<Element>,
    view: &ViewMapping,
    camera: &Camera,
    selected: bool,
) {
    if !shows_scene_camera(view, camera) {
        return;
    }
    let half_tan = (camera.fov_deg.to_radians() * 0.5).tan().max(1e-6);
    let depth = view.world_per_point(camera.position) * RECTANGLE_PX * 0.5 / half_tan;
    let f = frustum(camera, depth);
    let colour = if selected {
        CAMERA_COLOUR
    } else {
        CAMERA_COLOUR.gamma_multiply(0.75)
    };
    let corners: Option<Vec<Pos2>> = f.corners.iter().map(|c| view.project(*c)).collect();
    let Some(eye) = view.project(f.eye) else {
        return;
    };
    if let Some(corners) = corners {
        for corner in &corners {
            line(out, eye, *corner, colour.gamma_multiply(0.7), None);
        }
        if let Some(tip) = view.project(f.up_tip) {
            out.push(Element {
                part: Part::Loop(vec![corners[0], tip, corners[1]]),
                colour,
                handle: None,
            });
        }
        out.push(Element {
            part: Part::Loop(corners),
            colour,
            handle: Some(HandleId::CameraMarker),
        });
    }
    dot(out, eye, 6.0, colour, Some(HandleId::CameraMarker));
}
