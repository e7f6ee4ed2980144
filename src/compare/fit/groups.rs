//! The groups of channels a single fitted number may scale: one term of one light on one
//! node of the object trees (an object, a group or CSG subtree, one leaf), or that term
//! for every light, or on every object, or both; one bug on one node or on all; one part
//! of a node, or all its parts, missing. A real bug changes one such group as a whole,
//! which is what makes the groups readable verdicts.

use std::ops::Range;

use rayon::prelude::*;

use super::target::{FitState, Target};
use crate::compare::catalogue::Nodes;
use crate::compare::catalogue::SpotBug;
use crate::compare::catalogue::{ChannelSpace, Family, Kind};
use crate::compare::catalogue::{ClampBug, NormalBug, Part, ShadowBug, SpawnBug, SpecularBug};
use crate::compare::catalogue::{Slot, TriedNode};
use crate::compare::split::Components;

/// A set of channels scaled by one number.
#[derive(Clone, Debug, PartialEq)]
pub struct Group {
    /// What kind of change.
    pub family: Family,
    /// The light, or `None` for every light (or none concerned).
    pub light: Option<usize>,
    /// The node ([`Nodes::nodes`]), or `None` for every object.
    pub object: Option<usize>,
    /// For a missing node: the part, or `None` for all its parts.
    pub part: Option<Part>,
    /// The leaves it covers: its node's (all of them for every object); groups whose
    /// leaves nest tell one story at two depths.
    pub leaves: Range<usize>,
    /// Its node's depth in its tree (0 for an object, or every object).
    pub depth: usize,
    /// The channels.
    pub members: Vec<u32>,
}

impl Group {
    /// A group of one channel (number 0) on object 0, for tests of what reads groups.
    #[cfg(test)]
    pub(crate) fn of_one_channel(family: Family) -> Self {
        Self {
            family,
            light: None,
            object: Some(0),
            part: None,
            leaves: 0..1,
            depth: 0,
            members: vec![0],
        }
    }
}

/// Every group of a world.
#[derive(Clone, Debug)]
pub struct Groups {
    /// The groups.
    pub list: Vec<Group>,
    /// For each channel, the groups it belongs to.
    pub of_channel: Vec<Vec<u32>>,
}

/// The families whose groups are per node and per light choice: each is scaled alone.
const PER_NODE: [(Family, Kind); 3] = [
    (Family::Ambient, Kind::Ambient),
    (Family::Reflection, Kind::Reflection),
    (Family::Transmission, Kind::Transmission),
];

/// The known bugs' families, each with its one channel, in the order the groups list
/// them: normals, highlights, clamps, shadow tests, spawned rays.
fn bug_families() -> impl Iterator<Item = (Family, Kind)> {
    let normal = NormalBug::ALL.map(|b| (Family::Normal(b), Kind::Normal(b)));
    let highlight = SpecularBug::ALL.map(|b| (Family::Highlight(b), Kind::Highlight(b)));
    let clamp = ClampBug::ALL.map(|b| (Family::Clamp(b), Kind::Clamp(b)));
    let shadow = ShadowBug::ALL.map(|b| (Family::ShadowTest(b), Kind::ShadowTest(b)));
    let spawn = SpawnBug::ALL.map(|b| (Family::Spawn(b), Kind::Spawn(b)));
    normal
        .into_iter()
        .chain(highlight)
        .chain(clamp)
        .chain(shadow)
        .chain(spawn)
}

