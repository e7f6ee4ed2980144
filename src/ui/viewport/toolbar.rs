//! The toolbar over the viewport: the six term switches, a solo choice and the view
//! picker (wrapped onto more rows only where the viewport's width needs it), then a row
//! that is always there: the pixel inspector's mode, the convergence plot, the NaN guard
//! and what is isolated. It edits editor state ([`PreviewSettings`]), not the scene:
//! nothing here is an undo step.

use egui::{Align, Color32, CornerRadius, Layout, Pos2, Rect, RichText, Shape, Stroke, UiBuilder};

use crate::trace::{Term, View};
use crate::ui::commands::Command;
use crate::ui::state::{IsolationToggle, PreviewSettings, view_label};

/// Height of one row of the toolbar; a narrow viewport wraps it onto more rows.
pub const TOOLBAR_ROW_HEIGHT: f32 = 24.0;

/// The guard's loud colour for pixels with a non-finite sample.
pub const NAN_COLOUR: Color32 = Color32::from_rgb(255, 0, 255);

/// Shows the toolbar across `width` from `top_left`, wrapping onto as many rows as the
/// width needs so every control stays reachable; pushes [`Command::SetPreviewSettings`]
/// on a change. `non_finite` is the guard count of the frame on screen, if there is one;
/// `isolated` says what is muted, solo or hidden, if anything is.
/// Returns the strip's height.
pub fn toolbar_ui(
    ui: &mut egui::Ui,
    top_left: Pos2,
    width: f32,
    settings: &PreviewSettings,
    non_finite: Option<u64>,
    isolated: Option<&str>,
    commands: &mut Vec<Command>,
) -> f32 {
    // The background goes under the controls, but its height is known only after them.
    let background = ui.painter().add(Shape::Noop);
    let margin = egui::vec2(8.0, 3.0);
    // One row high, as `horizontal_wrapped` starts: further rows grow it downward.
    let room = Rect::from_min_size(
        top_left + margin,
        egui::vec2(width - 2.0 * margin.x, TOOLBAR_ROW_HEIGHT),
    );
    let mut edited = *settings;
    // The shading controls, wrapped onto more rows only where the width needs it.
    let builder = UiBuilder::new()
        .max_rect(room)
        .layout(Layout::left_to_right(Align::Center).with_main_wrap(true));
    let first = ui
        .scope_builder(builder, |ui| {
            ui.spacing_mut().item_spacing = egui::vec2(4.0, 4.0);
            terms_ui(ui, &mut edited);
            ui.separator();
            view_ui(ui, &mut edited);
        })
        .response
        .rect;
    // The tools, and what is isolated, on a row of their own that is always there and
    // never wraps (a long note is cut short): muting or soloing never moves the picture.
    let row = Rect::from_min_size(
        Pos2::new(room.min.x, first.max.y + 4.0),
        egui::vec2(room.width(), TOOLBAR_ROW_HEIGHT),
    );
    let builder = UiBuilder::new()
        .max_rect(row)
        .layout(Layout::left_to_right(Align::Center));
    let used = ui
        .scope_builder(builder, |ui| {
            ui.spacing_mut().item_spacing = egui::vec2(4.0, 4.0);
            ui.set_min_height(TOOLBAR_ROW_HEIGHT);
            ui.toggle_value(&mut edited.inspect, "Inspect")
                .on_hover_text(
                    "Click a pixel to see every number behind it (or hold Alt and click)",
                );
            ui.toggle_value(&mut edited.show_convergence, "Convergence")
                .on_hover_text("Plot how much each preview pass still changes the picture");
            ui.separator();
            guard_ui(ui, &mut edited, non_finite);
            if let Some(note) = isolated {
                ui.separator();
                isolation_marker_ui(ui, note, commands);
            }
        })
        .response
        .rect;
    let rect = Rect::from_min_max(
        top_left,
        Pos2::new(top_left.x + width, used.max.y + margin.y),
    );
    ui.painter().set(
        background,
        Shape::rect_filled(rect, CornerRadius::ZERO, Color32::from_gray(20)),
    );
    ui.painter().hline(
        rect.x_range(),
        rect.max.y - 0.5,
        Stroke::new(1.0, Color32::from_gray(40)),
    );
    if edited != *settings {
        commands.push(Command::SetPreviewSettings(edited));
    }
    rect.height()
}

/// Not the full picture: a button back to everything, then what is isolated (the button
/// first, so a long note never pushes it out of view).
fn isolation_marker_ui(ui: &mut egui::Ui, note: &str, commands: &mut Vec<Command>) {
    if ui
        .small_button("show all")
        .on_hover_text("Unmute, unsolo and unhide everything")
        .clicked()
    {
        commands.push(Command::Isolate(IsolationToggle::ShowAll));
    }
    ui.add(
        egui::Label::new(RichText::new(format!("◐ {note}")).color(crate::ui::style::ACCENT))
            .truncate(),
    )
    .on_hover_text(format!("Not the full picture: {note}"));
}

