//! The ray-path overlay's controls, over the picture's bottom-left corner while rays are
//! drawn: a toggle per ray kind, pixel / row / column, and clearing the pins.

use egui::{Color32, CornerRadius, Layout, Rect, RichText, UiBuilder, Vec2};

use crate::ui::commands::Command;
use crate::ui::state::{RayPathSettings, RaySpan};

/// Accessible name of the controls' frame.
pub const RAY_PATHS_LABEL: &str = "Ray paths";

/// Shows the controls in `picture`'s corner; pushes [`Command::SetRayPaths`] on a change.
pub fn ray_path_controls_ui(
    ui: &mut egui::Ui,
    picture: Rect,
    settings: &RayPathSettings,
    commands: &mut Vec<Command>,
) {
    let height = 28.0;
    let rect = Rect::from_min_size(
        picture.left_bottom() + Vec2::new(8.0, -height - 8.0),
        Vec2::new((picture.width() - 16.0).max(0.0), height),
    );
    if !picture.contains_rect(rect) {
        return;
    }
    let mut edited = settings.clone();
    let mut child = ui.new_child(
        UiBuilder::new()
            .max_rect(rect)
            .layout(Layout::left_to_right(egui::Align::Center)),
    );
    egui::Frame::new()
        .fill(Color32::from_black_alpha(170))
        .corner_radius(CornerRadius::same(4))
        .inner_margin(3)
        .show(&mut child, |ui| {
            ui.spacing_mut().item_spacing.x = 3.0;
            ui.label(RichText::new(RAY_PATHS_LABEL).size(12.0).strong());
            let toggles = [
                (&mut edited.primary, "camera", "primary rays"),
                (&mut edited.shadow, "shadow", "shadow rays"),
                (&mut edited.reflection, "mirror", "reflection rays"),
                (&mut edited.transmission, "glass", "transmitted rays"),
                (&mut edited.normals, "normals", "normals"),
            ];
            for (on, text, name) in toggles {
                ui.toggle_value(on, RichText::new(text).size(12.0))
                    .on_hover_text(format!("Draw the {name}"))
                    .accessible_name(name);
            }
            ui.separator();
            for (span, text) in [
                (RaySpan::Pixel, "pixel"),
                (RaySpan::Row, "row"),
                (RaySpan::Column, "column"),
            ] {
                ui.selectable_value(&mut edited.span, span, RichText::new(text).size(12.0))
                    .on_hover_text(format!("Draw the rays of the inspected {text}"))
                    .accessible_name(format!("rays of the {text}"));
            }
            if !edited.pinned.is_empty() {
                ui.separator();
                let count = edited.pinned.len();
                ui.label(RichText::new(format!("{count} pinned")).size(12.0));
                if ui.small_button("Clear pins").clicked() {
                    edited.pinned.clear();
                }
            }
        });
    if edited != *settings {
        commands.push(Command::SetRayPaths(edited));
    }
}
