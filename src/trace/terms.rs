//! The term switches of the lighting model, the isolation switches of lights and objects,
//! and the debug views. The editor, the command line and the library all use these, so a
//! switch means the same thing everywhere.

use std::collections::BTreeSet;
use std::fmt;
use std::str::FromStr;

/// A term of the lighting model that can be switched off or shown alone.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Term {
    /// ka * ambient light (and the background of primary misses when solo).
    Ambient,
    /// kd * L * max(0, n.l).
    Diffuse,
    /// ks * L * max(0, r.v)^s.
    Specular,
    /// Visibility of lights (shadow rays). Off: every light is visible.
    Shadows,
    /// km * colour(reflected ray).
    Reflection,
    /// kt * colour(refracted ray) (along the mirror direction where Snell's law has no
    /// solution: total internal reflection).
    Transmission,
}

impl Term {
    /// All terms, in the order of the contract.
    pub const ALL: [Term; 6] = [
        Term::Ambient,
        Term::Diffuse,
        Term::Specular,
        Term::Shadows,
        Term::Reflection,
        Term::Transmission,
    ];

    /// The lower-case name used on the command line and in the editor.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Term::Ambient => "ambient",
            Term::Diffuse => "diffuse",
            Term::Specular => "specular",
            Term::Shadows => "shadows",
            Term::Reflection => "reflection",
            Term::Transmission => "transmission",
        }
    }
}

impl fmt::Display for Term {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Term {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        Term::ALL
            .into_iter()
            .find(|t| t.name().eq_ignore_ascii_case(s.trim()))
            .ok_or_else(|| {
                format!("unknown term \"{s}\" (expected ambient, diffuse, specular, shadows, reflection or transmission)")
            })
    }
}

/// Which terms are on, and which one (if any) is shown alone.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct TermSwitches {
    /// Whether each term of [`Term::ALL`] is on.
    pub on: [bool; Term::ALL.len()],
    /// A term shown alone at the primary hit; the reflected or transmitted colour it
    /// shows (for `reflection`, `transmission`) is still the full picture as the `on`
    /// switches have it.
    pub solo: Option<Term>,
}

impl Default for TermSwitches {
    fn default() -> Self {
        Self::ALL_ON
    }
}

impl TermSwitches {
    /// Everything on, nothing solo: the full picture.
    pub const ALL_ON: Self = Self {
        on: [true; Term::ALL.len()],
        solo: None,
    };

    /// Whether `term` is switched on (regardless of solo).
    #[must_use]
    pub fn is_on(&self, term: Term) -> bool {
        self.on[term as usize]
    }

    /// Switches `term` on or off.
    pub fn set(&mut self, term: Term, on: bool) {
        self.on[term as usize] = on;
    }

    /// The same switches with `term` shown alone.
    #[must_use]
    pub fn with_solo(mut self, term: Option<Term>) -> Self {
        self.solo = term;
        self
    }

    /// What to compute at the primary hit.
    #[must_use]
    pub fn primary(&self) -> ActiveTerms {
        let mut active = self.secondary();
        if let Some(solo) = self.solo {
            let shadows = active.shadows;
            active = ActiveTerms {
                ambient: solo == Term::Ambient,
                diffuse: solo == Term::Diffuse,
                specular: solo == Term::Specular,
                shadows,
                reflection: solo == Term::Reflection,
                transmission: solo == Term::Transmission,
                background: solo == Term::Ambient,
            };
        }
        active
    }

    /// The view the tracer shows: solo shadows turns the lit picture into the shadow mask.
    #[must_use]
    pub fn shown_view(&self, view: View) -> View {
        if view == View::Beauty && self.solo == Some(Term::Shadows) {
            View::ShadowMask
        } else {
            view
        }
    }

    /// The terms of camera rays and of mirror rays, where `view` shows the lit picture.
    #[must_use]
    pub fn beauty_terms(&self, view: View) -> Option<(ActiveTerms, ActiveTerms)> {
        (self.shown_view(view) == View::Beauty).then(|| (self.primary(), self.secondary()))
    }