/// The NaN guard toggle and, when on, the count of the frame on screen.
fn guard_ui(ui: &mut egui::Ui, settings: &mut PreviewSettings, non_finite: Option<u64>) {
    ui.toggle_value(&mut settings.nan_guard, "NaN guard")
        .on_hover_text("Paint pixels whose samples came out NaN or infinite in magenta");
    if settings.nan_guard
        && let Some(count) = non_finite
    {
        let colour = if count == 0 {
            Color32::from_gray(170)
        } else {
            NAN_COLOUR
        };
        ui.label(RichText::new(non_finite_text(count)).small().color(colour));
    }
}

/// "0 non-finite samples", "1 non-finite sample".
#[must_use]
pub fn non_finite_text(count: u64) -> String {
    let s = if count == 1 { "" } else { "s" };
    format!("{count} non-finite sample{s}")
}

/// The six switches and the solo choice.
fn terms_ui(ui: &mut egui::Ui, settings: &mut PreviewSettings) {
    for term in Term::ALL {
        let mut on = settings.switches.is_on(term);
        let dimmed = settings.switches.solo.is_some_and(|s| s != term) && term != Term::Shadows;
        let text = if dimmed {
            RichText::new(term.name()).weak()
        } else {
            RichText::new(term.name())
        };
        if ui
            .toggle_value(&mut on, text)
            .on_hover_text(term_tooltip(term))
            .changed()
        {
            settings.switches.set(term, on);
        }
    }
    let solo_text = settings.switches.solo.map_or("none", Term::name);
    egui::ComboBox::from_id_salt("solo")
        .selected_text(format!("solo: {solo_text}"))
        .width(118.0)
        .show_ui(ui, |ui| {
            ui.selectable_value(&mut settings.switches.solo, None, "none")
                .accessible_name("solo none");
            for term in Term::ALL {
                ui.selectable_value(&mut settings.switches.solo, Some(term), term.name())
                    .on_hover_text(solo_tooltip(term))
                    .accessible_name(format!("solo {term}"));
            }
        })
        .response
        .on_hover_text("Show one term alone (reflected colours keep the other switches)")
        .accessible_name("solo");
}

/// The view picker.
fn view_ui(ui: &mut egui::Ui, settings: &mut PreviewSettings) {
    egui::ComboBox::from_id_salt("view")
        .selected_text(view_label(settings.view))
        .width(100.0)
        .show_ui(ui, |ui| {
            for view in View::ALL {
                ui.selectable_value(&mut settings.view, view, view_label(view))
                    .on_hover_text(view_tooltip(view))
                    .accessible_name(format!("view {}", view_label(view)));
            }
        })
        .response
        .on_hover_text(view_tooltip(settings.view))
        .accessible_name("view");
}

/// What the picture shows with `term` switched off, in one line.
#[must_use]
pub fn term_tooltip(term: Term) -> &'static str {
    match term {
        Term::Ambient => "Off: no ka x ambient light; unlit sides and shadows go black",
        Term::Diffuse => "Off: no kd L max(0, n.l); only highlights, ambient and mirrors remain",
        Term::Specular => "Off: no Phong highlights (ks L max(0, r.v)^s); matte surfaces only",
        Term::Shadows => "Off: no shadow rays; every light reaches every point it faces",
        Term::Reflection => "Off: no mirror rays; mirrors show only their own colour",
        Term::Transmission => "Off: no refracted rays; glass shows only its own colour",
    }
}

/// What soloing `term` shows, in one line.
#[must_use]
pub fn solo_tooltip(term: Term) -> &'static str {
    match term {
        Term::Ambient => "Only ka x ambient light (and the background)",
        Term::Diffuse => "Only the diffuse term of every light, shadows included",
        Term::Specular => "Only the highlights of every light, shadows included",
        Term::Shadows => {
            "The shadow mask: the share of facing lights that reach each point (white: all); \
             the same picture as the shadow-mask view, kept here beside the other terms"
        }
        Term::Reflection => "Only what mirrors add: km x the reflected colour",
        Term::Transmission => "Only what glass lets through: kt x the refracted colour",
    }
}

/// What `view` shows, in one line.
#[must_use]
pub fn view_tooltip(view: View) -> &'static str {
    match view {
        View::Beauty => "The lit picture, with the term switches above",
        View::Normal => "The shading normal as colour: (n + 1) / 2, so +x red, +y green, +z blue",
        View::Depth => {
            "Distance from the eye: white near, black far; mid-grey at the camera's distance to its target"
        }
        View::ObjectId => "A flat colour per object: where one object ends and another begins",
        View::ShadowMask => {
            "The share of facing lights that reach each point: white all, black none"
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_control_says_what_the_picture_will_show_and_the_duplicate_is_explained() {
        let terms: Vec<&str> = Term::ALL.into_iter().map(term_tooltip).collect();
        let solos: Vec<&str> = Term::ALL.into_iter().map(solo_tooltip).collect();
        let views: Vec<&str> = View::ALL.into_iter().map(view_tooltip).collect();
        for lines in [&terms, &solos, &views] {
            for (i, a) in lines.iter().enumerate() {
                assert!(
                    !a.contains("on or off"),
                    "{a}: says what it shows, not what it is"
                );
                assert!(lines[i + 1..].iter().all(|b| a != b));
            }
        }
        assert!(solo_tooltip(Term::Shadows).contains("same picture as the shadow-mask view"));
    }
}
