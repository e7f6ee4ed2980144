//! The preview worker: generations, pass order, cancellation, staleness, errors.

use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use raylab::preview::{Pass, PreviewRequest, PreviewWorker, Published};
use raylab::scene::{Scene, parse_scene};

/// Generous: the machine may be busy with other builds.
const WAIT: Duration = Duration::from_secs(60);

fn default_scene() -> Scene {
    parse_scene(include_str!("../scenes/default.ron")).expect("default scene loads")
}

fn small_scene(width: u32, height: u32, samples: u32) -> Scene {
    let mut scene = default_scene();
    scene.camera.width = width;
    scene.camera.height = height;
    scene.render.samples_per_pixel = samples;
    scene
}

fn worker_with_counter() -> (PreviewWorker, Arc<AtomicUsize>) {
    let wakes = Arc::new(AtomicUsize::new(0));
    let counter = Arc::clone(&wakes);
    let worker = PreviewWorker::spawn(Box::new(move || {
        counter.fetch_add(1, Ordering::SeqCst);
    }));
    (worker, wakes)
}

fn next(worker: &mut PreviewWorker) -> Published {
    worker
        .recv_timeout(WAIT)
        .expect("the worker publishes within the wait")
}

/// Receives messages until the final frame of `generation`; returns all of them.
fn until_final(worker: &mut PreviewWorker, generation: u64) -> Vec<Published> {
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

#[test]
fn passes_arrive_coarse_first_then_full_then_samples() {
    let (mut worker, wakes) = worker_with_counter();
    worker.submit(PreviewRequest::for_scene(1, small_scene(320, 240, 4)));
    let messages = until_final(&mut worker, 1);
    let passes: Vec<Pass> = messages
        .iter()
        .map(|m| m.result.as_ref().expect("the scene renders").pass)
        .collect();
    assert_eq!(
        passes,
        vec![
            Pass::Coarse { divider: 4 },
            Pass::Full {
                samples: 1,
                target: 1
            },
            Pass::Full {
                samples: 4,
                target: 4
            },
        ]
    );
    let first = messages[0].result.as_ref().unwrap();
    assert_eq!((first.image.width, first.image.height), (80, 60));
    let last = messages.last().unwrap().result.as_ref().unwrap();
    assert_eq!((last.image.width, last.image.height), (320, 240));
    assert!(last.is_final);
    // The waker runs just after each send; give the last one a moment.
    let waited = Instant::now();
    while wakes.load(Ordering::SeqCst) < 3 && waited.elapsed() < WAIT {
        std::thread::sleep(Duration::from_millis(5));
    }
    assert_eq!(
        wakes.load(Ordering::SeqCst),
        3,
        "the waker runs once per publish"
    );
}

#[test]
fn after_a_submit_the_next_frame_carries_the_new_generation() {
    let (mut worker, _) = worker_with_counter();
    worker.submit(PreviewRequest::for_scene(1, small_scene(320, 240, 1)));
    until_final(&mut worker, 1);
    let mut edited = small_scene(320, 240, 1);
    edited.render.background = glam::DVec3::new(1.0, 0.0, 0.0);
    worker.submit(PreviewRequest::for_scene(2, edited));
    let message = next(&mut worker);
    assert_eq!(message.generation, 2);
    assert!(matches!(message.result.unwrap().pass, Pass::Coarse { .. }));
}

#[test]
fn stale_generations_are_never_published_after_a_newer_one() {
    let (mut worker, _) = worker_with_counter();
    for generation in 1..=12 {
        let mut scene = small_scene(200, 150, 4);
        scene.camera.fov_deg = 30.0 + generation as f64;
        worker.submit(PreviewRequest::for_scene(generation, scene));
        std::thread::sleep(Duration::from_millis(3));
    }
    let messages = until_final(&mut worker, 12);
    let generations: Vec<u64> = messages.iter().map(|m| m.generation).collect();
    assert!(
        generations.windows(2).all(|w| w[0] <= w[1]),
        "generations went back: {generations:?}"
    );
    assert_eq!(generations.last(), Some(&12));
    // An older request submitted late is ignored.
    worker.submit(PreviewRequest::for_scene(5, small_scene(64, 48, 1)));
    assert!(worker.recv_timeout(Duration::from_millis(500)).is_none());
}

/// Submits a render far longer than the bounds below and waits until its first
/// anti-aliasing pass (4 samples a pixel) is under way. Returns how long the one-sample
/// full-resolution pass took: the pass being rendered takes about four times that.
fn start_long_render(worker: &mut PreviewWorker, generation: u64) -> Duration {
    worker.submit(PreviewRequest::for_scene(
        generation,
        small_scene(2000, 1500, 1024),
    ));
    let one_sample = loop {
        let message = next(worker);
        assert_eq!(message.generation, generation);
        let frame = message.result.unwrap();
        if frame.pass
            == (Pass::Full {
                samples: 1,
                target: 1,
            })
        {
            break frame.elapsed;
        }
    };
    let started = Instant::now();
    while worker.pass_progress().is_none_or(|p| p <= 0.0) {
        assert!(started.elapsed() < WAIT, "the sampling pass never started");
        std::thread::sleep(Duration::from_millis(2));
    }
    one_sample
}

#[test]
fn a_long_render_is_cancelled_quickly_by_a_new_submit_and_by_drop() {
    let (mut worker, _) = worker_with_counter();
    let one_sample = start_long_render(&mut worker, 1);
    let submitted = Instant::now();
    worker.submit(PreviewRequest::for_scene(2, small_scene(64, 48, 1)));
    let message = next(&mut worker);
    assert_eq!(
        message.generation, 2,
        "nothing more of the cancelled render"
    );
    assert!(message.result.is_ok());
    let took = submitted.elapsed();
    assert!(
        took < Duration::from_secs(10) && took < one_sample,
        "restart took {took:?}; a one-sample pass takes {one_sample:?}"
    );

    let one_sample = start_long_render(&mut worker, 3);
    let dropping = Instant::now();
    drop(worker);
    let took = dropping.elapsed();
    assert!(
        took < Duration::from_secs(10) && took < one_sample,
        "drop took {took:?}; a one-sample pass takes {one_sample:?}"
    );
}

#[test]
fn an_invalid_scene_publishes_its_error() {
    let (mut worker, _) = worker_with_counter();
    let mut scene = small_scene(64, 48, 1);
    scene.objects[0].material = "no such material".to_owned();
    worker.submit(PreviewRequest::for_scene(7, scene));
    let message = next(&mut worker);
    assert_eq!(message.generation, 7);
    let error = message.result.expect_err("the scene is invalid");
    assert!(error.contains("no such material"), "{error}");
}

#[test]
fn the_final_frame_matches_a_direct_render_of_the_same_options() {
    let (mut worker, _) = worker_with_counter();
    let scene = small_scene(160, 120, 16);
    let request = PreviewRequest::for_scene(1, scene.clone());
    let options = request.options;
    worker.submit(request);
    let messages = until_final(&mut worker, 1);
    let last = messages.last().unwrap().result.as_ref().unwrap();
    let world = raylab::trace::World::new(&scene).unwrap();
    let progress = raylab::trace::RenderProgress::default();
    let (direct, _) = raylab::trace::render(&world, &options, &progress).unwrap();
    assert_eq!(last.image.to_rgba8(), direct.to_rgba8());
    let max_difference = last
        .image
        .pixels
        .iter()
        .zip(&direct.pixels)
        .map(|(a, b)| (*a - *b).abs().max_element())
        .fold(0.0f32, f32::max);
    assert!(max_difference < 1e-6, "{max_difference}");
}

#[test]
fn a_panic_on_the_worker_thread_is_reported_and_the_worker_carries_on() {
    // The waker runs on the worker thread inside its guard: make the first call panic.
    let calls = Arc::new(AtomicUsize::new(0));
    let counter = Arc::clone(&calls);
    let mut worker = PreviewWorker::spawn(Box::new(move || {
        if counter.fetch_add(1, Ordering::SeqCst) == 0 {
            panic!("boom");
        }
    }));
    worker.submit(PreviewRequest::for_scene(1, small_scene(320, 240, 1)));
    let first = next(&mut worker);
    assert!(first.result.is_ok(), "the frame went out before the panic");
    let report = next(&mut worker);
    assert_eq!(report.generation, 1);
    let error = report.result.expect_err("the panic is reported");
    assert!(
        error.contains("crashed") && error.contains("boom"),
        "{error}"
    );

    worker.submit(PreviewRequest::for_scene(2, small_scene(64, 48, 1)));
    let message = next(&mut worker);
    assert_eq!(message.generation, 2);
    assert!(message.result.is_ok(), "the worker still renders");
}
