//! The UI side of the preview worker: submits the scene when it changed (at most once
//! per frame), takes the newest published frame and keeps its texture alive.

use std::time::Duration;

use egui::{ColorImage, TextureHandle, TextureOptions};

use crate::preview::{MAX_PREVIEW_LONG_SIDE, Pass, PreviewRequest, PreviewWorker};
use crate::scene::Scene;

/// What is on screen: the pass, how long it took, whether more will follow.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShownFrame {
    /// Generation of the request the frame answers.
    pub generation: u64,
    /// The pass.
    pub pass: Pass,
    /// Render time of the pass.
    pub elapsed: Duration,
    /// Rays per second in the pass.
    pub rays_per_second: f64,
    /// Nothing sharper will follow for this generation.
    pub is_final: bool,
}

/// The worker, the scene last sent to it, and the texture of the newest frame.
pub struct PreviewLink {
    worker: PreviewWorker,
    submitted: Option<Scene>,
    generation: u64,
    texture: Option<TextureHandle>,
    shown: Option<ShownFrame>,
    error: Option<String>,
}

impl PreviewLink {
    /// Starts a worker whose publishes repaint `ctx`.
    #[must_use]
    pub fn new(ctx: &egui::Context) -> Self {
        let ctx = ctx.clone();
        Self {
            worker: PreviewWorker::spawn(Box::new(move || ctx.request_repaint())),
            submitted: None,
            generation: 0,
            texture: None,
            shown: None,
            error: None,
        }
    }

    /// Sends `scene` to the worker if it differs from the last one sent.
    pub fn sync(&mut self, scene: &Scene) {
        if self.submitted.as_ref() == Some(scene) {
            return;
        }
        self.generation += 1;
        self.worker.submit(PreviewRequest::for_scene_capped(
            self.generation,
            scene.clone(),
            MAX_PREVIEW_LONG_SIDE,
        ));
        self.submitted = Some(scene.clone());
    }

    /// Takes the newest published frame (or error) into the texture.
    pub fn poll(&mut self, ctx: &egui::Context) {
        let Some(message) = self.worker.latest() else {
            return;
        };
        match message.result {
            Ok(frame) => {
                let size = [frame.image.width as usize, frame.image.height as usize];
                let image = ColorImage::from_rgba_unmultiplied(size, &frame.image.to_rgba8());
                let options = match frame.pass {
                    Pass::Coarse { .. } => TextureOptions::NEAREST,
                    Pass::Full { .. } => TextureOptions::LINEAR,
                };
                match &mut self.texture {
                    Some(texture) => texture.set(image, options),
                    None => self.texture = Some(ctx.load_texture("preview", image, options)),
                }
                let seconds = frame.elapsed.as_secs_f64().max(1e-9);
                self.shown = Some(ShownFrame {
                    generation: message.generation,
                    pass: frame.pass,
                    elapsed: frame.elapsed,
                    rays_per_second: frame.rays.total() as f64 / seconds,
                    is_final: frame.is_final,
                });
                self.error = None;
            }
            Err(error) => self.error = Some(error),
        }
    }

    /// The newest frame's texture.
    #[must_use]
    pub fn texture(&self) -> Option<&TextureHandle> {
        self.texture.as_ref()
    }

    /// About the frame on screen.
    #[must_use]
    pub fn shown(&self) -> Option<ShownFrame> {
        self.shown
    }

    /// Why the current scene cannot be rendered, if it cannot.
    #[must_use]
    pub fn error(&self) -> Option<&str> {
        self.error.as_deref()
    }

    /// Whether the frame on screen is the newest scene's and at full resolution.
    #[must_use]
    pub fn shows_full_resolution(&self) -> bool {
        self.shown
            .is_some_and(|s| s.generation == self.generation && matches!(s.pass, Pass::Full { .. }))
    }

    /// Fraction of the running pass done, when rendering.
    #[must_use]
    pub fn pass_progress(&self) -> Option<f64> {
        self.worker.pass_progress()
    }
}
