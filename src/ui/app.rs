//! The editor's state and its frame: panels push commands, which are applied once per
//! frame; the result feeds undo, the title and the preview.

use std::path::{Path, PathBuf};

use egui::util::undoer::{Settings as UndoSettings, Undoer};
use egui::{Color32, RichText, ViewportCommand};

use super::autosave::{Autosave, RestoreAnswer};
use super::commands::{Command, SceneEdit, Selection, repair_selection};
use super::confirm::{DiscardAction, discard_modal};
use super::convergence_plot::convergence_plot_ui;
use super::export::{ExportState, export_window};
use super::files;
use super::inspector::inspector_ui;
use super::menu::{MenuState, menu_ui};
use super::outliner::outliner_ui;
use super::pixel_inspector::{PixelInspection, pixel_inspector_ui};
use super::preview_link::PreviewLink;
use super::preview_settings::PreviewSettings;
use super::recent::RecentFiles;
use super::screenshot::ScreenshotHook;
use super::shortcuts::{help_window, shortcut_commands};
use super::status_bar::{StatusInfo, status_bar_ui};
use super::style::apply_style;
use super::viewport::viewport_ui;
use crate::scene::Scene;

mod document;

/// How to start the editor.
#[derive(Clone, Debug, Default)]
pub struct EditorOptions {
    /// A scene file to open; the embedded default scene otherwise.
    pub scene: Option<PathBuf>,
    /// Run the background preview (tests may turn it off).
    pub preview: bool,
    /// Save a screenshot here once the first full-resolution frame is shown, then close.
    pub screenshot: Option<PathBuf>,
    /// Wait for the final (fully sampled) frame instead of the first full-resolution one.
    pub screenshot_final: bool,
    /// Where unsaved work is kept for crash recovery (none: no autosave).
    pub recovery: Option<crate::recovery::RecoveryStore>,
}

/// The editor.
pub struct EditorApp {
    scene: Scene,
    /// The scene as last loaded or saved: unsaved changes are a difference from it.
    saved: Scene,
    path: Option<PathBuf>,
    /// What stands for the file name when there is none ("default scene", "untitled").
    unnamed: &'static str,
    selection: Selection,
    undoer: Undoer<Scene>,
    commands: Vec<Command>,
    preview_enabled: bool,
    preview: Option<PreviewLink>,
    /// The toolbar's switches, view and overlays (editor state).
    preview_settings: PreviewSettings,
    /// The pixel under the inspector, kept current with the scene and switches.
    inspection: Option<PixelInspection>,
    export: ExportState,
    recent: RecentFiles,
    pending: Option<DiscardAction>,
    error: Option<String>,
    message: Option<String>,
    show_help: bool,
    focus_name: bool,
    allow_close: bool,
    title: String,
    styled: bool,
    screenshot: Option<ScreenshotHook>,
    screenshot_final: bool,
    autosave: Autosave,
}

impl EditorApp {
    /// The editor on `options.scene` (or the default scene), with `recent` files.
    #[must_use]
    pub fn new(options: EditorOptions, recent: RecentFiles) -> Self {
        let scene = files::default_scene();
        let mut app = Self {
            saved: scene.clone(),
            scene,
            path: None,
            unnamed: "default scene",
            selection: Selection::None,
            undoer: undoer(),
            commands: Vec::new(),
            preview_enabled: options.preview,
            preview: None,
            preview_settings: PreviewSettings::default(),
            inspection: None,
            export: ExportState::default(),
            recent,
            pending: None,
            error: None,
            message: None,
            show_help: false,
            focus_name: false,
            allow_close: false,
            title: String::new(),
            styled: false,
            screenshot: options.screenshot.map(ScreenshotHook::new),
            screenshot_final: options.screenshot_final,
            autosave: Autosave::new(options.recovery),
        };
        app.undoer.add_undo(&app.scene);
        if let Some(path) = options.scene {
            app.open(&path);
        }
        app
    }

    /// Queues a command, applied at the end of the next frame (as a panel's would be).
    pub fn push(&mut self, command: Command) {
        self.commands.push(command);
    }

    /// The scene being edited.
    #[must_use]
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// What the inspector shows.
    #[must_use]
    pub fn selection(&self) -> &Selection {
        &self.selection
    }

    /// The scene's file, if it has one.
    #[must_use]
    pub fn path(&self) -> Option<&Path> {
        self.path.as_deref()
    }

    /// Whether the scene differs from its file.
    #[must_use]
    pub fn is_dirty(&self) -> bool {
        self.scene != self.saved
    }

    /// The error shown in the error area, if any.
    #[must_use]
    pub fn error(&self) -> Option<&str> {
        self.error.as_deref()
    }

    /// The action waiting for a "discard unsaved changes?" answer.
    #[must_use]
    pub fn pending_discard(&self) -> Option<&DiscardAction> {
        self.pending.as_ref()
    }

