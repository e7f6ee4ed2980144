//! The inspector's field rows: three-number vectors, colours with a swatch, single
//! numbers, laid out in a two-column grid.
//!
//! Showing is not editing: every widget edits a copy, and the value itself changes only
//! when the widget reports a change from the user and [`Limits`] takes the new number.
//! A value outside a field's drag range (a mirror's negative scale, a 720° rotation, an
//! HDR colour) is shown as it is, never clamped.
//!
//! Typed text is the user's until the edit ends (Return, Tab, a click elsewhere): only
//! then is it read, taken or refused, so a half-typed `0.` or `.` or an emptied field
//! is never judged, rewritten or taken.

use std::cell::Cell;
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
                drag.speed(speed)
                    .prefix(axis_prefix(axis, width))
                    .suffix(suffix)
            })
            .accessible_name(format!("{label} {axis}"));
        }
    });
    ui.end_row();
}

/// A field's "x " or "r " prefix, left out where the field is too narrow for it and its
/// number (the row's order and the field's accessible name still say which it is), so a
/// row never grows past the panel.
fn axis_prefix(axis: &str, width: f32) -> String {
    if has_prefix(width) {
        format!("{axis} ")
    } else {
        String::new()
    }
}

/// Whether a field `width` points wide has room for its "x " prefix.
fn has_prefix(width: f32) -> bool {
    width >= 58.0
}

/// How many characters of number fit in a field `width` points wide, beside its prefix:
/// about 7 points a character at the body size, the prefix taking two.
fn number_room(width: f32) -> usize {
    let prefix = if has_prefix(width) { 2.0 } else { 0.0 };
    (((width - 10.0) / 7.0).floor() - prefix).max(4.0) as usize
}

/// `value` in at most the characters a field `width` points wide has room for (beside
/// its prefix, if it has one): up to three decimals, fewer where they do not fit, and
/// scientific notation where even the whole number does not.
fn fitted_number(value: f64, width: f32) -> String {
    let room = number_room(width);
    for decimals in (0..=3).rev() {
        let text = format!("{value:.decimals$}");
        if text.len() <= room {
            // A tiny negative shown as zero is zero: no "-0.000".
            let zero = text
                .trim_start_matches('-')
                .chars()
                .all(|c| c == '0' || c == '.');
            return if zero {
                text.trim_start_matches('-').to_owned()
            } else {
                text
            };
        }
    }
    format!("{value:.0e}")
}

/// The width of one of `count` fields sharing a row after `reserved` points: what is
/// left of the row, less a margin for the scroll bar that floats over the right edge,
/// so the row fits in the panel (a row wider than the panel would be cut off).
pub(super) fn field_width(ui: &Ui, count: usize, reserved: f32) -> f32 {
    let spacing = ui.spacing().item_spacing.x * (count as f32 - 1.0);
    let margin = ui.spacing().scroll.bar_width + ui.spacing().item_spacing.x;
    ((ui.available_width() - reserved - spacing - margin) / count as f32).clamp(34.0, 96.0)
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
                drag.speed(0.005).prefix(axis_prefix(channel, width))
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
    // As in `number_ui`: what was typed, to say what became of it.
    let typed: Cell<Option<Result<f64, String>>> = Cell::new(None);
    let response = ui.add(
        DragValue::new(&mut shown)
            .speed(speed)
            .range(range.clone())
            .clamp_existing_to_range(false)
            .update_while_editing(false)
            .custom_parser(|text| parse_typed(text, &typed)),
    );
    if let Some(typed) = typed.take() {
        let limits = Limits::closed(f64::from(*range.start()), f64::from(*range.end()));
        notice_typed(ui.ctx(), typed, f64::from(*value), limits);
    }
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
    // What the user typed, before the field holds it to its range: a value refused or
    // held is then said, not dropped in silence.
    let typed: Cell<Option<Result<f64, String>>> = Cell::new(None);
    let drag = DragValue::new(&mut shown)
        .range(limits.range())
        .clamp_existing_to_range(false)
        .update_while_editing(false)
        .max_decimals(3)
        .custom_parser(|text| parse_typed(text, &typed));
    // A fixed-width field shows what fits: fewer decimals, then scientific notation, so a
    // huge or tiny value never widens it (the value itself is untouched).
    let drag = match width {
        Some(width) => drag.custom_formatter(move |v, _| fitted_number(v, width)),
        None => drag,
    };
    let drag = look(drag);
    let response = match width {
        Some(width) => ui.add_sized([width, ui.spacing().interact_size.y], drag),
        None => ui.add(drag),
    };
    if let Some(typed) = typed.take() {
        notice_typed(ui.ctx(), typed, *value, limits);
    }
    if response.changed()
        && shown != *value
        && let Some(taken) = limits.take(shown)
    {
        *value = taken;
    }
    response
}

