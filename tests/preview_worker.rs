//! The preview worker: generations, pass order, cancellation, staleness, the bounded
//! outbox, errors. No test here asserts a time; latencies are measured by `raylab bench`.

mod worker_harness;

use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use raylab::preview::{OUTBOX_CAPACITY, Pass, PreviewRequest, PreviewWorker};
use worker_harness::{WAIT, next, small_scene, until_final, wait_for, worker_with_counter};

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
            Pass::Coarse { divider: 2 },
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
    let second = messages[1].result.as_ref().unwrap();
    assert_eq!((second.image.width, second.image.height), (160, 120));
    let last = messages.last().unwrap().result.as_ref().unwrap();
    assert_eq!((last.image.width, last.image.height), (320, 240));
    assert!(last.is_final);
    // The waker runs just after each send; give the last one a moment.
    let waited = Instant::now();
    while wakes.load(Ordering::SeqCst) < 4 && waited.elapsed() < WAIT {
        std::thread::sleep(Duration::from_millis(5));
    }
    assert_eq!(
        wakes.load(Ordering::SeqCst),
        4,
        "the waker runs once per publish"
    );
}

#[test]
fn drain_hands_out_passes_in_plan_order_up_to_the_final_one() {
    let (mut worker, _) = worker_with_counter();
    let scene = small_scene(320, 240, 16);
    let request = PreviewRequest::for_scene(1, scene);
    let plan = raylab::preview::plan_passes(&request.options);
    worker.submit(request);
    let mut passes = Vec::new();
    let mut final_seen = false;
    wait_for(|| {
        for message in worker.drain() {
            assert_eq!(message.generation, 1);
            let frame = message.result.unwrap();
            final_seen |= frame.is_final;
            passes.push(frame.pass);
        }
        final_seen
    });
    // A slow reader may miss passes (the outbox drops the oldest), never reorder them.
    let positions: Vec<usize> = passes
        .iter()
        .map(|p| {
            plan.iter()
                .position(|q| q == p)
                .expect("a pass of the plan")
        })
        .collect();
    assert!(positions.windows(2).all(|w| w[0] < w[1]), "{passes:?}");
    assert_eq!(passes.last(), plan.last());
}

#[test]
fn after_a_submit_no_frame_of_an_older_generation_can_be_taken() {
    let (mut worker, wakes) = worker_with_counter();
    worker.submit(PreviewRequest::for_scene(1, small_scene(320, 240, 1)));
    // A frame of generation 1 is published and not read yet when the edit comes.
    wait_for(|| wakes.load(Ordering::SeqCst) >= 1);
    let mut edited = small_scene(320, 240, 1);
    edited.render.background = glam::DVec3::new(1.0, 0.0, 0.0);
    worker.submit(PreviewRequest::for_scene(2, edited));
    let messages = until_final(&mut worker, 2);
    let generations: Vec<u64> = messages.iter().map(|m| m.generation).collect();
    assert!(generations.iter().all(|&g| g == 2), "{generations:?}");
}

#[test]
fn an_unread_outbox_keeps_only_the_newest_frames_and_the_whole_curve() {
    let (mut worker, wakes) = worker_with_counter();
    let request = PreviewRequest::for_scene(1, small_scene(64, 48, 256));
    let plan = raylab::preview::plan_passes(&request.options);
    assert!(plan.len() > OUTBOX_CAPACITY, "{plan:?}");
    worker.submit(request);
    wait_for(|| wakes.load(Ordering::SeqCst) == plan.len());
    let messages = worker.drain();
    let passes: Vec<Pass> = messages
        .iter()
        .map(|m| m.result.as_ref().unwrap().pass)
        .collect();
    assert_eq!(passes, plan[plan.len() - OUTBOX_CAPACITY..]);
    let last = messages.last().unwrap().result.as_ref().unwrap();
    assert!(last.is_final);
    // Every anti-aliasing pass (4, 8, ..., 256 samples) is on the final frame's curve.
    let sampled = plan
        .iter()
        .filter(|p| matches!(p, Pass::Full { samples, .. } if *samples > 1))
        .count();
    assert_eq!(last.convergence.points().len(), sampled);
    assert!(worker.drain().is_empty());
}

#[test]
fn after_a_submit_the_next_frame_carries_the_new_generation() {
    let (mut worker, _) = worker_with_counter();
    worker.submit(PreviewRequest::for_scene(1, small_scene(320, 240, 1)));
    until_final(&mut worker, 1);
    let mut edited = small_scene(320, 240, 1);
    edited.render.background = glam::DVec3::new(1.0, 0.0, 0.0);
    // With the camera moved too: an edit that moves nothing re-shades, full resolution
    // first (tests/preview_worker_reshade.rs).
    edited.camera.fov_deg += 1.0;
    worker.submit(PreviewRequest::for_scene(2, edited));
    let message = next(&mut worker);
    assert_eq!(message.generation, 2);
    let frame = message.result.unwrap();
    assert_eq!(
        frame.pass,
        Pass::Coarse { divider: 4 },
        "an edit restarts coarse"
    );
    // The new background shows in the very first frame of the new generation.
    assert_eq!(frame.image.get(0, 0), glam::Vec3::new(1.0, 0.0, 0.0));
}

#[test]
fn the_default_scene_refines_8_4_2_then_full_resolution() {
    let (mut worker, _) = worker_with_counter();
    worker.submit(PreviewRequest::for_scene(1, small_scene(800, 600, 1)));
    let messages = until_final(&mut worker, 1);
    let sizes: Vec<(Pass, u32, u32)> = messages
        .iter()
        .map(|m| {
            let frame = m.result.as_ref().unwrap();
            (frame.pass, frame.image.width, frame.image.height)
        })
        .collect();
    let full = Pass::Full {
        samples: 1,
        target: 1,
    };
    assert_eq!(
        sizes,
        vec![
            (Pass::Coarse { divider: 8 }, 100, 75),
            (Pass::Coarse { divider: 4 }, 200, 150),
            (Pass::Coarse { divider: 2 }, 400, 300),
            (full, 800, 600),
        ]
    );
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

/// Submits a render far longer than the test and waits until its first anti-aliasing
/// pass is under way.
fn start_long_render(worker: &mut PreviewWorker, generation: u64) {
    worker.submit(PreviewRequest::for_scene(
        generation,
        small_scene(800, 600, 1024),
    ));
    loop {
        let message = next(worker);
        assert_eq!(message.generation, generation);
        let frame = message.result.unwrap();
        if frame.pass
            == (Pass::Full {
                samples: 1,
                target: 1,
            })
        {
            break;
        }
    }
    wait_for(|| worker.pass_progress().is_some_and(|p| p > 0.0));
}

#[test]
fn a_submit_or_a_drop_during_a_long_pass_ends_it_and_nothing_of_it_follows() {
    let (mut worker, _) = worker_with_counter();
    start_long_render(&mut worker, 1);
    worker.submit(PreviewRequest::for_scene(2, small_scene(64, 48, 1)));
    let message = next(&mut worker);
    assert_eq!(
        message.generation, 2,
        "nothing more of the cancelled render"
    );
    assert!(message.result.is_ok());
    assert!(worker.recv_timeout(Duration::from_millis(200)).is_none());

    // Dropping joins the thread, which returns only once the pass has stopped (how soon
    // is `raylab bench`'s restart latency; trace::tiles tests the one-batch bound).
    start_long_render(&mut worker, 3);
    drop(worker);
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
