//! Each pixel's cached rays: the entries of its camera ray's tree (the camera ray's hit,
//! then the hit of each mirror and transmitted ray traced below it), in the order they
//! were traced, and how they link.
//!
//! A ray's entry is found by its parent's entry and which of the parent's rays it is,
//! never by its depth or its index in the tree: both change when an edit grows or prunes
//! the tree (a material given a transmission, a switch, `max_depth`), while a traced
//! ray's parent and branch do not.
//!
//! Most scenes have no glass, and then every pixel's entries are a mirror chain (entry
//! i + 1 is the mirror ray of entry i): no links are kept at all, so a chain costs what
//! it did before trees. The first entry that is not the mirror ray of the entry before it
//! (a transmitted ray, or a mirror ray of an entry that is not the last) gives the tile's
//! entries their links.

use std::ops::Range;

use super::cached_hit::CachedHit;
use super::light_factors::LightSlot;
use crate::trace::shade::Branch;

/// No entry: that ray was not traced.
pub(crate) const NO_ENTRY: u32 = u32::MAX;

/// Which of an entry's rays: its mirror ray, or its transmitted one (refracted or
/// internally reflected: the one share `kt`, whichever way Snell's law sends it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum ChildRay {
    Mirror = 0,
    Transmitted = 1,
}

impl ChildRay {
    /// The child a ray of branch `branch` is.
    #[inline]
    pub fn of(branch: Branch) -> Self {
        if branch.is_transmitted() {
            Self::Transmitted
        } else {
            Self::Mirror
        }
    }
}

/// An entry's children, indexed by [`ChildRay`]: each an entry of the same pixel (an
/// index from the pixel's first entry), or [`NO_ENTRY`].
pub(crate) type Children = [u32; 2];

/// One pixel's entries as the cache holds them.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PixelEntries<'a> {
    /// Each entry's object (`u32::MAX` for a miss); entry 0 is the camera ray's.
    pub objects: &'a [u32],
    /// Each entry's children; `None`: the entries are a mirror chain.
    pub children: Option<&'a [Children]>,
    /// `lights` light slots per entry.
    pub slots: &'a [LightSlot],
}

/// The entries of one tile's pixels, row-major within the tile.
#[derive(Clone, Debug, Default)]
pub(crate) struct Chains {
    /// End of each pixel's entries in `hits` (a pixel's start where the one before ends).
    chain_ends: Vec<u32>,
    /// Every pixel's entries, its camera ray's first.
    hits: Vec<CachedHit>,
    /// Each entry's object (`u32::MAX` for a miss) on its own: all a re-shade from light
    /// factors reads of an entry, 4 bytes instead of a whole hit.
    objects: Vec<u32>,
    /// Each entry's children; `None` while every pixel's entries are a mirror chain.
    children: Option<Vec<Children>>,
}

impl Chains {
    /// `pixels` pixels with no entries.
    pub fn empty(pixels: usize) -> Self {
        Self {
            chain_ends: vec![0; pixels],
            ..Self::default()
        }
    }

    /// No pixel yet, room for `pixels` of them with `entries` entries in all.
    pub fn with_capacity(pixels: usize, entries: usize) -> Self {
        Self {
            chain_ends: Vec::with_capacity(pixels),
            hits: Vec::with_capacity(entries),
            objects: Vec::with_capacity(entries),
            children: None,
        }
    }

    /// The entries of the first `pixels` pixels of `self` (and the entries up to `end`),
    /// with room for more.
    pub fn prefix(&self, pixels: usize, end: usize) -> Self {
        fn copy<T: Copy>(from: &[T], end: usize, room: usize) -> Vec<T> {
            let mut to = Vec::with_capacity(room);
            to.extend_from_slice(&from[..end]);
            to
        }
        let room = self.hits.len() + self.chain_ends.len() / 4;
        Self {
            chain_ends: self.chain_ends[..pixels].to_vec(),
            hits: copy(&self.hits, end, room),
            objects: copy(&self.objects, end, room),
            children: (self.children.as_deref()).map(|links| copy(links, end, room)),
        }
    }

