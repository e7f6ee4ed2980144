//! What the viewport is handed each frame (the scene, the preview, the selection and the
//! editor's view state) and what it hands back (sizes and places found while laying out).

use super::pixel_inspector::{PixelAnchor, PixelInspection};
use super::preview_link::PreviewLink;
use crate::scene::Scene;
use crate::trace::Isolation;
use crate::ui::commands::Selection;
use crate::ui::state::{PreviewSettings, RayPathSettings, ViewCamera};

/// What the viewport shows.
pub struct ViewportInput<'a> {
    /// The scene.
    pub scene: &'a Scene,
    /// The preview, when running.
    pub preview: Option<&'a PreviewLink>,
    /// The selection.
    pub selection: &'a Selection,
    /// The toolbar's settings.
    pub settings: &'a PreviewSettings,
    /// Lights muted or solo, objects hidden.
    pub isolation: &'a Isolation,
    /// The view camera (or camera view).
    pub view: &'a ViewCamera,
    /// What the ray-path overlay draws.
    pub ray_paths: &'a RayPathSettings,
    /// The inspected pixel.
    pub inspected: Option<(u32, u32)>,
    /// The newest inspections of the inspected and pinned pixels.
    pub inspections: &'a [PixelInspection],
}

/// What the viewport found out while laying out.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ViewportOutput {
    /// The size a free view renders at in this viewport.
    pub free_size: (u32, u32),
    /// Where the inspected pixel is on screen.
    pub anchor: Option<PixelAnchor>,
}
