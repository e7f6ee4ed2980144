//! The preview worker in tests: scenes of a chosen size, a worker counting its wakes, and
//! bounded waits for its messages.
#![allow(dead_code)]

use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use raylab::preview::{PreviewWorker, Published};
use raylab::scene::{Scene, parse_scene};

/// Generous: the machine may be busy with other builds.
pub const WAIT: Duration = Duration::from_secs(60);

pub fn default_scene() -> Scene {
    parse_scene(include_str!("../../scenes/default.ron")).expect("default scene loads")
}

pub fn small_scene(width: u32, height: u32, samples: u32) -> Scene {
    let mut scene = default_scene();
    scene.camera.width = width;
    scene.camera.height = height;
    scene.render.samples_per_pixel = samples;
    scene
}

pub fn worker_with_counter() -> (PreviewWorker, Arc<AtomicUsize>) {
    let wakes = Arc::new(AtomicUsize::new(0));
    let counter = Arc::clone(&wakes);
    let worker = PreviewWorker::spawn(Box::new(move || {
        counter.fetch_add(1, Ordering::SeqCst);
    }));
    (worker, wakes)
}

/// Waits (up to [`WAIT`]) until `done` holds.
pub fn wait_for(mut done: impl FnMut() -> bool) {
    let started = Instant::now();
    while !done() {
        assert!(started.elapsed() < WAIT, "gave up waiting");
        std::thread::sleep(Duration::from_millis(2));
    }
}

pub fn next(worker: &mut PreviewWorker) -> Published {
    worker
        .recv_timeout(WAIT)
        .expect("the worker publishes within the wait")
}

/// Receives messages until the final frame of `generation`; returns all of them.
pub fn until_final(worker: &mut PreviewWorker, generation: u64) -> Vec<Published> {
    let deadline = Instant::now() + WAIT;
    let mut seen = Vec::new();
    while Instant::now() < deadline {
        let Some(message) = worker.recv_timeout(Duration::from_millis(200)) else {
            continue;
        };
        let done =
            message.generation == generation && message.result.as_ref().is_ok_and(|f| f.is_final);
        seen.push(message);
        if done {
            return seen;
        }
    }
    panic!("no final frame of generation {generation} within {WAIT:?}");
}
