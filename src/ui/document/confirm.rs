//! The "unsaved changes: save, discard or cancel?" question, and the actions that wait
//! for its answer.

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

/// The answer to "the scene has unsaved changes".
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DiscardAnswer {
    /// Save the scene first (asking for a file if it has none), then go on.
    Save,
    /// Drop the changes and go on.
    Discard,
    /// Do nothing.
    Cancel,
}

/// Asks what to do with unsaved changes before `action`; the answer once given.
pub fn discard_modal(ctx: &egui::Context, action: &DiscardAction) -> Option<DiscardAnswer> {
    let what = match action {
        DiscardAction::New => "starting a new scene",
        DiscardAction::OpenDialog | DiscardAction::Open(_) => "opening another scene",
        DiscardAction::ImportDialog | DiscardAction::Import(_) => "importing a scene",
        DiscardAction::Quit => "quitting",
    };
    let mut answer = None;
    let modal = egui::Modal::new(egui::Id::unique("discard changes")).show(ctx, |ui| {
        ui.set_width(360.0);
        ui.heading("Unsaved changes");
        ui.add_space(4.0);
        ui.label(format!(
            "The scene has unsaved changes. Save them before {what}?"
        ));
        ui.add_space(8.0);
        ui.horizontal(|ui| {
            if ui.button("Save").clicked() {
                answer = Some(DiscardAnswer::Save);
            }
            if ui.button("Discard").clicked() {
                answer = Some(DiscardAnswer::Discard);
            }
            if ui.button("Cancel").clicked() {
                answer = Some(DiscardAnswer::Cancel);
            }
        });
    });
    if modal.should_close() && answer.is_none() {
        answer = Some(DiscardAnswer::Cancel);
    }
    answer
}
