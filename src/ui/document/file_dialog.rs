//! The file dialogs behind Open, Save As, Import and Export's Browse. A native dialog
//! runs on a thread of its own, so the window keeps drawing while it is open; where no
//! native dialog can be shown (see [`super::native_dialogs`]), or when the user prefers
//! it, an in-app dialog (egui_file) opens instead. Either way the answer comes back
//! through [`FileDialogs::ui`], once per frame.

use std::future::Future;
use std::path::{Path, PathBuf};
use std::pin::Pin;
use std::sync::Arc;

use crate::preview::BackgroundJob;

/// Storage key of the "prefer the in-app dialog" setting.
const KEY: &str = "raylab.prefer_in_app_file_dialog";

/// What a file dialog is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DialogPurpose {
    /// File > Open…
    OpenScene,
    /// File > Save As… (and Save of an untitled scene).
    SaveSceneAs,
    /// File > Import Legacy…
    ImportLegacy,
    /// Export PNG > Browse…
    ExportPng,
    /// Compare with Image > Browse… (a PNG or PPM).
    CompareImage,
    /// File > Import OBJ Mesh…
    ImportObj,
    /// File > Export Course Scene… (the course's text format, in a dialect).
    ExportCourse(crate::scene::legacy::Dialect),
}

impl DialogPurpose {
    /// The dialog's title.
    #[must_use]
    pub fn title(self) -> &'static str {
        match self {
            // The titles of filtered dialogs say what they show.
            DialogPurpose::OpenScene => "Open scene (.ron, or a course .txt)",
            DialogPurpose::SaveSceneAs => "Save scene as (.ron)",
            DialogPurpose::ImportLegacy => "Import legacy scene",
            DialogPurpose::ExportPng => "Export PNG to (.png)",
            DialogPurpose::CompareImage => "Compare with image",
            DialogPurpose::ImportObj => "Import OBJ mesh (.obj)",
            DialogPurpose::ExportCourse(crate::scene::legacy::Dialect::Framework2020) => {
                "Export course scene, 2020 dialect (.txt)"
            }
            DialogPurpose::ExportCourse(crate::scene::legacy::Dialect::Framework2016) => {
                "Export course scene, 2016 dialect (.txt)"
            }
        }
    }

    /// Whether it asks for a file to write.
    #[must_use]
    pub fn is_save(self) -> bool {
        matches!(
            self,
            DialogPurpose::SaveSceneAs | DialogPurpose::ExportPng | DialogPurpose::ExportCourse(_)
        )
    }

    /// The filter's name and extensions, if the dialog shows some kinds of file only.
    fn filter(self) -> Option<(&'static str, &'static [&'static str])> {
        match self {
            DialogPurpose::OpenScene => Some(("raylab or course scene", &["ron", "txt"])),
            DialogPurpose::SaveSceneAs => Some(("raylab scene", &["ron"])),
            DialogPurpose::ExportPng => Some(("PNG image", &["png"])),
            DialogPurpose::ImportObj => Some(("Wavefront OBJ mesh", &["obj"])),
            DialogPurpose::ExportCourse(_) => Some(("course text scene", &["txt"])),
            DialogPurpose::ImportLegacy | DialogPurpose::CompareImage => None,
        }
    }
}

/// How a dialog ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DialogOutcome {
    /// The user chose this file.
    Picked(PathBuf),
    /// The user closed the dialog without choosing.
    Cancelled,
    /// The dialog could not be shown or crashed; the message says why.
    Failed(String),
}

/// The dialog on screen.
enum OpenDialog {
    Native(BackgroundJob<Option<PathBuf>>),
    InApp(Box<egui_file::FileDialog>),
}

/// What a native dialog is asked for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DialogRequest {
    /// What it is for (its title, filter, open or save).
    pub purpose: DialogPurpose,
    /// The folder it opens in.
    pub folder: PathBuf,
    /// The file name it suggests for a save.
    pub file_name: String,
}

/// The answer of a native dialog, waited for off the UI thread.
pub type PathFuture = Pin<Box<dyn Future<Output = Option<PathBuf>> + Send>>;

/// Opens a native dialog (on the UI thread, as some desktops need) and returns the
/// future of its answer.
pub type NativeDialog = Arc<dyn Fn(&DialogRequest) -> PathFuture + Send + Sync>;

/// The editor's file dialogs: at most one open at a time.
pub struct FileDialogs {
    native: Option<NativeDialog>,
    /// The user's setting: use the in-app dialog even where a native one exists.
    pub prefer_in_app: bool,
    /// Where a dialog opens when the scene has no folder of its own.
    start_folder: Option<PathBuf>,
    open: Option<(DialogPurpose, OpenDialog)>,
}

impl FileDialogs {
    /// Dialogs for a desktop with this `native` dialog (or none); `start_folder` is
    /// where they open by default (the working folder otherwise).
    #[must_use]
    pub fn new(native: Option<NativeDialog>, start_folder: Option<PathBuf>) -> Self {
        Self {
            native,
            prefer_in_app: false,
            start_folder,
            open: None,
        }
    }

    /// The "prefer the in-app dialog" setting saved by an earlier run (off if none).
    #[must_use]
    pub fn stored_preference(storage: Option<&dyn eframe::Storage>) -> bool {
        storage
            .and_then(|s| eframe::get_value(s, KEY))
            .unwrap_or(false)
    }

