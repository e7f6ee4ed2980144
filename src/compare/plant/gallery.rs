//! The bug gallery: raylab's picture of a scene and the same scene under each bug of the
//! catalogue that shows in it ([`super::gallery_bugs`]), for `raylab bugs` and the
//! editor's Bug gallery window.

use super::models::{PlantedBug, gallery_bugs, plant, plant_each};
use crate::compare::other_image::OtherImage;
use crate::scene::{MAX_IMAGE_SIDE, Scene};
use crate::trace::{MeshStore, RenderProgress};

/// Widest default picture: a gallery of 30 pictures stays quick and the sheet readable.
const DEFAULT_MAX_WIDTH: u32 = 480;

/// One picture of the gallery.
pub struct GalleryPicture {
    /// The bug, as `raylab render --bug` takes it.
    pub label: String,
    /// What it is in a tracer's code.
    pub in_code: &'static str,
    /// The picture.
    pub picture: OtherImage,
    /// The share of pixels it changes.
    pub changed_share: f64,
}

/// The scene resized to `width` (keeping its aspect), or at most [`DEFAULT_MAX_WIDTH`].
#[must_use]
pub fn gallery_scene(mut scene: Scene, width: Option<u32>) -> Scene {
    let (w, h) = (scene.camera.width, scene.camera.height);
    let width = width.unwrap_or(w.min(DEFAULT_MAX_WIDTH));
    if width != w {
        let height = (f64::from(h) * f64::from(width) / f64::from(w)).round() as u32;
        scene.camera.width = width;
        scene.camera.height = height.clamp(1, MAX_IMAGE_SIDE);
    }
    scene
}

/// The gallery of a scene: raylab's own picture, each bug of [`gallery_bugs`] that
/// changes at least one byte of it, and the bugs that could not be planted, with why.
pub struct Gallery {
    /// raylab's picture, as the scene writes it.
    pub own: OtherImage,
    /// The bugs that show, in the catalogue's order.
    pub pictures: Vec<GalleryPicture>,
    /// Bugs that could not be planted in this scene, each with its reason.
    pub left_out: Vec<String>,
}

/// raylab's own picture of `scene` and the gallery: each bug of [`gallery_bugs`] that
/// changes at least one byte of it.
///
/// # Errors
/// The scene does not compile.
pub fn gallery(
    scene: &Scene,
    meshes: &MeshStore,
    spp: u32,
    progress: &RenderProgress,
) -> Result<Gallery, String> {
    let own = plant(scene, meshes, &[], spp, progress).map_err(|e| e.to_string())?;
    let bugs: Vec<PlantedBug> = gallery_bugs(scene);
    let pictures = plant_each(scene, meshes, &bugs, spp, progress).map_err(|e| e.to_string())?;
    let mut shown = Vec::new();
    let mut left_out = Vec::new();
    for (bug, picture) in bugs.iter().zip(pictures) {
        let picture = match picture {
            Ok(p) => p,
            Err(e) => {
                left_out.push(format!("{}: {e}", bug.label(scene)));
                continue;
            }
        };
        let changed = own
            .rgb
            .iter()
            .zip(&picture.rgb)
            .filter(|(a, b)| a != b)
            .count();
        if changed == 0 {
            continue; // the bug has nothing to act on in this scene
        }
        shown.push(GalleryPicture {
            label: bug.label(scene),
            in_code: bug.plant.in_code(),
            picture,
            changed_share: changed as f64 / own.rgb.len() as f64,
        });
    }
    Ok(Gallery {
        own,
        pictures: shown,
        left_out,
    })
}
