//! The tile loop's tests: cancels, batches and the guard against non-finite samples.

use std::sync::atomic::AtomicU64;

use super::*;

/// The colour of sample `index` of pixel `(px, py)`, unguarded (it may be non-finite),
/// adding the rays it cast to the tally.
pub trait SampleColour: Fn(u32, u32, u32, &mut RayCounts) -> DVec3 + Sync {}

impl<F: Fn(u32, u32, u32, &mut RayCounts) -> DVec3 + Sync> SampleColour for F {}

/// Continues `sums` with the samples `samples` of every pixel, each colour from
/// `sample`. Each pixel adds its samples in index order whatever the batching, so the
/// numbers do not depend on how a range is split. Returns the rays of this call (also
/// added to `sums.rays`), or `None` if cancelled, leaving `sums` untouched.
fn render_tiles(
    sums: &mut SampleSums,
    samples: Range<u32>,
    progress: &RenderProgress,
    sample: &impl SampleColour,
) -> Option<RayCounts> {
    let sample = |_: &mut (), px, py, index, rays: &mut RayCounts| sample(px, py, index, rays);
    let tile = TileWork {
        new_state: |_, _| (),
        whole: |_: &mut ()| None,
        batch: |_: &mut (), _| None,
        sample: &sample,
    };
    render_tiles_with(sums, samples, progress, &tile).map(|(rays, _)| rays)
}

/// As [`render_tiles`], every batch given whole: each tile's pixels for one sample at a
/// time, from `sample`, the way the tracer's tile pass gives them.
fn render_batches(
    sums: &mut SampleSums,
    samples: Range<u32>,
    progress: &RenderProgress,
    sample: &impl SampleColour,
) -> Option<RayCounts> {
    let batch = |rect: &mut TileRect, index: u32| {
        let mut rays = RayCounts::default();
        let colours = (rect.y0..rect.y0 + rect.h)
            .flat_map(|py| (rect.x0..rect.x0 + rect.w).map(move |px| (px, py)))
            .map(|(px, py)| sample(px, py, index, &mut rays))
            .collect();
        Some((colours, rays))
    };
    let unused = |_: &mut TileRect, _, _, _, _: &mut RayCounts| -> DVec3 {
        unreachable!("every batch is given whole")
    };
    let tile = TileWork {
        new_state: |_, rect| rect,
        whole: |_: &mut TileRect| None,
        batch,
        sample: &unused,
    };
    render_tiles_with(sums, samples, progress, &tile).map(|(rays, _)| rays)
}

/// A sample colour that depends on the pixel and index only; counts its calls and
/// cancels `progress` on call number `cancel_at` (counting from 1).
fn cancelling(
    calls: &AtomicU64,
    cancel_at: u64,
    progress: &RenderProgress,
) -> impl Fn(u32, u32, u32, &mut RayCounts) -> DVec3 + Sync {
    move |px, py, index, _| {
        if calls.fetch_add(1, Ordering::SeqCst) + 1 == cancel_at {
            progress.cancel();
        }
        DVec3::new(f64::from(px), f64::from(py), f64::from(index))
    }
}

#[test]
fn a_cancel_inside_a_tile_stops_it_at_the_end_of_that_row() {
    // One 16 x 16 tile on one thread, 64 samples a pixel; the 300th sample (the
    // third row of the second batch) cancels: one batch and three rows are traced.
    let progress = RenderProgress::default();
    let calls = AtomicU64::new(0);
    let cancel_at = 300;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let mut sums = SampleSums::zero(16, 16);
    let sample = cancelling(&calls, cancel_at, &progress);
    let outcome = pool.install(|| render_tiles(&mut sums, 0..64, &progress, &sample));
    assert!(outcome.is_none());
    let batch = u64::from(TILE_SIZE * TILE_SIZE);
    assert_eq!(
        calls.load(Ordering::SeqCst),
        batch + 3 * u64::from(TILE_SIZE)
    );
    assert!(
        sums.sums.iter().all(|s| *s == DVec3::ZERO),
        "a cancelled render leaves the sums untouched"
    );
}

