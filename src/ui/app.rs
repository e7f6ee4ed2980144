//! The editor's state and its frame: panels push commands, which are applied once per
//! frame; the result feeds undo, the title and the preview.

use std::path::{Path, PathBuf};

use crate::ui::commands::Command;
use crate::ui::document::autosave::Autosave;
use crate::ui::document::confirm::DiscardAction;
use crate::ui::document::file_dialog::FileDialogs;
use crate::ui::document::files;
use crate::ui::document::native_dialogs::NativeDialogs;
use crate::ui::document::recent::RecentFiles;
use crate::ui::panels::status_bar::StatusMessage;
use crate::ui::screenshot::ScreenshotHook;
use crate::ui::state::keep_in_range;
use crate::ui::stored::Stored;
use crate::ui::viewport::isolation_memory::IsolationMemory;
use crate::ui::viewport::preview_link::PreviewLink;

mod apply;
mod document;
mod file_actions;
mod frame;
mod looking;
mod mesh_fit;
mod tools;
mod view;
mod view_state;

pub use document::Document;
pub use looking::Looking;
pub use tools::Tools;
pub use view::View;

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
    /// Whether native file dialogs may be used (tests make them unavailable).
    pub native_dialogs: NativeDialogs,
    /// Where file dialogs open for a scene without a folder (the working folder if none).
    pub dialog_folder: Option<PathBuf>,
}

/// The editor: the document, how it is viewed, the tools working on it, and the
/// frame's own state (the commands to apply, the notices, the window).
pub struct EditorApp {
    /// The scene being edited, its file, undo history and selection.
    document: Document,
    /// How the document is shown: preview, view camera, isolation, open panels.
    view: View,
    /// The tool windows and dialogs: export, compare, bug gallery, file dialogs.
    tools: Tools,
    /// This frame's commands, applied at its end.
    commands: Vec<Command>,
    /// Recent files (File > Open Recent), kept across runs.
    recent: RecentFiles,
    /// The error shown in the error area, if any.
    error: Option<String>,
    /// Something the user should know that is not a failure (an import's warnings).
    warning: Option<String>,
    /// The status bar's message.
    message: Option<StatusMessage>,
    /// Whether the window may close (Quit was answered, or a screenshot is taken).
    allow_close: bool,
    /// The window title last sent.
    title: String,
    /// Whether the style and fonts were installed.
    styled: bool,
    /// The screenshot to take, for a screenshot run.
    screenshot: Option<ScreenshotHook>,
    /// Whether the screenshot waits for the final (fully sampled) frame.
    screenshot_final: bool,
    /// Crash recovery: unsaved work written aside, and the offer to restore it.
    autosave: Autosave,
}

impl EditorApp {
    /// The editor on `options.scene` (or the default scene), with `recent` files.
    #[must_use]
    pub fn new(options: EditorOptions, recent: RecentFiles) -> Self {
        let scene = files::default_scene();
        let looking = looking::Looking::new(&scene);
        let mut app = Self {
            document: Document::new(scene, "default scene"),
            view: View::new(looking, options.preview),
            tools: Tools::new(FileDialogs::new(
                options.native_dialogs.resolve(),
                options.dialog_folder,
            )),
            commands: Vec::new(),
            recent,
            error: None,
            warning: None,
            message: None,
            allow_close: false,
            title: String::new(),
            styled: false,
            screenshot: options.screenshot.map(ScreenshotHook::new),
            screenshot_final: options.screenshot_final,
            autosave: Autosave::new(options.recovery),
        };
        if let Some(path) = options.scene {
            app.open(&path);
        }
        app
    }

    /// Queues a command, applied at the end of the next frame (as a panel's would be).
    pub fn push(&mut self, command: Command) {
        self.commands.push(command);
    }

    /// The document: the scene, its file, undo history and selection. Read only: the
    /// scene changes through commands ([`Self::push`]), which also record undo.
    #[must_use]
    pub fn document(&self) -> &Document {
        &self.document
    }

    /// How the document is shown: preview settings, view camera, isolation.
    #[must_use]
    pub fn view(&self) -> &View {
        &self.view
    }

    /// The tool windows and dialogs: export, compare, bug gallery, file dialogs.
    #[must_use]
    pub fn tools(&self) -> &Tools {
        &self.tools
    }

    /// The scene's file, if it has one.
    #[must_use]
    pub fn path(&self) -> Option<&Path> {
        self.document.path.as_deref()
    }

    /// The error shown in the error area, if any.
    #[must_use]
    pub fn error(&self) -> Option<&str> {
        self.error.as_deref()
    }

    /// The warning shown in the warning area, if any.
    #[must_use]
    pub fn warning(&self) -> Option<&str> {
        self.warning.as_deref()
    }

    /// The last autosave error, while autosave keeps failing.
    #[must_use]
    pub fn autosave_error(&self) -> Option<&str> {
        self.autosave.error.as_deref()
    }

    /// Whether the editor has let the window close (after Quit was answered).
    #[must_use]
    pub fn is_closing(&self) -> bool {
        self.allow_close
    }

    /// The action waiting for a "discard unsaved changes?" answer.
    #[must_use]
    pub fn pending_discard(&self) -> Option<&DiscardAction> {
        self.tools.pending.as_ref()
    }

    /// The window title: file name, `*` when unsaved.
    #[must_use]
    pub fn title(&self) -> String {
        let marker = if self.document.is_dirty() { "*" } else { "" };
        format!("{}{marker} — raylab", self.document.file_label())
    }

    /// The preview, when running.
    #[must_use]
    pub fn preview(&self) -> Option<&PreviewLink> {
        self.view.preview.as_ref()
    }

    /// Installs the per-file isolation memory of an earlier run (read from eframe's
    /// storage at start-up) and brings back the open file's switches.
    pub fn set_isolation_memory(&mut self, memory: IsolationMemory) {
        self.view.isolation_memory = memory;
        if let Some(path) = &self.document.path {
            self.view.isolation = self.view.isolation_memory.recall(path);
            keep_in_range(&mut self.view.isolation, &self.document.scene);
        }
    }

    /// The per-file isolation memory as it would be saved now.
    #[must_use]
    pub fn isolation_memory(&self) -> IsolationMemory {
        let mut memory = self.view.isolation_memory.clone();
        if let Some(path) = &self.document.path {
            memory.remember(path, &self.view.isolation);
        }
        memory
    }

    /// Recent files.
    #[must_use]
    pub fn recent(&self) -> &RecentFiles {
        &self.recent
    }

    /// The end of a clean session: nothing left to recover.
    pub fn on_clean_exit(&mut self) {
        self.autosave.clear();
    }

    /// Persists editor state (recent files, toolbar, views per file) in eframe's storage.
    pub fn save_state(&self, storage: &mut dyn eframe::Storage) {
        if self.screenshot.is_none() {
            self.recent.save(storage);
            self.view.preview_settings.save(storage);
            self.view_memory().save(storage);
            self.tools.file_dialogs.save_setting(storage);
            self.isolation_memory().save(storage);
        }
    }

    /// Whether this run only takes a screenshot (and must not touch stored state).
    #[must_use]
    pub fn is_screenshot_run(&self) -> bool {
        self.screenshot.is_some()
    }
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
