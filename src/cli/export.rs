//! `raylab export`: a RON scene to the COSC342 course's text format, in the 2020
//! framework's dialect (default) or the 2016 one.
//!
//! Warnings (what is written with a loss, each naming its object, light or material) go
//! to stderr; a scene the dialect cannot say writes nothing, lists every refusal and
//! exits non-zero. Mesh paths are rewritten relative to the written file.

use std::path::{Path, PathBuf};

use clap::{Args, ValueEnum};

use crate::scene::legacy::{Dialect, export_course_file};
use crate::scene::load_scene;

/// The course framework whose readers the file is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum DialectArg {
    /// The 2020 framework and its students' extensions (CSG blocks, groups, torus, tube,
    /// octahedron, glass, anti-aliasing, sphere lights).
    #[value(name = "2020")]
    Framework2020,
    /// The 2016 framework: point lights only, nested `Object CSG`, meshes.
    #[value(name = "2016")]
    Framework2016,
}

impl From<DialectArg> for Dialect {
    fn from(arg: DialectArg) -> Self {
        match arg {
            DialectArg::Framework2020 => Dialect::Framework2020,
            DialectArg::Framework2016 => Dialect::Framework2016,
        }
    }
}

/// Arguments of `raylab export`.
#[derive(Debug, Args)]
pub struct ExportArgs {
    /// The scene file (RON).
    pub scene: PathBuf,
    /// The course text scene to write.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Which framework's dialect to write.
    #[arg(long, value_enum, default_value = "2020")]
    pub dialect: DialectArg,
}

/// Runs `raylab export`.
///
/// # Errors
/// Why the scene could not be read, every refusal of the dialect (nothing is written),
/// or why the file could not be written.
pub fn run(args: &ExportArgs) -> Result<(), String> {
    let scene = load_scene(&args.scene).map_err(|e| format!("{}: {e}", args.scene.display()))?;
    let folder = args.scene.parent().unwrap_or(Path::new(""));
    let warnings = export_course_file(&scene, folder, &args.output, args.dialect.into())
        .map_err(|e| e.to_string())?;
    for warning in &warnings {
        eprintln!("warning: {}: {warning}", args.scene.display());
    }
    eprintln!(
        "exported {} to {} ({} warning{})",
        args.scene.display(),
        args.output.display(),
        warnings.len(),
        if warnings.len() == 1 { "" } else { "s" }
    );
    Ok(())
}
