//! The editor's side of the isolation switches (mute, solo, hide): the toggles the
//! outliner and the light markers push, the toolbar's note of what is isolated, and how
//! the switches follow their lights and objects when the lists are reshuffled. Like the
//! term switches they are debugging state: never in the scene, never an undo step.

use super::labels::light_label;
use crate::scene::tree::object_at;
use crate::scene::{Light, Object, Scene};
use crate::trace::Isolation;

/// One click on an isolation toggle.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum IsolationToggle {
    /// Mute or unmute a light.
    Mute(usize),
    /// Solo a light: alone, or (`add`, with Ctrl or Shift held) with the other solo lights.
    Solo {
        /// The light.
        light: usize,
        /// Join the solo lights instead of replacing them.
        add: bool,
    },
    /// Hide or show an object.
    Hide(usize),
    /// Hide or show a part of an object tree, by path.
    HidePart(Vec<usize>),
    /// Back to the full picture: nothing muted, solo or hidden.
    ShowAll,
}

impl IsolationToggle {
    /// Applies the click to `isolation`.
    pub fn apply(self, isolation: &mut Isolation) {
        match self {
            IsolationToggle::Mute(light) => isolation.toggle_mute(light),
            IsolationToggle::Solo { light, add } => isolation.toggle_solo(light, add),
            IsolationToggle::Hide(object) => isolation.toggle_hide(object),
            IsolationToggle::HidePart(path) => isolation.toggle_hide_part(&path),
            IsolationToggle::ShowAll => *isolation = Isolation::NONE,
        }
    }
}

/// What the toolbar says while isolation changes the picture, e.g.
/// "solo Spot light 4 · muted Point light 2 · hidden red ball"; `None` for the full
/// picture. Long lists are counted instead of named.
#[must_use]
pub fn isolation_note(isolation: &Isolation, scene: &Scene) -> Option<String> {
    if isolation.is_none() {
        return None;
    }
    let light = |i: &usize| {
        scene
            .lights
            .get(*i)
            .map_or_else(|| format!("light {}", i + 1), |l| light_label(l, *i))
    };
    let object = |i: &usize| {
        scene
            .objects
            .get(*i)
            .map_or_else(|| format!("object {i}"), |o| o.name.clone())
    };
    let parts = [
        (
            "solo",
            "light",
            listed(isolation.solo_lights.iter().map(light)),
        ),
        (
            "muted",
            "light",
            listed(isolation.muted_lights.iter().map(light)),
        ),
        (
            "hidden",
            "object",
            listed(isolation.hidden_objects.iter().map(object)),
        ),
        (
            "hidden",
            "part",
            listed(
                isolation
                    .hidden_parts
                    .iter()
                    .map(|p| crate::scene::tree::path_name(&scene.objects, p)),
            ),
        ),
    ];
    let text: Vec<String> = parts
        .into_iter()
        .filter_map(|(what, noun, names)| match names {
            Listed::None => None,
            Listed::Names(names) => Some(format!("{what} {names}")),
            Listed::Count(n) => Some(format!("{what} {n} {noun}s")),
        })
        .collect();
    Some(text.join(" · "))
}

enum Listed {
    None,
    Names(String),
    Count(usize),
}

/// Up to two names joined, else the count.
fn listed(names: impl Iterator<Item = String>) -> Listed {
    let names: Vec<String> = names.collect();
    match names.len() {
        0 => Listed::None,
        1 | 2 => Listed::Names(names.join(", ")),
        n => Listed::Count(n),
    }
}

/// The isolated lights and objects as they were before a command that may reshuffle the
/// lists (a delete, a duplicate, an undo), to find them again afterwards.
#[derive(Clone, Debug)]
pub struct IsolationAnchors {
    isolation: Isolation,
    lights: Vec<(usize, Light)>,
    objects: Vec<(usize, Object)>,
    /// The hidden parts' names, by path.
    parts: Vec<(Vec<usize>, String)>,
}

impl IsolationAnchors {
    /// Remembers the isolated items of `scene` (only those: usually none or a few).
    #[must_use]
    pub fn take(scene: &Scene, isolation: &Isolation) -> Self {
        let lights = isolation
            .muted_lights
            .union(&isolation.solo_lights)
            .filter_map(|&i| scene.lights.get(i).map(|l| (i, l.clone())))
            .collect();
        let objects = isolation
            .hidden_objects
            .iter()
            .filter_map(|&i| scene.objects.get(i).map(|o| (i, o.clone())))
            .collect();
        let parts = isolation
            .hidden_parts
            .iter()
            .filter_map(|p| object_at(&scene.objects, p).map(|o| (p.clone(), o.name.clone())))
            .collect();
        Self {
            isolation: isolation.clone(),
            lights,
            objects,
            parts,
        }
    }

