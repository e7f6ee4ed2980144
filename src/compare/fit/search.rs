//! The fit: a greedy search over the groups. Each round fits every group's one number to
//! what is left of the difference (least squares: `c = <r, g> / <g, g>`, which lowers
//! the squared residual by `<r, g>^2 / <g, g>`), takes the group that explains the most,
//! and keeps it if it really lowers the error (the interval error, not the linear one:
//! clipping and rounding count). Bugs and missing parts must fit with a weight near 1
//! (the bug is there or not); term factors may take any value >= 0.
//!
//! The groups that compete with each step ([`super::rivals`]) say how sure it is, what
//! fits as well, and which of two that fit the same goes first.

use rayon::prelude::*;

use super::groups::{Group, Groups};
use super::rivals::{alike, margin, prefer_specific};
use super::target::{FitState, Target};
use crate::compare::catalogue::{Family, Kind};
use crate::compare::split::Components;

/// A step must lower the error by at least this share of the whole difference...
pub const MIN_STEP_SHARE: f64 = 0.005;

/// ...and by at least this much: four channels a full 8-bit level outside their bytes.
/// A difference smaller than this is no difference.
pub const MIN_ERROR: f64 = 4.0 / (255.0 * 255.0);

/// A step smaller than the share floor is kept when it leaves at most this share of the
/// error it found on the pixels it changes: a bug that acts on a few pixels (acne on
/// one object, a dim light's term) and makes them right is named whatever else the
/// picture holds.
const EXACT_LEFT: f64 = 0.1;

/// What a step must remove to be kept.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Floor {
    /// Any step: a share of the whole difference (and at least [`MIN_ERROR`] and the
    /// sampling's noise).
    pub any: f64,
    /// A step that makes its own pixels right ([`EXACT_LEFT`]): [`MIN_ERROR`] and the
    /// sampling's noise only.
    pub exact: f64,
}

/// Rounds of the search at most.
pub const MAX_STEPS: usize = 16;

/// Groups tried in one round before the search gives up.
const TRIES_PER_ROUND: usize = 4;

/// The range a bug's weight must fit in to count as that bug.
const BUG_WEIGHT: (f64, f64) = (0.5, 1.5);

/// One accepted change.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// Index of the group in [`Groups::list`].
    pub group: usize,
    /// What was added to the group's scale (factor - 1 for a term; the weight of the
    /// light that shadows took away; the weight of a bug's or a missing part's picture).
    pub coefficient: f64,
    /// How much the interval error fell.
    pub gain: f64,
    /// How much better this step explains the difference than its best competitor, 0
    /// to 1 (see [`margin`]).
    pub margin: f64,
    /// Pixels the change moved by at least half an 8-bit level.
    pub pixels: Vec<u32>,
    /// Squared size of the change on each leaf (an inner node's own channels count
    /// on none).
    pub energy_by_object: Vec<f64>,
    /// Squared size of the change from each light (per-light families).
    pub energy_by_light: Vec<f64>,
    /// Other groups that fit alike (their gain within [`ALIKE`] of this one's, and taken
    /// by it): another reading of the same pixels, more general or another story.
    pub alike: Vec<usize>,
}

/// Whether the family scales raylab's terms (any factor >= 0) rather than adding a bug.
fn is_term(family: Family) -> bool {
    matches!(
        family,
        Family::Ambient
            | Family::Reflection
            | Family::Transmission
            | Family::Diffuse
            | Family::Specular
            | Family::Background
    )
}

/// The lowest and highest current scale of a group's channels.
fn scale_range(group: &Group, scale: &[f64]) -> (f64, f64) {
    group
        .members
        .iter()
        .map(|&c| scale[c as usize])
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| {
            (lo.min(s), hi.max(s))
        })
}

/// The fitted coefficient of a group and its linear gain, or `None` if it may not move.
fn fit(group: &Group, correlation: f64, norm: f64, scale: &[f64]) -> Option<(f64, f64)> {
    if norm <= 0.0 {
        return None;
    }
    let free = correlation / norm;
    let (lowest, highest) = scale_range(group, scale);
    let (lo, hi) = if is_term(group.family) {
        (-lowest, f64::INFINITY) // a factor stays >= 0
    } else if group.family == Family::Shadow {
        (-lowest, 1.0 - highest) // shadows take away between none and all of a light
    } else {
        if highest == 0.0 && !(BUG_WEIGHT.0..=BUG_WEIGHT.1).contains(&free) {
            return None; // a bug that fits with a weight far from 1 is not that bug
        }
        (-lowest, BUG_WEIGHT.1 - highest)
    };
    let c = free.clamp(lo, hi);
    let gain = 2.0 * c * correlation - c * c * norm;
    // A bug is there or not: it is ranked by what it explains at weight 1.
    let rank_gain = if !is_term(group.family) && group.family != Family::Shadow && highest == 0.0 {
        2.0 * correlation - norm
    } else {
        gain
    };
    (c != 0.0 && rank_gain > 0.0).then_some((c, rank_gain))
}