impl Groups {
    /// The groups of a world numbered by `space`, whose trees are `nodes`, with the
    /// nodes `tried` as missing and each leaf made of `parts_of[leaf]`
    /// ([`Part::of_leaf`]).
    #[must_use]
    pub fn new(
        space: ChannelSpace,
        nodes: &Nodes,
        tried: &[TriedNode],
        parts_of: &[&'static [Part]],
    ) -> Self {
        let mut list = Vec::new();
        let every = 0..space.objects;
        // `kinds` on each leaf of the node (every object's for `None`), or on an inner
        // node's `slot`: its channels are its own.
        let mut add = |family, light, object: Option<usize>, part, kinds: Vec<Kind>, slot| {
            let (leaves, depth) = object.map_or((every.clone(), 0), |n| {
                let node = &nodes.nodes[n];
                (node.leaves.clone(), node.depth())
            });
            let members = match slot {
                Some(slot) => kinds.iter().map(|&k| space.id(k, Some(slot))).collect(),
                None => leaves
                    .clone()
                    .flat_map(|o| kinds.iter().map(move |&k| space.id(k, Some(o))))
                    .collect(),
            };
            list.push(Group {
                family,
                light,
                object,
                part,
                leaves,
                depth,
                members,
            });
        };
        let lights: Vec<usize> = (0..space.lights).collect();
        // Every object, then each node; a node holding the same leaves as its child is
        // that child, better named by it.
        let choices = std::iter::once(None).chain(
            (0..nodes.nodes.len())
                .filter(|&n| !nodes.has_same_child(n))
                .map(Some),
        );
        for object in choices {
            for (family, kind) in PER_NODE {
                add(family, None, object, None, vec![kind], None);
            }
            for light in std::iter::once(None).chain(lights.iter().copied().map(Some)) {
                let chosen: Vec<usize> = light.map_or(lights.clone(), |l| vec![l]);
                for (family, kind) in [
                    (Family::Diffuse, Kind::Diffuse as fn(usize) -> Kind),
                    (Family::Specular, Kind::Specular),
                    (Family::Shadow, Kind::Shadow),
                ] {
                    add(
                        family,
                        light,
                        object,
                        None,
                        chosen.iter().map(|&l| kind(l)).collect(),
                        None,
                    );
                }
            }
            for (family, kind) in bug_families() {
                add(family, None, object, None, vec![kind], None);
            }
        }
        for tried in tried {
            let node = Some(tried.node);
            let leaf = match tried.slot {
                Slot::Leaf(leaf) => leaf,
                Slot::Inner(slot) => {
                    let kinds = vec![Kind::NodeMissing, Kind::NodeShadowCast];
                    add(Family::Missing, None, node, None, kinds, Some(slot));
                    continue;
                }
            };
            let parts = parts_of[leaf];
            // The whole node missing takes its shadows with it; a part alone (a
            // plane's back) still casts them.
            let whole = |mut kinds: Vec<Kind>| {
                kinds.push(Kind::ShadowCast);
                kinds
            };
            for &part in parts {
                let kinds = vec![Kind::Missing(part)];
                let kinds = if parts.len() == 1 {
                    whole(kinds)
                } else {
                    kinds
                };
                add(Family::Missing, None, node, Some(part), kinds, None);
            }
            if parts.len() > 1 {
                let kinds = parts.iter().map(|&p| Kind::Missing(p)).collect();
                add(Family::Missing, None, node, None, whole(kinds), None);
            }
        }
        // A spot light's bug is the light's, wherever it shows. A spot light without
        // cone and fall-off saturates the picture, where one light's change alone cannot
        // be told from the others' (the clipped pixels hide which): that bug is also
        // tried on every light at once. (The other bugs tried so read as every light
        // where one light has them: the fit cannot yet prefer the specific one there.)
        if space.lights > 1 {
            let bug = SpotBug::NoConeNoFalloff;
            let kinds = (0..space.lights).map(|l| Kind::Spot(bug, l)).collect();
            add(Family::Spot(bug), None, None, None, kinds, None);
        }
        for light in 0..space.lights {
            for bug in SpotBug::ALL {
                add(
                    Family::Spot(bug),
                    Some(light),
                    None,
                    None,
                    vec![Kind::Spot(bug, light)],
                    None,
                );
            }
        }
        let background = space.id(Kind::Background, None);
        list.push(Group {
            family: Family::Background,
            light: None,
            object: None,
            part: None,
            leaves: every,
            depth: 0,
            members: vec![background],
        });
        let mut of_channel = vec![Vec::new(); space.count()];
        for (index, group) in list.iter().enumerate() {
            for &channel in &group.members {
                of_channel[channel as usize].push(index as u32);
            }
        }
        Self { list, of_channel }
    }

    /// Each group's squared norm `sum over pixels of weight * |sum of its channels|^2`.
    #[must_use]
    pub fn norms(&self, components: &Components, target: &Target) -> Vec<f64> {
        let pixels = components.labels.len();
        let chunk = 4096;
        let chunks = (0..pixels.div_ceil(chunk))
            .into_par_iter()
            .map(|c| {
                let mut norms = vec![0.0; self.list.len()];
                let mut scratch = vec![[0.0f64; 3]; self.list.len()];
                let mut touched: Vec<u32> = Vec::new();
                for p in c * chunk..((c + 1) * chunk).min(pixels) {
                    for entry in components.pixel(p) {
                        for &g in &self.of_channel[entry.channel as usize] {
                            let sum = &mut scratch[g as usize];
                            if *sum == [0.0; 3] {
                                touched.push(g);
                            }
                            for (s, v) in sum.iter_mut().zip(entry.value) {
                                *s += f64::from(v);
                            }
                        }
                    }
                    let w = &target.weight[p];
                    for g in touched.drain(..) {
                        let sum = std::mem::take(&mut scratch[g as usize]);
                        norms[g as usize] += (0..3).map(|k| w[k] * sum[k] * sum[k]).sum::<f64>();
                    }
                }
                norms
            })
            .collect::<Vec<_>>();
        sum_in_order(chunks, self.list.len())
    }

    /// Each group's inner product with the current residual.
    #[must_use]
    pub fn correlations(
        &self,
        components: &Components,
        target: &Target,
        state: &FitState,
    ) -> Vec<f64> {
        let by_channel = channel_correlations(components, target, state);
        self.list
            .iter()
            .map(|g| g.members.iter().map(|&c| by_channel[c as usize]).sum())
            .collect()
    }
}

/// Each channel's inner product with the residual.
fn channel_correlations(components: &Components, target: &Target, state: &FitState) -> Vec<f64> {
    let channels = components.space.count();
    let pixels = components.labels.len();
    let chunk = 8192;
    let chunks = (0..pixels.div_ceil(chunk))
        .into_par_iter()
        .map(|c| {
            let mut sums = vec![0.0; channels];
            for p in c * chunk..((c + 1) * chunk).min(pixels) {
                let r = state.residual(target, p);
                if r == [0.0; 3] {
                    continue;
                }
                for entry in components.pixel(p) {
                    let v = entry.value;
                    sums[entry.channel as usize] +=
                        r[0] * f64::from(v[0]) + r[1] * f64::from(v[1]) + r[2] * f64::from(v[2]);
                }
            }
            sums
        })
        .collect::<Vec<_>>();
    sum_in_order(chunks, channels)
}

/// The element-wise sum of the chunks' sums, added in the chunks' order: the same bits
/// whichever threads made them (a parallel `reduce` adds them in the order work was
/// stolen, so the last bits followed the scheduling).
fn sum_in_order(chunks: Vec<Vec<f64>>, len: usize) -> Vec<f64> {
    chunks.into_iter().fold(vec![0.0; len], |mut sum, chunk| {
        sum.iter_mut().zip(chunk).for_each(|(x, y)| *x += y);
        sum
    })
}
