//! The components raylab's picture is split into, and their numbering. A *channel* is
//! one kind of contribution on one leaf of the object trees ([`super::nodes`]; in a
//! scene without trees, one object): the ambient term of the floor, light 2's diffuse
//! term on the ball, the ball's picture if its normals lacked their z part... A tree's
//! inner node tried as missing has two channels of its own. Every channel is a
//! per-pixel colour; the fit scales them.

use super::bugs::{ClampBug, NormalBug, Part, ShadowBug, SpawnBug, SpecularBug};
use super::spot_bugs::SpotBug;

/// What a channel holds. Light indices are positions in the world's list of
/// non-ambient lights.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kind {
    /// `ka * ambient` at every hit of the object (mirrored hits weighted by the mirrors).
    Ambient,
    /// `km * colour(reflected ray)` at the object's hits: the whole mirror image in it.
    Reflection,
    /// `kt * colour(transmitted ray)` at the object's hits: all that is seen through it.
    Transmission,
    /// The light the object's shadows take away from other surfaces, where no other
    /// object blocks it (0 in raylab's picture): part of the object's missing picture.
    ShadowCast,
    /// Light `l`'s diffuse term, as shadowed, at the object's hits.
    Diffuse(usize),
    /// Light `l`'s specular term, as shadowed, at the object's hits.
    Specular(usize),
    /// What light `l` would add where it is shadowed (0 in raylab's picture).
    Shadow(usize),
    /// The change of the object's diffuse and specular terms under a normal bug.
    Normal(NormalBug),
    /// The change of the object's specular term under a specular bug.
    Highlight(SpecularBug),
    /// The change of a pixel seeing the object under a clamping bug.
    Clamp(ClampBug),
    /// The change of the object's lit terms under a shadow bug.
    ShadowTest(ShadowBug),
    /// The change of the object's mirror term under a spawning bug.
    Spawn(SpawnBug),
    /// The change of the pixels where a part of the object is seen, if it were missing.
    Missing(Part),
    /// The change of the pixels seeing the object under a bug of spot light `l`.
    Spot(SpotBug, usize),
    /// Rays that hit nothing (object: none).
    Background,
    /// The change of the pixels an inner node of a tree changes, if it were missing
    /// (object: the node's slot, [`super::missing_nodes::Slot::Inner`]).
    NodeMissing,
    /// The light an inner node's shadows take away (object: its slot).
    NodeShadowCast,
}

/// A family: the channels a group may combine (across lights and objects).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Family {
    /// [`Kind::Ambient`].
    Ambient,
    /// [`Kind::Reflection`].
    Reflection,
    /// [`Kind::Transmission`].
    Transmission,
    /// [`Kind::Diffuse`].
    Diffuse,
    /// [`Kind::Specular`].
    Specular,
    /// [`Kind::Shadow`].
    Shadow,
    /// [`Kind::Normal`] of one bug.
    Normal(NormalBug),
    /// [`Kind::Highlight`] of one bug.
    Highlight(SpecularBug),
    /// [`Kind::Clamp`] of one bug.
    Clamp(ClampBug),
    /// [`Kind::ShadowTest`] of one bug.
    ShadowTest(ShadowBug),
    /// [`Kind::Spawn`] of one bug.
    Spawn(SpawnBug),
    /// [`Kind::Missing`], any part, and [`Kind::ShadowCast`].
    Missing,
    /// [`Kind::Spot`] of one bug.
    Spot(SpotBug),
    /// [`Kind::Background`].
    Background,
}

