//! Culling tile by tile, for camera rays and the shadow rays from their hits (those in
//! [`super::shadows`]). Every camera ray through a rectangle of the
//! image starts at the eye and runs inside the pyramid spanned by the rectangle's corner
//! directions ([`PinholeCamera::film_direction`] is affine in the image point). An object
//! whose world box lies wholly outside one of the pyramid's four side planes, or behind
//! the eye, cannot be hit by any of those rays, so their closest-hit query skips it.
//!
//! The test is conservative by a relative margin far above the rounding of the ray and
//! box arithmetic, and the queries keep scene order, so a frame is bit-identical to one
//! that tests every object.

use glam::{DVec2, DVec3};

use super::shadows::{CullBox, shadow_set, tile_hit_box};
use crate::trace::film::PinholeCamera;
use crate::trace::world::{ObjectSet, World};

/// Side of a culling tile in image pixels (the render's tiles, so one list per tile).
pub const CULL_TILE: u32 = crate::trace::film::TILE_SIZE;

/// A margin of this many times the sizes involved keeps an object that rounding could
/// put on the inner side of a plane (rounding is ~1e-16 relative; boxes are padded by
/// 1e-9 already).
const RELATIVE_MARGIN: f64 = 1e-8;

/// The objects each tile's camera rays, and the shadow rays from their hits, may meet.
#[derive(Clone, Debug)]
pub struct TileCull {
    tiles_x: u32,
    tiles_y: u32,
    /// Row-major, one set per tile: the camera rays' candidates.
    camera: Vec<ObjectSet>,
    /// Row-major by tile, then one set per light of [`World::lights`].
    shadow: Vec<ObjectSet>,
    lights: usize,
}

/// What one camera ray may meet: the objects it may hit, and per light those that may
/// block a shadow ray from its hit.
#[derive(Clone, Copy, Debug)]
pub struct Candidates<'a> {
    /// The objects the camera ray may hit.
    pub camera: ObjectSet,
    /// Per light, the objects that may block a shadow ray from the camera hit; empty for
    /// every object.
    shadow: &'a [ObjectSet],
}

impl Candidates<'static> {
    /// No culling.
    pub const ALL: Self = Self {
        camera: ObjectSet::ALL,
        shadow: &[],
    };
}

impl Candidates<'_> {
    /// The objects that may block a shadow ray from the camera hit to light `light` (an
    /// index into [`World::lights`]).
    #[must_use]
    #[inline]
    pub fn shadow(&self, light: usize) -> ObjectSet {
        self.shadow.get(light).copied().unwrap_or(ObjectSet::ALL)
    }
}

impl TileCull {
    /// The lists for a `width` x `height` render through `camera`.
    #[must_use]
    pub fn new(world: &World, camera: &PinholeCamera, width: u32, height: u32) -> Self {
        let (tiles_x, tiles_y) = (width.div_ceil(CULL_TILE), height.div_ceil(CULL_TILE));
        let eye = camera.position();
        let world_boxes: Vec<CullBox> = world
            .objects
            .iter()
            .take(ObjectSet::CULLED_BELOW)
            .map(|object| CullBox::of(&object.bounds))
            .collect();
        let boxes: Vec<EyeBox> = world_boxes.iter().map(|b| EyeBox::new(b, eye)).collect();
        // Film directions at the tile grid's corners, shared by neighbouring tiles.
        let corners_x = tiles_x + 1;
        let corners: Vec<DVec3> = (0..=tiles_y)
            .flat_map(|j| (0..corners_x).map(move |i| (i, j)))
            .map(|(i, j)| {
                let point = DVec2::new(f64::from(i * CULL_TILE), f64::from(j * CULL_TILE));
                camera.film_direction(point)
            })
            .collect();
        let corner = |i: u32, j: u32| corners[(j * corners_x + i) as usize];
        let forward = camera.forward();
        let tiles = (tiles_x * tiles_y) as usize;
        let lights = world.lights.len();
        let mut camera_sets = Vec::with_capacity(tiles);
        let mut shadow = Vec::with_capacity(tiles * lights);
        for j in 0..tiles_y {
            for i in 0..tiles_x {
                let quad = [
                    corner(i, j),
                    corner(i + 1, j),
                    corner(i + 1, j + 1),
                    corner(i, j + 1),
                ];
                let set = tile_set(&quad, forward, &boxes);
                camera_sets.push(set);
                let in_view = set
                    .members_below(world_boxes.len())
                    .map(|index| world_boxes[index]);
                let hits = tile_hit_box(eye, forward, &quad, in_view);
                shadow.extend(world.lights.iter().map(|light| match &hits {
                    Some(hits) => shadow_set(hits, light, &world_boxes),
                    // The tile's camera rays hit nothing: no shadow rays.
                    None => ObjectSet::none(),
                }));
            }
        }
        Self {
            tiles_x,
            tiles_y,
            camera: camera_sets,
            shadow,
            lights,
        }
    }

