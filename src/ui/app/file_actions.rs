//! The document actions of the editor: new, open, save, import, each behind the
//! "unsaved changes: save, discard or cancel?" question where they would drop edits,
//! and what a file dialog's answer does.

use std::path::{Path, PathBuf};

use egui::ViewportCommand;

use super::EditorApp;
use crate::scene::Scene;
use crate::scene::legacy::{Dialect, export_course_file, year};
use crate::ui::commands::SceneEdit;
use crate::ui::document::autosave::RestoreAnswer;
use crate::ui::document::confirm::{DiscardAction, DiscardAnswer};
use crate::ui::document::file_dialog::{DialogOutcome, DialogPurpose};
use crate::ui::document::files;
use crate::ui::panels::status_bar::StatusMessage;
use crate::ui::state::keep_in_range;

impl EditorApp {
    /// Does `action` now, or asks first when it would drop unsaved changes.
    pub(super) fn guard(&mut self, action: DiscardAction, ctx: &egui::Context) {
        if self.document.is_dirty() {
            self.tools.pending = Some(action);
        } else {
            self.perform(action, ctx);
        }
    }

    pub(super) fn perform(&mut self, action: DiscardAction, ctx: &egui::Context) {
        match action {
            DiscardAction::New => {
                self.replace_scene(files::new_scene(), None);
                self.document.unnamed = "untitled";
            }
            DiscardAction::OpenDialog => self.request_dialog(DialogPurpose::OpenScene, ctx),
            DiscardAction::Open(path) => self.open(&path),
            DiscardAction::ImportDialog => self.request_dialog(DialogPurpose::ImportLegacy, ctx),
            DiscardAction::Import(path) => self.import(&path),
            DiscardAction::Quit => {
                self.allow_close = true;
                ctx.send_viewport_cmd(ViewportCommand::Close);
            }
        }
    }

    /// The answer to the unsaved-changes question about `action`.
    pub(super) fn answer_discard(
        &mut self,
        action: DiscardAction,
        answer: DiscardAnswer,
        ctx: &egui::Context,
    ) {
        match answer {
            DiscardAnswer::Save => match self.document.path.clone() {
                Some(path) => {
                    if self.save_as(&path) {
                        self.perform(action, ctx);
                    }
                }
                None => {
                    self.tools.after_save = Some(action);
                    self.save_as_dialog(ctx);
                }
            },
            DiscardAnswer::Discard => self.perform(action, ctx),
            DiscardAnswer::Cancel => {}
        }
    }

    /// Opens a file dialog for `purpose`, in the scene's folder; errors are shown.
    pub(super) fn request_dialog(&mut self, purpose: DialogPurpose, ctx: &egui::Context) {
        let folder = match purpose {
            DialogPurpose::ExportPng => {
                let typed = PathBuf::from(self.tools.export.path.trim());
                typed.parent().filter(|p| p.is_dir()).map(Path::to_owned)
            }
            _ => None,
        }
        .or_else(|| {
            self.document
                .path
                .as_deref()
                .and_then(Path::parent)
                .map(Path::to_owned)
        })
        .or_else(|| self.tools.last_folder.clone());
        let name = match purpose {
            DialogPurpose::ExportPng => PathBuf::from(self.tools.export.path.trim())
                .file_name()
                .map_or_else(
                    || "render.png".to_owned(),
                    |n| n.to_string_lossy().into_owned(),
                ),
            DialogPurpose::ExportCourse(_) => {
                match self.document.document_file().and_then(Path::file_stem) {
                    Some(stem) => format!("{}.txt", stem.to_string_lossy()),
                    None => format!("{}.txt", self.document.unnamed),
                }
            }
            _ => match self.document.document_file().and_then(Path::file_stem) {
                Some(stem) => format!("{}.ron", stem.to_string_lossy()),
                None => format!("{}.ron", self.document.unnamed),
            },
        };
        if let Err(error) = self
            .tools
            .file_dialogs
            .request(purpose, folder.as_deref(), &name, ctx)
        {
            self.error = Some(format!("cannot show the file dialog: {error}"));
        }
    }

