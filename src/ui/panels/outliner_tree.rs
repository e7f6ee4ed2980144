//! The outliner's object rows as a tree: a CSG node or a group folds open to show its
//! operands or children (indented, each selectable, with its own menu), to any depth.

use egui::Ui;
use egui::collapsing_header::CollapsingState;

use crate::scene::Object;
use crate::ui::commands::{Command, Selection};

use super::outliner::{Row, item_menu, item_ui, shape_icon};

/// An object row for `object` at `path` (its index alone at the top level): a plain row
/// for a leaf, a row that folds open for a tree node. `top_row` draws the row itself
/// (the top level adds its hide toggle); parts below get plain rows.
pub(super) fn node_ui(
    ui: &mut Ui,
    object: &Object,
    path: &[usize],
    selection: &Selection,
    commands: &mut Vec<Command>,
    row: &mut dyn FnMut(&mut Ui, &mut Vec<Command>),
) {
    let children = object.shape.children();
    if children.is_empty() {
        row(ui, commands);
        return;
    }
    let id = ui.make_persistent_id(("outliner node", path));
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
            let selected = *selection == target;
            let mut child_row = |ui: &mut Ui, commands: &mut Vec<Command>| {
                let row = Row::plain(&child.name, shape_icon(&child.shape));
                let response = item_ui(ui, &row, selected, target.clone(), commands);
                item_menu(&response, target.clone(), commands);
            };
            node_ui(ui, child, &child_path, selection, commands, &mut child_row);
        }
    });
}
