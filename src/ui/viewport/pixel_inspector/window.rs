//! The pixel inspector's window: the report laid out as text, bounce by bounce.

use egui::{Color32, RichText};
use glam::DVec3;

use super::{InspectedBounce, InspectedLight, InspectedPixel, PixelInspection};
use crate::trace::{BounceReport, LightRecord, Term, TermSwitches};
use crate::ui::commands::Command;

/// Accessible name of the inspector window's final colour line.
pub const FINAL_COLOUR_LABEL: &str = "final colour";

/// Shows the inspector window; closing it pushes [`Command::InspectPixel`]`(None)`.
pub fn pixel_inspector_ui(
    ctx: &egui::Context,
    inspection: &PixelInspection,
    commands: &mut Vec<Command>,
) {
    let mut open = true;
    // Over the right of the picture, below the toolbar, clear of the side panels.
    let corner = ctx.content_rect().right_top() + egui::vec2(-800.0, 110.0);
    egui::Window::new("Pixel inspector")
        .open(&mut open)
        .default_pos(corner.max(egui::pos2(0.0, 0.0)))
        .default_width(420.0)
        .resizable(true)
        .show(ctx, |ui| {
            let (x, y) = inspection.pixel;
            ui.label(RichText::new(format!("Pixel ({x}, {y})")).strong());
            ui.weak(format!(
                "centre ray, beauty lighting · {}",
                switches_text(inspection.switches)
            ));
            ui.separator();
            match &inspection.result {
                Ok(pixel) => pixel_ui(ui, pixel),
                Err(error) => {
                    ui.colored_label(Color32::from_rgb(255, 120, 110), error);
                }
            }
        });
    if !open {
        commands.push(Command::InspectPixel(None));
    }
}

/// "all terms on", or "off: diffuse, shadows · solo specular".
#[must_use]
pub fn switches_text(switches: TermSwitches) -> String {
    let off: Vec<&str> = Term::ALL
        .into_iter()
        .filter(|t| !switches.is_on(*t))
        .map(Term::name)
        .collect();
    let mut parts = Vec::new();
    if !off.is_empty() {
        parts.push(format!("off: {}", off.join(", ")));
    }
    if let Some(solo) = switches.solo {
        parts.push(format!("solo {solo}"));
    }
    if parts.is_empty() {
        "all terms on".to_owned()
    } else {
        parts.join(" · ")
    }
}

fn pixel_ui(ui: &mut egui::Ui, pixel: &InspectedPixel) {
    for line in isolation_lines(pixel) {
        ui.label(RichText::new(line).color(crate::ui::style::ACCENT));
    }
    let report = &pixel.report;
    egui::ScrollArea::vertical()
        .max_height(380.0)
        .show(ui, |ui| {
            for (bounce, names) in report.bounces.iter().zip(&pixel.bounces) {
                let title = match bounce.depth {
                    0 => "Camera ray".to_owned(),
                    d => format!("Reflection, depth {d}"),
                };
                egui::CollapsingHeader::new(RichText::new(title).strong())
                    .id_salt(("bounce", bounce.depth))
                    .default_open(true)
                    .show(ui, |ui| bounce_ui(ui, bounce, names));
            }
        });
    ui.separator();
    egui::Grid::new("final colour")
        .num_columns(2)
        .show(ui, |ui| {
            ui.label("before clamping");
            ui.monospace(colour_text(report.unclamped));
            ui.end_row();
            ui.label(FINAL_COLOUR_LABEL);
            ui.horizontal(|ui| {
                swatch_ui(ui, report.clamped);
                ui.monospace(colour_text(report.clamped));
            });
            ui.end_row();
        });
}

