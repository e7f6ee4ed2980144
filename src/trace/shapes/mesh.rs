//! Triangle meshes ready to trace: the file's triangles in hierarchy order, with the
//! closest-hit and any-hit walks, and the store of meshes a world is compiled with.
//! Reading files is not done here (trace has no I/O): callers read them with
//! `scene::read_scene_meshes` and hand the data to [`MeshStore::build`].

use std::collections::{BTreeMap, HashMap};
use std::sync::Arc;

use glam::{DVec3, Vec3};

use super::bounds::Aabb;
use super::hit::{ShapeHit, in_range};
use super::mesh_bvh::{self, Node};
use super::triangle::{self, RayShear};
use crate::scene::MeshData;
use crate::trace::ray::Ray;

/// The id of the next mesh built.
static NEXT_MESH_ID: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);

/// A mesh with its hierarchy, in object space.
#[derive(Clone, PartialEq)]
pub struct TriangleMesh {
    pub(super) positions: Vec<[f32; 3]>,
    /// Per-vertex normals, or empty.
    normals: Vec<[f32; 3]>,
    /// Triangles in hierarchy order.
    pub(super) triangles: Vec<[u32; 3]>,
    /// The file's number (0-based, after fanning) of each triangle of `triangles`.
    file_index: Vec<u32>,
    nodes: Vec<Node>,
    bounds: Aabb,
    /// Unique among the meshes built in this process (never reused), so caches can tell
    /// whether two worlds hold the same triangles without comparing them.
    id: u64,
    /// Whether the surface is closed, worked out on first need (see `mesh_solid`).
    pub(super) closed: std::sync::OnceLock<bool>,
}

impl std::fmt::Debug for TriangleMesh {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TriangleMesh")
            .field("triangles", &self.triangles.len())
            .field("vertices", &self.positions.len())
            .field("smooth", &self.is_smooth())
            .field("bounds", &self.bounds)
            .finish_non_exhaustive()
    }
}

/// Which triangle a ray met and where on it, for the inspector.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleHit {
    /// The triangle's number in the file (0-based, counting fanned polygons' triangles).
    pub triangle: u32,
    /// Ray parameter.
    pub t: f64,
    /// Barycentric weights of the triangle's three corners, in the file's order.
    pub weights: [f64; 3],
}

impl TriangleMesh {
    /// Builds the hierarchy over a mesh's triangles (in parallel).
    #[must_use]
    pub fn new(data: &MeshData) -> Self {
        let (nodes, order) = mesh_bvh::build(&data.positions, &data.triangles);
        let triangles = order.iter().map(|&i| data.triangles[i as usize]).collect();
        let (min, max) = nodes[0].bounds();
        Self {
            positions: data.positions.clone(),
            normals: data.normals.clone(),
            triangles,
            file_index: order,
            nodes,
            bounds: Aabb::new(min, max),
            id: NEXT_MESH_ID.fetch_add(1, std::sync::atomic::Ordering::Relaxed),
            closed: std::sync::OnceLock::new(),
        }
    }

    /// This mesh's identity: equal ids mean the same triangles.
    #[must_use]
    pub fn id(&self) -> u64 {
        self.id
    }

    /// Number of triangles.
    #[must_use]
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// Whether the file gave vertex normals (the surface is shaded smooth).
    #[must_use]
    pub fn is_smooth(&self) -> bool {
        !self.normals.is_empty()
    }

    /// The object-space bounds of every triangle.
    #[must_use]
    pub fn bounds(&self) -> Aabb {
        self.bounds
    }

    /// Bytes the mesh holds in memory (vertices, normals, triangles, hierarchy).
    #[must_use]
    pub fn memory_bytes(&self) -> usize {
        use std::mem::size_of_val;
        size_of_val(self.positions.as_slice())
            + size_of_val(self.normals.as_slice())
            + size_of_val(self.triangles.as_slice())
            + size_of_val(self.file_index.as_slice())
            + size_of_val(self.nodes.as_slice())
    }

    #[inline(always)]
    pub(super) fn corners(&self, triangle: usize) -> [DVec3; 3] {
        self.triangles[triangle].map(|i| Vec3::from_array(self.positions[i as usize]).as_dvec3())
    }

    /// The nearest crossing with t in (0, t_max): triangle (build order) and crossing.
    fn closest(&self, ray: &Ray, t_max: f64) -> Option<(usize, triangle::TriangleCrossing)> {
        let shear = RayShear::new(ray);
        let mut best = None;
        let mut t_limit = t_max;
        self.walk(
            ray,
            |range, t_limit_now| {
                for index in range {
                    let [a, b, c] = self.corners(index);
                    if let Some(hit) = triangle::cross(&shear, a, b, c, t_limit)
                        && in_range(ray, hit.t, t_limit)
                    {
                        t_limit = hit.t;
                        best = Some((index, hit));
                    }
                }
                *t_limit_now = t_limit;
                false
            },
            t_max,
        );
        best
    }

