//! The desktop editor (eframe/egui). A thin shell composes one panel per file: menu,
//! outliner, inspector, viewport, status bar. Panels push [`Command`]s, applied once per
//! frame in [`EditorApp`], which also feeds undo and restarts the preview.

mod app;
pub mod bug_gallery;
pub mod commands;
pub mod compare;
pub mod document;
pub mod gizmo;
pub mod panels;
mod scene_job;
mod screenshot;
mod shortcuts;
pub mod state;
pub mod stored;
mod style;
#[cfg(test)]
mod test_storage;
pub mod viewport;

use std::path::PathBuf;

use stored::Stored;

pub use app::{Document, EditorApp, EditorOptions, Looking, Tools, View};
pub use commands::{Command, LightKind, SceneEdit, Selection};
pub use document::confirm::DiscardAction;
pub use document::export::ExportState;
pub use document::file_dialog::{
    DialogPurpose, DialogRequest, FileDialogs, NativeDialog, PathFuture,
};
pub use document::native_dialogs::NativeDialogs;
pub use document::{files, recent};
pub use gizmo::toolbar::{CAMERA_VIEW_LABEL, SET_CAMERA_LABEL};
pub use state::{
    IsolationToggle, PreviewSettings, RayPathSettings, RaySpan, ViewCamera, isolation_note,
    light_label, view_label,
};
pub use viewport::convergence_plot::CONVERGENCE_EXPLANATION;
pub use viewport::full_picture_marker::NOT_FULL_PICTURE;
pub use viewport::isolation_memory::IsolationMemory;
pub use viewport::picture::{VIEWPORT_LABEL, letterbox};
pub use viewport::pixel_inspector::{
    FINAL_COLOUR_LABEL, InspectedBounce, InspectedHit, InspectedLight, InspectedPixel,
    PixelInspection,
};
pub use viewport::preview_link::{PreviewLink, ShownFrame, frame_rgba};
pub use viewport::ray_paths::RAY_PATHS_LABEL;
pub use viewport::toolbar::{NAN_COLOUR, non_finite_text};
pub use viewport::view_memory::ViewMemory;

/// The window and taskbar icon (`assets/icon.png`, rendered by raylab itself).
pub const ICON_PNG: &[u8] = include_bytes!("../../assets/icon.png");

/// Environment variable naming a PNG file: take a screenshot once the first
/// full-resolution preview is shown, save it there, and quit.
pub const SCREENSHOT_ENV: &str = "RAYLAB_SCREENSHOT";

/// With [`SCREENSHOT_ENV`]: the outliner label of an item to select before the screenshot
/// (so the documentation's picture shows a filled inspector).
pub const SCREENSHOT_SELECT_ENV: &str = "RAYLAB_SCREENSHOT_SELECT";

/// With [`SCREENSHOT_ENV`]: when set, wait for the final anti-aliased frame.
pub const SCREENSHOT_FINAL_ENV: &str = "RAYLAB_SCREENSHOT_FINAL";

/// Opens the editor on `scene`, or on the embedded default scene.
///
/// # Errors
/// When the window cannot be created.
pub fn run(scene: Option<PathBuf>) -> Result<(), String> {
    let screenshot = std::env::var_os(SCREENSHOT_ENV).map(PathBuf::from);
    let options = EditorOptions {
        scene,
        preview: true,
        screenshot: screenshot.clone(),
        screenshot_final: std::env::var_os(SCREENSHOT_FINAL_ENV).is_some(),
        // Screenshot runs are throwaway: they neither keep nor offer recovered work.
        recovery: if screenshot.is_some() {
            None
        } else {
            eframe::storage_dir("raylab")
                .map(|dir| crate::recovery::RecoveryStore::new(dir.join("recovery")))
        },
        native_dialogs: NativeDialogs::Detect,
        dialog_folder: None,
    };
    let viewport = egui::ViewportBuilder::default()
        .with_title("raylab")
        .with_app_id("raylab")
        .with_inner_size([1280.0, 800.0])
        .with_min_inner_size([720.0, 480.0])
        .with_drag_and_drop(true)
        .with_icon(eframe::icon_data::from_png_bytes(ICON_PNG).expect("assets/icon.png is a PNG"));
    let native = eframe::NativeOptions {
        viewport,
        // A screenshot run must look the same every time: no restored window size.
        persist_window: options.screenshot.is_none(),
        ..eframe::NativeOptions::default()
    };
    eframe::run_native(
        "raylab",
        native,
        Box::new(move |cc| {
            let recent = if options.screenshot.is_some() {
                document::recent::RecentFiles::default()
            } else {
                document::recent::RecentFiles::load(cc.storage)
            };
            let mut app = EditorApp::new(options, recent);
            if !app.is_screenshot_run() {
                app = app.with_view_memory(ViewMemory::load(cc.storage));
                app.push(Command::SetPreviewSettings(PreviewSettings::load(
                    cc.storage,
                )));
                app.push(Command::SetPreferInAppFileDialog(
                    FileDialogs::stored_preference(cc.storage),
                ));
                app.set_isolation_memory(viewport::isolation_memory::IsolationMemory::load(
                    cc.storage,
                ));
            }
            if let Some(label) = std::env::var_os(SCREENSHOT_SELECT_ENV)
                && let Some(selection) =
                    selection_by_label(&app.document().scene, &label.to_string_lossy())
            {
                app.push(Command::Select(selection));
            }
            Ok(Box::new(app))
        }),
    )
    .map_err(|e| format!("cannot open the editor window: {e}"))
}

/// The item whose outliner row reads `label`: an object, "Camera", "Render settings", a
/// material or a light ("Point light 2").
#[must_use]
pub fn selection_by_label(scene: &crate::scene::Scene, label: &str) -> Option<Selection> {
    if let Some(index) = scene.objects.iter().position(|o| o.name == label) {
        return Some(Selection::Object(index));
    }
    match label {
        "Camera" => return Some(Selection::Camera),
        "Render settings" => return Some(Selection::Render),
        _ => {}
    }
    if scene.materials.contains_key(label) {
        return Some(Selection::Material(label.to_owned()));
    }
    scene
        .lights
        .iter()
        .enumerate()
        .position(|(i, l)| light_label(l, i) == label)
        .map(Selection::Light)
}
