//! The light gizmos: a marker per light (a click selects it), a selected spotlight's cone
//! with its tip and rim handles, and a directional light's arrow with its aim handle.

use egui::{Color32, Pos2};
use glam::DVec3;

use super::overlay::{CONE_COLOUR, Element, Part, dot, line};
use super::projection::{ViewMapping, sun_tail};
use crate::gizmo::HandleId;
use crate::gizmo::spot::{rim_handle, rim_points, rim_radial, tip_point};
use crate::scene::Light;

/// The marker of one light; a selected spotlight's cone (its handles come later, on top).
pub(super) fn light_elements(
    out: &mut Vec<Element>,
    view: &ViewMapping,
    index: usize,
    light: &Light,
    selected: bool,
) {
    let colour = light_colour(light);
    match *light {
        Light::Ambient { .. } => {}
        Light::Point { position, .. } => {
            if let Some(p) = view.project(position) {
                dot(out, p, 6.0, colour, Some(HandleId::Marker(index)));
            }
        }
        Light::Spot {
            position,
            direction,
            angle_deg,
            ..
        } => {
            if selected {
                cone_wireframe(out, view, position, direction, angle_deg);
            } else if let (Some(p), Some(q)) = (
                view.project(position),
                view.project(
                    position
                        + direction.normalize_or_zero() * view.world_per_point(position) * 22.0,
                ),
            ) {
                line(out, p, q, colour.gamma_multiply(0.8), None);
            }
            if let Some(p) = view.project(position) {
                dot(out, p, 6.0, colour, Some(HandleId::Marker(index)));
            }
        }
        Light::Directional { direction, .. } => {
            let (anchor, length) = view.sun_anchor();
            let tail = sun_tail(anchor, length, direction);
            if let (Some(from), Some(to)) = (view.project(tail), view.project(anchor)) {
                out.push(Element {
                    part: Part::Arrow(from, to),
                    colour: colour.gamma_multiply(if selected { 1.0 } else { 0.7 }),
                    handle: Some(HandleId::Marker(index)),
                });
                if selected {
                    dot(out, from, 6.5, CONE_COLOUR, Some(HandleId::Aim));
                }
            }
        }
    }
}

/// A light's colour as a marker colour: its hue, bright enough to see.
fn light_colour(light: &Light) -> Color32 {
    let c = light.colour();
    let peak = c.max_element();
    let c = if peak > 0.0 { c / peak } else { DVec3::ONE };
    let channel = |v: f64| (155.0 + 100.0 * v.clamp(0.0, 1.0)) as u8;
    Color32::from_rgb(channel(c.x), channel(c.y), channel(c.z))
}

/// The cone of a selected spotlight: rim circle, silhouette and axis.
fn cone_wireframe(
    out: &mut Vec<Element>,
    view: &ViewMapping,
    position: DVec3,
    direction: DVec3,
    angle_deg: f64,
) {
    let length = view.cone_length();
    let rim: Option<Vec<Pos2>> = rim_points(position, direction, angle_deg, length, 64)
        .into_iter()
        .map(|p| view.project(p))
        .collect();
    let Some(apex) = view.project(position) else {
        return;
    };
    if let Some(rim) = rim {
        for k in [0, 16, 32, 48] {
            line(out, apex, rim[k], CONE_COLOUR.gamma_multiply(0.45), None);
        }
        out.push(Element {
            part: Part::Loop(rim),
            colour: CONE_COLOUR,
            handle: None,
        });
    }
    for side in [1.0, -1.0] {
        if let Some(edge) = rim_edge(view, position, direction, angle_deg, side) {
            line(out, apex, edge, CONE_COLOUR, None);
        }
    }
    if let Some(tip) = view.project(tip_point(position, direction, length)) {
        line(out, apex, tip, CONE_COLOUR.gamma_multiply(0.6), None);
    }
}

/// The tip and rim handles of a selected spotlight, drawn over everything else.
pub(super) fn spot_handles(
    out: &mut Vec<Element>,
    view: &ViewMapping,
    position: DVec3,
    direction: DVec3,
    angle_deg: f64,
) {
    let length = view.cone_length();
    if let Some(rim) = rim_edge(view, position, direction, angle_deg, 1.0) {
        dot(out, rim, 6.5, CONE_COLOUR, Some(HandleId::SpotRim));
    }
    if let Some(tip) = view.project(tip_point(position, direction, length)) {
        dot(out, tip, 6.5, CONE_COLOUR, Some(HandleId::SpotTip));
    }
}

/// Where the cone's silhouette edge meets the rim on screen, on the side `side` (1 or -1)
/// of the rim handle's radial direction.
fn rim_edge(
    view: &ViewMapping,
    position: DVec3,
    direction: DVec3,
    angle_deg: f64,
    side: f64,
) -> Option<Pos2> {
    let radial = rim_radial(direction, position - view.eye()) * side;
    view.project(rim_handle(
        position,
        direction,
        radial,
        angle_deg,
        view.cone_length(),
    ))
}
