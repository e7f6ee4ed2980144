//! Pictures laid out in a grid, each under a title and a few lines of caption, as one
//! PNG: the diff's report image and the bug gallery's contact sheet. Panels are scaled
//! with nearest-pixel sampling so single pixels stay visible in small renders.

use plotters::prelude::*;

/// Height of the caption above each panel: a title and up to two lines.
const LABEL_HEIGHT: u32 = 58;
/// Space around panels.
const MARGIN: u32 = 12;

/// One picture of the grid and its caption.
pub struct Panel {
    /// Its pixels, row-major from the top-left, at the grid's picture size.
    pub pixels: Vec<[u8; 3]>,
    /// The first line, larger.
    pub title: String,
    /// Up to two more lines.
    pub lines: Vec<String>,
}

/// `panels` (each `width` x `height` pixels) in `columns` columns, each scaled to about
/// `panel_width` pixels wide, as PNG bytes.
///
/// # Errors
/// A message when text cannot be drawn or the PNG not encoded.
///
/// # Panics
/// When a panel does not hold `width * height` pixels.
pub fn panel_grid_png(
    (width, height): (u32, u32),
    panels: &[Panel],
    columns: u32,
    panel_width: f64,
) -> Result<Vec<u8>, String> {
    // ab_glyph draws text from font bytes; egui's own font ships with the project.
    let _ = plotters::style::register_font(
        "sans-serif",
        FontStyle::Normal,
        epaint_default_fonts::UBUNTU_LIGHT,
    );
    let (w, h) = (width, height);
    let scale = panel_width / f64::from(w);
    let (pw, ph) = (
        ((f64::from(w) * scale).round() as u32).max(1),
        ((f64::from(h) * scale).round() as u32).max(1),
    );
    let columns = columns.max(1);
    let rows = (panels.len() as u32).div_ceil(columns);
    let cell = (pw + MARGIN, ph + LABEL_HEIGHT + MARGIN);
    let size = (MARGIN + columns * cell.0, MARGIN + rows * cell.1);
    let mut buffer = vec![255u8; (size.0 * size.1 * 3) as usize];
    for (i, panel) in panels.iter().enumerate() {
        assert_eq!(panel.pixels.len(), (w * h) as usize, "panel size");
        let x0 = MARGIN + (i as u32 % columns) * cell.0;
        let y0 = MARGIN + (i as u32 / columns) * cell.1 + LABEL_HEIGHT;
        for y in 0..ph {
            let sy = ((f64::from(y) + 0.5) / scale) as u32;
            for x in 0..pw {
                let sx = ((f64::from(x) + 0.5) / scale) as u32;
                let source = panel.pixels[(sy.min(h - 1) * w + sx.min(w - 1)) as usize];
                let at = (((y0 + y) * size.0 + x0 + x) * 3) as usize;
                buffer[at..at + 3].copy_from_slice(&source);
            }
        }
    }
    {
        let error = |e: &dyn std::fmt::Display| format!("panel grid: {e}");
        let root = BitMapBackend::with_buffer(&mut buffer, size).into_drawing_area();
        for (i, panel) in panels.iter().enumerate() {
            let x = (MARGIN + (i as u32 % columns) * cell.0) as i32;
            let y = (MARGIN + (i as u32 / columns) * cell.1) as i32;
            root.draw(&Text::new(
                panel.title.clone(),
                (x, y),
                ("sans-serif", 19).into_font().color(&BLACK),
            ))
            .map_err(|e| error(&e))?;
            for (k, line) in panel.lines.iter().take(2).enumerate() {
                root.draw(&Text::new(
                    line.clone(),
                    (x, y + 22 + 16 * k as i32),
                    ("sans-serif", 14).into_font().color(&RGBColor(60, 60, 60)),
                ))
                .map_err(|e| error(&e))?;
            }
        }
        root.present().map_err(|e| error(&e))?;
    }
    let image = image::RgbImage::from_raw(size.0, size.1, buffer).ok_or("panel grid size")?;
    let mut bytes = Vec::new();
    image
        .write_to(
            &mut std::io::Cursor::new(&mut bytes),
            image::ImageFormat::Png,
        )
        .map_err(|e| format!("panel grid: {e}"))?;
    Ok(bytes)
}
