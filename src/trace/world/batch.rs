//! Closest hits for a batch of rays that share one culled candidate set, as a tile's
//! camera rays, or its mirror rays of one depth, do: the objects outer and the rays
//! inner, so that each object's data and test are set up once per batch instead of once
//! per ray. Per ray it is the flat list's query (the objects in scene order, each tested
//! only up to the nearest hit so far), and in a world larger than culling covers then
//! the tree over the rest, ray by ray, from the list's nearest hit, so every answer is
//! [`World::intersect_among`]'s bit for bit.

use glam::DVec3;

use super::compiled::{BVH_MIN_OBJECTS, SurfacePoint, World};
use super::object::ObjectHit;
use super::object_set::ObjectSet;
use crate::trace::ray::Ray;

impl World {
    /// Whether [`World::intersect_among`] answers a query on `among` from the flat list
    /// (then, in a world larger than culling covers, the tree over the rest), and so
    /// whether [`World::intersect_batch`] can turn its loops around.
    fn lists(&self, among: ObjectSet) -> bool {
        self.bvh.is_none() || among != ObjectSet::ALL
    }

    /// For each ray of `rays`, its closest hit among the objects of `among` with `t` in
    /// (0, infinity): the same answers as [`World::intersect_among`], ray by ray.
    #[must_use]
    pub fn intersect_batch(&self, rays: &[Ray], among: ObjectSet) -> Vec<Option<SurfacePoint>> {
        if !self.lists(among) {
            return rays
                .iter()
                .map(|ray| self.intersect_among(ray, f64::INFINITY, among))
                .collect();
        }
        let inv_dirs: Vec<DVec3> = rays.iter().map(|ray| ray.dir.recip()).collect();
        let mut t_limits = vec![f64::INFINITY; rays.len()];
        let mut closest: Vec<Option<(usize, ObjectHit)>> = vec![None; rays.len()];
        // As `intersect_among`: with a tree over the uncovered objects, the list holds
        // only the covered ones; unless they are too few for a tree to pay, when the list
        // holds them too (the tree's answer is the list's).
        let uncovered = self.objects.len().saturating_sub(ObjectSet::CULLED_BELOW);
        let tail = (uncovered >= BVH_MIN_OBJECTS)
            .then(|| self.bvh.as_ref().and(self.tail_bvh.as_ref()))
            .flatten();
        let listed = tail.map_or(self.objects.len(), |_| ObjectSet::CULLED_BELOW);
        for index in among.members_below(listed) {
            let object = &self.objects[index];
            let per_ray = rays
                .iter()
                .zip(&inv_dirs)
                .zip(&mut t_limits)
                .zip(&mut closest);
            for (((ray, &inv_dir), t_limit), closest) in per_ray {
                if let Some(hit) = object.hit(ray, inv_dir, *t_limit) {
                    *t_limit = hit.hit.t;
                    *closest = Some((index, hit));
                }
            }
        }
        if let Some(tail) = tail {
            let per_ray = rays.iter().zip(&inv_dirs).zip(&t_limits).zip(&mut closest);
            for (((ray, &inv_dir), &t_limit), closest) in per_ray {
                *closest = self.closest_in_tail(tail, ray, inv_dir, t_limit, among, *closest);
            }
        }
        closest
            .iter()
            .zip(rays)
            .map(|(closest, ray)| closest.map(|(index, hit)| self.surface_point(index, ray, &hit)))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use super::*;
    use crate::scene::examples;
    use crate::trace::world::Acceleration;

    /// Rays from the default scene's camera over its whole picture, some hitting.
    fn camera_rays(world: &World) -> Vec<Ray> {
        let eye = world.camera.position;
        (0..40)
            .flat_map(|j| (0..40).map(move |i| (i, j)))
            .map(|(i, j)| {
                let target = DVec3::new(-6.0 + 0.3 * f64::from(i), 3.5 - 0.2 * f64::from(j), 0.0);
                Ray::new(eye, target - eye)
            })
            .collect()
    }

    #[test]
    fn a_batch_answers_as_each_ray_alone_with_and_without_the_tree() {
        let scene = examples::default_scene();
        for acceleration in [Acceleration::Flat, Acceleration::Bvh] {
            let mut world = World::new(&scene).unwrap();
            world.set_acceleration(acceleration);
            let rays = camera_rays(&world);
            let mut some = ObjectSet::none();
            some.insert(0);
            some.insert(2);
            for among in [ObjectSet::ALL, some] {
                let batch = world.intersect_batch(&rays, among);
                let hits = batch.iter().filter(|hit| hit.is_some()).count();
                assert!(
                    hits > 200 && hits < rays.len(),
                    "{hits} hits: a mixed batch"
                );
                for (ray, answer) in rays.iter().zip(&batch) {
                    assert_eq!(*answer, world.intersect_among(ray, f64::INFINITY, among));
                }
            }
        }
    }

    /// glass.ron, with `beads` small balls over its floor after its own objects.
    fn glass_world(beads: usize) -> World {
        let text = crate::scene::examples::EXAMPLE_SCENES
            .iter()
            .find(|(name, _)| name.contains("glass"))
            .expect("glass.ron is an example")
            .1;
        let end = text.rfind("    ],").expect("the objects' list ends");
        let beads: String = (0..beads)
            .map(|i| {
                let (x, z) = (-3.5 + 0.35 * i as f64, -2.0 + 0.2 * i as f64);
                format!(
                    "(name: \"bead {i}\", shape: Sphere, transform: (translate: ({x}, 0.3, {z}), \
                     scale: (0.2, 0.2, 0.2)), material: \"red\"),\n"
                )
            })
            .collect();
        let text = format!("{}{beads}{}", &text[..end], &text[end..]);
        World::new(&crate::scene::parse_scene(&text).unwrap()).unwrap()
    }

    /// glass.ron has more objects than culling covers (64 tiles, then the glass, too
    /// few for a tree to pay, listed too); with 20 beads more, the rest have a tree.
    /// Rays down from the camera, and up through the floor into the glass, answer in a
    /// batch as alone, the tail's hits and the tiles' both.
    #[test]
    fn a_batch_answers_as_each_ray_alone_beyond_the_objects_culling_covers() {
        for world in [glass_world(0), glass_world(20)] {
            assert!(world.tail_bvh.is_some(), "a tail");
            a_batch_answers_as_each_ray_alone_in(&world);
        }
    }

    fn a_batch_answers_as_each_ray_alone_in(world: &World) {
        let mut rays = Vec::new();
        for i in 0..30 {
            for j in 0..30 {
                let x = -4.0 + 8.0 * f64::from(i) / 29.0;
                let z = -4.0 + 8.0 * f64::from(j) / 29.0;
                let target = DVec3::new(x, 0.6, z);
                rays.push(Ray::new(
                    world.camera.position,
                    target - world.camera.position,
                ));
                // From under the floor: a tile first, then perhaps the glass beyond it.
                let below = DVec3::new(x + 0.3, -2.0, z + 0.2);
                rays.push(Ray::new(below, target - below));
            }
        }
        let mut every_third = ObjectSet::none();
        for i in (0..64).step_by(3) {
            every_third.insert(i);
        }
        for among in [ObjectSet::ALL, every_third, ObjectSet::none()] {
            let batch = world.intersect_batch(&rays, among);
            let hit = |glass: bool| {
                batch
                    .iter()
                    .flatten()
                    .filter(|hit| (hit.object >= ObjectSet::CULLED_BELOW) == glass)
                    .count()
            };
            assert!(hit(true) > 50, "{among:?}: {} glass hits", hit(true));
            if among != ObjectSet::none() {
                assert!(hit(false) > 50, "{among:?}: {} tile hits", hit(false));
            }
            for (ray, answer) in rays.iter().zip(&batch) {
                assert_eq!(*answer, world.intersect_among(ray, f64::INFINITY, among));
            }
        }
    }
}
