//! Hit points checked in higher precision: every reported hit lies within its own error
//! bound of the true surface. The surface is the f64 transform of the unit shape (the
//! matrix is exact by definition); distances are measured in double-double arithmetic.
//!
//! `cargo test --release --test hit_precision -- --ignored --nocapture` prints the table
//! of measured errors in docs/NUMERICS.md.

mod common;

use common::*;
use glam::DVec3;
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use raylab::scene::{Material, Shape};
use raylab::trace::WorldObject;
use raylab::trace::shapes::Primitive;
use raylab::trace::{Ray, SurfacePoint, World};
use twofloat::TwoFloat as Dd;

/// The object-space point that `world_from_object` takes exactly to `p_world`, in
/// double-double: Newton steps on the residual p - (M q + t).
fn to_object_precise(object: &WorldObject, p_world: DVec3) -> [Dd; 3] {
    let m = object.world_from_object.matrix3;
    let t = object.world_from_object.translation;
    let inverse = object.object_from_world.matrix3;
    let start = object.object_from_world.transform_point3(p_world);
    let mut q = [Dd::from(start.x), Dd::from(start.y), Dd::from(start.z)];
    for _ in 0..3 {
        let mut residual = DVec3::ZERO;
        for row in 0..3 {
            let r = m.row(row);
            let mapped = Dd::from(r.x) * q[0]
                + Dd::from(r.y) * q[1]
                + Dd::from(r.z) * q[2]
                + Dd::from(t[row]);
            residual[row] = f64::from(Dd::from(p_world[row]) - mapped);
        }
        let step = inverse * residual;
        for axis in 0..3 {
            q[axis] += Dd::from(step[axis]);
        }
    }
    q
}

/// Distance (world units) from `p_world` to the true surface of `object`, and the
/// object-space unit normal used to convert it.
fn distance_to_surface(object: &WorldObject, p_world: DVec3) -> f64 {
    let q = to_object_precise(object, p_world);
    let q64 = DVec3::new(q[0].hi(), q[1].hi(), q[2].hi());
    let radius = (q[0] * q[0] + q[1] * q[1]).sqrt();
    let z = q[2];
    let one = Dd::from(1.0);
    let near = |x: f64, limit: f64| x <= limit * (1.0 + 1e-9);
    // Each part: (signed object-space distance, object-space normal), when p is over it.
    let mut parts: Vec<(f64, DVec3)> = Vec::new();
    match object.shape {
        Primitive::Sphere => {
            let len = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt();
            parts.push((f64::from(len - one), q64.normalize()));
        }
        Primitive::Plane => parts.push((q64.z, DVec3::Z)),
        // Mesh hit points are checked in tests/mesh.rs (spawned rays clear their triangle).
        Primitive::Mesh => unreachable!("the precision scenes have no meshes"),
        Primitive::Cube => {
            for axis in 0..3 {
                let others_inside = (0..3)
                    .filter(|&a| a != axis)
                    .all(|a| near(q64[a].abs(), 1.0));
                if others_inside {
                    let mut n = DVec3::ZERO;
                    n[axis] = 1.0;
                    parts.push((f64::from(q[axis].abs() - one), n));
                }
            }
        }
        Primitive::Cylinder => {
            if near(q64.z.abs(), 1.0) {
                parts.push((
                    f64::from(radius - one),
                    DVec3::new(q64.x, q64.y, 0.0).normalize_or_zero(),
                ));
            }
            if near(radius.hi(), 1.0) {
                parts.push((f64::from(z.abs() - one), DVec3::Z));
            }
        }
        Primitive::Cone => {
            if near(q64.z, 1.0) && q64.z >= -1e-9 {
                let side = f64::from((radius - z) / Dd::from(std::f64::consts::SQRT_2));
                let n = DVec3::new(q64.x, q64.y, -radius.hi()).normalize_or(-DVec3::Z);
                parts.push((side, n));
            }
            if near(radius.hi(), 1.0) {
                parts.push((f64::from(z - one), DVec3::Z));
            }
        }
        Primitive::Torus { minor } => {
            // Distance to the circle's nearest point, less the tube radius.
            let from_circle = ((radius - one) * (radius - one) + z * z).sqrt();
            let centre = DVec3::new(q64.x, q64.y, 0.0).normalize_or(DVec3::X);
            let n = (q64 - centre).normalize_or(DVec3::Z);
            parts.push((f64::from(from_circle - Dd::from(minor)), n));
        }
        Primitive::Tube { inner } => {
            let radial_n = DVec3::new(q64.x, q64.y, 0.0).normalize_or_zero();
            if near(q64.z.abs(), 1.0) {
                parts.push((f64::from(radius - one), radial_n));
                parts.push((f64::from(radius - Dd::from(inner)), radial_n));
            }
            if near(radius.hi(), 1.0) && radius.hi() >= inner * (1.0 - 1e-9) {
                parts.push((f64::from(z.abs() - one), DVec3::Z));
            }
        }
        Primitive::Octahedron => {
            // The face whose sign vector matches the point's: s.q = |x| + |y| + |z|.
            let sign = |x: Dd| if x.hi() < 0.0 { -x } else { x };
            let sum = sign(q[0]) + sign(q[1]) + sign(q[2]);
            let s = DVec3::new(q64.x.signum(), q64.y.signum(), q64.z.signum());
            let d = (sum - one) / Dd::from(3f64.sqrt());
            parts.push((f64::from(d), s.normalize()));
        }
    }
    parts
        .into_iter()
        .map(|(d_object, n_object)| {
            // A plane n.x = c in object space is at distance 1/|N n| per unit of c in world.
            let stretch = (object.normal_from_object * n_object).length();
            d_object.abs() / stretch
        })
        .fold(f64::INFINITY, f64::min)
}

