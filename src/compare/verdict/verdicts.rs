//! From the search's steps to explanations: each step's group read as a term, light and
//! node (a group over every object whose change lies on one node names the deepest such
//! node: an object, or a part of its tree), steps that say the same merged, and each
//! given its confidence:
//!
//! ```text
//! confidence = margin * (1 - |1 - weight|)   for bugs and missing parts
//! confidence = margin                        for term factors
//! ```
//!
//! where `margin` is how much better the step explains the difference than its best
//! competitor ([`crate::compare::fit::Step::margin`]: 1 when nothing else explains those
//! pixels, 0 when a competitor explains them as well).

use super::explanation::{Cause, ExplainedTerm, Explanation};
use super::summary::summary;
use crate::compare::catalogue::Family;
use crate::compare::catalogue::Part;
use crate::compare::extras::PixelBox;
use crate::compare::fit::Step;
use crate::compare::fit::{Group, Groups};
use crate::compare::split::Components;
use crate::scene::Scene;
use crate::trace::{Term, World};

/// The share of a change on one node above which the node is named.
const NAMED: f64 = 0.995;

/// Where raylab draws node `node` among `pixels` (its first hits there; where it is
/// only seen in mirrors, all of them).
fn drawn_box(components: &Components, node: usize, pixels: &[u32]) -> Option<PixelBox> {
    let leaves = &components.nodes.nodes[node].leaves;
    let own: Vec<u32> = pixels
        .iter()
        .copied()
        .filter(|&p| leaves.contains(&(components.labels[p as usize] as usize)))
        .collect();
    PixelBox::of(if own.is_empty() { pixels } else { &own }, components.width)
}

/// The term and cause a family stands for; `split` tells a normal bug's diffuse from
/// its specular share.
fn term_and_cause(family: Family, split: [f64; 2], part: Option<Part>) -> (ExplainedTerm, Cause) {
    match family {
        Family::Ambient => (ExplainedTerm::Term(Term::Ambient), Cause::Factor),
        Family::Reflection => (ExplainedTerm::Term(Term::Reflection), Cause::Factor),
        Family::Transmission => (ExplainedTerm::Term(Term::Transmission), Cause::Factor),
        Family::Diffuse => (ExplainedTerm::Term(Term::Diffuse), Cause::Factor),
        Family::Specular => (ExplainedTerm::Term(Term::Specular), Cause::Factor),
        Family::Shadow => (ExplainedTerm::Term(Term::Shadows), Cause::Factor),
        Family::Background => (ExplainedTerm::Background, Cause::Factor),
        Family::Normal(bug) => {
            let term = if split[1] > split[0] {
                ExplainedTerm::Term(Term::Specular)
            } else {
                ExplainedTerm::Term(Term::Diffuse)
            };
            (term, Cause::Normal(bug))
        }
        Family::Highlight(bug) => (ExplainedTerm::Term(Term::Specular), Cause::Highlight(bug)),
        Family::Clamp(bug) => (ExplainedTerm::Term(Term::Reflection), Cause::Clamp(bug)),
        Family::ShadowTest(bug) => (ExplainedTerm::Term(Term::Shadows), Cause::ShadowTest(bug)),
        Family::Spawn(bug) => (ExplainedTerm::Term(Term::Reflection), Cause::Spawn(bug)),
        Family::Missing => (ExplainedTerm::Geometry, Cause::Missing(part)),
        Family::Spot(bug) => (ExplainedTerm::Term(Term::Diffuse), Cause::Spot(bug)),
    }
}

