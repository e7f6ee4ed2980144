//! The groups that compete with a step of the search: the best one telling another
//! story about the same pixels says how sure the step is ([`margin`]); those that fit
//! alike are listed as fitting as well ([`alike`]); and of groups that fit the same and
//! tell one story, the most specific goes first ([`prefer_specific`]).

use super::groups::{Group, Groups};
use crate::compare::catalogue::{Family, ShadowBug};

/// Two groups fit alike when their gains differ by less than this share of the larger.
const ALIKE: f64 = 0.01;

/// A more specific group goes first when its gain is within this share of the best:
/// the same fit, not merely a close one (a term of every light on a ball, scaled, is
/// not one light's even where the other adds little there).
const SAME_FIT: f64 = 0.001;

/// Whether two groups tell the same story (one may be more specific than the other):
/// the same family, lights that agree, and nodes one inside the other (every object
/// holds them all; an object holds its parts).
#[must_use]
pub fn compatible(a: &Group, b: &Group) -> bool {
    let agree = |x: Option<usize>, y: Option<usize>| x.is_none() || y.is_none() || x == y;
    let within =
        |x: &Group, y: &Group| x.leaves.start >= y.leaves.start && x.leaves.end <= y.leaves.end;
    a.family == b.family && agree(a.light, b.light) && (within(a, b) || within(b, a))
}

/// How specific a group is: one for each of a light, an object and a part it names, and
/// one for each level below its object the node lies.
fn specificity(group: &Group) -> usize {
    usize::from(group.light.is_some())
        + group.object.map_or(0, |_| 1 + group.depth)
        + usize::from(group.part.is_some())
}

/// Among the groups that fit the same as the best ([`SAME_FIT`]) and tell its story
/// (nested in it or around it), the most specific goes first: where one light lights the whole diffuse
/// term, "light 2 contributes nothing" explains as much as "the diffuse term is
/// missing", and a light that never lights is the likelier bug.
pub(super) fn prefer_specific(groups: &Groups, ranked: &mut [(usize, f64, f64)]) {
    let Some(&(best, _, gain)) = ranked.first() else {
        return;
    };
    let same = ranked
        .iter()
        .take_while(|r| r.2 >= (1.0 - SAME_FIT) * gain)
        .count();
    let most_specific = (0..same)
        .filter(|&i| compatible(&groups.list[best], &groups.list[ranked[i].0]))
        .max_by_key(|&i| (specificity(&groups.list[ranked[i].0]), std::cmp::Reverse(i)));
    if let Some(i) = most_specific {
        ranked[..=i].rotate_right(1);
    }
    prefer_self_shadow_bug(groups, ranked);
}

/// Shadows missing on one object alone, where they are all the object's own (the same
/// picture as an object that never shadows itself, within [`ALIKE`]), are that bug: a
/// tracer whose shadow ray skips the object it leaves is common, one that drops the
/// shadows of a single object is not. The factor stays a reading that fits as well.
fn prefer_self_shadow_bug(groups: &Groups, ranked: &mut [(usize, f64, f64)]) {
    let Some(&(best, _, gain)) = ranked.first() else {
        return;
    };
    let shadows = &groups.list[best];
    let bug = ranked
        .iter()
        .take_while(|r| r.2 >= (1.0 - ALIKE) * gain)
        .position(|r| self_shadow_story(shadows, &groups.list[r.0]));
    if let Some(i) = bug {
        ranked[..=i].rotate_right(1);
    }
}

