//! Which term switches a pixel's colour can depend on, worked out from its cached entries
//! each time it is shaded, so that a switch edit re-shades only the pixels it can change:
//! turning specular off or on leaves alone every pixel none of whose hits has a Phong
//! lobe (over half of the default scene's).
//!
//! The rule follows the shader's own tests (`Tracer::shade`): a term adds nothing, and
//! casts no ray, where the test before it fails. It is conservative: a light whose
//! factors are unknown counts as reaching the hit with a lobe.

use glam::DVec3;
use smallvec::SmallVec;

use super::chains::{NO_ENTRY, PixelEntries};
use super::light_factors::LightSlot;
use crate::trace::shade::LitFactors;
use crate::trace::terms::ActiveTerms;
use crate::trace::world::World;

/// Switches a pixel depends on (or that an edit changed), for the camera ray's hit and
/// for the hits of the rays below it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct TermDependence(u16);

/// `ka * ambient` is not zero.
const AMBIENT: u16 = 1 << 0;
/// A miss, with a background that is not black.
const BACKGROUND: u16 = 1 << 1;
/// Some light reaches the hit from in front: its diffuse term, its shadow ray and
/// whether the shader looks at the lights at all.
const LIGHTS: u16 = 1 << 2;
/// Some light reaching the hit from in front has a Phong lobe.
const SPECULAR: u16 = 1 << 3;
/// The hit casts a mirror ray when reflection is on.
const REFLECTION: u16 = 1 << 4;
/// The hit casts a transmitted ray when transmission is on.
const TRANSMISSION: u16 = 1 << 5;
/// The bits of the hits below the camera ray's sit this far up.
const MIRROR_HITS: u32 = 6;

impl TermDependence {
    /// Depends on every switch: a pixel whose dependence was not worked out.
    pub const ANY: Self = Self(u16::MAX);
    /// Depends on no switch (or: no switch changed).
    pub const NONE: Self = Self(0);

    /// The switches that differ between `old` and `new`, each the terms of camera rays
    /// and of the rays below them.
    #[must_use]
    pub fn switched(old: (ActiveTerms, ActiveTerms), new: (ActiveTerms, ActiveTerms)) -> Self {
        let of = |a: ActiveTerms, b: ActiveTerms| {
            let looks_at_lights = |t: ActiveTerms| t.diffuse || t.specular;
            let mut bits = 0;
            for (differs, bit) in [
                (a.ambient != b.ambient, AMBIENT),
                (a.background != b.background, BACKGROUND),
                (a.diffuse != b.diffuse, LIGHTS),
                (a.shadows != b.shadows, LIGHTS),
                (looks_at_lights(a) != looks_at_lights(b), LIGHTS),
                (a.specular != b.specular, SPECULAR),
                (a.reflection != b.reflection, REFLECTION),
                (a.transmission != b.transmission, TRANSMISSION),
            ] {
                if differs {
                    bits |= bit;
                }
            }
            bits
        };
        Self(of(old.0, new.0) | of(old.1, new.1) << MIRROR_HITS)
    }

    /// Whether a pixel of this dependence may change when the switches `switched` do.
    #[must_use]
    #[inline]
    pub fn meets(self, switched: Self) -> bool {
        self.0 & switched.0 != 0
    }

    /// What a group of pixels of dependences `self` and `other` depends on: a switch
    /// meets it exactly where it meets one of them.
    #[must_use]
    #[inline]
    pub fn union(self, other: Self) -> Self {
        Self(self.0 | other.0)
    }

    /// Adds what an entry at `depth` of the tree depends on.
    #[inline]
    pub fn add(&mut self, depth: usize, entry: EntryTerms) {
        self.0 |= if depth == 0 {
            entry.0
        } else {
            entry.0 << MIRROR_HITS
        };
    }
}

/// What one entry of a tree depends on, found as the shader's tests go (by
/// [`DependenceRule::of_pixel`] and by the quick re-shade as it shades).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct EntryTerms(u16);

impl EntryTerms {
    /// A miss, showing `background` when the term is on.
    #[must_use]
    #[inline]
    pub fn miss(background: DVec3) -> Self {
        // NaN is not zero either.
        Self(if background != DVec3::ZERO {
            BACKGROUND
        } else {
            0
        })
    }

    /// A hit whose `ka * ambient` is `ambient`, which casts a mirror ray when
    /// reflection is on exactly if `casts_mirror_ray` and a transmitted ray when
    /// transmission is on exactly if `casts_transmitted_ray`.
    #[must_use]
    #[inline]
    pub fn hit(ambient: DVec3, casts_mirror_ray: bool, casts_transmitted_ray: bool) -> Self {
        let mut bits = 0;
        if ambient != DVec3::ZERO {
            bits |= AMBIENT;
        }
        if casts_mirror_ray {
            bits |= REFLECTION;
        }
        if casts_transmitted_ray {
            bits |= TRANSMISSION;
        }
        Self(bits)
    }

