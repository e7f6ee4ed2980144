//! What the UI asks the worker to render.

use std::sync::Arc;

use crate::scene::Scene;
use crate::trace::{MeshStore, RenderOptions};

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
    /// The built meshes the scene's mesh objects refer to (read by the caller, off the
    /// worker; empty for scenes without meshes). Shared, so a material edit keeps the
    /// same meshes and the hit cache re-shades instead of re-tracing.
    pub meshes: Arc<MeshStore>,
}

/// The longest side the editor's preview renders at; larger scenes are previewed scaled
/// down (export and the command line still render the scene's own size).
pub const MAX_PREVIEW_LONG_SIDE: u32 = 2048;

impl PreviewRequest {
    /// A request for `scene` at its own resolution and samples, everything switched on.
    #[must_use]
    pub fn for_scene(generation: u64, scene: Scene) -> Self {
        let options = RenderOptions::from_scene(&scene);
        Self {
            generation,
            scene: Arc::new(scene),
            options,
            meshes: Arc::default(),
        }
    }

    /// As [`Self::for_scene`], with the size scaled down (aspect kept) so that the long
    /// side is at most `max_long_side`.
    #[must_use]
    pub fn for_scene_capped(generation: u64, scene: Scene, max_long_side: u32) -> Self {
        let options = Self::capped_options(&scene, max_long_side);
        Self {
            generation,
            scene: Arc::new(scene),
            options,
            meshes: Arc::default(),
        }
    }

    /// The options of [`Self::for_scene_capped`], without building a request.
    #[must_use]
    pub fn capped_options(scene: &Scene, max_long_side: u32) -> RenderOptions {
        let mut options = RenderOptions::from_scene(scene);
        let (width, height) = (options.width, options.height);
        let long = width.max(height);
        if long > max_long_side {
            let scale = f64::from(max_long_side) / f64::from(long);
            let side = |s: u32| ((f64::from(s) * scale).round() as u32).max(1);
            options.width = side(width);
            options.height = side(height);
        }
        options
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn capping_keeps_the_aspect_and_leaves_small_scenes_alone() {
        let mut scene = Scene::empty();
        scene.camera.width = 8000;
        scene.camera.height = 2000;
        let request = PreviewRequest::for_scene_capped(1, scene.clone(), 2048);
        assert_eq!((request.options.width, request.options.height), (2048, 512));
        scene.camera.width = 800;
        scene.camera.height = 600;
        let request = PreviewRequest::for_scene_capped(1, scene, 2048);
        assert_eq!((request.options.width, request.options.height), (800, 600));
    }
}
