//! The viewport's gizmo adapter: reads the picture's response, picks handles, turns
//! drags into scene edits (always computed from the values at the drag's start, so the
//! point under the cursor stays under it) and pushes them as commands. A drag holds the
//! mouse button, so the app records one undo step for the whole gesture.

use egui::{CursorIcon, Id, Key, Modifiers, PointerButton, Pos2, Rect, Response};
use glam::{DVec2, DVec3};

use super::camera_navigation::{CameraDrag, drag_camera, frame_selection, zoom_with_wheel};
use super::commands::{Command, SceneEdit, Selection};
use super::gizmo_overlay::{
    GizmoMode, HandleId, Part, ViewMapping, cone_length, gizmo_elements, handle_shapes,
    paint_elements, paint_matrix_hint, paint_readout, sun_anchor,
};
use super::gizmo_toolbar::{ToolbarAction, toolbar_ui};
use crate::gizmo::handles::{HandleShape, pick_handle};
use crate::gizmo::snap::{ROTATE_STEP_DEG, SCALE_STEP, TRANSLATE_STEP, snap};
use crate::gizmo::spot::{aim_from_tip_drag, angle_from_rim_drag, rim_radial};
use crate::gizmo::transform_drag::{
    TranslateHandle, euler_ring_axes, rotate_drag, scale_drag, translate_drag,
};
use crate::gizmo::view::object_axes;
use crate::scene::{Light, Object, Scene, Transform, Trs};
use crate::trace::Ray;

/// What a handle drag started on, as it was then.
#[derive(Clone, Debug, PartialEq)]
pub enum Grabbed {
    /// An object with a translate/rotate/scale transform.
    Object(usize, Object, Trs),
    /// A light.
    Light(usize, Light),
}

/// Fixed sizes of a handle drag, taken at its start.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DragGeometry {
    /// The camera's eye.
    pub eye: DVec3,
    /// The spotlight cone's slant length.
    pub cone_length: f64,
    /// A directional light's arrow: the point it ends at and its length.
    pub sun: (DVec3, f64),
}

/// A handle drag's result: the edit and the value to show while dragging.
#[derive(Clone, Debug, PartialEq)]
pub struct DragEdit {
    /// The edit to push.
    pub edit: SceneEdit,
    /// What changed, for the readout ("angle 30.0°").
    pub readout: String,
}

/// The edit of dragging `handle` of `grabbed` from the pointer ray `start` to `now`;
/// `snapped` rounds the changed values to the snapping steps. `None` when the drag is
/// degenerate this frame (a ray parallel to the axis or plane): keep the last value.
#[must_use]
pub fn drag_edit(
    handle: HandleId,
    grabbed: &Grabbed,
    geometry: &DragGeometry,
    start: &Ray,
    now: &Ray,
    snapped: bool,
) -> Option<DragEdit> {
    match grabbed {
        Grabbed::Object(index, object, trs) => {
            let trs = object_drag(handle, trs, start, now, snapped)?;
            let readout = object_readout(handle, &trs);
            let mut object = object.clone();
            object.transform = Transform::Trs(trs);
            Some(DragEdit {
                edit: SceneEdit::SetObject(*index, object),
                readout,
            })
        }
        Grabbed::Light(index, light) => {
            let (light, readout) = light_drag(handle, light, geometry, start, now, snapped)?;
            Some(DragEdit {
                edit: SceneEdit::SetLight(*index, light),
                readout,
            })
        }
    }
}

/// The new position after a translate drag of a gizmo at `origin`.
fn moved(
    handle: TranslateHandle,
    origin: DVec3,
    start: &Ray,
    now: &Ray,
    snapped: bool,
) -> Option<DVec3> {
    let mut p = origin + translate_drag(handle, origin, start, now)?;
    if snapped {
        for i in 0..3 {
            let moves = match handle {
                TranslateHandle::Axis(axis) => i == axis,
                TranslateHandle::Plane(normal) => i != normal,
            };
            if moves {
                p[i] = snap(p[i], TRANSLATE_STEP);
            }
        }
    }
    p.is_finite().then_some(p)
}

