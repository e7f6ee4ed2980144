//! `raylab import`: a legacy COSC342 text scene to a RON scene. Placeholder.

use std::path::PathBuf;

use clap::Args;

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
/// Always, until the importer lands.
pub fn run(_args: &ImportArgs) -> Result<(), String> {
    Err("import is not implemented yet".to_owned())
}
