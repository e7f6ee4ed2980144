//! The "not the full picture" marker over the viewport's top-right corner: whenever a
//! term is off, a term is soloed or a debug view is on (these persist across restarts),
//! or anything else leaves part of the picture out, it says so and lists why.

use egui::{Align, Color32, CornerRadius, Layout, Rect, RichText, UiBuilder, Vec2};

/// The marker's accessible text starts with this (for tests and screen readers).
pub const NOT_FULL_PICTURE: &str = "Not the full picture";

/// Shows the marker in `picture`'s top-right corner when `reasons` is not empty. Each
/// reason is a short phrase ("diffuse off", "solo specular", "depth view").
pub fn full_picture_marker_ui(ui: &mut egui::Ui, picture: Rect, reasons: &[String]) {
    if reasons.is_empty() {
        return;
    }
    let room = Rect::from_min_max(
        picture.left_top() + Vec2::new(8.0, 8.0),
        picture.right_bottom() - Vec2::new(8.0, 8.0),
    );
    if room.width() < 40.0 || room.height() < 20.0 {
        return;
    }
    let builder = UiBuilder::new()
        .max_rect(room)
        .layout(Layout::right_to_left(Align::Min));
    ui.scope_builder(builder, |ui| {
        egui::Frame::new()
            .fill(Color32::from_rgba_unmultiplied(70, 52, 10, 230))
            .corner_radius(CornerRadius::same(3))
            .inner_margin(egui::Margin::symmetric(6, 3))
            .show(ui, |ui| {
                ui.set_max_width(room.width() * 0.6);
                let text = format!("{NOT_FULL_PICTURE}: {}", reasons.join(", "));
                ui.add(
                    egui::Label::new(
                        RichText::new(text)
                            .size(12.0)
                            .color(Color32::from_rgb(255, 214, 140)),
                    )
                    .wrap()
                    .selectable(false),
                )
                .on_hover_text(
                    "The viewport leaves part of the lighting out. These switches are kept \
                     across restarts; turn them back on in the toolbar.",
                );
            });
    });
}
