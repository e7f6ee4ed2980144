//! Property tests of the intersection code: random shapes, transforms and rays.

mod common;

use common::*;
use glam::DVec3;
use proptest::prelude::*;
use raylab::scene::{Material, Shape};
use raylab::trace::spawn_ray;
use raylab::trace::{Ray, World};

/// Whether an object-space point is strictly inside a solid unit shape (`None` for the
/// plane, which has no inside).
fn inside(shape: &Shape, p: DVec3) -> Option<bool> {
    let r2 = p.x * p.x + p.y * p.y;
    Some(match shape {
        Shape::Sphere => p.length_squared() < 1.0,
        Shape::Cube => p.abs().max_element() < 1.0,
        Shape::Cylinder => r2 < 1.0 && p.z.abs() < 1.0,
        Shape::Cone => r2 < p.z * p.z && p.z > 0.0 && p.z < 1.0,
        Shape::Plane => return None,
        Shape::Octahedron => p.abs().element_sum() < 1.0,
        Shape::Torus { minor } => (r2.sqrt() - 1.0).hypot(p.z) < *minor,
        Shape::Tube { inner } => r2 < 1.0 && r2 > inner * inner && p.z.abs() < 1.0,
        other => panic!("no inside test for {other:?}"),
    })
}

/// Distance-like residual of an object-space point from the shape's surface.
fn surface_residual(shape: &Shape, p: DVec3) -> f64 {
    let r = (p.x * p.x + p.y * p.y).sqrt();
    match shape {
        Shape::Sphere => (p.length() - 1.0).abs(),
        Shape::Plane => {
            p.z.abs()
                .max((p.x.abs() - 1.0).max(p.y.abs() - 1.0).max(0.0))
        }
        Shape::Cube => (p.abs().max_element() - 1.0).abs(),
        Shape::Cylinder => {
            let side = (r - 1.0).abs().max((p.z.abs() - 1.0).max(0.0));
            let cap = (p.z.abs() - 1.0).abs().max((r - 1.0).max(0.0));
            side.min(cap)
        }
        Shape::Cone => {
            let side = ((r - p.z).abs() / std::f64::consts::SQRT_2)
                .max((p.z - 1.0).max(0.0))
                .max(-p.z.min(0.0));
            let cap = (p.z - 1.0).abs().max((r - 1.0).max(0.0));
            side.min(cap)
        }
        Shape::Octahedron => (p.abs().element_sum() - 1.0).abs() / 3f64.sqrt(),
        Shape::Torus { minor } => ((r - 1.0).hypot(p.z) - minor).abs(),
        Shape::Tube { inner } => {
            let within_height = (p.z.abs() - 1.0).max(0.0);
            let outer = (r - 1.0).abs().max(within_height);
            let hole = (r - inner).abs().max(within_height);
            let ring = (p.z.abs() - 1.0)
                .abs()
                .max((r - 1.0).max(0.0))
                .max((inner - r).max(0.0));
            outer.min(hole).min(ring)
        }
        other => panic!("no surface residual for {other:?}"),
    }
}

fn shape_strategy() -> impl Strategy<Value = Shape> {
    prop::sample::select(Shape::ALL.to_vec())
}

fn unit_vector() -> impl Strategy<Value = DVec3> {
    (-1.0..1.0f64, 0.0..std::f64::consts::TAU).prop_map(|(z, phi)| {
        let r = (1.0 - z * z).sqrt();
        DVec3::new(r * phi.cos(), r * phi.sin(), z)
    })
}

/// A shape placed with a random rotation, scales from 1e-3 to 1e3 (mixed per axis within
/// a factor of 10), and offsets up to 1e6; and a ray aimed at a random point near it.
fn placed_shape_and_ray() -> impl Strategy<Value = (Shape, DVec3, DVec3, DVec3, Ray)> {
    (
        shape_strategy(),
        -3.0..3.0f64,                            // log10 of the overall scale
        (0.3..3.0f64, 0.3..3.0f64, 0.3..3.0f64), // per-axis factors
        (-180.0..180.0f64, -180.0..180.0f64, -180.0..180.0f64),
        prop::sample::select(vec![0.0, 1.0, 1e3, 1e6]), // offset magnitude
        unit_vector(),
        unit_vector(), // where the eye is, around the object
        (-1.3..1.3f64, -1.3..1.3f64, -1.3..1.3f64), // aim point in object space
        1.5..50.0f64,  // eye distance in object sizes
    )
        .prop_map(
            |(shape, log_scale, factors, rot, offset, offset_dir, eye_dir, aim, distance)| {
                let size = 10f64.powf(log_scale);
                let scale = DVec3::new(factors.0, factors.1, factors.2) * size;
                let rotate = DVec3::new(rot.0, rot.1, rot.2);
                let translate = offset_dir * offset;
                let placed = object(shape.clone(), translate, rotate, scale);
                let m = placed.transform.world_from_object();
                let target = m.transform_point3(DVec3::new(aim.0, aim.1, aim.2));
                let eye = target + eye_dir * distance * scale.max_element();
                (
                    shape,
                    translate,
                    rotate,
                    scale,
                    Ray::new(eye, (target - eye).normalize()),
                )
            },
        )
}

