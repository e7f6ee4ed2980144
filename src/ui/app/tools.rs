//! The editor's tools over the document: the windows that work on it (export, compare
//! with a picture, the bug gallery) and the file dialogs and questions waiting for an
//! answer.

use std::path::PathBuf;

use crate::ui::bug_gallery::BugGallery;
use crate::ui::compare::CompareSession;
use crate::ui::document::confirm::DiscardAction;
use crate::ui::document::export::ExportState;
use crate::ui::document::file_dialog::FileDialogs;

/// The tool windows and dialogs, each with its own state.
pub struct Tools {
    /// File > Export: the export window and its running job.
    pub export: ExportState,
    /// File > Compare with Image: the running or shown comparison.
    pub compare: CompareSession,
    /// File > Bug gallery: the scene under each bug of the catalogue.
    pub bug_gallery: BugGallery,
    /// The file dialogs (which one is open, the in-app preference).
    pub file_dialogs: FileDialogs,
    /// The folder of the last file picked in a dialog: the next dialog starts there when
    /// the scene has no file of its own (an import, a new scene).
    pub last_folder: Option<PathBuf>,
    /// The action waiting for a "discard unsaved changes?" answer.
    pub pending: Option<DiscardAction>,
    /// An action to do once the Save As dialog has saved the scene ("Save" in the
    /// unsaved-changes question of an untitled scene).
    pub after_save: Option<DiscardAction>,
}

impl Tools {
    /// No tool window open, no question waiting; file dialogs as `file_dialogs`.
    #[must_use]
    pub fn new(file_dialogs: FileDialogs) -> Self {
        Self {
            export: ExportState::default(),
            compare: CompareSession::default(),
            bug_gallery: BugGallery::default(),
            file_dialogs,
            last_folder: None,
            pending: None,
            after_save: None,
        }
    }
}
