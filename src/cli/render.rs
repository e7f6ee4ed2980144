//! `raylab render`: a scene file to a PNG, with the term and isolation switches and the
//! debug views.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use clap::Args;

use super::conventions::ConventionArgs;
use super::isolation::IsolationArgs;
use crate::preview::BackgroundJob;
use crate::scene::Scene;
use crate::scene::{MAX_IMAGE_SIDE, write_atomically};
use crate::trace::{
    PRUNE_BUDGET, PrunedRender, RenderOptions, SampleSums, Term, TermSwitches, View, World,
    render_pruned, render_samples,
};

/// Arguments of `raylab render`.
#[derive(Debug, Args)]
pub struct RenderArgs {
    /// The scene file: RON, or a course `.txt` scene (told by its content, imported on the fly).
    pub scene: PathBuf,
    /// The PNG to write.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Image width (default: the scene's; height follows the aspect ratio if not given).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=i64::from(MAX_IMAGE_SIDE)))]
    pub width: Option<u32>,
    /// Image height (default: the scene's; width follows the aspect ratio if not given).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=i64::from(MAX_IMAGE_SIDE)))]
    pub height: Option<u32>,
    /// Samples per pixel (default: the scene's).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=65536))]
    pub spp: Option<u32>,
    /// Terms to switch off, comma-separated: ambient,diffuse,specular,shadows,reflection,
    /// transmission.
    #[arg(long, value_delimiter = ',')]
    pub off: Vec<Term>,
    /// Show one term alone.
    #[arg(long)]
    pub solo: Option<Term>,
    /// What to show: beauty, normal, depth, object-id or shadow-mask.
    #[arg(long, default_value = "beauty")]
    pub view: View,
    /// Lights muted or solo, objects hidden.
    #[command(flatten)]
    pub isolation: IsolationArgs,
    /// The course's conventions, over the scene's.
    #[command(flatten)]
    pub conventions: ConventionArgs,
    /// Trace every ray to max_depth. The PNG is the same byte for byte either way: by
    /// default, in scenes with glass (whose ray trees split at every surface), rays that
    /// cannot change a byte are left out, and the pixels they might have changed are
    /// traced again in full. Elsewhere the bookkeeping costs more than it saves.
    #[arg(long)]
    pub no_prune: bool,
    /// What each sample may leave out when pruning, in steps of a byte (1/255): more
    /// leaves out more rays and traces more pixels again. The PNG is the same.
    #[arg(long, default_value_t = PRUNE_BUDGET * 255.0)]
    pub prune_budget: f64,
    /// Render as a tracer with these bugs would, comma-separated, each named as `raylab
    /// diff` names its cause: `CAUSE[@LIGHT|@OBJECT]` (`half-vector`, `spot-no-cone@3`,
    /// `missing-object@red ball`), or a term factor `TERM=FACTOR` (`diffuse=0@2`,
    /// `shadows=0`). `raylab bugs SCENE -o DIR` shows each. Not with the term, view or
    /// isolation switches.
    #[arg(long, value_name = "BUGS")]
    pub bug: Option<String>,
}

impl RenderArgs {
    /// The render options these arguments ask for, given the scene's defaults.
    ///
    /// # Errors
    /// An isolation flag naming a light or object the scene does not have.
    pub fn options(&self, scene: &Scene) -> Result<RenderOptions, String> {
        let mut options = RenderOptions::from_scene(scene);
        let aspect = f64::from(scene.camera.width) / f64::from(scene.camera.height);
        let side = |x: f64| (x.round() as u32).clamp(1, MAX_IMAGE_SIDE);
        match (self.width, self.height) {
            (Some(w), Some(h)) => (options.width, options.height) = (w, h),
            (Some(w), None) => (options.width, options.height) = (w, side(f64::from(w) / aspect)),
            (None, Some(h)) => (options.width, options.height) = (side(f64::from(h) * aspect), h),
            (None, None) => {}
        }
        if let Some(spp) = self.spp {
            options.samples_per_pixel = spp;
        }
        let mut switches = TermSwitches::ALL_ON;
        for term in &self.off {
            switches.set(*term, false);
        }
        options.switches = switches.with_solo(self.solo);
        options.view = self.view;
        options.isolation = self.isolation.isolation(scene)?;
        Ok(options)
    }
}

/// Runs `raylab render`.
///
/// # Errors
/// A message naming what went wrong (file, scene problem, write failure), or how many
/// pixels had non-finite samples (the image is written all the same, those samples
/// black, so it can be looked at).
pub fn run(args: &RenderArgs) -> Result<(), String> {
    let scene = super::load_any_scene(&args.scene)?;
    let scene = args.conventions.applied(scene);
    if let Some(bugs) = &args.bug {
        return run_with_bugs(args, scene, bugs);
    }
    let scene = args.isolation.without_hidden_children(&scene)?;
    let options = args.options(&scene)?;
    let meshes = crate::cli::load_meshes(&scene, &args.scene)?;
    let world = World::isolated_with_meshes(&scene, &options.isolation, &meshes)
        .map_err(|e| format!("{}: {e}", args.scene.display()))?;
    let started = Instant::now();
    let glass = scene
        .materials
        .values()
        .any(|m| m.transmission != glam::DVec3::ZERO);
    let budget = (!args.no_prune && glass).then_some(args.prune_budget / 255.0);
    let rendered = render_with_progress_bar(world, options.clone(), budget)?;
    let elapsed = started.elapsed();
    let sums = rendered.sums;
    let image = sums.average(options.samples_per_pixel);
    let rays = sums.rays;
    let quantise = scene.render.conventions.quantise;
    write_atomically(&args.output, &image.png_bytes_as(quantise))
        .map_err(|e| format!("cannot write {}: {e}", args.output.display()))?;
    eprintln!(
        "{}: {}x{} at {} spp in {:.1} ms, {} rays ({:.2} Mrays/s; {} camera, {} shadow, {} mirror, {} transmitted)",
        args.output.display(),
        options.width,
        options.height,
        options.samples_per_pixel,
        elapsed.as_secs_f64() * 1e3,
        rays.total(),
        rays.total() as f64 / elapsed.as_secs_f64() / 1e6,
        rays.primary,
        rays.shadow,
        rays.reflection,
        rays.transmission,
    );
    if rendered.pruned_pixels > 0 {
        eprintln!(
            "pruned: rays left out in {} pixels, {} of them traced again in full",
            rendered.pruned_pixels, rendered.retraced_pixels
        );
    }
    non_finite_report(&sums)
}