/// A channel's scale in raylab's own picture: 1 for its terms, 0 for the changes.
fn initial_scale(kind: Kind) -> f64 {
    if kind.is_partition() || kind == Kind::Reflection || kind == Kind::Transmission {
        1.0
    } else {
        0.0
    }
}

/// The change a group with coefficient `c` makes, pixel by pixel.
struct Change {
    pixels: Vec<(usize, [f64; 3])>,
    energy_by_object: Vec<f64>,
    energy_by_light: Vec<f64>,
}

fn change_of(components: &Components, group: &Group, c: f64) -> Change {
    let space = components.space;
    let mut member = vec![false; space.count()];
    for &m in &group.members {
        member[m as usize] = true;
    }
    let pixels = components.labels.len();
    let chunk = 8192;
    let parts: Vec<Change> = (0..pixels.div_ceil(chunk))
        .into_par_iter()
        .map(|k| {
            let mut out = Change {
                pixels: Vec::new(),
                energy_by_object: vec![0.0; space.objects],
                energy_by_light: vec![0.0; space.lights],
            };
            for p in k * chunk..((k + 1) * chunk).min(pixels) {
                let mut sum = [0.0f64; 3];
                for entry in components.pixel(p) {
                    if !member[entry.channel as usize] {
                        continue;
                    }
                    let v = entry.value.map(|x| c * f64::from(x));
                    let energy = v.iter().map(|x| x * x).sum::<f64>();
                    let (kind, object) = space.decode(entry.channel);
                    if let Some(o) = object.filter(|_| !kind.is_of_node()) {
                        out.energy_by_object[o] += energy;
                    }
                    if let Some(l) = kind.light() {
                        out.energy_by_light[l] += energy;
                    }
                    (0..3).for_each(|i| sum[i] += v[i]);
                }
                if sum != [0.0; 3] {
                    out.pixels.push((p, sum));
                }
            }
            out
        })
        .collect();
    let mut all = Change {
        pixels: Vec::new(),
        energy_by_object: vec![0.0; space.objects],
        energy_by_light: vec![0.0; space.lights],
    };
    for part in parts {
        all.pixels.extend(part.pixels);
        all.energy_by_object
            .iter_mut()
            .zip(part.energy_by_object)
            .for_each(|(a, b)| *a += b);
        all.energy_by_light
            .iter_mut()
            .zip(part.energy_by_light)
            .for_each(|(a, b)| *a += b);
    }
    all
}

/// The groups' fitted coefficients and ranking gains on the current residual, best first.
fn rank(
    groups: &Groups,
    correlations: &[f64],
    norms: &[f64],
    scale: &[f64],
) -> Vec<(usize, f64, f64)> {
    let mut ranked: Vec<(usize, f64, f64)> = groups
        .list
        .iter()
        .enumerate()
        .filter_map(|(i, g)| fit(g, correlations[i], norms[i], scale).map(|(c, gain)| (i, c, gain)))
        .collect();
    ranked.sort_by(|a, b| b.2.total_cmp(&a.2));
    prefer_specific(groups, &mut ranked);
    ranked
}

/// Whether a step that lowered the error by `gain`, leaving `left` of the `found` error
/// on its pixels, is kept.
fn kept(gain: f64, found: f64, left: f64, floor: Floor) -> bool {
    gain >= floor.any || (gain >= floor.exact && left <= EXACT_LEFT * found)
}

/// Applies `group` at `c` to `state` and keeps it if [`kept`]; else undoes it.
fn try_step(
    components: &Components,
    group: &Group,
    c: f64,
    target: &Target,
    state: &mut FitState,
    floor: Floor,
) -> Option<(f64, Change)> {
    let change = change_of(components, group, c);
    let before = state.total;
    let found: f64 = change.pixels.iter().map(|&(p, _)| state.error[p]).sum();
    for &(p, d) in &change.pixels {
        state.add(target, p, d);
    }
    let gain = before - state.total;
    let left: f64 = change.pixels.iter().map(|&(p, _)| state.error[p]).sum();
    if kept(gain, found, left, floor) {
        return Some((gain, change));
    }
    for &(p, d) in &change.pixels {
        state.add(target, p, d.map(|x| -x));
    }
    None
}

