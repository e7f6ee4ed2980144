//! What the viewport writes around and over the picture: the header strip (which camera
//! is shown, at what size), the pass badge and render error, and the selection's ring.

use egui::{Align2, Color32, CornerRadius, FontId, Pos2, Rect, Stroke, Vec2};

use super::preview_link::PreviewLink;
use crate::preview::Pass;
use crate::scene::{Camera, Scene};
use crate::ui::commands::Selection;
use crate::ui::gizmo::projection::ViewMapping;

/// Height of the strip above the toolbar.
pub const HEADER_HEIGHT: f32 = 28.0;

/// The strip above the toolbar: which camera the picture is from, its size, samples and
/// depth.
pub fn header_ui(
    ui: &mut egui::Ui,
    header: Rect,
    scene: &Scene,
    shown: &Camera,
    camera_view: bool,
) {
    let painter = ui.painter_at(header);
    painter.rect_filled(header, CornerRadius::ZERO, Color32::from_gray(24));
    painter.hline(
        header.x_range(),
        header.max.y - 0.5,
        Stroke::new(1.0, Color32::from_gray(40)),
    );
    let title = if camera_view {
        "VIEWPORT · CAMERA VIEW"
    } else {
        "VIEWPORT · VIEW CAMERA"
    };
    painter.text(
        header.left_center() + Vec2::new(10.0, 0.0),
        Align2::LEFT_CENTER,
        title,
        FontId::proportional(10.0),
        Color32::from_gray(150),
    );
    let size = if camera_view {
        format!("{} × {}", scene.camera.width, scene.camera.height)
    } else {
        format!(
            "view {} × {} (scene camera {} × {})",
            shown.width, shown.height, scene.camera.width, scene.camera.height
        )
    };
    let info = format!(
        "{size}  ·  {} spp  ·  depth {}",
        scene.render.samples_per_pixel, scene.render.max_depth
    );
    painter.text(
        header.right_center() - Vec2::new(10.0, 0.0),
        Align2::RIGHT_CENTER,
        info,
        FontId::proportional(12.0),
        Color32::from_gray(170),
    );
}

/// A small label in the corner: which pass is showing, and the render error if any.
pub fn pass_badge(painter: &egui::Painter, picture: Rect, preview: &PreviewLink) {
    let text = match preview.shown() {
        Some(shown) => match shown.pass {
            Pass::Coarse { divider } => format!("preview 1/{divider}"),
            Pass::Full { target: 1, .. } => "1 sample".to_owned(),
            Pass::Full { samples, target } => format!("{samples}/{target} samples"),
        },
        None => String::new(),
    };
    if !text.is_empty() {
        let pos = picture.left_top() + Vec2::new(8.0, 8.0);
        let galley = painter.layout_no_wrap(text, FontId::monospace(11.0), Color32::from_gray(220));
        let back = Rect::from_min_size(pos, galley.size()).expand(4.0);
        painter.rect_filled(back, CornerRadius::same(3), Color32::from_black_alpha(150));
        painter.galley(pos, galley, Color32::WHITE);
    }
    if let Some(error) = preview.error() {
        let band = Rect::from_min_max(Pos2::new(picture.min.x, picture.max.y - 28.0), picture.max);
        painter.rect_filled(
            band,
            CornerRadius::ZERO,
            Color32::from_rgba_unmultiplied(120, 20, 20, 220),
        );
        painter.text(
            band.left_center() + Vec2::new(8.0, 0.0),
            Align2::LEFT_CENTER,
            format!("Cannot render: {error}"),
            FontId::proportional(13.0),
            Color32::WHITE,
        );
    }
}

/// A ring at the selected object's origin, with its name.
pub fn selection_marker(
    painter: &egui::Painter,
    view: &ViewMapping,
    scene: &Scene,
    selection: &Selection,
) {
    let Selection::Object(index) = selection else {
        return;
    };
    let Some(object) = scene.objects.get(*index) else {
        return;
    };
    let origin = object.transform.world_from_object().translation;
    let Some(pos) = view.project(origin) else {
        return;
    };
    if !view.screen_from_image.to().contains(pos) {
        return;
    }
    let accent = crate::ui::style::ACCENT;
    painter.circle_stroke(pos, 6.0, Stroke::new(2.0, Color32::from_black_alpha(160)));
    painter.circle_stroke(pos, 5.0, Stroke::new(1.5, accent));
    painter.text(
        pos + Vec2::new(10.0, -10.0),
        Align2::LEFT_BOTTOM,
        &object.name,
        FontId::proportional(12.0),
        accent,
    );
}
