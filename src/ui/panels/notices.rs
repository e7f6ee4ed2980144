//! The banners under the menu bar: an error (red) or a warning (amber), each with
//! Dismiss. A failure and a warning look different, so a warning is not mistaken for a
//! failed import. They float over the top of the window rather than taking a strip of
//! it, so one appearing or going never moves the panels or the picture under the cursor.

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

/// One banner: how loud, what it says, and the command its Dismiss pushes.
pub struct Notice<'a> {
    /// How loud.
    pub tone: Tone,
    /// What it says.
    pub text: &'a str,
    /// What Dismiss does.
    pub dismiss: Command,
}

/// Shows the banners stacked over the top of the window, below the menu bar (`top`).
pub fn notices_ui(
    ctx: &egui::Context,
    top: f32,
    notices: Vec<Notice<'_>>,
    commands: &mut Vec<Command>,
) {
    if notices.is_empty() {
        return;
    }
    let screen = ctx.content_rect();
    let width = (screen.width() - 32.0).min(760.0);
    egui::Area::new(egui::Id::unique("raylab notices"))
        .order(egui::Order::Foreground)
        .fixed_pos(egui::pos2(screen.center().x - width / 2.0, top + 6.0))
        .show(ctx, |ui| {
            ui.set_width(width);
            for notice in notices {
                notice_ui(ui, &notice, commands);
            }
        });
}

/// One banner, as wide as the stack.
fn notice_ui(ui: &mut Ui, notice: &Notice<'_>, commands: &mut Vec<Command>) {
    let (tone, text) = (notice.tone, notice.text);
    let (mark, fill, mark_colour) = match tone {
        Tone::Error => (
            "▲",
            Color32::from_rgb(90, 28, 28),
            Color32::from_rgb(255, 200, 120),
        ),
        Tone::Warning => (
            "!",
            Color32::from_rgb(78, 62, 20),
            Color32::from_rgb(255, 220, 130),
        ),
    };
    egui::Frame::new()
        .fill(fill)
        .inner_margin(8)
        .corner_radius(4)
        .stroke(egui::Stroke::new(1.0, Color32::from_black_alpha(120)))
        .show(ui, |ui| {
            ui.set_width(ui.available_width());
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
                        commands.push(notice.dismiss.clone());
                    }
                    // Long messages (many import warnings) wrap instead of running off.
                    ui.with_layout(egui::Layout::left_to_right(egui::Align::Min), |ui| {
                        ui.add(egui::Label::new(RichText::new(text).color(Color32::WHITE)).wrap());
                    });
                });
            });
        });
    ui.add_space(4.0);
}
