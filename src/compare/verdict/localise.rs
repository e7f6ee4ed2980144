//! What no factor or known bug explains, localised. After the search, pixels still off
//! by more than [`OFF_LEVELS`] levels are sorted into two verdicts:
//!
//! - near an outline in raylab's object-id view (within [`OUTLINE_REACH`] pixels), where
//!   the other picture shows another surface than raylab's there (its colour is what
//!   the fitted model shows on another object or the background nearby, and not what
//!   it shows on the pixel's own object): *geometry*, a silhouette that moved, grew or
//!   shrank. Lighting that differs at an edge is no evidence of that;
//! - inside an object (or at its edge without that evidence): *shading* that varies
//!   across it, labelled with the term whose picture the left-over difference follows
//!   most (its magnitude-weighted overlap).

use super::explanation::{Cause, ExplainedTerm, Explanation};
use super::summary::summary;
use crate::compare::catalogue::Kind;
use crate::compare::catalogue::MISS;
use crate::compare::fit::{FitState, NOISE_SHARE, OFF_LEVELS, Target};
use crate::compare::split::Components;
use crate::scene::Scene;
use crate::trace::Term;

/// Pixels this close to an outline count as geometry.
pub const OUTLINE_REACH: i64 = 2;

/// How far around an outline pixel to look for the surface the other picture shows.
const LOOK: i64 = 3;

/// The other picture shows a neighbour's surface where its colour is within this many
/// 8-bit levels of the model's there (in every channel)...
const LOOKS_LIKE_LEVELS: f64 = 6.0;

/// ...and at most this fraction of its distance from the pixel's own surface nearby.
const CLEARLY_NEARER: f64 = 0.5;

/// A localised verdict must explain at least this share to be reported.
pub const MIN_SHARE: f64 = 0.02;

/// Confidence of a silhouette verdict: the outline is certain, the cause is not.
const SILHOUETTE_CONFIDENCE: f64 = 0.5;

/// Confidence of a shading verdict: it says where, not which bug.
const SHADING_CONFIDENCE: f64 = 0.35;

/// Whether each pixel lies within [`OUTLINE_REACH`] of a change of label.
fn near_outline(components: &Components) -> Vec<bool> {
    let (w, h) = (i64::from(components.width), i64::from(components.height));
    // Outlines of objects, as raylab's object-id view shows them.
    let edge = components.outline();
    let mut near = vec![false; edge.len()];
    for y in 0..h {
        for x in 0..w {
            near[(y * w + x) as usize] = (-OUTLINE_REACH..=OUTLINE_REACH).any(|dy| {
                (-OUTLINE_REACH..=OUTLINE_REACH).any(|dx| {
                    let (nx, ny) = (x + dx, y + dy);
                    nx >= 0 && ny >= 0 && nx < w && ny < h && edge[(ny * w + nx) as usize]
                })
            });
        }
    }
    near
}

/// The leaf a pixel near an outline belongs to: its own, or the nearest neighbour's.
fn outline_leaf(components: &Components, p: usize) -> Option<usize> {
    if components.labels[p] != MISS {
        return Some(components.labels[p] as usize);
    }
    let w = i64::from(components.width);
    let (x, y) = (p as i64 % w, p as i64 / w);
    for reach in 1..=OUTLINE_REACH + 1 {
        for dy in -reach..=reach {
            for dx in -reach..=reach {
                let (nx, ny) = (x + dx, y + dy);
                if nx >= 0 && ny >= 0 && nx < w && ny < i64::from(components.height) {
                    let label = components.labels[(ny * w + nx) as usize];
                    if label != MISS {
                        return Some(label as usize);
                    }
                }
            }
        }
    }
    None
}