    /// What a camera ray through image point `image_point` may meet (everything for a
    /// point outside the tiled image).
    #[must_use]
    #[inline]
    pub fn candidates(&self, image_point: DVec2) -> Candidates<'_> {
        let tile = f64::from(CULL_TILE);
        let (x, y) = (image_point.x / tile, image_point.y / tile);
        if !(x >= 0.0 && y >= 0.0) {
            return Candidates::ALL;
        }
        let (i, j) = (x as u32, y as u32);
        if i >= self.tiles_x || j >= self.tiles_y {
            return Candidates::ALL;
        }
        let index = (j * self.tiles_x + i) as usize;
        Candidates {
            camera: self.camera[index],
            shadow: &self.shadow[index * self.lights..(index + 1) * self.lights],
        }
    }
}

/// An object's world box relative to the eye, with the margin of its plane tests.
struct EyeBox {
    centre_from_eye: DVec3,
    half: DVec3,
    /// The margin before scaling by a plane normal's length.
    margin: f64,
}

impl EyeBox {
    fn new(world_box: &CullBox, eye: DVec3) -> Self {
        let centre_from_eye = world_box.centre - eye;
        let reach = centre_from_eye.length()
            + world_box.half.length()
            + eye.abs().max_element()
            + world_box.centre.abs().max_element();
        Self {
            centre_from_eye,
            half: world_box.half,
            margin: RELATIVE_MARGIN * reach,
        }
    }
}

