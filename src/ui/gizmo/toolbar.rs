//! The gizmo mode buttons over the picture's top-left corner: Move (W), Rotate (E),
//! Scale (R), Frame (F), and the camera buttons: Camera view (0) and Set camera from
//! view (Ctrl+Alt+0).

use egui::{Color32, CornerRadius, Layout, Rect, RichText, UiBuilder, Vec2};

use crate::gizmo::GizmoMode;

/// What a toolbar click asks for besides a mode change.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ToolbarAction {
    /// Frame the selection.
    Frame,
    /// Look through the scene camera, or back at the view camera.
    CameraView,
    /// Move the scene camera to the view camera.
    SetSceneCamera,
}

/// Accessible name of the camera view toggle.
pub const CAMERA_VIEW_LABEL: &str = "Camera view";
/// Accessible name of the "set scene camera from view" button.
pub const SET_CAMERA_LABEL: &str = "Set camera from view";

/// The buttons, their key and the mode they pick.
const MODES: [(&str, &str, GizmoMode); 3] = [
    ("Move", "W", GizmoMode::Translate),
    ("Rotate", "E", GizmoMode::Rotate),
    ("Scale", "R", GizmoMode::Scale),
];

/// Shows the toolbar in the picture's corner (below the pass badge); changes `mode`.
/// `camera_view` is whether the viewport looks through the scene camera. Returns the
/// action asked for and the rectangle the buttons cover (where a press belongs to them,
/// not to a light marker or handle under them).
pub fn gizmo_modes_ui(
    ui: &mut egui::Ui,
    picture: Rect,
    mode: &mut GizmoMode,
    camera_view: bool,
) -> (Option<ToolbarAction>, Option<Rect>) {
    let rect = Rect::from_min_size(
        picture.left_top() + Vec2::new(8.0, 34.0),
        Vec2::new(520.0_f32.min(picture.width() - 16.0), 28.0),
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
            ui.separator();
            if ui
                .add(egui::Button::selectable(
                    camera_view,
                    RichText::new(CAMERA_VIEW_LABEL).size(12.0),
                ))
                .on_hover_text("Look through the scene camera: its framing and resolution (0)")
                .clicked()
            {
                action = Some(ToolbarAction::CameraView);
            }
            if !camera_view
                && ui
                    .add(egui::Button::new(RichText::new(SET_CAMERA_LABEL).size(12.0)).frame(false))
                    .on_hover_text("Move the scene camera to this view (Ctrl+Alt+0)")
                    .clicked()
            {
                action = Some(ToolbarAction::SetSceneCamera);
            }
        });
    (action, Some(frame.response.rect))
}