/// Whether the other picture at `p` shows another surface than raylab's there. Either
/// its colour is, within [`LOOK`] pixels, what the fitted model shows on another object
/// (or the background), and clearly not what the model shows on `p`'s own object nor
/// what the other picture shows on it where the two pictures agree; or the other
/// picture itself is smooth from `p` into another object's pixels and has an edge
/// towards `p`'s own (its outline is elsewhere). Where the other picture is clipped
/// white, nothing tells.
fn object_differs(components: &Components, target: &Target, state: &FitState, p: usize) -> bool {
    let w = i64::from(components.width);
    let (x, y) = (p as i64 % w, p as i64 / w);
    let off = (OFF_LEVELS / 255.0).powi(2);
    let theirs = target.middle[p];
    // Channels the other picture clipped say nothing of the surface: white is white.
    let seen = target.weight[p];
    if seen == [0.0; 3] {
        return false;
    }
    let levels = |colour: [f64; 3]| {
        (0..3)
            .filter(|&c| seen[c] > 0.0)
            .map(|c| (theirs[c] - colour[c].clamp(0.0, 1.0)).abs())
            .fold(0.0, f64::max)
            * 255.0
    };
    let own = components.object_label(p);
    // Nearest colours on p's own object and on others: the model's, the other
    // picture's, and the other picture's where it agrees with the model.
    let (mut model_own, mut model_other) = (levels(state.model[p]), f64::INFINITY);
    let (mut other_own, mut other_other) = (f64::INFINITY, f64::INFINITY);
    let mut agreeing_own = f64::INFINITY;
    for ny in (y - LOOK).max(0)..=(y + LOOK).min(i64::from(components.height) - 1) {
        for nx in (x - LOOK).max(0)..=(x + LOOK).min(w - 1) {
            let q = (ny * w + nx) as usize;
            // A pixel whose samples saw two surfaces is neither side's.
            if components.mixed[q] || q == p {
                continue;
            }
            let (by_model, by_other) = (levels(state.model[q]), levels(target.middle[q]));
            if components.object_label(q) == own {
                model_own = model_own.min(by_model);
                other_own = other_own.min(by_other);
                if state.error[q] < off {
                    agreeing_own = agreeing_own.min(by_other);
                }
            } else {
                model_other = model_other.min(by_model);
                other_other = other_other.min(by_other);
            }
        }
    }
    let nearer = |to_other: f64, to_own: f64| {
        to_other <= LOOKS_LIKE_LEVELS && to_other <= CLEARLY_NEARER * to_own
    };
    nearer(model_other, model_own.min(agreeing_own)) || nearer(other_other, other_own)
}

/// The term whose picture a pixel's left-over difference overlaps, weighted.
fn term_weights(components: &Components, p: usize, size: f64, weights: &mut [f64; 5]) {
    for entry in components.pixel(p) {
        let slot = match components.space.decode(entry.channel).0 {
            Kind::Ambient => 0,
            Kind::Diffuse(_) => 1,
            Kind::Specular(_) => 2,
            Kind::Reflection => 3,
            Kind::Transmission => 4,
            _ => continue,
        };
        let v = entry.value.map(f64::from);
        weights[slot] += size * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    }
}

/// One object's left-over pixels of one kind.
#[derive(Default)]
struct Pile {
    error: f64,
    /// The part of `error` on edges, where sampling alone makes differences.
    edge_error: f64,
    pixels: Vec<u32>,
    terms: [f64; 5],
    /// The first and last leaf seen among them: the node holding both is named.
    leaves: Option<(usize, usize)>,
}

impl Pile {
    /// This pile, or none when it lies mostly on edges: then it joins `sampled`.
    fn unless_sampled(self, sampled: &mut Pile) -> Option<Pile> {
        if self.error == 0.0 || self.edge_error < NOISE_SHARE * self.error {
            return Some(self);
        }
        sampled.error += self.error;
        sampled.edge_error += self.edge_error;
        sampled.pixels.extend(self.pixels);
        None
    }

