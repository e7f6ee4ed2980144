//! The editor's state and its frame: panels push commands, which are applied once per
//! frame; the result feeds undo, the title and the preview.

use std::path::{Path, PathBuf};

use egui::util::undoer::{Settings as UndoSettings, Undoer};

use crate::scene::Scene;
use crate::trace::Isolation;
use crate::ui::bug_gallery::BugGallery;
use crate::ui::commands::{Command, Selection};
use crate::ui::compare::CompareSession;
use crate::ui::document::autosave::Autosave;
use crate::ui::document::confirm::DiscardAction;
use crate::ui::document::export::ExportState;
use crate::ui::document::file_dialog::FileDialogs;
use crate::ui::document::files;
use crate::ui::document::native_dialogs::NativeDialogs;
use crate::ui::document::recent::RecentFiles;
use crate::ui::panels::status_bar::StatusMessage;
use crate::ui::screenshot::ScreenshotHook;
use crate::ui::state::PreviewSettings;
use crate::ui::state::keep_in_range;
use crate::ui::stored::Stored;
use crate::ui::viewport::isolation_memory::IsolationMemory;
use crate::ui::viewport::preview_link::PreviewLink;

mod apply;
mod document;
mod frame;
mod looking;
mod mesh_fit;
mod view_state;

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

/// The editor.
pub struct EditorApp {
    scene: Scene,
    /// The scene as last loaded or saved: unsaved changes are a difference from it.
    saved: Scene,
    path: Option<PathBuf>,
    /// The course text file the scene was imported from, while it has no file of its own.
    imported_from: Option<PathBuf>,
    /// Whether an imported OBJ is scaled to a unit box once its size is known.
    fit_imported_meshes: bool,
    /// The mesh imported last, until the preview knows its size.
    pending_fit: Option<mesh_fit::PendingFit>,
    /// What stands for the file name when there is none ("default scene", "untitled").
    unnamed: &'static str,
    selection: Selection,
    undoer: Undoer<Scene>,
    commands: Vec<Command>,
    preview_enabled: bool,
    preview: Option<PreviewLink>,
    /// The toolbar's switches, view and overlays (editor state).
    preview_settings: PreviewSettings,
    /// The view camera, the inspected and pinned pixels, the probes (never the scene).
    looking: looking::Looking,
    /// Lights muted or solo, objects hidden (editor state, remembered per file).
    isolation: Isolation,
    /// The isolation of every file that has some, for the next time it opens.
    isolation_memory: IsolationMemory,
    export: ExportState,
    /// File > Compare with Image: the running or shown comparison.
    compare: CompareSession,
    /// File > Bug gallery: the scene under each bug of the catalogue.
    bug_gallery: BugGallery,
    recent: RecentFiles,
    pending: Option<DiscardAction>,
    /// An action to do once the Save As dialog has saved the scene ("Save" in the
    /// unsaved-changes question of an untitled scene).
    after_save: Option<DiscardAction>,
    file_dialogs: FileDialogs,
    /// The folder of the last file picked in a dialog: the next dialog starts there when
    /// the scene has no file of its own (an import, a new scene).
    last_folder: Option<std::path::PathBuf>,
    error: Option<String>,
    /// Something the user should know that is not a failure (an import's warnings).
    warning: Option<String>,
    message: Option<StatusMessage>,
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
        let looking = looking::Looking::new(&scene);
        let mut app = Self {
            saved: scene.clone(),
            scene,
            path: None,
            imported_from: None,
            fit_imported_meshes: true,
            pending_fit: None,
            unnamed: "default scene",
            selection: Selection::None,
            undoer: undoer(),
            commands: Vec::new(),
            preview_enabled: options.preview,
            preview: None,
            preview_settings: PreviewSettings::default(),
            looking,
            isolation: Isolation::NONE,
            isolation_memory: IsolationMemory::default(),
            export: ExportState::default(),
            compare: CompareSession::default(),
            bug_gallery: BugGallery::default(),
            recent,
            pending: None,
            after_save: None,
            file_dialogs: FileDialogs::new(options.native_dialogs.resolve(), options.dialog_folder),
            last_folder: None,
            error: None,
            warning: None,
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

    /// Whether Undo would do something (an edit was made since the scene was opened).
    #[must_use]
    pub fn can_undo(&self) -> bool {
        self.undoer.has_undo(&self.scene)
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

    /// The file dialogs (which one is open, the in-app preference).
    #[must_use]
    pub fn file_dialogs(&self) -> &FileDialogs {
        &self.file_dialogs
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

    /// Lights muted or solo and objects hidden, by scene index.
    #[must_use]
    pub fn isolation(&self) -> &Isolation {
        &self.isolation
    }

    /// Installs the per-file isolation memory of an earlier run (read from eframe's
    /// storage at start-up) and brings back the open file's switches.
    pub fn set_isolation_memory(&mut self, memory: IsolationMemory) {
        self.isolation_memory = memory;
        if let Some(path) = &self.path {
            self.isolation = self.isolation_memory.recall(path);
            keep_in_range(&mut self.isolation, &self.scene);
        }
    }

    /// The per-file isolation memory as it would be saved now.
    #[must_use]
    pub fn isolation_memory(&self) -> IsolationMemory {
        let mut memory = self.isolation_memory.clone();
        if let Some(path) = &self.path {
            memory.remember(path, &self.isolation);
        }
        memory
    }

    /// The comparison with another renderer's picture.
    #[must_use]
    pub fn compare(&self) -> &CompareSession {
        &self.compare
    }

    /// The Bug gallery window's state.
    #[must_use]
    pub fn bug_gallery(&self) -> &BugGallery {
        &self.bug_gallery
    }

    /// Recent files.
    #[must_use]
    pub fn recent(&self) -> &RecentFiles {
        &self.recent
    }

    /// The scene's file name; for an import not saved yet, the file it came from
    /// ("snowman.txt (imported)").
    fn file_label(&self) -> String {
        let name = |p: &Path| p.file_name().map(|n| n.to_string_lossy().into_owned());
        if let Some(name) = self.path.as_deref().and_then(name) {
            return name;
        }
        match self.imported_from.as_deref().and_then(name) {
            Some(name) => format!("{name} (imported)"),
            None => self.unnamed.to_owned(),
        }
    }

    /// The file the scene stands for: its own, else the course file it was imported from.
    fn document_file(&self) -> Option<&Path> {
        self.path.as_deref().or(self.imported_from.as_deref())
    }

    /// Where the scene's mesh files are found: its file's folder, or the folder of the
    /// course file it was imported from (whose mesh paths are relative to it).
    fn scene_folder(&self) -> Option<&Path> {
        self.document_file().and_then(Path::parent)
    }

    /// The end of a clean session: nothing left to recover.
    pub fn on_clean_exit(&mut self) {
        self.autosave.clear();
    }

    /// Persists editor state (recent files, toolbar, views per file) in eframe's storage.
    pub fn save_state(&self, storage: &mut dyn eframe::Storage) {
        if self.screenshot.is_none() {
            self.recent.save(storage);
            self.preview_settings.save(storage);
            self.view_memory().save(storage);
            self.file_dialogs.save_setting(storage);
            self.isolation_memory().save(storage);
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
