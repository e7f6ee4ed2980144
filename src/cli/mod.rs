//! The command line: `raylab [SCENE.ron]` starts the editor, `raylab render` renders
//! headless, `raylab import` and `raylab export` convert from and to the course format,
//! `raylab inspect` prints a pixel's rays, `raylab diff` compares with another renderer,
//! `raylab bugs` shows each known bug, `raylab class` a whole class's renders. `main.rs`
//! only calls [`run`].

mod bench;
mod bugs;
mod class;
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
pub use class::ClassArgs;
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
    /// Compare a whole class's renders with the scenes: a table, the bugs across the
    /// class and feedback per student, in a report folder.
    Class(ClassArgs),
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
        Some(Command::Class(args)) => class::run(&args),
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
/// the editor's File > Open does) imported on the fly, the import's warnings to stderr.
///
/// # Errors
/// The loader's or the importer's message, naming the file.
pub(crate) fn load_any_scene(path: &std::path::Path) -> Result<crate::scene::Scene, String> {
    let (scene, warnings) = crate::scene::load_any_scene(path)?;
    if crate::scene::read_text_file(path).is_ok_and(|t| crate::scene::legacy::looks_like_legacy(&t))
    {
        eprintln!("note: {} is a course scene, imported", path.display());
    }
    for warning in &warnings {
        eprintln!("warning: {warning}");
    }
    Ok(scene)
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
    let (data, warnings) = crate::scene::read_meshes_beside(scene, scene_path)?;
    for warning in warnings {
        eprintln!("warning: {warning}");
    }
    Ok(crate::trace::MeshStore::build(&data))
}
