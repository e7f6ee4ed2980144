//! The outliner's object rows as a tree: a CSG node or a group folds open to show its
//! operands or children (indented, each selectable, with its own menu), to any depth.
//! A row dragged onto a tree node moves into it; onto a leaf, next to it.

use egui::Ui;
use egui::collapsing_header::CollapsingState;

use crate::scene::Object;
use crate::ui::commands::{Command, SceneEdit, Selection};

use super::row::{HIDE_ICON, Row, item_button, item_menu, row_ui, shape_icon, toggle_ui};
use crate::trace::Isolation;
use crate::ui::state::IsolationToggle;

/// What the rows show beside the scene: the selection and the isolation switches.
#[derive(Clone, Copy)]
pub(super) struct Shown<'a> {
    pub(super) selection: &'a Selection,
    pub(super) isolation: &'a Isolation,
}

/// An object row for `object` at `path` (its index alone at the top level), `key` the
/// names of its parents (for the folding state): a plain row for a leaf, a row that
/// folds open for a tree node. `row` draws the row itself (the top level adds its hide
/// toggle); parts below get rows with their own hide toggle.
pub(super) fn node_ui(
    ui: &mut Ui,
    object: &Object,
    path: &[usize],
    key: &str,
    shown: Shown<'_>,
    commands: &mut Vec<Command>,
    row: &mut dyn FnMut(&mut Ui, &mut Vec<Command>),
) {
    let Shown {
        selection,
        isolation,
    } = shown;
    let children = object.shape.children();
    if children.is_empty() {
        row(ui, commands);
        return;
    }
    // Keyed by names, not indices: a node keeps its folding when a move shifts indices.
    let id = ui.make_persistent_id(("outliner node", key, &object.name));
    // A node holding the selection opens, so a part picked in the picture is shown.
    let holds_selection =
        matches!(selection, Selection::Part(p) if p.len() > path.len() && p.starts_with(path));
    let mut state = CollapsingState::load_with_default_open(ui.ctx(), id, false);
    if holds_selection && !state.is_open() {
        state.set_open(true);
    }
    state.show_header(ui, |ui| row(ui, commands)).body(|ui| {
        for (index, child) in children.iter().enumerate() {
            let mut child_path = path.to_vec();
            child_path.push(index);
            let target = Selection::Part(child_path.clone());
            let mut child_row = |ui: &mut Ui, commands: &mut Vec<Command>| {
                let hidden = isolation.is_node_hidden(&child_path);
                let row = Row {
                    name: &child.name,
                    icon: shape_icon(&child.shape),
                    greyed: hidden,
                };
                row_ui(
                    ui,
                    commands,
                    |ui, commands| {
                        let own = isolation.hidden_parts.contains(&child_path);
                        let toggle = toggle_ui(ui, own, HIDE_ICON, &format!("hide {}", child.name))
                            .on_hover_text(if own {
                                "Hidden: click to show it again"
                            } else {
                                "Hide this part: it counts as empty space (a subtracted part cuts nothing)"
                            });
                        if toggle.clicked() {
                            commands.push(Command::Isolate(IsolationToggle::HidePart(
                                child_path.clone(),
                            )));
                        }
                    },
                    |ui, commands| {
                        let response = node_row_ui(ui, &row, &child_path, selection, commands);
                        item_menu(&response, target.clone(), commands);
                    },
                );
            };
            let child_key = format!("{key}/{}", object.name);
            node_ui(
                ui,
                child,
                &child_path,
                &child_key,
                shown,
                commands,
                &mut child_row,
            );
        }
    });
}

/// What an outliner drag carries: the path of the node dragged.
struct DraggedNode(Vec<usize>);

/// The row of the object or part at `path`: a click selects it, Ctrl+click adds it to
/// (or takes it from) a selection of several, and it can be dragged onto another row.
pub(super) fn node_row_ui(
    ui: &mut Ui,
    row: &Row,
    path: &[usize],
    selection: &Selection,
    commands: &mut Vec<Command>,
) -> egui::Response {
    let picked = selection.node_paths();
    let selected = picked.iter().any(|p| p == path);
    let response = item_button(ui, row, selected, egui::Sense::click_and_drag());
    if response.clicked() {
        let several = ui.input(|i| i.modifiers.command);
        if several && !picked.is_empty() {
            let mut paths = picked;
            match paths.iter().position(|p| p == path) {
                Some(at) => {
                    paths.remove(at);
                }
                None => paths.push(path.to_vec()),
            }
            commands.push(Command::Select(Selection::several(paths)));
        } else if selection.node_path().as_deref() != Some(path) {
            commands.push(Command::Select(Selection::node(path.to_vec())));
        }
    }
    drag_and_drop(ui, &response, path.to_vec(), commands);
    response
}

/// Makes an object row a drag source and a drop target: a node dropped on it moves
/// into it (a tree node) or beside it (a leaf), in one undo step.
fn drag_and_drop(
    ui: &Ui,
    response: &egui::Response,
    path: Vec<usize>,
    commands: &mut Vec<Command>,
) {
    if let Some(dragged) = response.dnd_hover_payload::<DraggedNode>()
        && dragged.0 != path
    {
        // Where it would land: a line around the row.
        let stroke = egui::Stroke::new(1.5, crate::ui::style::ACCENT);
        ui.painter()
            .rect_stroke(response.rect, 2.0, stroke, egui::StrokeKind::Inside);
    }
    if let Some(dragged) = response.dnd_release_payload::<DraggedNode>()
        && dragged.0 != path
    {
        commands.push(Command::Edit(SceneEdit::MoveNode {
            from: dragged.0.clone(),
            onto: path.clone(),
        }));
    }
    response.dnd_set_drag_payload(DraggedNode(path));
}
