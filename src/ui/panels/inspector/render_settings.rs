//! The render settings inspector: mirror depth, background, samples, and the course
//! framework's conventions (how mirrors blend, when colour is clamped, how bytes round).

use egui::Ui;

use super::fields::{colour_row_ui, whole_number_row_ui};
use super::layout::{grid_ui, heading_ui};
use super::limits::{MAX_DEPTH, MAX_SAMPLES_PER_PIXEL};
use crate::scene::*;
use crate::ui::commands::{Command, SceneEdit};

pub(super) fn render_ui(ui: &mut Ui, render: &RenderSettings, commands: &mut Vec<Command>) {
    heading_ui(ui, "RENDER", "Render settings");
    let mut edited = render.clone();
    grid_ui(ui, "render", |ui| {
        whole_number_row_ui(ui, "max depth", &mut edited.max_depth, 0.1, 0..=MAX_DEPTH);
        colour_row_ui(ui, "background", &mut edited.background);
        whole_number_row_ui(
            ui,
            "samples",
            &mut edited.samples_per_pixel,
            0.2,
            1..=MAX_SAMPLES_PER_PIXEL,
        );
    });
    ui.weak(
        "max depth: mirror bounces. samples: anti-aliasing samples per pixel; \
         the preview refines up to this and Export PNG uses it.",
    );
    conventions_ui(ui, &mut edited.conventions);
    if edited != *render {
        commands.push(Command::Edit(SceneEdit::SetRender(edited)));
    }
}

/// The three conventions, each a pair of choices with one line saying what it does, and
/// the two presets: the contract's model and the course skeleton's habits.
fn conventions_ui(ui: &mut Ui, conventions: &mut Conventions) {
    ui.add_space(6.0);
    ui.label("Conventions");
    grid_ui(ui, "conventions", |ui| {
        choice_row_ui(
            ui,
            "mirror",
            &mut conventions.mirror,
            [
                (MirrorConvention::Add, "Add"),
                (MirrorConvention::Blend, "Blend"),
            ],
        );
        choice_row_ui(
            ui,
            "clamp",
            &mut conventions.clamp,
            [
                (ClampConvention::Pixel, "Pixel"),
                (ClampConvention::EachRay, "Each ray"),
            ],
        );
        choice_row_ui(
            ui,
            "quantise",
            &mut conventions.quantise,
            [(Quantise::Round, "Round"), (Quantise::Truncate, "Truncate")],
        );
    });
    ui.weak(match conventions.mirror {
        MirrorConvention::Add => "mirror Add: local + km * reflected (the contract).",
        MirrorConvention::Blend => "mirror Blend: (1 - km) * local + km * reflected.",
    });
    ui.weak(match conventions.clamp {
        ClampConvention::Pixel => "clamp Pixel: only the final pixel is clamped to [0, 1].",
        ClampConvention::EachRay => {
            "clamp Each ray: every ray's colour is clamped, as clip() does."
        }
    });
    ui.weak(match conventions.quantise {
        Quantise::Round => "quantise Round: a byte is round(255 c).",
        Quantise::Truncate => "quantise Truncate: a byte is floor(255 c), as int(255 c) does.",
    });
    ui.horizontal(|ui| {
        if ui
            .add_enabled(!conventions.is_default(), egui::Button::new("Contract"))
            .on_hover_text("Add, Pixel, Round: the lighting model of the scene format")
            .clicked()
        {
            *conventions = Conventions::default();
        }
        if ui
            .add_enabled(
                *conventions != Conventions::COURSE,
                egui::Button::new("Course"),
            )
            .on_hover_text("Add, Each ray, Truncate: what the course's skeletons do")
            .clicked()
        {
            *conventions = Conventions::COURSE;
        }
    });
}

/// A labelled row of two exclusive choices.
fn choice_row_ui<T: PartialEq + Copy>(
    ui: &mut Ui,
    label: &str,
    value: &mut T,
    choices: [(T, &str); 2],
) {
    ui.label(label);
    ui.horizontal(|ui| {
        for (choice, name) in choices {
            ui.selectable_value(value, choice, name);
        }
    });
    ui.end_row();
}
