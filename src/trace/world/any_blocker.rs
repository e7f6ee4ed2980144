//! Occlusion queries that need only whether a shadow ray is blocked, not by what: the
//! tile pass's, whose shading never names the blocker (no recorder there). They stop at
//! the first blocker met instead of proving it the first in scene order, which spares a
//! blocked ray the walk through every earlier object's subtree it crosses (in glass.ron
//! the glass ball is object 64, after the checker's tiles). Blocked or not is
//! [`World::occluder_except_among`]'s answer whenever that is so: both test the same
//! candidates with the same `blocks`, and the walks' box tests only skip objects whose
//! boxes the ray misses.

use super::compiled::World;
use super::object_set::ObjectSet;
use crate::trace::ray::Ray;

impl World {
    /// An object of `among` other than `except` that blocks the ray before `t_max`, if
    /// any, trying `first` before the others (where it is a candidate): not necessarily
    /// the first in scene order, but `Some` exactly where
    /// [`World::occluder_except_among`] is.
    #[must_use]
    #[inline(never)]
    pub fn any_occluder_among(
        &self,
        ray: &Ray,
        t_max: f64,
        except: Option<usize>,
        among: ObjectSet,
        first: Option<usize>,
    ) -> Option<usize> {
        let inv_dir = ray.dir.recip();
        if let Some(first) = first
            && Some(first) != except
            && among.contains(first)
            && self.objects[first].blocks(ray, inv_dir, t_max)
        {
            return Some(first);
        }
        self.occluder_in::<true>(ray, inv_dir, t_max, except, among)
    }

    /// Whether object `index` blocks the ray before `t_max`: the test the queries above
    /// make of each candidate.
    #[must_use]
    #[inline]
    pub fn object_blocks(&self, index: usize, ray: &Ray, t_max: f64) -> bool {
        self.objects[index].blocks(ray, ray.dir.recip(), t_max)
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::scene::parse_scene;

    /// Shadow rays from glass.ron's floor and from inside its glass towards its light,
    /// every way of asking: blocked exactly where the first-blocker query says so, by an
    /// object that blocks.
    #[test]
    fn any_blocker_is_blocked_exactly_where_the_first_blocker_is() {
        let text = crate::scene::examples::EXAMPLE_SCENES
            .iter()
            .find(|(name, _)| name.contains("glass"))
            .expect("glass.ron is an example")
            .1;
        let world = World::new(&parse_scene(text).unwrap()).unwrap();
        assert!(world.bvh.is_some() && world.tail_bvh.is_some());
        let light = DVec3::new(-3.0, 7.0, 5.0);
        let mut some_tiles = ObjectSet::none();
        for i in (0..64).step_by(3) {
            some_tiles.insert(i);
        }
        let (mut blocked, mut clear) = (0, 0);
        for i in 0..60 {
            for j in 0..60 {
                let (x, z) = (
                    -4.0 + 8.0 * f64::from(i) / 59.0,
                    -4.0 + 8.0 * f64::from(j) / 59.0,
                );
                for y in [1e-9, 0.5, 1.0, 1.3] {
                    let origin = DVec3::new(x, y, z);
                    let ray = Ray::new(origin, light - origin);
                    for except in [None, Some(64), Some(3)] {
                        for among in [ObjectSet::ALL, some_tiles] {
                            let first = world.occluder_except_among(&ray, 1.0, except, among);
                            let any = world.any_occluder_among(&ray, 1.0, except, among, None);
                            assert_eq!(first.is_some(), any.is_some(), "{ray:?} {except:?}");
                            // Trying any object first changes nothing but the blocker.
                            for tried in [0, 3, 64, 65, 66] {
                                let tried = Some(tried);
                                let trying =
                                    world.any_occluder_among(&ray, 1.0, except, among, tried);
                                assert_eq!(trying.is_some(), any.is_some(), "{ray:?} {tried:?}");
                            }
                            if let Some(any) = any {
                                assert!(among.contains(any) && Some(any) != except);
                                assert!(world.object_blocks(any, &ray, 1.0));
                                blocked += 1;
                            } else {
                                clear += 1;
                            }
                        }
                    }
                }
            }
        }
        assert!(
            blocked > 1000 && clear > 1000,
            "{blocked} blocked, {clear} clear"
        );
    }
}
