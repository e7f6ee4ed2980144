//! The comparison view that takes the viewport's place: a toolbar, the two pictures in
//! the chosen mode (nearest-pixel, zoomed and panned together, the highlighted
//! explanation's pixels painted over them), and the explanation list below. A click
//! inspects the pixel under the pointer; the pixel inspector then shows both pictures'
//! values there.

use egui::{Align2, Color32, CornerRadius, FontId, PointerButton, Pos2, Rect, Sense, Stroke, Vec2};

use super::bar::compare_bar_ui;
use super::explanations::explanations_ui;
use super::mode::{CompareMode, Side};
use super::session::CompareSession;
use super::textures::CompareTextures;
use super::view::split_at;
use crate::scene::Scene;
use crate::ui::commands::Command;
use crate::ui::viewport::picture::letterbox;

/// Accessible name of the comparison picture, for tests and screen readers.
pub const COMPARE_PICTURE_LABEL: &str = "Comparison picture";

/// Space between the two pictures side by side, in points.
const SIDE_GAP: f32 = 8.0;

/// The frames the pictures fill in `outer`: one, or two side by side.
#[must_use]
pub fn picture_frames(mode: CompareMode, outer: Rect, aspect: f32) -> Vec<Rect> {
    let inner = outer.shrink(16.0);
    if mode == CompareMode::SideBySide {
        let half = (inner.width() - SIDE_GAP) / 2.0;
        let left = Rect::from_min_size(inner.min, Vec2::new(half, inner.height()));
        let right = left.translate(Vec2::new(half + SIDE_GAP, 0.0));
        vec![letterbox(left, aspect), letterbox(right, aspect)]
    } else {
        vec![letterbox(inner, aspect)]
    }
}

/// Shows the comparison view in `ui` (the central panel).
pub fn compare_view_ui(
    ui: &mut egui::Ui,
    session: &mut CompareSession,
    scene: &Scene,
    commands: &mut Vec<Command>,
) {
    egui::Panel::top("compare bar").show(ui, |ui| {
        compare_bar_ui(ui, session, scene, commands);
    });
    // As tall as its explanations need (measured last frame), so a dozen read without
    // scrolling; past 60% of the view the list scrolls, leaving the pictures room.
    let needed_id = egui::Id::unique("compare explanations height");
    let needed = ui.data(|d| d.get_temp::<f32>(needed_id)).unwrap_or(190.0);
    let height = needed.min(ui.available_height() * 0.6).max(90.0);
    let measured = egui::Panel::bottom("compare explanations")
        .resizable(false)
        .exact_size(height)
        .show(ui, |ui| {
            ui.add_space(4.0);
            // The panel's margins and the space above, beside what the list measured.
            let margins = height - ui.available_height() + 4.0;
            margins + explanations_ui(ui, session, scene, commands)
        })
        .inner;
    if (measured - needed).abs() > 0.5 {
        ui.data_mut(|d| d.insert_temp(needed_id, measured));
        ui.ctx().request_repaint();
    }
    let outer = ui.available_rect_before_wrap();
    pictures_ui(ui, outer, session, commands);
}

fn pictures_ui(
    ui: &mut egui::Ui,
    outer: Rect,
    session: &mut CompareSession,
    commands: &mut Vec<Command>,
) {
    let ctx = ui.ctx().clone();
    let highlighted = session.highlighted();
    let (mode, view, swipe) = (session.mode, session.view, session.swipe);
    let side = shown_side(ui, session);
    let Some(compared) = session.compared_mut() else {
        return;
    };
    let c = &compared.comparison;
    let (width, height) = (c.width, c.height);
    let textures = compared
        .textures
        .get_or_insert_with(|| CompareTextures::new(&ctx, c));
    let painter = ui.painter_at(outer);
    painter.rect_filled(outer, CornerRadius::ZERO, Color32::from_gray(14));
    let frames = picture_frames(mode, outer, width as f32 / height.max(1) as f32);
    let uv = view.uv_rect();
    let image = |texture: &egui::TextureHandle, rect: Rect, uv: Rect| {
        painter.image(texture.id(), rect, uv, Color32::WHITE);
    };
    let swipe_x = frames[0].min.x + swipe * frames[0].width();
    match mode {
        CompareMode::Swipe => {
            let [(left, uv_left), (right, uv_right)] = split_at(frames[0], uv, swipe_x);
            image(&textures.raylab, left, uv_left);
            image(&textures.other, right, uv_right);
        }
        CompareMode::SideBySide => {
            image(&textures.raylab, frames[0], uv);
            image(&textures.other, frames[1], uv);
        }
        CompareMode::Difference => image(&textures.difference, frames[0], uv),
        CompareMode::Flip => {
            let texture = match side {
                Side::Raylab => &textures.raylab,
                Side::Other => &textures.other,
            };
            image(texture, frames[0], uv);
        }
    }
    let most = textures.difference_most;
    if let Some(mask) = textures.highlight(&ctx, c, highlighted) {
        for &frame in &frames {
            painter.image(mask.id(), frame, uv, Color32::WHITE);
        }
    }
    for &frame in &frames {
        painter.rect_stroke(
            frame,
            CornerRadius::ZERO,
            Stroke::new(1.0, Color32::from_gray(50)),
            egui::StrokeKind::Outside,
        );
    }
    let labels: Vec<(Pos2, Align2, String)> = match mode {
        CompareMode::Swipe => vec![
            (frames[0].left_top(), Align2::LEFT_TOP, "raylab".to_owned()),
            (
                frames[0].right_top(),
                Align2::RIGHT_TOP,
                "other image".to_owned(),
            ),
        ],
        CompareMode::SideBySide => vec![
            (frames[0].left_top(), Align2::LEFT_TOP, "raylab".to_owned()),
            (
                frames[1].left_top(),
                Align2::LEFT_TOP,
                "other image".to_owned(),
            ),
        ],
        CompareMode::Difference => vec![(
            frames[0].left_top(),
            Align2::LEFT_TOP,
            format!("difference · white = {most} levels"),
        )],
        CompareMode::Flip => vec![(
            frames[0].left_top(),
            Align2::LEFT_TOP,
            side.name().to_owned(),
        )],
    };
    for (pos, align, text) in labels {
        badge(&painter, pos, align, &text);
    }
    if mode == CompareMode::Swipe {
        let line = Stroke::new(2.0, Color32::from_white_alpha(220));
        painter.vline(swipe_x, frames[0].y_range(), line);
        painter.circle_filled(
            Pos2::new(swipe_x, frames[0].center().y),
            6.0,
            Color32::WHITE,
        );
    }

    let response = ui.allocate_rect(outer, Sense::click_and_drag());
    let label = format!("{COMPARE_PICTURE_LABEL}: {}", mode.label());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, &label));
    interact(ui, &response, &frames, session, (width, height), commands);
    let hovered = response.hover_pos().and_then(|pos| {
        let frame = frames.iter().copied().find(|f| f.contains(pos))?;
        session.view.pixel_at(frame, pos, width, height)
    });
    if let Some(pixel) = hovered
        && let Some(values) = session.pixel_values(pixel)
    {
        let text = format!(
            "({}, {})  raylab {:?}  other {:?}  difference {}",
            pixel.0,
            pixel.1,
            values.raylab_rgb,
            values.other_rgb,
            values
                .raylab_rgb
                .iter()
                .zip(values.other_rgb)
                .map(|(a, b)| a.abs_diff(b))
                .max()
                .unwrap_or(0)
        );
        let pos = outer.left_bottom() + Vec2::new(8.0, -8.0);
        badge(&painter, pos, Align2::LEFT_BOTTOM, &text);
        ui.ctx().set_cursor_icon(egui::CursorIcon::Crosshair);
    }
}

