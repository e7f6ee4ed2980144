//! The tile pass's shadow rays. Its shading only asks whether a shadow ray is blocked
//! (it records nothing, so the blocker is never named), which allows two shortcuts that
//! keep every answer: the object that last blocked a shadow ray to the same light is
//! tried first (POV-Ray's shadow cache: neighbouring rays of a batch are blocked by the
//! same object), and otherwise the walk stops at the first blocker it meets rather than
//! the first in scene order ([`World::any_occluder_among`]). A ray is blocked exactly
//! where [`LiveRays`](crate::trace::shade::LiveRays) finds it blocked: the same culled
//! candidates, and an object that blocks is a blocker whichever way it was found.

use crate::trace::cull::Candidates;
use crate::trace::shade::{MakeRay, ShadowRequest};
use crate::trace::world::World;

/// One tile batch's shadow queries, with the last blocker of each light's rays.
pub(super) struct TileShadows<'c> {
    among: Candidates<'c>,
    /// Per light (an index into [`World::lights`]): the object that blocked the last
    /// shadow ray to it, `None` if that ray was clear.
    last_blocker: Vec<Option<usize>>,
}

impl<'c> TileShadows<'c> {
    /// The queries of a batch whose camera rays share the culled sets `among`, in a world
    /// of `lights` lights.
    pub fn new(among: Candidates<'c>, lights: usize) -> Self {
        Self {
            among,
            last_blocker: vec![None; lights],
        }
    }

    /// An object blocking the shadow ray `to` (not necessarily the first in scene order),
    /// if any: `Some` exactly where [`LiveRays`](crate::trace::shade::LiveRays)'s answer
    /// is. Out of line: inlined into the tile pass's loop, the pass ran 4.6% fewer
    /// instructions on glass.ron and took 4% longer (docs/BENCHMARKS.md).
    #[inline(never)]
    pub fn occluder(
        &mut self,
        world: &World,
        to: ShadowRequest,
        ray: impl MakeRay,
    ) -> Option<usize> {
        let except = to.except;
        // The candidates `LiveRays` tests: the tile's culled set from a camera ray's hit.
        let among = if to.depth == 0 && !to.off_centre {
            let among = self.among.shadow(to.light);
            if among.without(except).is_empty_below(world.objects.len()) {
                return None;
            }
            among
        } else {
            to.within
        };
        let query = ray();
        let last = &mut self.last_blocker[to.light];
        let found = world.any_occluder_among(&query.ray, query.t_max, except, among, *last);
        // A ray found clear forgets the blocker: trying it on the clear rays that follow
        // cost csg.ron 2% more instructions (its blockers are costly CSG nodes).
        *last = found;
        found
    }
}