    /// The window title: file name, `*` when unsaved.
    #[must_use]
    pub fn title(&self) -> String {
        let marker = if self.is_dirty() { "*" } else { "" };
        format!("{}{marker} — raylab", self.file_label())
    }

    /// The export window's state.
    #[must_use]
    pub fn export(&self) -> &ExportState {
        &self.export
    }

    /// The preview, when running.
    #[must_use]
    pub fn preview(&self) -> Option<&PreviewLink> {
        self.preview.as_ref()
    }

    /// The toolbar's settings.
    #[must_use]
    pub fn preview_settings(&self) -> &PreviewSettings {
        &self.preview_settings
    }

    /// The pixel inspector's contents, when open.
    #[must_use]
    pub fn inspection(&self) -> Option<&PixelInspection> {
        self.inspection.as_ref()
    }

    /// Recent files.
    #[must_use]
    pub fn recent(&self) -> &RecentFiles {
        &self.recent
    }

    fn file_label(&self) -> String {
        self.path.as_ref().and_then(|p| p.file_name()).map_or_else(
            || self.unnamed.to_owned(),
            |n| n.to_string_lossy().into_owned(),
        )
    }

    /// One frame of the whole editor.
    pub fn editor_ui(&mut self, ui: &mut egui::Ui) {
        let ctx = ui.ctx().clone();
        if !self.styled {
            // Fonts change from the next pass: lay nothing out until then.
            apply_style(&ctx);
            self.styled = true;
            ctx.request_repaint();
            return;
        }
        if self.preview_enabled && self.preview.is_none() {
            self.preview = Some(PreviewLink::new(&ctx));
        }
        if let Some(preview) = &mut self.preview {
            preview.poll(&ctx, self.preview_settings.nan_guard);
        }
        self.input(&ctx);
        self.panels_ui(ui);
        self.dialogs(&ctx);
        self.apply_commands(&ctx);
        let dirty = self.is_dirty();
        let now = std::time::Instant::now();
        if let Some(wait) = self
            .autosave
            .tick(&self.scene, dirty, self.path.as_deref(), now)
        {
            ctx.request_repaint_after(wait);
        }
        if let Some(preview) = &mut self.preview {
            preview.sync(&self.scene, &self.preview_settings);
        }
        let title = self.title();
        if title != self.title {
            ctx.send_viewport_cmd(ViewportCommand::Title(title.clone()));
            self.title = title;
        }
        if let Some(hook) = &mut self.screenshot {
            let ready = self.preview.as_ref().is_some_and(|p| {
                p.shows_full_resolution()
                    && (!self.screenshot_final || p.shown().is_some_and(|s| s.is_final))
            });
            if let Some(outcome) = hook.step(&ctx, ready) {
                if let Err(error) = outcome {
                    eprintln!("raylab: screenshot failed: {error}");
                }
                self.allow_close = true;
                ctx.send_viewport_cmd(ViewportCommand::Close);
            }
        }
    }

    /// Shortcuts, dropped files and the close button.
    fn input(&mut self, ctx: &egui::Context) {
        self.commands.extend(shortcut_commands(ctx));
        let dropped: Vec<PathBuf> = ctx.input(|i| {
            i.raw
                .dropped_files
                .iter()
                .map(|f| f.path().to_owned())
                .filter(|p| !p.as_os_str().is_empty())
                .collect()
        });
        if let Some(path) = dropped.into_iter().next() {
            if files::is_scene_file(&path) {
                self.commands.push(Command::Open(path));
            } else {
                self.error = Some(format!(
                    "{}: only .ron scene files can be opened",
                    path.display()
                ));
            }
        }
        if ctx.input(|i| !i.raw.hovered_files.is_empty()) {
            drop_hint(ctx);
        }
        if ctx.input(|i| i.viewport().close_requested()) && !self.allow_close && self.is_dirty() {
            ctx.send_viewport_cmd(ViewportCommand::CancelClose);
            self.pending = Some(DiscardAction::Quit);
        }
    }

