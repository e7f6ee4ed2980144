//! The command line: `raylab [SCENE.ron]` starts the editor, `raylab render` renders
//! headless, `raylab inspect` prints a pixel's rays, `raylab diff` compares with another
//! renderer, `raylab class` a whole class's renders. `main.rs` only calls [`run`].

mod bench;
mod class;
mod conventions;
mod diff;
mod import;
mod inspect;
mod inspect_tree;
mod isolation;
mod render;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

pub use bench::BenchArgs;
pub use class::ClassArgs;
pub use conventions::ConventionArgs;
pub use diff::DiffArgs;
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
    /// Measure throughput, preview latency and speed against error.
    Bench(BenchArgs),
    /// Print every ray behind one pixel: the camera ray, shadow rays, mirror bounces.
    Inspect(InspectArgs),
    /// Compare with another renderer's image: which light, object and term differ.
    Diff(DiffArgs),
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
        Some(Command::Bench(args)) => bench::run(&args),
        Some(Command::Inspect(args)) => inspect::run(&args),
        Some(Command::Diff(args)) => diff::run(&args),
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
