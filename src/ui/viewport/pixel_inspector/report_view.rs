//! The pixel inspector's report laid out as text: the final colour, then each ray of the
//! pixel's tree (the camera ray, its mirror and transmitted rays) with its hit, its
//! terms and every light of the scene with what its shadow rays found.

use egui::{Color32, RichText};
use glam::DVec3;

use super::inspection::{InspectedBounce, InspectedLight, InspectedPixel};
use crate::trace::{BounceReport, Branch, LightRecord};

/// The label of the final colour's row (tests find the window by it).
pub const FINAL_COLOUR_LABEL: &str = "final colour";

pub(super) fn pixel_ui(ui: &mut egui::Ui, pixel: &InspectedPixel) {
    for line in isolation_lines(pixel) {
        ui.label(RichText::new(line).color(crate::ui::style::ACCENT));
    }
    let report = &pixel.report;
    egui::Grid::new("final colour")
        .num_columns(2)
        .show(ui, |ui| {
            ui.label(FINAL_COLOUR_LABEL);
            ui.horizontal(|ui| {
                swatch_ui(ui, report.clamped);
                ui.monospace(colour_text(report.clamped));
            });
            ui.end_row();
            ui.label("before clamping");
            ui.monospace(colour_text(report.unclamped));
            ui.end_row();
        });
    for (index, (bounce, names)) in report.bounces.iter().zip(&pixel.bounces).enumerate() {
        egui::CollapsingHeader::new(RichText::new(bounce_title(bounce)).strong())
            .id_salt(("bounce", index))
            .default_open(true)
            .show(ui, |ui| bounce_ui(ui, index, bounce, names));
    }
}

/// "Camera ray", "Reflection, depth 2", "Refraction, depth 1 (from ray 1)", or
/// "Total internal reflection, depth 3 (from ray 2)": rays number from 1 in the order the
/// window lists them, named where a tree makes the parent ambiguous.
fn bounce_title(bounce: &BounceReport) -> String {
    let Some((parent, branch)) = bounce.from else {
        return "Camera ray".to_owned();
    };
    let what = match branch {
        Branch::Mirror => "Reflection",
        Branch::Refracted => "Refraction",
        Branch::InternallyReflected => "Total internal reflection",
    };
    let depth = bounce.depth;
    if parent + 1 == depth as usize {
        format!("{what}, depth {depth}")
    } else {
        format!("{what}, depth {depth} (from ray {})", parent + 1)
    }
}

fn bounce_ui(ui: &mut egui::Ui, index: usize, bounce: &BounceReport, names: &InspectedBounce) {
    let (Some(hit), Some(hit_names)) = (&bounce.hit, &names.hit) else {
        egui::Grid::new(("miss", index))
            .num_columns(2)
            .show(ui, |ui| {
                ui.label("hit");
                ui.label("nothing (background)");
                ui.end_row();
                number_row_ui(ui, "colour", colour_text(bounce.colour));
            });
        return;
    };
    egui::Grid::new(("hit", index))
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
    for light in &names.lights {
        light_ui(ui, light, index);
    }
    if names.lights.is_empty() {
        ui.weak("the scene has no lights");
    }
    egui::Grid::new(("result", index))
        .num_columns(2)
        .show(ui, |ui| {
            // One colour per row: all three on one line would widen the window over
            // the pixel it sits beside.
            match bounce.reflection {
                Some((km, reflected)) => {
                    number_row_ui(ui, "mirror km", colour_text(km));
                    number_row_ui(ui, "reflected", colour_text(reflected));
                    number_row_ui(ui, "km × reflected", colour_text(km * reflected));
                }
                None => {
                    ui.label("reflection");
                    ui.weak("no mirror ray");
                    ui.end_row();
                }
            }
            if let Some((kt, transmitted)) = bounce.transmission {
                number_row_ui(ui, "transmission kt", colour_text(kt));
                number_row_ui(ui, "transmitted", colour_text(transmitted));
                number_row_ui(ui, "kt × transmitted", colour_text(kt * transmitted));
            }
            if let Some(unclamped) = bounce.unclamped {
                number_row_ui(ui, "before each-ray clamp", colour_text(unclamped));
            }
            number_row_ui(ui, "colour", colour_text(bounce.colour));
        });
}

/// One light: its name, what it did (green when it added light), and the numbers.
fn light_ui(ui: &mut egui::Ui, light: &InspectedLight, bounce: usize) {
    ui.horizontal(|ui| {
        ui.label(RichText::new(&light.label).underline());
        let colour = if light.adds_light {
            Color32::from_rgb(140, 220, 140)
        } else {
            Color32::from_gray(160)
        };
        ui.label(RichText::new(&light.outcome).color(colour));
    });
    let Some(record) = &light.record else {
        return;
    };
    egui::Grid::new(("light", bounce, light.scene_index))
        .num_columns(2)
        .show(ui, |ui| {
            number_row_ui(ui, "strength", colour_text(record.strength));
            number_row_ui(ui, "n·l", format!("{:.4}", record.n_dot_l));
            ui.label("shadow ray");
            ui.label(shadow_text(record));
            ui.end_row();
            number_row_ui(ui, "diffuse", colour_text(record.diffuse));
            number_row_ui(ui, "specular", colour_text(record.specular));
        });
}

/// What a light's shadow rays found: "blocked", "12 of 16 reach the light (vis 0.75)".
fn shadow_text(record: &LightRecord) -> String {
    let (fraction, rays) = record.visibility;
    if !record.shadow_ray_cast {
        return if record.n_dot_l <= 0.0 {
            "not cast (light behind the surface)"
        } else {
            "not cast (shadows off)"
        }
        .to_owned();
    }
    if rays > 1 {
        let reach = (fraction * f64::from(rays)).round();
        return format!("{reach} of {rays} reach the light (vis {fraction:.3})");
    }
    if record.blocked_by.is_some() {
        "blocked".to_owned()
    } else {
        "cast, reaches the light".to_owned()
    }
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

/// One grid row: a label and a number in monospace.
fn number_row_ui(ui: &mut egui::Ui, label: &str, value: String) {
    ui.label(label);
    ui.monospace(value);
    ui.end_row();
}

fn swatch_ui(ui: &mut egui::Ui, colour: DVec3) {
    let (rect, _) = ui.allocate_exact_size(egui::vec2(14.0, 14.0), egui::Sense::hover());
    let [r, g, b] = colour.as_vec3().to_array().map(crate::trace::encode_linear);
    ui.painter()
        .rect_filled(rect, 2.0, Color32::from_rgb(r, g, b));
}

fn colour_text(c: DVec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", c.x, c.y, c.z)
}

fn vector_text(v: DVec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", v.x, v.y, v.z)
}