    fn panels_ui(&mut self, ui: &mut egui::Ui) {
        let mut commands = std::mem::take(&mut self.commands);
        egui::Panel::top("menu").show(ui, |ui| {
            let state = MenuState {
                recent: self.recent.paths(),
                can_undo: self.undoer.has_undo(&self.scene),
                can_redo: self.undoer.has_redo(&self.scene),
                has_selection: matches!(
                    self.selection,
                    Selection::Object(_) | Selection::Light(_) | Selection::Material(_)
                ),
            };
            menu_ui(ui, &state, &mut commands);
        });
        if let Some(error) = &self.error {
            egui::Panel::top("error")
                .frame(
                    egui::Frame::new()
                        .fill(Color32::from_rgb(90, 28, 28))
                        .inner_margin(8),
                )
                .show(ui, |ui| {
                    ui.horizontal(|ui| {
                        ui.label(RichText::new("▲").color(Color32::from_rgb(255, 200, 120)));
                        ui.label(RichText::new(error).color(Color32::WHITE));
                        ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                            if ui.button("Dismiss").clicked() {
                                commands.push(Command::DismissError);
                            }
                        });
                    });
                });
        }
        egui::Panel::bottom("status").show(ui, |ui| {
            let file = self.file_label();
            let info = StatusInfo {
                file: &file,
                dirty: self.is_dirty(),
                objects: self.scene.objects.len(),
                lights: self.scene.lights.len(),
                frame: self.preview.as_ref().and_then(PreviewLink::shown),
                progress: self.preview.as_ref().and_then(PreviewLink::pass_progress),
                error: self.preview.as_ref().and_then(PreviewLink::error),
                message: self.message.as_deref(),
            };
            status_bar_ui(ui, &info);
        });
        egui::Panel::left("outliner")
            .resizable(true)
            .default_size(230.0)
            .size_range(160.0..=420.0)
            .show(ui, |ui| {
                panel_title_ui(ui, "Outliner");
                outliner_ui(ui, &self.scene, &self.selection, &mut commands);
            });
        egui::Panel::right("inspector")
            .resizable(true)
            .default_size(330.0)
            .size_range(240.0..=560.0)
            .show(ui, |ui| {
                panel_title_ui(ui, "Inspector");
                inspector_ui(
                    ui,
                    &self.scene,
                    &self.selection,
                    &mut self.focus_name,
                    &mut commands,
                );
                // A rename asked for an item without a name field: forget it.
                self.focus_name = false;
            });
        egui::CentralPanel::no_frame().show(ui, |ui| {
            viewport_ui(
                ui,
                &self.scene,
                self.preview.as_ref(),
                &self.selection,
                &self.preview_settings,
                &mut commands,
            );
        });
        self.commands = commands;
    }

    fn dialogs(&mut self, ctx: &egui::Context) {
        if let Some(answer) = self.autosave.offer_ui(ctx) {
            self.restore(answer);
        }
        help_window(ctx, &mut self.show_help);
        export_window(ctx, &mut self.export, &self.scene);
        if let Some(inspection) = &self.inspection {
            pixel_inspector_ui(ctx, inspection, &mut self.commands);
        }
        if self.preview_settings.show_convergence
            && let Some(preview) = &self.preview
        {
            convergence_plot_ui(
                ctx,
                preview.convergence(),
                &self.preview_settings,
                &mut self.commands,
            );
        }
        if let Some(action) = self.pending.clone() {
            let answer = discard_modal(ctx, &action);
            match answer {
                Some(true) => {
                    self.pending = None;
                    self.perform(action, ctx);
                }
                Some(false) => self.pending = None,
                None => {}
            }
        }
    }

    /// Applies this frame's commands, then records an undo point unless an edit is still
    /// in progress (a drag or a text field), so a whole drag is one step.
    fn apply_commands(&mut self, ctx: &egui::Context) {
        let commands = std::mem::take(&mut self.commands);
        if !commands.is_empty() {
            // What the commands changed is drawn in the next frame.
            ctx.request_repaint();
        }
        // Panels compute edits against the scene as it was laid out. Once a command has
        // reshuffled the lists (a delete, an add, an undo...), a later edit by index in
        // the same frame could name another item, so it is dropped.
        let mut reshuffled = false;
        for command in commands {
            if reshuffled && matches!(&command, Command::Edit(edit) if edit.is_by_index()) {
                continue;
            }
            let lists = (self.scene.objects.len(), self.scene.lights.len());
            let may_reshuffle = matches!(
                command,
                Command::Undo
                    | Command::Redo
                    | Command::New
                    | Command::Open(_)
                    | Command::ImportLegacy(_)
            );
            self.execute(command, ctx);
            reshuffled |=
                may_reshuffle || lists != (self.scene.objects.len(), self.scene.lights.len());
        }
        repair_selection(&self.scene, &mut self.selection);
        if let Some(inspection) = &self.inspection
            && !inspection.is_current(&self.scene, self.preview_settings.switches)
        {
            let pixel = inspection.pixel;
            self.inspection = Some(PixelInspection::new(
                &self.scene,
                self.preview_settings.switches,
                pixel,
            ));
        }
        let editing = ctx.input(|i| i.pointer.any_down())
            || ctx.text_edit_focused()
            || super::camera_navigation::zoom_in_progress(ctx);
        if !editing {
            self.undoer.add_undo(&self.scene);
        }
    }

    fn execute(&mut self, command: Command, ctx: &egui::Context) {
        match command {
            Command::Select(selection) => self.selection = selection,
            Command::Edit(edit) => self.edit(edit),
            Command::Undo => {
                if let Some(scene) = self.undoer.undo(&self.scene) {
                    self.scene = scene.clone();
                }
            }
            Command::Redo => {
                if let Some(scene) = self.undoer.redo(&self.scene) {
                    self.scene = scene.clone();
                }
            }
            Command::New => self.guard(DiscardAction::New, ctx),
            Command::OpenDialog => self.guard(DiscardAction::OpenDialog, ctx),
            Command::Open(path) => self.guard(DiscardAction::Open(path), ctx),
            Command::ImportLegacyDialog => self.guard(DiscardAction::ImportDialog, ctx),
            Command::ImportLegacy(path) => self.guard(DiscardAction::Import(path), ctx),
            Command::Quit => self.guard(DiscardAction::Quit, ctx),
            Command::Save => match self.path.clone() {
                Some(path) => self.save_as(&path),
                None => self.save_as_dialog(),
            },
            Command::SaveAsDialog => self.save_as_dialog(),
            Command::SaveAs(path) => self.save_as(&path),
            Command::ShowExport => {
                let default = self.path.as_ref().map(|p| p.with_extension("png"));
                self.export.show(&self.scene, default);
            }
            Command::ShowHelp => self.show_help = !self.show_help,
            Command::DismissError => self.error = None,
            Command::FocusName => self.focus_name = true,
            Command::SetPreviewSettings(settings) => self.preview_settings = settings,
            Command::InspectPixel(pixel) => {
                self.inspection = pixel.map(|pixel| {
                    PixelInspection::new(&self.scene, self.preview_settings.switches, pixel)
                });
            }
        }
    }

    fn edit(&mut self, edit: SceneEdit) {
        if let Err(error) = edit.apply(&mut self.scene, &mut self.selection) {
            self.error = Some(error);
        }
    }

    /// Answers the crash-recovery offer as its buttons do (for tests and the window).
    pub fn answer_restore(&mut self, restore: bool) {
        if let Some(answer) = self.autosave.answer(restore) {
            self.restore(answer);
        }
    }

    /// Whether a crash-recovery offer is waiting.
    #[must_use]
    pub fn has_restore_offer(&self) -> bool {
        self.autosave.has_offer()
    }

    /// Opens a recovered scene: its file (when it still loads) is what it is compared
    /// with, so the recovered edits show as unsaved changes.
    fn restore(&mut self, answer: RestoreAnswer) {
        let RestoreAnswer::Restore(scene, source) = answer else {
            return;
        };
        let saved = source
            .as_deref()
            .and_then(|p| crate::scene::load_scene(p).ok())
            .unwrap_or_else(files::new_scene);
        self.replace_scene(*scene, source);
        self.saved = saved;
        self.message = Some("Restored unsaved work from the last session".to_owned());
    }

    /// The end of a clean session: nothing left to recover.
    pub fn on_clean_exit(&mut self) {
        self.autosave.clear();
    }

    /// Persists editor state (recent files) in eframe's storage.
    pub fn save_state(&self, storage: &mut dyn eframe::Storage) {
        if self.screenshot.is_none() {
            self.recent.save(storage);
            self.preview_settings.save(storage);
        }
    }

    /// Whether this run only takes a screenshot (and must not touch stored state).
    #[must_use]
    pub fn is_screenshot_run(&self) -> bool {
        self.screenshot.is_some()
    }
}

