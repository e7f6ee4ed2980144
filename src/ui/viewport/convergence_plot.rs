//! The live convergence plot: for the preview generation on screen, the estimated
//! remaining error of each anti-aliasing pass against render time since the edit. The
//! worker computes the points as it renders; this file only draws them.

use egui::{Color32, RichText};
use egui_plot::{Line, Plot, PlotPoints, Points};

use crate::preview::{ConvergenceCurve, Pass};
use crate::ui::commands::Command;
use crate::ui::state::PreviewSettings;

/// The plot's title.
pub const CONVERGENCE_TITLE: &str = "Estimated remaining error";

/// What the plot shows, in words (the window says it; a tooltip repeats it).
pub const CONVERGENCE_EXPLANATION: &str = "An estimate, not a measurement: for each \
     anti-aliasing pass, the RMSE between the picture and the converged one (values \
     clamped to [0, 1]), estimated from the difference between the mean of each pixel's \
     first half of samples and the mean of all of them, against the render time spent \
     since the last edit. Passes of one sample per pixel have no estimate. `raylab bench` \
     checks the estimate against the true error.";

/// Shows the convergence window for the curve of `generation`; closing it turns the
/// setting off.
pub fn convergence_plot_ui(
    ctx: &egui::Context,
    curve: Option<(u64, &ConvergenceCurve)>,
    settings: &PreviewSettings,
    commands: &mut Vec<Command>,
) {
    let mut open = true;
    // Over the bottom left of the picture, clear of the outliner and the toolbar.
    let corner = ctx.content_rect().left_bottom() + egui::vec2(250.0, -330.0);
    egui::Window::new("Convergence")
        .open(&mut open)
        .default_pos(corner.max(egui::pos2(0.0, 0.0)))
        .default_size([380.0, 260.0])
        .resizable(true)
        .show(ctx, |ui| curve_ui(ui, curve));
    if !open {
        commands.push(Command::SetPreviewSettings(PreviewSettings {
            show_convergence: false,
            ..*settings
        }));
    }
}

fn curve_ui(ui: &mut egui::Ui, curve: Option<(u64, &ConvergenceCurve)>) {
    ui.label(RichText::new(CONVERGENCE_TITLE).strong())
        .on_hover_text(CONVERGENCE_EXPLANATION);
    let points: Vec<[f64; 2]> = curve
        .map(|(_, c)| c.points())
        .unwrap_or_default()
        .iter()
        .map(|p| [p.render_time.as_secs_f64() * 1e3, p.estimated_rmse])
        .collect();
    match curve.map(|(generation, c)| (generation, c.points().last())) {
        Some((generation, Some(last))) => {
            ui.weak(format!(
                "edit {generation} · {} · estimated RMSE {:.5} after {:.0} ms",
                pass_text(last.pass),
                last.estimated_rmse,
                last.render_time.as_secs_f64() * 1e3,
            ));
        }
        _ => {
            ui.weak("no estimate yet: the first comes with the first anti-aliasing pass");
        }
    }
    let accent = crate::ui::style::ACCENT;
    // A short axis label: a long one, turned along the axis, ran up over the line above
    // the plot (the title already says what is plotted).
    ui.add_space(4.0);
    Plot::new("convergence")
        .x_axis_label("render time since the edit (ms)")
        .y_axis_label("RMSE")
        .include_y(0.0)
        .include_x(0.0)
        .allow_scroll(false)
        .show(ui, |plot| {
            plot.line(Line::new("estimate", PlotPoints::from(points.clone())).color(accent));
            plot.points(
                Points::new("passes", PlotPoints::from(points))
                    .radius(3.0)
                    .color(Color32::WHITE),
            );
        })
        .response
        .on_hover_text(CONVERGENCE_EXPLANATION);
}

/// "8/16 spp" (only anti-aliasing passes have estimates).
fn pass_text(pass: Pass) -> String {
    match pass {
        Pass::Coarse { divider } => format!("1/{divider}"),
        Pass::Full { samples, target } => format!("{samples}/{target} spp"),
    }
}
