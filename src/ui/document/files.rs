//! File operations as plain functions of paths. The menu's native dialogs only pick a
//! path and call these, so tests call exactly what the dialogs call.

use std::path::{Path, PathBuf};

use glam::DVec3;

use crate::scene::{Light, LightSource, Scene, save_scene, write_atomically};
use crate::trace::Image;

pub use crate::scene::examples::{DEFAULT_SCENE_RON, default_scene};

/// What File > New starts from: the default camera, one grey material, an ambient and a
/// point light, no objects.
#[must_use]
pub fn new_scene() -> Scene {
    let mut scene = Scene::empty();
    scene
        .materials
        .insert("default".to_owned(), crate::scene::Material::grey());
    scene.render.background = DVec3::new(0.05, 0.06, 0.09);
    scene.lights = vec![
        Light::Ambient {
            colour: DVec3::splat(0.1),
            intensity: 1.0,
        },
        Light::Point {
            position: DVec3::new(-4.0, 6.0, 5.0),
            source: LightSource::point(DVec3::ONE, 40.0),
        },
    ];
    scene
}

/// What a file opened with File > Open holds.
#[derive(Debug)]
pub enum Opened {
    /// A RON scene.
    Scene(Box<Scene>),
    /// A course text scene (told by its content, whatever its name), imported.
    Legacy(Box<crate::scene::legacy::LegacyImport>),
}

/// Loads a scene file, or imports a course text scene (told by its content, through
/// [`crate::scene::load_scene_or_course`] as the command line does); the message names
/// the file and, for syntax errors, the line and column, and says what raylab opens.
///
/// # Errors
/// The file cannot be read, is not a scene, or describes an impossible scene.
pub fn open_scene(path: &Path) -> Result<Opened, String> {
    use crate::scene::{SceneOrCourse, SceneOrCourseError, load_scene_or_course};
    let e = match load_scene_or_course(path) {
        Ok(SceneOrCourse::Ron(scene)) => return Ok(Opened::Scene(scene)),
        Ok(SceneOrCourse::Course(import)) => return Ok(Opened::Legacy(import)),
        Err(error @ SceneOrCourseError::Course(_)) => return Err(error.to_string()),
        Err(SceneOrCourseError::Ron(e)) => e,
    };
    let text = crate::scene::read_text_file(path);
    let looks_like_ron = text
        .as_ref()
        .is_ok_and(|t| t.trim_start().starts_with("Scene(") || t.trim_start().starts_with("//"));
    if looks_like_ron {
        return Err(format!("{}: {e}", path.display()));
    }
    // Not RON at all: the parser's words would only confuse; show what the file
    // starts with instead, and what raylab opens.
    let start = text.as_ref().ok().and_then(|t| {
        t.lines().map(str::trim).find(|l| !l.is_empty()).map(|l| {
            let short: String = l.chars().take(40).collect();
            format!(" (it starts \u{201c}{short}\u{201d})")
        })
    });
    Err(format!(
        "{} is neither a raylab scene nor a course text scene{}. File > Open takes \
         raylab scenes (.ron) and the course's .txt scenes; File > Import Legacy \
         takes the latter too",
        path.display(),
        start.unwrap_or_default()
    ))
}

/// Saves a scene atomically (a temporary file renamed over the target).
///
/// # Errors
/// The scene is invalid, or the file cannot be written; the old file is then intact.
pub fn save_scene_to(scene: &Scene, path: &Path) -> Result<(), String> {
    save_scene(scene, path).map_err(|e| match e {
        crate::scene::SceneError::Write { .. } => e.to_string(),
        other => format!("cannot save {}: {other}", path.display()),
    })
}

/// Imports a legacy COSC342 text scene: the scene, the import's one-line summary (which
/// framework dialect was read, and what came in) and its warnings.
///
/// # Errors
/// The importer's message.
pub fn import_legacy(path: &Path) -> Result<(Scene, String, Vec<String>), String> {
    crate::scene::legacy::import_legacy_file(path)
        .map(|import| (import.summary(), import))
        .map(|(summary, import)| (import.scene, summary, import.warnings))
        .map_err(|e| e.to_string())
}

/// Writes an image as PNG atomically, each channel made a byte as `quantise` says (the
/// scene's conventions).
///
/// # Errors
/// The file cannot be written; the message names it.
pub fn write_png(
    image: &Image,
    path: &Path,
    quantise: crate::scene::Quantise,
) -> Result<(), String> {
    write_atomically(path, &image.png_bytes_as(quantise))
        .map_err(|e| format!("cannot write {}: {e}", path.display()))
}

/// Whether a dropped file looks like a scene (`.ron`).
#[must_use]
pub fn is_scene_file(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("ron"))
}

/// `path` with the `.png` extension when it has none.
#[must_use]
pub fn with_png_extension(path: PathBuf) -> PathBuf {
    if path.extension().is_some() {
        path
    } else {
        path.with_extension("png")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn embedded_and_new_scenes_are_valid() {
        assert_eq!(default_scene().objects.len(), 6);
        crate::scene::validate(&new_scene()).unwrap();
    }

    #[test]
    fn only_ron_files_are_scenes() {
        assert!(is_scene_file(Path::new("a/b.RON")));
        assert!(!is_scene_file(Path::new("a/b.png")));
        assert_eq!(
            with_png_extension(PathBuf::from("out")),
            PathBuf::from("out.png")
        );
    }
}
