//! Speed against error: RMSE and PSNR against a converged reference (the preview's own
//! clamped, nearest-neighbour `rmse_nearest`), against render time,
//! for the progressive preview passes, uniform stratified sampling and adaptive sampling.

use std::time::Instant;

use serde::Serialize;

use crate::preview::rmse_nearest;
use crate::scene::Scene;
use crate::trace::{
    AdaptiveOptions, RenderOptions, RenderProgress, World, render, render_adaptive,
};

/// One point of an error-against-time curve.
#[derive(Clone, Debug, Serialize)]
pub struct CurvePoint {
    /// Render time (for the progressive passes: cumulative up to this pass).
    pub time_ms: f64,
    /// Root mean square error of displayed values (clamped to [0, 1]) over all channels.
    pub rmse: f64,
    /// Peak signal-to-noise ratio, dB: 20 log10(1 / rmse).
    pub psnr: f64,
    /// Average samples per pixel (for a progressive pass: per pixel of that pass).
    pub spp: f64,
    /// `uniform`, `adaptive` or `progressive`.
    pub strategy: String,
}

/// What to measure.
#[derive(Clone, Debug)]
pub struct ConvergencePlan {
    /// Image size of every render.
    pub width: u32,
    /// Image size of every render.
    pub height: u32,
    /// Samples per pixel of the reference.
    pub reference_spp: u32,
    /// Sample counts of the uniform curve.
    pub uniform_spp: Vec<u32>,
    /// Average sample counts of the adaptive curve.
    pub adaptive_spp: Vec<u32>,
}

fn point(strategy: &str, spp: f64, seconds: f64, error: f64) -> CurvePoint {
    CurvePoint {
        time_ms: seconds * 1e3,
        rmse: error,
        psnr: 20.0 * (1.0 / error.max(1e-12)).log10(),
        spp,
        strategy: strategy.to_owned(),
    }
}

/// Measures the curves for `scene`.
///
/// # Errors
/// The scene's validation error.
pub fn convergence_curves(
    scene: &Scene,
    plan: &ConvergencePlan,
) -> Result<Vec<CurvePoint>, String> {
    let world = World::new(scene).map_err(|e| e.to_string())?;
    let base = RenderOptions {
        width: plan.width,
        height: plan.height,
        ..RenderOptions::from_scene(scene)
    };
    let progress = RenderProgress::default();
    let timed = |options: &RenderOptions| {
        let started = Instant::now();
        let (image, _) = render(&world, options, &progress).expect("not cancelled");
        (image, started.elapsed().as_secs_f64())
    };
    let (reference, _) = timed(&RenderOptions {
        samples_per_pixel: plan.reference_spp,
        ..base.clone()
    });
    let mut curve = Vec::new();

    // progressive preview passes: divider 8, 4, 2, 1 at one sample, time cumulative
    let mut elapsed = 0.0;
    for divider in [8, 4, 2, 1] {
        let options = RenderOptions {
            width: (plan.width / divider).max(1),
            height: (plan.height / divider).max(1),
            samples_per_pixel: 1,
            ..base.clone()
        };
        let (image, seconds) = timed(&options);
        elapsed += seconds;
        let error = rmse_nearest(&image, &reference);
        curve.push(point(
            "progressive",
            1.0 / f64::from(divider * divider),
            elapsed,
            error,
        ));
    }
    for &spp in &plan.uniform_spp {
        let (image, seconds) = timed(&RenderOptions {
            samples_per_pixel: spp,
            ..base.clone()
        });
        curve.push(point(
            "uniform",
            f64::from(spp),
            seconds,
            rmse_nearest(&image, &reference),
        ));
    }
    for &spp in &plan.adaptive_spp {
        let adaptive = AdaptiveOptions {
            pilot_spp: if spp >= 8 { 4 } else { 2 },
            mean_spp: f64::from(spp),
            max_spp: spp * 16,
        };
        let started = Instant::now();
        let result = render_adaptive(&world, &base, &adaptive, &progress).expect("not cancelled");
        let seconds = started.elapsed().as_secs_f64();
        let mean = result.samples as f64 / (f64::from(plan.width) * f64::from(plan.height));
        curve.push(point(
            "adaptive",
            mean,
            seconds,
            rmse_nearest(&result.image, &reference),
        ));
    }
    Ok(curve)
}