    /// Shows the open file dialog, if any, and acts on its answer.
    pub(super) fn file_dialog_ui(&mut self, ctx: &egui::Context) {
        let Some((purpose, outcome)) = self.tools.file_dialogs.ui(ctx) else {
            return;
        };
        let after = if purpose == DialogPurpose::SaveSceneAs {
            self.tools.after_save.take()
        } else {
            None
        };
        let path = match outcome {
            DialogOutcome::Picked(path) => {
                self.tools.last_folder = path.parent().map(Path::to_owned);
                path
            }
            DialogOutcome::Cancelled => return,
            DialogOutcome::Failed(error) => {
                self.error = Some(format!("the file dialog failed: {error}"));
                return;
            }
        };
        match purpose {
            DialogPurpose::OpenScene => self.open(&path),
            DialogPurpose::ImportLegacy => self.import(&path),
            DialogPurpose::ImportObj => self.import_obj(&path),
            DialogPurpose::SaveSceneAs => {
                let path = if files::is_scene_file(&path) {
                    path
                } else {
                    path.with_extension("ron")
                };
                if self.save_as(&path)
                    && let Some(action) = after
                {
                    self.perform(action, ctx);
                }
            }
            DialogPurpose::ExportPng => {
                self.tools.export.path = files::with_png_extension(path).display().to_string();
            }
            DialogPurpose::CompareImage => {
                self.tools.compare.path_text = path.display().to_string()
            }
            DialogPurpose::ExportCourse(dialect) => {
                let path = if path.extension().is_some() {
                    path
                } else {
                    path.with_extension("txt")
                };
                self.export_course(&path, dialect);
            }
        }
    }

    /// Writes the scene in the course's text format, in `dialect`, to `path` (mesh paths
    /// made relative to it). What the dialect loses is shown as a warning naming each
    /// object, light or material; a scene it cannot say writes nothing and shows every
    /// refusal as the error.
    pub(super) fn export_course(&mut self, path: &Path, dialect: Dialect) {
        // An untitled scene's mesh paths are relative to the working directory.
        let folder = self
            .document
            .path
            .as_deref()
            .and_then(Path::parent)
            .unwrap_or(Path::new(""));
        match export_course_file(&self.document.scene, folder, path, dialect) {
            Ok(warnings) => {
                self.message = Some(StatusMessage::done(format!(
                    "Exported {} ({} framework's dialect)",
                    path.display(),
                    year(dialect)
                )));
                self.warning = (!warnings.is_empty()).then(|| {
                    let lines: Vec<String> = warnings.iter().map(ToString::to_string).collect();
                    format!("Exported with warnings: {}", lines.join("; "))
                });
            }
            Err(error) => self.error = Some(error.to_string()),
        }
    }

    /// Opens a scene file; on failure the error is shown and the scene stays as it was.
    pub(super) fn open(&mut self, path: &Path) {
        match files::open_scene(path) {
            Ok(files::Opened::Legacy(import)) => {
                let summary = import.summary();
                self.take_import(path, import.scene, &summary, &import.warnings);
            }
            Ok(files::Opened::Scene(scene)) => {
                self.replace_scene(*scene, Some(path.to_owned()));
                self.recent.push(path);
                self.message = Some(StatusMessage::done(format!("Opened {}", path.display())));
            }
            Err(error) => {
                // A recent file that does not open now (an unplugged drive, a share
                // that is down) stays in the list, marked.
                self.recent.mark_failed(path);
                self.error = Some(error);
            }
        }
    }

    fn import(&mut self, path: &Path) {
        match files::import_legacy(path) {
            Ok((scene, summary, warnings)) => self.take_import(path, scene, &summary, &warnings),
            Err(error) => self.error = Some(format!("{}: {error}", path.display())),
        }
    }

    /// Makes an imported course scene the document. It has no file of its own yet, but
    /// an untouched import is no change: the course file still holds it, so opening
    /// another asks nothing; the title names the file it came from.
    fn take_import(&mut self, path: &Path, scene: Scene, summary: &str, warnings: &[String]) {
        self.replace_scene(scene, None);
        self.document.imported_from = Some(path.to_owned());
        self.document.unnamed = "imported scene";
        self.message = Some(StatusMessage::done(format!(
            "Imported {} (not saved yet), {summary}",
            path.display()
        )));
        if !warnings.is_empty() {
            self.warning = Some(format!("Imported with warnings: {}", warnings.join("; ")));
        }
    }

