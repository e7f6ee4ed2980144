//! One tile's rays during the one-sample pass ([`crate::trace::render::cached`]): the
//! previous cache's entries and light slots read in place, grown where a pixel needs a ray
//! they lack (`super::pixel_rays` answers the shader from them).

use std::sync::Arc;

use glam::DVec3;
use smallvec::SmallVec;

use super::cached_hit::{CachedHit, NOT_CAST};
use super::chains::{Chains, ChildRay, PixelEntries};
use super::dependence::TermDependence;
use super::hit_cache::TileHits;
use super::keep_rule::{KeepRule, TileSummary};
use super::light_factors::LightSlot;
use super::pixel_colour::PixelColour;
use crate::trace::ray_counts::RayCounts;
use crate::trace::shade::{LitFactors, RayAt};

/// One tile's rays during the pass. It reads the previous cache's entries in place,
/// shared, until a pixel needs a ray the cache lacks; from then on the tile's entries are
/// rebuilt (the pixels before copied at once, each later one as it comes). Light slots
/// are written into the shared ones on first change (copied once per tile).
pub(crate) struct TileRays {
    pub(super) chains: Arc<Chains>,
    slots: Arc<Vec<LightSlot>>,
    /// The rebuilt chains and slots, once one chain had to grow.
    pub(super) grown: Option<(Chains, Vec<LightSlot>)>,
    /// The pixels' colours in the cache read (none for a fresh tile), and in this pass
    /// once one of them changed (until then the old ones stand for them).
    old_colours: Option<Arc<Vec<PixelColour>>>,
    colours: Option<Vec<PixelColour>>,
    /// The summary of the tile read, which still holds while its chains and colours do,
    /// and the one worked out as [`Self::whole_tile`] re-shaded it.
    old_summary: TileSummary,
    new_summary: Option<TileSummary>,
    /// Pixels shaded so far, and of them those shaded from light factors alone.
    pub shaded: u64,
    pub quick: u64,
    /// The pixel being shaded, row-major within the tile, and its chain in the chains
    /// read.
    pixel: usize,
    read_chain: std::ops::Range<usize>,
    /// Where the pixel's entries start, read or rebuilt (rebuilding keeps the entries
    /// before it where they were, so this holds for the whole pixel).
    entry_start: usize,
    /// Per ray of the pixel's tree shaded so far ([`RayAt::node`]), its entry (from the
    /// pixel's first).
    nodes: SmallVec<[u32; 16]>,
    pub(super) lights: usize,
    pub traced: RayCounts,
}

/// How the light slots of the cache read map onto the lights of the new world.
pub(crate) struct SlotColumns<'a> {
    /// Lights per entry in the cache read.
    pub old_lights: usize,
    /// Per new light, the old column whose shadow answers stay valid.
    pub shadows: &'a [Option<usize>],
    /// Per new light, the old column whose light factors stay valid.
    pub factors: &'a [Option<usize>],
    /// Per world object, whether its transmitted rays go another way now (its `ior`
    /// changed): the entries below them are dropped, to be traced again. `None`: no
    /// object's do.
    pub bent: Option<&'a [bool]>,
}

