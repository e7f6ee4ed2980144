//! Whether every pixel value between two sums of samples writes the same bytes: the test
//! that tells a pruned pixel that is already exact from one to trace again.

use glam::DVec3;

use crate::scene::Quantise;
use crate::trace::film::encode;

/// How much wider than `[sum, sum + left_out]` the interval is taken, relative to the
/// values: more than the rounding of the tracer's arithmetic (`shade/subtree_bound.rs`).
const ROUNDING_SLACK: f64 = 1e-9;

/// Whether a pixel whose sum of `count` samples is `sum` as traced, and at most
/// `left_out` more in full, is written as the same bytes whatever the full sum is.
///
/// The bytes are made exactly as [`crate::trace::SampleSums::average`] and
/// [`crate::trace::Image::write_png`] make them: the sum times 1/count, to f32, clamped,
/// then rounded or truncated. Each of those steps is non-decreasing, so a sum between
/// the interval's ends gives a byte between the ends' bytes, and equal ends' bytes
/// leave no other.
#[must_use]
pub fn same_bytes(sum: DVec3, left_out: DVec3, count: u32, quantise: Quantise) -> bool {
    let slack = (sum.abs() + left_out + DVec3::splat(f64::from(count))) * ROUNDING_SLACK;
    let low = sum - slack;
    let high = sum + left_out + slack;
    let scale = 1.0 / f64::from(count.max(1));
    let bytes = |sum: DVec3| {
        (sum * scale)
            .as_vec3()
            .to_array()
            .map(|c| encode(c, quantise))
    };
    bytes(low) == bytes(high)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_interval_within_one_step_keeps_its_bytes_and_one_across_does_not() {
        let step = 1.0 / 255.0;
        let inside = DVec3::splat(100.25 * step);
        let small = DVec3::splat(0.5 * step);
        assert!(same_bytes(inside, DVec3::ZERO, 1, Quantise::Round));
        // 100.25 to 100.75 crosses round's step at 100.5, not truncate's at 101.
        assert!(!same_bytes(inside, small, 1, Quantise::Round));
        assert!(same_bytes(inside, small, 1, Quantise::Truncate));
        // Four samples: the sum is four times the pixel, and so is what was left out
        // (100.25 to 100.75, then to 101.25).
        assert!(same_bytes(inside * 4.0, small * 4.0, 4, Quantise::Truncate));
        assert!(!same_bytes(
            inside * 4.0,
            small * 8.0,
            4,
            Quantise::Truncate
        ));
        // One channel is enough to retrace.
        let one = DVec3::new(0.0, 0.0, 0.6 * step);
        assert!(!same_bytes(inside, one, 1, Quantise::Round));
    }

    #[test]
    fn the_clamp_is_inside_the_interval() {
        // Above 1 every value writes 255; below 0 every value writes 0.
        let over = DVec3::splat(1.2);
        assert!(same_bytes(over, DVec3::splat(5.0), 1, Quantise::Round));
        assert!(!same_bytes(
            DVec3::splat(0.99),
            DVec3::splat(0.1),
            1,
            Quantise::Round
        ));
        assert!(same_bytes(
            DVec3::splat(-0.5),
            DVec3::splat(0.4),
            1,
            Quantise::Truncate
        ));
    }
}
