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
        // A ray into the convex solid it leaves (not leaving it outward, so not
        // excepted) meets that solid's far side, unless the light is inside it.
        let into = except.is_none() && !world.objects[to.from].can_meet_itself();
        let first = if into { Some(to.from) } else { *last };
        let found = world.any_occluder_among(&query.ray, query.t_max, except, among, first);
        // A ray found clear forgets the blocker: trying it on the clear rays that follow
        // cost csg.ron 2% more instructions (its blockers are costly CSG nodes).
        *last = found;
        found
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::scene::parse_scene;
    use crate::trace::shade::ShadowQuery;
    use crate::trace::world::ObjectSet;
    use crate::trace::world::spawn_ray_to;

    /// A glass ball (object 1, after a far cube) and shadow rays from the inside of its
    /// surface into it: towards a light beyond it the ball blocks them, towards a light
    /// inside it nothing does, though the ball is tried first either way.
    #[test]
    fn a_ray_into_the_solid_it_leaves_is_blocked_only_where_the_light_is_beyond_it() {
        let world = World::new(
            &parse_scene(
                r#"Scene(camera: (position: (0.0, 0.0, 9.0), look_at: (0.0, 0.0, 0.0), fov_deg: 40.0, width: 8, height: 8),
                    materials: {"m": ()},
                    objects: [(shape: Cube, transform: (translate: (9.0, 9.0, 9.0)), material: "m"),
                              (shape: Sphere, material: "m")])"#,
            )
            .unwrap(),
        )
        .unwrap();
        // The ball's surface at its top, seen from inside (the ray that met it came up).
        let hit = world
            .intersect(
                &crate::trace::ray::Ray::new(DVec3::ZERO, DVec3::Y),
                f64::INFINITY,
            )
            .unwrap();
        assert_eq!(hit.object, 1);
        for (light, blocked) in [
            (DVec3::new(0.3, -5.0, 0.0), true),
            (DVec3::new(0.3, -0.5, 0.0), false),
        ] {
            let mut shadows = TileShadows::new(Candidates::ALL, 1);
            let request = ShadowRequest {
                depth: 1,
                node: 0,
                light: 0,
                except: None,
                from: hit.object,
                off_centre: false,
                within: ObjectSet::ALL,
            };
            let (ray, t_max) = spawn_ray_to(&hit, light);
            let found = shadows.occluder(&world, request, || ShadowQuery { ray, t_max });
            assert_eq!(found.is_some(), blocked, "light at {light}");
            assert_eq!(found.is_some(), world.occluder(&ray, t_max).is_some());
        }
    }
}
