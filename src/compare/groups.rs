//! The groups of channels a single fitted number may scale: one term of one light on one
//! object, or that term for every light, or on every object, or both; one bug on one
//! object or on all; one part of an object, or all its parts, missing. A real bug
//! changes one such group as a whole, which is what makes the groups readable verdicts.

use rayon::prelude::*;

use super::bugs::{ClampBug, NormalBug, Part, SpecularBug};
use super::channels::{ChannelSpace, Family, Kind};
use super::components::{Components, MAX_MISSING_OBJECTS};
use super::spot_bugs::SpotBug;
use super::target::{FitState, Target};

/// A set of channels scaled by one number.
#[derive(Clone, Debug, PartialEq)]
pub struct Group {
    /// What kind of change.
    pub family: Family,
    /// The light, or `None` for every light (or none concerned).
    pub light: Option<usize>,
    /// The object, or `None` for every object.
    pub object: Option<usize>,
    /// For a missing object: the part, or `None` for all its parts.
    pub part: Option<Part>,
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

/// The light and object choices of a family: every one, then each.
fn choices(count: usize) -> impl Iterator<Item = Option<usize>> + Clone {
    std::iter::once(None).chain((0..count).map(Some))
}

impl Groups {
    /// The groups of a world numbered by `space` whose objects are made of these parts
    /// ([`Part::of_scene_object`]).
    #[must_use]
    pub fn new(space: ChannelSpace, parts_of: &[&'static [Part]]) -> Self {
        let mut list = Vec::new();
        let objects = space.objects;
        let mut add = |family, light, object: Option<usize>, part, kinds: Vec<Kind>| {
            let objects_in: Vec<usize> = object.map_or((0..objects).collect(), |o| vec![o]);
            let members = objects_in
                .iter()
                .flat_map(|&o| kinds.iter().map(move |&k| space.id(k, Some(o))))
                .collect();
            list.push(Group {
                family,
                light,
                object,
                part,
                members,
            });
        };
        let lights: Vec<usize> = (0..space.lights).collect();
        for object in choices(objects) {
            add(Family::Ambient, None, object, None, vec![Kind::Ambient]);
            add(
                Family::Reflection,
                None,
                object,
                None,
                vec![Kind::Reflection],
            );
            add(
                Family::Transmission,
                None,
                object,
                None,
                vec![Kind::Transmission],
            );
            for light in choices(space.lights) {
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
                    );
                }
            }
            for bug in NormalBug::ALL {
                add(
                    Family::Normal(bug),
                    None,
                    object,
                    None,
                    vec![Kind::Normal(bug)],
                );
            }
            for bug in SpecularBug::ALL {
                add(
                    Family::Highlight(bug),
                    None,
                    object,
                    None,
                    vec![Kind::Highlight(bug)],
                );
            }
            for bug in ClampBug::ALL {
                add(
                    Family::Clamp(bug),
                    None,
                    object,
                    None,
                    vec![Kind::Clamp(bug)],
                );
            }
        }
        for (object, &parts) in parts_of.iter().enumerate().take(MAX_MISSING_OBJECTS) {
            // The whole object missing takes its shadows with it; a part alone (a
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
                add(Family::Missing, None, Some(object), Some(part), kinds);
            }
            if parts.len() > 1 {
                let kinds = parts.iter().map(|&p| Kind::Missing(p)).collect();
                add(Family::Missing, None, Some(object), None, whole(kinds));
            }
        }
        // A spot light's bug is the light's, wherever it shows.
        for light in 0..space.lights {
            for bug in SpotBug::ALL {
                add(
                    Family::Spot(bug),
                    Some(light),
                    None,
                    None,
                    vec![Kind::Spot(bug, light)],
                );
            }
        }
        let background = space.id(Kind::Background, None);
        list.push(Group {
            family: Family::Background,
            light: None,
            object: None,
            part: None,
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
        (0..pixels.div_ceil(chunk))
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
            .reduce(
                || vec![0.0; self.list.len()],
                |mut a, b| {
                    a.iter_mut().zip(b).for_each(|(x, y)| *x += y);
                    a
                },
            )
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
    (0..pixels.div_ceil(chunk))
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
        .reduce(
            || vec![0.0; channels],
            |mut a, b| {
                a.iter_mut().zip(b).for_each(|(x, y)| *x += y);
                a
            },
        )
}
