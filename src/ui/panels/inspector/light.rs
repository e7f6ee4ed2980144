//! The light inspector: the fields of each light kind.

use egui::Ui;
use glam::DVec3;

use super::fields::{colour_row_ui, number_row_ui, vec3_row_ui, whole_number_row_ui};
use super::layout::{grid_ui, heading_ui};
use super::limits::{LIGHT_RADIUS, LIGHT_SAMPLES, Limits, SPOT_ANGLE_DEG};
use crate::scene::Light;
use crate::ui::commands::{Command, SceneEdit};

pub(super) fn light_ui(ui: &mut Ui, index: usize, light: &Light, commands: &mut Vec<Command>) {
    heading_ui(ui, "LIGHT", &format!("{} light", light.kind_name()));
    let mut edited = light.clone();
    // Positions are in scene units, so they move faster under the mouse than directions.
    let (placement_speed, intensity_speed) = match light {
        Light::Point { .. } | Light::Spot { .. } => (0.02, 0.1),
        Light::Ambient { .. } | Light::Directional { .. } => (0.01, 0.01),
    };
    let any = Limits::ANY;
    grid_ui(ui, "light", |ui| {
        let (colour, intensity) = match &mut edited {
            Light::Ambient { colour, intensity } => (colour, intensity),
            Light::Point { position, source } => {
                vec3_row_ui(ui, "position", position, placement_speed, any);
                sphere_rows_ui(ui, &mut source.radius, &mut source.samples);
                (&mut source.colour, &mut source.intensity)
            }
            Light::Directional {
                direction,
                colour,
                intensity,
            } => {
                vec3_row_ui(ui, "direction", direction, 0.01, any);
                (colour, intensity)
            }
            Light::Spot {
                position,
                direction,
                angle_deg,
                source,
            } => {
                vec3_row_ui(ui, "position", position, placement_speed, any);
                vec3_row_ui(ui, "direction", direction, 0.01, any);
                number_row_ui(ui, "angle", angle_deg, 0.2, SPOT_ANGLE_DEG);
                sphere_rows_ui(ui, &mut source.radius, &mut source.samples);
                (&mut source.colour, &mut source.intensity)
            }
        };
        strength_rows_ui(ui, colour, intensity, intensity_speed);
    });
    if edited != *light {
        commands.push(Command::Edit(SceneEdit::SetLight(index, edited)));
    }
}

/// A Point or Spot light's sphere: its radius (0: a point, hard shadows) and the shadow
/// rays each shading point casts at it.
fn sphere_rows_ui(ui: &mut Ui, radius: &mut f64, samples: &mut u32) {
    number_row_ui(ui, "radius", radius, 0.01, LIGHT_RADIUS);
    whole_number_row_ui(ui, "shadow rays", samples, 0.2, LIGHT_SAMPLES);
}

/// Colour and intensity, which every light kind has.
fn strength_rows_ui(ui: &mut Ui, colour: &mut DVec3, intensity: &mut f64, speed: f64) {
    colour_row_ui(ui, "colour", colour);
    number_row_ui(ui, "intensity", intensity, speed, Limits::NON_NEGATIVE);
}
