//! Where in a pixel each anti-aliasing sample goes.
//!
//! Samples come from an Owen-scrambled Sobol sequence (`sobol_burley`), scrambled per
//! pixel. Its first two dimensions form a (0,2)-sequence: the first 2^k samples, and every
//! aligned block of 2^k samples, put exactly one sample in each elementary box of area
//! 2^-k (each quadrant for 4, each cell of a 4x4 grid for 16, each 2x8 or 8x2 strip...).
//! So every prefix a progressive preview shows (4, 8, 16, ... samples) is stratified over
//! the whole pixel, and sample `index` is the same whatever the total count: the
//! n-sample pass of a larger target is exactly the n-sample image.

use glam::DVec2;

/// Samples of one scrambled sequence; `sobol_burley` supports this many indices. Beyond
/// it a pixel continues with a freshly seeded sequence (no render asks for that many).
const SEQUENCE_LENGTH: u32 = 1 << 16;

/// The position within pixel `(px, py)` (each coordinate in [0, 1)) of sample `index` of
/// `count` samples per pixel. One sample is the pixel centre; more are
/// [`sequence_sample`]s, so they do not depend on `count`.
#[must_use]
pub fn sample_in_pixel(px: u32, py: u32, index: u32, count: u32) -> DVec2 {
    if count <= 1 {
        DVec2::splat(0.5)
    } else {
        sequence_sample(px, py, index)
    }
}

/// Sample `index` of pixel `(px, py)`'s own scrambled Sobol sequence, in [0, 1)^2. Any
/// prefix is well spread and power-of-two prefixes are stratified, so it suits counts
/// decided on the fly (adaptive sampling) as well as fixed ones.
#[must_use]
pub fn sequence_sample(px: u32, py: u32, index: u32) -> DVec2 {
    let seed = pixel_seed(px, py, index / SEQUENCE_LENGTH);
    let index = index % SEQUENCE_LENGTH;
    // The first four dimensions at once (the crate's SIMD path): the same values as two
    // calls of `sample` for dimensions 0 and 1, which shuffled the index twice; 15%
    // fewer instructions (docs/PERFORMANCE_HISTORY.md).
    let [x, y, _, _] = sobol_burley::sample_4d(index, 0, seed);
    DVec2::new(f64::from(x), f64::from(y))
}

/// A per-pixel scramble seed (and per run of [`SEQUENCE_LENGTH`] samples), so that
/// neighbouring pixels' errors are independent noise rather than a shared pattern.
fn pixel_seed(px: u32, py: u32, run: u32) -> u32 {
    let mut h = u64::from(px) | (u64::from(py) << 32);
    h ^= u64::from(run).wrapping_mul(0x2545_f491_4f6c_dd1d);
    // splitmix64 finaliser
    h = (h ^ (h >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h = (h ^ (h >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    h ^= h >> 31;
    (h >> 32) as u32
}

#[cfg(test)]
mod tests {
    use super::*;

    /// How many of `samples` fall in each of the `2^a x 2^b` boxes of the pixel.
    fn box_counts(samples: &[DVec2], a: u32, b: u32) -> Vec<u32> {
        let (columns, rows) = (1u32 << a, 1u32 << b);
        let mut counts = vec![0; (columns * rows) as usize];
        for s in samples {
            let column = (s.x * f64::from(columns)) as u32;
            let row = (s.y * f64::from(rows)) as u32;
            counts[(row * columns + column) as usize] += 1;
        }
        counts
    }

    fn samples(px: u32, py: u32, indices: std::ops::Range<u32>, count: u32) -> Vec<DVec2> {
        indices.map(|i| sample_in_pixel(px, py, i, count)).collect()
    }

    /// The four-dimension call gives the sequence's first two dimensions exactly, run
    /// after run of [`SEQUENCE_LENGTH`] samples.
    #[test]
    fn a_sample_is_the_sequences_first_two_dimensions() {
        for (px, py) in [(0, 0), (3, 7), (799, 599)] {
            for index in (0..300).chain([SEQUENCE_LENGTH - 1, SEQUENCE_LENGTH + 5]) {
                let seed = pixel_seed(px, py, index / SEQUENCE_LENGTH);
                let i = index % SEQUENCE_LENGTH;
                let expected = DVec2::new(
                    f64::from(sobol_burley::sample(i, 0, seed)),
                    f64::from(sobol_burley::sample(i, 1, seed)),
                );
                assert_eq!(
                    sequence_sample(px, py, index),
                    expected,
                    "({px}, {py}) #{index}"
                );
            }
        }
    }

    #[test]
    fn one_sample_is_the_centre_and_more_lie_inside_the_pixel() {
        assert_eq!(sample_in_pixel(3, 7, 0, 1), DVec2::splat(0.5));
        for s in samples(3, 7, 0..256, 256) {
            assert!(
                (0.0..1.0).contains(&s.x) && (0.0..1.0).contains(&s.y),
                "{s}"
            );
        }
    }

    #[test]
    fn power_of_two_prefixes_and_blocks_put_one_sample_in_every_elementary_box() {
        for (px, py) in [(0, 0), (1, 0), (17, 3), (799, 599)] {
            for k in 1..=8 {
                let n = 1u32 << k;
                // The prefix, and the second block of the same size.
                for start in [0, n] {
                    let block = samples(px, py, start..start + n, 1024);
                    for a in 0..=k {
                        let counts = box_counts(&block, a, k - a);
                        assert!(
                            counts.iter().all(|&c| c == 1),
                            "pixel ({px}, {py}) samples {start}..{}: {}x{} boxes {counts:?}",
                            start + n,
                            1 << a,
                            1 << (k - a)
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn a_sample_does_not_depend_on_the_count_and_pixels_differ() {
        for index in 0..64 {
            assert_eq!(
                sample_in_pixel(5, 9, index, 64),
                sample_in_pixel(5, 9, index, 4096)
            );
        }
        assert_ne!(sample_in_pixel(5, 9, 3, 16), sample_in_pixel(6, 9, 3, 16));
        assert_ne!(sample_in_pixel(5, 9, 3, 16), sample_in_pixel(5, 10, 3, 16));
    }

    #[test]
    fn indices_past_one_sequence_continue_inside_the_pixel_with_new_points() {
        let last = sequence_sample(2, 2, SEQUENCE_LENGTH - 1);
        let next = sequence_sample(2, 2, SEQUENCE_LENGTH);
        assert_ne!(last, next);
        assert_ne!(
            next,
            sequence_sample(2, 2, 0),
            "a fresh scramble, not a repeat"
        );
        let block = samples(
            2,
            2,
            SEQUENCE_LENGTH..SEQUENCE_LENGTH + 16,
            2 * SEQUENCE_LENGTH,
        );
        assert!(box_counts(&block, 2, 2).iter().all(|&c| c == 1));
    }
}
