//! The depth debug view's grey scale: the range of distances the camera sees, found once
//! per render from a coarse grid of camera rays, is spread over the grey scale (nearest
//! white, farthest dark grey), so objects stand out from the floor behind them. Rays
//! that hit nothing stay black.

use glam::DVec2;

use crate::trace::film::PinholeCamera;
use crate::trace::world::World;

/// Rays per side of the grid that finds the visible depth range.
const GRID: u32 = 32;

/// The grey of the farthest visible surface (the nearest is white; misses are black).
const FAR_GREY: f64 = 0.15;

/// The distances from the eye the camera sees, nearest to farthest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthRange {
    /// The nearest hit distance on the grid.
    pub near: f64,
    /// The farthest hit distance on the grid.
    pub far: f64,
}

impl DepthRange {
    /// The range over a `GRID` x `GRID` lattice of the scene camera's rays; `None` when
    /// none of them hits anything.
    #[must_use]
    pub fn visible(world: &World) -> Option<Self> {
        let (width, height) = (world.camera.width.max(1), world.camera.height.max(1));
        let camera = PinholeCamera::new(&world.camera, width, height);
        let step = DVec2::new(f64::from(width), f64::from(height)) / f64::from(GRID);
        let mut range: Option<Self> = None;
        for j in 0..GRID {
            for i in 0..GRID {
                let point = (DVec2::new(f64::from(i), f64::from(j)) + 0.5) * step;
                let Some(hit) = world.intersect(&camera.ray(point), f64::INFINITY) else {
                    continue;
                };
                let r = range.get_or_insert(Self {
                    near: hit.t,
                    far: hit.t,
                });
                r.near = r.near.min(hit.t);
                r.far = r.far.max(hit.t);
            }
        }
        range
    }

    /// The grey of a hit at distance `t`: 1 at `near`, [`FAR_GREY`] at `far`, clamped
    /// outside (a small object nearer than the grid saw is white).
    #[must_use]
    pub fn grey(&self, t: f64) -> f64 {
        let span = (self.far - self.near).max(self.near.abs() * 1e-9);
        if span.is_nan() || span <= 0.0 {
            return 1.0;
        }
        let along = ((t - self.near) / span).clamp(0.0, 1.0);
        1.0 - (1.0 - FAR_GREY) * along
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::{RenderOptions, RenderProgress, View, render};

    #[test]
    fn the_visible_depths_span_the_grey_scale() {
        let scene = crate::scene::examples::default_scene();
        let world = World::new(&scene).unwrap();
        let range = DepthRange::visible(&world).expect("the default scene is in view");
        assert!(range.near > 0.0 && range.far > range.near, "{range:?}");
        let options = RenderOptions {
            width: 64,
            height: 48,
            samples_per_pixel: 1,
            view: View::Depth,
            ..RenderOptions::from_scene(&scene)
        };
        let (image, _) = render(&world, &options, &RenderProgress::default()).unwrap();
        let greys: Vec<f32> = image
            .pixels
            .iter()
            .map(|p| p.x)
            .filter(|g| *g > 0.0)
            .collect();
        let lightest = greys.iter().copied().fold(0.0_f32, f32::max);
        let darkest = greys.iter().copied().fold(1.0_f32, f32::min);
        // The old 1 / (1 + t / d) mapping spread this scene over less than half the scale.
        assert!(lightest - darkest > 0.7, "{darkest}..{lightest}");
    }

    #[test]
    fn nearest_is_white_farthest_dark_and_a_flat_range_is_white() {
        let range = DepthRange {
            near: 2.0,
            far: 10.0,
        };
        assert_eq!(range.grey(2.0), 1.0);
        assert!((range.grey(10.0) - FAR_GREY).abs() < 1e-12);
        assert_eq!(range.grey(0.5), 1.0);
        assert_eq!(
            DepthRange {
                near: 3.0,
                far: 3.0
            }
            .grey(3.0),
            1.0
        );
    }
}
