//! The objects that may block any of a shading point's shadow rays to a sphere light.
//! Those rays run from the point to points of the light's disc, all within the light's
//! radius of its centre, so they lie inside the cone from the point round the ball of
//! the light. An object whose bounds keep out of that cone blocks none of them: where no
//! object is left, the point sees the whole light and its rays need not be cast (the
//! floor of soft_spot.ron, lit by a sphere spot light, is most of its shading points).
//! And where a round ball covers the whole light as seen from the point, every ray meets
//! it: the point sees none of the light (the middle of a ball's shadow).
//!
//! Two tests, each enough to leave an object out: the cone's axis-aligned box misses the
//! object's box (the flat floor below the points above it), or the object's bounding ball
//! keeps out of the cone. As for the tiles' culling, the margins are far above rounding
//! (a spawned origin moves off the surface by a few error bounds, ~1e-15 relative), so
//! every answer is the one the rays themselves give.

use glam::DVec3;

use super::compiled::World;
use super::object_set::ObjectSet;
use crate::trace::shapes::Aabb;

/// Margin, relative to the lengths involved, by which an object must keep out.
const RELATIVE_MARGIN: f64 = 1e-8;

/// The cone from a shading point round a sphere light's ball.
#[derive(Clone, Copy, Debug)]
pub struct LightCone {
    /// The shading point.
    apex: DVec3,
    /// Unit direction from the apex to the light's centre.
    axis: DVec3,
    /// Distance from the apex to the light's centre.
    length: f64,
    /// The light's radius over `length` (below 1): the sine of the cone's half angle.
    sine: f64,
    /// The cone's axis-aligned box: the apex and the light's ball.
    lo: DVec3,
    hi: DVec3,
    /// The scale of the coordinates involved, for the margins.
    reach: f64,
    /// How far the rays' origins may lie from the apex (their offset off the surface).
    apex_error: f64,
}

impl LightCone {
    /// The cone from `apex` round the ball of `radius` about `centre`, for rays whose
    /// origins lie within `apex_error` of the apex; `None` when the apex is inside the
    /// ball or too near it for a cone.
    #[must_use]
    pub fn new(apex: DVec3, centre: DVec3, radius: f64, apex_error: f64) -> Option<Self> {
        let to_centre = centre - apex;
        let length = to_centre.length();
        let sine = radius / length;
        // (A NaN, from a point at the centre, fails the test too.)
        if sine.is_nan() || sine >= 1.0 - 1e-6 {
            return None;
        }
        Some(Self {
            apex,
            axis: to_centre / length,
            length,
            sine,
            lo: apex.min(centre - radius),
            hi: apex.max(centre + radius),
            reach: length + apex.abs().max_element() + centre.abs().max_element() + radius,
            apex_error,
        })
    }

    /// Whether the cone keeps out of `bounds` and out of the ball of `ball_radius` about
    /// `ball_centre` (both containing the same object) by more than the margin. A
    /// segment from the apex to a point `w` (`|w - centre| <= radius`) is, at its
    /// fraction `u`, within `u * radius` of the axis point `apex + u * length * axis`;
    /// so a ball at axial distance `s` and distance `d` from the axis is met only if
    /// `sqrt(d^2 + x^2) - sine * (x + s) <= ball_radius` for some `x`, whose least left
    /// side is `d * sqrt(1 - sine^2) - sine * s`.
    #[must_use]
    pub fn misses(&self, bounds: &Aabb, ball_centre: DVec3, ball_radius: f64) -> bool {
        let margin = RELATIVE_MARGIN
            * (self.reach + ball_centre.abs().max_element() + ball_radius + bounds_size(bounds))
            + self.apex_error;
        let apart = (bounds.min - self.hi).max(self.lo - bounds.max);
        if apart.max_element() > margin {
            return true;
        }
        let offset = ball_centre - self.apex;
        let along = offset.dot(self.axis);
        let off_axis = (offset.length_squared() - along * along).max(0.0).sqrt();
        let behind = along + ball_radius < -margin;
        let beyond = along - ball_radius > self.length * (1.0 + self.sine) + margin;
        let outside = off_axis * (1.0 - self.sine * self.sine).sqrt() - self.sine * along
            > ball_radius + margin;
        behind || beyond || outside
    }
}

