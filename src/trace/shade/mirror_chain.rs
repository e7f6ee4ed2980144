//! A camera ray's chain of mirror bounces: what each ray adds itself and the weight of
//! what its mirror ray brings back, folded from the deepest ray as
//! `colour(d) = local(d) + km(d) * colour(d + 1)` (or the course's blend, and each ray
//! clamped, as the scene's conventions say). The shader and the quick re-shade
//! ([`crate::trace::reshade::quick_shade`]) fold alike, so their sums agree bit for bit.

use glam::DVec3;
use smallvec::SmallVec;

use super::record::Recorder;
use crate::scene::{ClampConvention, Conventions, MirrorConvention};

/// What one ray of the mirror chain contributes: its own colour (ambient, diffuse and
/// specular at a hit, the background at a miss) and the weight of the colour its mirror
/// ray brings back (`km`; unused when no mirror ray was cast).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Bounce {
    pub local: DVec3,
    pub km: DVec3,
}

impl Bounce {
    /// The colour this ray returns, given the colour its mirror ray brought back
    /// (`None`: it cast none): the one step of every fold, the shader's, the tile pass's
    /// and the quick re-shade's, so their sums agree bit for bit.
    #[inline]
    pub fn returns(&self, brought_back: Option<DVec3>, conventions: &Conventions) -> DVec3 {
        ray_colour(self.unclamped(brought_back, conventions), conventions)
    }

    /// This ray's colour before any clamp. `Add`: local + km * reflected; `Blend`:
    /// (1 - km) * local + km * reflected, per channel (only where a mirror ray was cast).
    #[inline]
    fn unclamped(&self, brought_back: Option<DVec3>, conventions: &Conventions) -> DVec3 {
        let Some(reflected) = brought_back else {
            return self.local;
        };
        match conventions.mirror {
            MirrorConvention::Add => self.local + self.km * reflected,
            MirrorConvention::Blend => (DVec3::ONE - self.km) * self.local + self.km * reflected,
        }
    }

    /// A ray that casts no mirror ray.
    pub fn local(colour: DVec3) -> Self {
        Self {
            local: colour,
            km: DVec3::ZERO,
        }
    }
}

/// The colour a ray returns, as the conventions say: clamped to [0, 1] with `EachRay`
/// (the course skeleton's `clip()`), as it is with `Pixel` (only the pixel is clamped,
/// when it is written).
#[inline]
fn ray_colour(colour: DVec3, conventions: &Conventions) -> DVec3 {
    match conventions.clamp {
        ClampConvention::Pixel => colour,
        ClampConvention::EachRay => colour.clamp(DVec3::ZERO, DVec3::ONE),
    }
}

/// Mirror chains up to this long stay on the stack; longer ones spill to the heap.
const INLINE_BOUNCES: usize = 8;

/// The bounces of one camera ray, depth 0 first.
pub(crate) type Chain = SmallVec<[Bounce; INLINE_BOUNCES]>;

/// The colour of a chain of at least one bounce: the deepest ray returns its own colour,
/// each one before it adds km times the colour of the one after. The recorder sees each
/// ray's `reflection` and `result` after everything deeper, as a recursion would.
#[inline]
pub(crate) fn fold_back(
    chain: &[Bounce],
    conventions: &Conventions,
    recorder: &mut impl Recorder,
) -> DVec3 {
    let mut depth = chain.len() - 1;
    let mut colour = returned(depth as u32, &chain[depth], None, conventions, recorder);
    while depth > 0 {
        depth -= 1;
        let bounce = &chain[depth];
        recorder.reflection(depth as u32, bounce.km, colour);
        colour = returned(depth as u32, bounce, Some(colour), conventions, recorder);
    }
    colour
}

/// What the ray at `depth` returns ([`Bounce::returns`]); the recorder sees its colour,
/// and where the each-ray clamp changed it, the colour before.
#[inline]
pub(crate) fn returned<R: Recorder>(
    depth: u32,
    bounce: &Bounce,
    brought_back: Option<DVec3>,
    conventions: &Conventions,
    recorder: &mut R,
) -> DVec3 {
    let colour = bounce.unclamped(brought_back, conventions);
    let clamped = ray_colour(colour, conventions);
    if R::ACTIVE && clamped != colour {
        recorder.clamped(depth, colour);
    }
    recorder.result(depth, clamped);
    clamped
}
