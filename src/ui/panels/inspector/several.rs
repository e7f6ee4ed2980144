//! The inspector for several objects or parts picked together (Ctrl+click in the
//! outliner): what is picked, and how to combine them.

use egui::Ui;

use super::layout::heading_ui;
use crate::scene::Scene;
use crate::scene::tree::path_name;
use crate::ui::commands::{CSG_OPS, Command, SceneEdit};

/// Lists the picked nodes and offers Group and the three booleans.
pub(super) fn several_ui(
    ui: &mut Ui,
    scene: &Scene,
    paths: &[Vec<usize>],
    commands: &mut Vec<Command>,
) {
    heading_ui(ui, "SELECTION", &format!("{} objects", paths.len()));
    for (k, path) in paths.iter().enumerate() {
        let role = if k == 0 { "  (first)" } else { "" };
        ui.label(format!("{}{role}", path_name(&scene.objects, path)));
    }
    ui.add_space(6.0);
    ui.weak("Combine them into one node where the first stood; nothing moves.");
    ui.horizontal_wrapped(|ui| {
        if ui
            .button("Group")
            .on_hover_text("Put them in a new group (Ctrl+G)")
            .clicked()
        {
            commands.push(Command::Edit(SceneEdit::GroupSelected));
        }
        for (op, keeps) in CSG_OPS {
            let label = match op {
                crate::scene::CsgOp::Union => "Union",
                crate::scene::CsgOp::Intersection => "Intersect",
                crate::scene::CsgOp::Difference => "Subtract",
            };
            if ui
                .button(label)
                .on_hover_text(format!(
                    "A new {} node: the solid is what lies {keeps} (the first picked is the \
                     first operand)",
                    op.name()
                ))
                .clicked()
            {
                commands.push(Command::Edit(SceneEdit::CsgSelected(op)));
            }
        }
    });
}