fn object_drag(handle: HandleId, trs: &Trs, start: &Ray, now: &Ray, snapped: bool) -> Option<Trs> {
    let mut trs = *trs;
    match handle {
        HandleId::Translate(t) => trs.translate = moved(t, trs.translate, start, now, snapped)?,
        HandleId::Ring(i) => {
            let axis = euler_ring_axes(trs.rotate_deg)[i];
            let mut angle = trs.rotate_deg[i] + rotate_drag(trs.translate, axis, start, now)?;
            if snapped {
                angle = snap(angle, ROTATE_STEP_DEG);
            }
            trs.rotate_deg[i] = angle;
        }
        HandleId::Scale(i) => {
            let axis = object_axes(trs.rotate_deg)[i];
            let factor = scale_drag(trs.translate, axis, start, now)?;
            // No mirroring or collapsing: the object keeps at least a hundredth of its size.
            let mut value = trs.scale[i] * factor.max(0.01);
            if snapped {
                value = snap(value, SCALE_STEP);
                if value == 0.0 {
                    value = SCALE_STEP.copysign(trs.scale[i]);
                }
            }
            trs.scale[i] = value;
        }
        HandleId::SpotTip | HandleId::SpotRim | HandleId::Aim | HandleId::Marker(_) => {
            return None;
        }
    }
    (trs.translate.is_finite() && trs.rotate_deg.is_finite() && trs.scale.is_finite())
        .then_some(trs)
}

fn object_readout(handle: HandleId, trs: &Trs) -> String {
    const AXES: [&str; 3] = ["x", "y", "z"];
    match handle {
        HandleId::Ring(i) => format!("rotate {} {:.1}°", AXES[i], trs.rotate_deg[i]),
        HandleId::Scale(i) => format!("scale {} {:.2}", AXES[i], trs.scale[i]),
        _ => format_point(trs.translate),
    }
}

fn format_point(p: DVec3) -> String {
    format!("({:.2}, {:.2}, {:.2})", p.x, p.y, p.z)
}

fn light_drag(
    handle: HandleId,
    light: &Light,
    geometry: &DragGeometry,
    start: &Ray,
    now: &Ray,
    snapped: bool,
) -> Option<(Light, String)> {
    let mut light = light.clone();
    let readout = match (&mut light, handle) {
        (Light::Point { position, .. } | Light::Spot { position, .. }, HandleId::Translate(t)) => {
            *position = moved(t, *position, start, now, snapped)?;
            format_point(*position)
        }
        (
            Light::Spot {
                position,
                direction,
                ..
            },
            HandleId::SpotTip,
        ) => {
            let aim = aim_from_tip_drag(*position, geometry.cone_length, now)?;
            *direction = aim * direction.length().max(f64::MIN_POSITIVE);
            format_direction(aim)
        }
        (
            Light::Spot {
                position,
                direction,
                angle_deg,
                ..
            },
            HandleId::SpotRim,
        ) => {
            let radial = rim_radial(*direction, *position - geometry.eye);
            let mut angle = angle_from_rim_drag(*position, *direction, radial, now)
                .filter(|a| a.is_finite())?;
            if snapped {
                angle = snap(angle, ROTATE_STEP_DEG).clamp(
                    crate::gizmo::spot::MIN_ANGLE_DEG,
                    crate::gizmo::spot::MAX_ANGLE_DEG,
                );
            }
            *angle_deg = angle;
            format!("angle {angle:.1}°")
        }
        (Light::Directional { direction, .. }, HandleId::Aim) => {
            let (anchor, length) = geometry.sun;
            // The handle is the arrow's tail: the light comes from there.
            let tail = aim_from_tip_drag(anchor, length, now)?;
            *direction = -tail * direction.length().max(f64::MIN_POSITIVE);
            format_direction(-tail)
        }
        _ => return None,
    };
    Some((light, readout))
}

