//! A mesh as a solid, for CSG: whether its surface is closed (every edge shared by
//! exactly two triangles, once in each direction, vertices matched by position), and
//! every crossing of a ray with it, in order, alternating in and out.

use std::collections::HashMap;

use super::mesh::TriangleMesh;
use super::triangle::{self, RayShear};
use super::{ShapeHit, in_range};
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
    /// `out` (cleared first), with flat outward normals. Where a ray meets an edge or a
    /// vertex several triangles report the same crossing; of consecutive crossings
    /// with the same direction (in or out) only the first is kept, as crossings of a
    /// closed surface alternate.
    pub fn crossings(&self, ray: &Ray, out: &mut Vec<ShapeHit>) {
        out.clear();
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
        out.sort_by(|x, y| x.t.total_cmp(&y.t));
        let mut last_entering = None;
        out.retain(|hit| {
            let entering = hit.n.dot(ray.dir) < 0.0;
            let keep = last_entering != Some(entering);
            if keep {
                last_entering = Some(entering);
            }
            keep
        });
    }
}

/// Whether every directed edge has its reverse exactly once and no directed edge repeats.
fn closed(positions: &[[f32; 3]], triangles: &[[u32; 3]]) -> bool {
    // Vertices at one position are one vertex (files repeat them per group or normal).
    let mut by_position = HashMap::with_capacity(positions.len());
    let canonical: Vec<u32> = positions
        .iter()
        .enumerate()
        .map(|(index, p)| {
            let key = p.map(f32::to_bits);
            *by_position
                .entry(key)
                .or_insert(u32::try_from(index).expect("under 4G vertices"))
        })
        .collect();
    let mut edges: HashMap<(u32, u32), u32> = HashMap::with_capacity(triangles.len() * 3);
    for t in triangles {
        let [a, b, c] = t.map(|i| canonical[i as usize]);
        for edge in [(a, b), (b, c), (c, a)] {
            *edges.entry(edge).or_insert(0) += 1;
        }
    }
    !edges.is_empty()
        && edges
            .iter()
            .all(|(&(a, b), &count)| count == 1 && edges.get(&(b, a)) == Some(&1))
}
