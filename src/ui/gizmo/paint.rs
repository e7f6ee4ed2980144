//! Painting the gizmo elements over the preview: dark-edged lines so they read on any
//! picture, the handle under the pointer highlighted, readouts on dark chips.

use egui::{Align2, Color32, FontId, Pos2, Rect, Shape, Stroke, Vec2};

use crate::gizmo::HandleId;
use crate::ui::gizmo::element::{Element, HOT_COLOUR, Part};

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
    let pos = readout_pos(at, galley.size(), painter.clip_rect());
    let back = Rect::from_min_size(pos, galley.size()).expand(4.0);
    painter.rect_filled(back, 3.0, Color32::from_black_alpha(190));
    painter.galley(pos, galley, Color32::WHITE);
}

/// Where a readout of `size` goes: above and right of the cursor at `at`, moved inside
/// `bounds` (the picture) so that a drag near an edge does not clip its label.
#[must_use]
pub fn readout_pos(at: Pos2, size: Vec2, bounds: Rect) -> Pos2 {
    let inner = bounds.shrink(5.0);
    let wanted = at + Vec2::new(14.0, -24.0);
    Pos2::new(
        wanted.x.min(inner.max.x - size.x).max(inner.min.x),
        wanted.y.max(inner.min.y).min(inner.max.y - size.y),
    )
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_readout_near_an_edge_stays_inside_the_picture() {
        let picture = Rect::from_min_size(Pos2::new(100.0, 50.0), Vec2::new(400.0, 300.0));
        let size = Vec2::new(90.0, 14.0);
        for at in [
            Pos2::new(495.0, 200.0),
            Pos2::new(105.0, 52.0),
            Pos2::new(499.0, 349.0),
        ] {
            let label = Rect::from_min_size(readout_pos(at, size, picture), size).expand(4.0);
            assert!(picture.contains_rect(label), "{at:?}: {label:?}");
        }
        // Away from the edges it sits where it always did, up and right of the cursor.
        let middle = Pos2::new(300.0, 200.0);
        assert_eq!(
            readout_pos(middle, size, picture),
            middle + Vec2::new(14.0, -24.0)
        );
    }
}
