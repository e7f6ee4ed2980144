//! A mesh as a solid, for CSG: whether its surface is closed (every edge shared by
//! exactly two triangles, once in each direction, vertices matched by position), and
//! every crossing of a ray with it, in order, alternating in and out.

use super::hit::{ShapeHit, in_range};
use super::mesh::TriangleMesh;
use super::triangle::{self, RayShear};
use crate::trace::ray::Ray;

impl TriangleMesh {
    /// Whether the mesh bounds a solid: each edge (between vertices at the same
    /// positions) is used by exactly two triangles, in opposite directions. Worked out
    /// once, on first call. Only a closed mesh may be a CSG operand.
    #[must_use]
    pub fn is_closed(&self) -> bool {
        *self
            .closed
            .get_or_init(|| closed(&self.positions, &self.triangles))
    }

    /// Every crossing of the ray with the surface at t > 0, nearest first, appended to
    /// `out` (as `shapes::crossings` does for the unit shapes), with flat outward normals. Where a ray meets an edge or a
    /// vertex several triangles report the same crossing; of consecutive crossings
    /// with the same direction (in or out) only the first is kept, as crossings of a
    /// closed surface alternate.
    pub fn crossings(&self, ray: &Ray, out: &mut Vec<ShapeHit>) {
        let first = out.len();
        let shear = RayShear::new(ray);
        self.walk(
            ray,
            |range, _| {
                for index in range {
                    let [a, b, c] = self.corners(index);
                    if let Some(hit) = triangle::cross(&shear, a, b, c, f64::INFINITY)
                        && in_range(ray, hit.t, f64::INFINITY)
                    {
                        let (p, p_error) = triangle::point_and_error(hit.weights, a, b, c);
                        let n = (b - a).cross(c - a).normalize();
                        out.push(ShapeHit {
                            t: hit.t,
                            p,
                            n,
                            p_error,
                        });
                    }
                }
                false
            },
            f64::INFINITY,
        );
        out[first..].sort_by(|x, y| x.t.total_cmp(&y.t));
        let mut last_entering = None;
        let mut kept = first;
        for index in first..out.len() {
            let entering = out[index].n.dot(ray.dir) < 0.0;
            if last_entering != Some(entering) {
                last_entering = Some(entering);
                out[kept] = out[index];
                kept += 1;
            }
        }
        out.truncate(kept);
    }
}

/// Whether every directed edge has its reverse exactly once and no directed edge repeats.
/// Sorted lists rather than hash maps, in parallel: a million triangles take a small
/// part of a second (hash maps took about one, on the preview's load path).
fn closed(positions: &[[f32; 3]], triangles: &[[u32; 3]]) -> bool {
    use rayon::prelude::*;
    // Vertices at one position are one vertex (files repeat them per group or normal):
    // each takes the smallest index among those at its position.
    let key = |i: u32| positions[i as usize].map(f32::to_bits);
    let mut order: Vec<u32> =
        (0..u32::try_from(positions.len()).expect("under 4G vertices")).collect();
    order.par_sort_unstable_by_key(|&i| (key(i), i));
    let mut canonical = vec![0_u32; positions.len()];
    let mut first = None;
    for &i in &order {
        let same = first.is_some_and(|f| key(f) == key(i));
        if !same {
            first = Some(i);
        }
        canonical[i as usize] = first.expect("set above");
    }
    let edge = |a: u32, b: u32| (u64::from(a) << 32) | u64::from(b);
    let mut edges: Vec<u64> = triangles
        .par_iter()
        .flat_map_iter(|t| {
            let [a, b, c] = t.map(|i| canonical[i as usize]);
            [edge(a, b), edge(b, c), edge(c, a)]
        })
        .collect();
    edges.par_sort_unstable();
    // The edge the other way: its two ends swapped.
    let reverse = |e: u64| e.rotate_right(32);
    !edges.is_empty()
        && edges.windows(2).all(|w| w[0] != w[1])
        && edges
            .par_iter()
            .all(|&e| edges.binary_search(&reverse(e)).is_ok())
}