impl LightCone {
    /// Whether the ball of radius `inner` about `centre` (inside an object whose every
    /// point lies within `outer` of `centre`) crosses every segment from the apex to a
    /// point of the light's ball, between its ends: the whole light hidden. The ball is
    /// nearer than any point of the light, the apex outside it, and every segment's
    /// direction within the ball's angular radius `asin(inner / D)` of its centre's: the
    /// angle to the cone's axis plus the cone's half angle, with a margin.
    #[must_use]
    pub fn hidden_by(&self, centre: DVec3, inner: f64, outer: f64) -> bool {
        let offset = centre - self.apex;
        let distance = offset.length();
        let margin =
            RELATIVE_MARGIN * (self.reach + centre.abs().max_element() + outer) + self.apex_error;
        let nearest_light = self.length * (1.0 - self.sine);
        if !(distance - outer > margin && distance + outer < nearest_light * (1.0 - 1e-8) - margin)
        {
            return false;
        }
        let towards = offset / distance;
        let off_axis = self
            .axis
            .cross(towards)
            .length()
            .atan2(self.axis.dot(towards));
        let ball = (inner / distance).asin();
        off_axis + self.sine.asin() < ball - 1e-9
    }
}

/// The longest side of a box (0 for an empty or NaN one), for the margins.
fn bounds_size(bounds: &Aabb) -> f64 {
    let size = (bounds.max - bounds.min).max_element();
    if size.is_finite() { size.max(0.0) } else { 0.0 }
}

impl World {
    /// Whether one of the objects of `among` other than `except` is a ball that hides the
    /// whole light of `cone` from its apex ([`LightCone::hidden_by`]): every ray from the
    /// apex to the light meets that ball.
    #[must_use]
    pub fn ball_hides_light(&self, cone: &LightCone, among: ObjectSet, except: usize) -> bool {
        among
            .members_below(self.objects.len())
            .filter(|&index| index != except)
            .filter_map(|index| self.objects[index].ball())
            .any(|(centre, radius)| {
                cone.hidden_by(centre, radius * (1.0 - 1e-9), radius * (1.0 + 1e-9))
            })
    }

    /// The objects that may block a shadow ray inside `cone`: all of them in a world
    /// too large for [`ObjectSet`] to cull.
    #[must_use]
    pub fn blockers_in_cone(&self, cone: &LightCone) -> ObjectSet {
        if self.objects.len() > ObjectSet::CULLED_BELOW {
            return ObjectSet::ALL;
        }
        let mut set = ObjectSet::none();
        for (index, object) in self.objects.iter().enumerate() {
            let (centre, radius) = object.bounding_ball();
            if !cone.misses(&object.bounds, centre, radius) {
                set.insert(index);
            }
        }
        set
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::parse_scene;
    use crate::test_cases::Xorshift;
    use crate::trace::ray::Ray;
    use crate::trace::world::spawn_ray_to;

    /// The test's random cases.
    struct Cases(Xorshift);

    impl Cases {
        fn unit(&mut self) -> f64 {
            self.0.unit()
        }

        fn within(&mut self, lo: f64, hi: f64) -> f64 {
            lo + (hi - lo) * self.unit()
        }

        fn vector(&mut self, lo: f64, hi: f64) -> DVec3 {
            DVec3::new(
                self.within(lo, hi),
                self.within(lo, hi),
                self.within(lo, hi),
            )
        }

        /// A point of the unit ball, its surface one time in four.
        fn in_ball(&mut self) -> DVec3 {
            loop {
                let v = self.vector(-1.0, 1.0);
                if v.length_squared() <= 1.0 && v.length_squared() > 1e-6 {
                    return if self.unit() < 0.25 { v.normalize() } else { v };
                }
            }
        }
    }

    /// Small balls, whose bounding balls are exact, so that a cone a little too narrow
    /// lets a ray through one.
    fn balls(cases: &mut Cases) -> World {
        let mut objects = String::new();
        for _ in 0..60 {
            let t = cases.vector(-3.0, 3.0);
            let s = cases.within(0.05, 0.4);
            objects += &format!(
                "(shape: Sphere, transform: (translate: ({:?}, {:?}, {:?}), scale: ({s:?}, {s:?}, {s:?})), material: \"m\"),\n",
                t.x, t.y, t.z
            );
        }
        scene_world(&objects)
    }

    fn scene_world(objects: &str) -> World {
        let text = format!(
            r#"Scene(camera: (position: (0.0, 0.0, 10.0), look_at: (0.0, 0.0, 0.0), fov_deg: 45.0, width: 8, height: 8),
                     materials: {{"m": ()}}, objects: [{objects}])"#
        );
        World::new(&parse_scene(&text).unwrap()).unwrap()
    }