/// The objects whose boxes are not wholly outside the pyramid of `quad` (four film
/// directions in order round the rectangle) or behind the eye.
fn tile_set(quad: &[DVec3; 4], forward: DVec3, boxes: &[EyeBox]) -> ObjectSet {
    let inside = quad[0] + quad[1] + quad[2] + quad[3];
    let normals: [DVec3; 4] = std::array::from_fn(|k| {
        let n = quad[k].cross(quad[(k + 1) % 4]);
        if n.dot(inside) < 0.0 { -n } else { n }
    });
    let mut set = ObjectSet::none();
    for (index, cull_box) in boxes.iter().enumerate() {
        let outside = |n: DVec3| {
            // The box's farthest reach to the inner side of the plane through the eye.
            let reach = cull_box.centre_from_eye.dot(n) + cull_box.half.dot(n.abs());
            reach < -cull_box.margin * n.length()
        };
        if !(outside(forward) || normals.iter().any(|&n| outside(n))) {
            set.insert(index);
        }
    }
    set
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::examples::default_scene;
    use crate::scene::{Light, Transform};
    use crate::trace::world::{spawn_ray, spawn_ray_to};

    /// Every camera ray of a render gets bit for bit the hit it gets from all objects,
    /// and every shadow ray from that hit the blocker; returns how many object tests
    /// the lists skipped, and how many there were.
    fn assert_culling_is_exact(world: &World, width: u32, height: u32) -> (usize, usize) {
        let camera = PinholeCamera::new(&world.camera, width, height);
        let cull = TileCull::new(world, &camera, width, height);
        let count = world.objects.len();
        let (mut culled, mut tests) = (0, 0);
        for py in 0..height {
            for px in 0..width {
                for offset in [DVec2::ZERO, DVec2::splat(0.5), DVec2::splat(0.999_999)] {
                    let point = DVec2::new(f64::from(px), f64::from(py)) + offset;
                    let ray = camera.ray(point);
                    let among = cull.candidates(point);
                    culled += count - among.camera.count_below(count);
                    tests += count;
                    let hit = world.intersect(&ray, f64::INFINITY);
                    let at = format!("pixel ({px}, {py}) offset {offset}");
                    assert_eq!(
                        world.intersect_among(&ray, f64::INFINITY, among.camera),
                        hit,
                        "{at}"
                    );
                    let Some(hit) = hit else { continue };
                    for (index, light) in world.lights.iter().enumerate() {
                        let Some(sample) = light.sample(hit.p) else {
                            continue;
                        };
                        let (shadow, t_max) = match sample.light_position {
                            Some(position) => spawn_ray_to(&hit, position),
                            None => (spawn_ray(&hit, sample.to_light), f64::INFINITY),
                        };
                        let blockers = among.shadow(index);
                        culled += count - blockers.count_below(count);
                        tests += count;
                        assert_eq!(
                            world.occluder_except_among(&shadow, t_max, None, blockers),
                            world.occluder(&shadow, t_max),
                            "{at}, light {index}"
                        );
                    }
                }
            }
        }
        (culled, tests)
    }

    #[test]
    fn culled_camera_and_shadow_rays_meet_exactly_what_unculled_ones_do() {
        let world = World::new(&default_scene()).unwrap();
        let (culled, tests) = assert_culling_is_exact(&world, 160, 120);
        // The point of it: most object tests are skipped.
        assert!(culled * 2 > tests, "{culled} of {tests} culled");
    }

    #[test]
    fn culling_stays_exact_far_from_the_origin_and_at_tiny_and_huge_scales() {
        for (scale, shift) in [(1e-3, 0.0), (1e5, 0.0), (1.0, 1e6), (1e-3, 1e6)] {
            let mut scene = default_scene();
            let place = |p: DVec3| p * scale + DVec3::splat(shift);
            scene.camera.position = place(scene.camera.position);
            scene.camera.look_at = place(scene.camera.look_at);
            for object in &mut scene.objects {
                let Transform::Trs(trs) = &mut object.transform else {
                    panic!("the default scene places objects by TRS");
                };
                trs.translate = place(trs.translate);
                trs.scale *= scale;
            }
            let world = World::new(&scene).unwrap();
            assert_culling_is_exact(&world, 64, 48);
        }
    }

    /// A tiny deterministic generator, so a failing scene can be found again.
    struct Lcg(u64);

    impl Lcg {
        fn unit(&mut self) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1);
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
        fn range(&mut self, lo: f64, hi: f64) -> f64 {
            lo + (hi - lo) * self.unit()
        }
        fn vec(&mut self, lo: f64, hi: f64) -> DVec3 {
            DVec3::new(self.range(lo, hi), self.range(lo, hi), self.range(lo, hi))
        }
    }

    #[test]
    fn culling_stays_exact_on_random_scenes() {
        // The default scene's shapes, materials and light kinds, placed at random: up
        // to twelve objects turned and stretched any way, the camera and the lights
        // anywhere around them (inside objects too).
        let mut rng = Lcg(18);
        for _ in 0..24 {
            let mut scene = default_scene();
            let shapes = scene.objects.clone();
            let count = 1 + (rng.unit() * 12.0) as usize;
            scene.objects = (0..count)
                .map(|k| {
                    let mut object = shapes[k % shapes.len()].clone();
                    object.transform = Transform::Trs(crate::scene::Trs {
                        translate: rng.vec(-4.0, 4.0),
                        rotate_deg: rng.vec(-180.0, 180.0),
                        scale: DVec3::from_array([0; 3].map(|_| 10f64.powf(rng.range(-1.5, 0.7)))),
                    });
                    object
                })
                .collect();
            scene.camera.position = rng.vec(-9.0, 9.0);
            scene.camera.look_at = rng.vec(-1.0, 1.0);
            for light in &mut scene.lights {
                match light {
                    Light::Point { position, .. } => *position = rng.vec(-6.0, 6.0),
                    Light::Spot {
                        position,
                        direction,
                        ..
                    } => {
                        *position = rng.vec(-6.0, 6.0);
                        *direction = -*position + rng.vec(-1.0, 1.0);
                    }
                    Light::Directional { direction, .. } => {
                        *direction = rng.vec(-1.0, 1.0) - DVec3::new(0.0, 1.5, 0.0);
                    }
                    Light::Ambient { .. } => {}
                }
            }
            let world = World::new(&scene).unwrap();
            assert_culling_is_exact(&world, 40, 30);
        }
    }

    #[test]
    fn a_point_outside_the_image_gets_every_object() {
        let world = World::new(&default_scene()).unwrap();
        let camera = PinholeCamera::new(&world.camera, 40, 30);
        let cull = TileCull::new(&world, &camera, 40, 30);
        for point in [(-0.5, 3.0), (48.0, 3.0), (f64::NAN, 3.0)] {
            let among = cull.candidates(DVec2::from(point));
            assert_eq!(among.camera, ObjectSet::ALL);
            assert_eq!(among.shadow(0), ObjectSet::ALL);
        }
        let inside = cull.candidates(DVec2::new(20.0, 20.0));
        assert_eq!(inside.shadow(world.lights.len()), ObjectSet::ALL);
    }
}
