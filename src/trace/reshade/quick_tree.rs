//! The quick re-shade of a pixel whose cached entries form a tree (there is glass): the
//! tree the shader would follow, walked breadth first from the camera ray's entry, each
//! ray shaded as [`QuickShade`] shades one, then folded back from the last ray walked as
//! [`crate::trace::shade::fold_back`] folds the shader's, so bit for bit its colour.

use glam::DVec3;
use smallvec::SmallVec;

use super::chains::{ChildRay, Children, NO_ENTRY, PixelEntries};
use super::dependence::TermDependence;
use super::quick_shade::QuickShade;
use crate::trace::ray_counts::RayCounts;
use crate::trace::shade::{Bounce, BroughtBack};

/// One ray of the tree the shader would follow, as [`QuickShade::tree_pixel`] walks it.
#[derive(Clone, Copy, Debug)]
struct Walked {
    entry: u32,
    depth: u32,
    /// The parent's index in the walk, and which of its rays this is.
    from: Option<(u32, ChildRay)>,
    bounce: Bounce,
    brought_back: BroughtBack,
}

impl QuickShade<'_> {
    /// [`Self::pixel`] for entries that form a tree (linked by `children`): the tree the
    /// shader would follow walked breadth first from the camera ray's entry, then folded
    /// back from the last ray walked, as [`crate::trace::shade::fold_back`] folds it.
    #[inline(never)]
    pub(super) fn tree_pixel(
        &self,
        entries: &PixelEntries,
        children: &[Children],
        lights: usize,
        counts: &mut RayCounts,
    ) -> Option<(DVec3, TermDependence)> {
        let mut own = RayCounts {
            primary: 1,
            ..RayCounts::default()
        };
        let mut walk: SmallVec<[Walked; 16]> = SmallVec::new();
        walk.push(Walked {
            entry: 0,
            depth: 0,
            from: None,
            bounce: Bounce::local(DVec3::ZERO),
            brought_back: BroughtBack::default(),
        });
        let mut depends = TermDependence::NONE;
        let mut index = 0;
        while index < walk.len() {
            let Walked { entry, depth, .. } = walk[index];
            let object = *entries.objects.get(entry as usize)?;
            let row = &entries.slots[entry as usize * lights..(entry as usize + 1) * lights];
            let (local, terms) = self.entry(depth as usize, object, row, &mut own)?;
            depends.add(depth as usize, terms);
            walk[index].bounce = match self.objects.get(object as usize) {
                Some(shade) => Bounce {
                    local,
                    km: shade.mirror,
                    kt: shade.transmission,
                },
                None => Bounce::local(local),
            };
            // The shader's order: the mirror ray, then the transmitted one.
            for (child, casts) in [
                (
                    ChildRay::Mirror,
                    self.casts_mirror_ray(depth as usize, object),
                ),
                (
                    ChildRay::Transmitted,
                    self.casts_transmitted_ray(depth as usize, object),
                ),
            ] {
                if !casts {
                    continue;
                }
                let to = children[entry as usize][child as usize];
                if to == NO_ENTRY {
                    return None;
                }
                match child {
                    ChildRay::Mirror => own.reflection += 1,
                    ChildRay::Transmitted => own.transmission += 1,
                }
                walk.push(Walked {
                    entry: to,
                    depth: depth + 1,
                    from: Some((index as u32, child)),
                    bounce: Bounce::local(DVec3::ZERO),
                    brought_back: BroughtBack::default(),
                });
            }
            index += 1;
        }
        for index in (1..walk.len()).rev() {
            let ray = walk[index];
            let colour = Some(ray.bounce.returns(ray.brought_back, &self.conventions));
            let (parent, child) = ray.from.expect("every ray but the camera ray has a parent");
            let slot = &mut walk[parent as usize].brought_back;
            match child {
                ChildRay::Mirror => slot.reflected = colour,
                ChildRay::Transmitted => slot.transmitted = colour,
            }
        }
        let root = &walk[0];
        counts.add(&own);
        Some((
            root.bounce.returns(root.brought_back, &self.conventions),
            depends,
        ))
    }
}
