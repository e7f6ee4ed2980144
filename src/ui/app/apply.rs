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
            let lists = (
                self.document.scene.objects.len(),
                self.document.scene.lights.len(),
            );
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
            let anchors = (!self.view.isolation.is_none()
                && matches!(&command, Command::Undo | Command::Redo | Command::Edit(_)))
            .then(|| IsolationAnchors::take(&self.document.scene, &self.view.isolation));
            let undo = matches!(command, Command::Undo | Command::Redo);
            self.execute(command, ctx);
            let lists_changed = lists
                != (
                    self.document.scene.objects.len(),
                    self.document.scene.lights.len(),
                );
            if let Some(anchors) = anchors
                && (undo || lists_changed)
            {
                self.view.isolation = anchors.follow(&self.document.scene);
            }
            reshuffled |= may_reshuffle || lists_changed;
        }
        repair_selection(&self.document.scene, &mut self.document.selection);
        keep_in_range(&mut self.view.isolation, &self.document.scene);
        let editing = ctx.input(|i| i.pointer.any_down()) || ctx.text_edit_focused();
        if !editing {
            self.document.undoer.add_undo(&self.document.scene);
        }
    }

    pub(super) fn execute(&mut self, command: Command, ctx: &egui::Context) {
        match command {
            Command::Select(selection) => self.document.selection = selection,
            Command::Edit(edit) => self.edit(edit),
            Command::Undo => {
                if let Some(scene) = self.document.undoer.undo(&self.document.scene) {
                    self.document.scene = scene.clone();
                    self.forget_notice();
                }
            }
            Command::Redo => {
                if let Some(scene) = self.document.undoer.redo(&self.document.scene) {
                    self.document.scene = scene.clone();
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
            Command::Save => match self.document.path.clone() {
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
                let document = self.document.document_file().map(std::path::Path::to_owned);
                self.tools
                    .export
                    .show(&self.document.scene, document.as_deref());
            }
            Command::ShowHelp => self.view.show_help = !self.view.show_help,
            Command::BrowseExportPath => self.request_dialog(DialogPurpose::ExportPng, ctx),
            Command::ExportCourseDialog(dialect) => {
                self.request_dialog(DialogPurpose::ExportCourse(dialect), ctx);
            }
            Command::ExportCourse(path, dialect) => self.export_course(&path, dialect),
            Command::ImportObjDialog => self.request_dialog(DialogPurpose::ImportObj, ctx),
            Command::ImportObj(path) => self.import_obj(&path),
            Command::CancelMeshLoading => {
                if let Some(preview) = &self.view.preview {
                    preview.cancel_loading();
                }
            }
            Command::BrowseCompareImage => self.request_dialog(DialogPurpose::CompareImage, ctx),
            Command::SetPreferInAppFileDialog(prefer) => {
                self.tools.file_dialogs.prefer_in_app = prefer
            }
            Command::SetFitImportedMeshes(fit) => self.document.fit_imported_meshes = fit,
            Command::DismissError => self.error = None,
            Command::DismissWarning => self.warning = None,
            Command::FocusName => self.view.focus_name = true,
            Command::SetPreviewSettings(settings) => self.view.preview_settings = settings,
            Command::InspectPixel(pixel) => self.view.looking.inspected = pixel,
            Command::Pick(request) => {
                self.view
                    .looking
                    .pick(&self.document.scene, &self.view.isolation, request)
            }
            Command::SetView(view) => self.view.looking.camera = view,
            Command::ToggleCameraView => {
                let view = &mut self.view.looking.camera;
                // Leaving camera view starts from where the scene camera is, not from a
                // pose left over from earlier (another scene, a moved camera).
                *view = if view.through_scene_camera {
                    ViewCamera::free(&self.document.scene.camera)
                } else {
                    ViewCamera::through(&self.document.scene.camera)
                };
            }
            Command::SetSceneCameraFromView => {
                let camera = self
                    .view
                    .looking
                    .camera
                    .as_scene_camera(&self.document.scene.camera);
                self.edit(SceneEdit::SetCamera(camera));
                self.view.looking.camera = ViewCamera::through(&self.document.scene.camera);
            }
            Command::SetRayPaths(settings) => self.view.looking.ray_paths = settings,
            Command::ShowCompare => self.tools.compare.show_window(),
            Command::CompareWith(path) => {
                let folder = self.document.scene_folder().map(std::path::Path::to_owned);
                self.tools
                    .compare
                    .start(&self.document.scene, folder.as_deref(), &path, ctx);
            }
            Command::ShowBugGallery => {
                let folder = self.document.scene_folder().map(std::path::Path::to_owned);
                self.tools
                    .bug_gallery
                    .show(&self.document.scene, folder.as_deref(), ctx);
            }
            Command::CompareWithGalleryPicture(index) => {
                if let Some(picture) = self.tools.bug_gallery.picture_to_compare(index) {
                    self.tools.compare.start_picture(picture, ctx);
                }
            }
            Command::Isolate(toggle) => toggle.apply(&mut self.view.isolation),
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
        if let Err(error) = edit.apply(&mut self.document.scene, &mut self.document.selection) {
            self.error = Some(error);
        }
    }
}
