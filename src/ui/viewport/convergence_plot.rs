//! The live convergence plot: for the current preview generation, how much each pass
//! still changed the picture (RMSE against the pass before it), against render time
//! since the edit. Falls towards zero as the image settles.

use egui::{Color32, RichText};
use egui_plot::{Line, Plot, PlotPoints, Points};

use crate::preview::{ConvergenceCurve, Pass};
use crate::ui::commands::Command;
use crate::ui::viewport::preview_settings::PreviewSettings;

/// What the plot shows, in words (the window says it; a tooltip repeats it).
pub const CONVERGENCE_EXPLANATION: &str = "Change from the previous pass: RMSE between each \
     pass and the one before it (values clamped to [0, 1], coarse passes enlarged \
     nearest-neighbour), against the render time spent since the last edit. It measures \
     how much the picture still changes, not the error against a converged reference.";

/// Shows the convergence window; closing it turns the setting off.
pub fn convergence_plot_ui(
    ctx: &egui::Context,
    curve: &ConvergenceCurve,
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

fn curve_ui(ui: &mut egui::Ui, curve: &ConvergenceCurve) {
    ui.label(RichText::new("Change from previous pass").strong())
        .on_hover_text(CONVERGENCE_EXPLANATION);
    let points: Vec<[f64; 2]> = curve
        .points()
        .iter()
        .map(|p| [p.render_time.as_secs_f64() * 1e3, p.change])
        .collect();
    match (curve.generation(), curve.points().last()) {
        (Some(generation), Some(last)) => {
            ui.weak(format!(
                "edit {generation} · {} passes compared · last: {} at {:.0} ms, RMSE {:.5}",
                points.len(),
                pass_text(last.pass),
                last.render_time.as_secs_f64() * 1e3,
                last.change
            ));
        }
        _ => {
            ui.weak("waiting for a second pass of this edit");
        }
    }
    let accent = crate::ui::style::ACCENT;
    Plot::new("convergence")
        .x_axis_label("render time since the edit (ms)")
        .y_axis_label("RMSE vs previous pass")
        .include_y(0.0)
        .include_x(0.0)
        .allow_scroll(false)
        .show(ui, |plot| {
            plot.line(Line::new("change", PlotPoints::from(points.clone())).color(accent));
            plot.points(
                Points::new("passes", PlotPoints::from(points))
                    .radius(3.0)
                    .color(Color32::WHITE),
            );
        })
        .response
        .on_hover_text(CONVERGENCE_EXPLANATION);
}

/// "1/4", "1 spp", "8/16 spp".
fn pass_text(pass: Pass) -> String {
    match pass {
        Pass::Coarse { divider } => format!("1/{divider}"),
        Pass::Full { target: 1, .. } => "1 spp".to_owned(),
        Pass::Full { samples, target } => format!("{samples}/{target} spp"),
    }
}