fn format_direction(d: DVec3) -> String {
    format!("direction ({:.2}, {:.2}, {:.2})", d.x, d.y, d.z)
}

/// A drag in progress.
#[derive(Clone, Debug)]
enum Drag {
    Handle {
        handle: HandleId,
        grabbed: Box<Grabbed>,
        geometry: DragGeometry,
        start: Pos2,
    },
    Camera {
        drag: CameraDrag,
        start: Pos2,
    },
}

/// The gizmos' state between frames (egui's temporary memory).
#[derive(Clone, Debug, Default)]
struct GizmoState {
    mode: GizmoMode,
    drag: Option<Drag>,
    readout: Option<String>,
}

/// What the selection is, as a handle drag would take it.
fn grab(scene: &Scene, selection: &Selection, handle: HandleId) -> Option<Grabbed> {
    match (selection, handle) {
        (_, HandleId::Marker(_)) => None,
        (Selection::Object(i), _) => {
            let object = scene.objects.get(*i)?;
            match &object.transform {
                Transform::Trs(trs) => Some(Grabbed::Object(*i, object.clone(), *trs)),
                Transform::Matrix(_) => None,
            }
        }
        (Selection::Light(i), _) => Some(Grabbed::Light(*i, scene.lights.get(*i)?.clone())),
        _ => None,
    }
}

fn to_dvec(p: Pos2) -> DVec2 {
    DVec2::new(f64::from(p.x), f64::from(p.y))
}

/// Draws the gizmos over the picture and handles their input and camera navigation.
/// Returns whether a click was taken (a light marker or handle), so the viewport does
/// not also pick an object under it.
pub fn gizmo_ui(
    ui: &mut egui::Ui,
    response: &Response,
    picture: Rect,
    scene: &Scene,
    selection: &Selection,
    commands: &mut Vec<Command>,
) -> bool {
    let ctx = ui.ctx().clone();
    let id = Id::unique("raylab gizmo");
    let mut state: GizmoState = ctx.data(|d| d.get_temp(id)).unwrap_or_default();

    if !ctx.text_edit_focused() {
        let keys = [
            (Key::W, GizmoMode::Translate),
            (Key::E, GizmoMode::Rotate),
            (Key::R, GizmoMode::Scale),
        ];
        for (key, mode) in keys {
            if ctx.input_mut(|i| i.consume_key(Modifiers::NONE, key)) {
                state.mode = mode;
            }
        }
        if ctx.input_mut(|i| i.consume_key(Modifiers::NONE, Key::F)) {
            frame_selection(scene, selection, commands);
        }
    }

    let view = ViewMapping::new(scene, picture);
    let elements = gizmo_elements(scene, selection, state.mode, &view);
    let shapes = handle_shapes(&elements);
    let hit_shapes: Vec<HandleShape> = shapes.iter().map(|(s, _)| *s).collect();
    let pick = |pos: Pos2| pick_handle(to_dvec(pos), &hit_shapes).map(|k| shapes[k].1);

    let modifiers = ctx.input(|i| i.modifiers);
    if response.drag_started() {
        let start = ctx
            .input(|i| i.pointer.press_origin())
            .or_else(|| response.interact_pointer_pos());
        if let Some(start) = start {
            state.drag = start_drag(response, scene, selection, &view, modifiers, start, pick);
        }
    }
    let now = ctx.input(|i| i.pointer.latest_pos());
    if let (Some(drag), Some(now)) = (&state.drag, now)
        && (response.dragged() || response.drag_stopped())
    {
        state.readout = continue_drag(drag, &view, now, modifiers.shift, picture, commands);
    }
    let mut took_click = false;
    if response.clicked()
        && let Some(pos) = response.interact_pointer_pos()
    {
        match pick(pos) {
            Some(HandleId::Marker(i)) => {
                commands.push(Command::Select(Selection::Light(i)));
                took_click = true;
            }
            Some(_) => took_click = true,
            None => {}
        }
    }
    if response.hovered() {
        zoom_with_wheel(&ctx, scene, commands);
    }

    // Paint, with the dragged or hovered handle highlighted.
    let dragged_handle = match &state.drag {
        Some(Drag::Handle { handle, .. }) => Some(*handle),
        _ => None,
    };
    let hot = dragged_handle.or_else(|| response.hover_pos().and_then(pick));
    let painter = ui.painter_at(picture);
    paint_elements(&painter, &elements, hot);
    if let Selection::Object(i) = selection
        && let Some(object) = scene.objects.get(*i)
        && matches!(object.transform, Transform::Matrix(_))
        && let Some(p) = view.project(object.transform.world_from_object().translation)
    {
        paint_matrix_hint(&painter, p);
    }
    if let (Some(text), Some(pos)) = (&state.readout, now)
        && state.drag.is_some()
    {
        paint_readout(&painter, pos, text);
    } else if let Selection::Light(i) = selection
        && let Some(Light::Spot { angle_deg, .. }) = scene.lights.get(*i)
        && let Some(rim) = elements.iter().find_map(|e| match e.part {
            Part::Dot(p, _) if e.handle == Some(HandleId::SpotRim) => Some(p),
            _ => None,
        })
    {
        // The cone's angle beside its rim handle.
        paint_readout(&painter, rim, &format!("{angle_deg:.1}°"));
    }
    match (&state.drag, hot) {
        (Some(Drag::Camera { .. }), _) => ctx.set_cursor_icon(CursorIcon::AllScroll),
        (Some(Drag::Handle { .. }), _) => ctx.set_cursor_icon(CursorIcon::Grabbing),
        (None, Some(HandleId::Marker(_))) => ctx.set_cursor_icon(CursorIcon::PointingHand),
        (None, Some(_)) => ctx.set_cursor_icon(CursorIcon::Grab),
        (None, None) => {}
    }

    match toolbar_ui(ui, picture, &mut state.mode) {
        Some(ToolbarAction::Frame) => frame_selection(scene, selection, commands),
        None => {}
    }

    if response.drag_stopped() || !ctx.input(|i| i.pointer.any_down()) {
        state.drag = None;
        state.readout = None;
    }
    ctx.data_mut(|d| d.insert_temp(id, state));
    took_click
}

