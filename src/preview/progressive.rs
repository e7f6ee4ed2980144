//! One generation's plan, rendered pass by pass as the preview worker and the benchmark
//! run it: the coarse passes, the one-sample pass, then anti-aliasing samples added to one
//! set of sums sample by sample in index order, exactly as [`crate::trace::render`] sums
//! them, so the final frame is bit-identical to a direct render. Each anti-aliasing pass
//! comes with its estimated remaining error, from the mean of its first half of samples
//! (the previous pass's picture; the first pass is rendered in two halves for this).
//!
//! With a [`HitCache`] the rays of the one-sample pass are kept (traced once more after
//! the pass is shown), and a later plan whose world the cache can serve (an edit that
//! moved no object and not the camera) skips the coarse passes: its one-sample pass
//! re-shades the cached hits, tracing only the rays the cache lacks, and is the first
//! frame published. A light moved, or the `ior` of glass changed, keeps the coarsest
//! pass before it, since casting the light's shadow rays, or the rays below the glass,
//! again takes about a traced frame's time.

use std::sync::Arc;
use std::time::Instant;

use super::convergence::{ConvergenceCurve, estimated_rmse};
use super::frame::Frame;
use super::plan::{Pass, plan_passes};
use crate::trace::{HitCache, MAX_CACHE_BYTES, Reuse, cache_fits, render_one_sample_cached};
use crate::trace::{Image, RayCounts, RenderOptions, RenderProgress, SampleSums, World};
use crate::trace::{render_samples, render_samples_into};

/// Renders the passes of `target`'s plan in order, handing each finished one to
/// `publish`. Before each pass `start_pass` gives the progress to render it with, or
/// `None` to stop; a pass cancelled through its progress also ends the plan.
pub fn render_plan(
    world: &World,
    target: &RenderOptions,
    start_pass: &mut dyn FnMut() -> Option<Arc<RenderProgress>>,
    publish: &mut dyn FnMut(Frame),
) {
    run_plan(world, target, None, start_pass, publish);
}

/// As [`render_plan`], with the rays of the last one-sample pass in `cache`: a plan the
/// cache can serve starts at the one-sample pass, re-shaded, and leaves its rays there for
/// the next plan. Any other plan publishes its one-sample pass traced as usual and then
/// traces it again keeping the rays, before the anti-aliasing passes: keeping them makes
/// a pass slower (memory for every hit), and an edit that re-traces must not show its
/// first full frame later for it. `None` where it would not fit ([`cache_fits`], for the
/// rays the traced pass counted: a tree of rays under glass can be far more than a
/// chain), or where a re-shade grew it past [`MAX_CACHE_BYTES`]. A cancelled pass leaves
/// `cache` as it was.
pub fn render_plan_cached(
    world: &World,
    target: &RenderOptions,
    cache: &mut Option<HitCache>,
    start_pass: &mut dyn FnMut() -> Option<Arc<RenderProgress>>,
    publish: &mut dyn FnMut(Frame),
) {
    run_plan(world, target, Some(cache), start_pass, publish);
}

fn run_plan(
    world: &World,
    target: &RenderOptions,
    mut cache: Option<&mut Option<HitCache>>,
    start_pass: &mut dyn FnMut() -> Option<Arc<RenderProgress>>,
    publish: &mut dyn FnMut(Frame),
) {
    let cacheable = cache_fits(world, target.width, target.height, None);
    let reuse = cache
        .as_deref()
        .and_then(Option::as_ref)
        .filter(|_| cacheable)
        .map(|c| c.reuse(world, target.width, target.height));
    let reshade = reuse.as_ref().is_some_and(Reuse::is_reshade);
    // A re-shade that casts a moved light's shadow rays again (or the rays below glass
    // given another index: 0.42 s against 0.37 s for tracing glass.ron afresh) takes
    // about as long as a traced frame, so it keeps the coarsest pass: without it, a
    // light dragged with edits coming faster than that frame showed nothing until the
    // drag stopped.
    let keep_coarsest = reuse.is_some_and(|r| r.traces_again());
    let plan = plan_passes(target);
    let coarsest = plan.first().copied();
    let passes: Vec<Pass> = plan
        .into_iter()
        .filter(|&pass| {
            !(reshade && matches!(pass, Pass::Coarse { .. }))
                || (keep_coarsest && Some(pass) == coarsest)
        })
        .collect();
    let mut accumulated = None;
    let mut curve = ConvergenceCurve::default();
    for (index, &pass) in passes.iter().enumerate() {
        let Some(progress) = start_pass() else {
            return;
        };
        let started = Instant::now();
        let one_sample = matches!(pass, Pass::Full { target: 1, .. });
        let rendered = match cache.as_deref_mut() {
            Some(cache) if one_sample && reshade => reshade_pass(world, target, cache, &progress),
            _ => render_pass(world, target, pass, &mut accumulated, &progress),
        };
        let Some(rendered) = rendered else {
            return;
        };
        let elapsed = started.elapsed();
        let rays = rendered.rays;
        curve.add(pass, elapsed, rendered.estimated_rmse);
        publish(Frame {
            image: rendered.image,
            pass,
            elapsed,
            rays: rendered.rays,
            is_final: index + 1 == passes.len(),
            non_finite_samples: rendered.non_finite_samples,
            non_finite_pixels: rendered.non_finite_pixels,
            estimated_rmse: rendered.estimated_rmse,
            convergence: curve.clone(),
        });
        if let Some(cache) = cache.as_deref_mut()
            && one_sample
            && !reshade
        {
            // The rays of the picture just shown, for the next edit (stale ones go), if
            // as many as it traced fit.
            *cache = None;
            let closest_hit_rays = rays.primary + rays.reflection + rays.transmission;
            if cacheable && cache_fits(world, target.width, target.height, Some(closest_hit_rays)) {
                let Some(progress) = start_pass() else {
                    return;
                };
                let kept = render_one_sample_cached(world, target, None, &progress);
                let Some(kept) = kept else {
                    return;
                };
                *cache = Some(kept.cache);
            }
        }
    }
}