/// The groups other than `chosen` that fit alike with it before it was applied and
/// whose gain it took (they explain the same pixels); of two that tell one story (one
/// nested in the other), the more specific.
pub(super) fn alike(
    groups: &Groups,
    chosen: usize,
    before: &[(usize, f64, f64)],
    after: &[(usize, f64, f64)],
) -> Vec<usize> {
    let gain = before.iter().find(|r| r.0 == chosen).map_or(0.0, |r| r.2);
    let alike: Vec<usize> = before
        .iter()
        .filter(|r| r.0 != chosen && r.2 >= (1.0 - ALIKE) * gain)
        .filter(|r| {
            let kept = after.iter().find(|a| a.0 == r.0).map_or(0.0, |a| a.2);
            kept < 0.5 * r.2
        })
        .map(|r| r.0)
        .collect();
    alike
        .iter()
        .copied()
        .filter(|&g| {
            let group = &groups.list[g];
            !alike.iter().any(|&h| {
                let other = &groups.list[h];
                h != g && compatible(group, other) && specificity(other) > specificity(group)
            })
        })
        .collect()
}

/// Whether `shadows` (shadows missing on an object) and `bug` (the object never shadowing
/// itself, on it or a part of it) tell one story: where they fit alike they are one
/// picture, so neither is the other's competitor.
fn self_shadow_story(shadows: &Group, bug: &Group) -> bool {
    shadows.family == Family::Shadow
        && shadows.object.is_some()
        && bug.family == Family::ShadowTest(ShadowBug::NoSelfShadow)
        && bug.object.is_some()
        && bug.leaves.start >= shadows.leaves.start
        && bug.leaves.end <= shadows.leaves.end
}

/// How sure a step is against its best competitor: among the groups telling another
/// story, those whose gain the step took (it fell by half or more once the step was
/// applied; a group that keeps its gain explains something else), the best (an object's
/// shadows missing and it never shadowing itself are one story, not rivals). With `g`
/// the step's gain, `g_r` the competitor's and `left` the error the step leaves on the
/// pixels it changed, `(g - g_r) / (g - g_r + left)`: what the step explains beyond the
/// competitor, against what it leaves unexplained where it acts.
pub(super) fn margin(
    groups: &Groups,
    chosen: usize,
    before: &[(usize, f64, f64)],
    after: &[(usize, f64, f64)],
    left: f64,
) -> f64 {
    let gain = before.iter().find(|r| r.0 == chosen).map_or(0.0, |r| r.2);
    let rival = before
        .iter()
        .filter(|r| {
            let (a, b) = (&groups.list[chosen], &groups.list[r.0]);
            r.0 != chosen
                && !compatible(a, b)
                && !self_shadow_story(b, a)
                && !self_shadow_story(a, b)
        })
        .filter(|r| {
            let kept = after.iter().find(|a| a.0 == r.0).map_or(0.0, |a| a.2);
            kept < 0.5 * r.2
        })
        .map(|r| r.2)
        .fold(0.0, f64::max);
    let beyond = (gain - rival).max(0.0);
    if beyond + left <= 0.0 {
        0.0
    } else {
        beyond / (beyond + left)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn group(family: Family) -> Group {
        Group::of_one_channel(family)
    }

    #[test]
    fn groups_that_name_different_lights_or_terms_compete() {
        let mut a = group(Family::Diffuse);
        let mut b = group(Family::Diffuse);
        assert!(compatible(&a, &b));
        (a.light, b.light) = (Some(0), Some(1));
        assert!(!compatible(&a, &b));
        b.light = None;
        assert!(compatible(&a, &b));
        assert!(!compatible(&a, &group(Family::Specular)));
    }

    #[test]
    fn a_node_and_its_parts_tell_one_story_and_the_deeper_is_more_specific() {
        let mut object = group(Family::Diffuse);
        object.leaves = 0..3;
        let mut pip = group(Family::Diffuse);
        (pip.object, pip.leaves, pip.depth) = (Some(2), 1..2, 1);
        let mut other = group(Family::Diffuse);
        (other.object, other.leaves) = (Some(4), 3..4);
        assert!(compatible(&object, &pip) && compatible(&pip, &object));
        assert!(!compatible(&pip, &other) && !compatible(&object, &other));
        assert!(specificity(&pip) > specificity(&object));
    }
}
