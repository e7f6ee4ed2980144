//! Which pixels an edit of materials or switches leaves as they were, and the summary of
//! a cached tile that lets a whole tile be kept in one test: most tiles of a material
//! edit meet no object of that material, and then no pixel of theirs needs looking at.

use super::chains::Chains;
use super::dependence::TermDependence;
use super::pixel_colour::PixelColour;
use crate::trace::ray_counts::RayCounts;

/// Which pixels an edit leaves as they were: none of whose rays meets an object whose
/// material changed, and that depend on none of the switches that changed.
#[derive(Clone, Debug)]
pub(crate) struct KeepRule {
    /// Per world object, whether its material changed; `None`: none did.
    changed_objects: Option<Vec<bool>>,
    /// The changed objects as an [`ObjectMask`].
    changed_mask: ObjectMask,
    /// The switches that changed.
    switched: TermDependence,
}

impl KeepRule {
    /// Per world object whether its material changed, and the switches that changed.
    #[must_use]
    pub fn new(changed_objects: Vec<bool>, switched: TermDependence) -> Self {
        let mut changed_mask = ObjectMask::default();
        for (object, _) in changed_objects.iter().enumerate().filter(|(_, c)| **c) {
            changed_mask.add(object as u32);
        }
        Self {
            changed_objects: changed_objects.contains(&true).then_some(changed_objects),
            changed_mask,
            switched,
        }
    }

    /// Whether a pixel whose chain met `objects` (`u32::MAX`: a miss) and whose colour
    /// had dependence `depends` keeps its colour.
    #[must_use]
    #[inline]
    pub fn keeps(&self, objects: &[u32], depends: TermDependence) -> bool {
        !depends.meets(self.switched)
            && self.changed_objects.as_ref().is_none_or(|changed| {
                !objects
                    .iter()
                    .any(|&o| o != u32::MAX && changed[o as usize])
            })
    }

    /// Whether every pixel of the tile `summary` sums up keeps its colour. `false` may
    /// still keep them all (the mask is coarse): ask [`Self::keeps`] pixel by pixel.
    #[must_use]
    pub fn keeps_tile(&self, summary: &TileSummary) -> bool {
        !summary.depends.meets(self.switched) && !summary.objects.meets(self.changed_mask)
    }
}

/// A set of objects, coarsely: object `o` sets bit `o % 64`. Two masks that share no bit
/// share no object.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct ObjectMask(u64);

impl ObjectMask {
    /// Adds object `object` (`u32::MAX`, a miss, is no object).
    #[inline]
    pub fn add(&mut self, object: u32) {
        if object != u32::MAX {
            self.0 |= 1 << (object % 64);
        }
    }

    /// Whether the two sets may share an object.
    #[must_use]
    pub fn meets(self, other: Self) -> bool {
        self.0 & other.0 != 0
    }
}

/// What one cached tile's pixels depend on, all together, and the rays behind them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct TileSummary {
    /// The union of the pixels' dependences.
    depends: TermDependence,
    /// Every object the tile's chains met.
    objects: ObjectMask,
    /// The rays of all its pixels.
    pub rays: RayCounts,
}

impl TileSummary {
    /// The summary of a tile whose pixels have `chains` and `colours`.
    #[must_use]
    pub fn of(chains: &Chains, colours: &[PixelColour]) -> Self {
        let mut summary = Self::default();
        for colour in colours {
            summary.depends = summary.depends.union(colour.depends);
            summary.rays.add(&colour.counts());
        }
        for &object in chains.objects(0..chains.len()) {
            summary.objects.add(object);
        }
        summary
    }

    /// The summary of this tile's chains once its pixels came out with dependences
    /// `depends` all together, made of `rays`.
    #[must_use]
    pub fn reshaded(self, depends: TermDependence, rays: RayCounts) -> Self {
        Self {
            depends,
            rays,
            ..self
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn object_masks_meet_when_they_may_share_an_object() {
        let mut floor = ObjectMask::default();
        floor.add(0);
        floor.add(u32::MAX);
        let mut others = ObjectMask::default();
        others.add(1);
        others.add(2);
        assert!(!floor.meets(others));
        // 64 lands on 0's bit: a coarse mask may say "meets" for distinct objects, never
        // the other way round.
        others.add(64);
        assert!(floor.meets(others));
        assert!(!ObjectMask::default().meets(floor));
    }

    #[test]
    fn a_tile_is_kept_only_if_no_changed_object_and_no_switched_term_is_in_it() {
        let switched = TermDependence::ANY;
        let mut summary = TileSummary::default();
        summary.objects.add(3);
        assert!(KeepRule::new(vec![false; 5], TermDependence::NONE).keeps_tile(&summary));
        let mut changed = vec![false; 5];
        changed[3] = true;
        assert!(!KeepRule::new(changed.clone(), TermDependence::NONE).keeps_tile(&summary));
        changed[3] = false;
        changed[4] = true;
        assert!(KeepRule::new(changed, TermDependence::NONE).keeps_tile(&summary));
        // A tile that depends on nothing keeps through any switch; one that depends on
        // everything through none.
        assert!(KeepRule::new(vec![false; 5], switched).keeps_tile(&summary));
        summary.depends = TermDependence::ANY;
        assert!(!KeepRule::new(vec![false; 5], switched).keeps_tile(&summary));
    }

    #[test]
    fn every_cached_tile_holds_its_own_summary_and_a_material_edit_keeps_whole_tiles() {
        use crate::trace::{RenderOptions, RenderProgress, Term, World, render_one_sample_cached};
        use std::sync::Arc;
        let mut scene = crate::scene::examples::default_scene();
        scene.camera.width = 96;
        scene.camera.height = 64;
        let mut options = RenderOptions::from_scene(&scene);
        let progress = RenderProgress::default();
        let world = World::new(&scene).unwrap();
        let mut cache = render_one_sample_cached(&world, &options, None, &progress)
            .unwrap()
            .cache;
        // A material edit (the floor), then a switch, then no edit at all.
        let floor = scene.objects[0].material.clone();
        scene.materials.get_mut(&floor).unwrap().diffuse = glam::DVec3::new(0.8, 0.3, 0.2);
        for edit in 0..3 {
            if edit == 1 {
                options.switches.set(Term::Specular, false);
            }
            let world = World::new(&scene).unwrap();
            let pass = render_one_sample_cached(&world, &options, Some(&cache), &progress).unwrap();
            let mut kept_whole = 0;
            for (old, new) in cache.tiles.iter().zip(&pass.cache.tiles) {
                assert_eq!(new.summary, TileSummary::of(&new.chains, &new.colours));
                kept_whole += usize::from(Arc::ptr_eq(&old.colours, &new.colours));
            }
            let tiles = cache.tiles.len();
            // Some tiles see no floor and no lobe; with no edit every tile is kept.
            assert!(
                kept_whole > 0 && kept_whole < tiles || edit == 2,
                "{edit}: {kept_whole}"
            );
            assert!(edit != 2 || kept_whole == tiles && pass.shaded_pixels == 0);
            cache = pass.cache;
        }
    }
}