    /// Visits the leaves whose boxes the ray meets before the current limit, nearer
    /// child first. `visit` may lower the limit; it returns true to stop the walk.
    #[inline(always)]
    pub(super) fn walk(
        &self,
        ray: &Ray,
        mut visit: impl FnMut(std::ops::Range<usize>, &mut f64) -> bool,
        t_max: f64,
    ) {
        let inv_dir = ray.dir.recip();
        let mut t_limit = t_max;
        let mut stack = [0_u32; 64];
        let mut depth = 0;
        let mut at = 0_usize;
        if box_entry(&self.nodes[0], ray, inv_dir, t_limit).is_none() {
            return;
        }
        loop {
            let node = &self.nodes[at];
            if let Some(range) = node.leaf() {
                if visit(range, &mut t_limit) {
                    return;
                }
            } else {
                let (left, right) = node.children(at);
                let near_left = box_entry(&self.nodes[left], ray, inv_dir, t_limit);
                let near_right = box_entry(&self.nodes[right], ray, inv_dir, t_limit);
                match (near_left, near_right) {
                    (Some(l), Some(r)) => {
                        let (first, second) = if l <= r { (left, right) } else { (right, left) };
                        stack[depth] = second as u32;
                        depth += 1;
                        at = first;
                        continue;
                    }
                    (Some(_), None) => {
                        at = left;
                        continue;
                    }
                    (None, Some(_)) => {
                        at = right;
                        continue;
                    }
                    (None, None) => {}
                }
            }
            if depth == 0 {
                return;
            }
            depth -= 1;
            at = stack[depth] as usize;
        }
    }

    /// The closest hit with t in (0, t_max), as every shape reports it. The normal is the
    /// interpolated one where the file has normals and it is safe for this ray
    /// (see `triangle::safe_shading_normal`), else the flat one.
    #[must_use]
    pub fn intersect(&self, ray: &Ray, t_max: f64) -> Option<ShapeHit> {
        let (index, hit) = self.closest(ray, t_max)?;
        let [a, b, c] = self.corners(index);
        let (p, p_error) = triangle::point_and_error(hit.weights, a, b, c);
        let geometric = (b - a).cross(c - a).normalize();
        let n = if self.normals.is_empty() {
            geometric
        } else {
            let [na, nb, nc] = self.triangles[index]
                .map(|i| Vec3::from_array(self.normals[i as usize]).as_dvec3());
            let [wa, wb, wc] = hit.weights;
            let interpolated = (wa * na + wb * nb + wc * nc).normalize_or_zero();
            triangle::safe_shading_normal(ray.dir, geometric, interpolated)
        };
        // Spawned rays leave along `n`; where it is not the flat normal, widen the error
        // bound so the offset along `n` still clears the triangle's plane.
        let p_error = if n == geometric {
            p_error
        } else {
            DVec3::splat(p_error.max_element() * 3.0_f64.sqrt() / n.dot(geometric))
        };
        Some(ShapeHit {
            t: hit.t,
            p,
            n,
            p_error,
        })
    }

    /// Whether the ray meets any triangle with t in (0, t_max).
    #[must_use]
    pub fn occluded(&self, ray: &Ray, t_max: f64) -> bool {
        let shear = RayShear::new(ray);
        let mut found = false;
        self.walk(
            ray,
            |range, _| {
                found = range.into_iter().any(|index| {
                    let [a, b, c] = self.corners(index);
                    triangle::cross(&shear, a, b, c, t_max)
                        .is_some_and(|h| in_range(ray, h.t, t_max))
                });
                found
            },
            t_max,
        );
        found
    }

    /// Which triangle the ray meets first and where on it, for the inspector.
    #[must_use]
    pub fn triangle_hit(&self, ray: &Ray, t_max: f64) -> Option<TriangleHit> {
        let (index, hit) = self.closest(ray, t_max)?;
        Some(TriangleHit {
            triangle: self.file_index[index],
            t: hit.t,
            weights: hit.weights,
        })
    }
}

/// Where the ray enters a node's box, if it does before `t_max`. The far distance is
/// widened by the rounding of the slab arithmetic (Ize 2013), so no box that holds a
/// hit is ever skipped.
#[inline(always)]
fn box_entry(node: &Node, ray: &Ray, inv_dir: DVec3, t_max: f64) -> Option<f64> {
    let (min, max) = node.bounds();
    let t0 = (min - ray.origin) * inv_dir;
    let t1 = (max - ray.origin) * inv_dir;
    let near = t0.min(t1).max_element().max(0.0);
    let far = t0.max(t1).min_element() * (1.0 + 2.0 * super::hit::gamma(3));
    (near <= far.min(t_max) || near.is_nan() || far.is_nan()).then_some(near)
}

/// The meshes a world is compiled with, built once and shared: keyed by the path as the
/// scene writes it.
#[derive(Clone, Debug, Default)]
pub struct MeshStore {
    meshes: HashMap<String, Arc<TriangleMesh>>,
}

impl MeshStore {
    /// Builds every mesh's hierarchy.
    #[must_use]
    pub fn build(data: &BTreeMap<String, MeshData>) -> Self {
        Self {
            meshes: data
                .iter()
                .map(|(path, mesh)| (path.clone(), Arc::new(TriangleMesh::new(mesh))))
                .collect(),
        }
    }

    /// Adds (or replaces) one mesh.
    pub fn insert(&mut self, path: String, mesh: Arc<TriangleMesh>) {
        self.meshes.insert(path, mesh);
    }

    /// The mesh for a path as the scene writes it.
    #[must_use]
    pub fn get(&self, path: &str) -> Option<&Arc<TriangleMesh>> {
        self.meshes.get(path)
    }

    /// The mesh of the object at tree path `object` (for errors), read from `file`.
    ///
    /// # Errors
    /// The file is not among the loaded meshes.
    pub fn for_object(
        &self,
        file: &str,
        object: &str,
    ) -> Result<&Arc<TriangleMesh>, crate::scene::SceneError> {
        self.get(file).ok_or_else(|| {
            crate::scene::SceneError::Invalid(format!(
                "object \"{object}\": the mesh file \"{file}\" is not loaded"
            ))
        })
    }
}
