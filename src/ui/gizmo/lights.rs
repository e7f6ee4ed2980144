//! The light gizmos: a marker per light (a click selects it; dimmed while the light is
//! muted or another is solo, with mute and solo buttons beside the selected or isolated
//! ones), a selected spotlight's cone with its tip and rim handles, and a directional
//! light's arrow with its aim handle.

use egui::{Color32, CornerRadius, Pos2, Rect, UiBuilder, Vec2};
use glam::DVec3;

use super::element::{CONE_COLOUR, Element, Part, dot, line};
use super::projection::{ViewMapping, sun_tail};
use crate::gizmo::HandleId;
use crate::gizmo::spot::{rim_handle, rim_points, rim_radial, tip_point};
use crate::scene::{Light, Scene};
use crate::trace::Isolation;
use crate::ui::commands::{Command, Selection};
use crate::ui::state::IsolationToggle;
use crate::ui::state::light_label;

/// How much of a directional light's arrow shows while the light is not selected.
pub(super) const UNSELECTED_ARROW_OPACITY: f32 = 0.3;

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
                let cone = SpotCone {
                    position,
                    direction,
                    angle_deg,
                };
                cone_wireframe(out, view, cone);
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
                    // Unselected, the arrow is faint: it sits over the objects it lights.
                    colour: colour.gamma_multiply(if selected {
                        1.0
                    } else {
                        UNSELECTED_ARROW_OPACITY
                    }),
                    handle: Some(HandleId::Marker(index)),
                });
                if selected {
                    dot(out, from, 6.5, CONE_COLOUR, Some(HandleId::Aim));
                }
            }
        }
    }
}

/// Dims the markers of the lights that do not shine under `isolation`.
pub(super) fn dim_unlit_markers(elements: &mut [Element], isolation: &Isolation) {
    for element in elements {
        if let Some(HandleId::Marker(i)) = element.handle
            && !isolation.is_light_lit(i)
        {
            element.colour = element.colour.gamma_multiply(0.3);
        }
    }
}

/// Where each light's marker is on screen: a point or spot light's dot, the head of a
/// directional light's arrow (ambient lights have none).
fn marker_positions(elements: &[Element]) -> Vec<(usize, Pos2)> {
    elements
        .iter()
        .filter_map(|e| match (e.handle, &e.part) {
            (Some(HandleId::Marker(i)), Part::Dot(p, _) | Part::Arrow(_, p)) => Some((i, *p)),
            _ => None,
        })
        .collect()
}

/// Mute and solo buttons beside the marker of the selected light and of every muted or
/// solo one (so the state shows in the picture); Ctrl- or Shift-click on solo adds.
/// `canvas` is where the gizmo is drawn (the picture and the margin around it).
pub(super) fn marker_toggles_ui(
    ui: &mut egui::Ui,
    canvas: Rect,
    elements: &[Element],
    scene: &Scene,
    selection: &Selection,
    isolation: &Isolation,
    commands: &mut Vec<Command>,
) {
    let builder = UiBuilder::new().max_rect(canvas);
    ui.scope_builder(builder, |ui| {
        ui.set_clip_rect(canvas);
        for (index, at) in marker_positions(elements) {
            let muted = isolation.muted_lights.contains(&index);
            let solo = isolation.solo_lights.contains(&index);
            let Some(light) = scene.lights.get(index) else {
                continue;
            };
            if !(muted || solo || *selection == Selection::Light(index)) {
                continue;
            }
            let label = light_label(light, index);
            let size = Vec2::new(20.0, 18.0);
            let mute_rect = Rect::from_min_size(at + Vec2::new(9.0, -size.y - 4.0), size);
            let solo_rect = mute_rect.translate(Vec2::new(size.x + 2.0, 0.0));
            // On a backing of their own: over a bright picture, or over the "not the full
            // picture" marker, the letters stay readable and nothing shows through.
            for rect in [mute_rect, solo_rect] {
                ui.painter()
                    .rect_filled(rect, CornerRadius::same(3), Color32::from_gray(28));
            }
            let mute = egui::Button::selectable(muted, "M").small();
            if ui
                .put(mute_rect, mute)
                .accessible_name(format!("mute {label} (marker)"))
                .on_hover_text("Mute: render without this light")
                .clicked()
            {
                commands.push(Command::Isolate(IsolationToggle::Mute(index)));
            }
            let solo_button = egui::Button::selectable(solo, "S").small();
            if ui
                .put(solo_rect, solo_button)
                .accessible_name(format!("solo {label} (marker)"))
                .on_hover_text("Solo: only this light (Ctrl- or Shift-click: several)")
                .clicked()
            {
                let add = ui.input(|i| i.modifiers.command || i.modifiers.shift);
                commands.push(Command::Isolate(IsolationToggle::Solo {
                    light: index,
                    add,
                }));
            }
        }
    });
}

/// A light's colour as a marker colour: its hue, bright enough to see.
fn light_colour(light: &Light) -> Color32 {
    let c = light.colour();
    let peak = c.max_element();
    let c = if peak > 0.0 { c / peak } else { DVec3::ONE };
    let channel = |v: f64| (155.0 + 100.0 * v.clamp(0.0, 1.0)) as u8;
    Color32::from_rgb(channel(c.x), channel(c.y), channel(c.z))
}

/// A spotlight's cone in world space: apex, axis and half-angle.
#[derive(Clone, Copy, Debug)]
pub(super) struct SpotCone {
    /// The apex: the light's position.
    pub position: DVec3,
    /// The axis (not necessarily unit length).
    pub direction: DVec3,
    /// The half-angle in degrees.
    pub angle_deg: f64,
}

/// The cone of a selected spotlight: rim circle, silhouette and axis.
fn cone_wireframe(out: &mut Vec<Element>, view: &ViewMapping, cone: SpotCone) {
    let SpotCone {
        position,
        direction,
        angle_deg,
    } = cone;
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
        if let Some(edge) = rim_edge(view, cone, side) {
            line(out, apex, edge, CONE_COLOUR, None);
        }
    }
    if let Some(tip) = view.project(tip_point(position, direction, length)) {
        line(out, apex, tip, CONE_COLOUR.gamma_multiply(0.6), None);
    }
}

/// The tip and rim handles of a selected spotlight, drawn over everything else.
pub(super) fn spot_handles(out: &mut Vec<Element>, view: &ViewMapping, cone: SpotCone) {
    let length = view.cone_length();
    if let Some(rim) = rim_edge(view, cone, 1.0) {
        dot(out, rim, 6.5, CONE_COLOUR, Some(HandleId::SpotRim));
    }
    if let Some(tip) = view.project(tip_point(cone.position, cone.direction, length)) {
        dot(out, tip, 6.5, CONE_COLOUR, Some(HandleId::SpotTip));
    }
}

/// Where the cone's silhouette edge meets the rim on screen, on the side `side` (1 or -1)
/// of the rim handle's radial direction.
fn rim_edge(view: &ViewMapping, cone: SpotCone, side: f64) -> Option<Pos2> {
    let radial = rim_radial(cone.direction, cone.position - view.eye()) * side;
    view.project(rim_handle(
        cone.position,
        cone.direction,
        radial,
        cone.angle_deg,
        view.cone_length(),
    ))
}
