//! How far the preview still is from converged: for every anti-aliasing pass, an estimate
//! of the RMSE between the picture and the one infinitely many samples would give, from
//! two halves of the pixel's samples, against the render time spent since the edit. The
//! worker computes it as it renders (no reference image needed, no work on the UI
//! thread); the benchmark checks it against the true error.

use std::time::Duration;

use glam::Vec3;

use super::plan::Pass;
use crate::trace::Image;

/// One point of the curve: a sampled pass, when it finished, and its estimated error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConvergencePoint {
    /// The pass.
    pub pass: Pass,
    /// Render time of the generation's passes up to and including this one.
    pub render_time: Duration,
    /// Estimated RMSE of this pass's displayed values (clamped to [0, 1]) against the
    /// converged picture; see [`estimated_rmse`].
    pub estimated_rmse: f64,
}

/// The curve of one generation so far; every published frame carries a copy, so the
/// newest frame alone is enough to draw it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ConvergenceCurve {
    render_time: Duration,
    points: Vec<ConvergencePoint>,
}

impl ConvergenceCurve {
    /// Adds a pass that took `elapsed`; it becomes a point when it has an estimate.
    pub fn add(&mut self, pass: Pass, elapsed: Duration, estimated_rmse: Option<f64>) {
        self.render_time += elapsed;
        if let Some(estimated_rmse) = estimated_rmse {
            self.points.push(ConvergencePoint {
                pass,
                render_time: self.render_time,
                estimated_rmse,
            });
        }
    }

    /// The points so far, in pass order (none before the first anti-aliasing pass).
    #[must_use]
    pub fn points(&self) -> &[ConvergencePoint] {
        &self.points
    }

    /// Render time of the generation so far, every pass included.
    #[must_use]
    pub fn render_time(&self) -> Duration {
        self.render_time
    }
}

/// The estimated RMSE of `all`, the mean of samples `0..all_samples` of every pixel,
/// given `first`, the mean of the first `first_samples` of them.
///
/// With A the mean of the first s samples, B the mean of the other n - s and M = (s A +
/// (n - s) B) / n, two independent estimates whose variance falls as 1 / count give
/// E[(M - I)^2] = E[(A - M)^2] s / (n - s). For halves (s = n / 2) the estimate is the RMS
/// of A - M, which is (A - B) / 2. Stratified halves are better than independent, so this
/// errs on the high side; the benchmark measures by how much.
#[must_use]
pub fn estimated_rmse(first: &Image, first_samples: u32, all: &Image, all_samples: u32) -> f64 {
    let rest = all_samples.saturating_sub(first_samples).max(1);
    rmse_nearest(first, all) * (f64::from(first_samples) / f64::from(rest)).sqrt()
}

/// RMSE of the clamped values of `a` and `b` over the larger image's pixel grid, the
/// smaller image enlarged nearest-neighbour (a coarse pass as the viewport shows it).
#[must_use]
pub fn rmse_nearest(a: &Image, b: &Image) -> f64 {
    let (large, small) = if a.pixels.len() >= b.pixels.len() {
        (a, b)
    } else {
        (b, a)
    };
    if large.pixels.is_empty() || small.pixels.is_empty() {
        return 0.0;
    }
    let clamp = |v: Vec3| v.clamp(Vec3::ZERO, Vec3::ONE);
    let mut sum = 0.0f64;
    for y in 0..large.height {
        let sy = (u64::from(y) * u64::from(small.height) / u64::from(large.height)) as u32;
        for x in 0..large.width {
            let sx = (u64::from(x) * u64::from(small.width) / u64::from(large.width)) as u32;
            let d = clamp(large.get(x, y)) - clamp(small.get(sx, sy));
            sum += f64::from(d.length_squared());
        }
    }
    (sum / (3.0 * large.pixels.len() as f64)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn filled(width: u32, height: u32, value: f32) -> Image {
        let mut image = Image::new(width, height);
        image.pixels.fill(Vec3::splat(value));
        image
    }

    #[test]
    fn rmse_enlarges_the_smaller_image_and_clamps() {
        let mut small = Image::new(2, 1);
        small.pixels[1] = Vec3::splat(1.0);
        let mut large = Image::new(4, 2);
        for y in 0..2 {
            for x in 2..4 {
                large.pixels[y * 4 + x] = Vec3::splat(3.0);
            }
        }
        assert_eq!(rmse_nearest(&small, &large), 0.0, "clamped 3 is 1");
        assert_eq!(rmse_nearest(&large, &small), 0.0);
        let grey = filled(4, 2, 0.5);
        assert!((rmse_nearest(&grey, &small) - 0.5).abs() < 1e-12);
    }

    #[test]
    fn the_estimate_of_independent_samples_matches_their_true_error() {
        // Pixels whose samples are independent coin flips (0 or 1, true mean 0.5): the
        // estimate from the halves must agree with the error against 0.5.
        let (width, n, s) = (4096u32, 16u32, 8u32);
        let mut cases = crate::test_cases::Xorshift(0x2545_f491_4f6c_dd1d);
        let mut flip = || (cases.next_u64() >> 40) & 1;
        let mut first = Image::new(width, 1);
        let mut all = Image::new(width, 1);
        for x in 0..width as usize {
            let samples: Vec<f32> = (0..n).map(|_| flip() as f32).collect();
            first.pixels[x] = Vec3::splat(samples[..s as usize].iter().sum::<f32>() / s as f32);
            all.pixels[x] = Vec3::splat(samples.iter().sum::<f32>() / n as f32);
        }
        let truth = rmse_nearest(&all, &filled(width, 1, 0.5));
        let estimate = estimated_rmse(&first, s, &all, n);
        assert!(
            (estimate / truth - 1.0).abs() < 0.1,
            "estimate {estimate}, true {truth}"
        );
        // Unequal parts are weighted: 4 of 16 samples first.
        let mut quarter = Image::new(width, 1);
        let mut state = 7u64;
        let mut flip = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1);
            (state >> 63) as f32
        };
        for x in 0..width as usize {
            let samples: Vec<f32> = (0..n).map(|_| flip()).collect();
            quarter.pixels[x] = Vec3::splat(samples[..4].iter().sum::<f32>() / 4.0);
            all.pixels[x] = Vec3::splat(samples.iter().sum::<f32>() / n as f32);
        }
        let truth = rmse_nearest(&all, &filled(width, 1, 0.5));
        let estimate = estimated_rmse(&quarter, 4, &all, n);
        assert!(
            (estimate / truth - 1.0).abs() < 0.1,
            "estimate {estimate}, true {truth}"
        );
    }

    #[test]
    fn the_curve_adds_time_for_every_pass_and_a_point_for_each_estimate() {
        let mut curve = ConvergenceCurve::default();
        curve.add(Pass::Coarse { divider: 2 }, Duration::from_millis(5), None);
        let one = Pass::Full {
            samples: 1,
            target: 1,
        };
        curve.add(one, Duration::from_millis(20), None);
        assert!(curve.points().is_empty());
        let four = Pass::Full {
            samples: 4,
            target: 16,
        };
        curve.add(four, Duration::from_millis(80), Some(0.02));
        assert_eq!(
            curve.points(),
            &[ConvergencePoint {
                pass: four,
                render_time: Duration::from_millis(105),
                estimated_rmse: 0.02
            }]
        );
        assert_eq!(curve.render_time(), Duration::from_millis(105));
    }
}
