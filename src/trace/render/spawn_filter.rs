//! Which of the mirror and transmitted rays a tile batch's shading starts are traced:
//! all of them ([`TraceAll`], every render but the pruned one), or all but those whose
//! whole subtree can add less than a budget to its pixel ([`PruneBelow`]), keeping per
//! pixel the sum of the bounds of what was left out.

use glam::DVec3;

use crate::trace::shade::SubtreeBound;

/// Decides, level by level of a tile batch's ray trees, which rays to trace.
pub(crate) trait SpawnFilter {
    /// A batch starts: `count` camera rays, one per pixel of the tile in order.
    fn camera_rays(&mut self, count: usize);
    /// Whether to trace the ray at `depth` that ray `slot` of the current level starts
    /// with weight `k` (its km or kt). A ray kept takes the next slot of the next level.
    fn keep(&mut self, slot: usize, depth: u32, k: DVec3) -> bool;
    /// The next level becomes the current one.
    fn next_level(&mut self);
}

/// Every ray is traced.
pub(crate) struct TraceAll;

impl SpawnFilter for TraceAll {
    #[inline(always)]
    fn camera_rays(&mut self, _count: usize) {}

    #[inline(always)]
    fn keep(&mut self, _slot: usize, _depth: u32, _k: DVec3) -> bool {
        true
    }

    #[inline(always)]
    fn next_level(&mut self) {}
}

/// Leaves out a ray while its subtree's bound ([`SubtreeBound::of`]) fits in what its
/// sample has left of `budget`, and adds that bound to its pixel's `left_out`.
///
/// The budget is per sample in the units of a sample's colour: a pixel, the mean of its
/// samples, then moves by at most `budget` in all, whatever its sample count (each
/// sample's share of the pixel is 1/spp, and so is its share of the pixel's budget).
pub(crate) struct PruneBelow<'a> {
    bound: &'a SubtreeBound,
    budget: f64,
    /// Per pixel of the tile (row-major): the bounds of the rays left out, over every
    /// sample so far.
    left_out: &'a mut [DVec3],
    /// Per pixel: what this batch's sample may still leave out.
    room: Vec<DVec3>,
    /// Per ray of the current level: its path weight and its pixel.
    current: Vec<(DVec3, u32)>,
    /// The same for the rays kept for the next level.
    next: Vec<(DVec3, u32)>,
}

impl<'a> PruneBelow<'a> {
    /// A filter for one tile's batches, adding to `left_out` (one sum per pixel).
    pub fn new(bound: &'a SubtreeBound, budget: f64, left_out: &'a mut [DVec3]) -> Self {
        Self {
            bound,
            budget,
            left_out,
            room: Vec::new(),
            current: Vec::new(),
            next: Vec::new(),
        }
    }
}

impl SpawnFilter for PruneBelow<'_> {
    fn camera_rays(&mut self, count: usize) {
        debug_assert_eq!(count, self.left_out.len(), "one camera ray per pixel");
        self.room.clear();
        self.room.resize(count, DVec3::splat(self.budget));
        self.current.clear();
        self.current
            .extend((0..count as u32).map(|pixel| (DVec3::ONE, pixel)));
        self.next.clear();
    }

    // Out of line: inlined, it grew the tile pass past inlining the shadow queries
    // (callgrind on csg.ron: 6% more instructions).
    #[inline(never)]
    fn keep(&mut self, slot: usize, depth: u32, k: DVec3) -> bool {
        let (weight, pixel) = self.current[slot];
        let weight = weight * k;
        let bound = self.bound.of(weight, depth);
        let room = &mut self.room[pixel as usize];
        if bound.cmple(*room).all() {
            *room -= bound;
            self.left_out[pixel as usize] += bound;
            false
        } else {
            self.next.push((weight, pixel));
            true
        }
    }

    fn next_level(&mut self) {
        std::mem::swap(&mut self.current, &mut self.next);
        self.next.clear();
    }
}
