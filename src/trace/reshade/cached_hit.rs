//! What the hit cache keeps per ray: the hit as it was found, and the encoding of a
//! shadow ray's answer.

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

    /// The world index of the object hit; `u32::MAX` for a miss.
    pub fn object(&self) -> u32 {
        self.object
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
