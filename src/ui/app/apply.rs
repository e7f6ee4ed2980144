//! Applying the frame's commands: the one place the scene changes, which also records
//! undo steps.

use crate::ui::commands::{Command, SceneEdit, repair_selection};
use crate::ui::document::confirm::DiscardAction;
use crate::ui::document::file_dialog::DialogPurpose;
use crate::ui::state::ViewCamera;
use crate::ui::state::{IsolationAnchors, keep_in_range};

use super::EditorApp;

impl EditorApp {
    /// Applies this frame's commands, then records an undo point unless an edit is still
    /// in progress (a drag or a text field), so a whole drag is one step.
    pub(super) fn apply_commands(&mut self, ctx: &egui::Context) {
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
            // The isolation switches follow their items through a reshuffle of this
            // document (opening another brings that file's own switches).
            let anchors = (!self.isolation.is_none()
                && matches!(&command, Command::Undo | Command::Redo | Command::Edit(_)))
            .then(|| IsolationAnchors::take(&self.scene, &self.isolation));
            let undo = matches!(command, Command::Undo | Command::Redo);
            self.execute(command, ctx);
            let lists_changed = lists != (self.scene.objects.len(), self.scene.lights.len());
            if let Some(anchors) = anchors
                && (undo || lists_changed)
            {
                self.isolation = anchors.follow(&self.scene);
            }
            reshuffled |= may_reshuffle || lists_changed;
        }
        repair_selection(&self.scene, &mut self.selection);
        keep_in_range(&mut self.isolation, &self.scene);
        let editing = ctx.input(|i| i.pointer.any_down()) || ctx.text_edit_focused();
        if !editing {
            self.undoer.add_undo(&self.scene);
        }
    }

    pub(super) fn execute(&mut self, command: Command, ctx: &egui::Context) {
        match command {
            Command::Select(selection) => self.selection = selection,
            Command::Edit(edit) => self.edit(edit),
            Command::Undo => {
                if let Some(scene) = self.undoer.undo(&self.scene) {
                    self.scene = scene.clone();
                    self.forget_notice();
                }
            }
            Command::Redo => {
                if let Some(scene) = self.undoer.redo(&self.scene) {
                    self.scene = scene.clone();
                    self.forget_notice();
                }
            }
            Command::New => self.guard(DiscardAction::New, ctx),
            Command::OpenDialog => self.guard(DiscardAction::OpenDialog, ctx),
            Command::Open(path) => self.guard(DiscardAction::Open(path), ctx),
            Command::OpenInFolder { forward } => self.open_in_folder(forward, ctx),
            Command::ImportLegacyDialog => self.guard(DiscardAction::ImportDialog, ctx),
            Command::ImportLegacy(path) => self.guard(DiscardAction::Import(path), ctx),
            Command::Quit => self.guard(DiscardAction::Quit, ctx),
            Command::Save => match self.path.clone() {
                Some(path) => {
                    self.save_as(&path);
                }
                None => self.save_as_dialog(ctx),
            },
            Command::SaveAsDialog => self.save_as_dialog(ctx),
            Command::SaveAs(path) => {
                self.save_as(&path);
            }
            Command::ShowExport => {
                let document = self.document_file().map(std::path::Path::to_owned);
                self.export.show(&self.scene, document.as_deref());
            }
            Command::ShowHelp => self.show_help = !self.show_help,
            Command::BrowseExportPath => self.request_dialog(DialogPurpose::ExportPng, ctx),
            Command::ExportCourseDialog(dialect) => {
                self.request_dialog(DialogPurpose::ExportCourse(dialect), ctx);
            }
            Command::ExportCourse(path, dialect) => self.export_course(&path, dialect),
            Command::ImportObjDialog => self.request_dialog(DialogPurpose::ImportObj, ctx),
            Command::ImportObj(path) => self.import_obj(&path),
            Command::CancelMeshLoading => {
                if let Some(preview) = &self.preview {
                    preview.cancel_loading();
                }
            }
            Command::BrowseCompareImage => self.request_dialog(DialogPurpose::CompareImage, ctx),
            Command::SetPreferInAppFileDialog(prefer) => self.file_dialogs.prefer_in_app = prefer,
            Command::SetFitImportedMeshes(fit) => self.fit_imported_meshes = fit,
            Command::DismissError => self.error = None,
            Command::DismissWarning => self.warning = None,
            Command::FocusName => self.focus_name = true,
            Command::SetPreviewSettings(settings) => self.preview_settings = settings,
            Command::InspectPixel(pixel) => self.looking.inspected = pixel,
            Command::Pick(request) => self.looking.pick(&self.scene, &self.isolation, request),
            Command::SetView(view) => self.looking.view = view,
            Command::ToggleCameraView => {
                let view = &mut self.looking.view;
                // Leaving camera view starts from where the scene camera is, not from a
                // pose left over from earlier (another scene, a moved camera).
                *view = if view.through_scene_camera {
                    ViewCamera::free(&self.scene.camera)
                } else {
                    ViewCamera::through(&self.scene.camera)
                };
            }
            Command::SetSceneCameraFromView => {
                let camera = self.looking.view.as_scene_camera(&self.scene.camera);
                self.edit(SceneEdit::SetCamera(camera));
                self.looking.view = ViewCamera::through(&self.scene.camera);
            }
            Command::SetRayPaths(settings) => self.looking.ray_paths = settings,
            Command::ShowCompare => self.compare.show_window(),
            Command::CompareWith(path) => {
                let folder = self.scene_folder().map(std::path::Path::to_owned);
                self.compare
                    .start(&self.scene, folder.as_deref(), &path, ctx);
            }
            Command::ShowBugGallery => {
                let folder = self.scene_folder().map(std::path::Path::to_owned);
                self.bug_gallery.show(&self.scene, folder.as_deref(), ctx);
            }
            Command::CompareWithGalleryPicture(index) => {
                if let Some(picture) = self.bug_gallery.picture_to_compare(index) {
                    self.compare.start_picture(picture, ctx);
                }
            }
            Command::Isolate(toggle) => toggle.apply(&mut self.isolation),
        }
    }

    /// A notice about a typed value speaks of a value an undo or redo has just replaced:
    /// it goes.
    fn forget_notice(&mut self) {
        if self.message.as_ref().is_some_and(|m| m.notice) {
            self.message = None;
        }
    }

    pub(super) fn edit(&mut self, edit: SceneEdit) {
        if let Err(error) = edit.apply(&mut self.scene, &mut self.selection) {
            self.error = Some(error);
        }
    }
}
