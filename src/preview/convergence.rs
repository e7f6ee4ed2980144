//! How fast the preview converges: for one generation, the change from each published
//! pass to the one before it, against the render time spent since the edit. The editor
//! plots it live; it needs no reference image, so it is honest about what it measures:
//! how much each pass still changed the picture (it falls towards 0 as the image settles).

use std::time::Duration;

use glam::Vec3;

use super::frame::Frame;
use super::plan::Pass;
use crate::trace::Image;

/// One point of the curve: a pass, when it finished, and how much it changed the image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConvergencePoint {
    /// The pass.
    pub pass: Pass,
    /// Render time of the generation's passes up to and including this one.
    pub render_time: Duration,
    /// RMSE between this pass and the previous one (displayed values: clamped to [0, 1]).
    pub change: f64,
}

/// The curve of the current generation; starts over when a newer generation arrives.
#[derive(Clone, Debug, Default)]
pub struct ConvergenceCurve {
    generation: Option<u64>,
    render_time: Duration,
    previous: Option<Image>,
    points: Vec<ConvergencePoint>,
}

impl ConvergenceCurve {
    /// Adds a published pass of `generation`; a newer generation resets the curve, an
    /// older one is ignored.
    pub fn add(&mut self, generation: u64, frame: &Frame) {
        match self.generation {
            Some(current) if generation < current => return,
            Some(current) if generation == current => {}
            _ => *self = Self::default(),
        }
        self.generation = Some(generation);
        self.render_time += frame.elapsed;
        if let Some(previous) = &self.previous {
            self.points.push(ConvergencePoint {
                pass: frame.pass,
                render_time: self.render_time,
                change: rmse_nearest(&frame.image, previous),
            });
        }
        self.previous = Some(frame.image.clone());
    }

    /// The generation the curve belongs to.
    #[must_use]
    pub fn generation(&self) -> Option<u64> {
        self.generation
    }

    /// The points so far, in pass order (none before the second pass).
    #[must_use]
    pub fn points(&self) -> &[ConvergencePoint] {
        &self.points
    }

    /// Render time of the generation so far.
    #[must_use]
    pub fn render_time(&self) -> Duration {
        self.render_time
    }
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
    use crate::trace::RayCounts;

    fn frame(pass: Pass, image: Image, ms: u64) -> Frame {
        Frame {
            image,
            pass,
            elapsed: Duration::from_millis(ms),
            rays: RayCounts::default(),
            is_final: false,
            non_finite_samples: 0,
            non_finite_pixels: Vec::new(),
        }
    }

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
    fn the_curve_measures_each_pass_against_the_one_before_and_resets_on_a_new_generation() {
        let mut curve = ConvergenceCurve::default();
        curve.add(3, &frame(Pass::Coarse { divider: 2 }, filled(2, 2, 0.0), 5));
        assert!(curve.points().is_empty());
        let full = Pass::Full {
            samples: 1,
            target: 1,
        };
        curve.add(3, &frame(full, filled(4, 4, 0.25), 20));
        assert_eq!(curve.points().len(), 1);
        assert_eq!(curve.points()[0].render_time, Duration::from_millis(25));
        assert!((curve.points()[0].change - 0.25).abs() < 1e-9);
        curve.add(2, &frame(full, filled(4, 4, 1.0), 20));
        assert_eq!(curve.points().len(), 1, "an older generation is ignored");
        curve.add(4, &frame(Pass::Coarse { divider: 2 }, filled(2, 2, 0.0), 5));
        assert_eq!(curve.generation(), Some(4));
        assert!(curve.points().is_empty());
        assert_eq!(curve.render_time(), Duration::from_millis(5));
    }
}
