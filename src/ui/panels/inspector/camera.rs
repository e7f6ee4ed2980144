//! The camera inspector: placement, field of view and output size.

use egui::Ui;

use super::fields::{number_row_ui, vec3_row_ui, whole_number_row_ui};
use super::layout::{grid_ui, heading_ui};
use super::limits::{FOV_DEG, IMAGE_SIDE, Limits};
use crate::scene::*;
use crate::ui::commands::{Command, SceneEdit};

pub(super) fn camera_ui(ui: &mut Ui, camera: &Camera, commands: &mut Vec<Command>) {
    heading_ui(ui, "CAMERA", "Camera");
    let mut edited = camera.clone();
    grid_ui(ui, "camera", |ui| {
        vec3_row_ui(ui, "position", &mut edited.position, 0.02, Limits::ANY);
        vec3_row_ui(ui, "look at", &mut edited.look_at, 0.02, Limits::ANY);
        vec3_row_ui(ui, "up", &mut edited.up, 0.01, Limits::ANY);
        number_row_ui(ui, "fov", &mut edited.fov_deg, 0.2, FOV_DEG);
        whole_number_row_ui(ui, "width", &mut edited.width, 1.0, IMAGE_SIDE);
        whole_number_row_ui(ui, "height", &mut edited.height, 1.0, IMAGE_SIDE);
    });
    ui.weak("fov is the vertical field of view, in degrees. Width and height are the output size.");
    if edited != *camera {
        commands.push(Command::Edit(SceneEdit::SetCamera(edited)));
    }
}