    /// Writes the setting to storage.
    pub fn save_setting(&self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, KEY, &self.prefer_in_app);
    }

    /// Whether a native dialog can be shown on this desktop.
    #[must_use]
    pub fn native_available(&self) -> bool {
        self.native.is_some()
    }

    /// Whether the next dialog is the in-app one.
    #[must_use]
    pub fn uses_in_app(&self) -> bool {
        self.prefer_in_app || self.native.is_none()
    }

    /// The purpose of the dialog on screen, if one is.
    #[must_use]
    pub fn open_purpose(&self) -> Option<DialogPurpose> {
        self.open.as_ref().map(|(purpose, _)| *purpose)
    }

    /// Opens a dialog for `purpose` in `folder` (or the start folder), suggesting
    /// `file_name` for a save.
    ///
    /// # Errors
    /// A dialog is already open, or the thread for a native one cannot start.
    pub fn request(
        &mut self,
        purpose: DialogPurpose,
        folder: Option<&Path>,
        file_name: &str,
        ctx: &egui::Context,
    ) -> Result<(), String> {
        if let Some((open, _)) = &self.open {
            return Err(format!(
                "the \u{201c}{}\u{201d} dialog is still open",
                open.title()
            ));
        }
        let folder = folder
            .map(Path::to_owned)
            .or_else(|| self.start_folder.clone())
            .or_else(|| std::env::current_dir().ok())
            .unwrap_or_default();
        let dialog = match &self.native {
            Some(native) if !self.prefer_in_app => {
                let request = DialogRequest {
                    purpose,
                    folder,
                    file_name: file_name.to_owned(),
                };
                OpenDialog::Native(wait_off_the_ui_thread(native(&request), ctx)?)
            }
            _ => OpenDialog::InApp(Box::new(in_app_dialog(purpose, folder, file_name, ctx))),
        };
        self.open = Some((purpose, dialog));
        Ok(())
    }

    /// Shows the in-app dialog or polls the native one; the outcome once it ends.
    pub fn ui(&mut self, ctx: &egui::Context) -> Option<(DialogPurpose, DialogOutcome)> {
        let (purpose, dialog) = self.open.as_mut()?;
        let purpose = *purpose;
        let outcome = match dialog {
            OpenDialog::Native(job) => match job.try_result()? {
                Ok(Some(path)) => DialogOutcome::Picked(path),
                Ok(None) => DialogOutcome::Cancelled,
                Err(error) => DialogOutcome::Failed(error),
            },
            OpenDialog::InApp(dialog) => {
                dialog.show(ctx);
                match dialog.state() {
                    egui_file::State::Open => return None,
                    egui_file::State::Selected => match dialog.path() {
                        Some(path) => DialogOutcome::Picked(path.to_owned()),
                        None => DialogOutcome::Cancelled,
                    },
                    egui_file::State::Cancelled | egui_file::State::Closed => {
                        DialogOutcome::Cancelled
                    }
                }
            }
        };
        self.open = None;
        Some((purpose, outcome))
    }
}

/// The in-app dialog, sized to fit a small window.
fn in_app_dialog(
    purpose: DialogPurpose,
    folder: PathBuf,
    file_name: &str,
    ctx: &egui::Context,
) -> egui_file::FileDialog {
    // egui_file's open mode takes the file selected in the list and ignores a name typed
    // in its field (Open then does nothing, or opens the other file); its save mode takes
    // the typed name, and a click in the list fills the field. So every in-app dialog is
    // a save-mode one, its button named for what it does; a typed name that does not
    // exist is then refused by the open itself, with a message.
    let mut dialog = if purpose.is_save() {
        egui_file::FileDialog::save_file().default_filename(file_name)
    } else {
        egui_file::FileDialog::save_file().save_button_text("Open".into())
    };
    let size = ctx.content_rect().size() * 0.85;
    dialog = dialog
        .initial_path(folder)
        .title(purpose.title())
        .id(egui::Id::unique("raylab file dialog"))
        .default_size(size.min(egui::vec2(560.0, 460.0)))
        .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
        .keep_on_top(true);
    if let Some((_, extensions)) = purpose.filter() {
        dialog = dialog.show_files_filter(Box::new(move |path: &Path| {
            path.extension()
                .is_some_and(|e| extensions.iter().any(|x| e.eq_ignore_ascii_case(x)))
        }));
    }
    dialog.open();
    dialog
}

/// The desktop's dialog through rfd's async API.
#[must_use]
pub fn rfd_dialog(request: &DialogRequest) -> PathFuture {
    let purpose = request.purpose;
    let mut dialog = rfd::AsyncFileDialog::new()
        .set_title(purpose.title())
        .set_directory(&request.folder);
    if let Some((name, extensions)) = purpose.filter() {
        dialog = dialog.add_filter(name, extensions);
    }
    let answer: Pin<Box<dyn Future<Output = Option<rfd::FileHandle>> + Send>> = if purpose.is_save()
    {
        Box::pin(dialog.set_file_name(&request.file_name).save_file())
    } else {
        Box::pin(dialog.pick_file())
    };
    Box::pin(async move { answer.await.map(|file| file.path().to_owned()) })
}

/// Waits for a native dialog's answer on a thread of its own, so the window keeps
/// drawing; the window is repainted when it ends.
fn wait_off_the_ui_thread(
    answer: PathFuture,
    ctx: &egui::Context,
) -> Result<BackgroundJob<Option<PathBuf>>, String> {
    let ctx = ctx.clone();
    BackgroundJob::spawn(
        "file dialog",
        move |_| Some(pollster::block_on(answer)),
        move || ctx.request_repaint(),
    )
}