    fn add(&mut self, p: usize, error: f64, edge: f64, leaf: Option<usize>) {
        self.error += error;
        self.edge_error += error * edge;
        self.pixels.push(p as u32);
        if let Some(leaf) = leaf {
            self.leaves = Some(
                self.leaves
                    .map_or((leaf, leaf), |(a, b)| (a.min(leaf), b.max(leaf))),
            );
        }
    }
}

/// The localised verdicts for what `state` leaves unexplained of `target`, as shares
/// of `total`.
#[must_use]
pub fn localise(
    components: &Components,
    target: &Target,
    state: &FitState,
    scene: &Scene,
    total: f64,
) -> Vec<Explanation> {
    let off = (OFF_LEVELS / 255.0).powi(2);
    let near = near_outline(components);
    let objects = scene.objects.len();
    let mut outline: Vec<Pile> = (0..=objects).map(|_| Pile::default()).collect();
    let mut inside: Vec<Pile> = (0..objects).map(|_| Pile::default()).collect();
    for (p, &error) in state.error.iter().enumerate() {
        if error < off {
            continue;
        }
        if near[p] && object_differs(components, target, state, p) {
            let leaf = outline_leaf(components, p);
            let object = leaf.map_or(objects, |l| components.nodes.object_of_leaf(l));
            outline[object].add(p, error, target.edge[p], leaf);
        } else if components.labels[p] != MISS {
            let leaf = components.labels[p] as usize;
            let pile = &mut inside[components.nodes.object_of_leaf(leaf)];
            term_weights(components, p, error.sqrt(), &mut pile.terms);
            pile.add(p, error, target.edge[p], Some(leaf));
        }
    }
    let mut out = Vec::new();
    let nodes = &components.nodes;
    // Piles that lie mostly on edges are another renderer's sampling, gathered in one.
    let mut sampled = Pile::default();
    let (outline, inside): (Vec<Pile>, Vec<Pile>) = (
        outline
            .into_iter()
            .filter_map(|p| p.unless_sampled(&mut sampled))
            .collect(),
        inside
            .into_iter()
            .filter_map(|p| p.unless_sampled(&mut sampled))
            .collect(),
    );
    let mut emit = |pile: Pile, term: ExplainedTerm, cause: Cause, confidence| {
        if pile.error / total < MIN_SHARE {
            return;
        }
        let mut e = Explanation {
            term,
            light: None,
            object: None,
            object_name: None,
            node: Vec::new(),
            factor: 1.0,
            share: pile.error / total,
            pixels: pile.pixels,
            cause,
            confidence,
            bbox: None,
            fits_as_well: Vec::new(),
            summary: String::new(),
        };
        // The deepest node holding every leaf the pixels show: an object, or one part.
        let node = pile.leaves.and_then(|(a, b)| nodes.holding(a..b + 1));
        e.name_node(nodes, node);
        e.summary = summary(&e, scene);
        out.push(e);
    };
    for pile in outline {
        emit(
            pile,
            ExplainedTerm::Geometry,
            Cause::Silhouette,
            SILHOUETTE_CONFIDENCE,
        );
    }
    for pile in inside {
        let terms = pile.terms;
        let best = (0..5)
            .max_by(|&a, &b| terms[a].total_cmp(&terms[b]))
            .unwrap_or(1);
        let term = [
            ExplainedTerm::Term(Term::Ambient),
            ExplainedTerm::Term(Term::Diffuse),
            ExplainedTerm::Term(Term::Specular),
            ExplainedTerm::Term(Term::Reflection),
            ExplainedTerm::Term(Term::Transmission),
        ][best];
        emit(pile, term, Cause::Shading, SHADING_CONFIDENCE);
    }
    sampled.pixels.sort_unstable();
    let confidence = sampled.edge_error / sampled.error.max(f64::MIN_POSITIVE);
    emit(
        sampled,
        ExplainedTerm::Geometry,
        Cause::Sampling,
        confidence,
    );
    out
}