/// The side the flip mode shows now: the chosen one, or every half second the other
/// when flipping by itself.
fn shown_side(ui: &egui::Ui, session: &CompareSession) -> Side {
    if session.mode != CompareMode::Flip || !session.auto_flip {
        return session.flip_side;
    }
    ui.ctx()
        .request_repaint_after(std::time::Duration::from_millis(100));
    let half_seconds = (ui.input(|i| i.time) / AUTO_FLIP_SECONDS) as u64;
    if half_seconds.is_multiple_of(2) {
        session.flip_side
    } else {
        session.flip_side.flipped()
    }
}

/// How long each picture shows when flipping by itself.
const AUTO_FLIP_SECONDS: f64 = 0.5;

/// Scroll zooms about the pointer; a primary drag moves the swipe line (swipe mode) or
/// pans; a secondary or middle drag always pans; a click inspects the pixel; Space flips.
fn interact(
    ui: &egui::Ui,
    response: &egui::Response,
    frames: &[Rect],
    session: &mut CompareSession,
    (width, height): (u32, u32),
    commands: &mut Vec<Command>,
) {
    let pointer = response.hover_pos().or(response.interact_pointer_pos());
    let frame = pointer
        .and_then(|p| frames.iter().copied().find(|f| f.contains(p)))
        .unwrap_or(frames[0]);
    if response.hovered()
        && let Some(pos) = pointer
    {
        let (scroll, pinch) = ui.input(|i| (i.smooth_scroll_delta.y, i.zoom_delta()));
        // One wheel notch (about 50 points) zooms by about 1.13.
        let factor = pinch * (scroll / 400.0).exp();
        if factor != 1.0 {
            session.view.zoom_about(frame, pos, factor);
        }
    }
    let swiping = session.mode == CompareMode::Swipe && response.dragged_by(PointerButton::Primary);
    if swiping && let Some(pos) = response.interact_pointer_pos() {
        session.swipe = ((pos.x - frames[0].min.x) / frames[0].width()).clamp(0.0, 1.0);
    } else if response.dragged() {
        session.view.pan(frame, response.drag_delta());
    }
    if response.clicked()
        && let Some(pos) = response.interact_pointer_pos()
        && let Some(pixel) = session.view.pixel_at(frame, pos, width, height)
    {
        commands.push(Command::InspectPixel(Some(pixel)));
    }
    let space = response.hovered()
        && !ui.ctx().text_edit_focused()
        && ui.input(|i| i.key_pressed(egui::Key::Space));
    if space && session.mode == CompareMode::Flip {
        session.flip_side = session.flip_side.flipped();
    }
}

/// A small dark label at `pos`.
fn badge(painter: &egui::Painter, pos: Pos2, align: Align2, text: &str) {
    let galley = painter.layout_no_wrap(
        text.to_owned(),
        FontId::monospace(11.0),
        Color32::from_gray(230),
    );
    let offset = Vec2::new(
        if align.x() == egui::Align::Max {
            -6.0
        } else {
            6.0
        },
        if align.y() == egui::Align::Max {
            -6.0
        } else {
            6.0
        },
    );
    let rect = align.anchor_size(pos + offset, galley.size());
    painter.rect_filled(
        rect.expand(4.0),
        CornerRadius::same(3),
        Color32::from_black_alpha(170),
    );
    painter.galley(rect.min, galley, Color32::WHITE);
}