/// Where the other picture clips (255: only a lower bound), the linear fit gives a
/// channel no weight, so a bug that makes the picture clip (a spot without its fall-off
/// whitening a floor) correlates with nothing. When the ranked groups all fail, the spot
/// light bugs not yet taken are ranked by how far they push raylab's picture up into the other's
/// clipped channels, and the first few tried at weight 1 on the interval error, which
/// knows a clipped channel is right anywhere above its bound.
fn try_clipped(
    components: &Components,
    groups: &Groups,
    target: &Target,
    state: &mut FitState,
    scale: &[f64],
    floor: Floor,
) -> Option<(usize, f64, f64, Change)> {
    let mut push = vec![0.0f64; components.space.count()];
    let mut any = false;
    for (p, intervals) in target.intervals.iter().enumerate() {
        for (k, &(lo, hi)) in intervals.iter().enumerate() {
            let below = lo - state.model[p][k];
            if hi.is_infinite() && lo.is_finite() && below > 0.0 {
                any = true;
                for entry in components.pixel(p) {
                    push[entry.channel as usize] += below * f64::from(entry.value[k]).max(0.0);
                }
            }
        }
    }
    if !any {
        return None;
    }
    let mut ranked: Vec<(usize, f64)> = groups
        .list
        .iter()
        .enumerate()
        // A light that reaches further or stronger than raylab's: a spot's cone or
        // fall-off bugs (a missing part is no reason for a picture to clip).
        .filter(|(_, g)| matches!(g.family, Family::Spot(_)))
        .filter(|(_, g)| scale_range(g, scale).1 == 0.0)
        .map(|(i, g)| (i, g.members.iter().map(|&m| push[m as usize]).sum::<f64>()))
        .filter(|&(_, push)| push > 0.0)
        .collect();
    ranked.sort_by(|a, b| b.1.total_cmp(&a.1));
    ranked.iter().take(TRIES_PER_ROUND).find_map(|&(index, _)| {
        try_step(components, &groups.list[index], 1.0, target, state, floor)
            .map(|(gain, change)| (index, 1.0, gain, change))
    })
}

/// Runs the search on `state` (changed in place), keeping steps that lower the error by
/// at least `floor.any`, or by `floor.exact` where they make their pixels right.
#[must_use]
pub fn search(
    components: &Components,
    groups: &Groups,
    target: &Target,
    state: &mut FitState,
    floor: Floor,
) -> Vec<Step> {
    let norms = groups.norms(components, target);
    // Each channel's scale so far: 1 for raylab's terms, 0 for the bugs and shadows.
    let mut scale: Vec<f64> = (0..components.space.count() as u32)
        .map(|c| initial_scale(components.space.decode(c).0))
        .collect();
    let mut steps = Vec::new();
    let mut correlations = groups.correlations(components, target, state);
    while steps.len() < MAX_STEPS && state.total > floor.exact {
        let ranked = rank(groups, &correlations, &norms, &scale);
        let mut accepted = None;
        for &(index, c, _) in ranked.iter().take(TRIES_PER_ROUND) {
            if let Some((gain, change)) =
                try_step(components, &groups.list[index], c, target, state, floor)
            {
                accepted = Some((index, c, gain, change));
                break;
            }
        }
        if accepted.is_none() {
            accepted = try_clipped(components, groups, target, state, &scale, floor);
        }
        let Some((index, c, gain, change)) = accepted else {
            break;
        };
        for &m in &groups.list[index].members {
            scale[m as usize] += c;
        }
        correlations = groups.correlations(components, target, state);
        let after = rank(groups, &correlations, &norms, &scale);
        let left: f64 = change.pixels.iter().map(|&(p, _)| state.error[p]).sum();
        let half_level = 0.5 / 255.0;
        steps.push(Step {
            group: index,
            coefficient: c,
            gain,
            margin: margin(groups, index, &ranked, &after, left),
            alike: alike(groups, index, &ranked, &after),
            pixels: change
                .pixels
                .iter()
                .filter(|(_, d)| d.iter().any(|x| x.abs() >= half_level))
                .map(|&(p, _)| p as u32)
                .collect(),
            energy_by_object: change.energy_by_object,
            energy_by_light: change.energy_by_light,
        });
    }
    steps
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compare::catalogue::NormalBug;

    fn group(family: Family) -> Group {
        Group::of_one_channel(family)
    }

    #[test]
    fn factors_stay_non_negative_and_bugs_must_fit_near_weight_one() {
        // A term asked to go to -1 (factor 0 - 1) stops at factor 0.
        let (c, _) = fit(&group(Family::Diffuse), -3.0, 1.0, &[1.0]).unwrap();
        assert_eq!(c, -1.0);
        // A bug whose picture fits at weight 0.2 is not that bug; at 0.9 it is, and it
        // is ranked by what it explains at weight 1: 2 * 0.9 - 1.
        let bug = group(Family::Normal(NormalBug::DropZ));
        assert!(fit(&bug, 0.2, 1.0, &[0.0]).is_none());
        let (c, rank) = fit(&bug, 0.9, 1.0, &[0.0]).unwrap();
        assert!((c - 0.9).abs() < 1e-12 && (rank - 0.8).abs() < 1e-12);
        // Shadows take away between none and all of a light.
        let (c, _) = fit(&group(Family::Shadow), 5.0, 1.0, &[0.0]).unwrap();
        assert_eq!(c, 1.0);
    }
}
