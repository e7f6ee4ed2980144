//! The grabbable shapes of the gizmo elements, for [`crate::gizmo::handles::pick_handle`].

use egui::Pos2;
use glam::DVec2;

use super::element::{Element, Part};
use crate::gizmo::HandleId;
use crate::gizmo::handles::HandleShape;

/// A screen point as a `DVec2`, for the plain hit-test math.
#[must_use]
pub fn dvec(p: Pos2) -> DVec2 {
    DVec2::new(f64::from(p.x), f64::from(p.y))
}

/// The grabbable shapes of `elements`, each with its handle, for
/// [`crate::gizmo::handles::pick_handle`].
#[must_use]
pub fn handle_shapes(elements: &[Element]) -> Vec<(HandleShape, HandleId)> {
    let mut shapes = Vec::new();
    for element in elements {
        let Some(handle) = element.handle else {
            continue;
        };
        match &element.part {
            Part::Line(a, b) | Part::Arrow(a, b) => {
                shapes.push((HandleShape::Segment(dvec(*a), dvec(*b)), handle));
            }
            Part::Loop(points) => {
                for (k, a) in points.iter().enumerate() {
                    let b = points[(k + 1) % points.len()];
                    shapes.push((HandleShape::Segment(dvec(*a), dvec(b)), handle));
                }
            }
            Part::Dot(p, _) => shapes.push((HandleShape::Point(dvec(*p)), handle)),
            Part::Quad(q) => {
                let centre =
                    (q[0].to_vec2() + q[1].to_vec2() + q[2].to_vec2() + q[3].to_vec2()) / 4.0;
                shapes.push((HandleShape::Point(dvec(centre.to_pos2())), handle));
            }
        }
    }
    shapes
}
