//! The viewport's gizmo adapter: reads the picture's response, picks handles, turns
//! drags into scene edits with [`crate::ui::gizmo::edit`] (always computed from the values at
//! the drag's start, so the point under the cursor stays under it) and pushes them as
//! commands. A drag holds the mouse button, so the app records one undo step for the
//! whole gesture.

use egui::{CursorIcon, Id, Key, Modifiers, PointerButton, Pos2, Rect, Response};
use glam::DVec2;

use crate::gizmo::gesture::{
    ClickTarget, Cursor, DragKind, DragTarget, Dragging, PressKeys, click_target, cursor, drag_kind,
};
use crate::gizmo::handles::{HandleShape, pick_handle};
use crate::gizmo::{GizmoMode, HandleId};
use crate::scene::{Light, Scene, Transform};
use crate::trace::Isolation;
use crate::ui::commands::{Command, Selection};
use crate::ui::gizmo::edit::{DragGeometry, Grabbed, drag_edit, grab};
use crate::ui::gizmo::element::{Element, Part};
use crate::ui::gizmo::hit::handle_shapes;
use crate::ui::gizmo::lights::{dim_unlit_markers, marker_toggles_ui};
use crate::ui::gizmo::overlay::gizmo_elements;
use crate::ui::gizmo::paint::{paint_elements, paint_matrix_hint, paint_readout};
use crate::ui::gizmo::projection::ViewMapping;
use crate::ui::gizmo::toolbar::{ToolbarAction, gizmo_modes_ui};
use crate::ui::viewport::camera_navigation::{
    CameraDrag, drag_camera, frame_selection, zoom_with_wheel,
};

/// A drag in progress.
#[derive(Clone, Debug)]
enum Drag {
    Handle {
        handle: HandleId,
        grabbed: Box<Grabbed>,
        geometry: DragGeometry,
        start: Pos2,
        /// What was selected when the drag began: the drag edits that item only.
        target: DragTarget<Selection>,
    },
    Camera {
        drag: CameraDrag,
        start: Pos2,
    },
}

impl Drag {
    fn dragging(&self) -> Dragging {
        match self {
            Drag::Handle { .. } => Dragging::Handle,
            Drag::Camera { .. } => Dragging::Camera,
        }
    }
}

/// The gizmos' state between frames (egui's temporary memory).
#[derive(Clone, Debug, Default)]
struct GizmoState {
    mode: GizmoMode,
    drag: Option<Drag>,
    readout: Option<String>,
    /// Where the mode buttons were last frame: presses there are theirs.
    toolbar: Option<Rect>,
}

fn to_dvec(p: Pos2) -> DVec2 {
    DVec2::new(f64::from(p.x), f64::from(p.y))
}

/// What the gizmos are drawn for.
#[derive(Clone, Copy)]
pub struct GizmoInput<'a> {
    /// The scene.
    pub scene: &'a Scene,
    /// The selection.
    pub selection: &'a Selection,
    /// Lights muted or solo (their markers are dimmed), objects hidden.
    pub isolation: &'a Isolation,
    /// Inspect mode: only navigation, no handle.
    pub navigate_only: bool,
    /// Where the gizmo is drawn and grabbed: the viewport around the picture, so a
    /// light's arrows near an edge of the picture run on into the margin, whole.
    pub canvas: Rect,
}

/// A spot light's tip or a directional light's tail being dragged is drawn under the
/// cursor: the light aims through the point there (see
/// [`crate::gizmo::spot::aim_from_tip_drag`]), which may lie off the sphere the handle
/// sits on between drags.
fn follow_the_cursor(elements: &mut [Element], drag: Option<&Drag>, cursor: Option<Pos2>) {
    let (Some(Drag::Handle { handle, .. }), Some(cursor)) = (drag, cursor) else {
        return;
    };
    if !matches!(handle, HandleId::SpotTip | HandleId::Aim) {
        return;
    }
    for element in elements.iter_mut().filter(|e| e.handle == Some(*handle)) {
        if let Part::Dot(at, _) = &mut element.part {
            *at = cursor;
        }
    }
}

/// The target a handle drag started now would have.
fn target_now(scene: &Scene, selection: &Selection) -> DragTarget<Selection> {
    DragTarget {
        selection: selection.clone(),
        objects: scene.objects.len(),
        lights: scene.lights.len(),
    }
}

