//! The central viewport: the preview at the scene's aspect ratio, letterboxed; a click
//! selects the object under the cursor, found with the tracer's own primary ray.

use egui::{Align2, Color32, CornerRadius, FontId, Pos2, Rect, Sense, Stroke, Vec2};
use glam::DVec2;

use crate::preview::Pass;
use crate::scene::Scene;
use crate::trace::{Isolation, PinholeCamera, World};
use crate::ui::commands::{Command, Selection};
use crate::ui::viewport::full_picture_marker::full_picture_marker_ui;
use crate::ui::viewport::isolation::isolation_note;
use crate::ui::viewport::pixel_inspector::inspected_pixel;
use crate::ui::viewport::preview_link::PreviewLink;
use crate::ui::viewport::preview_settings::PreviewSettings;
use crate::ui::viewport::toolbar::toolbar_ui;

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

/// The object whose surface the primary ray of the pixel under `image_point` hits first,
/// hidden objects left out. `image_point` is in the scene's output pixels; the ray goes
/// through that pixel's centre, as the renderer's one-sample pass does.
#[must_use]
pub fn pick_object(scene: &Scene, isolation: &Isolation, image_point: DVec2) -> Option<usize> {
    let (width, height) = (scene.camera.width, scene.camera.height);
    if !(image_point.x >= 0.0
        && image_point.y >= 0.0
        && image_point.x < f64::from(width)
        && image_point.y < f64::from(height))
    {
        return None;
    }
    let world = World::isolated(scene, isolation).ok()?;
    let pixel_centre = image_point.floor() + DVec2::splat(0.5);
    crate::trace::pick(&world, width, height, pixel_centre)
}

/// Shows the viewport and pushes a selection when the picture is clicked.
pub fn viewport_ui(
    ui: &mut egui::Ui,
    scene: &Scene,
    preview: Option<&PreviewLink>,
    selection: &Selection,
    settings: &PreviewSettings,
    isolation: &Isolation,
    commands: &mut Vec<Command>,
) {
    let full = ui.available_rect_before_wrap();
    let header = Rect::from_min_size(full.min, Vec2::new(full.width(), HEADER_HEIGHT));
    header_ui(ui, header, scene);
    let non_finite = preview
        .and_then(PreviewLink::frame)
        .map(|f| f.non_finite_samples);
    let isolated = isolation_note(isolation, scene);
    let bar_height = toolbar_ui(
        ui,
        header.left_bottom(),
        full.width(),
        settings,
        non_finite,
        isolated.as_deref(),
        commands,
    );
    let outer = Rect::from_min_max(Pos2::new(full.min.x, header.max.y + bar_height), full.max);
    ui.painter()
        .rect_filled(outer, CornerRadius::ZERO, Color32::from_gray(14));
    let aspect = scene.camera.width as f32 / scene.camera.height.max(1) as f32;
    let picture = letterbox(outer.shrink(16.0), aspect);
    let response = ui.allocate_rect(picture, Sense::click_and_drag());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, VIEWPORT_LABEL));
    let painter = ui.painter_at(outer);
    let texture = preview.and_then(PreviewLink::texture);
    match texture {
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
    if let Some(preview) = preview {
        pass_badge(&painter, picture, preview);
    }
    selection_marker(&painter, picture, scene, selection);
    full_picture_marker_ui(ui, picture, &settings.not_full_picture_reasons());
    if response.hovered() {
        ui.ctx().set_cursor_icon(egui::CursorIcon::Crosshair);
    }
    // Inspect mode (the toolbar's toggle, or Alt held): a click, or moving with Alt held
    // and no button down, inspects the pixel under the pointer instead of selecting.
    // Alt+drag still orbits the camera through the gizmo layer.
    let alt = ui.input(|i| i.modifiers.alt);
    let inspecting = settings.inspect || alt;
    let gizmo_took_click = !settings.inspect
        && crate::ui::gizmo::drag::gizmo_ui(
            ui, &response, picture, scene, selection, isolation, commands,
        );
    if inspecting {
        let moved = alt
            && response.hovered()
            && ui.input(|i| i.pointer.delta() != Vec2::ZERO && !i.pointer.any_down());
        let pos = if (response.clicked() && !gizmo_took_click) || moved {
            response.interact_pointer_pos().or(response.hover_pos())
        } else {
            None
        };
        if let Some(pixel) =
            pos.and_then(|p| inspected_pixel(scene, image_from_screen(picture, scene, p)))
        {
            commands.push(Command::InspectPixel(Some(pixel)));
        }
    }
    if let Some(pos) = response
        .interact_pointer_pos()
        .filter(|_| response.clicked() && !inspecting && !gizmo_took_click)
    {
        let image_point = image_from_screen(picture, scene, pos);
        let selection =
            pick_object(scene, isolation, image_point).map_or(Selection::None, Selection::Object);
        commands.push(Command::Select(selection));
    }
}

