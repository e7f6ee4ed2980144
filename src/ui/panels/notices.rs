//! The banners under the menu bar: an error (red) or a warning (amber), each with
//! Dismiss. A failure and a warning look different, so a warning is not mistaken for a
//! failed import.

use egui::{Color32, RichText, Ui};

use crate::ui::commands::Command;

/// How loud a banner is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tone {
    /// Something failed.
    Error,
    /// Something worked, with a caveat worth reading.
    Warning,
}

/// Shows `text` as a full-width banner; Dismiss pushes `dismiss`.
pub fn notice_ui(
    ui: &mut Ui,
    tone: Tone,
    text: &str,
    dismiss: Command,
    commands: &mut Vec<Command>,
) {
    let (id, fill, mark, mark_colour) = match tone {
        Tone::Error => (
            "error",
            Color32::from_rgb(90, 28, 28),
            "▲",
            Color32::from_rgb(255, 200, 120),
        ),
        Tone::Warning => (
            "warning",
            Color32::from_rgb(78, 62, 20),
            "!",
            Color32::from_rgb(255, 220, 130),
        ),
    };
    egui::Panel::top(id)
        .frame(egui::Frame::new().fill(fill).inner_margin(8))
        .show(ui, |ui| {
            ui.horizontal(|ui| {
                ui.label(RichText::new(mark).strong().color(mark_colour));
                ui.with_layout(egui::Layout::right_to_left(egui::Align::Min), |ui| {
                    let button = ui
                        .button("Dismiss")
                        .on_hover_text("Hide this message")
                        .accessible_name(match tone {
                            Tone::Error => "Dismiss",
                            Tone::Warning => "Dismiss warning",
                        });
                    if button.clicked() {
                        commands.push(dismiss);
                    }
                    // Long messages (many import warnings) wrap instead of running off.
                    ui.with_layout(egui::Layout::left_to_right(egui::Align::Min), |ui| {
                        ui.add(egui::Label::new(RichText::new(text).color(Color32::WHITE)).wrap());
                    });
                });
            });
        });
}
