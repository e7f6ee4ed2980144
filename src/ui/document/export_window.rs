//! The Export PNG window: size (linked to the aspect ratio unless unlinked), samples,
//! full picture or as shown, the file, and a status line. The window grows downward
//! only (it is pinned by its top-left corner), so nothing moves under the cursor when
//! the status line appears.

use std::path::PathBuf;
use std::time::Duration;

use egui::{DragValue, RichText, Ui};

use crate::scene::{MAX_IMAGE_SIDE, Scene};
use crate::ui::commands::Command;
use crate::ui::document::export::{ExportState, ViewportLook};
use crate::ui::document::files::with_png_extension;
use crate::ui::state::isolation_note;

/// The window's width, used to place it centred when it first opens.
const WIDTH: f32 = 380.0;

/// The most samples per pixel an export takes (the validator's limit).
const MAX_EXPORT_SAMPLES: u32 = 65536;

/// Shows the Export PNG window (when open). Browse pushes [`Command::BrowseExportPath`].
pub fn export_window(
    ctx: &egui::Context,
    state: &mut ExportState,
    scene: &Scene,
    shown: ViewportLook<'_>,
    commands: &mut Vec<Command>,
) {
    let mut open = state.open;
    let centre = ctx.content_rect().center();
    egui::Window::new("Export PNG")
        .open(&mut open)
        .resizable(false)
        .collapsible(false)
        .default_width(WIDTH)
        .pivot(egui::Align2::LEFT_TOP)
        .default_pos(centre - egui::vec2(WIDTH / 2.0, 150.0))
        .show(ctx, |ui| export_ui(ui, state, scene, shown, commands));
    state.open = open || state.is_running();
    state.poll();
    if state.is_running() {
        ctx.request_repaint_after(Duration::from_millis(100));
    }
}

fn export_ui(
    ui: &mut Ui,
    state: &mut ExportState,
    scene: &Scene,
    shown: ViewportLook<'_>,
    commands: &mut Vec<Command>,
) {
    let running = state.is_running();
    ui.add_enabled_ui(!running, |ui| {
        egui::Grid::new("export settings")
            .num_columns(2)
            .spacing([12.0, 6.0])
            .show(ui, |ui| {
                size_rows_ui(ui, state, scene);
                ui.label("Picture");
                picture_choice_ui(ui, state, scene, shown);
                ui.end_row();
                ui.label("File");
                ui.horizontal(|ui| {
                    ui.add(egui::TextEdit::singleline(&mut state.path).desired_width(220.0))
                        .accessible_name("export path");
                    if ui.button("Browse…").clicked() {
                        commands.push(Command::BrowseExportPath);
                    }
                });
                ui.end_row();
            });
    });
    ui.add_space(6.0);
    actions_ui(ui, state, scene, shown);
    // The status line always takes its room, so the window does not change size when
    // a message appears.
    let (text, colour) = match &state.status {
        Some(Ok(message)) => (message.as_str(), egui::Color32::from_rgb(140, 200, 140)),
        Some(Err(error)) => (error.as_str(), egui::Color32::from_rgb(255, 120, 110)),
        None => (" ", egui::Color32::TRANSPARENT),
    };
    ui.add(egui::Label::new(RichText::new(text).color(colour)).wrap());
}

/// Width, height (linked or not) and samples.
fn size_rows_ui(ui: &mut Ui, state: &mut ExportState, scene: &Scene) {
    let mut settings = state
        .settings
        .clone()
        .unwrap_or_else(|| crate::trace::RenderOptions::from_scene(scene));
    state.settings = Some(settings.clone());
    let (mut width, mut height) = (settings.width, settings.height);
    ui.label("Width");
    let width_changed = ui
        .add(DragValue::new(&mut width).range(1..=MAX_IMAGE_SIDE))
        .accessible_name("export width")
        .changed();
    ui.end_row();
    ui.label("Height");
    let height_changed = ui
        .horizontal(|ui| {
            let changed = ui
                .add(DragValue::new(&mut height).range(1..=MAX_IMAGE_SIDE))
                .accessible_name("export height")
                .changed();
            let mut linked = state.keep_aspect;
            if ui
                .checkbox(&mut linked, "keep aspect")
                .on_hover_text("Width and height keep their ratio when either is changed")
                .changed()
            {
                state.keep_aspect = linked;
                state.aspect = f64::from(width) / f64::from(height.max(1));
            }
            changed
        })
        .inner;
    ui.end_row();
    if width_changed || height_changed {
        state.resize(width, height, height_changed);
    }
    settings = state.settings.clone().unwrap_or(settings);
    ui.label("Samples");
    ui.add(DragValue::new(&mut settings.samples_per_pixel).range(1..=MAX_EXPORT_SAMPLES))
        .accessible_name("export samples");
    ui.end_row();
    state.settings = Some(settings);
}

/// Full picture, or the viewport's switches and view.
fn picture_choice_ui(ui: &mut Ui, state: &mut ExportState, scene: &Scene, shown: ViewportLook<'_>) {
    let mut reasons = shown.settings.not_full_picture_reasons();
    reasons.extend(isolation_note(shown.isolation, scene));
    let hover = if reasons.is_empty() {
        "The viewport shows the full picture: both choices give the same image".to_owned()
    } else {
        format!("The viewport shows: {}", reasons.join(", "))
    };
    ui.checkbox(&mut state.as_shown, "as the viewport shows it")
        .on_hover_text(hover);
}

/// Render and save / Save kept render, or the progress bar and Cancel.
fn actions_ui(ui: &mut Ui, state: &mut ExportState, scene: &Scene, shown: ViewportLook<'_>) {
    if let Some(progress) = state.progress() {
        ui.horizontal(|ui| {
            if state.is_rendering() {
                ui.add(
                    egui::ProgressBar::new(progress as f32)
                        .show_percentage()
                        .desired_width(260.0),
                );
                if ui.button("Cancel").clicked() {
                    state.cancel();
                }
            } else {
                ui.add(egui::Spinner::new());
                ui.label("Writing…");
            }
        });
        return;
    }
    ui.horizontal(|ui| {
        let path = with_png_extension(PathBuf::from(state.path.trim()));
        let has_path = !state.path.trim().is_empty();
        let outcome = if ui
            .add_enabled(has_path, egui::Button::new("Render and save"))
            .clicked()
        {
            state.start(scene, shown, &path, ui.ctx())
        } else if state.kept_image().is_some()
            && ui
                .add_enabled(has_path, egui::Button::new("Save kept render"))
                .clicked()
        {
            state.save_kept(&path, ui.ctx())
        } else {
            Ok(())
        };
        if let Err(error) = outcome {
            state.status = Some(Err(error));
        }
    });
}
