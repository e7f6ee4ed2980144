//! From the fit's start to the explanations: the search, objects the other picture
//! draws and raylab does not (found after a first search, then taken out of the fit,
//! which runs again without their pixels), the verdicts, what is left localised, and
//! whether the picture is of another scene.

use super::different_scene::different_scene;
use super::explanation::{Cause, ExplainedTerm, Explanation};
use super::localise::localise;
use super::summary::{extra_object_summary, summary};
use super::verdicts::explain_steps;
use crate::compare::catalogue::Part;
use crate::compare::extras::{ExtraObject, Palette, confirm_shadows, find_extra_objects};
use crate::compare::fit::{FitState, Floor, Groups, Target, search};
use crate::compare::split::Components;
use crate::scene::Scene;
use crate::trace::World;

/// The explanations of a comparison, and the share nothing explains.
pub struct Explained {
    /// The explanations, the largest share first (a different-scene verdict first).
    pub explanations: Vec<Explanation>,
    /// The share of the whole difference nothing explains.
    pub unexplained_share: f64,
}

/// Explains what `start` (raylab's picture against `target`) leaves, as shares of
/// `total`, keeping search steps that lower the error by at least `floor`.
#[must_use]
pub fn explain(
    components: &Components,
    scene: &Scene,
    world: &World,
    target: &Target,
    start: &FitState,
    (total, floor): (f64, Floor),
) -> Explained {
    let nodes = &components.nodes;
    let parts: Vec<_> = nodes
        .leaves
        .iter()
        .map(|leaf| Part::of_leaf(world, leaf))
        .collect();
    let groups = Groups::new(components.space, nodes, &components.tried, &parts);
    let mut state = start.clone();
    let mut steps = search(components, &groups, target, &mut state, floor);
    let palette = Palette::new(world, scene.objects.len());
    let mut extras = find_extra_objects(components, &palette, target, &state, None);
    if extras.is_empty() {
        extras = find_extra_objects(components, &palette, target, &state, Some(start));
    }
    // Their pixels out of the fit, which runs again: no factor of what lies behind them
    // bends to them. Then their shadows, against the model fitted without them (which
    // holds any second bug).
    let mut masked = None;
    if !extras.is_empty() {
        let claimed = |extras: &[ExtraObject]| -> Vec<u32> {
            extras.iter().flat_map(ExtraObject::claimed).collect()
        };
        let without = target.without(&claimed(&extras));
        let mut refit = FitState::new(start.model.clone(), &without);
        steps = search(components, &groups, &without, &mut refit, floor);
        confirm_shadows(&mut extras, components, &palette, target, &refit.model);
        let without = target.without(&claimed(&extras));
        state = FitState::new(refit.model, &without);
        masked = Some(without);
    }
    let target = masked.as_ref().unwrap_or(target);
    let mut explanations: Vec<Explanation> = extras
        .iter()
        .map(|extra| extra_verdict(extra, start, scene, total))
        .collect();
    explanations.extend(explain_steps(
        &steps, &groups, components, scene, world, total,
    ));
    let localised = localise(components, target, &state, scene, total);
    let localised_share: f64 = localised.iter().map(|e| e.share).sum();
    explanations.extend(localised);
    explanations.sort_by(|a, b| b.share.total_cmp(&a.share));
    let unexplained_share = (state.total / total - localised_share).max(0.0);
    if let Some(mut verdict) = different_scene(&explanations, unexplained_share) {
        verdict.summary = summary(&verdict, scene);
        explanations.insert(0, verdict);
    }
    Explained {
        explanations,
        unexplained_share,
    }
}

/// The verdict of one extra object: its share is its pixels' error in raylab's picture.
fn extra_verdict(extra: &ExtraObject, start: &FitState, scene: &Scene, total: f64) -> Explanation {
    let pixels = extra.claimed();
    let error: f64 = pixels.iter().map(|&p| start.error[p as usize]).sum();
    let mut e = Explanation {
        term: ExplainedTerm::Geometry,
        light: None,
        object: extra.looks_like,
        object_name: extra.looks_like.map(|o| scene.objects[o].name.clone()),
        node: extra.looks_like.map_or_else(Vec::new, |o| vec![o]),
        factor: 1.0,
        share: error / total,
        pixels,
        cause: Cause::ExtraObject(extra.shape),
        confidence: extra.edge_share,
        bbox: Some(extra.bbox),
        fits_as_well: Vec::new(),
        summary: String::new(),
    };
    e.summary = extra_object_summary(&e, extra.shape, &extra.behind, scene);
    e
}
