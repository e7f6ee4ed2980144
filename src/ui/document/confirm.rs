//! The "discard unsaved changes?" question, and the actions that wait for its answer.

use std::path::PathBuf;

/// An action that would drop unsaved changes, waiting for the user's answer.
#[derive(Clone, Debug, PartialEq)]
pub enum DiscardAction {
    /// File > New.
    New,
    /// File > Open… (the dialog comes after the answer).
    OpenDialog,
    /// Open this file.
    Open(PathBuf),
    /// File > Import Legacy… (the dialog comes after the answer).
    ImportDialog,
    /// Import this legacy file.
    Import(PathBuf),
    /// Close the window.
    Quit,
}

/// Asks whether to drop unsaved changes: `Some(true)` discard, `Some(false)` cancel.
pub fn discard_modal(ctx: &egui::Context, action: &DiscardAction) -> Option<bool> {
    let what = match action {
        DiscardAction::New => "start a new scene",
        DiscardAction::OpenDialog | DiscardAction::Open(_) => "open another scene",
        DiscardAction::ImportDialog | DiscardAction::Import(_) => "import a scene",
        DiscardAction::Quit => "quit",
    };
    let mut answer = None;
    let modal = egui::Modal::new(egui::Id::unique("discard changes")).show(ctx, |ui| {
        ui.set_width(340.0);
        ui.heading("Unsaved changes");
        ui.add_space(4.0);
        ui.label(format!(
            "The scene has unsaved changes. Discard them and {what}?"
        ));
        ui.add_space(8.0);
        ui.horizontal(|ui| {
            if ui.button("Discard changes").clicked() {
                answer = Some(true);
            }
            if ui.button("Cancel").clicked() {
                answer = Some(false);
            }
        });
    });
    if modal.should_close() && answer.is_none() {
        answer = Some(false);
    }
    answer
}