    /// Adds one light's factors at the hit (of a material with a diffuse or specular
    /// colour): in front it adds the light terms, with a lobe the specular term;
    /// unknown factors add both.
    #[inline]
    pub fn light(&mut self, factors: &LitFactors) {
        let n_dot_l = factors.n_dot_l();
        if n_dot_l.is_nan() {
            self.0 |= LIGHTS | SPECULAR;
        } else if n_dot_l > 0.0 {
            self.lit(factors.lobe().is_some());
        }
    }

    /// Adds a light known to be in front of the hit, with or without a lobe.
    #[inline]
    pub fn lit(&mut self, has_lobe: bool) {
        self.0 |= if has_lobe { LIGHTS | SPECULAR } else { LIGHTS };
    }

    /// Adds every light of the hit's row of light slots ([`Self::light`]).
    #[inline]
    pub fn lights(&mut self, row: &[LightSlot]) {
        for slot in row {
            let factors = slot.factors;
            self.light(&factors);
        }
    }
}

/// What the shader's tests look at per object, found once per pass.
#[derive(Clone, Copy, Debug)]
struct ObjectTerms {
    /// What an entry on it depends on before its lights: below `max_depth` (a mirror
    /// and a transmitted ray cast when their terms are on) and at it.
    below_max: EntryTerms,
    at_max: EntryTerms,
    /// A diffuse or specular colour: the shader looks at the lights.
    local: bool,
}

/// The dependence of pixels in one world: for those shaded in full
/// ([`Self::of_pixel`]), and what the quick re-shade starts each entry from.
#[derive(Clone, Debug)]
pub(crate) struct DependenceRule {
    objects: Vec<ObjectTerms>,
    miss: EntryTerms,
    max_depth: u32,
}

impl DependenceRule {
    /// For `world`'s materials, lights and depth.
    #[must_use]
    pub fn new(world: &World) -> Self {
        let objects = world
            .objects
            .iter()
            .map(|object| {
                let material = &world.materials[object.material];
                let ambient = material.ambient * world.ambient;
                ObjectTerms {
                    below_max: EntryTerms::hit(
                        ambient,
                        material.mirror != DVec3::ZERO,
                        material.transmission != DVec3::ZERO,
                    ),
                    at_max: EntryTerms::hit(ambient, false, false),
                    local: material.diffuse != DVec3::ZERO || material.specular != DVec3::ZERO,
                }
            })
            .collect();
        Self {
            objects,
            miss: EntryTerms::miss(world.background),
            max_depth: world.max_depth,
        }
    }

    /// What a miss depends on.
    #[must_use]
    #[inline]
    pub fn miss_terms(&self) -> EntryTerms {
        self.miss
    }

    /// What an entry on world object `object` at `depth` depends on before its lights.
    #[must_use]
    #[inline]
    pub fn hit_terms(&self, object: usize, depth: u32) -> EntryTerms {
        let terms = &self.objects[object];
        if depth < self.max_depth {
            terms.below_max
        } else {
            terms.at_max
        }
    }

    /// The dependence of a pixel with cached entries `entries` (`lights` light slots
    /// each): every entry's, the rays the pixel's tree no longer follows too.
    #[must_use]
    pub fn of_pixel(&self, entries: &PixelEntries, lights: usize) -> TermDependence {
        let mut all = TermDependence::NONE;
        let mut add = |index: usize, depth: u32| {
            let object = entries.objects[index];
            let entry = match self.objects.get(object as usize) {
                None => self.miss,
                Some(terms) => {
                    let mut entry = self.hit_terms(object as usize, depth);
                    if terms.local {
                        entry.lights(&entries.slots[index * lights..(index + 1) * lights]);
                    }
                    entry
                }
            };
            all.add(depth as usize, entry);
        };
        match entries.children {
            // A chain: an entry's index is its depth.
            None => (0..entries.objects.len()).for_each(|i| add(i, i as u32)),
            Some(children) => {
                // Parents come before their children.
                let mut depths: SmallVec<[u32; 16]> = SmallVec::from_elem(0, children.len());
                for (index, links) in children.iter().enumerate() {
                    for &child in links.iter().filter(|&&c| c != NO_ENTRY) {
                        depths[child as usize] = depths[index] + 1;
                    }
                    add(index, depths[index]);
                }
            }
        }
        all
    }
}

#[cfg(test)]
mod tests {
    use super::super::keep_rule::KeepRule;
    use super::*;
    use crate::trace::terms::{Term, TermSwitches};
    use crate::trace::world::LightSample;

