//! What a handle drag does to the scene, in plain functions without egui: from the value
//! at the drag's start, the pointer's ray then and now, and whether Shift snaps, to the
//! scene edit to push and the value to show. The adapter in `gizmo_drag.rs` feeds it.

use glam::{DAffine3, DVec3};

use crate::gizmo::HandleId;
use crate::gizmo::snap::{ROTATE_STEP_DEG, SCALE_STEP, TRANSLATE_STEP, snap};
use crate::gizmo::spot::{
    MAX_ANGLE_DEG, MIN_ANGLE_DEG, aim_from_tip_drag, angle_from_rim_drag, rim_radial, tip_point,
};
use crate::gizmo::transform_drag::{
    TranslateHandle, euler_ring_axes, rotate_drag, scale_drag, translate_drag,
};
use crate::gizmo::view::object_axes;
use crate::scene::tree::{object_at, world_from_parent};
use crate::scene::{Camera, Light, Object, Scene, Transform, Trs};
use crate::trace::Ray;
use crate::ui::commands::{SceneEdit, Selection};

/// What a handle drag started on, as it was then.
#[derive(Clone, Debug, PartialEq)]
pub enum Grabbed {
    /// An object with a translate/rotate/scale transform.
    Object(usize, Object, Trs),
    /// A part of an object tree with such a transform, by path, and the transform from
    /// the world to its parent's space (it moves along its parent's axes).
    Part(Vec<usize>, Object, Trs, DAffine3),
    /// A light.
    Light(usize, Light),
    /// The scene camera (its frustum, seen from the view camera).
    Camera(Camera),
}

/// Fixed sizes of a handle drag, taken at its start.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DragGeometry {
    /// The eye of the camera the viewport shows.
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
        Grabbed::Part(path, object, trs, parent_from_world) => {
            // The drag worked out in the parent's space keeps the grabbed point under
            // the cursor: an affine map keeps points on the pointer's rays on them.
            let (start, now) = (
                start.transformed(parent_from_world),
                now.transformed(parent_from_world),
            );
            let trs = object_drag(handle, trs, &start, &now, snapped)?;
            let readout = object_readout(handle, &trs);
            let mut object = object.clone();
            object.transform = Transform::Trs(trs);
            Some(DragEdit {
                edit: SceneEdit::SetPart(path.clone(), object),
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
        Grabbed::Camera(camera) => {
            let HandleId::Translate(t) = handle else {
                return None;
            };
            // The camera moves as a whole: eye and target together, so it keeps its aim.
            let position = moved(t, camera.position, start, now, snapped)?;
            let camera = Camera {
                position,
                look_at: camera.look_at + (position - camera.position),
                ..camera.clone()
            };
            Some(DragEdit {
                readout: format_point(position),
                edit: SceneEdit::SetCamera(camera),
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
        HandleId::SpotTip
        | HandleId::SpotRim
        | HandleId::Aim
        | HandleId::Marker(_)
        | HandleId::CameraMarker => {
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
            let start_tip = tip_point(*position, *direction, geometry.cone_length);
            let aim = aim_from_tip_drag(*position, start_tip, geometry.eye, now)?;
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
                angle = snap(angle, ROTATE_STEP_DEG).clamp(MIN_ANGLE_DEG, MAX_ANGLE_DEG);
            }
            *angle_deg = angle;
            format!("angle {angle:.1}°")
        }
        (Light::Directional { direction, .. }, HandleId::Aim) => {
            let (anchor, length) = geometry.sun;
            // The handle is the arrow's tail: the light comes from there.
            let start_tail = anchor - direction.normalize() * length;
            let tail = aim_from_tip_drag(anchor, start_tail, geometry.eye, now)?;
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

/// What the selection is, as a handle drag would take it.
pub fn grab(scene: &Scene, selection: &Selection, handle: HandleId) -> Option<Grabbed> {
    match (selection, handle) {
        (_, HandleId::Marker(_) | HandleId::CameraMarker) => None,
        (Selection::Object(i), _) => {
            let object = scene.objects.get(*i)?;
            match &object.transform {
                Transform::Trs(trs) => Some(Grabbed::Object(*i, object.clone(), *trs)),
                Transform::Matrix(_) => None,
            }
        }
        (Selection::Part(path), _) => {
            let object = object_at(&scene.objects, path)?;
            match &object.transform {
                Transform::Trs(trs) => Some(Grabbed::Part(
                    path.clone(),
                    object.clone(),
                    *trs,
                    world_from_parent(&scene.objects, path).inverse(),
                )),
                Transform::Matrix(_) => None,
            }
        }
        (Selection::Light(i), _) => Some(Grabbed::Light(*i, scene.lights.get(*i)?.clone())),
        (Selection::Camera, HandleId::Translate(_)) => Some(Grabbed::Camera(scene.camera.clone())),
        _ => None,
    }
}

#[cfg(test)]
mod tests;