impl TileRays {
    /// Reading `old` for a world whose lights keep the old columns `columns` names.
    pub fn reading(old: &TileHits, columns: &SlotColumns) -> Self {
        let old_lights = columns.old_lights;
        let same_lights = columns.shadows.len() == old_lights
            && (0..old_lights)
                .all(|i| columns.shadows[i] == Some(i) && columns.factors[i] == Some(i));
        let slots = if same_lights {
            Arc::clone(&old.slots)
        } else {
            // Entry by entry, not chunks of the old rows: the old world may have had no
            // light at all.
            let lights = columns.shadows.len();
            let mut remapped = Vec::with_capacity(old.chains.len() * lights);
            for entry in 0..old.chains.len() {
                let row = &old.slots[entry * old_lights..(entry + 1) * old_lights];
                for (shadow, factors) in columns.shadows.iter().zip(columns.factors) {
                    remapped.push(LightSlot {
                        shadow: shadow.map_or(NOT_CAST, |c| row[c].shadow),
                        factors: factors.map_or(LitFactors::UNKNOWN, |c| row[c].factors),
                    });
                }
            }
            Arc::new(remapped)
        };
        let lights = columns.shadows.len();
        // (The summary read still holds: its objects, a superset of those kept, are
        // what decides whether the tile can be kept whole, and a pixel with an entry cut
        // met a changed material, so it is shaded.)
        let pruned = columns.bent.and_then(|bent| {
            old.chains.pruned(&slots, lights, |object, child| {
                child == ChildRay::Transmitted && bent.get(object as usize) == Some(&true)
            })
        });
        let (chains, slots) = match pruned {
            Some((chains, slots)) => (Arc::new(chains), Arc::new(slots)),
            None => (Arc::clone(&old.chains), slots),
        };
        Self {
            old_colours: Some(Arc::clone(&old.colours)),
            old_summary: old.summary,
            ..Self::at_start(chains, slots, lights)
        }
    }

    /// A tile with nothing cached, for a world with `lights` lights, with room for
    /// `entries` entries: growing a tile's chains reallocates and copies them.
    pub fn fresh(pixels: usize, lights: usize, entries: usize) -> Self {
        Self {
            grown: Some((
                Chains::with_capacity(pixels, entries),
                Vec::with_capacity(entries * lights),
            )),
            colours: Some(Vec::with_capacity(pixels)),
            ..Self::at_start(
                Arc::new(Chains::empty(pixels)),
                Arc::new(Vec::new()),
                lights,
            )
        }
    }

    /// A tile reading `chains` and `slots`, before its first pixel: nothing grown, no
    /// colours kept, nothing counted.
    fn at_start(chains: Arc<Chains>, slots: Arc<Vec<LightSlot>>, lights: usize) -> Self {
        Self {
            chains,
            slots,
            grown: None,
            old_colours: None,
            colours: None,
            old_summary: TileSummary::default(),
            new_summary: None,
            shaded: 0,
            quick: 0,
            pixel: 0,
            read_chain: 0..0,
            entry_start: 0,
            nodes: SmallVec::new(),
            lights,
            traced: RayCounts::default(),
        }
    }

    /// Starts the next pixel: once rebuilding, copies its cached entries across.
    pub fn begin_pixel(&mut self) {
        self.read_chain = self.chains.chain(self.pixel);
        self.entry_start = self.chain().start;
        self.nodes.clear();
        // Nothing to copy for an empty chain (each of a fresh tile's).
        if let Some((chains, slots)) = self.grown.as_mut().filter(|_| !self.read_chain.is_empty()) {
            let chain = self.read_chain.clone();
            let lights = self.lights;
            slots.extend_from_slice(&self.slots[chain.start * lights..chain.end * lights]);
            chains.extend_from(&self.chains, chain);
        }
    }

    /// The light slot of light `light` at the entry of ray `node` of the current
    /// pixel's tree (found or traced already).
    #[inline]
    pub(super) fn slot_index(&self, node: u32, light: usize) -> usize {
        debug_assert_eq!(self.entry_start, self.chain().start);
        (self.entry_start + self.nodes[node as usize] as usize) * self.lights + light
    }

    /// The entry (in the chains read or rebuilt) of ray `at` of the current pixel's
    /// tree, if the cache holds it. Rays are asked for in the order of their
    /// [`RayAt::node`], each parent before its children.
    #[inline]
    pub(super) fn entry_for(&mut self, at: RayAt) -> Option<usize> {
        debug_assert_eq!(self.nodes.len(), at.node as usize, "rays in tree order");
        let pixel = self.chain();
        let entry = match at.from {
            None => (!pixel.is_empty()).then_some(0)?,
            Some((parent, branch)) => {
                let parent = self.nodes[parent as usize];
                let chains = self.grown.as_ref().map_or(&*self.chains, |(c, _)| c);
                chains.child(pixel.clone(), parent, ChildRay::of(branch))?
            }
        };
        self.nodes.push(entry);
        Some(pixel.start + entry as usize)
    }

