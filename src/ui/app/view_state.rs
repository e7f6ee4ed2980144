//! What the editor shows of its view state: the view camera, the inspected and pinned
//! pixels and their inspections, the ray-path settings, the views remembered per file.

use super::EditorApp;
use crate::ui::viewport::pixel_inspector::PixelInspection;
use crate::ui::viewport::view_memory::ViewMemory;

impl EditorApp {
    /// The pixel inspector's contents: the newest inspection of the inspected pixel
    /// (traced off the UI thread; `None` until the first is done, or when closed).
    #[must_use]
    pub fn inspection(&self) -> Option<&PixelInspection> {
        self.view.looking.inspection()
    }

    /// The newest inspections of the inspected pixel, its row or column, and the pins.
    #[must_use]
    pub fn inspections(&self) -> &[PixelInspection] {
        self.view.looking.inspections()
    }

    /// The camera the viewport shows, with the size of the image it renders.
    #[must_use]
    pub fn shown_camera(&self) -> crate::scene::Camera {
        self.view
            .looking
            .camera
            .shown(&self.document.scene.camera, self.view.looking.free_size)
    }

    /// Whether picks and inspections are still being traced.
    #[must_use]
    pub fn is_probing(&self) -> bool {
        self.view.looking.is_busy()
    }

    /// Sets the views remembered per file (from eframe's storage) and brings back the
    /// one of the open file.
    #[must_use]
    pub fn with_view_memory(mut self, memory: ViewMemory) -> Self {
        self.view.looking.memory = memory;
        if let Some(view) = self
            .document
            .path
            .as_deref()
            .and_then(|p| self.view.looking.memory.get(p))
        {
            self.view.looking.camera = view.clone();
        }
        self
    }

    /// The views remembered per file, with the open file's current view.
    #[must_use]
    pub fn view_memory(&self) -> ViewMemory {
        let mut memory = self.view.looking.memory.clone();
        if let Some(path) = &self.document.path {
            memory.remember(path, &self.view.looking.camera);
        }
        memory
    }
}
