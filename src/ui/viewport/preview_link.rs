//! The UI side of the preview worker: submits the scene when it or the toolbar's render
//! settings changed (at most once per frame), takes the newest published frame of the
//! newest submitted generation (it carries its convergence curve, computed by the
//! worker) and keeps the texture alive, with the NaN guard's overlay when it is on.

use std::time::Duration;

use egui::{ColorImage, TextureHandle, TextureOptions};

use crate::preview::{
    ConvergenceCurve, Frame, MAX_PREVIEW_LONG_SIDE, Pass, PreviewRequest, PreviewWorker, Published,
};
use crate::scene::Scene;
use crate::trace::{Isolation, RenderOptions};
use crate::ui::state::PreviewSettings;
use crate::ui::viewport::toolbar::NAN_COLOUR;

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
    /// Nothing sharper will follow for this generation, and no newer edit is waiting.
    pub is_final: bool,
}

/// The worker, the scene last sent to it, and the texture of the newest frame.
pub struct PreviewLink {
    worker: PreviewWorker,
    submitted: Option<Scene>,
    /// The options of the last request (size, samples, switches, view).
    submitted_options: Option<RenderOptions>,
    /// The scene folder last sent (where mesh files are read).
    submitted_folder: Option<std::path::PathBuf>,
    generation: u64,
    texture: Option<TextureHandle>,
    /// Whether the texture carries the NaN guard's overlay.
    texture_guarded: bool,
    /// The newest frame taken from the worker.
    frame: Option<Frame>,
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
            submitted_options: None,
            submitted_folder: None,
            generation: 0,
            texture: None,
            texture_guarded: false,
            frame: None,
            shown: None,
            error: None,
        }
    }

    /// Sends `scene` with the toolbar's switches and view and the isolation switches to
    /// the worker if any of them differs from what was last sent.
    /// `folder` is the scene file's, where the worker finds mesh files.
    pub fn sync(
        &mut self,
        scene: &Scene,
        folder: Option<&std::path::Path>,
        settings: &PreviewSettings,
        isolation: &Isolation,
    ) {
        let options = RenderOptions {
            switches: settings.switches,
            view: settings.view,
            isolation: isolation.clone(),
            ..PreviewRequest::capped_options(scene, MAX_PREVIEW_LONG_SIDE)
        };
        if self.submitted.as_ref() == Some(scene)
            && self.submitted_options.as_ref() == Some(&options)
            && self.submitted_folder.as_deref() == folder
        {
            return;
        }
        self.generation += 1;
        self.submitted = Some(scene.clone());
        self.submitted_options = Some(options.clone());
        self.submitted_folder = folder.map(std::path::Path::to_path_buf);
        self.worker.submit(PreviewRequest {
            generation: self.generation,
            scene: std::sync::Arc::new(scene.clone()),
            options,
            meshes: std::sync::Arc::default(),
            scene_folder: self.submitted_folder.clone(),
        });
    }

    /// Takes the newest published frame (or error) of the newest submitted generation
    /// into the texture, painted with the NaN guard's overlay if `nan_guard`.
    pub fn poll(&mut self, ctx: &egui::Context, nan_guard: bool) {
        let Some(message) = self.worker.latest().filter(|m| self.is_newest(m)) else {
            if nan_guard != self.texture_guarded
                && let Some(frame) = self.frame.take()
            {
                self.upload(ctx, &frame, nan_guard);
                self.frame = Some(frame);
            }
            return;
        };
        match message.result {
            Ok(frame) => {
                self.upload(ctx, &frame, nan_guard);
                let seconds = frame.elapsed.as_secs_f64().max(1e-9);
                self.shown = Some(ShownFrame {
                    generation: message.generation,
                    pass: frame.pass,
                    elapsed: frame.elapsed,
                    rays_per_second: frame.rays.total() as f64 / seconds,
                    is_final: frame.is_final,
                });
                self.frame = Some(frame);
                self.error = None;
            }
            Err(error) => self.error = Some(error),
        }
    }

    /// Whether `message` answers the last request sent (the worker already drops older
    /// ones at a submit; this keeps the link honest on its own).
    fn is_newest(&self, message: &Published) -> bool {
        message.generation == self.generation
    }

    /// Puts `frame` into the texture.
    fn upload(&mut self, ctx: &egui::Context, frame: &Frame, nan_guard: bool) {
        let size = [frame.image.width as usize, frame.image.height as usize];
        let image = ColorImage::from_rgba_unmultiplied(size, &frame_rgba(frame, nan_guard));
        let options = match frame.pass {
            Pass::Coarse { .. } => TextureOptions::NEAREST,
            Pass::Full { .. } => TextureOptions::LINEAR,
        };
        match &mut self.texture {
            Some(texture) => texture.set(image, options),
            None => self.texture = Some(ctx.load_texture("preview", image, options)),
        }
        self.texture_guarded = nan_guard;
    }

    /// The newest frame taken from the worker (its exact pixels, before 8-bit encoding).
    #[must_use]
    pub fn frame(&self) -> Option<&Frame> {
        self.frame.as_ref()
    }

    /// The options of the last request sent to the worker.
    #[must_use]
    pub fn submitted_options(&self) -> Option<RenderOptions> {
        self.submitted_options.clone()
    }

    /// The generation of the last request sent.
    #[must_use]
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// The convergence curve of the frame on screen, with its generation.
    #[must_use]
    pub fn convergence(&self) -> Option<(u64, &ConvergenceCurve)> {
        let shown = self.shown?;
        Some((shown.generation, &self.frame.as_ref()?.convergence))
    }

    /// The newest frame's texture.
    #[must_use]
    pub fn texture(&self) -> Option<&TextureHandle> {
        self.texture.as_ref()
    }

    /// About the frame on screen; it is final only while no newer edit is waiting for
    /// its first frame.
    #[must_use]
    pub fn shown(&self) -> Option<ShownFrame> {
        self.shown.map(|s| ShownFrame {
            is_final: s.is_final && s.generation == self.generation,
            ..s
        })
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

    /// The mesh file being read before the next pass, and the fraction read.
    #[must_use]
    pub fn loading(&self) -> Option<(String, f64)> {
        self.worker.loading()
    }

    /// What is known of each mesh file the preview has read.
    #[must_use]
    pub fn mesh_facts(&self) -> std::collections::BTreeMap<String, crate::preview::MeshFacts> {
        self.worker.mesh_facts()
    }

    /// Stops reading the mesh file being read.
    pub fn cancel_loading(&self) {
        self.worker.cancel_loading();
    }
}

