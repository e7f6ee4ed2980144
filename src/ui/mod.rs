//! The desktop editor (eframe/egui). A thin shell composes one panel per file: menu,
//! outliner, inspector, viewport, status bar. Panels push [`Command`]s, applied once per
//! frame in [`EditorApp`], which also feeds undo and restarts the preview.

mod app;
pub mod commands;
mod export;
pub mod files;
mod inspector;
mod menu;
mod outliner;
mod preview_link;
pub mod recent;
mod screenshot;
mod shortcuts;
mod status_bar;
mod style;
mod viewport;

use std::path::PathBuf;

pub use app::{DiscardAction, EditorApp, EditorOptions};
pub use commands::{Command, LightKind, SceneEdit, Selection};
pub use export::{ExportSettings, ExportState};
pub use inspector::trs_from_matrix;
pub use outliner::light_label;
pub use preview_link::{PreviewLink, ShownFrame};
pub use viewport::{VIEWPORT_LABEL, letterbox, pick_object};

/// Environment variable naming a PNG file: take a screenshot once the first
/// full-resolution preview is shown, save it there, and quit.
pub const SCREENSHOT_ENV: &str = "RAYLAB_SCREENSHOT";

/// With [`SCREENSHOT_ENV`]: the name of an object to select before the screenshot (so
/// the documentation's picture shows a filled inspector).
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
        screenshot,
        screenshot_final: std::env::var_os(SCREENSHOT_FINAL_ENV).is_some(),
    };
    let viewport = egui::ViewportBuilder::default()
        .with_title("raylab")
        .with_app_id("raylab")
        .with_inner_size([1280.0, 800.0])
        .with_min_inner_size([720.0, 480.0])
        .with_drag_and_drop(true);
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
                recent::RecentFiles::default()
            } else {
                recent::RecentFiles::load(cc.storage)
            };
            let mut app = EditorApp::new(options, recent);
            if let Some(name) = std::env::var_os(SCREENSHOT_SELECT_ENV) {
                let name = name.to_string_lossy();
                if let Some(index) = app.scene().objects.iter().position(|o| o.name == name) {
                    app.push(Command::Select(Selection::Object(index)));
                }
            }
            Ok(Box::new(app))
        }),
    )
    .map_err(|e| format!("cannot open the editor window: {e}"))
}
