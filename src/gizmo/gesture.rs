//! What a pointer gesture over the viewport means, decided without egui: which kind of
//! drag a press starts, what a click on a handle selects, which cursor shows, and whether
//! a drag still applies to what it grabbed.

use super::HandleId;

/// The kind of drag a press starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DragKind {
    /// Drags the handle under the press.
    Handle(HandleId),
    /// Pans the view camera.
    Pan,
    /// Orbits the view camera about its target.
    Orbit,
}

/// The buttons and keys held when a drag starts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PressKeys {
    /// The middle button started the drag.
    pub middle: bool,
    /// Alt is held (orbit, even over a handle).
    pub alt: bool,
    /// Shift is held (pan).
    pub shift: bool,
}

/// The drag a press starts: the middle button pans; a handle under the press that can
/// be grabbed is dragged unless Alt is held; otherwise Shift pans and anything else
/// orbits.
#[must_use]
pub fn drag_kind(keys: PressKeys, grabbable_handle: Option<HandleId>) -> DragKind {
    if keys.middle {
        return DragKind::Pan;
    }
    match grabbable_handle {
        Some(handle) if !keys.alt => DragKind::Handle(handle),
        _ if keys.shift && !keys.alt => DragKind::Pan,
        _ => DragKind::Orbit,
    }
}

/// What a click on a handle selects: a light's marker selects the light, the scene
/// camera's frustum the camera; other handles select nothing (the click is theirs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClickTarget {
    /// Light `i`.
    Light(usize),
    /// The scene camera.
    Camera,
    /// Nothing new: the click only stops an object pick under the handle.
    Nothing,
}

/// The target of a click on `handle`.
#[must_use]
pub fn click_target(handle: HandleId) -> ClickTarget {
    match handle {
        HandleId::Marker(i) => ClickTarget::Light(i),
        HandleId::CameraMarker => ClickTarget::Camera,
        _ => ClickTarget::Nothing,
    }
}

/// The pointer's look over the viewport.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cursor {
    /// The system default.
    Default,
    /// Moving the view.
    Move,
    /// A handle held.
    Grabbing,
    /// Over a handle that can be grabbed.
    Grab,
    /// Over a marker a click selects.
    Pointing,
}

/// What the drag in progress (if any) is doing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dragging {
    /// A handle.
    Handle,
    /// The view camera.
    Camera,
}

/// The cursor for a drag in progress, or for the handle under the pointer.
#[must_use]
pub fn cursor(dragging: Option<Dragging>, hot: Option<HandleId>) -> Cursor {
    match (dragging, hot) {
        (Some(Dragging::Camera), _) => Cursor::Move,
        (Some(Dragging::Handle), _) => Cursor::Grabbing,
        (None, Some(HandleId::Marker(_) | HandleId::CameraMarker)) => Cursor::Pointing,
        (None, Some(_)) => Cursor::Grab,
        (None, None) => Cursor::Default,
    }
}

/// What a handle drag was started on: the selection's identity and the sizes of the
/// object and light lists. A delete, an undo or another pick can make the selected index
/// name another item, so the drag ends as soon as any of these changes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DragTarget<S> {
    /// The selection when the drag began.
    pub selection: S,
    /// How many objects there were.
    pub objects: usize,
    /// How many lights there were.
    pub lights: usize,
}

impl<S: PartialEq> DragTarget<S> {
    /// Whether a drag started on `self` still applies now.
    #[must_use]
    pub fn still_applies(&self, now: &DragTarget<S>) -> bool {
        self == now
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gizmo::transform_drag::TranslateHandle;

    const HANDLE: HandleId = HandleId::Scale(0);
    const KEYS: PressKeys = PressKeys {
        middle: false,
        alt: false,
        shift: false,
    };

    #[test]
    fn a_press_on_a_handle_drags_it_unless_alt_or_the_middle_button() {
        assert_eq!(drag_kind(KEYS, Some(HANDLE)), DragKind::Handle(HANDLE));
        let alt = PressKeys { alt: true, ..KEYS };
        assert_eq!(drag_kind(alt, Some(HANDLE)), DragKind::Orbit);
        let middle = PressKeys {
            middle: true,
            ..KEYS
        };
        assert_eq!(drag_kind(middle, Some(HANDLE)), DragKind::Pan);
    }

    #[test]
    fn away_from_handles_shift_pans_and_alt_shift_orbits() {
        assert_eq!(drag_kind(KEYS, None), DragKind::Orbit);
        let shift = PressKeys {
            shift: true,
            ..KEYS
        };
        assert_eq!(drag_kind(shift, None), DragKind::Pan);
        let both = PressKeys {
            shift: true,
            alt: true,
            ..KEYS
        };
        assert_eq!(drag_kind(both, None), DragKind::Orbit);
        // Shift over a handle still drags the handle (Shift snaps it).
        assert_eq!(drag_kind(shift, Some(HANDLE)), DragKind::Handle(HANDLE));
    }

    #[test]
    fn markers_select_and_other_handles_only_take_the_click() {
        assert_eq!(click_target(HandleId::Marker(3)), ClickTarget::Light(3));
        assert_eq!(click_target(HandleId::CameraMarker), ClickTarget::Camera);
        assert_eq!(
            click_target(HandleId::Translate(TranslateHandle::Axis(1))),
            ClickTarget::Nothing
        );
    }

    #[test]
    fn cursors_follow_the_drag_then_the_hot_handle() {
        assert_eq!(cursor(Some(Dragging::Camera), Some(HANDLE)), Cursor::Move);
        assert_eq!(cursor(Some(Dragging::Handle), None), Cursor::Grabbing);
        assert_eq!(cursor(None, Some(HandleId::Marker(0))), Cursor::Pointing);
        assert_eq!(cursor(None, Some(HANDLE)), Cursor::Grab);
        assert_eq!(cursor(None, None), Cursor::Default);
    }

    #[test]
    fn a_drag_ends_when_its_target_changes() {
        let at_start = DragTarget {
            selection: 1,
            objects: 6,
            lights: 4,
        };
        assert!(at_start.still_applies(&at_start.clone()));
        let deleted = DragTarget {
            objects: 5,
            ..at_start.clone()
        };
        assert!(!at_start.still_applies(&deleted));
    }
}
