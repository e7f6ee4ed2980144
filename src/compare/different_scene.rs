//! A picture that is not of this scene: a render committed from an older version of the
//! scene file (the camera moved, an object moved) shows up as outlines that differ on
//! several objects and shading no factor explains. Rather than a list of low-confidence
//! factors, the comparison then says first that the picture looks like another scene.

use std::collections::BTreeSet;

use super::explanation::{Cause, ExplainedTerm, Explanation};

/// At least this share of the difference must be outlines and shading no factor or bug
/// explains.
const MIN_UNEXPLAINED_BY_FACTORS: f64 = 0.5;

/// Outlines must differ on at least this many objects: one object moved, missing or
/// extra changes its own outline and that of what lies behind it (two), which is a
/// question about that object, not another scene.
const MIN_OBJECTS_MOVED: usize = 3;

/// The `different-scene` verdict for `explanations` (sorted, shares of the whole), with
/// `unexplained` the share nothing explains; `None` where the factors and known bugs
/// explain the bulk, or only one object's outline differs.
#[must_use]
pub fn different_scene(explanations: &[Explanation], unexplained: f64) -> Option<Explanation> {
    let localised = |e: &&Explanation| matches!(e.cause, Cause::Silhouette | Cause::Shading);
    let share: f64 = explanations.iter().filter(localised).map(|e| e.share).sum();
    let moved: BTreeSet<usize> = explanations
        .iter()
        .filter(|e| e.cause == Cause::Silhouette)
        .filter_map(|e| e.object)
        .collect();
    if share + unexplained < MIN_UNEXPLAINED_BY_FACTORS || moved.len() < MIN_OBJECTS_MOVED {
        return None;
    }
    let pixels: BTreeSet<u32> = explanations
        .iter()
        .filter(localised)
        .flat_map(|e| e.pixels.iter().copied())
        .collect();
    Some(Explanation {
        term: ExplainedTerm::Scene,
        light: None,
        object: None,
        object_name: None,
        factor: 1.0,
        share: share + unexplained,
        pixels: pixels.into_iter().collect(),
        cause: Cause::DifferentScene {
            objects: u32::try_from(moved.len()).unwrap_or(u32::MAX),
        },
        confidence: (share + unexplained).min(1.0),
        summary: String::new(),
    })
}
