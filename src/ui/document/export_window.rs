//! The Export PNG window: size (linked to the aspect ratio unless unlinked), samples,
//! full picture or as shown, the file, and a status line. The window grows downward
//! only (it is pinned by its top-left corner), so nothing moves under the cursor when
//! the status line appears.

use std::path::{Path, PathBuf};
use std::time::Duration;

use egui::{DragValue, RichText, Ui};

use crate::scene::{MAX_IMAGE_SIDE, Scene};
use crate::ui::commands::Command;
use crate::ui::document::export::{ExportStage, ExportState, ViewportLook};
use crate::ui::document::files::with_png_extension;
use crate::ui::state::isolation_note;

/// The window's width, used to place it centred when it first opens.
const WIDTH: f32 = 380.0;

/// The most samples per pixel an export takes (the validator's limit).
const MAX_EXPORT_SAMPLES: u32 = 65536;

/// Shows the Export PNG window (when open). Browse pushes [`Command::BrowseExportPath`].
/// `folder` is the scene file's, where its mesh files are read.
pub fn export_window(
    ctx: &egui::Context,
    state: &mut ExportState,
    scene: &Scene,
    folder: Option<&Path>,
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
        .show(ctx, |ui| {
            export_ui(ui, state, scene, folder, shown, commands)
        });
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
    folder: Option<&Path>,
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
                    path_field_ui(ui, &mut state.path);
                    if ui.button("Browse…").clicked() {
                        commands.push(Command::BrowseExportPath);
                    }
                });
                ui.end_row();
            });
    });
    ui.add_space(6.0);
    actions_ui(ui, state, scene, folder, shown);
    // The status line always takes its room, so the window does not change size when
    // a message appears.
    let (text, colour) = match &state.status {
        Some(Ok(message)) => (message.as_str(), egui::Color32::from_rgb(140, 200, 140)),
        Some(Err(error)) => (error.as_str(), egui::Color32::from_rgb(255, 120, 110)),
        None => (" ", egui::Color32::TRANSPARENT),
    };
    ui.add(egui::Label::new(RichText::new(text).color(colour)).wrap());
}

/// The file field. A path too long for it shows its end while the field is not being
/// edited ("…/renders/glass.png"): the file's name matters more than the start of the
/// folder. Editing shows the whole text, as typed.
fn path_field_ui(ui: &mut Ui, path: &mut String) {
    let id = ui.make_persistent_id("export path");
    let editing = ui.memory(|m| m.has_focus(id));
    let font = egui::TextStyle::Body.resolve(ui.style());
    let colour = ui.visuals().text_color();
    let width = 220.0;
    let inner = width - 2.0 * ui.spacing().button_padding.x;
    let text_width = |text: &str| {
        ui.ctx()
            .fonts_mut(|f| f.layout_no_wrap(text.to_owned(), font.clone(), colour))
            .size()
            .x
    };
    let elided = (!editing && text_width(path) > inner).then(|| {
        let chars: Vec<char> = path.chars().collect();
        (1..chars.len())
            .map(|start| format!("…{}", chars[start..].iter().collect::<String>()))
            .find(|text| text_width(text) <= inner)
            .unwrap_or_default()
    });
    let mut edit = egui::TextEdit::singleline(path).id(id).desired_width(width);
    if elided.is_some() {
        // The field's own text is hidden; its end is painted over it below.
        edit = edit.text_color(egui::Color32::TRANSPARENT);
    }
    let response = ui.add(edit).accessible_name("export path");
    if let Some(text) = elided {
        let at = response.rect.left_center() + egui::vec2(ui.spacing().button_padding.x, 0.0);
        ui.painter()
            .text(at, egui::Align2::LEFT_CENTER, text, font, colour);
    }
    response.on_hover_text(path.as_str());
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
fn actions_ui(
    ui: &mut Ui,
    state: &mut ExportState,
    scene: &Scene,
    folder: Option<&Path>,
    shown: ViewportLook<'_>,
) {
    if let Some(progress) = state.progress() {
        ui.horizontal(|ui| {
            if state.is_rendering() {
                // Reading a mesh file says so, with the file's own progress.
                let bar = match state.stage() {
                    Some(reading @ ExportStage::ReadingMesh { fraction, .. }) => {
                        egui::ProgressBar::new(fraction as f32).text(reading.to_string())
                    }
                    _ => egui::ProgressBar::new(progress as f32).show_percentage(),
                };
                ui.add(bar.desired_width(260.0));
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
            state.start(scene, folder, shown, &path, ui.ctx())
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
