//! `raylab bugs SCENE -o DIR`: the bug gallery. The scene under each bug of the catalogue
//! that shows in it, one PNG each, and a contact sheet with captions: what each bug looks
//! like before a student hunts it.

use std::path::{Path, PathBuf};

use clap::Args;

use crate::compare::OtherImage;
use crate::compare::plant::{GalleryPicture, gallery, gallery_scene};
use crate::compare::report::{Panel, panel_grid_png};
use crate::scene::{MAX_IMAGE_SIDE, write_atomically};
use crate::trace::RenderProgress;

/// Arguments of `raylab bugs`.
#[derive(Debug, Args)]
pub struct BugsArgs {
    /// The scene: RON, or a course `.txt` scene.
    pub scene: PathBuf,
    /// The folder to write the pictures and `contact_sheet.png` into (made if missing).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Picture width (default: the scene's, at most 480; the height keeps the aspect).
    #[arg(long, value_parser = clap::value_parser!(u32).range(8..=i64::from(MAX_IMAGE_SIDE)))]
    pub width: Option<u32>,
    /// Samples per pixel (default: 1, as the course's tracers render).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=256))]
    pub spp: u32,
}

/// A file name for a bug's picture: its position and label, with only safe characters.
fn file_name(index: usize, label: &str) -> String {
    let safe: String = label
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '=' || c == '.' {
                c
            } else {
                '_'
            }
        })
        .collect();
    format!("{index:02}-{safe}.png")
}

/// Writes the gallery into `dir`: `00-own.png`, one PNG per bug, `contact_sheet.png`.
///
/// # Errors
/// A file that cannot be written, named.
pub fn write_gallery(
    dir: &Path,
    own: &OtherImage,
    pictures: &[GalleryPicture],
) -> Result<Vec<PathBuf>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let write = |name: String, bytes: &[u8]| -> Result<PathBuf, String> {
        let path = dir.join(name);
        write_atomically(&path, bytes)
            .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        Ok(path)
    };
    let mut written = vec![write("00-own.png".to_owned(), &own.png_bytes())?];
    for (i, p) in pictures.iter().enumerate() {
        written.push(write(file_name(i + 1, &p.label), &p.picture.png_bytes())?);
    }
    let mut panels = vec![Panel {
        pixels: own.rgb.clone(),
        title: "raylab (no bug)".to_owned(),
        lines: vec!["the scene as the contract renders it".to_owned()],
    }];
    panels.extend(pictures.iter().map(|p| Panel {
        pixels: p.picture.rgb.clone(),
        title: p.label.clone(),
        lines: vec![
            p.in_code.to_owned(),
            format!("{:.1}% of pixels change", 100.0 * p.changed_share),
        ],
    }));
    let sheet = panel_grid_png((own.width, own.height), &panels, 4, 300.0)?;
    written.push(write("contact_sheet.png".to_owned(), &sheet)?);
    Ok(written)
}

/// Runs `raylab bugs`.
///
/// # Errors
/// The scene cannot be read or rendered, or a file not written.
pub fn run(args: &BugsArgs) -> Result<(), String> {
    let scene = super::load_any_scene(&args.scene)?;
    let meshes = crate::cli::load_meshes(&scene, &args.scene)?;
    let scene = gallery_scene(scene, args.width);
    let found = gallery(&scene, &meshes, args.spp, &RenderProgress::default())?;
    for note in &found.left_out {
        eprintln!("note: not in the gallery: {note}");
    }
    let (own, pictures) = (&found.own, &found.pictures);
    let written = write_gallery(&args.output, own, pictures)?;
    eprintln!(
        "{}: {} bugs show in this scene; {} files, the contact sheet {}",
        args.scene.display(),
        pictures.len(),
        written.len(),
        written
            .last()
            .map_or(String::new(), |p| p.display().to_string())
    );
    Ok(())
}
