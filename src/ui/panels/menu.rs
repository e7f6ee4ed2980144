//! The menu bar: File, Edit, Help.

use egui::{Button, RichText, Ui};

use crate::scene::legacy::Dialect;
use crate::ui::commands::{Command, SceneEdit};
use crate::ui::document::recent::RecentFiles;
use crate::ui::shortcuts::shortcut_text;

/// What the menus need to know to enable their entries.
pub struct MenuState<'a> {
    /// Recently used files, most recent first.
    pub recent: &'a RecentFiles,
    /// Whether file dialogs are the in-app ones.
    pub in_app_dialogs: bool,
    /// Whether an imported OBJ is scaled to a unit box.
    pub fit_imported_meshes: bool,
    /// Whether this desktop can show native file dialogs at all.
    pub native_dialogs: bool,
    /// Whether Undo would do something.
    pub can_undo: bool,
    /// Whether Redo would do something.
    pub can_redo: bool,
    /// Whether an object, light or material is selected.
    pub has_selection: bool,
    /// Whether an object or a part of a tree is selected (it can be grouped).
    pub has_object_selected: bool,
    /// Whether the selection is a group (it can be ungrouped).
    pub group_selected: bool,
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
        recent_ui(ui, state.recent, commands);
    });
    entry_ui(
        ui,
        "Open Next in Folder",
        "Open next scene in folder",
        true,
        Command::OpenInFolder { forward: true },
        commands,
    );
    entry_ui(
        ui,
        "Open Previous in Folder",
        "Open previous scene in folder",
        true,
        Command::OpenInFolder { forward: false },
        commands,
    );
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
        "Import OBJ Mesh…",
        "",
        true,
        Command::ImportObjDialog,
        commands,
    );
    let mut fit = state.fit_imported_meshes;
    if ui
        .checkbox(&mut fit, "Fit Imported Meshes to a Unit Box")
        .on_hover_text(
            "Scale an imported OBJ so that its largest side is 1, once it is read \
             (its own undo step: Undo gives back the file's size)",
        )
        .changed()
    {
        commands.push(Command::SetFitImportedMeshes(fit));
    }
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
        "Export Course Scene…",
        "",
        true,
        Command::ExportCourseDialog(Dialect::Framework2020),
        commands,
    );
    entry_ui(
        ui,
        "Export Course Scene (2016)…",
        "",
        true,
        Command::ExportCourseDialog(Dialect::Framework2016),
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
    entry_ui(
        ui,
        "Bug gallery…",
        "",
        true,
        Command::ShowBugGallery,
        commands,
    );
    ui.separator();
    let mut in_app = state.in_app_dialogs;
    let hover = if state.native_dialogs {
        "Use raylab's own file dialog instead of the desktop's"
    } else {
        "This desktop shows no native file dialog (no xdg portal, no zenity): raylab's own is used"
    };
    if ui
        .add_enabled(
            state.native_dialogs,
            egui::Checkbox::new(&mut in_app, "Built-in file dialog"),
        )
        .on_hover_text(hover)
        .on_disabled_hover_text(hover)
        .changed()
    {
        commands.push(Command::SetPreferInAppFileDialog(in_app));
    }
    ui.separator();
    entry_ui(ui, "Quit", "", true, Command::Quit, commands);
}

/// Open Recent's entries; one that failed to open last time is marked and still opens.
fn recent_ui(ui: &mut Ui, recent: &RecentFiles, commands: &mut Vec<Command>) {
    if recent.paths().is_empty() {
        ui.weak("No recent files");
    }
    for path in recent.paths() {
        let name = path.file_name().map_or_else(
            || path.display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        );
        let failed = recent.has_failed(path);
        let (text, hover) = if failed {
            (
                RichText::new(format!("{name} (could not open)")).weak(),
                format!(
                    "{}\nThe last try to open it failed; click to try again",
                    path.display()
                ),
            )
        } else {
            (RichText::new(name), path.display().to_string())
        };
        if ui.button(text).on_hover_text(hover).clicked() {
            commands.push(Command::Open(path.clone()));
        }
    }
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
    ui.separator();
    entry_ui(
        ui,
        "Group",
        "Group selection",
        state.has_object_selected,
        Command::Edit(SceneEdit::GroupSelected),
        commands,
    );
    entry_ui(
        ui,
        "Ungroup",
        "Ungroup selection",
        state.group_selected,
        Command::Edit(SceneEdit::UngroupSelected),
        commands,
    );
}