/// The one-sample pass re-shaded from `cache`, which then holds its rays. `None` if
/// cancelled (`cache` as it was).
fn reshade_pass(
    world: &World,
    target: &RenderOptions,
    cache: &mut Option<HitCache>,
    progress: &RenderProgress,
) -> Option<Rendered> {
    let cached = render_one_sample_cached(world, target, cache.as_ref(), progress)?;
    // An edit can grow the trees under glass (a deeper `max_depth`) past what fits.
    *cache = Some(cached.cache).filter(|cache| cache.bytes() <= MAX_CACHE_BYTES);
    let sums = cached.sums;
    Some(Rendered::new(&sums, sums.average(1), sums.rays, None))
}

/// Anti-aliasing samples summed so far at full resolution, and the picture they made.
struct Accumulated {
    sums: SampleSums,
    samples: u32,
    image: Image,
}

/// What one pass made.
struct Rendered {
    image: Image,
    /// Rays of this pass alone.
    rays: RayCounts,
    non_finite_samples: u64,
    non_finite_pixels: Vec<u32>,
    estimated_rmse: Option<f64>,
}

impl Rendered {
    fn new(sums: &SampleSums, image: Image, rays: RayCounts, estimate: Option<f64>) -> Self {
        Self {
            image,
            rays,
            non_finite_samples: sums.non_finite,
            non_finite_pixels: sums.non_finite_pixels.clone(),
            estimated_rmse: estimate,
        }
    }
}