/// The explanations of the search's steps, merged, with `total` the error they are
/// shares of.
#[must_use]
pub fn explain_steps(
    steps: &[Step],
    groups: &Groups,
    components: &Components,
    scene: &Scene,
    world: &World,
    total: f64,
) -> Vec<Explanation> {
    let mut out: Vec<(Explanation, f64, Option<usize>)> = Vec::new();
    for step in steps {
        let group = &groups.list[step.group];
        let (term, cause) = term_and_cause(group.family, split_of(group, components), group.part);
        // Lights are named only by the group: every light is every light, even where
        // one of them dominates.
        let light = group.light.map(|l| world.light_scene_index[l]);
        let node = group
            .object
            .or_else(|| components.nodes.concentrated(&step.energy_by_object, NAMED));
        let is_bug = !matches!(cause, Cause::Factor);
        let confidence = if is_bug {
            step.margin * (1.0 - (1.0 - step.coefficient).abs()).max(0.0)
        } else {
            step.margin
        };
        let readings: Vec<String> = step
            .alike
            .iter()
            .map(|&g| reading(&groups.list[g], components, world))
            .collect();
        let path = node.map(|n| components.nodes.nodes[n].path.as_slice());
        let found = out.iter_mut().find(|(e, ..)| {
            e.term == term
                && e.cause == cause
                && e.light == light
                && Some(e.node.as_slice()).filter(|p| !p.is_empty()) == path
        });
        match found {
            Some((e, coefficient, _)) => {
                e.fits_as_well.extend(readings);
                *coefficient += step.coefficient;
                let weight = e.share + step.gain / total;
                e.confidence = (e.confidence * e.share + confidence * step.gain / total) / weight;
                e.share = weight;
                e.pixels.extend(&step.pixels);
                e.pixels.sort_unstable();
                e.pixels.dedup();
            }
            None => {
                let mut e = Explanation {
                    term,
                    light,
                    object: None,
                    object_name: None,
                    node: Vec::new(),
                    factor: 1.0,
                    share: step.gain / total,
                    pixels: step.pixels.clone(),
                    cause,
                    confidence,
                    bbox: None,
                    fits_as_well: readings,
                    summary: String::new(),
                };
                e.name_node(&components.nodes, node);
                out.push((e, step.coefficient, node));
            }
        }
    }
    merge_missing_lights(&mut out);
    out.into_iter()
        .map(|(mut e, coefficient, node)| {
            // Terms scale from 1; shadows and bugs add a picture whose weight is 1 - factor.
            let factor = if e.cause == Cause::Factor && e.term != ExplainedTerm::Term(Term::Shadows)
            {
                1.0 + coefficient
            } else {
                1.0 - coefficient
            };
            // Rounding noise around 0 reads as "-0.00" otherwise.
            e.factor = if factor.abs() < 1e-6 { 0.0 } else { factor };
            if let (Cause::Missing(Some(Part::Whole) | None), Some(node)) = (e.cause, node) {
                e.bbox = drawn_box(components, node, &e.pixels);
            }
            e.fits_as_well.sort();
            e.fits_as_well.dedup();
            e.summary = summary(&e, scene);
            if !e.fits_as_well.is_empty() {
                let list = e.fits_as_well.join("; ");
                e.summary.push_str(&format!(" Fits as well: {list}."));
            }
            e
        })
        .collect()
}

/// A factor below this is a term missing.
const MISSING: f64 = 0.05;

/// A light whose diffuse and specular terms are both missing, on the same objects or on
/// some of them (the highlights show on fewer), is one finding: the light is missing (a
/// loop that skips it). The specular line joins the diffuse one, which becomes the
/// light's.
fn merge_missing_lights(out: &mut Vec<(Explanation, f64, Option<usize>)>) {
    let missing = |(e, coefficient, _): &(Explanation, f64, Option<usize>), term| {
        e.cause == Cause::Factor
            && e.term == ExplainedTerm::Term(term)
            && e.light.is_some()
            && 1.0 + coefficient < MISSING
    };
    let mut i = 0;
    while i < out.len() {
        if missing(&out[i], Term::Diffuse) {
            let diffuse = &out[i].0;
            let specular = (0..out.len()).find(|&j| {
                let e = &out[j].0;
                missing(&out[j], Term::Specular)
                    && e.light == diffuse.light
                    && e.node.starts_with(&diffuse.node)
            });
            if let Some(j) = specular {
                let (s, ..) = out.remove(j);
                if j < i {
                    i -= 1;
                }
                let d = &mut out[i].0;
                let share = d.share + s.share;
                d.confidence = (d.confidence * d.share + s.confidence * s.share) / share;
                d.share = share;
                d.pixels.extend(s.pixels);
                d.pixels.sort_unstable();
                d.pixels.dedup();
                d.fits_as_well.extend(s.fits_as_well);
                // Its own two terms are the light now, not other readings.
                if let Some(l) = d.light {
                    let own = [Term::Diffuse, Term::Specular]
                        .map(|t| format!("the {} term of light {l}", t.name()));
                    d.fits_as_well.retain(|r| !own.contains(r));
                }
                d.term = ExplainedTerm::Light;
            }
        }
        i += 1;
    }
}

/// The diffuse and specular shares of a group's normal-bug channels.
fn split_of(group: &Group, components: &Components) -> [f64; 2] {
    group.members.iter().fold([0.0; 2], |acc, &m| {
        let s = components.split[m as usize];
        [acc[0] + s[0], acc[1] + s[1]]
    })
}

/// A group read as a short phrase ("the diffuse term of every light", "the ambient
/// term on 'floor'", "the normal-without-z bug on 'die/pip 1.1'"), for what fits as well.
fn reading(group: &Group, components: &Components, world: &World) -> String {
    let (term, cause) = term_and_cause(group.family, split_of(group, components), group.part);
    let what = match cause {
        Cause::Factor => format!("the {} term", term.name()),
        Cause::Missing(_) => cause.name().to_owned(),
        other => format!("the {} bug", other.name()),
    };
    let per_light = matches!(
        group.family,
        Family::Diffuse | Family::Specular | Family::Shadow
    );
    let light = match group.light {
        Some(l) => format!(" of light {}", world.light_scene_index[l]),
        None if per_light => " of every light".to_owned(),
        None => String::new(),
    };
    let object = group.object.map_or_else(String::new, |n| {
        format!(" on '{}'", components.nodes.nodes[n].name)
    });
    format!("{what}{light}{object}")
}