/// What a drag starting at `start` does: a handle drag on a handle (unless Alt orbits),
/// a pan with the middle button or Shift, an orbit otherwise.
fn start_drag(
    response: &Response,
    scene: &Scene,
    selection: &Selection,
    view: &ViewMapping,
    modifiers: Modifiers,
    start: Pos2,
    pick: impl Fn(Pos2) -> Option<HandleId>,
) -> Option<Drag> {
    let camera = scene.camera.clone();
    if response.drag_started_by(PointerButton::Middle) {
        return Some(Drag::Camera {
            drag: CameraDrag::Pan(camera),
            start,
        });
    }
    if !modifiers.alt
        && let Some(handle) = pick(start)
        && let Some(grabbed) = grab(scene, selection, handle)
    {
        let geometry = DragGeometry {
            eye: scene.camera.position,
            cone_length: cone_length(scene),
            sun: sun_anchor(scene, view),
        };
        return Some(Drag::Handle {
            handle,
            grabbed: Box::new(grabbed),
            geometry,
            start,
        });
    }
    let drag = if modifiers.shift && !modifiers.alt {
        CameraDrag::Pan(camera)
    } else {
        CameraDrag::Orbit(camera)
    };
    Some(Drag::Camera { drag, start })
}

/// Pushes the edit of a drag now at `now`; returns the readout to show.
fn continue_drag(
    drag: &Drag,
    view: &ViewMapping,
    now: Pos2,
    snapped: bool,
    picture: Rect,
    commands: &mut Vec<Command>,
) -> Option<String> {
    match drag {
        Drag::Handle {
            handle,
            grabbed,
            geometry,
            start,
        } => {
            let edit = drag_edit(
                *handle,
                grabbed,
                geometry,
                &view.ray(*start),
                &view.ray(now),
                snapped,
            )?;
            commands.push(Command::Edit(edit.edit));
            Some(edit.readout)
        }
        Drag::Camera { drag, start } => {
            drag_camera(drag, *start, now, picture.height(), commands);
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::PinholeCamera;

    fn scene() -> Scene {
        super::super::files::default_scene()
    }

    fn geometry(scene: &Scene) -> DragGeometry {
        DragGeometry {
            eye: scene.camera.position,
            cone_length: cone_length(scene),
            sun: (scene.camera.look_at, 1.0),
        }
    }

    #[test]
    fn snapped_translate_lands_on_whole_units_of_the_moved_axis_only() {
        let scene = scene();
        let camera = PinholeCamera::new(&scene.camera, 800, 600);
        let Transform::Trs(trs) = scene.objects[1].transform else {
            panic!("red ball has a TRS transform");
        };
        let grabbed = Grabbed::Object(1, scene.objects[1].clone(), trs);
        let a = camera.ray(camera.project(trs.translate + DVec3::X * 0.5).unwrap());
        let b = camera.ray(camera.project(trs.translate + DVec3::X * 1.8).unwrap());
        let handle = HandleId::Translate(TranslateHandle::Axis(0));
        let edit = drag_edit(handle, &grabbed, &geometry(&scene), &a, &b, true).unwrap();
        let SceneEdit::SetObject(1, object) = edit.edit else {
            panic!("an object edit");
        };
        let Transform::Trs(moved) = object.transform else {
            panic!("still TRS");
        };
        // -1.7 + 1.3 = -0.4 snaps to 0; y and z stay.
        assert_eq!(moved.translate.x, 0.0);
        assert_eq!(moved.translate.y, trs.translate.y);
        assert_eq!(moved.translate.z, trs.translate.z);
    }

    #[test]
    fn snapped_rotation_and_scale_use_their_steps() {
        let scene = scene();
        let camera = PinholeCamera::new(&scene.camera, 800, 600);
        let Transform::Trs(trs) = scene.objects[2].transform else {
            panic!("mirror ball has a TRS transform");
        };
        let grabbed = Grabbed::Object(2, scene.objects[2].clone(), trs);
        let ray_at = |p: DVec3| camera.ray(camera.project(p).unwrap());
        let c = trs.translate;
        let (a, b) = (ray_at(c + DVec3::X), ray_at(c + DVec3::new(0.8, 0.0, -0.6)));
        let edit = drag_edit(HandleId::Ring(1), &grabbed, &geometry(&scene), &a, &b, true);
        assert!(edit.unwrap().readout.contains("rotate y 30.0°"));
        let (a, b) = (ray_at(c + DVec3::X), ray_at(c + DVec3::X * 1.73));
        let edit = drag_edit(
            HandleId::Scale(0),
            &grabbed,
            &geometry(&scene),
            &a,
            &b,
            true,
        );
        assert_eq!(edit.unwrap().readout, "scale x 1.70");
    }

    #[test]
    fn aiming_a_directional_light_puts_its_tail_under_the_cursor() {
        let scene = scene();
        let camera = PinholeCamera::new(&scene.camera, 800, 600);
        let light = scene.lights[2].clone();
        let grabbed = Grabbed::Light(2, light);
        let wanted = DVec3::new(-1.0, -1.0, -0.5).normalize();
        // The tail on the side of the sphere facing the camera (the one a drag reaches).
        let tail = scene.camera.look_at - wanted;
        let ray = camera.ray(camera.project(tail).unwrap());
        let edit = drag_edit(
            HandleId::Aim,
            &grabbed,
            &geometry(&scene),
            &ray,
            &ray,
            false,
        );
        let Some(DragEdit {
            edit: SceneEdit::SetLight(2, Light::Directional { direction, .. }),
            ..
        }) = edit
        else {
            panic!("a directional light edit");
        };
        assert!(
            (direction.normalize() - wanted).length() < 1e-6,
            "{direction}"
        );
    }
}
