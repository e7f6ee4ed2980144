//! The document actions of the editor: new, open, save, import, each behind the
//! "discard unsaved changes?" question where they would drop edits.

use std::path::{Path, PathBuf};

use egui::ViewportCommand;

use super::{EditorApp, undoer};
use crate::scene::Scene;
use crate::ui::commands::Selection;
use crate::ui::document::autosave::RestoreAnswer;
use crate::ui::document::confirm::DiscardAction;
use crate::ui::document::files;
use crate::ui::viewport::isolation::keep_in_range;

impl EditorApp {
    /// Does `action` now, or asks first when it would drop unsaved changes.
    pub(super) fn guard(&mut self, action: DiscardAction, ctx: &egui::Context) {
        if self.is_dirty() {
            self.pending = Some(action);
        } else {
            self.perform(action, ctx);
        }
    }

    pub(super) fn perform(&mut self, action: DiscardAction, ctx: &egui::Context) {
        match action {
            DiscardAction::New => {
                self.replace_scene(files::new_scene(), None);
                self.unnamed = "untitled";
            }
            DiscardAction::OpenDialog => {
                if let Some(path) = scene_dialog().pick_file() {
                    self.open(&path);
                }
            }
            DiscardAction::Open(path) => self.open(&path),
            DiscardAction::ImportDialog => {
                if let Some(path) = rfd::FileDialog::new()
                    .set_title("Import legacy scene")
                    .pick_file()
                {
                    self.import(&path);
                }
            }
            DiscardAction::Import(path) => self.import(&path),
            DiscardAction::Quit => {
                self.allow_close = true;
                ctx.send_viewport_cmd(ViewportCommand::Close);
            }
        }
    }

    /// Opens a scene file; on failure the error is shown and the scene stays as it was.
    pub(super) fn open(&mut self, path: &Path) {
        match files::open_scene(path) {
            Ok(scene) => {
                self.replace_scene(scene, Some(path.to_owned()));
                self.recent.push(path);
                self.message = Some(format!("Opened {}", path.display()));
            }
            Err(error) => {
                // A recent file that no longer opens leaves the list.
                self.recent.remove(path);
                self.error = Some(error);
            }
        }
    }

    fn import(&mut self, path: &Path) {
        match files::import_legacy(path) {
            Ok((scene, warnings)) => {
                self.replace_scene(scene, None);
                self.unnamed = "imported scene";
                // An imported scene has no file yet: everything is unsaved.
                self.saved = files::new_scene();
                if !warnings.is_empty() {
                    self.error = Some(format!("Imported with warnings: {}", warnings.join("; ")));
                }
            }
            Err(error) => self.error = Some(format!("{}: {error}", path.display())),
        }
    }

    /// Saves to `path`, which becomes the scene's file; errors are shown.
    pub(super) fn save_as(&mut self, path: &Path) {
        match files::save_scene_to(&self.scene, path) {
            Ok(()) => {
                self.saved = self.scene.clone();
                // The switches stay with the scene, now under its new name.
                self.isolation_memory = self.isolation_memory();
                self.path = Some(path.to_owned());
                self.recent.push(path);
                self.message = Some(format!("Saved {}", path.display()));
            }
            Err(error) => self.error = Some(error),
        }
    }

    pub(super) fn save_as_dialog(&mut self) {
        let name = format!("{}.ron", self.file_label().trim_end_matches(".ron"));
        if let Some(path) = scene_dialog().set_file_name(name).save_file() {
            let path = if files::is_scene_file(&path) {
                path
            } else {
                path.with_extension("ron")
            };
            self.save_as(&path);
        }
    }

    /// A new document: fresh undo history, nothing unsaved, selection cleared, the
    /// isolation switches remembered for the file left and recalled for the file opened.
    pub(super) fn replace_scene(&mut self, scene: Scene, path: Option<PathBuf>) {
        self.isolation_memory = self.isolation_memory();
        self.isolation = path.as_deref().map_or(crate::trace::Isolation::NONE, |p| {
            self.isolation_memory.recall(p)
        });
        keep_in_range(&mut self.isolation, &scene);
        self.saved = scene.clone();
        self.scene = scene;
        self.path = path;
        self.undoer = undoer();
        self.undoer.add_undo(&self.scene);
        self.selection = Selection::None;
        self.error = None;
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
    pub(super) fn restore(&mut self, answer: RestoreAnswer) {
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
}

fn scene_dialog() -> rfd::FileDialog {
    rfd::FileDialog::new().add_filter("raylab scene", &["ron"])
}
