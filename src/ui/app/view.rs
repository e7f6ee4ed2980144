//! How the editor shows the document, none of it saved in the scene file: the preview
//! and its toolbar settings, the view camera and pixel inspection, the isolation
//! switches, and which helper panels are open.

use crate::trace::Isolation;
use crate::ui::state::PreviewSettings;
use crate::ui::viewport::isolation_memory::IsolationMemory;
use crate::ui::viewport::preview_link::PreviewLink;

use super::looking::Looking;

/// The editor's way of looking at the document (editor state, never the scene).
pub struct View {
    /// Whether the background preview runs (tests may turn it off).
    pub preview_enabled: bool,
    /// The background preview, started with the first frame when enabled.
    pub preview: Option<PreviewLink>,
    /// The toolbar's switches, view and overlays.
    pub preview_settings: PreviewSettings,
    /// The view camera, the inspected and pinned pixels, the probes.
    pub looking: Looking,
    /// Lights muted or solo, objects hidden, by scene index (remembered per file).
    pub isolation: Isolation,
    /// The isolation of every file that has some, for the next time it opens.
    pub isolation_memory: IsolationMemory,
    /// Whether the keyboard-shortcut help window is open.
    pub show_help: bool,
    /// Whether the inspector's name field takes the focus in the next frame (Rename).
    pub focus_name: bool,
}

impl View {
    /// Looking at a document through `looking`; the preview runs if `preview_enabled`.
    pub(super) fn new(looking: Looking, preview_enabled: bool) -> Self {
        Self {
            preview_enabled,
            preview: None,
            preview_settings: PreviewSettings::default(),
            looking,
            isolation: Isolation::NONE,
            isolation_memory: IsolationMemory::default(),
            show_help: false,
            focus_name: false,
        }
    }
}
