//! The result of a comparison as one value: both pictures, the difference, the object
//! under each pixel and the explanations with their pixels, so a viewer (the command
//! line's report, the editor) shows it without computing anything again.

use std::sync::OnceLock;

use serde::Serialize;

use crate::compare::fit::Encoding;
use crate::compare::other_image::OtherImage;
use crate::compare::perceptual::{Perceptual, ldr_flip};
use crate::compare::verdict::{Cause, Explanation};
use crate::trace::Image;
use crate::trace::encode_linear;

/// PSNR reported for images that are identical byte for byte (the true value is
/// infinite, which JSON cannot hold).
pub const PSNR_IDENTICAL_DB: f64 = 100.0;

/// Everything a comparison found.
#[derive(Clone, Debug)]
pub struct Comparison {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Samples per pixel of raylab's picture.
    pub samples_per_pixel: u32,
    /// raylab's picture, linear and unclamped.
    pub raylab: Image,
    /// raylab's picture as it writes it (linear `round(255 c)`).
    pub raylab_rgb: Vec<[u8; 3]>,
    /// The other picture, as read.
    pub other: OtherImage,
    /// The encoding the other picture was found to use.
    pub encoding: Encoding,
    /// The object the first sample of each pixel hit (raylab's object-id view).
    pub objects: Vec<Option<usize>>,
    /// The scene's object names, by index.
    pub object_names: Vec<String>,
    /// Per pixel, the largest channel difference of the two 8-bit pictures, in levels.
    pub difference: Vec<u8>,
    /// PSNR of the other picture against raylab's 8-bit picture, in dB.
    pub psnr_db: f64,
    /// The explanations, largest share first.
    pub explanations: Vec<Explanation>,
    /// Share of the squared difference nothing explains.
    pub unexplained_share: f64,
    /// LDR-FLIP of the other picture against raylab's 8-bit picture, computed the first
    /// time [`Comparison::perceptual`] asks (the editor's comparisons never pay for it).
    pub(in crate::compare) perceptual: OnceLock<Perceptual>,
}

/// Both pictures' values at one pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelValues {
    /// raylab's linear, unclamped colour.
    pub raylab_linear: [f32; 3],
    /// raylab's bytes.
    pub raylab_rgb: [u8; 3],
    /// The other picture's bytes.
    pub other_rgb: [u8; 3],
    /// The other picture's bytes decoded as linear colour with the found encoding.
    pub other_linear: [f64; 3],
    /// The object raylab sees there.
    pub object: Option<usize>,
    /// Indices of the explanations that cover the pixel.
    pub explanations: Vec<usize>,
}

/// The JSON form of an explanation (the fields of the issue, then extras).
#[derive(Serialize)]
struct ExplanationJson<'a> {
    term: &'static str,
    light: Option<usize>,
    /// The node's name: an object's, or a tree path (`"die/pip 1.1"`).
    object: Option<&'a str>,
    /// For a part of an object's tree: its path of indices (`[2, 1]`), as the editor
    /// selects it.
    #[serde(skip_serializing_if = "<[usize]>::is_empty")]
    node: &'a [usize],
    factor: f64,
    share: f64,
    pixels: usize,
    summary: &'a str,
    cause: &'static str,
    confidence: f64,
    sure: &'static str,
    /// For an object missing or extra: `[x0, y0, x1, y1]`, inclusive.
    #[serde(skip_serializing_if = "Option::is_none")]
    bbox: Option<[u32; 4]>,
    /// For an extra object: the shape its outline suggests.
    #[serde(skip_serializing_if = "Option::is_none")]
    shape: Option<&'static str>,
    /// Other readings that fit as well.
    #[serde(skip_serializing_if = "<[String]>::is_empty")]
    fits_as_well: &'a [String],
}

/// The JSON form of a comparison.
#[derive(Serialize)]
struct ComparisonJson<'a> {
    psnr_db: f64,
    explanations: Vec<ExplanationJson<'a>>,
    unexplained_share: f64,
    encoding: &'static str,
    width: u32,
    height: u32,
    samples_per_pixel: u32,
    /// Mean LDR-FLIP error, 0 to 1.
    flip_mean: f64,
    /// 99th percentile of the per-pixel LDR-FLIP error, 0 to 1.
    flip_p99: f64,
}

/// Rounds for reports: 4 decimals are plenty and keep the JSON readable.
fn round4(x: f64) -> f64 {
    (x * 1e4).round() / 1e4
}

/// Rounds FLIP figures: a near match's mean is often below 1e-3, so 6 decimals.
fn round6(x: f64) -> f64 {
    (x * 1e6).round() / 1e6
}

impl Comparison {
    /// LDR-FLIP of the other picture (the test image) against raylab's 8-bit picture
    /// (the reference): the per-pixel map, its mean and 99th percentile.
    #[must_use]
    pub fn perceptual(&self) -> &Perceptual {
        self.perceptual
            .get_or_init(|| ldr_flip(self.width, self.height, &self.raylab_rgb, &self.other.rgb))
    }

