//! The unit shapes' `crossings` against their own `intersect`: for any ray, the first
//! crossing in (0, infinity) is the closest hit, crossings ascend, and each normal faces
//! out of the solid (against the ray where it enters, with it where it leaves).

use glam::DVec3;
use proptest::prelude::*;

use super::{
    Primitive, ShapeHit, crossings, in_range, intersect, line_crossing, line_span, starts_inside,
};
use crate::scene::Shape;
use crate::trace::ray::Ray;

/// Every unit shape as the editor makes it ([`Shape::ALL`]), and the torus whose hole
/// closes, the one that crosses its axis, and a thinner tube.
fn shapes() -> impl Iterator<Item = Primitive> {
    let units = Shape::ALL.iter().filter_map(Primitive::of);
    units.chain([
        Primitive::Torus { minor: 1.0 },
        Primitive::Torus { minor: 1.7 },
        Primitive::Tube { inner: 0.6 },
    ])
}

fn vector(range: f64) -> impl Strategy<Value = DVec3> {
    (-range..range, -range..range, -range..range).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

/// Whether the point is inside the shape's solid (the plane's: the half-space z <= 0).
fn contains(shape: Primitive, p: DVec3) -> bool {
    let r2 = p.x * p.x + p.y * p.y;
    match shape {
        Primitive::Sphere => p.length_squared() <= 1.0,
        Primitive::Plane => p.z <= 0.0,
        Primitive::Cube => p.abs().max_element() <= 1.0,
        Primitive::Cylinder => r2 <= 1.0 && p.z.abs() <= 1.0,
        Primitive::Cone => r2 <= p.z * p.z && (0.0..=1.0).contains(&p.z),
        Primitive::Octahedron => p.abs().element_sum() <= 1.0,
        Primitive::Torus { minor } => (r2.sqrt() - 1.0).hypot(p.z) <= minor,
        Primitive::Tube { inner } => r2 <= 1.0 && r2 >= inner * inner && p.z.abs() <= 1.0,
        Primitive::Mesh => unreachable!("meshes are not among the shapes tested"),
    }
}

proptest! {
    #[test]
    fn crossings_agree_with_intersect_and_bound_the_solid(
        origin in vector(3.0),
        dir in vector(1.0).prop_filter("a direction", |d| d.length() > 0.1),
    ) {
        let ray = Ray::new(origin, dir);
        for shape in shapes() {
            let mut out: Vec<ShapeHit> = Vec::new();
            crossings(shape, &ray, &mut out);
            prop_assert!(out.windows(2).all(|w| w[0].t <= w[1].t), "{shape:?} ascends");
            let mut inside = starts_inside(shape, &ray);
            for hit in &out {
                let facing = hit.n.dot(ray.dir);
                // Entering, the outward normal faces the ray (a touch may be either).
                if inside { prop_assert!(facing >= -1e-9, "{shape:?} leaves along n"); }
                else { prop_assert!(facing <= 1e-9, "{shape:?} enters against n"); }
                inside = !inside;
            }
            // Between crossings the line is inside exactly where the spans say.
            let mut inside = starts_inside(shape, &ray);
            for pair in out.windows(2) {
                inside = !inside;
                if pair[1].t - pair[0].t > 1e-6 {
                    let mid = ray.at(0.5 * (pair[0].t + pair[1].t));
                    prop_assert_eq!(contains(shape, mid), inside, "{:?} between crossings", shape);
                }
            }
            if shape == Primitive::Plane {
                continue; // the plane's intersect is the bounded square, not the half-space
            }
            let first = out.iter().find(|h| in_range(&ray, h.t, f64::INFINITY));
            let closest = intersect(shape, &ray, f64::INFINITY);
            match (first, closest) {
                (Some(a), Some(b)) => prop_assert!((a.t - b.t).abs() <= 1e-9 * a.t.abs().max(1.0),
                    "{shape:?}: first crossing {} but closest hit {}", a.t, b.t),
                (None, None) => {}
                // A touch (tangent, rim, apex) may count on one side and not the other.
                (a, b) => {
                    let t = a.or(b.as_ref()).unwrap().t;
                    let touch = out.windows(2).any(|w| (w[1].t - w[0].t).abs() < 1e-6 && (w[0].t - t).abs() < 1e-6);
                    prop_assert!(touch || a.is_none() && out.len() == 2 && (out[1].t - out[0].t).abs() < 1e-6,
                        "{shape:?}: crossings {out:?} but closest {b:?}");
                }
            }
        }
    }

    #[test]
    fn a_line_span_and_its_crossings_are_crossings_own(
        origin in vector(3.0),
        dir in vector(1.0).prop_filter("a direction", |d| d.length() > 0.1),
        axis in 0usize..4,
    ) {
        // Axis-parallel rays too (`axis` < 3), which graze faces, edges and rims.
        let dir = if axis < 3 { DVec3::AXES[axis] * dir.length() } else { dir };
        let ray = Ray::new(origin, dir);
        for shape in [Primitive::Sphere, Primitive::Cube, Primitive::Cylinder, Primitive::Cone] {
            let mut out: Vec<ShapeHit> = Vec::new();
            crossings(shape, &ray, &mut out);
            let span = line_span(shape, &ray).expect("a shape with line spans");
            match span {
                None => prop_assert!(out.is_empty(), "{shape:?} {out:?}"),
                Some([t0, t1]) => {
                    prop_assert_eq!(out.len(), 2);
                    prop_assert_eq!([out[0].t, out[1].t], [t0, t1]);
                    for (k, t) in [t0, t1].into_iter().enumerate() {
                        prop_assert_eq!(line_crossing(shape, &ray, k, t), out[k]);
                    }
                }
            }
        }
    }
}
