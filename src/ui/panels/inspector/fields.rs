//! The inspector's field rows: three-number vectors, colours with a swatch, single
//! numbers, laid out in a two-column grid.

use egui::{DragValue, Ui};
use glam::DVec3;

/// Three drag values named "`label` x/y/z".
pub(super) fn vec3_row_ui(
    ui: &mut Ui,
    label: &str,
    value: &mut DVec3,
    speed: f64,
    range: std::ops::RangeInclusive<f64>,
) {
    ui.label(label);
    ui.horizontal(|ui| {
        let width = field_width(ui, 3, 0.0);
        for (axis, component) in
            ["x", "y", "z"]
                .into_iter()
                .zip([&mut value.x, &mut value.y, &mut value.z])
        {
            ui.add_sized(
                [width, ui.spacing().interact_size.y],
                DragValue::new(component)
                    .speed(speed)
                    .range(range.clone())
                    .max_decimals(3)
                    .prefix(format!("{axis} "))
                    .suffix(if label == "rotate" { "°" } else { "" }),
            )
            .accessible_name(format!("{label} {axis}"));
        }
    });
    ui.end_row();
}

/// The width of one of `count` fields sharing a row after `reserved` points.
pub(super) fn field_width(ui: &Ui, count: usize, reserved: f32) -> f32 {
    let spacing = ui.spacing().item_spacing.x * (count as f32 - 1.0);
    ((ui.available_width() - reserved - spacing) / count as f32).clamp(44.0, 96.0)
}

/// A linear-RGB colour: a picker plus the three numbers (lights may exceed 1).
pub(super) fn colour_row_ui(ui: &mut Ui, label: &str, colour: &mut DVec3) {
    ui.label(label);
    ui.horizontal(|ui| {
        let width = field_width(
            ui,
            3,
            ui.spacing().interact_size.x + ui.spacing().item_spacing.x,
        );
        // The picker works in f32 through HSV and may hand back a value that moved by
        // rounding alone: only a real change from the user is taken.
        let clamped = colour.as_vec3().to_array().map(|c| c.clamp(0.0, 1.0));
        let mut picked = clamped;
        let response = ui
            .color_edit_button_rgb(&mut picked)
            .accessible_name(format!("{label} colour"));
        let moved = picked
            .iter()
            .zip(clamped)
            .any(|(a, b)| (a - b).abs() > 1e-4);
        if response.changed() && moved {
            *colour = glam::Vec3::from_array(picked).as_dvec3();
        }
        for (channel, component) in
            ["r", "g", "b"]
                .into_iter()
                .zip([&mut colour.x, &mut colour.y, &mut colour.z])
        {
            ui.add_sized(
                [width, ui.spacing().interact_size.y],
                DragValue::new(component)
                    .speed(0.005)
                    .range(0.0..=f64::INFINITY)
                    .max_decimals(3)
                    .prefix(format!("{channel} ")),
            )
            .accessible_name(format!("{label} {channel}"));
        }
    });
    ui.end_row();
}

/// One labelled drag value.
pub(super) fn number_row_ui<N: egui::emath::Numeric>(
    ui: &mut Ui,
    label: &str,
    value: &mut N,
    speed: f64,
    range: std::ops::RangeInclusive<N>,
) {
    let mut drag = DragValue::new(value).speed(speed).range(range);
    if !N::INTEGRAL {
        drag = drag.max_decimals(3);
    }
    if matches!(label, "angle" | "fov") {
        drag = drag.suffix("°");
    }
    let label = ui.label(label);
    ui.add(drag).labelled_by(label.id);
    ui.end_row();
}
