//! What each light gave each cached hit: the distance its strength falls off with, `n.l`
//! and the Phong lobe. From these the diffuse and specular terms follow for any kd, ks,
//! light strength and term switch, so [`super::quick_shade`] re-shades a pixel without a
//! ray, a light sample or a lobe. They depend on the geometry, on where each light is and
//! points ([`crate::trace::world::WorldLight::placement`]) and, for the lobe, on the shininess.

use super::cached_hit::NOT_CAST;
use super::object_materials::value_changed;
use crate::scene::Material;
use crate::trace::shade::LitFactors;
use crate::trace::world::{World, WorldLight};

/// What the cache keeps per hit and light: the shadow ray's answer
/// ([`super::cached_hit::encode_blocker`], or `NOT_CAST`) and the light's factors.
/// Packed to 28 bytes instead of 32: a re-shade reads little else, and waits on memory.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, packed(4))]
pub(crate) struct LightSlot {
    pub shadow: u32,
    pub factors: LitFactors,
}

impl LightSlot {
    /// No shadow ray cast, no factor known.
    pub const NOTHING: Self = Self {
        shadow: NOT_CAST,
        factors: LitFactors::UNKNOWN,
    };
}

/// Per light of `world`, the column of `old` placements ([`WorldLight::placement`]) whose
/// factors stay valid for it; `None` where they must be worked out again.
pub(crate) fn factor_columns(old: &[[u64; 8]], world: &World) -> Vec<Option<usize>> {
    world
        .lights
        .iter()
        .map(|light| {
            let placement = light.placement();
            old.iter().position(|p| *p == placement)
        })
        .collect()
}

/// Per object, whether the lobes cached for it are stale: its material's shininess is
/// not, bit for bit, the one they were worked out with.
pub(crate) fn stale_lobes(cached: &[Material], world: &World) -> Vec<bool> {
    value_changed(cached, world, |m| m.shininess).collect()
}

/// The placements of `world`'s lights, for [`factor_columns`].
pub(crate) fn placements(world: &World) -> Vec<[u64; 8]> {
    world.lights.iter().map(WorldLight::placement).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::world::LightSample;
    use glam::DVec3;

    /// A re-shade reads little but these slots: kept packed (28 bytes, not 32).
    #[test]
    fn a_light_slot_is_packed() {
        assert_eq!(size_of::<LightSlot>(), 4 + 3 * 8);
    }

    #[test]
    fn factors_decode_to_what_was_kept() {
        let sample = LightSample {
            radiance: DVec3::ONE,
            to_light: DVec3::Y,
            light_position: None,
            distance_squared: 2.5,
        };
        assert!(LitFactors::UNKNOWN.is_unknown());
        let unreachable = LitFactors::UNREACHABLE;
        assert!(!unreachable.is_unknown());
        assert_eq!(
            unreachable.n_dot_l(),
            f64::NEG_INFINITY,
            "no term, as behind"
        );
        for (n_dot_l, lobe) in [
            (0.5, Some(0.0)),
            (0.5, Some(0.25)),
            (0.5, None),
            (-0.2, None),
        ] {
            let factors = LitFactors::reached(&sample, n_dot_l, lobe);
            assert!(!factors.is_unknown());
            assert_eq!(factors.distance_squared(), 2.5);
            assert_eq!(factors.n_dot_l(), n_dot_l);
            assert_eq!(factors.lobe(), lobe);
        }
    }
}