    /// What to compute at the hits of reflected rays: the `on` switches, no solo.
    #[must_use]
    pub fn secondary(&self) -> ActiveTerms {
        ActiveTerms {
            ambient: self.is_on(Term::Ambient),
            diffuse: self.is_on(Term::Diffuse),
            specular: self.is_on(Term::Specular),
            shadows: self.is_on(Term::Shadows),
            reflection: self.is_on(Term::Reflection),
            transmission: self.is_on(Term::Transmission),
            background: true,
        }
    }
}

/// The terms one level of the shader computes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ActiveTerms {
    /// Add ka * ambient.
    pub ambient: bool,
    /// Add the diffuse term.
    pub diffuse: bool,
    /// Add the specular term.
    pub specular: bool,
    /// Cast shadow rays (otherwise every light is visible).
    pub shadows: bool,
    /// Add km * colour(reflected ray).
    pub reflection: bool,
    /// Add kt * colour(transmitted ray).
    pub transmission: bool,
    /// Rays that miss show the background.
    pub background: bool,
}

/// Which lights and objects take part in a render, by their index in the scene's lists:
/// the isolation switches, as the term switches are for terms. A muted light and a hidden
/// object are absent from the render (a hidden object casts no shadow, is not reflected
/// and cannot be picked); while any light is solo, only the solo lights shine. The
/// background goes with one light's solo (see [`crate::trace::world::isolation`]) so that the
/// solo images of all the lights add up to the full picture.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct Isolation {
    /// Lights switched off. Muting a solo light silences it too.
    pub muted_lights: BTreeSet<usize>,
    /// Lights shown alone (all of them together); empty: no solo.
    pub solo_lights: BTreeSet<usize>,
    /// Objects left out of the render.
    pub hidden_objects: BTreeSet<usize>,
    /// Parts of object trees left out, by path (a top-level index, then child and
    /// operand indices; two or more). A hidden part counts as empty space: a hidden
    /// group child or subtracted operand is as if it were not there; an Intersection
    /// with a hidden operand is empty.
    pub hidden_parts: BTreeSet<Vec<usize>>,
}

impl Isolation {
    /// Every light and object takes part: the full picture.
    pub const NONE: Self = Self {
        muted_lights: BTreeSet::new(),
        solo_lights: BTreeSet::new(),
        hidden_objects: BTreeSet::new(),
        hidden_parts: BTreeSet::new(),
    };

    /// Whether nothing is muted, solo or hidden.
    #[must_use]
    pub fn is_none(&self) -> bool {
        self.muted_lights.is_empty()
            && self.solo_lights.is_empty()
            && self.hidden_objects.is_empty()
            && self.hidden_parts.is_empty()
    }

    /// Whether light `index` shines: not muted, and solo if any light is.
    #[must_use]
    pub fn is_light_lit(&self, index: usize) -> bool {
        !self.muted_lights.contains(&index)
            && (self.solo_lights.is_empty() || self.solo_lights.contains(&index))
    }

    /// Whether object `index` takes part in the render.
    #[must_use]
    pub fn is_object_shown(&self, index: usize) -> bool {
        !self.hidden_objects.contains(&index)
    }

    /// Mutes light `index`, or unmutes it if it was muted.
    pub fn toggle_mute(&mut self, index: usize) {
        if !self.muted_lights.remove(&index) {
            self.muted_lights.insert(index);
        }
    }

    /// Hides object `index`, or shows it again if it was hidden.
    pub fn toggle_hide(&mut self, index: usize) {
        if !self.hidden_objects.remove(&index) {
            self.hidden_objects.insert(index);
        }
    }

    /// Hide or show the part of an object tree at `path` (two indices or more).
    pub fn toggle_hide_part(&mut self, path: &[usize]) {
        if !self.hidden_parts.remove(path) {
            self.hidden_parts.insert(path.to_vec());
        }
    }

    /// Whether the node at `path` (or a part of a tree holding it) is hidden.
    #[must_use]
    pub fn is_node_hidden(&self, path: &[usize]) -> bool {
        path.first()
            .is_some_and(|&top| self.hidden_objects.contains(&top))
            || (2..=path.len()).any(|n| self.hidden_parts.contains(&path[..n]))
    }

