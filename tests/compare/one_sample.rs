//! `raylab diff` as the compare tests run it (one sample per pixel), and the answer they
//! read first.

use raylab::compare::{
    CompareOptions, Comparison, ExplainedTerm, Explanation, OtherImage, compare,
};
use raylab::scene::Scene;
use raylab::trace::RenderProgress;

/// raylab's picture of `scene` at one sample per pixel, explained against `other`.
pub fn diff(scene: &Scene, other: &OtherImage) -> Comparison {
    let options = CompareOptions {
        samples_per_pixel: Some(1),
    };
    compare(scene, other, &options, &RenderProgress::default()).unwrap()
}

/// The first explanation other than the conventions' (which, when a convention fits,
/// comes first by design), and the report's text for failure messages.
#[allow(dead_code)]
pub fn first_beyond_conventions(c: &Comparison) -> (&Explanation, String) {
    let report = c.text_lines().join("\n");
    let first = c
        .explanations
        .iter()
        .find(|e| e.term != ExplainedTerm::Conventions)
        .unwrap_or_else(|| panic!("{report}"));
    (first, report)
}