    /// The range of entries holding pixel `pixel`'s.
    pub fn chain(&self, pixel: usize) -> Range<usize> {
        let start = pixel
            .checked_sub(1)
            .map_or(0, |p| self.chain_ends[p] as usize);
        start..self.chain_ends[pixel] as usize
    }

    /// Where the pixel being built starts: the end of the last pixel's entries.
    pub fn building(&self) -> Range<usize> {
        let start = self.chain_ends.last().map_or(0, |&end| end as usize);
        start..self.hits.len()
    }

    /// Entry `index`.
    pub fn hit(&self, index: usize) -> &CachedHit {
        &self.hits[index]
    }

    /// The objects of the entries `range`.
    pub fn objects(&self, range: Range<usize>) -> &[u32] {
        &self.objects[range]
    }

    /// The children of the entries `range`; `None` for a mirror chain.
    pub fn children(&self, range: Range<usize>) -> Option<&[Children]> {
        self.children.as_deref().map(|links| &links[range])
    }

    /// Whether some pixel's entries are not a mirror chain.
    pub fn has_trees(&self) -> bool {
        self.children.is_some()
    }

    /// The entry (from the pixel's first) of ray `child` of entry `parent`, among the
    /// pixel's entries `pixel`; `None` where that ray was not traced.
    #[inline]
    pub fn child(&self, pixel: Range<usize>, parent: u32, child: ChildRay) -> Option<u32> {
        match &self.children {
            // In a chain, entry i + 1 is entry i's mirror ray.
            None => (child == ChildRay::Mirror && (parent as usize + 1) < pixel.len())
                .then_some(parent + 1),
            Some(links) => {
                let entry = links[pixel.start + parent as usize][child as usize];
                (entry != NO_ENTRY).then_some(entry)
            }
        }
    }

    /// Entries held.
    pub fn len(&self) -> usize {
        self.hits.len()
    }

    /// Entries there is room for.
    pub fn capacity(&self) -> usize {
        self.hits.capacity()
    }

    /// Pixels there is room for.
    pub fn pixel_capacity(&self) -> usize {
        self.chain_ends.capacity()
    }

    /// Bytes per entry held: the hit, its object and, for trees, its links.
    pub fn entry_bytes(&self) -> usize {
        let links = if self.has_trees() {
            size_of::<Children>()
        } else {
            0
        };
        size_of::<CachedHit>() + size_of::<u32>() + links
    }

    /// Adds an entry to the pixel being built: its camera ray's (`from` `None`, the
    /// pixel's first entry) or ray `from.1` of its entry `from.0`. Returns the entry,
    /// from the pixel's first.
    pub fn push(&mut self, from: Option<(u32, ChildRay)>, hit: CachedHit) -> u32 {
        let building = self.building();
        let entry = u32::try_from(building.len()).expect("fewer than 2^32 rays a pixel");
        match from {
            None => debug_assert_eq!(entry, 0, "the camera ray comes first"),
            // The next link of a chain: still a chain.
            Some((parent, ChildRay::Mirror)) if self.children.is_none() && parent + 1 == entry => {}
            Some((parent, child)) => {
                self.links()[building.start + parent as usize][child as usize] = entry;
            }
        }
        self.objects.push(hit.object());
        self.hits.push(hit);
        if let Some(links) = &mut self.children {
            links.push([NO_ENTRY; 2]);
        }
        entry
    }

    /// Adds `other`'s entries `range` (one pixel's) to the pixel being built.
    pub fn extend_from(&mut self, other: &Chains, range: Range<usize>) {
        if other.has_trees() {
            self.links();
        }
        if let Some(links) = &mut self.children {
            match &other.children {
                Some(theirs) => links.extend_from_slice(&theirs[range.clone()]),
                None => links.extend((0..range.len()).map(|i| chain_link(i, range.len()))),
            }
        }
        self.hits.extend_from_slice(&other.hits[range.clone()]);
        self.objects.extend_from_slice(&other.objects[range]);
    }

