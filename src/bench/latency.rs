//! Preview latency through the real preview worker: from an edit (a new generation
//! submitted while the worker is busy sampling the previous one) to the first coarse
//! frame and to the first full-resolution frame of the new generation.

use std::time::{Duration, Instant};

use serde::Serialize;

use crate::preview::{Pass, PreviewRequest, PreviewWorker};
use crate::scene::Scene;

/// Median latencies over several edits.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct PreviewLatency {
    /// Edits measured.
    pub edits: u32,
    /// Edit to the first frame of the new generation (the coarsest pass), ms.
    pub first_frame_ms: f64,
    /// Edit to the first full-resolution frame, ms.
    pub full_frame_ms: f64,
}

/// Measures `edits` edits of `scene` (each moves the first object a little).
///
/// # Errors
/// When the worker reports an error or stops answering.
pub fn preview_latency(scene: &Scene, edits: u32) -> Result<PreviewLatency, String> {
    const PATIENCE: Duration = Duration::from_secs(60);
    let mut worker = PreviewWorker::spawn(Box::new(|| {}));
    let mut first = Vec::new();
    let mut full = Vec::new();
    let mut edited = scene.clone();
    for generation in 0..=u64::from(edits) {
        if let Some(object) = edited.objects.first_mut()
            && let crate::scene::Transform::Trs(trs) = &mut object.transform
        {
            trs.translate.x += 0.01;
        }
        let submitted = Instant::now();
        worker.submit(PreviewRequest::for_scene(generation, edited.clone()));
        let mut first_seen = None;
        loop {
            let message = worker
                .recv_timeout(PATIENCE)
                .ok_or("the preview worker stopped answering")?;
            if message.generation != generation {
                continue;
            }
            let frame = message.result?;
            let elapsed = submitted.elapsed().as_secs_f64() * 1e3;
            first_seen.get_or_insert(elapsed);
            if matches!(frame.pass, Pass::Full { .. }) {
                // Generation 0 only warms the worker up.
                if generation > 0 {
                    first.push(first_seen.unwrap_or(elapsed));
                    full.push(elapsed);
                }
                break;
            }
        }
        // Let the worker get busy with anti-aliasing samples, as after a real edit.
        std::thread::sleep(Duration::from_millis(30));
    }
    Ok(PreviewLatency {
        edits,
        first_frame_ms: median(&mut first),
        full_frame_ms: median(&mut full),
    })
}

fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied().unwrap_or(f64::NAN)
}
