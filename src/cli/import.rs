//! `raylab import`: a legacy COSC342 text scene to a RON scene.
//!
//! The summary (which framework dialect was read) and warnings (skipped objects, ignored
//! keywords...) go to stderr; the scene is written atomically, with its mesh paths
//! relative to the written file. A broken legacy file writes nothing and lists every
//! problem.

use std::path::PathBuf;

use clap::Args;

use crate::scene::legacy::{import_legacy_file, rebase_mesh_paths};
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
    let mut import = import_legacy_file(&args.legacy).map_err(|e| e.to_string())?;
    eprintln!("{}: {}", args.legacy.display(), import.summary());
    for warning in &import.warnings {
        eprintln!("warning: {}: {warning}", args.legacy.display());
    }
    let folder_of = |path: &std::path::Path| path.parent().map(PathBuf::from).unwrap_or_default();
    rebase_mesh_paths(
        &mut import.scene,
        &folder_of(&args.legacy),
        &folder_of(&args.output),
    );
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