    /// Ends the pixel being built: the next entry starts the next pixel's.
    pub fn end_chain(&mut self) {
        self.chain_ends.push(self.hits.len() as u32);
    }

    /// The links, made for the chains held if there were none.
    fn links(&mut self) -> &mut Vec<Children> {
        let (ends, len) = (&self.chain_ends, self.hits.len());
        self.children.get_or_insert_with(|| {
            let mut links = Vec::with_capacity(len.max(1) * 2);
            let mut start = 0;
            // Every pixel's entries, and those of the pixel being built.
            for end in ends.iter().map(|&e| e as usize).chain([len]) {
                links.extend((0..end - start).map(|i| chain_link(i, end - start)));
                start = end;
            }
            links
        })
    }

    /// The entries of every pixel but those below ray `child` of an entry on `object`
    /// where `cut(object, child)`, and their light slots (`lights` per entry, from
    /// `slots`); `None` where no entry is cut.
    pub fn pruned(
        &self,
        slots: &[LightSlot],
        lights: usize,
        cut: impl Fn(u32, ChildRay) -> bool,
    ) -> Option<(Chains, Vec<LightSlot>)> {
        let links = self.children.as_ref()?;
        let cuts = |entry: usize| {
            let object = self.objects[entry];
            [ChildRay::Mirror, ChildRay::Transmitted]
                .into_iter()
                .any(|child| links[entry][child as usize] != NO_ENTRY && cut(object, child))
        };
        if !(0..self.len()).any(cuts) {
            return None;
        }
        let mut kept = Chains::with_capacity(self.chain_ends.len(), self.len());
        kept.children = Some(Vec::with_capacity(self.len()));
        let mut kept_slots = Vec::with_capacity(slots.len());
        // Per entry of the pixel, its index among those kept (NO_ENTRY: cut; KEEP: to
        // be kept, not reached yet).
        const KEEP: u32 = NO_ENTRY - 1;
        let mut renumbered = Vec::new();
        for pixel in 0..self.chain_ends.len() {
            let range = self.chain(pixel);
            renumbered.clear();
            renumbered.resize(range.len(), NO_ENTRY);
            if let Some(root) = renumbered.first_mut() {
                *root = KEEP;
            }
            let mut count = 0;
            // Parents come before their children: an entry is kept when its parent is
            // and the ray from it is not cut.
            for local in 0..range.len() {
                if renumbered[local] != KEEP {
                    continue;
                }
                let entry = range.start + local;
                renumbered[local] = count;
                count += 1;
                kept.hits.push(self.hits[entry]);
                kept.objects.push(self.objects[entry]);
                kept_slots.extend_from_slice(&slots[entry * lights..(entry + 1) * lights]);
                for child in [ChildRay::Mirror, ChildRay::Transmitted] {
                    let to = links[entry][child as usize];
                    if to != NO_ENTRY && !cut(self.objects[entry], child) {
                        renumbered[to as usize] = KEEP;
                    }
                }
            }
            let kept_links = kept.children.as_mut().expect("made above");
            for local in (0..range.len()).filter(|&l| renumbered[l] != NO_ENTRY) {
                let old = links[range.start + local];
                kept_links.push(old.map(|to| {
                    if to == NO_ENTRY {
                        NO_ENTRY
                    } else {
                        renumbered[to as usize]
                    }
                }));
            }
            kept.end_chain();
        }
        Some((kept, kept_slots))
    }
}

/// The links of entry `index` of a mirror chain of `len` entries.
fn chain_link(index: usize, len: usize) -> Children {
    let next = if index + 1 < len {
        index as u32 + 1
    } else {
        NO_ENTRY
    };
    [next, NO_ENTRY]
}

#[cfg(test)]
mod tests;
