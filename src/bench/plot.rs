//! The error-against-time plot of the bench, drawn to a PNG with plotters.

use std::path::Path;

use plotters::prelude::*;

use super::convergence::CurvePoint;

/// Colours of the strategies, in the order they are drawn.
const SERIES: [(&str, RGBColor); 3] = [
    ("uniform", RGBColor(70, 130, 220)),
    ("adaptive", RGBColor(220, 90, 50)),
    ("progressive", RGBColor(60, 160, 90)),
];

/// The progressive preview's own estimate of its error, drawn dashed beside its true error.
const ESTIMATE: (&str, RGBColor) = ("progressive, estimated", RGBColor(60, 160, 90));

/// Draws RMSE (log scale) against render time (log scale), one line per strategy, and the
/// preview's estimate of its error as a dashed line.
///
/// # Errors
/// A message when the font cannot be registered or the file cannot be written.
pub fn plot_curve(curve: &[CurvePoint], path: &Path, title: &str) -> Result<(), String> {
    // ab_glyph draws text from font bytes; egui's own font ships with the project.
    let _ = plotters::style::register_font(
        "sans-serif",
        FontStyle::Normal,
        epaint_default_fonts::UBUNTU_LIGHT,
    );
    let error = |e: &dyn std::fmt::Display| format!("plot {}: {e}", path.display());
    const SIZE: (u32, u32) = (900, 560);
    let mut pixels = vec![0u8; (SIZE.0 * SIZE.1 * 3) as usize];
    let root = BitMapBackend::with_buffer(&mut pixels, SIZE).into_drawing_area();
    root.fill(&WHITE).map_err(|e| error(&e))?;
    let times = curve.iter().map(|p| p.time_ms.max(1e-3));
    let errors = curve
        .iter()
        .flat_map(|p| [Some(p.rmse), p.estimated_rmse])
        .flatten()
        .map(|e| e.max(1e-6));
    let (t_min, t_max) = times.fold((f64::INFINITY, 0.0f64), |(a, b), t| (a.min(t), b.max(t)));
    let (e_min, e_max) = errors.fold((f64::INFINITY, 0.0f64), |(a, b), e| (a.min(e), b.max(e)));
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 22))
        .margin(16)
        .x_label_area_size(44)
        .y_label_area_size(64)
        .build_cartesian_2d(
            (t_min * 0.8..t_max * 1.25).log_scale(),
            (e_min * 0.8..e_max * 1.25).log_scale(),
        )
        .map_err(|e| error(&e))?;
    chart
        .configure_mesh()
        .x_desc("render time (ms)")
        .y_desc("RMSE vs reference (dashed: estimate)")
        .label_style(("sans-serif", 15))
        .draw()
        .map_err(|e| error(&e))?;
    for (name, colour) in SERIES {
        let points: Vec<(f64, f64)> = curve
            .iter()
            .filter(|p| p.strategy == name)
            .map(|p| (p.time_ms.max(1e-3), p.rmse.max(1e-6)))
            .collect();
        if points.is_empty() {
            continue;
        }
        chart
            .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))
            .map_err(|e| error(&e))?
            .label(name)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
            });
        chart
            .draw_series(
                points
                    .into_iter()
                    .map(|p| Circle::new(p, 4, colour.filled())),
            )
            .map_err(|e| error(&e))?;
    }
    let estimates: Vec<(f64, f64)> = curve
        .iter()
        .filter_map(|p| Some((p.time_ms.max(1e-3), p.estimated_rmse?.max(1e-6))))
        .collect();
    if !estimates.is_empty() {
        let (name, colour) = ESTIMATE;
        chart
            .draw_series(DashedLineSeries::new(
                estimates,
                8,
                6,
                colour.stroke_width(2),
            ))
            .map_err(|e| error(&e))?
            .label(name)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 8, y)], colour.stroke_width(2))
            });
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .label_font(("sans-serif", 16))
        .draw()
        .map_err(|e| error(&e))?;
    root.present().map_err(|e| error(&e))?;
    drop(chart);
    drop(root);
    let png = image::RgbImage::from_raw(SIZE.0, SIZE.1, pixels).ok_or("plot buffer size")?;
    let mut bytes = Vec::new();
    png.write_to(
        &mut std::io::Cursor::new(&mut bytes),
        image::ImageFormat::Png,
    )
    .map_err(|e| error(&e))?;
    crate::scene::write_atomically(path, &bytes).map_err(|e| error(&e))
}
