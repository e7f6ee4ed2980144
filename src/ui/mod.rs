//! The desktop editor (eframe/egui). Placeholder until the editor lands.

use std::path::PathBuf;

/// Opens the editor on `scene`, or on the embedded default scene.
///
/// # Errors
/// When the window cannot be created.
pub fn run(_scene: Option<PathBuf>) -> Result<(), String> {
    Err("the editor is not built yet; use `raylab render`".to_owned())
}
