//! Speed against error: RMSE and PSNR against a converged reference (the preview's own
//! clamped, nearest-neighbour `rmse_nearest`), against render time, for the progressive
//! preview's passes (its own plan, run by the preview's own code), uniform stratified
//! sampling and adaptive sampling; and how well the preview's error estimate tracks the
//! true error.

use std::sync::Arc;
use std::time::Instant;

use serde::Serialize;

use crate::preview::{Pass, render_plan, rmse_nearest};
use crate::scene::Scene;
use crate::trace::{
    AdaptiveOptions, Image, RenderOptions, RenderProgress, World, render, render_adaptive,
    render_samples,
};

/// One point of an error-against-time curve.
#[derive(Clone, Debug, Serialize)]
pub struct CurvePoint {
    /// Render time (for the progressive passes: cumulative up to this pass).
    pub time_ms: f64,
    /// Root mean square error of displayed values (clamped to [0, 1]) over all channels.
    pub rmse: f64,
    /// The preview's own estimate of `rmse`, made without the reference (progressive
    /// anti-aliasing passes only).
    pub estimated_rmse: Option<f64>,
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
    /// Sample counts of the uniform curve; the largest is also the progressive target.
    pub uniform_spp: Vec<u32>,
    /// Average sample counts of the adaptive curve.
    pub adaptive_spp: Vec<u32>,
}