/// Reads typed text as a number, keeping what was typed in `typed` (to say what became
/// of it); `None` for text that is not a finite number.
fn parse_typed(text: &str, typed: &Cell<Option<Result<f64, String>>>) -> Option<f64> {
    let parsed = text
        .trim()
        .parse::<f64>()
        .map_err(|_| text.trim().to_owned());
    typed.set(Some(parsed.clone()));
    parsed.ok().filter(|v| v.is_finite())
}

/// Past this a value is taken with a warning: far beyond the scales and offsets the
/// tracer is tested at (docs/NUMERICS.md).
const FAR_VALUE: f64 = 1e9;

/// Where a field leaves its notice for the status line (see [`take_field_notice`]).
fn notice_id() -> egui::Id {
    egui::Id::unique("raylab inspector field notice")
}

/// Says what became of a typed value the field did not take as typed: not a number,
/// not finite, held to the field's range, or refused inside it.
fn notice_typed(ctx: &egui::Context, typed: Result<f64, String>, kept: f64, limits: Limits) {
    let notice = match typed {
        Err(text) => Some(format!(
            "\u{201c}{text}\u{201d} is not a number: the field keeps {kept}"
        )),
        Ok(v) if !v.is_finite() => Some(format!(
            "{v} is not a finite number: the field keeps {kept}"
        )),
        Ok(v) => {
            let held = v.clamp(limits.min, limits.max);
            match limits.take(v) {
                None => Some(format!(
                    "{v} is not taken here ({}): the field keeps {kept}",
                    limits.describe()
                )),
                Some(_) if held != v => Some(format!(
                    "{v} is outside what this field takes ({}): held to {held}",
                    limits.describe()
                )),
                // Taken, but far past the scales the tracer is tested at (1e-3 to 1e5,
                // offsets to 1e6): say so rather than let the picture go blank unexplained.
                Some(taken) if taken.abs() > FAR_VALUE => Some(format!(
                    "{taken:e} is taken, but it is far beyond the sizes raylab renders \
                     reliably (up to about 1e9): the picture may show nothing of it"
                )),
                Some(_) => None,
            }
        }
    };
    if let Some(notice) = notice {
        leave_notice(ctx, notice);
    }
}

/// Leaves a notice for the status line: something the user did was not taken as done.
pub(super) fn leave_notice(ctx: &egui::Context, notice: String) {
    ctx.data_mut(|d| d.insert_temp(notice_id(), notice));
}

/// The notice a field left this frame, if any: the app shows it in the status line.
#[must_use]
pub fn take_field_notice(ctx: &egui::Context) -> Option<String> {
    ctx.data_mut(|d| d.remove_temp::<String>(notice_id()))
}

#[cfg(test)]
mod tests {
    use super::{fitted_number, number_room};

    #[test]
    fn numbers_fit_their_field_with_fewer_decimals_then_in_scientific_notation() {
        assert_eq!(fitted_number(0.25, 96.0), "0.250");
        assert_eq!(fitted_number(-1234.5678, 60.0), "-1235");
        assert_eq!(fitted_number(1e30, 60.0), "1e30");
        assert_eq!(fitted_number(-2.5e-7, 96.0), "0.000", "no negative zero");
        for value in [1e30, -1e300, 123456789.0, 0.1, -0.5] {
            for width in [34.0, 44.0, 60.0, 96.0] {
                let room = number_room(width);
                let text = fitted_number(value, width);
                assert!(text.len() <= room.max(6), "{value} at {width}: {text}");
            }
        }
    }
}
