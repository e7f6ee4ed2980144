//! Clicks on the picture: a click selects what the ray under it meets (the leaf of an
//! object tree; Shift+click the node holding it); in inspect mode
//! (the toolbar's toggle, or Alt held) a click, or moving with Alt held and no button
//! down, inspects a pixel of the scene camera instead. The rays are cast off the UI
//! thread ([`Command::Pick`]); in camera view an inspected pixel is simply the one under
//! the cursor.

use egui::{Pos2, Response, Vec2};
use glam::{DVec2, DVec3};

use super::exchange::ViewportInput;
use super::pixel_inspector::{PixelInspection, inspected_pixel};
use crate::scene::Scene;
use crate::trace::PinholeCamera;
use crate::ui::commands::{Command, Selection};
use crate::ui::gizmo::camera::shows_scene_camera;
use crate::ui::gizmo::projection::ViewMapping;
use crate::ui::state::{PickPurpose, PickRequest};

/// Pushes what this frame's clicks on the picture ask for.
pub fn picture_clicks(
    ui: &egui::Ui,
    response: &Response,
    view: &ViewMapping,
    input: &ViewportInput,
    gizmo_took_click: bool,
    commands: &mut Vec<Command>,
) {
    let alt = ui.input(|i| i.modifiers.alt);
    let inspecting = input.settings.inspect || alt;
    let clicked = response.clicked() && !gizmo_took_click;
    if inspecting {
        // Alt+drag still orbits through the gizmo layer; Alt and a still button inspect.
        let moved = alt
            && response.hovered()
            && ui.input(|i| i.pointer.delta() != Vec2::ZERO && !i.pointer.any_down());
        let pos = if clicked || moved {
            response.interact_pointer_pos().or(response.hover_pos())
        } else {
            None
        };
        if let Some(pos) = pos {
            inspect_at(view, input.scene, pos, commands);
        }
    } else if clicked && let Some(pos) = response.interact_pointer_pos() {
        match view.pixel_ray(pos) {
            Some(ray) => {
                // A click selects the leaf hit; Shift+click the node holding it (Alt
                // is the inspector's).
                let shift = ui.input(|i| i.modifiers.shift);
                commands.push(Command::Pick(PickRequest {
                    ray,
                    purpose: if shift {
                        PickPurpose::SelectParent
                    } else {
                        PickPurpose::Select
                    },
                }));
            }
            None => commands.push(Command::Select(Selection::None)),
        }
    }
}

/// Inspects the scene camera's pixel at `pos`: directly in camera view, else through the
/// point the view's ray meets.
fn inspect_at(view: &ViewMapping, scene: &Scene, pos: Pos2, commands: &mut Vec<Command>) {
    if shows_scene_camera(view, &scene.camera) {
        if let Some(ray) = view.pixel_ray(pos) {
            commands.push(Command::Pick(PickRequest {
                ray,
                purpose: PickPurpose::Inspect,
            }));
        }
    } else if let Some(pixel) = inspected_pixel(scene, view.image_of_screen(pos)) {
        commands.push(Command::InspectPixel(Some(pixel)));
    }
}

/// Where the inspected `pixel` is on screen: the centre of that pixel in camera view,
/// else the point its camera ray meets (or a point along it), seen from the view.
#[must_use]
pub fn inspected_anchor(
    view: &ViewMapping,
    scene: &Scene,
    inspections: &[PixelInspection],
    pixel: (u32, u32),
) -> Option<Pos2> {
    let centre = DVec2::new(f64::from(pixel.0) + 0.5, f64::from(pixel.1) + 0.5);
    if !shows_scene_camera(view, &scene.camera) {
        return Some(view.screen_of_image(centre));
    }
    let hit: Option<DVec3> = inspections
        .iter()
        .find(|i| i.pixel == pixel)
        .and_then(|i| i.result.as_ref().ok())
        .and_then(|p| p.report.bounces.first())
        .and_then(|b| b.hit.map(|h| h.p));
    let point = hit.unwrap_or_else(|| {
        let camera = PinholeCamera::new(&scene.camera, scene.camera.width, scene.camera.height);
        let distance = (scene.camera.look_at - scene.camera.position).length();
        camera.ray(centre).at(distance)
    });
    view.project(point)
}
