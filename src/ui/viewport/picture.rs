//! The central viewport: the preview picture, from the view camera at the viewport's own
//! size or, in camera view, from the scene camera at its aspect ratio (letterboxed),
//! with the gizmos, the ray-path overlay and the clicks that select or inspect.

use egui::{Align2, Color32, CornerRadius, FontId, Pos2, Rect, Sense, Stroke, Vec2};

use super::clicks::{inspected_anchor, picture_clicks};
use super::exchange::{ViewportInput, ViewportOutput};
use super::full_picture_marker::full_picture_marker_ui;
use super::marks::{HEADER_HEIGHT, header_ui, pass_badge, selection_marker};
use super::pixel_inspector::PixelAnchor;
use super::preview_link::PreviewLink;
use super::ray_paths::{ray_path_controls_ui, ray_paths_ui, screen_segments};
use super::toolbar::toolbar_ui;
use crate::ui::commands::Command;
use crate::ui::gizmo::drag::GizmoInput;
use crate::ui::gizmo::projection::ViewMapping;
use crate::ui::state::free_render_size;
use crate::ui::state::isolation_note;

/// Accessible name of the picture, for tests and screen readers.
pub const VIEWPORT_LABEL: &str = "Viewport";

/// The largest rectangle of aspect `width / height` centred in `outer`.
#[must_use]
pub fn letterbox(outer: Rect, aspect: f32) -> Rect {
    let size = if outer.width() / outer.height().max(1.0) > aspect {
        Vec2::new(outer.height() * aspect, outer.height())
    } else {
        Vec2::new(outer.width(), outer.width() / aspect)
    };
    Rect::from_center_size(outer.center(), size)
}

/// Shows the viewport and pushes the commands of its clicks, drags and controls.
pub fn viewport_ui(
    ui: &mut egui::Ui,
    input: &ViewportInput,
    commands: &mut Vec<Command>,
) -> ViewportOutput {
    let scene = input.scene;
    let full = ui.available_rect_before_wrap();
    let header = Rect::from_min_size(full.min, Vec2::new(full.width(), HEADER_HEIGHT));
    let non_finite = input
        .preview
        .and_then(PreviewLink::frame)
        .map(|f| f.non_finite_samples);
    let isolated = isolation_note(input.isolation, scene);
    let bar_height = toolbar_ui(
        ui,
        header.left_bottom(),
        full.width(),
        input.settings,
        non_finite,
        isolated.as_deref(),
        commands,
    );
    let outer = Rect::from_min_max(Pos2::new(full.min.x, header.max.y + bar_height), full.max);
    let region = outer.shrink(16.0);
    let free_size = free_render_size(region.width(), region.height(), ui.ctx().pixels_per_point());
    let shown = input.view.shown(&scene.camera, free_size);
    header_ui(ui, header, scene, &shown, input.view.through_scene_camera);
    ui.painter()
        .rect_filled(outer, CornerRadius::ZERO, Color32::from_gray(14));
    let aspect = shown.width as f32 / shown.height.max(1) as f32;
    let picture = letterbox(region, aspect);
    let view = ViewMapping::new(&shown, picture);
    // The margin around the picture takes gizmo and camera drags (a handle drawn past the
    // picture's edge is grabbed there); the picture, added after, takes its own area.
    let margin = ui.interact(
        outer,
        egui::Id::unique("raylab viewport margin"),
        Sense::click_and_drag(),
    );
    let response = ui.allocate_rect(picture, Sense::click_and_drag());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, VIEWPORT_LABEL));
    let painter = ui.painter_at(outer);
    picture_ui(&painter, picture, input.preview);
    if let Some(preview) = input.preview {
        pass_badge(&painter, picture, preview);
    }
    selection_marker(&painter, &view, scene, input.selection);
    full_picture_marker_ui(ui, picture, &input.settings.not_full_picture_reasons());
    let shown_view = input.settings.switches.shown_view(input.settings.view);
    super::legend::view_legend_ui(ui, picture, shown_view, scene);
    if response.hovered() {
        ui.ctx().set_cursor_icon(egui::CursorIcon::Crosshair);
    }
    let gizmo_took_click = crate::ui::gizmo::drag::gizmo_ui(
        ui,
        &response.union(margin),
        &view,
        GizmoInput {
            scene,
            selection: input.selection,
            isolation: input.isolation,
            navigate_only: input.settings.inspect,
            canvas: outer,
        },
        commands,
    );
    let segments = screen_segments(
        &view,
        scene,
        input.inspections,
        input.ray_paths,
        input.inspected,
    );
    ray_paths_ui(
        ui,
        &ui.painter_at(picture),
        &segments,
        scene,
        input.inspections,
        response.hover_pos(),
    );
    if input.inspected.is_some() || !input.ray_paths.pinned.is_empty() {
        ray_path_controls_ui(ui, picture, input.ray_paths, commands);
    }
    picture_clicks(ui, &response, &view, input, gizmo_took_click, commands);
    ViewportOutput {
        free_size,
        anchor: input.inspected.and_then(|pixel| {
            inspected_anchor(&view, scene, input.inspections, pixel).map(|pos| PixelAnchor {
                pos,
                viewport: outer,
                screen: ui.ctx().content_rect(),
            })
        }),
    }
}

/// The preview texture, or a placeholder while there is none.
fn picture_ui(painter: &egui::Painter, picture: Rect, preview: Option<&PreviewLink>) {
    match preview.and_then(PreviewLink::texture) {
        Some(texture) => {
            let uv = Rect::from_min_max(Pos2::ZERO, Pos2::new(1.0, 1.0));
            painter.image(texture.id(), picture, uv, Color32::WHITE);
        }
        None => {
            painter.rect_filled(picture, CornerRadius::ZERO, Color32::from_gray(24));
            let text = if preview.is_some() {
                "Rendering…"
            } else {
                "Preview off"
            };
            painter.text(
                picture.center(),
                Align2::CENTER_CENTER,
                text,
                FontId::proportional(16.0),
                Color32::from_gray(140),
            );
        }
    }
    painter.rect_stroke(
        picture,
        CornerRadius::ZERO,
        Stroke::new(1.0, Color32::from_gray(50)),
        egui::StrokeKind::Outside,
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn letterbox_keeps_the_aspect_and_centres() {
        let outer = Rect::from_min_size(Pos2::ZERO, Vec2::new(400.0, 100.0));
        let r = letterbox(outer, 2.0);
        assert_eq!(r.size(), Vec2::new(200.0, 100.0));
        assert_eq!(r.center(), outer.center());
    }
}