    /// Every shape, turned and stretched any way, a sphere sheared by its group and a CSG
    /// lens, packed into a few units.
    fn shapes(cases: &mut Cases) -> World {
        let shapes = [
            "Sphere",
            "Cube",
            "Cylinder",
            "Cone",
            "Plane",
            "Torus(minor: 0.3)",
            "Tube(inner: 0.5)",
            "Octahedron",
        ];
        let mut objects = String::new();
        for i in 0..16 {
            let t = cases.vector(-3.0, 3.0);
            let r = cases.vector(-180.0, 180.0);
            let s = cases.vector(0.2, 1.5);
            objects += &format!(
                "(shape: {}, transform: (translate: ({:?}, {:?}, {:?}), rotate_deg: ({:?}, {:?}, {:?}), scale: ({:?}, {:?}, {:?})), material: \"m\"),\n",
                shapes[i % shapes.len()],
                t.x,
                t.y,
                t.z,
                r.x,
                r.y,
                r.z,
                s.x,
                s.y,
                s.z
            );
        }
        objects += r#"(shape: Group(children: [(shape: Sphere, transform: (rotate_deg: (0.0, 0.0, 45.0)))]),
                       transform: (translate: (1.0, -1.0, 0.5), scale: (2.0, 0.5, 1.0)), material: "m"),
                      (shape: Csg(op: Intersection, operands: [
                          (shape: Sphere, transform: (translate: (0.0, 0.0, -0.6))),
                          (shape: Sphere, transform: (translate: (0.0, 0.0, 0.6)))]),
                       transform: (translate: (-1.0, 1.5, -1.0), rotate_deg: (30.0, 10.0, 0.0), scale: (1.0, 1.5, 0.5)), material: "m"),"#;
        scene_world(&objects)
    }

    /// From surface points of random worlds (every shape; many small balls) towards
    /// sphere lights of many sizes: every ray is blocked where a ball hides the light, and
    /// no ray from the point to any point of the light's ball meets an object the cone leaves
    /// out, though many rays pass close by one (so a cone a little too narrow fails).
    #[test]
    fn no_shadow_ray_meets_an_object_its_cone_leaves_out() {
        let mut cases = Cases(Xorshift(0x2545_f491_4f6c_dd1d));
        let (mut left_out, mut close_calls, mut lights, mut hidden) = (0, 0, 0, 0);
        for round in 0..8 {
            let world = if round % 2 == 0 {
                shapes(&mut cases)
            } else {
                balls(&mut cases)
            };
            let mut points = 0;
            while points < 60 {
                let origin = cases.vector(-6.0, 6.0);
                let toward = cases.vector(-3.0, 3.0) - origin;
                let Some(hit) = world.intersect(&Ray::new(origin, toward), f64::INFINITY) else {
                    continue;
                };
                points += 1;
                for light in 0..8 {
                    // Half the lights anywhere; half behind an object as seen from the
                    // point, small, a little off its line: hidden or nearly.
                    let (centre, radius) = if light % 2 == 0 {
                        (cases.vector(-6.0, 6.0), cases.within(0.01, 2.0))
                    } else {
                        let index = (cases.unit() * world.objects.len() as f64) as usize;
                        let (ball, ball_radius) = world.objects[index].bounding_ball();
                        let behind = hit.p + (ball - hit.p) * cases.within(1.5, 4.0);
                        let off = cases.vector(-1.0, 1.0) * ball_radius;
                        (behind + off, cases.within(0.001, 0.3))
                    };
                    let Some(cone) =
                        LightCone::new(hit.p, centre, radius, 4.0 * hit.p_error.length())
                    else {
                        continue;
                    };
                    lights += 1;
                    let within = world.blockers_in_cone(&cone);
                    if world.ball_hides_light(&cone, within, hit.object) {
                        hidden += 1;
                        for _ in 0..64 {
                            let target = centre + radius * cases.in_ball();
                            let (ray, t_max) = spawn_ray_to(&hit, target);
                            assert!(
                                world.occluder(&ray, t_max).is_some(),
                                "a ray from {} to {target} is clear though a ball hides the light round {centre} (radius {radius})",
                                hit.p
                            );
                        }
                    }
                    for index in 0..world.objects.len() {
                        if within.contains(index) {
                            continue;
                        }
                        left_out += 1;
                        let (ball, ball_radius) = world.objects[index].bounding_ball();
                        for _ in 0..64 {
                            let target = centre + radius * cases.in_ball();
                            let (ray, t_max) = spawn_ray_to(&hit, target);
                            assert!(
                                !world.object_blocks(index, &ray, t_max),
                                "object {index} blocks a ray from {} to {target} though the cone from it round {centre} (radius {radius}) leaves it out",
                                hit.p
                            );
                            // The ray's nearest approach to the object's ball.
                            let along = ((ball - ray.origin).dot(ray.dir)
                                / ray.dir.length_squared())
                            .clamp(0.0, 1.0);
                            if (ray.at(along) - ball).length() < ball_radius * 1.05 {
                                close_calls += 1;
                            }
                        }
                    }
                }
            }
        }
        assert!(lights > 1000, "{lights} lights");
        assert!(left_out > 5000, "{left_out} objects left out");
        assert!(
            close_calls > 500,
            "{close_calls} rays within 5% of a left-out ball"
        );
        assert!(hidden > 500, "{hidden} lights hidden by a ball");
    }

    /// The cone of a unit light 10 away: a ball just outside its side is left out, one
    /// just inside it, behind the point or beyond the light is not met, and a point
    /// inside the light has no cone.
    #[test]
    fn the_cone_keeps_out_of_balls_beside_it_and_meets_those_it_touches() {
        let cone = LightCone::new(DVec3::ZERO, DVec3::new(0.0, 0.0, 10.0), 1.0, 0.0).unwrap();
        let far_box = |c: DVec3, _: f64| Aabb::new(c - 100.0, c + 100.0); // never separates
        // Half angle asin(0.1): at 5 along, the side is 5 tan(asin 0.1) = 0.5025 off axis;
        // a ball of radius 0.1 is tangent to the side when its centre is 0.1 / cos further.
        let side = 5.0 * 0.1 / (1.0f64 - 0.01).sqrt() + 0.1 / (1.0f64 - 0.01).sqrt();
        let at = |off: f64| DVec3::new(off, 0.0, 5.0);
        assert!(cone.misses(&far_box(at(side * 1.001), 0.1), at(side * 1.001), 0.1));
        assert!(!cone.misses(&far_box(at(side * 0.999), 0.1), at(side * 0.999), 0.1));
        assert!(cone.misses(
            &far_box(DVec3::new(0.0, 0.0, -0.2), 0.1),
            DVec3::new(0.0, 0.0, -0.2),
            0.1
        ));
        assert!(cone.misses(
            &far_box(DVec3::new(0.0, 0.0, 11.2), 0.1),
            DVec3::new(0.0, 0.0, 11.2),
            0.1
        ));
        assert!(
            LightCone::new(
                DVec3::new(0.0, 0.0, 9.5),
                DVec3::new(0.0, 0.0, 10.0),
                1.0,
                0.0
            )
            .is_none()
        );
    }

    /// A light of radius 1 at 10 seen from the origin spans asin(0.1); a ball at 5 on the
    /// line hides it where its own angular radius is larger, with the margin, and not
    /// where it is smaller, nor where it lies beyond the light or round the point.
    #[test]
    fn a_ball_on_the_line_to_the_light_hides_it_only_when_it_covers_it() {
        let cone = LightCone::new(DVec3::ZERO, DVec3::new(0.0, 0.0, 10.0), 1.0, 0.0).unwrap();
        let at = DVec3::new(0.0, 0.0, 5.0);
        // sin(asin 0.1) * 5 = 0.5: the ball's radius where the two angles are equal.
        assert!(cone.hidden_by(at, 0.5001, 0.5001));
        assert!(!cone.hidden_by(at, 0.4999, 0.4999));
        // Moved off the line by 0.1: it must be larger by about 0.1.
        let off = at + DVec3::new(0.1, 0.0, 0.0);
        assert!(!cone.hidden_by(off, 0.55, 0.55) && cone.hidden_by(off, 0.61, 0.61));
        assert!(
            !cone.hidden_by(DVec3::new(0.0, 0.0, 12.0), 5.0, 5.0),
            "beyond the light"
        );
        assert!(!cone.hidden_by(DVec3::ZERO, 0.5, 0.5), "round the point");
        assert!(
            !cone.hidden_by(DVec3::new(0.0, 0.0, 8.5), 0.9, 0.9),
            "reaching the light"
        );
    }
}