/// Renders one pass; anti-aliasing passes continue the sums in `accumulated`. `None` if
/// cancelled.
fn render_pass(
    world: &World,
    target: &RenderOptions,
    pass: Pass,
    accumulated: &mut Option<Accumulated>,
    progress: &RenderProgress,
) -> Option<Rendered> {
    match pass {
        Pass::Coarse { .. } | Pass::Full { target: 1, .. } => {
            let (width, height) = pass.size(target.width, target.height);
            let options = RenderOptions {
                width,
                height,
                samples_per_pixel: 1,
                ..target.clone()
            };
            let sums = render_samples(world, &options, 0..1, progress)?;
            Some(Rendered::new(&sums, sums.average(1), sums.rays, None))
        }
        Pass::Full {
            samples,
            target: count,
        } => {
            let options = RenderOptions {
                samples_per_pixel: count,
                ..target.clone()
            };
            let mut rays = RayCounts::default();
            if accumulated.is_none() {
                // The first half on its own, so that this pass has one to compare with.
                let mut sums = SampleSums::zero(options.width, options.height);
                let half = (samples / 2).max(1);
                rays = render_samples_into(world, &options, 0..half, &mut sums, progress)?;
                let image = sums.average(half);
                *accumulated = Some(Accumulated {
                    sums,
                    samples: half,
                    image,
                });
            }
            let state = accumulated.as_mut()?;
            let more = render_samples_into(
                world,
                &options,
                state.samples..samples,
                &mut state.sums,
                progress,
            )?;
            rays.add(&more);
            let image = state.sums.average(samples);
            let estimate = estimated_rmse(&state.image, state.samples, &image, samples);
            state.samples = samples;
            state.image = image.clone();
            Some(Rendered::new(&state.sums, image, rays, Some(estimate)))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::{TermSwitches, View, render};

    #[test]
    fn every_sampled_pass_is_the_direct_render_at_its_count_with_an_estimate() {
        let mut scene = crate::scene::examples::default_scene();
        scene.camera.width = 48;
        scene.camera.height = 32;
        let world = World::new(&scene).unwrap();
        let target = RenderOptions {
            width: 48,
            height: 32,
            samples_per_pixel: 16,
            switches: TermSwitches::ALL_ON,
            view: View::Beauty,
            isolation: crate::trace::Isolation::NONE,
        };
        let mut frames = Vec::new();
        render_plan(
            &world,
            &target,
            &mut || Some(Arc::new(RenderProgress::default())),
            &mut |frame| frames.push(frame),
        );
        let passes: Vec<Pass> = frames.iter().map(|f| f.pass).collect();
        assert_eq!(passes, plan_passes(&target));
        for frame in &frames {
            let Pass::Full { samples, .. } = frame.pass else {
                unreachable!("48 x 32 has no coarse pass")
            };
            // The 4-sample pass of a 16-sample target is the 4-sample image itself.
            let options = RenderOptions {
                samples_per_pixel: samples,
                ..target.clone()
            };
            let (direct, _) = render(&world, &options, &RenderProgress::default()).unwrap();
            assert_eq!(frame.image.pixels, direct.pixels, "{:?}", frame.pass);
            assert_eq!(frame.estimated_rmse.is_some(), samples > 1);
            assert!(frame.estimated_rmse.is_none_or(|e| e > 0.0 && e < 0.5));
        }
        let last = frames.last().unwrap();
        assert!(last.is_final);
        assert_eq!(last.convergence.points().len(), 3, "4, 8 and 16 samples");
    }

    #[test]
    fn a_pass_stopped_by_its_progress_ends_the_plan() {
        let scene = crate::scene::examples::default_scene();
        let world = World::new(&scene).unwrap();
        let target = RenderOptions {
            width: 32,
            height: 32,
            ..RenderOptions::from_scene(&scene)
        };
        let mut published = 0;
        let mut started = 0;
        render_plan(
            &world,
            &target,
            &mut || {
                started += 1;
                let progress = RenderProgress::default();
                if started == 2 {
                    progress.cancel();
                }
                Some(Arc::new(progress))
            },
            &mut |_| published += 1,
        );
        assert_eq!((started, published), (2, 1));
    }

    #[test]
    fn a_traced_plan_shows_its_one_sample_pass_before_keeping_its_rays() {
        let mut scene = crate::scene::examples::default_scene();
        (scene.camera.width, scene.camera.height) = (160, 120);
        let world = World::new(&scene).unwrap();
        let target = RenderOptions::from_scene(&scene);
        let passes = plan_passes(&target);
        let one_sample = passes
            .iter()
            .position(|p| matches!(p, Pass::Full { target: 1, .. }))
            .unwrap();
        assert!(one_sample > 0, "coarse passes first: {passes:?}");
        // Stopped right after the one-sample pass is shown: it was published, and no
        // rays were kept (keeping them comes after, and it was stopped).
        let mut cache = None;
        let (mut started, mut shown) = (0, Vec::new());
        render_plan_cached(
            &world,
            &target,
            &mut cache,
            &mut || {
                started += 1;
                (started <= one_sample + 1).then(|| Arc::new(RenderProgress::default()))
            },
            &mut |frame| shown.push(frame.pass),
        );
        assert_eq!(shown, passes[..=one_sample]);
        assert!(cache.is_none());
        // Left to run, the plan keeps the rays, and the next plan of the same world
        // re-shades: no coarse pass.
        let mut shown = Vec::new();
        let mut go = || Some(Arc::new(RenderProgress::default()));
        render_plan_cached(&world, &target, &mut cache, &mut go, &mut |f| {
            shown.push(f.pass);
        });
        assert_eq!(shown, passes);
        assert!(cache.is_some());
        let mut again = Vec::new();
        render_plan_cached(&world, &target, &mut cache, &mut go, &mut |f| {
            again.push(f.pass);
        });
        assert_eq!(again, passes[one_sample..]);
        // A light moved re-shades too, casting its shadow rays again, after the
        // coarsest pass (that re-shade takes about a traced frame's time).
        let mut moved = scene.clone();
        if let crate::scene::Light::Point { position, .. } = &mut moved.lights[1] {
            position.x += 0.5;
        }
        let moved = World::new(&moved).unwrap();
        let mut lit = Vec::new();
        render_plan_cached(&moved, &target, &mut cache, &mut go, &mut |f| {
            lit.push(f.pass);
        });
        // (At 160 x 120 the plan has one coarse pass; tests/preview_worker_reshade.rs
        // tells the re-shade from a re-trace at a size with two.)
        assert_eq!(lit[0], passes[0]);
        assert_eq!(lit[1..], passes[one_sample..]);
    }
}
