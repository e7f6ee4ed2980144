//! The world's queries through its BVH, out of line so that the flat list's loop (every
//! small scene's, and every culled query's) stays compact. A culled set names every
//! candidate among the objects culling covers (the first 64), and testing those few in
//! the list beats walking the tree; objects from 64 on have a tree of their own. Either
//! way the answers are the list's: the closest hit with ties to the earlier object, the
//! first blocker in scene order.

use glam::DVec3;

use super::bvh::Bvh;
use super::compiled::World;
use super::object::ObjectHit;
use super::object_set::ObjectSet;
use crate::trace::ray::Ray;

impl World {
    /// A culled closest-hit query in a world larger than culling covers: the covered
    /// candidates in the list, then the tree over the rest.
    #[inline(never)]
    pub(crate) fn closest_listed_then_tail(
        &self,
        ray: &Ray,
        inv_dir: DVec3,
        t_max: f64,
        among: ObjectSet,
    ) -> Option<(usize, ObjectHit)> {
        let offset = ObjectSet::CULLED_BELOW;
        let listed = self.closest_in_list(ray, inv_dir, t_max, among, offset);
        let tail = self.tail_bvh.as_ref()?;
        let t_limit = listed.map_or(t_max, |(_, hit)| hit.hit.t);
        self.closest_in_tail(tail, ray, inv_dir, t_limit, among, listed)
    }

    /// The closest hit among the objects of `among` in `tail`, the tree over the objects
    /// culling does not cover, nearer than `listed` (the covered candidates' closest, at
    /// `t_limit`), else `listed`. Out of line so that a batch's loops stay compact.
    #[inline(never)]
    pub(crate) fn closest_in_tail(
        &self,
        tail: &Bvh,
        ray: &Ray,
        inv_dir: DVec3,
        t_limit: f64,
        among: ObjectSet,
        listed: Option<(usize, ObjectHit)>,
    ) -> Option<(usize, ObjectHit)> {
        self.closest_in_tree::<{ ObjectSet::CULLED_BELOW }>(
            tail, ray, inv_dir, t_limit, among, listed,
        )
    }

    /// A culled occlusion query in a world larger than culling covers, once none of the
    /// covered candidates in the list blocks: the first blocker in the tree over the
    /// rest among the objects `candidate` admits.
    #[inline(never)]
    pub(crate) fn blocker_in_tail<const ANY: bool>(
        &self,
        ray: &Ray,
        inv_dir: DVec3,
        t_max: f64,
        candidate: impl Fn(usize) -> bool,
    ) -> Option<usize> {
        let offset = ObjectSet::CULLED_BELOW;
        let tail = self.tail_bvh.as_ref()?;
        let blocks = |i| {
            let index = i + offset;
            candidate(index) && self.objects[index].blocks(ray, inv_dir, t_max)
        };
        let local = if ANY {
            tail.any_blocker(ray, inv_dir, t_max, blocks)
        } else {
            tail.first_blocker(ray, inv_dir, t_max, blocks)
        };
        local.map(|i| i + offset)
    }

    /// The closest hit among the objects of `among` in a tree over the objects from
    /// `OFFSET` on, nearer than `closest` (found before, at `t_limit`). A constant, so
    /// that each tree's walk is its own copy, inlined (a shared one stayed out of line).
    #[inline(always)]
    pub(crate) fn closest_in_tree<const OFFSET: usize>(
        &self,
        bvh: &Bvh,
        ray: &Ray,
        inv_dir: DVec3,
        t_limit: f64,
        among: ObjectSet,
        mut closest: Option<(usize, ObjectHit)>,
    ) -> Option<(usize, ObjectHit)> {
        bvh.traverse(ray, inv_dir, t_limit, |local, t_limit| {
            let index = local + OFFSET;
            if !among.contains(index) {
                return Ok(None);
            }
            // A tie goes to the earlier object, as in the list: one before the closest
            // so far may also hit at exactly its `t`.
            let limit = match closest {
                Some((best, _)) if index < best => t_limit.next_up(),
                _ => t_limit,
            };
            let hit = self.objects[index].hit(ray, inv_dir, limit);
            if let Some(hit) = hit {
                closest = Some((index, hit));
            }
            Ok(hit.map(|hit| hit.hit.t))
        });
        closest
    }
}