    /// Adds the hit of ray `at` of the current pixel's tree, which the cache lacked
    /// ([`Self::entry_for`] said so), with no light slot known.
    pub(super) fn push_entry(&mut self, at: RayAt, hit: CachedHit) {
        let from = at
            .from
            .map(|(parent, branch)| (self.nodes[parent as usize], ChildRay::of(branch)));
        let lights = self.lights;
        let (chains, slots) = self.grow();
        let entry = chains.push(from, hit);
        slots.resize(slots.len() + lights, LightSlot::NOTHING);
        self.nodes.push(entry);
    }

    /// Entry `index` of the chains read or rebuilt.
    #[inline]
    pub(super) fn hit(&self, index: usize) -> &CachedHit {
        match &self.grown {
            Some((chains, _)) => chains.hit(index),
            None => self.chains.hit(index),
        }
    }

    /// The current pixel's cached colour, if `keep` keeps it (and so its rays and colour
    /// are what they were).
    pub fn unchanged_colour(&self, keep: &KeepRule) -> Option<PixelColour> {
        let old = self.old_colours.as_ref()?[self.pixel];
        keep.keeps(self.pixel_entries().objects, old.depends)
            .then_some(old)
    }

    /// The current pixel's cached entries: the objects they met, their links and their
    /// light slots.
    pub fn pixel_entries(&self) -> PixelEntries<'_> {
        let (chains, slots) = match &self.grown {
            Some((chains, slots)) => (chains, slots),
            None => (&*self.chains, &*self.slots),
        };
        entries_of(chains, slots, self.chain(), self.lights)
    }

    /// The whole tile of a cache read, no ray traced: each pixel `keep` keeps keeps its
    /// colour, the others come from `shade` (given its entries, as
    /// [`Self::pixel_entries`]: their colour and dependence). The colours and rays of
    /// every pixel, row-major; `None`, with the tile as it was, where `shade` cannot
    /// answer for some pixel.
    pub fn whole_tile(
        &mut self,
        keep: Option<&KeepRule>,
        shade: impl Fn(&PixelEntries, &mut RayCounts) -> Option<(DVec3, TermDependence)>,
    ) -> Option<(Vec<DVec3>, RayCounts)> {
        let old = match (&self.grown, &self.old_colours) {
            (None, Some(old)) if self.pixel == 0 => Arc::clone(old),
            _ => return None,
        };
        if keep.is_some_and(|keep| keep.keeps_tile(&self.old_summary)) {
            // No pixel to look at: the tile's colours, chains and slots stay shared.
            self.pixel = old.len();
            return Some((
                old.iter().map(|p| p.colour).collect(),
                self.old_summary.rays,
            ));
        }
        let (chains, slots, lights) = (&*self.chains, &*self.slots, self.lights);
        let mut colours = Vec::with_capacity(old.len());
        let mut rays = RayCounts::default();
        // Written from the first pixel whose colour changed on.
        let mut new: Option<Vec<PixelColour>> = None;
        let mut shaded = 0;
        let mut depends_all = TermDependence::NONE;
        for (pixel, kept) in old.iter().enumerate() {
            let chain = chains.chain(pixel);
            let objects = chains.objects(chain.clone());
            if keep.is_some_and(|keep| keep.keeps(objects, kept.depends)) {
                depends_all = depends_all.union(kept.depends);
                colours.push(kept.colour);
                rays.add(&kept.counts());
                if let Some(new) = &mut new {
                    new.push(*kept);
                }
                continue;
            }
            let mut own = RayCounts::default();
            let (colour, depends) = shade(&entries_of(chains, slots, chain, lights), &mut own)?;
            shaded += 1;
            depends_all = depends_all.union(depends);
            colours.push(colour);
            rays.add(&own);
            new.get_or_insert_with(|| {
                // Sized for the whole tile: growing it pixel by pixel reallocated.
                let mut new = Vec::with_capacity(old.len());
                new.extend_from_slice(&old[..pixel]);
                new
            })
            .push(PixelColour::of(colour, &own, depends));
        }
        self.colours = new;
        // The chains are those read: so are the objects they met.
        self.new_summary = Some(self.old_summary.reshaded(depends_all, rays));
        self.pixel = old.len();
        self.shaded += shaded;
        self.quick += shaded;
        Some((colours, rays))
    }

    /// Ends the pixel, which came out `colour` (`kept`: its colour in the cache read,
    /// [`Self::unchanged_colour`]).
    pub fn end_pixel(&mut self, colour: PixelColour, kept: bool) {
        if let Some((chains, _)) = &mut self.grown {
            chains.end_chain();
        }
        match (&mut self.colours, &self.old_colours) {
            (Some(colours), _) => colours.push(colour),
            // Every pixel so far kept its colour: the old ones still stand for them.
            (None, Some(_)) if kept => {}
            (None, old) => {
                let mut colours = Vec::with_capacity(old.as_ref().map_or(0, |o| o.len()));
                colours.extend_from_slice(old.as_ref().map_or(&[][..], |o| &o[..self.pixel]));
                colours.push(colour);
                self.colours = Some(colours);
            }
        }
        self.pixel += 1;
    }

    /// Where the current pixel's entries are, in the chains read or rebuilt.
    pub(super) fn chain(&self) -> std::ops::Range<usize> {
        match &self.grown {
            Some((chains, _)) => chains.building(),
            None => self.read_chain.clone(),
        }
    }

    /// Starts rebuilding, copying every pixel's entries up to and including the current
    /// pixel's.
    pub(super) fn grow(&mut self) -> &mut (Chains, Vec<LightSlot>) {
        let (pixel, lights) = (self.pixel, self.lights);
        let (chains, slots) = (&self.chains, &self.slots);
        self.grown.get_or_insert_with(|| {
            let end = chains.chain(pixel).end;
            (chains.prefix(pixel, end), slots[..end * lights].to_vec())
        })
    }

    /// The light slot `index` (entry * lights + light) to write.
    #[inline(always)]
    pub(super) fn slot_mut(&mut self, index: usize) -> &mut LightSlot {
        match &mut self.grown {
            Some((_, slots)) => &mut slots[index],
            // Copied once per tile, while the cache before still holds the original.
            None => &mut Arc::make_mut(&mut self.slots)[index],
        }
    }

    /// The light slot `index` to read.
    #[inline(always)]
    pub(super) fn slot(&self, index: usize) -> LightSlot {
        match &self.grown {
            Some((_, slots)) => slots[index],
            None => self.slots[index],
        }
    }

    /// The tile's rays for the new cache.
    pub fn finish(self) -> TileHits {
        let unchanged = self.colours.is_none() && self.grown.is_none();
        let colours = match (self.colours, self.old_colours) {
            (Some(colours), _) => Arc::new(colours),
            (None, Some(old)) => old,
            (None, None) => Arc::new(Vec::new()),
        };
        let (chains, slots) = match self.grown {
            Some((chains, slots)) => (Arc::new(chains), Arc::new(slots)),
            None => (self.chains, self.slots),
        };
        let summary = match self.new_summary {
            _ if unchanged => self.old_summary,
            Some(summary) => summary,
            None => TileSummary::of(&chains, &colours),
        };
        TileHits {
            chains,
            slots,
            colours,
            summary,
        }
    }
}

/// The entries `range` of `chains`, with their light slots (`lights` per entry in
/// `slots`).
#[inline]
fn entries_of<'a>(
    chains: &'a Chains,
    slots: &'a [LightSlot],
    range: std::ops::Range<usize>,
    lights: usize,
) -> PixelEntries<'a> {
    PixelEntries {
        objects: chains.objects(range.clone()),
        children: chains.children(range.clone()),
        slots: &slots[range.start * lights..range.end * lights],
    }
}
