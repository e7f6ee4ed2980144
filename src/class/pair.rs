//! One pair: a student's render of one scene, compared with raylab's picture of it
//! (`raylab diff`'s comparison) and scored with LDR-FLIP, its images written to the
//! pair's cache folder.

use std::path::Path;

use image::RgbImage;
use serde::{Deserialize, Serialize};

use crate::compare::{Comparison, OtherImage, PreparedScene, compare_prepared, report_png};
use crate::scene::Scene;
use crate::trace::{MeshStore, RenderProgress};

/// The pair's report image (both pictures, the difference, the top explanations).
pub const REPORT_IMAGE: &str = "report.png";
/// The pair's FLIP error map.
pub const FLIP_MAP: &str = "flip.png";
/// The student's picture, small, for the class table.
pub const THUMBNAIL: &str = "thumb.png";
/// Width of a thumbnail in pixels.
const THUMBNAIL_WIDTH: u32 = 120;

/// A scene read once for all of its pairs.
pub struct LoadedScene {
    /// The scene.
    pub scene: Scene,
    /// Its mesh objects' triangles.
    pub meshes: MeshStore,
    /// The bytes its result depends on: the scene file's, then each mesh file's.
    pub content: Vec<u8>,
}

/// One explanation of a pair, as the class report keeps it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Finding {
    /// The cause's name (`missing-object`, `factor`, `mirror-blend`, ...).
    pub cause: String,
    /// The term (`diffuse`, `shadows`, `geometry`, ...).
    pub term: String,
    /// The light's index in the scene's list, if one light is named.
    pub light: Option<usize>,
    /// The object's name (or tree path), if one is named.
    pub object: Option<String>,
    /// The fitted scale of raylab's component in the student's picture.
    pub factor: f64,
    /// The share of the squared difference it explains, 0 to 1.
    pub share: f64,
    /// "high", "medium" or "low".
    pub sure: String,
    /// The sentence for a reader.
    pub summary: String,
}

/// What a finished pair found; cached as JSON.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PairResult {
    /// PSNR of the student's picture against raylab's, in dB.
    pub psnr_db: f64,
    /// Mean LDR-FLIP error, 0 to 1.
    pub flip_mean: f64,
    /// 99th percentile of the per-pixel LDR-FLIP error, 0 to 1.
    pub flip_p99: f64,
    /// The explanations, largest share first.
    pub findings: Vec<Finding>,
    /// The share of the difference nothing explains.
    pub unexplained_share: f64,
}

impl Finding {
    fn of(comparison: &Comparison) -> Vec<Self> {
        comparison
            .explanations
            .iter()
            .map(|e| Finding {
                cause: e.cause.name().to_owned(),
                term: e.term.name().to_owned(),
                light: e.light,
                object: e.object_name.clone(),
                factor: e.factor,
                share: e.share,
                sure: e.sureness().to_owned(),
                summary: e.summary.clone(),
            })
            .collect()
    }

    /// A short name of the bug for tables and the class summary: the cause, and for a
    /// term scaled by a factor, the term and how (`diffuse off`, `specular x0.50`).
    #[must_use]
    pub fn bug(&self) -> String {
        if self.cause == "factor" {
            if self.factor.abs() < 0.05 {
                format!("{} off", self.term)
            } else {
                format!("{} x{:.2}", self.term, self.factor)
            }
        } else {
            self.cause.clone()
        }
    }

    /// The bug with where it is: its light and object, if named.
    #[must_use]
    pub fn bug_where(&self) -> String {
        let mut text = self.bug();
        if let Some(light) = self.light {
            text.push_str(&format!(", light {light}"));
        }
        if let Some(object) = &self.object {
            text.push_str(&format!(", '{object}'"));
        }
        text
    }
}

/// Compares `picture` with raylab's picture of a prepared scene (shared by the scene's
/// pairs) and writes the pair's images to `folder` (created if needed).
///
/// # Errors
/// The comparison's error (another size, a scene that does not render), or a write's.
pub fn compare_pair(
    scene: &PreparedScene,
    picture: &OtherImage,
    folder: &Path,
) -> Result<PairResult, String> {
    let comparison =
        compare_prepared(scene, picture, &RenderProgress::default()).map_err(|e| e.to_string())?;
    // The report image's FLIP panel and the pair's figures share one computation.
    let flip = comparison.perceptual();
    std::fs::create_dir_all(folder)
        .map_err(|e| format!("cannot create {}: {e}", folder.display()))?;
    let write = |name: &str, bytes: &[u8]| {
        let path = folder.join(name);
        std::fs::write(&path, bytes).map_err(|e| format!("cannot write {}: {e}", path.display()))
    };
    write(REPORT_IMAGE, &report_png(&comparison)?)?;
    write(FLIP_MAP, &flip.map_png()?)?;
    write(THUMBNAIL, &thumbnail_png(picture)?)?;
    Ok(PairResult {
        psnr_db: comparison.psnr_db,
        flip_mean: flip.mean,
        flip_p99: flip.p99,
        findings: Finding::of(&comparison),
        unexplained_share: comparison.unexplained_share,
    })
}

/// The picture scaled to [`THUMBNAIL_WIDTH`] wide, as PNG bytes.
fn thumbnail_png(picture: &OtherImage) -> Result<Vec<u8>, String> {
    let bytes = picture.rgb.iter().flatten().copied().collect();
    let image = RgbImage::from_raw(picture.width, picture.height, bytes).ok_or("picture size")?;
    let height = (u64::from(picture.height) * u64::from(THUMBNAIL_WIDTH)
        / u64::from(picture.width.max(1)))
    .max(1) as u32;
    let small = image::imageops::thumbnail(&image, THUMBNAIL_WIDTH, height);
    let mut png = Vec::new();
    small
        .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .map_err(|e| format!("thumbnail: {e}"))?;
    Ok(png)
}