    /// Opens the scene file after (or before) the current one in its folder, asking
    /// first about unsaved changes; says so when there is none.
    pub(super) fn open_in_folder(&mut self, forward: bool, ctx: &egui::Context) {
        let Some(current) = self.document.document_file().map(Path::to_owned) else {
            self.error = Some("this scene has no file, so no folder to go through".to_owned());
            return;
        };
        match crate::ui::document::folder_scenes::neighbour_scene(&current, forward) {
            Some(next) => self.guard(DiscardAction::Open(next), ctx),
            None => {
                let which = if forward { "last" } else { "first" };
                self.message = Some(StatusMessage::done(format!(
                    "{} is the {which} scene in its folder",
                    current.display()
                )));
            }
        }
    }

    /// Adds a Mesh object for the OBJ file at `path`, named after the file, in one undo
    /// step. The scene refers to the file (relative to the scene's folder where it lies
    /// under it, else in full) and never rewrites it; the preview reads it off this
    /// thread and names any problem with it.
    pub(super) fn import_obj(&mut self, path: &Path) {
        let folder = self.document.scene_folder();
        let written = folder
            .and_then(|folder| path.strip_prefix(folder).ok())
            .unwrap_or(path);
        let Some(text) = written.to_str() else {
            self.error = Some(format!(
                "{}: a scene file cannot hold this path (it is not UTF-8)",
                path.display()
            ));
            return;
        };
        self.edit(SceneEdit::AddMesh(text.replace('\\', "/")));
        self.document.pending_fit = self
            .document
            .fit_imported_meshes
            .then(|| {
                let index = self.document.scene.objects.len().checked_sub(1)?;
                let added = self.document.scene.objects[index].clone();
                Some(super::mesh_fit::PendingFit { index, added })
            })
            .flatten();
        self.message = Some(StatusMessage::done(format!(
            "Added the mesh {}",
            path.display()
        )));
    }

    /// Saves to `path`, which becomes the scene's file; errors are shown. Returns
    /// whether the scene was saved.
    pub(super) fn save_as(&mut self, path: &Path) -> bool {
        // A mesh added by its full path before the scene had a file is stored relative to
        // the scene when it lies below it, so the folder can move as a whole.
        let mut scene = self.document.scene.clone();
        if let Some(folder) = path.parent().and_then(|f| std::path::absolute(f).ok()) {
            crate::scene::mesh_file::relative_mesh_paths(&mut scene, &folder);
        }
        match files::save_scene_to(&scene, path) {
            Ok(()) => {
                self.document.scene = scene;
                self.document.saved = self.document.scene.clone();
                // The switches stay with the scene, now under its new name.
                self.view.isolation_memory = self.isolation_memory();
                self.document.path = Some(path.to_owned());
                self.recent.push(path);
                self.message = Some(StatusMessage::done(format!("Saved {}", path.display())));
                true
            }
            Err(error) => {
                self.error = Some(error);
                false
            }
        }
    }

    pub(super) fn save_as_dialog(&mut self, ctx: &egui::Context) {
        self.request_dialog(DialogPurpose::SaveSceneAs, ctx);
    }

    /// A new document: fresh undo history, nothing unsaved, selection cleared, the view
    /// its file was left with (or its camera's), the isolation switches remembered for
    /// the file left and recalled for the file opened.
    pub(super) fn replace_scene(&mut self, scene: Scene, path: Option<PathBuf>) {
        if let Some(old) = &self.document.path {
            self.view
                .looking
                .memory
                .remember(old, &self.view.looking.camera);
        }
        self.view.isolation_memory = self.isolation_memory();
        self.view.isolation = path.as_deref().map_or(crate::trace::Isolation::NONE, |p| {
            self.view.isolation_memory.recall(p)
        });
        keep_in_range(&mut self.view.isolation, &scene);
        self.document.replace(scene, path);
        self.view
            .looking
            .reset(&self.document.scene, self.document.path.as_deref());
        self.error = None;
        self.warning = None;
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
        self.document.saved = saved;
        self.message = Some(StatusMessage::done(
            "Restored unsaved work from the last session".to_owned(),
        ));
    }
}
