//! A camera ray's chain of mirror bounces: what each ray adds itself and the weight of
//! what its mirror ray brings back, folded from the deepest ray as
//! `colour(d) = local(d) + km(d) * colour(d + 1)`. The shader and the quick re-shade
//! ([`crate::trace::reshade::quick_shade`]) fold alike, so their sums agree bit for bit.

use glam::DVec3;
use smallvec::SmallVec;

use super::record::Recorder;

/// What one ray of the mirror chain contributes: its own colour (ambient, diffuse and
/// specular at a hit, the background at a miss) and the weight of the colour its mirror
/// ray brings back (`km`; unused when no mirror ray was cast).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Bounce {
    pub local: DVec3,
    pub km: DVec3,
}

impl Bounce {
    /// This ray's colour, given the colour its mirror ray brought back: the one step of
    /// every fold.
    #[inline]
    pub fn fold(&self, brought_back: DVec3) -> DVec3 {
        self.local + self.km * brought_back
    }

    /// A ray that casts no mirror ray.
    pub fn local(colour: DVec3) -> Self {
        Self {
            local: colour,
            km: DVec3::ZERO,
        }
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
pub(crate) fn fold_back(chain: &[Bounce], recorder: &mut impl Recorder) -> DVec3 {
    let mut depth = chain.len() - 1;
    let mut colour = chain[depth].local;
    recorder.result(depth as u32, colour);
    while depth > 0 {
        depth -= 1;
        let bounce = &chain[depth];
        recorder.reflection(depth as u32, bounce.km, colour);
        colour = bounce.fold(colour);
        recorder.result(depth as u32, colour);
    }
    colour
}
