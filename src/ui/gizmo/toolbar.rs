//! The gizmo mode buttons over the picture's top-left corner: Move (W), Rotate (E),
//! Scale (R) and Frame (F).

use egui::{Color32, CornerRadius, Layout, Rect, RichText, UiBuilder, Vec2};

use crate::gizmo::GizmoMode;

/// What a toolbar click asks for besides a mode change.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ToolbarAction {
    /// Frame the selection.
    Frame,
}

/// The buttons, their key and the mode they pick.
const MODES: [(&str, &str, GizmoMode); 3] = [
    ("Move", "W", GizmoMode::Translate),
    ("Rotate", "E", GizmoMode::Rotate),
    ("Scale", "R", GizmoMode::Scale),
];

/// Shows the toolbar in the picture's corner (below the pass badge); changes `mode`.
/// Returns the action asked for and the rectangle the buttons cover (where a press
/// belongs to them, not to a light marker or handle under them).
pub fn gizmo_modes_ui(
    ui: &mut egui::Ui,
    picture: Rect,
    mode: &mut GizmoMode,
) -> (Option<ToolbarAction>, Option<Rect>) {
    let rect = Rect::from_min_size(
        picture.left_top() + Vec2::new(8.0, 34.0),
        Vec2::new(300.0, 28.0),
    );
    if !picture.contains_rect(rect) {
        return (None, None);
    }
    let mut action = None;
    let mut child = ui.new_child(
        UiBuilder::new()
            .max_rect(rect)
            .layout(Layout::left_to_right(egui::Align::Center)),
    );
    let frame = egui::Frame::new()
        .fill(Color32::from_black_alpha(170))
        .corner_radius(CornerRadius::same(4))
        .inner_margin(3)
        .show(&mut child, |ui| {
            ui.spacing_mut().item_spacing.x = 2.0;
            for (label, key, button_mode) in MODES {
                let clicked = ui
                    .add(egui::Button::selectable(
                        *mode == button_mode,
                        RichText::new(label).size(12.0),
                    ))
                    .on_hover_text(format!("{label} gizmo ({key})"))
                    .clicked();
                if clicked {
                    *mode = button_mode;
                }
            }
            ui.separator();
            if ui
                .add(egui::Button::new(RichText::new("Frame").size(12.0)).frame(false))
                .on_hover_text("Frame the selection (F)")
                .clicked()
            {
                action = Some(ToolbarAction::Frame);
            }
        });
    (action, Some(frame.response.rect))
}