fn world_of(shape: Shape, translate: DVec3, rotate: DVec3, scale: DVec3) -> World {
    let mut scene = bare_scene(Material::default());
    scene.objects.push(object(shape, translate, rotate, scale));
    World::new(&scene).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 3000, ..ProptestConfig::default() })]

    #[test]
    fn hits_lie_on_the_surface_within_their_bound_and_normals_are_unit_and_facing(
        (shape, translate, rotate, scale, ray) in placed_shape_and_ray()
    ) {
        let world = world_of(shape.clone(), translate, rotate, scale);
        let Some(hit) = world.intersect(&ray, f64::INFINITY) else { return Ok(()); };
        prop_assert!(hit.p.is_finite() && hit.n.is_finite() && hit.t.is_finite() && hit.p_error.is_finite());
        prop_assert!((hit.n.length() - 1.0).abs() < 1e-12);
        prop_assert!(hit.n.dot(ray.dir) <= 0.0);
        // The hit is where the ray is (to its own error bound, relative to the travel).
        let along = (hit.p - ray.at(hit.t)).length();
        prop_assert!(along <= 1e-9 * (hit.t + ray.origin.abs().max_element()), "{along}");
        // And on the surface: the object-space residual, mapped to world units by the
        // largest scale, is within the reported bound (plus the map's own rounding).
        let object = &world.objects[0];
        let p_object = object.object_from_world.transform_point3(hit.p);
        let residual = surface_residual(&shape, p_object) * scale.max_element();
        let bound = hit.p_error.length() * 4.0;
        prop_assert!(residual <= bound, "residual {residual} bound {bound}");
    }

    #[test]
    fn nothing_is_crossed_before_the_reported_hit(
        (shape, translate, rotate, scale, ray) in placed_shape_and_ray()
    ) {
        let world = world_of(shape.clone(), translate, rotate, scale);
        let object = &world.objects[0];
        let status = |t: f64| inside(&shape, object.object_from_world.transform_point3(ray.at(t)));
        let Some(start) = status(0.0) else { return Ok(()); };
        let end = world.intersect(&ray, f64::INFINITY).map_or(1e3 * (ray.origin.length() + 1.0), |h| h.t);
        for i in 1..200 {
            let t = end * f64::from(i) / 200.0 * (1.0 - 1e-6);
            prop_assert_eq!(status(t), Some(start), "crossed at t = {} before {}", t, end);
        }
    }

    #[test]
    fn a_ray_spawned_outward_never_hits_its_own_surface_there(
        (shape, translate, rotate, scale, ray) in placed_shape_and_ray(),
        dir in unit_vector(),
    ) {
        prop_assume!(shape != Shape::Plane);
        let world = world_of(shape.clone(), translate, rotate, scale);
        let Some(hit) = world.intersect(&ray, f64::INFINITY) else { return Ok(()); };
        // Leave on the outside, anywhere in the outward hemisphere.
        let dir = if dir.dot(hit.n_outward) < 0.0 { -dir } else { dir };
        prop_assume!(dir.dot(hit.n_outward) > 0.0);
        let spawned = spawn_ray(&hit, dir);
        if shape.is_unit_shape() && !matches!(shape, Shape::Torus { .. } | Shape::Tube { .. }) {
            prop_assert!(world.intersect(&spawned, f64::INFINITY).is_none(), "self-hit from {:?}", hit);
            prop_assert!(world.occluder(&spawned, f64::INFINITY).is_none());
        } else if let Some(next) = world.intersect(&spawned, f64::INFINITY) {
            // A torus or a tube may be met again, but only entering it, away from here.
            prop_assert!(next.n_outward.dot(dir) < 0.0, "left {:?} and hit it leaving at {:?}", hit, next);
            prop_assert!((next.p - hit.p).length() > 1e-9 * scale.max_element(), "self-hit from {:?}", hit);
        }
    }

    #[test]
    fn a_ray_spawned_inward_leaves_through_the_far_side(
        (shape, translate, rotate, scale, ray) in placed_shape_and_ray(),
        dir in unit_vector(),
    ) {
        prop_assume!(shape != Shape::Plane);
        let world = world_of(shape, translate, rotate, scale);
        let Some(hit) = world.intersect(&ray, f64::INFINITY) else { return Ok(()); };
        let dir = if dir.dot(hit.n_outward) > 0.0 { -dir } else { dir };
        prop_assume!(dir.dot(hit.n_outward) < -1e-3);
        let spawned = spawn_ray(&hit, dir);
        let next = world.intersect(&spawned, f64::INFINITY);
        prop_assert!(next.is_some(), "no way out of {:?} from {:?}", world.objects[0].shape, hit);
        let next = next.unwrap();
        prop_assert!(next.n_outward.dot(dir) >= 0.0, "met an entry from inside: {:?}", next);
        prop_assert!((next.p - hit.p).length() > 1e-9 * scale.max_element(), "self-hit from {:?}", hit);
    }

    #[test]
    fn a_plane_spawned_ray_never_hits_its_own_plane(
        (_, translate, rotate, scale, ray) in placed_shape_and_ray(),
        dir in unit_vector(),
    ) {
        let world = world_of(Shape::Plane, translate, rotate, scale);
        let Some(hit) = world.intersect(&ray, f64::INFINITY) else { return Ok(()); };
        prop_assume!(dir.dot(hit.n_outward) != 0.0);
        let spawned = spawn_ray(&hit, dir);
        prop_assert!(world.intersect(&spawned, f64::INFINITY).is_none());
    }
}

