//! What the viewport's gizmos are made of: light markers, the scene camera's frustum,
//! the translate, rotate and scale gizmos of the selection, and the spotlight's cone,
//! built as screen-space elements (each maybe a grabbable handle); `paint.rs` paints
//! them. The math is in [`crate::gizmo`]; this file only projects.

use egui::{Color32, Pos2, Vec2};
use glam::DVec3;

use super::camera::{camera_elements, shows_scene_camera};
use super::element::{AXIS_COLOURS, Element, Part, dot, line};
use super::lights::{SpotCone, light_elements, spot_handles};
use super::projection::ViewMapping;
use crate::gizmo::transform_drag::{TranslateHandle, euler_ring_axes, world_axis};
use crate::gizmo::view::object_axes;
use crate::gizmo::{GizmoMode, HandleId};
use crate::scene::tree::{object_at, world_from_parent};
use crate::scene::{Light, Scene, Transform};
use crate::ui::commands::Selection;

/// Length of the translate and scale arrows, in screen points.
const ARROW_PX: f64 = 84.0;
/// Radius of the rotate rings, in screen points.
const RING_PX: f64 = 72.0;

/// Every element of the viewport's gizmos for this scene, selection and mode, in
/// painting order.
#[must_use]
pub fn gizmo_elements(
    scene: &Scene,
    selection: &Selection,
    mode: GizmoMode,
    view: &ViewMapping,
) -> Vec<Element> {
    let mut out = Vec::new();
    let selected_light = match selection {
        Selection::Light(i) => Some(*i),
        _ => None,
    };
    let camera_selected = *selection == Selection::Camera;
    camera_elements(&mut out, view, &scene.camera, camera_selected);
    for (index, light) in scene.lights.iter().enumerate() {
        light_elements(&mut out, view, index, light, selected_light == Some(index));
    }
    match selection {
        Selection::Object(_) | Selection::Part(_) => {
            let path = selection.node_path().unwrap_or_default();
            if let Some(Transform::Trs(trs)) =
                object_at(&scene.objects, &path).map(|o| &o.transform)
            {
                // A part moves in its parent's space: its handles follow the parent's axes.
                let view = &view.framed(world_from_parent(&scene.objects, &path));
                let size = view.world_per_point(trs.translate);
                match mode {
                    GizmoMode::Translate => translate_elements(&mut out, view, trs.translate, size),
                    GizmoMode::Rotate => rotate_elements(&mut out, view, trs, size),
                    GizmoMode::Scale => scale_elements(&mut out, view, trs, size),
                }
            }
        }
        Selection::Light(index) => {
            if let Some(Light::Point { position, .. } | Light::Spot { position, .. }) =
                scene.lights.get(*index)
            {
                let size = view.world_per_point(*position);
                translate_elements(&mut out, view, *position, size);
            }
            if let Some(Light::Spot {
                position,
                direction,
                angle_deg,
                ..
            }) = scene.lights.get(*index)
            {
                let cone = SpotCone {
                    position: *position,
                    direction: *direction,
                    angle_deg: *angle_deg,
                };
                spot_handles(&mut out, view, cone);
            }
        }
        Selection::Camera if shows_scene_camera(view, &scene.camera) => {
            let eye = scene.camera.position;
            translate_elements(&mut out, view, eye, view.world_per_point(eye));
        }
        _ => {}
    }
    out
}

/// Three axis arrows and three plane handles at `origin`; `size` is world units per point.
fn translate_elements(out: &mut Vec<Element>, view: &ViewMapping, origin: DVec3, size: f64) {
    let length = ARROW_PX * size;
    for (normal, colour) in AXIS_COLOURS.iter().enumerate() {
        let (a, b) = (world_axis(normal + 1), world_axis(normal + 2));
        let corners = [(0.28, 0.28), (0.5, 0.28), (0.5, 0.5), (0.28, 0.5)]
            .map(|(s, t)| view.project(origin + (a * s + b * t) * length));
        if let [Some(p0), Some(p1), Some(p2), Some(p3)] = corners
            && quad_area([p0, p1, p2, p3]) > 30.0
        {
            out.push(Element {
                part: Part::Quad([p0, p1, p2, p3]),
                colour: *colour,
                handle: Some(HandleId::Translate(TranslateHandle::Plane(normal))),
            });
        }
    }
    for (axis, colour) in AXIS_COLOURS.iter().enumerate() {
        let direction = world_axis(axis);
        if let (Some(from), Some(to)) = (
            view.project(origin + direction * length * 0.18),
            view.project(origin + direction * length),
        ) && from.distance(to) > 10.0
        {
            out.push(Element {
                part: Part::Arrow(from, to),
                colour: *colour,
                handle: Some(HandleId::Translate(TranslateHandle::Axis(axis))),
            });
        }
    }
    if let Some(p) = view.project(origin) {
        dot(out, p, 3.5, Color32::WHITE, None);
    }
}

/// Three rings about the Euler axes of `trs`.
fn rotate_elements(out: &mut Vec<Element>, view: &ViewMapping, trs: &crate::scene::Trs, size: f64) {
    let radius = RING_PX * size;
    for (i, axis) in euler_ring_axes(trs.rotate_deg).iter().enumerate() {
        let u = crate::gizmo::spot::perpendicular(*axis);
        let v = axis.normalize().cross(u);
        let points: Option<Vec<Pos2>> = (0..72)
            .map(|k| {
                let phi = f64::from(k) * std::f64::consts::TAU / 72.0;
                view.project(trs.translate + (u * phi.cos() + v * phi.sin()) * radius)
            })
            .collect();
        if let Some(points) = points {
            out.push(Element {
                part: Part::Loop(points),
                colour: AXIS_COLOURS[i],
                handle: Some(HandleId::Ring(i)),
            });
        }
    }
    if let Some(p) = view.project(trs.translate) {
        dot(out, p, 3.5, Color32::WHITE, None);
    }
}

