//! What the UI asks the worker to render.

use std::sync::Arc;

use crate::scene::Scene;
use crate::trace::RenderOptions;

/// An immutable snapshot to render: the scene, the full-resolution target and its
/// generation. Generations increase with every submit; the worker drops older ones.
#[derive(Clone, Debug)]
pub struct PreviewRequest {
    /// Increases with every edit; frames carry the generation they were rendered for.
    pub generation: u64,
    /// The scene as it was when submitted.
    pub scene: Arc<Scene>,
    /// Full-resolution size, anti-aliasing target, term switches and view.
    pub options: RenderOptions,
}

impl PreviewRequest {
    /// A request for `scene` at its own resolution and samples, everything switched on.
    #[must_use]
    pub fn for_scene(generation: u64, scene: Scene) -> Self {
        let options = RenderOptions::from_scene(&scene);
        Self {
            generation,
            scene: Arc::new(scene),
            options,
        }
    }
}