/// Height of the strip above the picture (where the term toolbar will go).
const HEADER_HEIGHT: f32 = 28.0;

/// The strip above the picture: title, output size, samples and depth.
fn header_ui(ui: &mut egui::Ui, header: Rect, scene: &Scene) {
    let painter = ui.painter_at(header);
    painter.rect_filled(header, CornerRadius::ZERO, Color32::from_gray(24));
    painter.hline(
        header.x_range(),
        header.max.y - 0.5,
        Stroke::new(1.0, Color32::from_gray(40)),
    );
    let info = format!(
        "{} × {}  ·  {} spp  ·  depth {}",
        scene.camera.width,
        scene.camera.height,
        scene.render.samples_per_pixel,
        scene.render.max_depth
    );
    let info = painter.layout_no_wrap(info, FontId::proportional(12.0), Color32::from_gray(170));
    let title = painter.layout_no_wrap(
        "VIEWPORT".to_owned(),
        FontId::proportional(10.0),
        Color32::from_gray(150),
    );
    // A narrow viewport drops the title rather than print the two over each other.
    if title.size().x + info.size().x + 40.0 <= header.width() {
        let pos = header.left_center() + Vec2::new(10.0, -title.size().y / 2.0);
        painter.galley(pos, title, Color32::from_gray(150));
    }
    let pos = header.right_center() - Vec2::new(10.0 + info.size().x, info.size().y / 2.0);
    painter.galley(pos, info, Color32::from_gray(170));
}

/// Scene output pixels of a screen position over the picture.
fn image_from_screen(picture: Rect, scene: &Scene, pos: Pos2) -> DVec2 {
    let u = f64::from((pos.x - picture.min.x) / picture.width());
    let v = f64::from((pos.y - picture.min.y) / picture.height());
    DVec2::new(
        u * f64::from(scene.camera.width),
        v * f64::from(scene.camera.height),
    )
}

/// The screen position of scene output pixel coordinates.
fn screen_from_image(picture: Rect, scene: &Scene, p: DVec2) -> Pos2 {
    Pos2::new(
        picture.min.x + (p.x / f64::from(scene.camera.width)) as f32 * picture.width(),
        picture.min.y + (p.y / f64::from(scene.camera.height)) as f32 * picture.height(),
    )
}

/// A small label in the corner: which pass is showing, and the render error if any.
fn pass_badge(painter: &egui::Painter, picture: Rect, preview: &PreviewLink) {
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
fn selection_marker(painter: &egui::Painter, picture: Rect, scene: &Scene, selection: &Selection) {
    let Selection::Object(index) = selection else {
        return;
    };
    let Some(object) = scene.objects.get(*index) else {
        return;
    };
    let camera = PinholeCamera::new(&scene.camera, scene.camera.width, scene.camera.height);
    let origin = object.transform.world_from_object().translation;
    let Some(p) = camera.project(origin) else {
        return;
    };
    let pos = screen_from_image(picture, scene, p);
    if !picture.contains(pos) {
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

    #[test]
    fn picking_uses_the_primary_ray_of_the_pixel() {
        let scene = crate::ui::document::files::default_scene();
        let camera = PinholeCamera::new(&scene.camera, scene.camera.width, scene.camera.height);
        for name in ["red ball", "blue box", "gold cone"] {
            let index = scene.objects.iter().position(|o| o.name == name).unwrap();
            // A point inside each shape (the cone's origin is its apex, so go up its axis).
            let inside = glam::DVec3::new(0.0, 0.0, if name == "gold cone" { 0.8 } else { 0.0 });
            let centre = scene.objects[index]
                .transform
                .world_from_object()
                .transform_point3(inside);
            let p = camera.project(centre).unwrap();
            assert_eq!(
                pick_object(&scene, &Isolation::NONE, p),
                Some(index),
                "{name}"
            );
        }
        let none = Isolation::NONE;
        assert_eq!(pick_object(&scene, &none, DVec2::new(-1.0, 5.0)), None);
        assert_eq!(
            pick_object(&scene, &none, DVec2::new(400.0, 2.0)),
            None,
            "sky"
        );
    }
}
