//! The document: the scene being edited, its file, what was last saved, the undo history
//! and the selection the edits act on. A new document (New, Open, Import, a restore)
//! replaces all of it at once.

use std::path::{Path, PathBuf};

use egui::util::undoer::{Settings as UndoSettings, Undoer};

use super::mesh_fit::PendingFit;
use crate::scene::Scene;
use crate::ui::commands::Selection;

/// The scene being edited and everything that belongs to it as a file.
pub struct Document {
    /// The scene being edited.
    pub scene: Scene,
    /// The scene as last loaded or saved: unsaved changes are a difference from it.
    pub saved: Scene,
    /// The scene's file, if it has one.
    pub path: Option<PathBuf>,
    /// The course text file the scene was imported from, while it has no file of its own.
    pub imported_from: Option<PathBuf>,
    /// What stands for the file name when there is none ("default scene", "untitled").
    pub unnamed: &'static str,
    /// What the inspector shows, and what edits of the selection act on.
    pub selection: Selection,
    /// The undo history of the scene.
    pub undoer: Undoer<Scene>,
    /// Whether an imported OBJ is scaled to a unit box once its size is known (a File
    /// menu switch kept across documents).
    pub fit_imported_meshes: bool,
    /// The mesh imported last, until the preview knows its size.
    pub(super) pending_fit: Option<PendingFit>,
}

impl Document {
    /// `scene` as an unsaved document without a file, called `unnamed`.
    #[must_use]
    pub fn new(scene: Scene, unnamed: &'static str) -> Self {
        let mut document = Self {
            saved: scene.clone(),
            scene,
            path: None,
            imported_from: None,
            unnamed,
            selection: Selection::None,
            undoer: undoer(),
            fit_imported_meshes: true,
            pending_fit: None,
        };
        document.undoer.add_undo(&document.scene);
        document
    }

    /// Makes `scene` (from `path`, if any) the document, as loaded: fresh undo history,
    /// nothing unsaved, nothing selected, no import source.
    pub fn replace(&mut self, scene: Scene, path: Option<PathBuf>) {
        self.saved = scene.clone();
        self.scene = scene;
        self.path = path;
        self.imported_from = None;
        self.undoer = undoer();
        self.undoer.add_undo(&self.scene);
        self.selection = Selection::None;
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

    /// Whether Redo would do something.
    #[must_use]
    pub fn can_redo(&self) -> bool {
        self.undoer.has_redo(&self.scene)
    }

    /// The scene's file name; for an import not saved yet, the file it came from
    /// ("snowman.txt (imported)").
    #[must_use]
    pub fn file_label(&self) -> String {
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
    #[must_use]
    pub fn document_file(&self) -> Option<&Path> {
        self.path.as_deref().or(self.imported_from.as_deref())
    }

    /// Where the scene's mesh files are found: its file's folder, or the folder of the
    /// course file it was imported from (whose mesh paths are relative to it).
    #[must_use]
    pub fn scene_folder(&self) -> Option<&Path> {
        self.document_file().and_then(Path::parent)
    }
}

/// A fresh undo history.
fn undoer() -> Undoer<Scene> {
    Undoer::with_settings(UndoSettings {
        max_undos: 200,
        ..UndoSettings::default()
    })
}
