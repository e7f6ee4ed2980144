//! Edit-to-picture latency through the real worker: how long from a submit to the first
//! coarse frame and to the first full-resolution frame, and how long an edit made midway
//! through the last anti-aliasing pass waits for its first frame. For the benchmark
//! report; timings belong in release builds.

use std::time::{Duration, Instant};

use super::plan::{Pass, plan_passes};
use super::request::PreviewRequest;
use super::worker::PreviewWorker;
use crate::scene::Scene;
use crate::trace::RenderOptions;

/// Latencies of one edit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PreviewLatency {
    /// Submit to the first published frame (the coarsest pass).
    pub first_frame: Duration,
    /// The pass that first frame was.
    pub first_pass: Pass,
    /// Submit to the first full-resolution frame (one sample per pixel).
    pub full_resolution: Duration,
}

/// Submits `scene` (at its own size, one request per run) to a fresh worker `runs` times,
/// as edits, and returns the median latencies. `None` if the scene cannot be rendered or
/// a frame does not come within `timeout`.
#[must_use]
pub fn measure_latency(scene: &Scene, runs: u32, timeout: Duration) -> Option<PreviewLatency> {
    let mut worker = PreviewWorker::spawn(Box::new(|| {}));
    let mut samples = Vec::new();
    for generation in 1..=u64::from(runs.max(1)) {
        let submitted = Instant::now();
        worker.submit(edit(scene, generation));
        let mut first = None;
        let full = loop {
            let message = worker.recv_timeout(timeout)?;
            let frame = message.result.ok()?;
            let at = submitted.elapsed();
            first.get_or_insert((at, frame.pass));
            if matches!(frame.pass, Pass::Full { .. }) {
                break at;
            }
        };
        let (first_frame, first_pass) = first?;
        samples.push(PreviewLatency {
            first_frame,
            first_pass,
            full_resolution: full,
        });
        // Let the anti-aliasing passes of this run go: the next submit cancels them.
    }
    Some(PreviewLatency {
        first_frame: median(samples.iter().map(|l| l.first_frame).collect()),
        first_pass: samples[0].first_pass,
        full_resolution: median(samples.iter().map(|l| l.full_resolution).collect()),
    })
}

/// For `scene` at its own size and samples: the median over `runs` of the time from an
/// edit submitted once the plan's last pass is half done to the first frame of that
/// edit. `None` if the plan has a single pass, the scene cannot be rendered, or nothing
/// comes within `timeout`.
#[must_use]
pub fn measure_restart_latency(scene: &Scene, runs: u32, timeout: Duration) -> Option<Duration> {
    let plan = plan_passes(&RenderOptions::from_scene(scene));
    let before_last = *plan.get(plan.len().checked_sub(2)?)?;
    let mut worker = PreviewWorker::spawn(Box::new(|| {}));
    let mut generation = 0;
    let mut latencies = Vec::new();
    // A run whose last pass ended before it was seen half done is tried again.
    for _attempt in 0..runs.max(1) * 4 {
        if latencies.len() >= runs.max(1) as usize {
            break;
        }
        generation += 1;
        worker.submit(edit(scene, generation));
        loop {
            let frame = worker.recv_timeout(timeout)?.result.ok()?;
            if frame.pass == before_last {
                break;
            }
        }
        if !wait_until_half_done(&mut worker, timeout)? {
            continue;
        }
        generation += 1;
        let submitted = Instant::now();
        worker.submit(edit(scene, generation));
        let message = worker.recv_timeout(timeout)?;
        let took = submitted.elapsed();
        // Nothing of the interrupted generation may come after the submit.
        if message.generation != generation || message.result.is_err() {
            return None;
        }
        latencies.push(took);
    }
    (!latencies.is_empty()).then(|| median(latencies))
}

/// Polls the running pass until it is half done (`Some(true)`), or until it ends first
/// and publishes (`Some(false)`); `None` after `timeout`.
fn wait_until_half_done(worker: &mut PreviewWorker, timeout: Duration) -> Option<bool> {
    let started = Instant::now();
    loop {
        if worker.pass_progress().is_some_and(|p| p >= 0.5) {
            return Some(true);
        }
        if worker.latest().is_some() {
            return Some(false);
        }
        if started.elapsed() > timeout {
            return None;
        }
        std::thread::sleep(Duration::from_micros(100));
    }
}

/// `scene` with a real edit for `generation` (the worker renders whatever it is sent).
fn edit(scene: &Scene, generation: u64) -> PreviewRequest {
    let mut edited = scene.clone();
    edited.camera.fov_deg += (generation % 1000) as f64 * 1e-3;
    PreviewRequest::for_scene(generation, edited)
}

/// The middle of `values` (the upper one of an even count).
///
/// # Panics
/// When `values` is empty.
#[must_use]
pub fn median(mut values: Vec<Duration>) -> Duration {
    values.sort();
    values[values.len() / 2]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn small_scene(samples: u32) -> Scene {
        let mut scene = crate::scene::examples::default_scene();
        scene.camera.width = 160;
        scene.camera.height = 120;
        scene.render.samples_per_pixel = samples;
        scene
    }

    #[test]
    fn the_first_frame_is_the_plans_first_pass_and_a_bad_scene_measures_nothing() {
        let scene = small_scene(1);
        let latency = measure_latency(&scene, 2, Duration::from_secs(60)).unwrap();
        let plan = plan_passes(&RenderOptions::from_scene(&scene));
        assert_eq!(latency.first_pass, plan[0]);
        assert_eq!(latency.first_pass, Pass::Coarse { divider: 2 });
        let mut broken = scene;
        broken.objects[0].material = "missing".to_owned();
        assert_eq!(measure_latency(&broken, 1, Duration::from_secs(60)), None);
    }

    #[test]
    fn a_restart_is_measured_only_where_the_plan_has_a_last_pass_to_interrupt() {
        let mut scene = small_scene(1);
        scene.camera.width = 32;
        scene.camera.height = 32;
        // 32 x 32 at 1 sample is a single pass: nothing to interrupt.
        assert_eq!(
            measure_restart_latency(&scene, 1, Duration::from_secs(60)),
            None
        );
        scene.render.samples_per_pixel = 256;
        assert!(measure_restart_latency(&scene, 1, Duration::from_secs(60)).is_some());
    }
}