    /// The values of both pictures at column `x`, row `y`.
    #[must_use]
    pub fn pixel(&self, x: u32, y: u32) -> PixelValues {
        let p = y as usize * self.width as usize + x as usize;
        let other_rgb = self.other.rgb[p];
        PixelValues {
            raylab_linear: self.raylab.pixels[p].to_array(),
            raylab_rgb: self.raylab_rgb[p],
            other_rgb,
            other_linear: other_rgb.map(|k| self.encoding.decode(k)),
            object: self.objects[p],
            explanations: (0..self.explanations.len())
                .filter(|&i| self.explanations[i].covers(p as u32))
                .collect(),
        }
    }

    /// The report as JSON text (pretty-printed).
    #[must_use]
    pub fn to_json(&self) -> String {
        let json = ComparisonJson {
            psnr_db: round4(self.psnr_db),
            explanations: self
                .explanations
                .iter()
                .map(|e| ExplanationJson {
                    term: e.term.name(),
                    light: e.light,
                    object: e.object_name.as_deref(),
                    node: if e.node.len() > 1 { &e.node } else { &[] },
                    factor: round4(e.factor),
                    share: round4(e.share),
                    pixels: e.pixels.len(),
                    summary: &e.summary,
                    cause: e.cause.name(),
                    confidence: round4(e.confidence),
                    sure: e.sureness(),
                    bbox: e.bbox.map(|b| [b.x0, b.y0, b.x1, b.y1]),
                    fits_as_well: &e.fits_as_well,
                    shape: match e.cause {
                        Cause::ExtraObject(shape) => Some(shape.name()),
                        _ => None,
                    },
                })
                .collect(),
            unexplained_share: round4(self.unexplained_share),
            encoding: self.encoding.name(),
            width: self.width,
            height: self.height,
            samples_per_pixel: self.samples_per_pixel,
            flip_mean: round6(self.perceptual().mean),
            flip_p99: round6(self.perceptual().p99),
        };
        serde_json::to_string_pretty(&json).expect("plain data serialises")
    }

    /// The report as lines for a reader.
    #[must_use]
    pub fn text_lines(&self) -> Vec<String> {
        let mut lines = vec![format!(
            "PSNR {:.2} dB over {}x{} pixels (raylab at {} samples per pixel; other image read as {})",
            self.psnr_db,
            self.width,
            self.height,
            self.samples_per_pixel,
            self.encoding.name()
        )];
        if self.explanations.is_empty() {
            lines.push(if self.psnr_db >= PSNR_IDENTICAL_DB {
                "The pictures are identical.".to_owned()
            } else {
                "No explanation: the pictures agree within 8-bit rounding.".to_owned()
            });
        }
        for (i, e) in self.explanations.iter().enumerate() {
            let light = e.light.map_or("-".to_owned(), |l| l.to_string());
            let object = e.object_name.as_deref().unwrap_or("-");
            lines.push(format!(
                "{}. {:>5.1}%  {} (light {light}, object {object}, factor {:.2}, {} pixels, {}; sure: {} {:.2})",
                i + 1,
                100.0 * e.share,
                e.term.name(),
                e.factor + 0.0,
                e.pixels.len(),
                e.cause.name(),
                e.sureness(),
                e.confidence
            ));
            lines.push(format!("   {}", e.summary));
        }
        lines.push(format!(
            "unexplained: {:.1}%",
            100.0 * self.unexplained_share
        ));
        let flip = self.perceptual();
        lines.push(format!(
            "LDR-FLIP: mean {:.4}, 99th percentile {:.4} (0 = no visible difference, 1 = the largest)",
            flip.mean, flip.p99
        ));
        lines
    }
}

/// raylab's picture as it writes it.
#[must_use]
pub fn rgb_of(image: &Image) -> Vec<[u8; 3]> {
    image
        .pixels
        .iter()
        .map(|p| p.to_array().map(encode_linear))
        .collect()
}

/// PSNR of `b` against `a`, over every channel, capped at [`PSNR_IDENTICAL_DB`].
#[must_use]
pub fn psnr_db(a: &[[u8; 3]], b: &[[u8; 3]]) -> f64 {
    let squared: f64 = a
        .iter()
        .zip(b)
        .flat_map(|(x, y)| (0..3).map(move |c| (f64::from(x[c]) - f64::from(y[c])) / 255.0))
        .map(|d| d * d)
        .sum();
    let mse = squared / (3 * a.len().max(1)) as f64;
    if mse == 0.0 {
        PSNR_IDENTICAL_DB
    } else {
        (10.0 * (1.0 / mse).log10()).min(PSNR_IDENTICAL_DB)
    }
}

/// Per pixel, the largest channel difference in levels.
#[must_use]
pub fn difference(a: &[[u8; 3]], b: &[[u8; 3]]) -> Vec<u8> {
    a.iter()
        .zip(b)
        .map(|(x, y)| (0..3).map(|c| x[c].abs_diff(y[c])).max().unwrap_or(0))
        .collect()
}
