//! Edit-to-picture latency through the real worker: how long from a submit to the first
//! coarse frame, and to the first full-resolution frame. For the benchmark report and the
//! `preview_latency` example; timings belong in release builds.

use std::time::{Duration, Instant};

use super::plan::Pass;
use super::request::PreviewRequest;
use super::worker::PreviewWorker;
use crate::scene::Scene;

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
        let mut edited = scene.clone();
        // A real edit each time (the worker renders whatever it is sent).
        edited.camera.fov_deg += generation as f64 * 1e-3;
        let submitted = Instant::now();
        worker.submit(PreviewRequest::for_scene(generation, edited));
        let mut first = None;
        let full = loop {
            let message = worker.recv_timeout(timeout)?;
            if message.generation != generation {
                // A pass of the previous edit, published just before this submit.
                continue;
            }
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
    let median = |key: fn(&PreviewLatency) -> Duration| {
        let mut values: Vec<Duration> = samples.iter().map(key).collect();
        values.sort();
        values[values.len() / 2]
    };
    Some(PreviewLatency {
        first_frame: median(|l| l.first_frame),
        first_pass: samples[0].first_pass,
        full_resolution: median(|l| l.full_resolution),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_small_scene_reports_its_coarse_then_full_latency() {
        let mut scene = crate::scene::examples::default_scene();
        scene.camera.width = 160;
        scene.camera.height = 120;
        scene.render.samples_per_pixel = 1;
        let latency = measure_latency(&scene, 3, Duration::from_secs(60)).unwrap();
        assert_eq!(latency.first_pass, Pass::Coarse { divider: 2 });
        assert!(latency.first_frame <= latency.full_resolution);
    }
}