fn bounce_ui(ui: &mut egui::Ui, bounce: &BounceReport, names: &InspectedBounce) {
    let (Some(hit), Some(hit_names)) = (&bounce.hit, &names.hit) else {
        egui::Grid::new(("miss", bounce.depth))
            .num_columns(2)
            .show(ui, |ui| {
                ui.label("hit");
                ui.label("nothing (background)");
                ui.end_row();
                ui.label("colour");
                ui.monospace(colour_text(bounce.colour));
                ui.end_row();
            });
        return;
    };
    egui::Grid::new(("hit", bounce.depth))
        .num_columns(2)
        .show(ui, |ui| {
            ui.label("hit");
            ui.label(RichText::new(&hit_names.object).strong());
            ui.end_row();
            ui.label("material");
            ui.label(&hit_names.material);
            ui.end_row();
            number_row_ui(ui, "t", format!("{:.6}", hit.t));
            number_row_ui(ui, "point", vector_text(hit.p));
            number_row_ui(ui, "normal", vector_text(hit.n));
            number_row_ui(ui, "ambient", colour_text(bounce.ambient));
        });
    for (light, light_names) in bounce.lights.iter().zip(&names.lights) {
        light_ui(ui, light, light_names, bounce.depth);
    }
    if bounce.lights.is_empty() {
        ui.weak("no light reaches this point");
    }
    egui::Grid::new(("result", bounce.depth))
        .num_columns(2)
        .show(ui, |ui| {
            ui.label("reflection");
            match bounce.reflection {
                Some((km, reflected)) => ui.monospace(format!(
                    "km {} × {} = {}",
                    colour_text(km),
                    colour_text(reflected),
                    colour_text(km * reflected)
                )),
                None => ui.weak("no mirror ray"),
            };
            ui.end_row();
            ui.label("colour");
            ui.monospace(colour_text(bounce.colour));
            ui.end_row();
        });
}

fn light_ui(ui: &mut egui::Ui, light: &LightRecord, names: &InspectedLight, depth: u32) {
    ui.label(RichText::new(&names.label).underline());
    egui::Grid::new(("light", depth, &names.label))
        .num_columns(2)
        .show(ui, |ui| {
            number_row_ui(ui, "strength", colour_text(light.strength));
            number_row_ui(ui, "n·l", format!("{:.4}", light.n_dot_l));
            ui.label("shadow ray");
            ui.label(shadow_text(light, names));
            ui.end_row();
            number_row_ui(ui, "diffuse", colour_text(light.diffuse));
            number_row_ui(ui, "specular", colour_text(light.specular));
        });
}

/// What the isolation switches leave out of every bounce, one line each:
/// "off (muted or not solo): Point light 2" and "hidden (rays pass through): red ball".
#[must_use]
pub fn isolation_lines(pixel: &InspectedPixel) -> Vec<String> {
    let mut lines = Vec::new();
    if !pixel.lights_off.is_empty() {
        lines.push(format!(
            "off (muted or not solo): {}",
            pixel.lights_off.join(", ")
        ));
    }
    if !pixel.hidden_objects.is_empty() {
        lines.push(format!(
            "hidden (rays pass through): {}",
            pixel.hidden_objects.join(", ")
        ));
    }
    lines
}

/// "blocked by red ball", "cast, reaches the light", "not cast".
#[must_use]
pub fn shadow_text(light: &LightRecord, names: &InspectedLight) -> String {
    match (&names.blocked_by, light.shadow_ray_cast) {
        (Some(blocker), _) => format!("blocked by {blocker}"),
        (None, true) => "cast, reaches the light".to_owned(),
        (None, false) => "not cast".to_owned(),
    }
}

/// One grid row: a label and a number in monospace.
fn number_row_ui(ui: &mut egui::Ui, label: &str, value: String) {
    ui.label(label);
    ui.monospace(value);
    ui.end_row();
}

fn swatch_ui(ui: &mut egui::Ui, colour: DVec3) {
    let (rect, _) = ui.allocate_exact_size(egui::vec2(14.0, 14.0), egui::Sense::hover());
    let [r, g, b] = colour
        .as_vec3()
        .to_array()
        .map(crate::trace::image::encode_linear);
    ui.painter()
        .rect_filled(rect, 2.0, Color32::from_rgb(r, g, b));
}

fn colour_text(c: DVec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", c.x, c.y, c.z)
}

fn vector_text(v: DVec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", v.x, v.y, v.z)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn switches_read_as_on_the_command_line() {
        let mut switches = TermSwitches::ALL_ON;
        assert_eq!(switches_text(switches), "all terms on");
        switches.set(Term::Diffuse, false);
        switches.set(Term::Shadows, false);
        assert_eq!(
            switches_text(switches.with_solo(Some(Term::Specular))),
            "off: diffuse, shadows · solo specular"
        );
    }
}
