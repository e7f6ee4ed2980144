//! `raylab diff` as the compare tests run it: one sample per pixel.

use raylab::compare::{CompareOptions, Comparison, OtherImage, compare};
use raylab::scene::Scene;
use raylab::trace::RenderProgress;

/// raylab's picture of `scene` at one sample per pixel, explained against `other`.
pub fn diff(scene: &Scene, other: &OtherImage) -> Comparison {
    let options = CompareOptions {
        samples_per_pixel: Some(1),
    };
    compare(scene, other, &options, &RenderProgress::default()).unwrap()
}
