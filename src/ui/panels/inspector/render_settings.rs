//! The render settings inspector: mirror depth, background and samples.

use egui::Ui;

use super::fields::{colour_row_ui, whole_number_row_ui};
use super::limits::{MAX_DEPTH, MAX_SAMPLES_PER_PIXEL};
use super::{grid_ui, heading_ui};
use crate::scene::*;
use crate::ui::commands::{Command, SceneEdit};

pub(super) fn render_ui(ui: &mut Ui, render: &RenderSettings, commands: &mut Vec<Command>) {
    heading_ui(ui, "RENDER", "Render settings");
    let mut edited = render.clone();
    grid_ui(ui, "render", |ui| {
        whole_number_row_ui(ui, "max depth", &mut edited.max_depth, 0.1, 0..=MAX_DEPTH);
        colour_row_ui(ui, "background", &mut edited.background);
        whole_number_row_ui(
            ui,
            "samples",
            &mut edited.samples_per_pixel,
            0.2,
            1..=MAX_SAMPLES_PER_PIXEL,
        );
    });
    ui.weak(
        "max depth: mirror bounces. samples: anti-aliasing samples per pixel; \
         the preview refines up to this and Export PNG uses it.",
    );
    if edited != *render {
        commands.push(Command::Edit(SceneEdit::SetRender(edited)));
    }
}
