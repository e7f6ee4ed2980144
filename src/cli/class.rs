//! `raylab class`: compare every student's renders with raylab's pictures of the
//! scenes, and write the class report (see [`crate::class`]).

use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use clap::Args;

use crate::class::{ClassOptions, run_class, write_report};

/// Arguments of `raylab class`.
#[derive(Debug, Args)]
pub struct ClassArgs {
    /// The folder of scenes: RON files and course `.txt` scenes.
    pub scenes: PathBuf,
    /// The folder of submissions: one folder per student holding their renders (PNG or
    /// PPM), named as the scenes (case and suffixes such as `_render` do not matter).
    pub submissions: PathBuf,
    /// The report folder to write (index.html, class.csv, class.json, the images, and
    /// the cache a rerun reuses). It must not lie inside SCENES or SUBMISSIONS.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Samples per pixel of raylab's pictures (default: each scene's; 1 for students'
    /// tracers without anti-aliasing).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=4096))]
    pub spp: Option<u32>,
}

/// Runs `raylab class`: a progress bar with the time left on stderr; the first Ctrl+C
/// lets the pairs being compared finish, keeps every finished pair and writes the report
/// of what is done; a second one quits at once.
///
/// # Errors
/// A folder cannot be read or written, or the report folder overlaps an input.
pub fn run(args: &ClassArgs) -> Result<(), String> {
    let stop = Arc::new(AtomicBool::new(false));
    let handler_stop = Arc::clone(&stop);
    // Setting the handler fails only when one is set already (a second run in one
    // process): the run then simply cannot be stopped early.
    let _ = ctrlc::set_handler(move || {
        if handler_stop.swap(true, Ordering::SeqCst) {
            std::process::exit(130);
        }
        eprintln!("\nstopping: finishing the pairs under way (Ctrl+C again to quit now)");
    });
    let bar = indicatif::ProgressBar::new(0);
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "comparing {bar:40} {pos}/{len} pairs {elapsed} (eta {eta})",
        )
        .expect("valid template"),
    );
    let options = ClassOptions {
        samples_per_pixel: args.spp,
    };
    let progress = |done: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    };
    let run = run_class(
        &args.scenes,
        &args.submissions,
        &args.output,
        &options,
        &stop,
        &progress,
    );
    bar.finish_and_clear();
    let run = run?;
    write_report(&run, &args.output)?;
    let errors = run
        .rows
        .iter()
        .filter(|r| matches!(r.outcome, crate::class::Outcome::Error(_)))
        .count();
    eprintln!(
        "{}: {} students x {} scenes; {} pairs compared, {} reused from the cache, {errors} errors{}",
        args.output.join(crate::class::PAGE).display(),
        run.roster.students.len(),
        run.roster.scenes.len(),
        run.computed,
        run.reused,
        if run.cancelled {
            "; stopped early (run again to finish)"
        } else {
            ""
        }
    );
    Ok(())
}