/// The bound the tracer reports along the normal: what `spawn` offsets by (before its
/// safety factor).
fn reported_bound(hit: &SurfacePoint) -> f64 {
    hit.n_outward.abs().dot(hit.p_error)
}

fn unit_vector() -> impl Strategy<Value = DVec3> {
    (-1.0..1.0f64, 0.0..std::f64::consts::TAU).prop_map(|(z, phi)| {
        let r = (1.0 - z * z).sqrt();
        DVec3::new(r * phi.cos(), r * phi.sin(), z)
    })
}

/// A random placement (scales 1e-3..1e3, any rotation, offsets up to 1e6) and a ray from
/// outside aimed near the object.
fn case(shape: Shape) -> impl Strategy<Value = (World, Ray)> {
    (
        -3.0..3.0f64,
        (0.3..3.0f64, 0.3..3.0f64, 0.3..3.0f64),
        (-180.0..180.0f64, -180.0..180.0f64, -180.0..180.0f64),
        prop::sample::select(vec![0.0, 10.0, 1e4, 1e6]),
        unit_vector(),
        unit_vector(),
        (-1.2..1.2f64, -1.2..1.2f64, -1.2..1.2f64),
        1.5..30.0f64,
    )
        .prop_map(
            move |(log_scale, f, r, offset, offset_dir, eye_dir, aim, distance)| {
                let scale = DVec3::new(f.0, f.1, f.2) * 10f64.powf(log_scale);
                let mut scene = bare_scene(Material::default());
                scene.objects.push(object(
                    shape.clone(),
                    offset_dir * offset,
                    DVec3::new(r.0, r.1, r.2),
                    scale,
                ));
                let world = World::new(&scene).unwrap();
                let target = world.objects[0]
                    .world_from_object
                    .transform_point3(DVec3::new(aim.0, aim.1, aim.2));
                let eye = target + eye_dir * distance * scale.max_element();
                (world, Ray::new(eye, (target - eye).normalize()))
            },
        )
}

/// Every unit shape, and the torus also thin, horn and spindle, the tube also thin-walled.
fn measured_shapes() -> Vec<Shape> {
    let mut shapes = Shape::ALL.to_vec();
    shapes.extend(
        [0.02, 1.0, 1.6]
            .map(|minor| Shape::Torus { minor })
            .into_iter()
            .chain([Shape::Tube { inner: 0.97 }]),
    );
    shapes
}

fn any_case() -> impl Strategy<Value = (World, Ray)> {
    prop::sample::select(measured_shapes()).prop_flat_map(case)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 10000, ..ProptestConfig::default() })]

    #[test]
    fn every_hit_lies_within_its_reported_bound_of_the_true_surface((world, ray) in any_case()) {
        let Some(hit) = world.intersect(&ray, f64::INFINITY) else { return Ok(()); };
        let distance = distance_to_surface(&world.objects[0], hit.p);
        let bound = reported_bound(&hit);
        prop_assert!(distance <= bound, "{:?}: distance {distance:e} > bound {bound:e} at {}", world.objects[0].shape, hit.p);
    }
}

/// Measured error of hit points per shape, in ulps of the hit point's largest component;
/// the table in docs/NUMERICS.md.
#[test]
#[ignore = "prints the table for docs/NUMERICS.md; run with --ignored --nocapture"]
fn print_error_table() {
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    println!(
        "| shape | hits | max error (ulps of |p|) | mean error (ulps of |p|) | mean bound (ulps of |p|) |"
    );
    println!("|---|---|---|---|---|");
    for shape in measured_shapes() {
        let strategy = case(shape.clone());
        let (mut hits, mut max, mut sum, mut bound_sum) = (0u32, 0f64, 0f64, 0f64);
        for _ in 0..20_000 {
            let (world, ray) = strategy.new_tree(&mut runner).unwrap().current();
            let Some(hit) = world.intersect(&ray, f64::INFINITY) else {
                continue;
            };
            let magnitude = hit.p.abs().max_element();
            let ulp = magnitude.next_up() - magnitude;
            let error = distance_to_surface(&world.objects[0], hit.p) / ulp;
            hits += 1;
            max = max.max(error);
            sum += error;
            bound_sum += reported_bound(&hit) / ulp;
        }
        let n = f64::from(hits);
        let name = match shape {
            Shape::Torus { minor } => format!("Torus (minor {minor})"),
            Shape::Tube { inner } => format!("Tube (inner {inner})"),
            _ => shape.name().to_owned(),
        };
        println!(
            "| {name} | {hits} | {max:.2} | {:.3} | {:.1} |",
            sum / n,
            bound_sum / n
        );
    }
}
