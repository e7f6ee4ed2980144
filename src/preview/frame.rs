//! What the worker publishes: finished passes, or why the scene cannot be rendered.

use std::time::Duration;

use super::convergence::ConvergenceCurve;
use super::plan::Pass;
use crate::trace::{Image, RayCounts};

/// One finished pass of a preview render.
#[derive(Clone, Debug)]
pub struct Frame {
    /// The picture (linear RGB); its size is the pass's size, not always the target's.
    pub image: Image,
    /// Which pass of the plan this is.
    pub pass: Pass,
    /// Wall time spent rendering this pass.
    pub elapsed: Duration,
    /// Rays cast in this pass.
    pub rays: RayCounts,
    /// Whether this is the last pass of the plan (nothing sharper will follow).
    pub is_final: bool,
    /// Samples behind this image that came out non-finite and were replaced by black: the
    /// renderer's own guard count (should stay 0).
    pub non_finite_samples: u64,
    /// Row-major indices into `image` of the pixels with such a sample, ascending.
    pub non_finite_pixels: Vec<u32>,
    /// For an anti-aliasing pass, the estimated RMSE of `image` against the converged
    /// picture ([`super::estimated_rmse`]); `None` for passes of one sample per pixel.
    pub estimated_rmse: Option<f64>,
    /// The generation's convergence curve up to and including this pass.
    pub convergence: ConvergenceCurve,
}

/// A message from the worker, tagged with the generation of the request it answers.
#[derive(Clone, Debug)]
pub struct Published {
    /// The generation of the request this answers.
    pub generation: u64,
    /// A finished pass, or the message of a scene that cannot be rendered.
    pub result: Result<Frame, String>,
}