fn point(strategy: &str, spp: f64, seconds: f64, error: f64) -> CurvePoint {
    CurvePoint {
        time_ms: seconds * 1e3,
        rmse: error,
        estimated_rmse: None,
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
    let reference = reference_image(&world, &base, plan.reference_spp);
    let target = RenderOptions {
        samples_per_pixel: plan.uniform_spp.iter().copied().max().unwrap_or(1),
        ..base.clone()
    };
    let mut curve = progressive_curve(&world, &target, &reference);
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

/// The reference: samples `spp..2 spp` of every pixel's sequence, so it shares no sample
/// with the images measured against it (they use samples `0..n`).
fn reference_image(world: &World, base: &RenderOptions, spp: u32) -> Image {
    let options = RenderOptions {
        samples_per_pixel: 2 * spp,
        ..base.clone()
    };
    render_samples(world, &options, spp..2 * spp, &RenderProgress::default())
        .expect("not cancelled")
        .average(spp)
}

/// The preview's plan for `target`, pass by pass through the preview's own code: time
/// cumulative since the edit, the true error and the preview's estimate of it.
fn progressive_curve(world: &World, target: &RenderOptions, reference: &Image) -> Vec<CurvePoint> {
    let mut curve = Vec::new();
    render_plan(
        world,
        target,
        &mut || Some(Arc::new(RenderProgress::default())),
        &mut |frame| {
            let spp = match frame.pass {
                Pass::Coarse { divider } => 1.0 / f64::from(divider * divider),
                Pass::Full { samples, .. } => f64::from(samples),
            };
            let seconds = frame.convergence.render_time().as_secs_f64();
            let error = rmse_nearest(&frame.image, reference);
            curve.push(CurvePoint {
                estimated_rmse: frame.estimated_rmse,
                ..point("progressive", spp, seconds, error)
            });
        },
    );
    curve
}

/// How the curves compare: the claims docs/BENCHMARKS.md makes, as numbers.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct CurveChecks {
    /// The largest ratio of a progressive pass's RMSE to uniform sampling's at the same
    /// samples per pixel (at most 1.15 is the target).
    pub progressive_over_uniform: f64,
    /// The smallest and largest ratio of the preview's estimate to the true RMSE, over
    /// the progressive passes of 4 samples or more (within [0.5, 2] is the target).
    pub estimate_over_true: [f64; 2],
}

/// The checks over a measured curve; ratios are NaN where there is nothing to compare.
#[must_use]
pub fn curve_checks(curve: &[CurvePoint]) -> CurveChecks {
    let of = |name: &'static str| curve.iter().filter(move |p| p.strategy == name);
    let progressive_over_uniform = of("progressive")
        .filter_map(|p| {
            let uniform = of("uniform").find(|u| u.spp == p.spp)?;
            Some(p.rmse / uniform.rmse.max(1e-12))
        })
        .fold(f64::NAN, f64::max);
    let ratios: Vec<f64> = of("progressive")
        .filter(|p| p.spp >= 4.0)
        .filter_map(|p| Some(p.estimated_rmse? / p.rmse.max(1e-12)))
        .collect();
    CurveChecks {
        progressive_over_uniform,
        estimate_over_true: [
            ratios.iter().copied().fold(f64::NAN, f64::min),
            ratios.iter().copied().fold(f64::NAN, f64::max),
        ],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(strategy: &str, spp: f64, rmse: f64, estimate: Option<f64>) -> CurvePoint {
        CurvePoint {
            estimated_rmse: estimate,
            ..point(strategy, spp, 1.0, rmse)
        }
    }

    #[test]
    fn checks_pair_passes_with_uniform_at_equal_spp_and_estimates_from_4_samples_on() {
        let curve = [
            at("progressive", 0.25, 0.5, None), // coarse: no uniform partner
            at("progressive", 2.0, 0.1, Some(1.0)), // below 4 spp: not an estimate checked
            at("progressive", 4.0, 0.06, Some(0.09)),
            at("progressive", 8.0, 0.04, Some(0.03)),
            at("uniform", 2.0, 0.1, None),
            at("uniform", 4.0, 0.05, None),
            at("uniform", 8.0, 0.04, None),
            at("adaptive", 4.0, 0.001, None),
        ];
        let checks = curve_checks(&curve);
        assert!((checks.progressive_over_uniform - 1.2).abs() < 1e-12);
        assert!((checks.estimate_over_true[0] - 0.75).abs() < 1e-12);
        assert!((checks.estimate_over_true[1] - 1.5).abs() < 1e-12);
        let nothing = curve_checks(&curve[..1]);
        assert!(nothing.progressive_over_uniform.is_nan());
        assert!(nothing.estimate_over_true.iter().all(|r| r.is_nan()));
    }

    #[test]
    fn the_preview_passes_match_uniform_sampling_and_the_estimate_tracks_the_true_error() {
        let scene = crate::scene::examples::default_scene();
        let plan = ConvergencePlan {
            width: 80,
            height: 60,
            reference_spp: 256,
            uniform_spp: vec![1, 2, 4, 8, 16],
            adaptive_spp: vec![],
        };
        let curve = convergence_curves(&scene, &plan).unwrap();
        let passes: Vec<f64> = curve
            .iter()
            .filter(|p| p.strategy == "progressive" && p.spp > 1.0)
            .map(|p| p.spp)
            .collect();
        assert_eq!(
            passes,
            [4.0, 8.0, 16.0],
            "the anti-aliasing passes are on the curve"
        );
        let checks = curve_checks(&curve);
        assert!(
            checks.progressive_over_uniform <= 1.15,
            "{:?}",
            checks.progressive_over_uniform
        );
        let [low, high] = checks.estimate_over_true;
        assert!(
            (0.5..=2.0).contains(&low) && (0.5..=2.0).contains(&high),
            "{low} {high}"
        );
    }

    #[test]
    fn a_sphere_lights_soft_shadow_converges_in_the_preview_as_in_uniform_sampling() {
        let (_, text) = crate::scene::examples::EXAMPLE_SCENES
            .iter()
            .find(|(name, _)| *name == "soft_spot.ron")
            .expect("the soft spot example");
        let scene = crate::scene::parse_scene(text).unwrap();
        let plan = ConvergencePlan {
            width: 80,
            height: 60,
            reference_spp: 256,
            uniform_spp: vec![1, 4, 16],
            adaptive_spp: vec![],
        };
        let curve = convergence_curves(&scene, &plan).unwrap();
        let uniform = |spp: f64| {
            curve
                .iter()
                .find(|p| p.strategy == "uniform" && p.spp == spp)
                .map(|p| p.rmse)
                .unwrap()
        };
        // The penumbra's noise falls as 1/sqrt(spp), a quarter at 16 times the samples
        // (at most half allows for the edges' share), and the preview's passes fall with
        // uniform sampling's: the curve measures a sphere light as it does the rest.
        assert!(uniform(16.0) < 0.5 * uniform(1.0), "{curve:?}");
        let checks = curve_checks(&curve);
        assert!(
            checks.progressive_over_uniform <= 1.15,
            "{:?}",
            checks.progressive_over_uniform
        );
    }
}
