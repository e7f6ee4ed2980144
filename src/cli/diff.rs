//! `raylab diff`: compare a scene's raylab picture with another renderer's image of it,
//! and say which light, object and term explain the difference (docs/COMPARE.md).

use std::path::PathBuf;

use clap::Args;

use crate::compare::{CompareOptions, OtherImage, compare_with_meshes, write_report_png};
use crate::trace::RenderProgress;

/// Arguments of `raylab diff`.
#[derive(Debug, Args)]
pub struct DiffArgs {
    /// The scene: RON, or a course `.txt` scene (told by its content, imported on the fly).
    pub scene: PathBuf,
    /// The other renderer's image of the scene: an 8-bit PNG or PPM at the scene's size.
    pub other: PathBuf,
    /// Print one JSON object instead of readable lines.
    #[arg(long)]
    pub json: bool,
    /// Also write a report image: both pictures, the difference, the LDR-FLIP error
    /// map, the top explanations.
    #[arg(short, long, visible_alias = "report")]
    pub output: Option<PathBuf>,
    /// Samples per pixel of raylab's picture (default: the scene's; 1 for a renderer
    /// without anti-aliasing).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub spp: Option<u32>,
    /// The course's conventions raylab's picture is made with, over the scene's.
    #[command(flatten)]
    pub conventions: super::ConventionArgs,
}

/// Runs `raylab diff`.
///
/// # Errors
/// A message naming what went wrong: the scene, the image (unreadable, not an image, not
/// 8-bit, another size), or the report's write.
pub fn run(args: &DiffArgs) -> Result<(), String> {
    let scene = args
        .conventions
        .applied(super::load_any_scene(&args.scene)?);
    let other = OtherImage::load(&args.other).map_err(|e| e.to_string())?;
    let options = CompareOptions {
        samples_per_pixel: args.spp,
    };
    let meshes = crate::cli::load_meshes(&scene, &args.scene)?;
    let comparison = compare_with_meshes(
        &scene,
        &meshes,
        &other,
        &options,
        &RenderProgress::default(),
    )
    .map_err(|e| format!("{}: {e}", args.other.display()))?;
    if let Some(path) = &args.output {
        write_report_png(&comparison, path)?;
    }
    if args.json {
        println!("{}", comparison.to_json());
    } else {
        for line in comparison.text_lines() {
            println!("{line}");
        }
    }
    Ok(())
}