impl Kind {
    /// The family of the kind.
    #[must_use]
    pub fn family(self) -> Family {
        match self {
            Kind::Ambient => Family::Ambient,
            Kind::Reflection => Family::Reflection,
            Kind::Transmission => Family::Transmission,
            Kind::Diffuse(_) => Family::Diffuse,
            Kind::Specular(_) => Family::Specular,
            Kind::Shadow(_) => Family::Shadow,
            Kind::Normal(b) => Family::Normal(b),
            Kind::Highlight(b) => Family::Highlight(b),
            Kind::Clamp(b) => Family::Clamp(b),
            Kind::ShadowTest(b) => Family::ShadowTest(b),
            Kind::Spawn(b) => Family::Spawn(b),
            Kind::Missing(_) | Kind::ShadowCast | Kind::NodeMissing | Kind::NodeShadowCast => {
                Family::Missing
            }
            Kind::Spot(b, _) => Family::Spot(b),
            Kind::Background => Family::Background,
        }
    }

    /// The light of a per-light kind.
    #[must_use]
    pub fn light(self) -> Option<usize> {
        match self {
            Kind::Diffuse(l) | Kind::Specular(l) | Kind::Shadow(l) | Kind::Spot(_, l) => Some(l),
            _ => None,
        }
    }

    /// Whether the kind's object is an inner node's slot rather than a leaf.
    #[must_use]
    pub fn is_of_node(self) -> bool {
        matches!(self, Kind::NodeMissing | Kind::NodeShadowCast)
    }

    /// Whether the kind is part of raylab's picture (the channels of these sum to it);
    /// the others are directions of change.
    #[must_use]
    pub fn is_partition(self) -> bool {
        matches!(
            self,
            Kind::Ambient | Kind::Diffuse(_) | Kind::Specular(_) | Kind::Background
        )
    }
}

/// Numbers the channels of a world with `lights` non-ambient lights, `objects` leaves
/// and `nodes` inner nodes tried as missing: each leaf's block, the background, then
/// two per inner node (so a scene without trees is numbered as before trees).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ChannelSpace {
    /// Non-ambient lights.
    pub lights: usize,
    /// Leaves (in a scene without trees, its objects).
    pub objects: usize,
    /// Inner nodes tried as missing.
    pub nodes: usize,
}

/// Kinds per object that do not depend on a light.
const FIXED: usize = 4;

impl ChannelSpace {
    fn per_object(&self) -> usize {
        FIXED
            + 3 * self.lights
            + NormalBug::ALL.len()
            + SpecularBug::ALL.len()
            + ClampBug::ALL.len()
            + Part::ALL.len()
            + SpotBug::ALL.len() * self.lights
            + ShadowBug::ALL.len()
            + SpawnBug::ALL.len()
    }

    /// How many channels there are.
    #[must_use]
    pub fn count(&self) -> usize {
        self.objects * self.per_object() + 1 + 2 * self.nodes
    }

    /// The channel of `kind` on `object` (`None` only for the background; an inner
    /// node's slot for [`Kind::is_of_node`]).
    ///
    /// # Panics
    /// When the object or light index is out of range, or the background has an object.
    #[must_use]
    pub fn id(&self, kind: Kind, object: Option<usize>) -> u32 {
        let l = self.lights;
        let (nb, sb, cb) = (
            NormalBug::ALL.len(),
            SpecularBug::ALL.len(),
            ClampBug::ALL.len(),
        );
        let slot = match kind {
            Kind::Background => {
                assert!(object.is_none(), "the background belongs to no object");
                return (self.objects * self.per_object()) as u32;
            }
            Kind::NodeMissing | Kind::NodeShadowCast => {
                let node = object.expect("a node's channel has its slot");
                assert!(node < self.nodes, "node {node} of {}", self.nodes);
                let second = u32::from(kind == Kind::NodeShadowCast);
                return (self.objects * self.per_object() + 1 + 2 * node) as u32 + second;
            }
            Kind::Ambient => 0,
            Kind::Reflection => 1,
            Kind::Transmission => 2,
            Kind::ShadowCast => 3,
            Kind::Diffuse(i) => FIXED + i,
            Kind::Specular(i) => FIXED + l + i,
            Kind::Shadow(i) => FIXED + 2 * l + i,
            Kind::Normal(b) => FIXED + 3 * l + b as usize,
            Kind::Highlight(b) => FIXED + 3 * l + nb + b as usize,
            Kind::Clamp(b) => FIXED + 3 * l + nb + sb + b as usize,
            Kind::Missing(p) => FIXED + 3 * l + nb + sb + cb + p as usize,
            Kind::Spot(b, i) => FIXED + 3 * l + nb + sb + cb + Part::ALL.len() + b as usize * l + i,
            Kind::ShadowTest(b) => {
                FIXED + 3 * l + nb + sb + cb + Part::ALL.len() + SpotBug::ALL.len() * l + b as usize
            }
            Kind::Spawn(b) => {
                FIXED
                    + 3 * l
                    + nb
                    + sb
                    + cb
                    + Part::ALL.len()
                    + SpotBug::ALL.len() * l
                    + ShadowBug::ALL.len()
                    + b as usize
            }
        };
        if let Some(i) = kind.light() {
            assert!(i < l, "light {i} of {l}");
        }
        let object = object.expect("every kind but the background has an object");
        assert!(object < self.objects, "object {object} of {}", self.objects);
        (object * self.per_object() + slot) as u32
    }

