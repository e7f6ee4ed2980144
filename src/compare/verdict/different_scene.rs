//! A picture that is not of this scene: a render committed from an older version of the
//! scene file (the camera moved, an object moved) shows up as outlines that differ on
//! several objects and shading no factor explains. Rather than a list of low-confidence
//! factors, the comparison then says first that the picture looks like another scene.

use std::collections::BTreeSet;

use super::explanation::{Cause, ExplainedTerm, Explanation};

/// At least this share of the difference must be outlines and shading no factor or bug
/// explains.
const MIN_UNEXPLAINED_BY_FACTORS: f64 = 0.5;

/// Outlines must differ on at least this many objects (raylab's, or ones the other
/// picture draws where raylab has none): one object moved, missing or extra changes
/// its own outline and that of what lies behind it (two), which is a question about
/// that object, not another scene.
const MIN_OBJECTS_MOVED: usize = 3;

/// The `different-scene` verdict for `explanations` (sorted, shares of the whole), with
/// `unexplained` the share nothing explains; `None` where the factors and known bugs
/// explain the bulk, or only one object's outline differs.
#[must_use]
pub fn different_scene(explanations: &[Explanation], unexplained: f64) -> Option<Explanation> {
    let localised = |e: &&Explanation| {
        matches!(
            e.cause,
            Cause::Silhouette | Cause::Shading | Cause::ExtraObject(_)
        )
    };
    let share: f64 = explanations.iter().filter(localised).map(|e| e.share).sum();
    // Outlines that differ: raylab's objects' (moved, or missing), and each object the
    // other picture draws where raylab has none.
    // An extra object that looks like one of raylab's counts as that object's.
    let moved: BTreeSet<usize> = explanations
        .iter()
        .filter(|e| {
            matches!(
                e.cause,
                Cause::Silhouette | Cause::Missing(_) | Cause::ExtraObject(_)
            )
        })
        .filter_map(|e| e.object)
        .collect();
    let extra = explanations
        .iter()
        .filter(|e| matches!(e.cause, Cause::ExtraObject(_)) && e.object.is_none())
        .count();
    let outlines = moved.len() + extra;
    if share + unexplained < MIN_UNEXPLAINED_BY_FACTORS || outlines < MIN_OBJECTS_MOVED {
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
        node: Vec::new(),
        factor: 1.0,
        share: share + unexplained,
        pixels: pixels.into_iter().collect(),
        bbox: None,
        fits_as_well: Vec::new(),
        cause: Cause::DifferentScene {
            objects: u32::try_from(outlines).unwrap_or(u32::MAX),
        },
        confidence: (share + unexplained).min(1.0),
        summary: String::new(),
    })
}