/// `raylab render --bug`: the scene as a tracer with `bugs` would write it, from the
/// models `raylab diff` fits ([`crate::compare::plant`]).
fn run_with_bugs(args: &RenderArgs, scene: Scene, bugs: &str) -> Result<(), String> {
    let switched = !args.off.is_empty()
        || args.solo.is_some()
        || args.view != View::Beauty
        || !args.isolation.mute_light.is_empty()
        || !args.isolation.solo_light.is_empty()
        || !args.isolation.hide.is_empty();
    if switched {
        return Err(
            "--bug renders the whole picture a buggy tracer makes: it does not combine with \
             --off, --solo, --view or the light and object switches"
                .to_owned(),
        );
    }
    let options = args.options(&scene)?;
    let mut scene = scene;
    scene.camera.width = options.width;
    scene.camera.height = options.height;
    let planted = crate::compare::plant::parse_bugs(bugs, &scene)?;
    let meshes = crate::cli::load_meshes(&scene, &args.scene)?;
    let started = Instant::now();
    let picture = crate::compare::plant::plant(
        &scene,
        &meshes,
        &planted,
        options.samples_per_pixel,
        &crate::trace::RenderProgress::default(),
    )
    .map_err(|e| format!("{}: {e}", args.scene.display()))?;
    write_atomically(&args.output, &picture.png_bytes())
        .map_err(|e| format!("cannot write {}: {e}", args.output.display()))?;
    let names: Vec<String> = planted.iter().map(|b| b.label(&scene)).collect();
    eprintln!(
        "{}: {}x{} at {} spp with {} in {:.1} ms",
        args.output.display(),
        options.width,
        options.height,
        options.samples_per_pixel,
        names.join(", "),
        started.elapsed().as_secs_f64() * 1e3,
    );
    Ok(())
}

/// `Ok` when every sample was finite, else a message with how many pixels (and samples)
/// were not, which `raylab render` turns into a non-zero exit.
///
/// # Errors
/// At least one sample came out NaN or infinite.
pub fn non_finite_report(sums: &SampleSums) -> Result<(), String> {
    if sums.non_finite == 0 {
        return Ok(());
    }
    let first = sums.non_finite_pixels.first().map_or(String::new(), |&i| {
        format!(" (first at x {}, y {})", i % sums.width, i / sums.width)
    });
    Err(format!(
        "{} pixels had non-finite samples ({} samples in all){first}; they were written \
         without those samples",
        sums.non_finite_pixels.len(),
        sums.non_finite
    ))
}

/// Renders on a background job while a progress bar on stderr follows it; the bar
/// appears only if the render takes longer than a moment, and the wait ends the moment
/// the render does (a tiny render pays no polling delay).
///
/// Returns the sums of all `options.samples_per_pixel` samples: exactly as
/// [`crate::trace::render`] adds them, with the guard's counts, or with a pruning
/// budget as [`render_pruned`] makes them (the same bytes, not the same floats).
///
/// # Errors
/// The render panicked.
pub fn render_with_progress_bar(
    world: World,
    options: RenderOptions,
    prune_budget: Option<f64>,
) -> Result<PrunedRender, String> {
    const SHOW_AFTER: Duration = Duration::from_millis(300);
    const TICK: Duration = Duration::from_millis(50);
    let work = move |p: &_| {
        if let Some(budget) = prune_budget {
            render_pruned(&world, &options, budget, p)
        } else {
            let samples = 0..options.samples_per_pixel;
            render_samples(&world, &options, samples, p).map(|sums| PrunedRender {
                sums,
                pruned_pixels: 0,
                retraced_pixels: 0,
            })
        }
    };
    let job = BackgroundJob::spawn("render", work, || {})?;
    let started = Instant::now();
    let mut bar: Option<indicatif::ProgressBar> = None;
    let outcome = job.wait(TICK, |fraction| {
        if bar.is_none() && started.elapsed() > SHOW_AFTER {
            let b = indicatif::ProgressBar::new(1000);
            b.set_style(
                indicatif::ProgressStyle::with_template(
                    "rendering {bar:40} {percent:>3}% {elapsed} (eta {eta})",
                )
                .expect("valid template"),
            );
            bar = Some(b);
        }
        if let Some(b) = &bar {
            b.set_position((fraction * 1000.0) as u64);
        }
    });
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    outcome
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_report_counts_pixels_and_samples_and_names_the_first_pixel() {
        let mut sums = SampleSums::zero(10, 4);
        assert_eq!(non_finite_report(&sums), Ok(()));
        sums.non_finite = 3;
        sums.non_finite_pixels = vec![23, 31];
        let message = non_finite_report(&sums).unwrap_err();
        assert!(
            message.starts_with(
                "2 pixels had non-finite samples (3 samples in all) (first at x 3, y 2)"
            ),
            "{message}"
        );
    }
}
