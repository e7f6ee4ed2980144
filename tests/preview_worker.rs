//! The preview worker: generations, pass order, cancellation, staleness, the bounded
//! outbox, errors. No test here asserts a time; latencies are measured by `raylab bench`.

use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use raylab::cli::RenderArgs;
use raylab::preview::{OUTBOX_CAPACITY, Pass, PreviewRequest, PreviewWorker, Published};
use raylab::scene::{Scene, parse_scene};
use raylab::trace::{
    Image, RenderOptions, RenderProgress, SampleSums, Term, View, World, render, render_samples,
    render_samples_into,
};

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

/// Waits (up to [`WAIT`]) until `done` holds.
fn wait_for(mut done: impl FnMut() -> bool) {
    let started = Instant::now();
    while !done() {
        assert!(started.elapsed() < WAIT, "gave up waiting");
        std::thread::sleep(Duration::from_millis(2));
    }
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

/// Render options as `raylab render` builds them from its arguments.
fn cli_options(scene: &Scene, off: &[Term], solo: Option<Term>, view: View) -> RenderOptions {
    let args = RenderArgs {
        scene: "scene.ron".into(),
        output: "out.png".into(),
        width: None,
        height: None,
        spp: None,
        off: off.to_vec(),
        solo,
        view,
        isolation: Default::default(),
    };
    args.options(scene).unwrap()
}

/// Whether two images are equal pixel for pixel (exact f32 equality).
fn identical(a: &Image, b: &Image) -> bool {
    a.width == b.width && a.height == b.height && a.pixels == b.pixels
}

#[test]
fn the_final_frame_is_bit_identical_to_the_cli_render_for_the_same_switches() {
    let (mut worker, _) = worker_with_counter();
    let scene = small_scene(160, 120, 16);
    let world = World::new(&scene).unwrap();
    let cases: [(&[Term], Option<Term>, View); 5] = [
        (&[], None, View::Beauty),
        (&[Term::Diffuse], None, View::Beauty),
        (&[Term::Shadows], Some(Term::Specular), View::Beauty),
        (&[], Some(Term::Reflection), View::Beauty),
        (&[Term::Ambient], None, View::Normal),
    ];
    for (generation, (off, solo, view)) in (1..).zip(cases) {
        let options = cli_options(&scene, off, solo, view);
        let mut request = PreviewRequest::for_scene(generation, scene.clone());
        request.options = options.clone();
        worker.submit(request);
        let messages = until_final(&mut worker, generation);
        let last = messages.last().unwrap().result.as_ref().unwrap();
        assert_eq!(
            last.pass,
            Pass::Full {
                samples: 16,
                target: 16
            }
        );
        let (direct, _) = render(&world, &options, &RenderProgress::default()).unwrap();
        assert!(
            identical(&last.image, &direct),
            "off {off:?} solo {solo:?} view {view}: the preview differs from the CLI"
        );
        assert_eq!(last.non_finite_samples, 0);
    }
}

#[test]
fn a_one_sample_scene_ends_on_the_cli_image_too() {
    let (mut worker, _) = worker_with_counter();
    let scene = small_scene(200, 100, 1);
    let options = cli_options(&scene, &[Term::Specular], None, View::ShadowMask);
    let mut request = PreviewRequest::for_scene(1, scene.clone());
    request.options = options.clone();
    worker.submit(request);
    let messages = until_final(&mut worker, 1);
    let last = messages.last().unwrap().result.as_ref().unwrap();
    let world = World::new(&scene).unwrap();
    let (direct, _) = render(&world, &options, &RenderProgress::default()).unwrap();
    assert!(identical(&last.image, &direct));
}

#[test]
fn samples_added_in_batches_sum_exactly_as_in_one_go() {
    let scene = small_scene(48, 32, 8);
    let world = World::new(&scene).unwrap();
    let options = RenderOptions::from_scene(&scene);
    let progress = RenderProgress::default();
    let at_once = render_samples(&world, &options, 0..8, &progress).unwrap();
    let mut batched = SampleSums::zero(48, 32);
    let mut rays = 0;
    for batch in [0..1, 1..4, 4..8] {
        rays += render_samples_into(&world, &options, batch, &mut batched, &progress)
            .unwrap()
            .total();
    }
    assert_eq!(batched.sums, at_once.sums);
    assert_eq!(batched.rays, at_once.rays);
    assert_eq!(rays, at_once.rays.total());
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
