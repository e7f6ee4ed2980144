//! The Compare with Image window: a path field (typed, or filled by the native dialog
//! where the desktop has one), progress with Cancel while the comparison runs, and the
//! error when it cannot be made. The field is always there, so a desktop without a
//! native file dialog still compares; nothing fails in silence.

use std::path::{Path, PathBuf};
use std::time::Duration;

use egui::{Color32, RichText};

use super::session::CompareSession;
use crate::ui::commands::Command;

/// Accessible name of the window's path field.
pub const COMPARE_PATH_LABEL: &str = "compare image path";

/// Whether a dropped or chosen file looks like another renderer's picture (PNG, PPM).
#[must_use]
pub fn is_compare_image(path: &Path) -> bool {
    path.extension().is_some_and(|e| {
        ["png", "ppm"]
            .iter()
            .any(|known| e.eq_ignore_ascii_case(known))
    })
}

/// Shows the window when open, polls the running comparison and pushes
/// [`Command::CompareWith`] when the user asks to compare.
pub fn compare_window(
    ctx: &egui::Context,
    session: &mut CompareSession,
    commands: &mut Vec<Command>,
) {
    session.poll();
    if session.is_running() {
        ctx.request_repaint_after(Duration::from_millis(100));
    }
    if !session.window_open {
        return;
    }
    let mut open = true;
    egui::Window::new("Compare with Image")
        .open(&mut open)
        .resizable(false)
        .collapsible(false)
        .default_width(420.0)
        .pivot(egui::Align2::CENTER_CENTER)
        .default_pos(ctx.content_rect().center())
        .show(ctx, |ui| window_ui(ui, session, commands));
    if !open {
        // Closing the window while it runs is a cancel, reported in the window.
        session.cancel();
        session.window_open = session.is_running();
    }
}

fn window_ui(ui: &mut egui::Ui, session: &mut CompareSession, commands: &mut Vec<Command>) {
    ui.label("Another renderer's picture of this scene (8-bit PNG or PPM, at the scene's size):");
    let running = session.is_running();
    ui.add_enabled_ui(!running, |ui| {
        ui.horizontal(|ui| {
            ui.add(egui::TextEdit::singleline(&mut session.path_text).desired_width(280.0))
                .accessible_name(COMPARE_PATH_LABEL);
            if ui.button("Browse…").clicked() {
                commands.push(Command::BrowseCompareImage);
            }
        });
    });
    ui.add_space(6.0);
    if let Some(progress) = session.progress() {
        ui.horizontal(|ui| {
            // Progress counts the rows traced; the fit that follows is quick but not free.
            let bar = egui::ProgressBar::new(progress as f32).desired_width(300.0);
            ui.add(if progress < 1.0 {
                bar.show_percentage()
            } else {
                bar.text("fitting…")
            });
            if ui.button("Cancel").clicked() {
                session.cancel();
            }
        });
    } else {
        let path = PathBuf::from(session.path_text.trim());
        let has_path = !session.path_text.trim().is_empty();
        if ui
            .add_enabled(has_path, egui::Button::new("Compare"))
            .clicked()
        {
            commands.push(Command::CompareWith(path));
        }
    }
    if let Some(error) = session.error() {
        ui.add_space(4.0);
        ui.label(RichText::new(error).color(Color32::from_rgb(255, 120, 110)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn png_and_ppm_of_any_case_are_pictures_to_compare() {
        assert!(is_compare_image(Path::new("a/theirs.PNG")));
        assert!(is_compare_image(Path::new("theirs.ppm")));
        assert!(!is_compare_image(Path::new("scene.ron")));
        assert!(!is_compare_image(Path::new("noextension")));
    }
}