/// Draws the gizmos over the picture (projected through `view`, the camera the viewport
/// shows) and handles their input and camera navigation. Returns whether a click was
/// taken (a light or camera marker, a handle), so the viewport does not also pick an
/// object under it. With `navigate_only` (inspect mode) no handle can be grabbed or
/// clicked, but the view can still be orbited, panned and zoomed.
pub fn gizmo_ui(
    ui: &mut egui::Ui,
    response: &Response,
    view: &ViewMapping,
    input: GizmoInput,
    commands: &mut Vec<Command>,
) -> bool {
    let GizmoInput {
        scene,
        selection,
        isolation,
        navigate_only,
        canvas,
    } = input;
    let picture = *view.screen_from_image.to();
    let ctx = ui.ctx().clone();
    let id = Id::unique("raylab gizmo");
    let mut state: GizmoState = ctx.data(|d| d.get_temp(id)).unwrap_or_default();
    shortcuts(&ctx, &mut state, scene, selection, view, commands);

    let mut elements = gizmo_elements(scene, selection, state.mode, view);
    dim_unlit_markers(&mut elements, isolation);
    follow_the_cursor(
        &mut elements,
        state.drag.as_ref(),
        ctx.input(|i| i.pointer.latest_pos()),
    );
    let shapes = handle_shapes(&elements);
    let hit_shapes: Vec<HandleShape> = shapes.iter().map(|(s, _)| *s).collect();
    // A marker or handle under the mode buttons must not take their presses.
    let toolbar = state.toolbar;
    let over_toolbar = |pos: Pos2| toolbar.is_some_and(|r| r.expand(2.0).contains(pos));
    let pick = |pos: Pos2| {
        if navigate_only || over_toolbar(pos) {
            return None;
        }
        pick_handle(to_dvec(pos), &hit_shapes).map(|k| shapes[k].1)
    };

    let modifiers = ctx.input(|i| i.modifiers);
    if response.drag_started() {
        let start = ctx
            .input(|i| i.pointer.press_origin())
            .or_else(|| response.interact_pointer_pos());
        if let Some(start) = start.filter(|p| !over_toolbar(*p)) {
            state.drag = Some(start_drag(
                response, scene, selection, view, modifiers, start, pick,
            ));
        }
    }
    if let Some(Drag::Handle { target, .. }) = &state.drag
        && !target.still_applies(&target_now(scene, selection))
    {
        state.drag = None;
    }
    let now = ctx.input(|i| i.pointer.latest_pos());
    if let (Some(drag), Some(now)) = (&state.drag, now)
        && (response.dragged() || response.drag_stopped())
    {
        state.readout = continue_drag(drag, view, now, modifiers.shift, picture, commands);
    }
    let took_click = handle_click(response, pick, commands);
    if response.hovered() {
        zoom_with_wheel(&ctx, &view.shown, commands);
    }

    // Paint, with the dragged or hovered handle highlighted.
    let dragged_handle = match &state.drag {
        Some(Drag::Handle { handle, .. }) => Some(*handle),
        _ => None,
    };
    let hot = dragged_handle.or_else(|| response.hover_pos().and_then(pick));
    let canvas = canvas.union(picture);
    let painter = ui.painter_at(canvas);
    paint_elements(&painter, &elements, hot);
    marker_toggles_ui(ui, canvas, &elements, scene, selection, isolation, commands);
    paint_hints(&painter, &state, now, scene, selection, &elements, view);
    set_cursor(&ctx, cursor(state.drag.as_ref().map(Drag::dragging), hot));

    let camera_view = !crate::ui::gizmo::camera::shows_scene_camera(view, &scene.camera);
    let (action, toolbar) = gizmo_modes_ui(ui, picture, &mut state.mode, camera_view);
    state.toolbar = toolbar;
    match action {
        Some(ToolbarAction::Frame) => frame_selection(scene, selection, view, commands),
        Some(ToolbarAction::CameraView) => commands.push(Command::ToggleCameraView),
        Some(ToolbarAction::SetSceneCamera) => commands.push(Command::SetSceneCameraFromView),
        None => {}
    }

    if response.drag_stopped() || !ctx.input(|i| i.pointer.any_down()) {
        state.drag = None;
        state.readout = None;
    }
    ctx.data_mut(|d| d.insert_temp(id, state));
    took_click
}