/// Handles along the object's own axes, ending in squares.
fn scale_elements(out: &mut Vec<Element>, view: &ViewMapping, trs: &crate::scene::Trs, size: f64) {
    let length = ARROW_PX * size;
    for (i, axis) in object_axes(trs.rotate_deg).iter().enumerate() {
        if let (Some(from), Some(to)) = (
            view.project(trs.translate + *axis * length * 0.18),
            view.project(trs.translate + *axis * length),
        ) && from.distance(to) > 10.0
        {
            line(out, from, to, AXIS_COLOURS[i], Some(HandleId::Scale(i)));
            out.push(Element {
                part: Part::Quad(square(to, 5.0)),
                colour: AXIS_COLOURS[i],
                handle: Some(HandleId::Scale(i)),
            });
        }
    }
    if let Some(p) = view.project(trs.translate) {
        dot(out, p, 3.5, Color32::WHITE, None);
    }
}

fn square(centre: Pos2, half: f32) -> [Pos2; 4] {
    [
        centre + Vec2::new(-half, -half),
        centre + Vec2::new(half, -half),
        centre + Vec2::new(half, half),
        centre + Vec2::new(-half, half),
    ]
}

fn quad_area(q: [Pos2; 4]) -> f32 {
    let cross = |a: Pos2, b: Pos2| a.x * b.y - a.y * b.x;
    0.5 * (0..4)
        .map(|i| cross(q[i], q[(i + 1) % 4]))
        .sum::<f32>()
        .abs()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::MatrixRows;
    use egui::Rect;

    fn scene_and_view() -> (Scene, ViewMapping) {
        let scene = crate::ui::document::files::default_scene();
        let picture = Rect::from_min_size(Pos2::new(100.0, 50.0), Vec2::new(400.0, 300.0));
        let view = ViewMapping::new(&scene.camera, picture);
        (scene, view)
    }

    fn handles(elements: &[Element]) -> Vec<HandleId> {
        elements.iter().filter_map(|e| e.handle).collect()
    }

    #[test]
    fn a_selected_spotlight_has_tip_and_rim_handles_and_lights_have_markers() {
        let (scene, view) = scene_and_view();
        let elements = gizmo_elements(&scene, &Selection::Light(3), GizmoMode::Rotate, &view);
        let handles = handles(&elements);
        for wanted in [
            HandleId::SpotTip,
            HandleId::SpotRim,
            HandleId::Marker(1),
            HandleId::Marker(2),
            HandleId::Marker(3),
            HandleId::Translate(TranslateHandle::Axis(0)),
        ] {
            assert!(handles.contains(&wanted), "{wanted:?}");
        }
        assert!(
            !handles.contains(&HandleId::Marker(0)),
            "ambient has no place"
        );
        assert!(!handles.contains(&HandleId::Ring(0)), "lights only move");
    }

    #[test]
    fn a_directional_lights_arrow_is_faint_unless_the_light_is_selected() {
        let (mut scene, view) = scene_and_view();
        scene.lights.push(Light::Directional {
            direction: glam::DVec3::new(0.3, -1.0, -0.2),
            colour: glam::DVec3::ONE,
            intensity: 1.0,
        });
        let sun = scene.lights.len() - 1;
        let arrow_alpha = |selection: &Selection| {
            gizmo_elements(&scene, selection, GizmoMode::Translate, &view)
                .iter()
                .find(|e| {
                    e.handle == Some(HandleId::Marker(sun)) && matches!(e.part, Part::Arrow(..))
                })
                .map(|e| e.colour.a())
                .expect("the sun's arrow is drawn")
        };
        assert_eq!(arrow_alpha(&Selection::Light(sun)), 255);
        assert!(
            arrow_alpha(&Selection::None) <= 80,
            "over the objects it lights, the arrow is faint: {}",
            arrow_alpha(&Selection::None)
        );
    }

    #[test]
    fn each_mode_shows_its_handles_and_a_matrix_transform_none() {
        let (mut scene, view) = scene_and_view();
        let select = Selection::Object(1);
        let only = |mode| {
            let elements = gizmo_elements(&scene, &select, mode, &view);
            handles(&elements)
                .into_iter()
                .filter(|h| !matches!(h, HandleId::Marker(_)))
                .collect::<Vec<_>>()
        };
        assert!(
            only(GizmoMode::Translate).contains(&HandleId::Translate(TranslateHandle::Plane(1)))
        );
        assert!(only(GizmoMode::Rotate).contains(&HandleId::Ring(2)));
        assert!(only(GizmoMode::Scale).contains(&HandleId::Scale(0)));
        let rows: MatrixRows = scene.objects[1].transform.to_rows();
        scene.objects[1].transform = Transform::Matrix(rows);
        let elements = gizmo_elements(&scene, &select, GizmoMode::Translate, &view);
        assert!(
            handles(&elements)
                .iter()
                .all(|h| matches!(h, HandleId::Marker(_)))
        );
    }
}
