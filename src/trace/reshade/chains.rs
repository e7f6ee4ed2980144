//! What the hit cache keeps per ray: each pixel's mirror chain of cached hits, and the
//! encoding of a shadow ray's answer.

use glam::DVec3;

use crate::trace::world::SurfacePoint;

/// A shadow ray the shader did not cast at that hit.
pub(crate) const NOT_CAST: u32 = u32::MAX;
/// A shadow ray that met nothing.
pub(crate) const CLEAR: u32 = u32::MAX - 1;

/// A hit as cached: a [`SurfacePoint`] with the shading normal kept as one bit (it is
/// the outward normal or its exact negation), or a miss.
#[derive(Clone, Copy, Debug)]
pub(crate) struct CachedHit {
    t: f64,
    p: DVec3,
    n_outward: DVec3,
    p_error: DVec3,
    /// World index of the object hit; `u32::MAX` for a miss.
    object: u32,
    /// The CSG operand leaf hit ([`SurfacePoint::part`]).
    part: u32,
    /// Whether the shading normal is `-n_outward`.
    flipped: bool,
}

impl CachedHit {
    /// What the closest-hit query returned.
    pub fn new(hit: Option<&SurfacePoint>) -> Self {
        match hit {
            Some(hit) => Self {
                t: hit.t,
                p: hit.p,
                n_outward: hit.n_outward,
                p_error: hit.p_error,
                object: u32::try_from(hit.object).expect("fewer than 2^32 - 1 objects"),
                part: hit.part,
                flipped: hit.n != hit.n_outward,
            },
            None => Self {
                t: 0.0,
                p: DVec3::ZERO,
                n_outward: DVec3::ZERO,
                p_error: DVec3::ZERO,
                object: u32::MAX,
                part: 0,
                flipped: false,
            },
        }
    }

    /// The hit again, bit for bit; `None` for a miss.
    pub fn point(&self) -> Option<SurfacePoint> {
        (self.object != u32::MAX).then(|| SurfacePoint {
            object: self.object as usize,
            part: self.part,
            t: self.t,
            p: self.p,
            n_outward: self.n_outward,
            n: if self.flipped {
                -self.n_outward
            } else {
                self.n_outward
            },
            p_error: self.p_error,
        })
    }
}

/// Marks a sphere light's answer: how many of its rays reached it (the low 11 bits) of
/// how many (the 11 above), each at most `MAX_LIGHT_SAMPLES` (1024). Blockers' indices
/// stay below it.
const SPHERE: u32 = 1 << 31;
const COUNT_BITS: u32 = 11;
const COUNT_MASK: u32 = (1 << COUNT_BITS) - 1;

/// A shadow answer as cached.
pub(crate) fn encode_blocker(blocked_by: Option<usize>) -> u32 {
    blocked_by.map_or(CLEAR, |i| {
        let code = u32::try_from(i).expect("fewer than 2^31 objects");
        assert!(code < SPHERE, "fewer than 2^31 objects");
        code
    })
}

/// The cached shadow answer `code` (not [`NOT_CAST`], nor a sphere light's).
pub(crate) fn decode_blocker(code: u32) -> Option<usize> {
    (code != CLEAR).then_some(code as usize)
}

/// A sphere light's answer as cached: `clear` of its `samples` rays reached it.
pub(crate) fn encode_sphere(clear: u32, samples: u32) -> u32 {
    assert!(
        clear <= samples && samples <= COUNT_MASK,
        "{clear} of {samples} rays"
    );
    SPHERE | (samples << COUNT_BITS) | clear
}

/// `(clear, samples)` of a sphere light's cached answer; `None` for any other code.
pub(crate) fn decode_sphere(code: u32) -> Option<(u32, u32)> {
    (code & SPHERE != 0 && code < CLEAR)
        .then_some((code & COUNT_MASK, (code >> COUNT_BITS) & COUNT_MASK))
}

/// The mirror chains of one tile's pixels, row-major within the tile.
#[derive(Clone, Debug, Default)]
pub(crate) struct Chains {
    /// End of each pixel's chain in `hits` (a chain starts where the one before ends).
    chain_ends: Vec<u32>,
    /// Every chain's entries, depth 0 first.
    hits: Vec<CachedHit>,
    /// Each entry's object (`u32::MAX` for a miss) on its own: all a re-shade from light
    /// factors reads of an entry, 4 bytes instead of a whole hit.
    objects: Vec<u32>,
}

impl Chains {
    /// `pixels` pixels with empty chains.
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
        }
    }

    /// The chains of the first `pixels` pixels of `self` (and the entries up to `end`),
    /// with room for more.
    pub fn prefix(&self, pixels: usize, end: usize) -> Self {
        let room = self.hits.len() + self.chain_ends.len() / 4;
        let mut hits = Vec::with_capacity(room);
        hits.extend_from_slice(&self.hits[..end]);
        let mut objects = Vec::with_capacity(room);
        objects.extend_from_slice(&self.objects[..end]);
        Self {
            chain_ends: self.chain_ends[..pixels].to_vec(),
            hits,
            objects,
        }
    }

    /// The range of entries holding pixel `pixel`'s chain.
    pub fn chain(&self, pixel: usize) -> std::ops::Range<usize> {
        let start = pixel
            .checked_sub(1)
            .map_or(0, |p| self.chain_ends[p] as usize);
        start..self.chain_ends[pixel] as usize
    }

    /// Where the chain being built starts: the end of the last pixel's.
    pub fn building(&self) -> std::ops::Range<usize> {
        let start = self.chain_ends.last().map_or(0, |&end| end as usize);
        start..self.hits.len()
    }

    /// Entry `index`.
    pub fn hit(&self, index: usize) -> &CachedHit {
        &self.hits[index]
    }

    /// The objects of the entries `range`.
    pub fn objects(&self, range: std::ops::Range<usize>) -> &[u32] {
        &self.objects[range]
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

    /// Adds an entry to the chain being built.
    pub fn push(&mut self, hit: CachedHit) {
        self.objects.push(hit.object);
        self.hits.push(hit);
    }

    /// Adds `other`'s entries `range` to the chain being built.
    pub fn extend_from(&mut self, other: &Chains, range: std::ops::Range<usize>) {
        self.hits.extend_from_slice(&other.hits[range.clone()]);
        self.objects.extend_from_slice(&other.objects[range]);
    }

    /// Ends the chain being built: the next entry starts the next pixel's.
    pub fn end_chain(&mut self) {
        self.chain_ends.push(self.hits.len() as u32);
    }
}
