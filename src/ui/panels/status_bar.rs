//! The status bar: scene file, counts, the preview's pass and render time (or the mesh
//! file it is reading, with a cancel button), errors (autosave's first: while it fails,
//! unsaved work is not protected).

use egui::{Color32, RichText, Ui};

use crate::preview::Pass;
use crate::ui::commands::Command;
use crate::ui::viewport::preview_link::ShownFrame;

/// What the status bar shows.
pub struct StatusInfo<'a> {
    /// The scene's file, or what stands for it ("default scene", "untitled").
    pub file: &'a str,
    /// Whether there are unsaved changes.
    pub dirty: bool,
    /// Number of objects.
    pub objects: usize,
    /// Number of lights.
    pub lights: usize,
    /// The frame on screen.
    pub frame: Option<ShownFrame>,
    /// Fraction of the pass being rendered.
    pub progress: Option<f64>,
    /// The mesh file the preview is reading (as the scene writes it) and the fraction
    /// read.
    pub loading: Option<(String, f64)>,
    /// The preview's error, if any.
    pub error: Option<&'a str>,
    /// Why the last autosave failed, while it keeps failing (unsaved work is at risk).
    pub autosave_error: Option<&'a str>,
    /// The latest message (e.g. "Saved"), if any.
    pub message: Option<&'a StatusMessage>,
}

/// A message for the status bar: something done ("Saved …"), or a notice about a value
/// the user gave that was not taken as given (held to a range, refused, out of reach).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StatusMessage {
    /// The words.
    pub text: String,
    /// Whether it is a notice (amber) rather than news of something done (green).
    pub notice: bool,
}

impl StatusMessage {
    /// News of something done.
    #[must_use]
    pub fn done(text: impl Into<String>) -> Self {
        Self {
            text: text.into(),
            notice: false,
        }
    }

    /// A notice about a value not taken as given.
    #[must_use]
    pub fn notice(text: impl Into<String>) -> Self {
        Self {
            text: text.into(),
            notice: true,
        }
    }
}

/// Shows the status bar.
pub fn status_bar_ui(ui: &mut Ui, info: &StatusInfo<'_>, commands: &mut Vec<Command>) {
    ui.horizontal(|ui| {
        let marker = if info.dirty { " •" } else { "" };
        ui.label(RichText::new(format!("{}{marker}", info.file)).strong());
        ui.separator();
        ui.label(format!("{} objects, {} lights", info.objects, info.lights));
        ui.separator();
        match info.frame {
            Some(frame) => {
                let pass = match frame.pass {
                    Pass::Coarse { divider } => format!("coarse 1/{divider}"),
                    Pass::Full { target: 1, .. } => "full, 1 sample".to_owned(),
                    Pass::Full { samples, target } => format!("full, {samples}/{target} samples"),
                };
                let state = if frame.is_final { "final" } else { "refining" };
                ui.label(format!(
                    "{pass} · {:.0} ms · {:.1} Mrays/s · {state}",
                    frame.elapsed.as_secs_f64() * 1000.0,
                    frame.rays_per_second / 1e6
                ));
            }
            None => {
                ui.weak("no preview");
            }
        }
        if let Some((file, fraction)) = &info.loading {
            let name = crate::scene::mesh_file::mesh_file_name(file);
            if *fraction < 1.0 {
                ui.label(format!("reading {name}"))
                    .on_hover_text(format!("The preview is reading the mesh file {file}"));
                ui.add(
                    egui::ProgressBar::new(*fraction as f32)
                        .desired_width(80.0)
                        .desired_height(10.0)
                        .show_percentage(),
                );
                if ui
                    .small_button("Cancel")
                    .on_hover_text("Stop reading the file; the object stays in the scene, undrawn")
                    .clicked()
                {
                    commands.push(Command::CancelMeshLoading);
                }
            } else {
                // Read: its hierarchy is being built (under a second for a million
                // triangles), which cannot be stopped half way.
                ui.label(format!("building {name}"))
                    .on_hover_text(format!("The preview is building the hierarchy of {file}"));
                ui.spinner();
            }
        } else if let Some(progress) = info.progress {
            ui.add(
                egui::ProgressBar::new(progress as f32)
                    .desired_width(80.0)
                    .desired_height(10.0),
            );
        }
        // The message takes what room is left, cut short with its whole text on hover:
        // a long one (an import's summary) never runs over the counts.
        ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
            let red = Color32::from_rgb(255, 120, 110);
            // One tooltip: the label's own tooltip for elided text is off, as this one
            // says the whole text (and, for some, why it matters).
            let shown = |ui: &mut Ui, text: &str, colour: Color32, hover: &str| {
                ui.add(
                    egui::Label::new(RichText::new(text).color(colour))
                        .truncate()
                        .show_tooltip_when_elided(false),
                )
                .on_hover_text(hover)
            };
            if let Some(error) = info.autosave_error {
                let hover = format!(
                    "{error}\nUnsaved changes are not protected against a crash until autosave works"
                );
                shown(ui, error, red, &hover);
            } else if let Some(error) = info.error {
                shown(ui, error, red, error);
            } else if let Some(message) = info.message {
                let colour = if message.notice {
                    crate::ui::style::ACCENT
                } else {
                    Color32::from_rgb(140, 200, 140)
                };
                shown(ui, &message.text, colour, &message.text);
            }
        });
    });
}