/// A fresh undo history.
fn undoer() -> Undoer<Scene> {
    Undoer::with_settings(UndoSettings {
        max_undos: 200,
        ..UndoSettings::default()
    })
}

/// While files are dragged over the window: say what dropping does.
fn drop_hint(ctx: &egui::Context) {
    let painter = ctx.layer_painter(egui::LayerId::new(
        egui::Order::Foreground,
        egui::Id::unique("drop hint"),
    ));
    let rect = ctx.content_rect();
    painter.rect_filled(rect, 0.0, Color32::from_black_alpha(170));
    painter.text(
        rect.center(),
        egui::Align2::CENTER_CENTER,
        "Drop a .ron scene to open it",
        egui::FontId::proportional(22.0),
        Color32::WHITE,
    );
}

fn panel_title_ui(ui: &mut egui::Ui, title: &str) {
    ui.add_space(6.0);
    ui.label(
        RichText::new(title.to_uppercase())
            .small()
            .strong()
            .color(Color32::from_gray(150)),
    );
    ui.add_space(2.0);
}

impl eframe::App for EditorApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.editor_ui(ui);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        self.save_state(storage);
    }

    fn persist_egui_memory(&self) -> bool {
        !self.is_screenshot_run()
    }

    fn on_exit(&mut self, _gl: Option<&eframe::glow::Context>) {
        self.on_clean_exit();
    }
}
