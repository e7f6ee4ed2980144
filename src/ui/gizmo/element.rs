//! What a gizmo is drawn as: elements (lines, arrows, loops, dots, quads in screen
//! points), each maybe part of a grabbable handle, and the gizmo colours.

use egui::{Color32, Pos2};

use crate::gizmo::HandleId;

/// Colours of the x, y and z handles.
pub const AXIS_COLOURS: [Color32; 3] = [
    Color32::from_rgb(236, 72, 80),
    Color32::from_rgb(118, 206, 62),
    Color32::from_rgb(66, 140, 246),
];
/// The spotlight cone and its handles.
pub const CONE_COLOUR: Color32 = Color32::from_rgb(255, 196, 64);
/// A handle under the pointer or being dragged.
pub const HOT_COLOUR: Color32 = Color32::from_rgb(255, 240, 120);

/// How an element is drawn (screen points).
#[derive(Clone, Debug)]
pub enum Part {
    /// A line.
    Line(Pos2, Pos2),
    /// An arrow from the first point to the second.
    Arrow(Pos2, Pos2),
    /// A closed line through the points.
    Loop(Vec<Pos2>),
    /// A filled dot with an outline.
    Dot(Pos2, f32),
    /// A filled quadrilateral.
    Quad([Pos2; 4]),
}

/// One drawn piece of a gizmo, grabbable when it has a handle.
#[derive(Clone, Debug)]
pub struct Element {
    /// What to draw.
    pub part: Part,
    /// Its colour.
    pub colour: Color32,
    /// The handle it belongs to.
    pub handle: Option<HandleId>,
}

/// Adds a dot of `radius` at `p`.
pub(super) fn dot(
    out: &mut Vec<Element>,
    p: Pos2,
    radius: f32,
    colour: Color32,
    handle: Option<HandleId>,
) {
    out.push(Element {
        part: Part::Dot(p, radius),
        colour,
        handle,
    });
}

/// Adds a line from `a` to `b`.
pub(super) fn line(
    out: &mut Vec<Element>,
    a: Pos2,
    b: Pos2,
    colour: Color32,
    handle: Option<HandleId>,
) {
    out.push(Element {
        part: Part::Line(a, b),
        colour,
        handle,
    });
}