/// W, E, R pick the mode and F frames the selection, unless a text field has the keys.
fn shortcuts(
    ctx: &egui::Context,
    state: &mut GizmoState,
    scene: &Scene,
    selection: &Selection,
    view: &ViewMapping,
    commands: &mut Vec<Command>,
) {
    if ctx.text_edit_focused() {
        return;
    }
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
        frame_selection(scene, selection, view, commands);
    }
}

/// A click on a handle: a marker selects its light or the camera; any handle takes the
/// click from the object pick under it. Returns whether it did.
fn handle_click(
    response: &Response,
    pick: impl Fn(Pos2) -> Option<HandleId>,
    commands: &mut Vec<Command>,
) -> bool {
    let Some(handle) = response
        .clicked()
        .then(|| response.interact_pointer_pos())
        .flatten()
        .and_then(pick)
    else {
        return false;
    };
    match click_target(handle) {
        ClickTarget::Light(i) => commands.push(Command::Select(Selection::Light(i))),
        ClickTarget::Camera => commands.push(Command::Select(Selection::Camera)),
        ClickTarget::Nothing => {}
    }
    true
}

/// The hints over the picture: a general matrix's marker, the drag's readout, or a
/// selected spot light's angle beside its rim handle.
fn paint_hints(
    painter: &egui::Painter,
    state: &GizmoState,
    now: Option<Pos2>,
    scene: &Scene,
    selection: &Selection,
    elements: &[Element],
    view: &ViewMapping,
) {
    if let Selection::Object(i) = selection
        && let Some(object) = scene.objects.get(*i)
        && matches!(object.transform, Transform::Matrix(_))
        && let Some(p) = view.project(object.transform.world_from_object().translation)
    {
        paint_matrix_hint(painter, p);
    }
    if let (Some(text), Some(pos)) = (&state.readout, now)
        && state.drag.is_some()
    {
        paint_readout(painter, pos, text);
    } else if let Selection::Light(i) = selection
        && let Some(Light::Spot { angle_deg, .. }) = scene.lights.get(*i)
        && let Some(rim) = elements.iter().find_map(|e| match e.part {
            Part::Dot(p, _) if e.handle == Some(HandleId::SpotRim) => Some(p),
            _ => None,
        })
    {
        paint_readout(painter, rim, &format!("{angle_deg:.1}°"));
    }
}

fn set_cursor(ctx: &egui::Context, cursor: Cursor) {
    let icon = match cursor {
        Cursor::Default => return,
        Cursor::Move => CursorIcon::AllScroll,
        Cursor::Grabbing => CursorIcon::Grabbing,
        Cursor::Grab => CursorIcon::Grab,
        Cursor::Pointing => CursorIcon::PointingHand,
    };
    ctx.set_cursor_icon(icon);
}

/// The drag a press at `start` begins ([`drag_kind`] decides which).
fn start_drag(
    response: &Response,
    scene: &Scene,
    selection: &Selection,
    view: &ViewMapping,
    modifiers: Modifiers,
    start: Pos2,
    pick: impl Fn(Pos2) -> Option<HandleId>,
) -> Drag {
    let keys = PressKeys {
        middle: response.drag_started_by(PointerButton::Middle),
        alt: modifiers.alt,
        shift: modifiers.shift,
    };
    // Only a handle whose target can be grabbed counts (a light marker cannot).
    let grabbed = pick(start).and_then(|h| grab(scene, selection, h).map(|g| (h, g)));
    let camera = view.shown.clone();
    match (drag_kind(keys, grabbed.as_ref().map(|(h, _)| *h)), grabbed) {
        (DragKind::Handle(handle), Some((_, grabbed))) => Drag::Handle {
            handle,
            grabbed: Box::new(grabbed),
            geometry: DragGeometry {
                eye: view.eye(),
                cone_length: view.cone_length(),
                sun: view.sun_anchor(),
            },
            start,
            target: target_now(scene, selection),
        },
        (DragKind::Pan, _) => Drag::Camera {
            drag: CameraDrag::Pan(camera),
            start,
        },
        _ => Drag::Camera {
            drag: CameraDrag::Orbit(camera),
            start,
        },
    }
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
            ..
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