/// Every shape, and a CSG lens (bounded by the sphere of one of its operands).
fn shape_or_lens() -> impl Strategy<Value = Shape> {
    let lens = Shape::Csg {
        op: raylab::scene::CsgOp::Intersection,
        operands: [-0.6, 0.6]
            .map(|z| {
                object(
                    Shape::Sphere,
                    DVec3::new(0.0, 0.0, z),
                    DVec3::ZERO,
                    DVec3::ONE,
                )
            })
            .to_vec(),
    };
    prop::sample::select([Shape::ALL.to_vec(), vec![lens]].concat())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    /// A child turned inside a group scaled unevenly is sheared. Its bounds (a box, a
    /// sphere's or a lens's bounding sphere) must still hold all of it: the world finds
    /// each hit the object's own test finds without its bounds, at the same `t`.
    #[test]
    fn a_sheared_object_is_hit_wherever_its_surface_is(
        shape in shape_or_lens(),
        turn in (-180.0..180.0f64, -180.0..180.0f64, -180.0..180.0f64),
        stretch in (0.2..5.0f64, 0.2..5.0f64, 0.2..5.0f64),
        group_turn in (-180.0..180.0f64, -180.0..180.0f64, -180.0..180.0f64),
        eye_dir in unit_vector(),
        aim in (-1.3..1.3f64, -1.3..1.3f64, -1.3..1.3f64),
        distance in 2.0..30.0f64,
    ) {
        let child = object(shape, DVec3::ZERO, DVec3::new(turn.0, turn.1, turn.2), DVec3::ONE);
        let stretch = DVec3::new(stretch.0, stretch.1, stretch.2);
        let group_turn = DVec3::new(group_turn.0, group_turn.1, group_turn.2);
        let group = object(
            Shape::Group { children: vec![child.clone()] },
            DVec3::new(1.0, -2.0, 3.0),
            group_turn,
            stretch,
        );
        let mut scene = bare_scene(Material::default());
        scene.objects.push(group.clone());
        let world = World::new(&scene).unwrap();
        let placed = group.transform.world_from_object() * child.transform.world_from_object();
        let target = placed.transform_point3(DVec3::new(aim.0, aim.1, aim.2));
        let eye = target + eye_dir * distance * stretch.max_element();
        let ray = Ray::new(eye, (target - eye).normalize());
        let bounded = world.intersect(&ray, f64::INFINITY).map(|hit| hit.t);
        let unbounded = world.intersect_object(0, &ray, f64::INFINITY).map(|hit| hit.t);
        prop_assert_eq!(bounded, unbounded);
    }
}

#[test]
fn the_ray_strategy_hits_often_enough_to_test_something() {
    use proptest::strategy::ValueTree;
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let strategy = placed_shape_and_ray();
    let mut hits = 0;
    for _ in 0..1000 {
        let (shape, translate, rotate, scale, ray) =
            strategy.new_tree(&mut runner).unwrap().current();
        if world_of(shape, translate, rotate, scale)
            .intersect(&ray, f64::INFINITY)
            .is_some()
        {
            hits += 1;
        }
    }
    assert!(hits > 400, "only {hits} of 1000 rays hit");
}
