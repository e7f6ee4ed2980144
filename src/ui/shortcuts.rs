//! Keyboard shortcuts, turned into commands, and the F1 window that lists them.

use egui::{Key, KeyboardShortcut, Modifiers};

use crate::ui::commands::{Command, SceneEdit};

/// A shortcut, what it does, and the command it sends. Order matters: a shortcut with
/// Shift comes before the same one without, which would also match.
const SHORTCUTS: [(Modifiers, Key, &str); 16] = [
    (Modifiers::COMMAND, Key::N, "New scene"),
    (Modifiers::COMMAND, Key::O, "Open…"),
    (
        Modifiers::COMMAND.plus(Modifiers::SHIFT),
        Key::S,
        "Save As…",
    ),
    (Modifiers::COMMAND, Key::S, "Save"),
    (Modifiers::COMMAND.plus(Modifiers::SHIFT), Key::Z, "Redo"),
    (Modifiers::COMMAND, Key::Y, "Redo"),
    (Modifiers::COMMAND, Key::Z, "Undo"),
    (Modifiers::COMMAND, Key::D, "Duplicate selection"),
    (Modifiers::NONE, Key::Delete, "Delete selection"),
    (Modifiers::COMMAND, Key::E, "Export PNG…"),
    (Modifiers::NONE, Key::F1, "Keyboard shortcuts"),
    (
        Modifiers::COMMAND.plus(Modifiers::ALT),
        Key::Num0,
        "Set scene camera from view",
    ),
    (Modifiers::NONE, Key::Num0, "Camera view / view camera"),
    (Modifiers::COMMAND, Key::G, "Group selection"),
    (Modifiers::NONE, Key::PageDown, "Open next scene in folder"),
    (
        Modifiers::NONE,
        Key::PageUp,
        "Open previous scene in folder",
    ),
];

fn command_for(index: usize) -> Command {
    match index {
        0 => Command::New,
        1 => Command::OpenDialog,
        2 => Command::SaveAsDialog,
        3 => Command::Save,
        4 | 5 => Command::Redo,
        6 => Command::Undo,
        7 => Command::Edit(SceneEdit::DuplicateSelected),
        8 => Command::Edit(SceneEdit::DeleteSelected),
        9 => Command::ShowExport,
        10 => Command::ShowHelp,
        11 => Command::SetSceneCameraFromView,
        12 => Command::ToggleCameraView,
        13 => Command::Edit(SceneEdit::GroupSelected),
        14 => Command::OpenInFolder { forward: true },
        _ => Command::OpenInFolder { forward: false },
    }
}

/// The shortcut text for a menu entry, e.g. "Ctrl+S".
#[must_use]
pub fn shortcut_text(ctx: &egui::Context, description: &str) -> String {
    SHORTCUTS
        .iter()
        .find(|(_, _, d)| *d == description)
        .map(|(m, k, _)| ctx.format_shortcut(&KeyboardShortcut::new(*m, *k)))
        .unwrap_or_default()
}

/// Consumes this frame's shortcuts and returns their commands. While a text field has
/// the keyboard, only F1 and the file shortcuts act (Ctrl+Z, Delete... belong to it).
#[must_use]
pub fn shortcut_commands(ctx: &egui::Context) -> Vec<Command> {
    let typing = ctx.text_edit_focused();
    let mut commands = Vec::new();
    ctx.input_mut(|input| {
        for (index, (modifiers, key, _)) in SHORTCUTS.iter().enumerate() {
            let editing_key = matches!(
                key,
                Key::Z
                    | Key::Y
                    | Key::D
                    | Key::G
                    | Key::Delete
                    | Key::Num0
                    | Key::PageDown
                    | Key::PageUp
            );
            if typing && editing_key {
                continue;
            }
            if input.consume_shortcut(&KeyboardShortcut::new(*modifiers, *key)) {
                commands.push(command_for(index));
            }
        }
    });
    commands
}

/// The F1 window listing every shortcut.
pub fn help_window(ctx: &egui::Context, open: &mut bool) {
    egui::Window::new("Keyboard shortcuts")
        .open(open)
        .resizable(false)
        .collapsible(false)
        .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
        .show(ctx, |ui| {
            egui::Grid::new("shortcuts")
                .num_columns(2)
                .spacing([24.0, 6.0])
                .striped(true)
                .show(ui, |ui| {
                    for (modifiers, key, description) in SHORTCUTS {
                        let text = ctx.format_shortcut(&KeyboardShortcut::new(modifiers, key));
                        ui.label(egui::RichText::new(text).monospace().strong());
                        ui.label(description);
                        ui.end_row();
                    }
                });
            ui.separator();
            ui.label("Click an object in the viewport to select it.");
            ui.label("W / E / R: move, rotate, scale gizmo · F: frame the selection.");
            ui.label(
                "Drag: orbit (Alt+drag over a handle) · Shift or middle drag: pan · wheel: zoom.",
            );
            ui.label("These move the view camera, never the scene's (0 or Numpad 0: camera view).");
            ui.label("Inspect (or Alt+click) a pixel to draw its rays; Pin keeps them drawn.");
            ui.label("Hold Shift while dragging a handle to snap.");
            ui.label("Drop a .ron file on the window to open it.");
        });
}
