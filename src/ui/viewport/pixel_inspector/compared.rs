//! The pixel inspector's comparison rows: raylab's value and the other picture's at the
//! inspected pixel, as bytes and as linear colour, and the explanations that cover it.

use egui::RichText;

use crate::compare::PixelValues;

/// Accessible name of the row with raylab's value.
pub const RAYLAB_VALUE_LABEL: &str = "raylab value";
/// Accessible name of the row with the other picture's value.
pub const OTHER_VALUE_LABEL: &str = "other image value";

/// The rows as (label, text): raylab's bytes and linear colour, the other picture's
/// bytes and their decoded value, the largest difference and the explanations.
#[must_use]
pub fn compared_rows(values: &PixelValues) -> Vec<(&'static str, String)> {
    let [r, g, b] = values.raylab_linear;
    let [or, og, ob] = values.other_linear;
    let largest = (0..3)
        .map(|c| values.raylab_rgb[c].abs_diff(values.other_rgb[c]))
        .max()
        .unwrap_or(0);
    let explanations = if values.explanations.is_empty() {
        "none".to_owned()
    } else {
        let numbers: Vec<String> = values
            .explanations
            .iter()
            .map(|i| (i + 1).to_string())
            .collect();
        numbers.join(", ")
    };
    vec![
        (
            RAYLAB_VALUE_LABEL,
            format!("{:?} · ({r:.4}, {g:.4}, {b:.4})", values.raylab_rgb),
        ),
        (
            OTHER_VALUE_LABEL,
            format!("{:?} · ({or:.4}, {og:.4}, {ob:.4})", values.other_rgb),
        ),
        ("difference", format!("{largest} levels (largest channel)")),
        ("explained by", explanations),
    ]
}

/// Shows the rows as a grid.
pub fn compared_ui(ui: &mut egui::Ui, values: &PixelValues) {
    ui.label(RichText::new("Compared with the other image").strong());
    egui::Grid::new("compared values")
        .num_columns(2)
        .show(ui, |ui| {
            for (label, text) in compared_rows(values) {
                ui.label(label);
                ui.monospace(&text)
                    .on_hover_text("bytes · linear colour")
                    .widget_info(|| {
                        egui::WidgetInfo::labeled(
                            egui::Role::Label,
                            true,
                            format!("{label}: {text}"),
                        )
                    });
                ui.end_row();
            }
        });
}