    /// The kind and object of a channel.
    #[must_use]
    pub fn decode(&self, id: u32) -> (Kind, Option<usize>) {
        let id = id as usize;
        let per = self.per_object();
        if id == self.objects * per {
            return (Kind::Background, None);
        }
        if id > self.objects * per {
            let slot = id - self.objects * per - 1;
            let kind = [Kind::NodeMissing, Kind::NodeShadowCast][slot % 2];
            return (kind, Some(slot / 2));
        }
        let (object, slot) = (id / per, id % per);
        let l = self.lights;
        let (nb, sb, cb) = (
            NormalBug::ALL.len(),
            SpecularBug::ALL.len(),
            ClampBug::ALL.len(),
        );
        let shadow_tests = FIXED + 3 * l + nb + sb + cb + Part::ALL.len() + SpotBug::ALL.len() * l;
        let kind = match slot {
            0 => Kind::Ambient,
            1 => Kind::Reflection,
            2 => Kind::Transmission,
            3 => Kind::ShadowCast,
            s if s < FIXED + l => Kind::Diffuse(s - FIXED),
            s if s < FIXED + 2 * l => Kind::Specular(s - FIXED - l),
            s if s < FIXED + 3 * l => Kind::Shadow(s - FIXED - 2 * l),
            s if s < FIXED + 3 * l + nb => Kind::Normal(NormalBug::ALL[s - FIXED - 3 * l]),
            s if s < FIXED + 3 * l + nb + sb => {
                Kind::Highlight(SpecularBug::ALL[s - FIXED - 3 * l - nb])
            }
            s if s < FIXED + 3 * l + nb + sb + cb => {
                Kind::Clamp(ClampBug::ALL[s - FIXED - 3 * l - nb - sb])
            }
            s if s < FIXED + 3 * l + nb + sb + cb + Part::ALL.len() => {
                Kind::Missing(Part::ALL[s - FIXED - 3 * l - nb - sb - cb])
            }
            s if s < FIXED + 3 * l + nb + sb + cb + Part::ALL.len() + SpotBug::ALL.len() * l => {
                let spot = s - FIXED - 3 * l - nb - sb - cb - Part::ALL.len();
                Kind::Spot(SpotBug::ALL[spot / l], spot % l)
            }
            s if s < shadow_tests + ShadowBug::ALL.len() => {
                Kind::ShadowTest(ShadowBug::ALL[s - shadow_tests])
            }
            s => Kind::Spawn(SpawnBug::ALL[s - shadow_tests - ShadowBug::ALL.len()]),
        };
        (kind, Some(object))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_channel_decodes_to_itself() {
        let space = ChannelSpace {
            lights: 3,
            objects: 4,
            nodes: 2,
        };
        let mut seen = std::collections::HashSet::new();
        for id in 0..space.count() as u32 {
            let (kind, object) = space.decode(id);
            assert_eq!(space.id(kind, object), id);
            assert!(seen.insert((kind, object)));
        }
    }
}
