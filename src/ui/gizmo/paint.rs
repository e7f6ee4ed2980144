//! Painting the gizmo elements over the preview: dark-edged lines so they read on any
//! picture, the handle under the pointer highlighted, readouts on dark chips.

use egui::{Align2, Color32, FontId, Pos2, Rect, Shape, Stroke, Vec2};

use crate::gizmo::HandleId;
use crate::ui::gizmo::overlay::{Element, HOT_COLOUR, Part};

/// Paints the elements; `hot` is the handle under the pointer or being dragged.
pub fn paint_elements(painter: &egui::Painter, elements: &[Element], hot: Option<HandleId>) {
    let shadow = Color32::from_black_alpha(140);
    for element in elements {
        let is_hot = hot.is_some() && element.handle == hot;
        let colour = if is_hot { HOT_COLOUR } else { element.colour };
        let width = if is_hot { 3.0 } else { 2.0 };
        match &element.part {
            Part::Line(a, b) => {
                painter.line_segment([*a, *b], Stroke::new(width + 1.5, shadow));
                painter.line_segment([*a, *b], Stroke::new(width, colour));
            }
            Part::Arrow(a, b) => arrow(painter, *a, *b, width, colour, shadow),
            Part::Loop(points) => {
                painter.add(Shape::closed_line(
                    points.clone(),
                    Stroke::new(width + 1.5, shadow),
                ));
                painter.add(Shape::closed_line(
                    points.clone(),
                    Stroke::new(width, colour),
                ));
            }
            Part::Dot(p, radius) => {
                let radius = if is_hot { radius + 1.5 } else { *radius };
                painter.circle(*p, radius, colour, Stroke::new(1.5, shadow));
            }
            Part::Quad(q) => {
                let fill = if is_hot {
                    HOT_COLOUR.gamma_multiply(0.8)
                } else {
                    colour.gamma_multiply(0.55)
                };
                painter.add(Shape::convex_polygon(
                    q.to_vec(),
                    fill,
                    Stroke::new(1.0, colour),
                ));
            }
        }
    }
}

fn arrow(painter: &egui::Painter, a: Pos2, b: Pos2, width: f32, colour: Color32, shadow: Color32) {
    let along = (b - a).normalized();
    let across = along.rot90();
    let head = 11.0;
    let base = b - along * head;
    painter.line_segment([a, base], Stroke::new(width + 1.5, shadow));
    painter.line_segment([a, base], Stroke::new(width, colour));
    painter.add(Shape::convex_polygon(
        vec![b, base + across * head * 0.42, base - across * head * 0.42],
        colour,
        Stroke::new(1.0, shadow),
    ));
}

/// A readout next to the pointer or a handle: white text on a dark chip.
pub fn paint_readout(painter: &egui::Painter, at: Pos2, text: &str) {
    let galley = painter.layout_no_wrap(
        text.to_owned(),
        FontId::monospace(12.0),
        Color32::from_gray(240),
    );
    let pos = at + Vec2::new(14.0, -24.0);
    let back = Rect::from_min_size(pos, galley.size()).expand(4.0);
    painter.rect_filled(back, 3.0, Color32::from_black_alpha(190));
    painter.galley(pos, galley, Color32::WHITE);
}

/// A hint for an object with a general matrix transform, which has no gizmo.
pub fn paint_matrix_hint(painter: &egui::Painter, at: Pos2) {
    painter.text(
        at + Vec2::new(10.0, 8.0),
        Align2::LEFT_TOP,
        "Matrix transform: no gizmo (reset it to translate/rotate/scale in the inspector)",
        FontId::proportional(12.0),
        Color32::from_gray(220),
    );
}
