//! The frame a render makes: what to render (size, samples, switches, view, isolation),
//! the progress shared with whoever watches, and the per-pixel sums of samples.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use glam::{DVec3, Vec3};
use rayon::prelude::*;

use super::image::Image;
use crate::scene::Scene;
use crate::trace::ray_counts::RayCounts;
use crate::trace::terms::{Isolation, TermSwitches, View};

/// What to render.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RenderOptions {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Anti-aliasing samples per pixel (see [`super::sampling`]).
    pub samples_per_pixel: u32,
    /// Term switches.
    pub switches: TermSwitches,
    /// Beauty or a debug view.
    pub view: View,
    /// Lights muted or solo, objects hidden: the world must be compiled with them
    /// ([`World::isolated`]).
    pub isolation: Isolation,
}

impl RenderOptions {
    /// The scene's own size and samples, everything on.
    #[must_use]
    pub fn from_scene(scene: &Scene) -> Self {
        Self {
            width: scene.camera.width,
            height: scene.camera.height,
            samples_per_pixel: scene.render.samples_per_pixel,
            switches: TermSwitches::ALL_ON,
            view: View::Beauty,
            isolation: Isolation::NONE,
        }
    }
}

/// Shared between a render and whoever watches it: batches of samples done, and a cancel
/// flag. A batch is one sample for every pixel of a tile (see [`render_samples_into`]).
#[derive(Debug, Default)]
pub struct RenderProgress {
    /// Batches finished so far.
    pub batches_done: AtomicUsize,
    /// Batches in the whole render (set when it starts).
    pub batches_total: AtomicUsize,
    /// Set to stop the render before its next batch.
    pub cancel: AtomicBool,
}

impl RenderProgress {
    /// Asks the render to stop.
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    /// Whether a stop was asked for.
    #[must_use]
    pub fn is_cancelled(&self) -> bool {
        self.cancel.load(Ordering::Relaxed)
    }

    /// Fraction done, 0 to 1.
    #[must_use]
    pub fn fraction(&self) -> f64 {
        let total = self.batches_total.load(Ordering::Relaxed);
        if total == 0 {
            0.0
        } else {
            self.batches_done.load(Ordering::Relaxed) as f64 / total as f64
        }
    }
}

/// Summed samples of a render pass, not yet divided by the sample count.
#[derive(Clone, Debug)]
pub struct SampleSums {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Sum of the samples of each pixel.
    pub sums: Vec<DVec3>,
    /// Rays cast.
    pub rays: RayCounts,
    /// Samples that came out non-finite and were replaced by black (should stay 0).
    pub non_finite: u64,
    /// Row-major indices (`y * width + x`) of the pixels with at least one non-finite
    /// sample, ascending, each once (should stay empty).
    pub non_finite_pixels: Vec<u32>,
}

/// `pixels` zero sums, cleared in parallel: one thread took a millisecond on an 800x600
/// frame, in which an edit waited for the pass it cancelled.
pub(crate) fn cleared(pixels: usize) -> Vec<DVec3> {
    rayon::iter::repeat_n(DVec3::ZERO, pixels).collect()
}

/// As [`cleared`], in parts with a look at the cancel flag between them (`None` once
/// cancelled): a pass that clears its frame first is often cancelled right then, by the
/// edit that follows the frame before it, and that edit would wait for the whole clear
/// (about half a millisecond at 800x600).
pub(crate) fn cleared_unless_cancelled(
    pixels: usize,
    progress: &RenderProgress,
) -> Option<Vec<DVec3>> {
    // Parts of at least 64 Ki pixels: a small frame clears at once, as each part
    // costs a round trip through the thread pool.
    let parts = (pixels / 65_536).clamp(1, 8);
    let mut sums = Vec::with_capacity(pixels);
    for part in 0..parts {
        if progress.is_cancelled() {
            return None;
        }
        let end = pixels * (part + 1) / parts;
        sums.par_extend(rayon::iter::repeat_n(DVec3::ZERO, end - sums.len()));
    }
    Some(sums)
}

impl SampleSums {
    /// Sums of no samples yet: black, nothing counted.
    #[must_use]
    pub fn zero(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            sums: cleared(width as usize * height as usize),
            rays: RayCounts::default(),
            non_finite: 0,
            non_finite_pixels: Vec::new(),
        }
    }

    /// Sums of no samples yet, to be made by the first render into them: no pixel held
    /// while that render runs, and none read before its tiles are placed.
    #[must_use]
    pub(crate) fn unsummed(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            sums: Vec::new(),
            rays: RayCounts::default(),
            non_finite: 0,
            non_finite_pixels: Vec::new(),
        }
    }

    /// The image these sums make when divided by `count` samples.
    #[must_use]
    pub fn average(&self, count: u32) -> Image {
        let scale = 1.0 / f64::from(count.max(1));
        Image {
            width: self.width,
            height: self.height,
            pixels: self
                .sums
                .par_iter()
                .map(|s| (*s * scale).as_vec3())
                .collect::<Vec<Vec3>>(),
        }
    }
}
