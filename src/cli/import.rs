//! `raylab import`: a legacy COSC342 text scene to a RON scene.
//!
//! Warnings (skipped octahedra, ignored keywords...) go to stderr; the scene is written
//! atomically. A broken legacy file writes nothing and lists every problem.

use std::path::PathBuf;

use clap::Args;

use crate::scene::legacy::import_legacy_file;
use crate::scene::save_scene;

/// Arguments of `raylab import`.
#[derive(Debug, Args)]
pub struct ImportArgs {
    /// The legacy text scene.
    pub legacy: PathBuf,
    /// The RON scene to write.
    #[arg(short, long)]
    pub output: PathBuf,
}

/// Runs `raylab import`.
///
/// # Errors
/// A message listing every problem of the legacy file (one per line, with its line
/// number and token), or why the file could not be read or the scene written.
pub fn run(args: &ImportArgs) -> Result<(), String> {
    let import = import_legacy_file(&args.legacy).map_err(|e| e.to_string())?;
    for warning in &import.warnings {
        eprintln!("warning: {}: {warning}", args.legacy.display());
    }
    save_scene(&import.scene, &args.output).map_err(|e| e.to_string())?;
    eprintln!(
        "imported {} objects, {} lights and {} materials into {}",
        import.scene.objects.len(),
        import.scene.lights.len(),
        import.scene.materials.len(),
        args.output.display()
    );
    Ok(())
}
