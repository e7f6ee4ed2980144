//! The gizmo vocabulary: which gizmo the selection shows, and the handles one can grab.

use super::transform_drag::TranslateHandle;

/// Which gizmo the selected object shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum GizmoMode {
    /// Axis arrows and plane handles.
    #[default]
    Translate,
    /// Rings about the Euler axes.
    Rotate,
    /// Handles along the object's own axes.
    Scale,
}

/// A grabbable part of a gizmo.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HandleId {
    /// Moves the selected object or light.
    Translate(TranslateHandle),
    /// Changes Euler angle 0, 1 or 2 of the selected object.
    Ring(usize),
    /// Changes scale component 0, 1 or 2 of the selected object.
    Scale(usize),
    /// Re-aims the selected spotlight.
    SpotTip,
    /// Changes the selected spotlight's angle.
    SpotRim,
    /// Re-aims the selected directional light.
    Aim,
    /// The marker of light `i` (a click selects it).
    Marker(usize),
    /// The scene camera's frustum, drawn from the view camera (a click selects it).
    CameraMarker,
}