/// The frame as 8-bit RGBA; with `nan_guard`, the pixels with a non-finite sample are
/// painted in the guard's loud colour.
#[must_use]
pub fn frame_rgba(frame: &Frame, nan_guard: bool) -> Vec<u8> {
    let mut rgba = frame.image.to_rgba8();
    if nan_guard {
        let [r, g, b, a] = NAN_COLOUR.to_array();
        for &index in &frame.non_finite_pixels {
            let at = index as usize * 4;
            if let Some(pixel) = rgba.get_mut(at..at + 4) {
                pixel.copy_from_slice(&[r, g, b, a]);
            }
        }
    }
    rgba
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::{Image, RayCounts};

    #[test]
    fn the_guard_paints_exactly_the_listed_pixels() {
        let mut image = Image::new(3, 2);
        image.pixels.fill(glam::Vec3::splat(0.5));
        let frame = Frame {
            image,
            pass: Pass::Full {
                samples: 1,
                target: 1,
            },
            elapsed: Duration::ZERO,
            rays: RayCounts::default(),
            is_final: true,
            non_finite_samples: 2,
            non_finite_pixels: vec![1, 5],
            estimated_rmse: None,
            convergence: ConvergenceCurve::default(),
        };
        let plain = frame_rgba(&frame, false);
        assert!(plain.chunks(4).all(|p| p == [128, 128, 128, 255]));
        let guarded = frame_rgba(&frame, true);
        for (i, pixel) in guarded.chunks(4).enumerate() {
            let expected = if i == 1 || i == 5 {
                [255, 0, 255, 255]
            } else {
                [128, 128, 128, 255]
            };
            assert_eq!(pixel, expected, "pixel {i}");
        }
    }
}