    /// Solo light `index`. With `add`, it joins (or, if solo already, leaves) the solo
    /// lights; without, it becomes the only solo light, or ends the solo if it already was.
    pub fn toggle_solo(&mut self, index: usize, add: bool) {
        let was_solo = self.solo_lights.contains(&index);
        if add {
            if was_solo {
                self.solo_lights.remove(&index);
            } else {
                self.solo_lights.insert(index);
            }
        } else if was_solo && self.solo_lights.len() == 1 {
            self.solo_lights.clear();
        } else {
            self.solo_lights = BTreeSet::from([index]);
        }
    }
}

/// What the image shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum View {
    /// The lit picture, with the term switches applied.
    #[default]
    Beauty,
    /// The shading normal (facing the ray) as colour: n * 0.5 + 0.5.
    Normal,
    /// Distance from the eye: 1 / (1 + t / view distance), white near, black far.
    Depth,
    /// A distinct flat colour per object.
    ObjectId,
    /// Fraction of the lights reaching each point that are not shadowed.
    ShadowMask,
}

impl View {
    /// All views, in menu order.
    pub const ALL: [View; 5] = [
        View::Beauty,
        View::Normal,
        View::Depth,
        View::ObjectId,
        View::ShadowMask,
    ];

    /// The name used on the command line.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            View::Beauty => "beauty",
            View::Normal => "normal",
            View::Depth => "depth",
            View::ObjectId => "object-id",
            View::ShadowMask => "shadow-mask",
        }
    }
}

impl fmt::Display for View {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for View {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        View::ALL
            .into_iter()
            .find(|v| v.name().eq_ignore_ascii_case(s.trim()))
            .ok_or_else(|| {
                format!("unknown view \"{s}\" (expected beauty, normal, depth, object-id or shadow-mask)")
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solo_keeps_the_shadow_switch_and_shows_background_only_for_ambient() {
        let mut switches = TermSwitches::ALL_ON.with_solo(Some(Term::Diffuse));
        switches.set(Term::Shadows, false);
        let p = switches.primary();
        assert!(p.diffuse && !p.ambient && !p.specular && !p.reflection && !p.shadows);
        assert!(!p.background);
        assert!(switches.with_solo(Some(Term::Ambient)).primary().background);
        assert!(switches.secondary().ambient && switches.secondary().background);
    }

    #[test]
    fn solo_replaces_or_adds_and_mute_wins_over_solo() {
        let mut isolation = Isolation::NONE;
        assert!(isolation.is_none() && isolation.is_light_lit(3));
        isolation.toggle_solo(1, false);
        isolation.toggle_solo(2, false);
        assert_eq!(
            isolation.solo_lights,
            BTreeSet::from([2]),
            "a plain solo replaces"
        );
        isolation.toggle_solo(0, true);
        assert_eq!(
            isolation.solo_lights,
            BTreeSet::from([0, 2]),
            "an added solo joins"
        );
        assert!(isolation.is_light_lit(0) && !isolation.is_light_lit(1));
        isolation.toggle_mute(0);
        assert!(!isolation.is_light_lit(0), "a muted solo light is silent");
        isolation.toggle_solo(2, true);
        isolation.toggle_solo(0, false);
        assert!(
            isolation.solo_lights.is_empty(),
            "solo again on the only solo ends it"
        );
        isolation.toggle_mute(0);
        isolation.toggle_hide(4);
        assert!(!isolation.is_object_shown(4) && isolation.is_object_shown(3));
        isolation.toggle_hide(4);
        assert_eq!(isolation, Isolation::NONE);
    }

    #[test]
    fn names_parse_back() {
        for t in Term::ALL {
            assert_eq!(t.name().parse::<Term>().unwrap(), t);
        }
        for v in View::ALL {
            assert_eq!(v.name().parse::<View>().unwrap(), v);
        }
        assert!("glow".parse::<Term>().is_err());
    }
}
