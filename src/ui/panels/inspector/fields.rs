//! The inspector's field rows: three-number vectors, colours with a swatch, single
//! numbers, laid out in a two-column grid.
//!
//! Showing is not editing: every widget edits a copy, and the value itself changes only
//! when the widget reports a change from the user and [`Limits`] takes the new number.
//! A value outside a field's drag range (a mirror's negative scale, a 720° rotation, an
//! HDR colour) is shown as it is, never clamped.

use std::ops::RangeInclusive;

use egui::{DragValue, Response, Ui};
use glam::DVec3;

use super::limits::Limits;

/// Three drag values named "`label` x/y/z".
pub(super) fn vec3_row_ui(ui: &mut Ui, label: &str, value: &mut DVec3, speed: f64, limits: Limits) {
    ui.label(label);
    ui.horizontal(|ui| {
        let width = field_width(ui, 3, 0.0);
        let suffix = if label == "rotate" { "°" } else { "" };
        for (axis, component) in
            ["x", "y", "z"]
                .into_iter()
                .zip([&mut value.x, &mut value.y, &mut value.z])
        {
            number_ui(ui, component, limits, Some(width), |drag| {
                drag.speed(speed).prefix(format!("{axis} ")).suffix(suffix)
            })
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

/// A linear-RGB colour: a swatch plus the three numbers, which are authoritative. The
/// swatch shows the colour scaled into [0, 1] by its largest channel (an HDR light of
/// (4, 2, 0) shows as (1, 0.5, 0)) and a colour picked there keeps that scale, so picking
/// a hue never dims a light.
pub(super) fn colour_row_ui(ui: &mut Ui, label: &str, colour: &mut DVec3) {
    ui.label(label);
    ui.horizontal(|ui| {
        let width = field_width(
            ui,
            3,
            ui.spacing().interact_size.x + ui.spacing().item_spacing.x,
        );
        swatch_ui(ui, label, colour);
        for (channel, component) in
            ["r", "g", "b"]
                .into_iter()
                .zip([&mut colour.x, &mut colour.y, &mut colour.z])
        {
            number_ui(ui, component, Limits::NON_NEGATIVE, Some(width), |drag| {
                drag.speed(0.005).prefix(format!("{channel} "))
            })
            .accessible_name(format!("{label} {channel}"));
        }
    });
    ui.end_row();
}

/// The colour picker button: edits the colour's hue and relative brightness.
fn swatch_ui(ui: &mut Ui, label: &str, colour: &mut DVec3) {
    let scale = colour.max_element().max(1.0);
    let shown = (*colour / scale).as_vec3().to_array();
    let mut picked = shown;
    let response = ui
        .color_edit_button_rgb(&mut picked)
        .accessible_name(format!("{label} colour"));
    // The picker works in f32 through HSV and may hand back a value that moved by
    // rounding alone: only a real change from the user is taken.
    let moved = picked.iter().zip(shown).any(|(a, b)| (a - b).abs() > 1e-4);
    if response.changed() && moved {
        *colour = glam::Vec3::from_array(picked).as_dvec3() * scale;
    }
}

/// One labelled number.
pub(super) fn number_row_ui(ui: &mut Ui, label: &str, value: &mut f64, speed: f64, limits: Limits) {
    let suffix = if matches!(label, "angle" | "fov") {
        "°"
    } else {
        ""
    };
    let label = ui.label(label);
    number_ui(ui, value, limits, None, |drag| {
        drag.speed(speed).suffix(suffix)
    })
    .labelled_by(label.id);
    ui.end_row();
}

/// One labelled whole number in `range`.
pub(super) fn whole_number_row_ui(
    ui: &mut Ui,
    label: &str,
    value: &mut u32,
    speed: f64,
    range: RangeInclusive<u32>,
) {
    let label = ui.label(label);
    let mut shown = *value;
    let response = ui.add(
        DragValue::new(&mut shown)
            .speed(speed)
            .range(range.clone())
            .clamp_existing_to_range(false),
    );
    if response.changed() {
        *value = shown.clamp(*range.start(), *range.end());
    }
    response.labelled_by(label.id);
    ui.end_row();
}

/// A drag value over a copy of `value`; `value` takes the copy only after a change by
/// the user that `limits` accepts. `width` fixes the field's width (its natural width
/// otherwise).
fn number_ui(
    ui: &mut Ui,
    value: &mut f64,
    limits: Limits,
    width: Option<f32>,
    look: impl FnOnce(DragValue<'_>) -> DragValue<'_>,
) -> Response {
    let mut shown = *value;
    let drag = DragValue::new(&mut shown)
        .range(limits.range())
        .clamp_existing_to_range(false)
        .max_decimals(3);
    let drag = look(drag);
    let response = match width {
        Some(width) => ui.add_sized([width, ui.spacing().interact_size.y], drag),
        None => ui.add(drag),
    };
    if response.changed()
        && shown != *value
        && let Some(taken) = limits.take(shown)
    {
        *value = taken;
    }
    response
}