    fn slot(n_dot_l: f64, lobe: Option<f64>) -> LightSlot {
        let sample = LightSample {
            radiance: DVec3::ONE,
            to_light: DVec3::Y,
            light_position: None,
            distance_squared: 1.0,
        };
        LightSlot {
            factors: LitFactors::reached(&sample, n_dot_l, lobe),
            ..LightSlot::NOTHING
        }
    }

    fn terms(switches: TermSwitches) -> (ActiveTerms, ActiveTerms) {
        (switches.primary(), switches.secondary())
    }

    #[test]
    fn each_switch_names_the_dependences_it_can_change() {
        let on = TermSwitches::ALL_ON;
        let off = |term| {
            let mut s = on;
            s.set(term, false);
            TermDependence::switched(terms(on), terms(s))
        };
        assert_eq!(
            TermDependence::switched(terms(on), terms(on)),
            TermDependence::NONE
        );
        let both = |bits: u16| TermDependence(bits | bits << MIRROR_HITS);
        assert_eq!(off(Term::Specular), both(SPECULAR));
        assert_eq!(off(Term::Diffuse), both(LIGHTS));
        assert_eq!(off(Term::Shadows), both(LIGHTS));
        assert_eq!(off(Term::Ambient), both(AMBIENT));
        assert_eq!(off(Term::Reflection), both(REFLECTION));
        assert_eq!(off(Term::Transmission), both(TRANSMISSION));
        // With diffuse off, specular decides whether the lights are looked at at all.
        let mut no_diffuse = on;
        no_diffuse.set(Term::Diffuse, false);
        let mut neither = no_diffuse;
        neither.set(Term::Specular, false);
        let switched = TermDependence::switched(terms(no_diffuse), terms(neither));
        assert_eq!(switched, both(SPECULAR | LIGHTS));
        // A solo changes the camera ray's terms only.
        let solo = TermDependence::switched(terms(on), terms(on.with_solo(Some(Term::Diffuse))));
        assert_eq!(
            solo,
            TermDependence(AMBIENT | BACKGROUND | SPECULAR | REFLECTION | TRANSMISSION)
        );
    }

    #[test]
    fn lights_behind_or_out_of_reach_add_nothing_and_unknown_ones_add_everything() {
        let lit = |slots: &[LightSlot]| {
            let mut entry = EntryTerms::default();
            entry.lights(slots);
            entry.0
        };
        let unreachable = LightSlot {
            factors: LitFactors::UNREACHABLE,
            ..LightSlot::NOTHING
        };
        assert_eq!(lit(&[slot(-0.3, None), unreachable]), 0);
        assert_eq!(lit(&[slot(0.5, None)]), LIGHTS);
        assert_eq!(
            lit(&[slot(0.5, None), slot(0.2, Some(0.0))]),
            LIGHTS | SPECULAR
        );
        assert_eq!(
            lit(&[slot(-1.0, None), LightSlot::NOTHING]),
            LIGHTS | SPECULAR
        );
        assert_eq!(EntryTerms::miss(DVec3::ZERO).0, 0);
        assert_eq!(EntryTerms::miss(DVec3::splat(0.1)).0, BACKGROUND);
        assert_eq!(EntryTerms::hit(DVec3::ZERO, true, false).0, REFLECTION);
        assert_eq!(EntryTerms::hit(DVec3::ZERO, false, true).0, TRANSMISSION);
        assert_eq!(
            EntryTerms::hit(DVec3::splat(f64::NAN), false, false).0,
            AMBIENT
        );
        let mut chain = TermDependence::NONE;
        chain.add(0, EntryTerms::hit(DVec3::ONE, false, false));
        chain.add(2, EntryTerms::miss(DVec3::ONE));
        assert_eq!(chain, TermDependence(AMBIENT | BACKGROUND << MIRROR_HITS));
    }

    #[test]
    fn a_kept_pixel_meets_no_changed_object_and_no_changed_switch() {
        let rule = KeepRule::new(vec![false, true], TermDependence(SPECULAR));
        assert!(rule.keeps(&[0, u32::MAX], TermDependence(LIGHTS)));
        assert!(
            !rule.keeps(&[0, 1], TermDependence(LIGHTS)),
            "meets object 1"
        );
        assert!(!rule.keeps(&[0], TermDependence(SPECULAR)), "has a lobe");
        assert!(!rule.keeps(&[0], TermDependence::ANY));
        let switches_only = KeepRule::new(vec![false; 2], TermDependence(SPECULAR << MIRROR_HITS));
        assert!(
            switches_only.keeps(&[1], TermDependence(SPECULAR)),
            "lobe at the camera hit only"
        );
    }
}