    /// The isolation moved to where its items are now in `scene`: each at its old index
    /// if the item there is unchanged, else at the nearest index holding an equal item;
    /// an item that is gone loses its switch.
    #[must_use]
    pub fn follow(&self, scene: &Scene) -> Isolation {
        let light_to = |old: usize| moved_to(&self.lights, &scene.lights, old);
        let object_to = |old: usize| moved_to(&self.objects, &scene.objects, old);
        Isolation {
            muted_lights: self
                .isolation
                .muted_lights
                .iter()
                .filter_map(|&i| light_to(i))
                .collect(),
            solo_lights: self
                .isolation
                .solo_lights
                .iter()
                .filter_map(|&i| light_to(i))
                .collect(),
            hidden_objects: self
                .isolation
                .hidden_objects
                .iter()
                .filter_map(|&i| object_to(i))
                .collect(),
            // A hidden part stays hidden while a node of its name is at its path below
            // where its top-level object went (edits inside a tree keep it hidden).
            hidden_parts: self
                .parts
                .iter()
                .filter_map(|(path, name)| {
                    let top = object_to(path[0]).unwrap_or(path[0]);
                    let moved = [&[top], &path[1..]].concat();
                    (object_at(&scene.objects, &moved)?.name == *name).then_some(moved)
                })
                .collect(),
        }
    }
}

/// Where the item that was at `old` is in `now`: `old` itself, or the nearest equal one.
fn moved_to<T: PartialEq>(anchors: &[(usize, T)], now: &[T], old: usize) -> Option<usize> {
    let (_, item) = anchors.iter().find(|(i, _)| *i == old)?;
    if now.get(old) == Some(item) {
        return Some(old);
    }
    (1..now.len().max(old + 1)).find_map(|d| {
        [old.checked_sub(d), Some(old + d)]
            .into_iter()
            .flatten()
            .find(|&j| now.get(j) == Some(item))
    })
}

/// Drops the indices `scene` does not have (after opening a file that changed since its
/// switches were stored).
pub fn keep_in_range(isolation: &mut Isolation, scene: &Scene) {
    let lights = scene.lights.len();
    isolation.muted_lights.retain(|&i| i < lights);
    isolation.solo_lights.retain(|&i| i < lights);
    let objects = scene.objects.len();
    isolation.hidden_objects.retain(|&i| i < objects);
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;

    fn scene() -> Scene {
        crate::scene::examples::default_scene()
    }

    #[test]
    fn the_note_names_a_few_and_counts_many() {
        let scene = scene();
        assert_eq!(isolation_note(&Isolation::NONE, &scene), None);
        let mut isolation = Isolation::NONE;
        IsolationToggle::Solo {
            light: 3,
            add: false,
        }
        .apply(&mut isolation);
        IsolationToggle::Mute(1).apply(&mut isolation);
        IsolationToggle::Hide(1).apply(&mut isolation);
        assert_eq!(
            isolation_note(&isolation, &scene).unwrap(),
            "solo Spot light 4 · muted Point light 2 · hidden red ball"
        );
        for object in [0, 2, 3] {
            IsolationToggle::Hide(object).apply(&mut isolation);
        }
        let note = isolation_note(&isolation, &scene).unwrap();
        assert!(note.ends_with("hidden 4 objects"), "{note}");
        IsolationToggle::ShowAll.apply(&mut isolation);
        assert!(isolation.is_none());
    }

    #[test]
    fn switches_follow_their_items_through_a_delete_and_its_undo() {
        let before = scene();
        let isolation = Isolation {
            muted_lights: BTreeSet::from([3]),
            solo_lights: BTreeSet::from([1]),
            hidden_objects: BTreeSet::from([1, 4]),
            hidden_parts: BTreeSet::new(),
        };
        let anchors = IsolationAnchors::take(&before, &isolation);
        let mut after = before.clone();
        after.lights.remove(2);
        after.objects.remove(1);
        let followed = anchors.follow(&after);
        assert_eq!(followed.muted_lights, BTreeSet::from([2]), "shifted down");
        assert_eq!(followed.solo_lights, BTreeSet::from([1]), "unchanged");
        assert_eq!(
            followed.hidden_objects,
            BTreeSet::from([3]),
            "the deleted one is gone"
        );
        // Undo brings the deleted items back in place: the switches move back up.
        let undone = IsolationAnchors::take(&after, &followed).follow(&before);
        assert_eq!(undone.muted_lights, BTreeSet::from([3]));
        assert_eq!(undone.hidden_objects, BTreeSet::from([4]));
    }

    #[test]
    fn out_of_range_indices_are_dropped() {
        let scene = scene();
        let mut isolation = Isolation {
            muted_lights: BTreeSet::from([0, 7]),
            solo_lights: BTreeSet::from([4]),
            hidden_objects: BTreeSet::from([5, 6]),
            hidden_parts: BTreeSet::new(),
        };
        keep_in_range(&mut isolation, &scene);
        assert_eq!(isolation.muted_lights, BTreeSet::from([0]));
        assert!(isolation.solo_lights.is_empty());
        assert_eq!(isolation.hidden_objects, BTreeSet::from([5]));
    }
}
