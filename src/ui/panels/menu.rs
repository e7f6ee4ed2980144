//! The menu bar: File, Edit, Help.

use egui::{Button, Ui};

use crate::ui::commands::{Command, SceneEdit};
use crate::ui::shortcuts::shortcut_text;

/// What the menus need to know to enable their entries.
pub struct MenuState<'a> {
    /// Recently used files, most recent first.
    pub recent: &'a [std::path::PathBuf],
    /// Whether Undo would do something.
    pub can_undo: bool,
    /// Whether Redo would do something.
    pub can_redo: bool,
    /// Whether an object, light or material is selected.
    pub has_selection: bool,
}

/// Shows the menu bar.
pub fn menu_ui(ui: &mut Ui, state: &MenuState<'_>, commands: &mut Vec<Command>) {
    egui::MenuBar::new().ui(ui, |ui| {
        ui.menu_button("File", |ui| file_menu_ui(ui, state, commands));
        ui.menu_button("Edit", |ui| edit_menu_ui(ui, state, commands));
        ui.menu_button("Help", |ui| {
            entry_ui(
                ui,
                "Keyboard shortcuts",
                "Keyboard shortcuts",
                true,
                Command::ShowHelp,
                commands,
            );
            ui.separator();
            ui.label(format!("raylab {}", env!("CARGO_PKG_VERSION")));
            ui.weak("A Whitted-style ray tracer and scene editor.");
        });
    });
}

/// A menu entry with its shortcut shown on the right.
fn entry_ui(
    ui: &mut Ui,
    label: &str,
    shortcut: &str,
    enabled: bool,
    command: Command,
    commands: &mut Vec<Command>,
) {
    let text = shortcut_text(ui.ctx(), shortcut);
    if ui
        .add_enabled(enabled, Button::new(label).shortcut_text(text))
        .accessible_name(label)
        .clicked()
    {
        commands.push(command);
    }
}

fn file_menu_ui(ui: &mut Ui, state: &MenuState<'_>, commands: &mut Vec<Command>) {
    entry_ui(ui, "New", "New scene", true, Command::New, commands);
    entry_ui(ui, "Open…", "Open…", true, Command::OpenDialog, commands);
    ui.menu_button("Open Recent", |ui| {
        if state.recent.is_empty() {
            ui.weak("No recent files");
        }
        for path in state.recent {
            let name = path.file_name().map_or_else(
                || path.display().to_string(),
                |n| n.to_string_lossy().into_owned(),
            );
            if ui
                .button(name)
                .on_hover_text(path.display().to_string())
                .clicked()
            {
                commands.push(Command::Open(path.clone()));
            }
        }
    });
    ui.separator();
    entry_ui(ui, "Save", "Save", true, Command::Save, commands);
    entry_ui(
        ui,
        "Save As…",
        "Save As…",
        true,
        Command::SaveAsDialog,
        commands,
    );
    ui.separator();
    entry_ui(
        ui,
        "Import Legacy…",
        "",
        true,
        Command::ImportLegacyDialog,
        commands,
    );
    entry_ui(
        ui,
        "Export PNG…",
        "Export PNG…",
        true,
        Command::ShowExport,
        commands,
    );
    entry_ui(
        ui,
        "Compare with Image…",
        "",
        true,
        Command::ShowCompare,
        commands,
    );
    ui.separator();
    entry_ui(ui, "Quit", "", true, Command::Quit, commands);
}

fn edit_menu_ui(ui: &mut Ui, state: &MenuState<'_>, commands: &mut Vec<Command>) {
    entry_ui(ui, "Undo", "Undo", state.can_undo, Command::Undo, commands);
    entry_ui(ui, "Redo", "Redo", state.can_redo, Command::Redo, commands);
    ui.separator();
    entry_ui(
        ui,
        "Duplicate",
        "Duplicate selection",
        state.has_selection,
        Command::Edit(SceneEdit::DuplicateSelected),
        commands,
    );
    entry_ui(
        ui,
        "Delete",
        "Delete selection",
        state.has_selection,
        Command::Edit(SceneEdit::DeleteSelected),
        commands,
    );
}
