//! A pixel's colour as the cache keeps it, with the rays it is made of and the switches
//! it depends on.

use glam::DVec3;

use super::dependence::TermDependence;
use crate::trace::ray_counts::RayCounts;

/// A pixel's colour in the pass that filled the cache (as the shader returned it, maybe
/// non-finite), the rays it is made of and the switches it depends on: kept for a pixel
/// no edit could change.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PixelColour {
    /// The colour.
    pub colour: DVec3,
    /// Shadow, mirror and transmitted rays behind it (and one camera ray: one sample a
    /// pixel), each saturating at `u32::MAX`.
    pub rays: [u32; 3],
    /// The switches whose change may change it.
    pub depends: TermDependence,
}

impl PixelColour {
    /// `colour`, made of the rays `rays`, depending on the switches `depends`.
    pub fn of(colour: DVec3, rays: &RayCounts, depends: TermDependence) -> Self {
        debug_assert_eq!(rays.primary, 1, "one camera ray a pixel");
        Self {
            colour,
            rays: [rays.shadow, rays.reflection, rays.transmission]
                .map(|n| u32::try_from(n).unwrap_or(u32::MAX)),
            depends,
        }
    }

    /// The rays behind it.
    pub fn counts(&self) -> RayCounts {
        RayCounts {
            primary: 1,
            shadow: u64::from(self.rays[0]),
            reflection: u64::from(self.rays[1]),
            transmission: u64::from(self.rays[2]),
        }
    }
}
