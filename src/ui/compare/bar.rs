//! The comparison view's toolbar: the four modes, flip and swipe controls, zoom, the
//! compared file (and a warning once the scene has changed since), and the way back to
//! the live preview.

use egui::{Color32, RichText};

use super::mode::{CompareMode, Side};
use super::session::{CompareSession, OtherSource};
use super::view::{MAX_ZOOM, ZoomView};
use crate::scene::Scene;
use crate::ui::commands::Command;

/// Zoom steps of the + and − buttons.
const ZOOM_STEP: f32 = 2.0;

/// Shows the toolbar.
pub fn compare_bar_ui(
    ui: &mut egui::Ui,
    session: &mut CompareSession,
    scene: &Scene,
    commands: &mut Vec<Command>,
) {
    ui.horizontal_wrapped(|ui| {
        ui.label(
            RichText::new("COMPARE")
                .small()
                .strong()
                .color(Color32::from_gray(150)),
        );
        // First, so it stays in one place whatever the mode's own controls are.
        if ui.button("Close comparison").clicked() {
            session.close();
        }
        ui.separator();
        for mode in CompareMode::ALL {
            let button = ui
                .selectable_label(session.mode == mode, mode.label())
                .on_hover_text(mode.hint());
            if button.clicked() {
                session.mode = mode;
            }
        }
        ui.separator();
        mode_controls_ui(ui, session);
        zoom_ui(ui, &mut session.view);
        ui.separator();
        if let Some(compared) = session.compared() {
            let hover = match &compared.source {
                OtherSource::File(path) => path.display().to_string(),
                OtherSource::Planted(label) => {
                    format!("The scene rendered as a tracer with the bug {label} would")
                }
            };
            ui.weak(compared.source.name()).on_hover_text(hover);
        }
        if session.is_stale(scene) {
            ui.label(RichText::new("scene changed since").color(Color32::from_rgb(255, 200, 120)));
            match session.compared().map(|c| c.source.clone()) {
                Some(OtherSource::File(path)) => {
                    let again = ui.button("Compare again").clicked();
                    if again {
                        commands.push(Command::CompareWith(path));
                    }
                }
                Some(OtherSource::Planted(_)) => {
                    ui.weak("(refresh the Bug gallery for pictures of this scene)");
                }
                None => {}
            }
        }
    });
}

/// Flip mode: the picture shown and its switch; swipe mode: the line's place.
fn mode_controls_ui(ui: &mut egui::Ui, session: &mut CompareSession) {
    match session.mode {
        CompareMode::Flip => {
            let other = session.flip_side.flipped();
            let text = match other {
                Side::Raylab => "Flip to raylab",
                Side::Other => "Flip to other image",
            };
            if ui
                .button(text)
                .on_hover_text("Space over the picture flips too")
                .clicked()
            {
                session.flip_side = other;
            }
            ui.checkbox(&mut session.auto_flip, "auto");
            ui.separator();
        }
        CompareMode::Swipe => {
            ui.add(
                egui::Slider::new(&mut session.swipe, 0.0..=1.0)
                    .show_value(false)
                    .text("swipe"),
            );
            ui.separator();
        }
        CompareMode::SideBySide | CompareMode::Difference => {}
    }
}

/// Fit, −, +, and the zoom as screen points per image pixel's width of picture.
fn zoom_ui(ui: &mut egui::Ui, view: &mut ZoomView) {
    if ui
        .button("Fit")
        .on_hover_text("Show the whole picture")
        .clicked()
    {
        *view = ZoomView::default();
    }
    let centre = view.centre_uv;
    if ui
        .add_enabled(view.zoom > 1.0, egui::Button::new("−"))
        .clicked()
    {
        view.zoom = (view.zoom / ZOOM_STEP).max(1.0);
        view.centre_uv = centre;
    }
    if ui
        .add_enabled(view.zoom < MAX_ZOOM, egui::Button::new("+"))
        .clicked()
    {
        view.zoom = (view.zoom * ZOOM_STEP).min(MAX_ZOOM);
        view.centre_uv = centre;
    }
    ui.weak(format!("zoom {:.0}×", view.zoom))
        .on_hover_text("Scroll over the picture to zoom about the pointer; drag to pan");
}