/// Renders 96 x 64 pixels (24 tiles) on 2 threads, each tile pixel by pixel or (with
/// `batches`) batch by batch given whole, the sample numbered `cancel_at` cancelling;
/// checks the render is cancelled with its sums untouched, and returns how many samples
/// were traced after the cancel.
fn traced_after_a_cancel(batches: bool, samples: Range<u32>, cancel_at: u64) -> u64 {
    let progress = RenderProgress::default();
    let calls = AtomicU64::new(0);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(THREADS)
        .build()
        .unwrap();
    let mut sums = SampleSums::zero(96, 64);
    let sample = cancelling(&calls, cancel_at, &progress);
    let outcome = pool.install(|| {
        if batches {
            render_batches(&mut sums, samples, &progress, &sample)
        } else {
            render_tiles(&mut sums, samples, &progress, &sample)
        }
    });
    assert!(outcome.is_none());
    assert!(
        sums.sums.iter().all(|s| *s == DVec3::ZERO),
        "sums untouched"
    );
    calls.load(Ordering::SeqCst) - cancel_at
}

/// The threads of [`traced_after_a_cancel`].
const THREADS: usize = 2;

#[test]
fn after_a_cancel_each_running_tile_traces_at_most_one_more_batch() {
    // 1024 samples: a cancel after the 1000th sample lets at most one batch per tile in
    // flight finish.
    let after = traced_after_a_cancel(false, 0..1024, 1000);
    let batch = u64::from(TILE_SIZE * TILE_SIZE);
    assert!(
        after <= THREADS as u64 * batch,
        "{after} samples traced after the cancel"
    );
}

#[test]
fn a_non_finite_sample_is_counted_listed_and_kept_out_of_the_sum() {
    // 20 x 18 pixels (four tiles, one partial); sample 2 of pixel (17, 3) is NaN and
    // sample 0 of pixel (4, 16) is infinite.
    let progress = RenderProgress::default();
    let mut sums = SampleSums::zero(20, 18);
    let sample = |px: u32, py: u32, index: u32, rays: &mut RayCounts| {
        rays.primary += 1;
        match (px, py, index) {
            (17, 3, 2) => DVec3::new(0.5, f64::NAN, 0.5),
            (4, 16, 0) => DVec3::splat(f64::INFINITY),
            _ => DVec3::splat(0.25),
        }
    };
    render_tiles(&mut sums, 0..2, &progress, &sample).unwrap();
    render_tiles(&mut sums, 2..4, &progress, &sample).unwrap();
    let mut batched = SampleSums::zero(20, 18);
    render_batches(&mut batched, 0..2, &progress, &sample).unwrap();
    render_batches(&mut batched, 2..4, &progress, &sample).unwrap();
    assert_eq!(batched.sums, sums.sums, "batches given whole sum alike");
    assert_eq!(
        (batched.non_finite, &batched.non_finite_pixels, batched.rays),
        (sums.non_finite, &sums.non_finite_pixels, sums.rays)
    );
    assert_eq!(sums.non_finite, 2);
    assert_eq!(sums.non_finite_pixels, vec![3 * 20 + 17, 16 * 20 + 4]);
    assert_eq!(sums.rays.primary, 20 * 18 * 4);
    assert_eq!(
        sums.sums[3 * 20 + 17],
        DVec3::splat(0.75),
        "three samples kept"
    );
    assert_eq!(sums.sums[16 * 20 + 4], DVec3::splat(0.75));
    assert_eq!(sums.sums[0], DVec3::splat(1.0));
    assert!(sums.sums.iter().all(|s| s.is_finite()));
    assert_eq!(progress.fraction(), 1.0);
}

#[test]
fn a_cancel_stops_a_tile_given_batch_by_batch_before_its_next_batch() {
    // 64 samples, every batch given whole: a cancel during the 30th batch lets no tile
    // start another batch (without the check before each batch, every tile would run
    // all 64).
    let batch = u64::from(TILE_SIZE * TILE_SIZE);
    let after = traced_after_a_cancel(true, 0..64, 30 * batch);
    // The rest of the cancelling batch, and a batch of each other thread.
    assert!(
        after < THREADS as u64 * batch,
        "{after} samples traced after the cancel"
    );
}

#[test]
fn a_frame_is_cleared_in_parts_unless_cancelled() {
    let progress = RenderProgress::default();
    // Sizes below one part, not a multiple of the parts, and of the most parts.
    for pixels in [0, 1, 7_500, 480_001, 1_000_003] {
        let frame = cleared_unless_cancelled(pixels, &progress).unwrap();
        assert_eq!(frame.len(), pixels);
        assert!(frame.iter().all(|sum| *sum == DVec3::ZERO));
    }
    progress.cancel();
    assert!(cleared_unless_cancelled(480_000, &progress).is_none());
}
