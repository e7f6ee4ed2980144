//! What the object inspector adds for object trees: where a node sits (a breadcrumb of
//! its parents, each a link), a CSG node's operator, and the tree actions (group,
//! ungroup, start a CSG solid, add an operand).

use egui::Ui;

use crate::scene::tree::object_at;
use crate::scene::{Scene, Shape};
use crate::ui::commands::{CSG_OPS, Command, SceneEdit, Selection};

/// The node's parents as links, top level first, when it is inside a tree.
pub(super) fn breadcrumb_ui(
    ui: &mut Ui,
    scene: &Scene,
    path: &[usize],
    commands: &mut Vec<Command>,
) {
    if path.len() < 2 {
        return;
    }
    ui.horizontal_wrapped(|ui| {
        ui.weak("in");
        for depth in 1..path.len() {
            let Some(parent) = object_at(&scene.objects, &path[..depth]) else {
                return;
            };
            if depth > 1 {
                ui.weak("›");
            }
            if ui
                .link(&parent.name)
                .on_hover_text("Select this parent (Alt+click in the picture does too)")
                .clicked()
            {
                commands.push(Command::Select(Selection::node(path[..depth].to_vec())));
            }
        }
    });
}

/// A CSG node's operator, as a choice with what each keeps.
pub(super) fn csg_op_row_ui(ui: &mut Ui, shape: &mut Shape) {
    let Shape::Csg { op, operands } = shape else {
        return;
    };
    ui.label("Operator");
    egui::ComboBox::from_id_salt("csg operator")
        .selected_text(op.name())
        .show_ui(ui, |ui| {
            for (choice, keeps) in CSG_OPS {
                ui.selectable_value(op, choice, choice.name())
                    .on_hover_text(format!("The solid is what lies {keeps}"));
            }
        })
        .response
        .accessible_name("operator");
    ui.end_row();
    ui.label("Operands");
    ui.label(operands.len().to_string())
        .on_hover_text("Select them in the outliner, under this node");
    ui.end_row();
}

/// Group, ungroup and add-operand buttons for the selected node.
pub(super) fn tree_actions_ui(ui: &mut Ui, shape: &Shape, commands: &mut Vec<Command>) {
    ui.horizontal_wrapped(|ui| {
        if ui
            .button("Group")
            .on_hover_text("Put this object in a new group in its place (Ctrl+G)")
            .clicked()
        {
            commands.push(Command::Edit(SceneEdit::GroupSelected));
        }
        ui.menu_button("Boolean", |ui| {
            for (op, keeps) in CSG_OPS {
                if ui
                    .button(op.name())
                    .on_hover_text(format!(
                        "Make this the first operand of a new {} node: the solid is what \
                         lies {keeps}; add the other operands next",
                        op.name()
                    ))
                    .clicked()
                {
                    commands.push(Command::Edit(SceneEdit::CsgSelected(op)));
                }
            }
        })
        .response
        .on_hover_text("Start a CSG solid from this object");
        if matches!(shape, Shape::Group { .. })
            && ui
                .button("Ungroup")
                .on_hover_text("Put the group's children in its place, where they are now")
                .clicked()
        {
            commands.push(Command::Edit(SceneEdit::UngroupSelected));
        }
        if shape.is_tree_node() {
            let what = if matches!(shape, Shape::Csg { .. }) {
                "+ Add operand"
            } else {
                "+ Add child"
            };
            ui.menu_button(what, |ui| {
                for kind in Shape::ALL {
                    if ui.button(kind.name()).clicked() {
                        commands.push(Command::Edit(SceneEdit::AddOperand(kind)));
                    }
                }
            });
        }
    });
}
