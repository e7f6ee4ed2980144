//! REPORT.png: raylab's picture, the other one, the difference heatmap and the LDR-FLIP
//! error map in the first row, the pixels of the top explanations in the second, each
//! panel labelled ([`super::panel_grid_png`]).

use std::path::Path;

use super::comparison::Comparison;
use super::panel_grid::{Panel, panel_grid_png};
use crate::compare::verdict::Explanation;

/// Panels are scaled to about this width.
const PANEL_WIDTH: f64 = 360.0;
/// Panels per row: the four pictures of the first row.
const COLUMNS: u32 = 4;
/// Explanations shown as mask panels.
const MASK_PANELS: usize = 3;
/// Mask pixels are painted in this colour over a dimmed raylab picture.
const MASK_COLOUR: [f64; 3] = [255.0, 150.0, 0.0];

/// The difference heatmap, one colour per pixel, and the number of levels shown as
/// white (the largest difference, at least 1). The report and the editor show this.
#[must_use]
pub fn difference_heatmap(comparison: &Comparison) -> (Vec<[u8; 3]>, u8) {
    let most = comparison
        .difference
        .iter()
        .copied()
        .max()
        .unwrap_or(0)
        .max(1);
    let pixels = comparison
        .difference
        .iter()
        .map(|&d| heat(f64::from(d) / f64::from(most)))
        .collect();
    (pixels, most)
}

/// A colour ramp for the heatmap: black, red, yellow, white as `t` goes 0 to 1.
fn heat(t: f64) -> [u8; 3] {
    let t = t.clamp(0.0, 1.0) * 3.0;
    let (r, g, b) = if t < 1.0 {
        (t, 0.0, 0.0)
    } else if t < 2.0 {
        (1.0, t - 1.0, 0.0)
    } else {
        (1.0, 1.0, t - 2.0)
    };
    [r, g, b].map(|c| (c * 255.0).round() as u8)
}

fn mask_panel(comparison: &Comparison, index: usize, e: &Explanation) -> Panel {
    let mut pixels: Vec<[u8; 3]> = comparison
        .raylab_rgb
        .iter()
        .map(|p| p.map(|c| (f64::from(c) * 0.3) as u8))
        .collect();
    for &p in &e.pixels {
        let base = comparison.raylab_rgb[p as usize];
        pixels[p as usize] =
            std::array::from_fn(|c| (0.65 * MASK_COLOUR[c] + 0.35 * f64::from(base[c])) as u8);
    }
    let light = e.light.map_or(String::new(), |l| format!(", light {l}"));
    let object = e
        .object_name
        .as_ref()
        .map_or(String::new(), |o| format!(", '{o}'"));
    Panel {
        pixels,
        title: format!("{}. {}{light}{object}", index + 1, e.term.name()),
        lines: vec![
            format!(
                "{:.1}% of the difference, factor {:.2}",
                100.0 * e.share,
                e.factor
            ),
            format!(
                "{}, sure: {} ({:.2})",
                e.cause.name(),
                e.sureness(),
                e.confidence
            ),
        ],
    }
}

/// The LDR-FLIP error map in the FLIP tool's own colours, so it reads as FLIP's does.
fn flip_panel(comparison: &Comparison) -> Panel {
    let flip = comparison.perceptual();
    Panel {
        pixels: flip.map_rgb(),
        title: "LDR-FLIP".to_owned(),
        lines: vec![
            format!("mean {:.4}, 99th percentile {:.4}", flip.mean, flip.p99),
            "black = no visible difference, yellow = most".to_owned(),
        ],
    }
}

fn panels(comparison: &Comparison) -> Vec<Panel> {
    let (heatmap, most) = difference_heatmap(comparison);
    let mut panels = vec![
        Panel {
            pixels: comparison.raylab_rgb.clone(),
            title: "raylab".to_owned(),
            lines: vec![format!(
                "{}x{}, samples per pixel: {}",
                comparison.width, comparison.height, comparison.samples_per_pixel
            )],
        },
        Panel {
            pixels: comparison.other.rgb.clone(),
            title: "other renderer".to_owned(),
            lines: vec![format!("read as {}", comparison.encoding.name())],
        },
        Panel {
            pixels: heatmap,
            title: "difference".to_owned(),
            lines: vec![
                format!("white = {most} levels (largest channel)"),
                format!(
                    "PSNR {:.2} dB, unexplained {:.1}%",
                    comparison.psnr_db,
                    100.0 * comparison.unexplained_share
                ),
            ],
        },
        flip_panel(comparison),
    ];
    for (i, e) in comparison.explanations.iter().take(MASK_PANELS).enumerate() {
        panels.push(mask_panel(comparison, i, e));
    }
    panels
}

/// The report as PNG bytes.
///
/// # Errors
/// A message when text cannot be drawn or the PNG not encoded.
pub fn report_png(comparison: &Comparison) -> Result<Vec<u8>, String> {
    let size = (comparison.width, comparison.height);
    panel_grid_png(size, &panels(comparison), COLUMNS, PANEL_WIDTH)
        .map_err(|e| format!("report image: {e}"))
}

/// Writes the report PNG atomically.
///
/// # Errors
/// As [`report_png`], or the write's error naming the file.
pub fn write_report_png(comparison: &Comparison, path: &Path) -> Result<(), String> {
    let bytes = report_png(comparison)?;
    crate::scene::write_atomically(path, &bytes)
        .map_err(|e| format!("cannot write {}: {e}", path.display()))
}
