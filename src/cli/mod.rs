//! The command line: `raylab [SCENE.ron]` starts the editor, `raylab render` renders
//! headless, `raylab import` and `raylab export` convert from and to the course format,
//! `raylab inspect` prints a pixel's rays, `raylab diff` compares with another renderer.
//! `main.rs` only calls [`run`].

mod bench;
mod bugs;
mod conventions;
mod diff;
mod export;
mod import;
mod inspect;
mod inspect_tree;
mod isolation;
mod render;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

pub use bench::BenchArgs;
pub use bugs::BugsArgs;
pub use conventions::ConventionArgs;
pub use diff::DiffArgs;
pub use export::{DialectArg, ExportArgs};
pub use import::ImportArgs;
pub use inspect::{InspectArgs, TermArgs, inspect_text};
pub use isolation::IsolationArgs;
pub use render::RenderArgs;

/// raylab: a Whitted-style ray tracer and scene editor.
#[derive(Debug, Parser)]
#[command(name = "raylab", version, about, long_about = None)]
pub struct Cli {
    /// What to do; with none, the editor opens.
    #[command(subcommand)]
    pub command: Option<Command>,
    /// A scene to open in the editor.
    pub scene: Option<PathBuf>,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Render a scene to a PNG file.
    Render(RenderArgs),
    /// Import a legacy COSC342 text scene as a RON scene.
    Import(ImportArgs),
    /// Export a scene in the COSC342 course's text format (2020 or 2016 dialect).
    Export(ExportArgs),
    /// Measure throughput, preview latency and speed against error.
    Bench(BenchArgs),
    /// Print every ray behind one pixel: the camera ray, shadow rays, mirror bounces.
    Inspect(InspectArgs),
    /// Compare with another renderer's image: which light, object and term differ.
    Diff(DiffArgs),
    /// The bug gallery: the scene under each known bug, one PNG each and a contact sheet.
    Bugs(BugsArgs),
}

/// Parses the command line and runs it. Errors are printed to stderr with a non-zero exit.
#[must_use]
pub fn run() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Some(Command::Render(args)) => render::run(&args),
        Some(Command::Import(args)) => import::run(&args),
        Some(Command::Export(args)) => export::run(&args),
        Some(Command::Bench(args)) => bench::run(&args),
        Some(Command::Inspect(args)) => inspect::run(&args),
        Some(Command::Diff(args)) => diff::run(&args),
        Some(Command::Bugs(args)) => bugs::run(&args),
        None => start_editor(cli.scene),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}

#[cfg(feature = "editor")]
fn start_editor(scene: Option<PathBuf>) -> Result<(), String> {
    crate::ui::run(scene)
}

#[cfg(not(feature = "editor"))]
fn start_editor(_scene: Option<PathBuf>) -> Result<(), String> {
    Err(
        "this raylab was built without the editor (feature `editor`); use `raylab render`"
            .to_owned(),
    )
}

/// Reads the scene a command takes: RON, or a course text scene (told by its content, as
/// the editor's File > Open does) imported on the fly, the import's summary and warnings
/// to stderr.
///
/// # Errors
/// The loader's or the importer's message, naming the file.
pub(crate) fn load_any_scene(path: &std::path::Path) -> Result<crate::scene::Scene, String> {
    use crate::scene::{SceneOrCourse, SceneOrCourseError, load_scene_or_course};
    match load_scene_or_course(path) {
        Ok(SceneOrCourse::Ron(scene)) => Ok(*scene),
        Ok(SceneOrCourse::Course(import)) => {
            eprintln!(
                "note: {} is a course scene, imported: {}",
                path.display(),
                import.summary()
            );
            for warning in &import.warnings {
                eprintln!("warning: {}: {warning}", path.display());
            }
            Ok(import.scene)
        }
        Err(SceneOrCourseError::Ron(e)) => Err(format!("{}: {e}", path.display())),
        Err(error @ SceneOrCourseError::Course(_)) => Err(error.to_string()),
    }
}

/// Reads and builds the meshes `scene` (read from `scene_path`) refers to, printing the
/// loader's warnings.
///
/// # Errors
/// The first mesh file that cannot be read, named with its object and the scene file.
pub(crate) fn load_meshes(
    scene: &crate::scene::Scene,
    scene_path: &std::path::Path,
) -> Result<crate::trace::MeshStore, String> {
    let folder = scene_path.parent().unwrap_or(std::path::Path::new("."));
    let data = crate::scene::read_scene_meshes(scene, folder)
        .map_err(|e| format!("{}: {e}", scene_path.display()))?;
    for warning in data.values().flat_map(|mesh| &mesh.warnings) {
        eprintln!("warning: {warning}");
    }
    Ok(crate::trace::MeshStore::build(&data))
}
