//! The mesh benchmark: a finely tessellated torus knot (a closed tube, a million
//! triangles and more), its hierarchy's build time and memory, primary-ray throughput
//! through it on all cores, and how soon the editor's preview shows an edit of it.

use std::f64::consts::TAU;
use std::time::Instant;

use glam::DVec3;
use rayon::prelude::*;
use serde::Serialize;

use super::edit_latency::{FirstFrameLatency, first_frame_latency};
use crate::preview::PreviewRequest;
use crate::scene::MeshData;
use crate::trace::{MeshStore, Ray, TriangleMesh};

/// What the mesh benchmark measured.
#[derive(Clone, Debug, Serialize)]
pub struct MeshBench {
    /// Triangles in the mesh.
    pub triangles: usize,
    /// Best time to build the hierarchy, all cores.
    pub build_ms: f64,
    /// Primary rays per second through the mesh, all cores, millions.
    pub mrays_per_s: f64,
    /// Memory of the built mesh per triangle.
    pub bytes_per_triangle: f64,
}

/// A (p, q) torus knot of major radius 1 and knot radius 0.4, as a closed tube of radius
/// `tube` with `segments` rings of `sides` vertices: 2 x segments x sides triangles,
/// counter-clockwise seen from outside, with smooth normals when `normals` is set.
#[must_use]
pub fn torus_knot(segments: u32, sides: u32, tube: f64, normals: bool) -> MeshData {
    let (p, q) = (2.0, 3.0);
    let centre = |s: f64| {
        let r = 1.0 + 0.4 * (q * s).cos();
        DVec3::new(r * (p * s).cos(), r * (p * s).sin(), 0.4 * (q * s).sin())
    };
    let mut mesh = MeshData::default();
    for i in 0..segments {
        let s = TAU * f64::from(i) / f64::from(segments);
        let c = centre(s);
        let tangent = (centre(s + 1e-4) - centre(s - 1e-4)).normalize();
        // The knot's tangent is never vertical (its xy speed is at least p(1 - 0.4)).
        let n = tangent.cross(DVec3::Z).normalize();
        let b = tangent.cross(n);
        for j in 0..sides {
            let a = TAU * f64::from(j) / f64::from(sides);
            let out = n * a.cos() + b * a.sin();
            mesh.positions.push((c + tube * out).as_vec3().to_array());
            if normals {
                mesh.normals.push(out.as_vec3().to_array());
            }
        }
    }
    let at = |i: u32, j: u32| (i % segments) * sides + (j % sides);
    for i in 0..segments {
        for j in 0..sides {
            let (v00, v10, v01, v11) = (at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1));
            mesh.triangles.push([v00, v10, v11]);
            mesh.triangles.push([v00, v11, v01]);
        }
    }
    mesh
}

/// Builds a torus knot of about `triangles` triangles and measures it: the best of
/// `runs` builds, and primary rays from a pinhole camera (`width` x `height`, framing the
/// whole knot) timed over `runs` passes.
#[must_use]
pub fn mesh_bench(triangles: u32, width: u32, height: u32, runs: u32) -> MeshBench {
    let sides = 100;
    let segments = (triangles / (2 * sides)).max(3);
    let data = torus_knot(segments, sides, 0.15, true);
    let mut build_ms = f64::INFINITY;
    let mut mesh = None;
    for _ in 0..runs.max(1) {
        let start = Instant::now();
        let built = TriangleMesh::new(&data);
        build_ms = build_ms.min(start.elapsed().as_secs_f64() * 1e3);
        mesh = Some(built);
    }
    let mesh = mesh.expect("built at least once");
    let rays = camera_rays(width, height);
    let start = Instant::now();
    let mut hits = 0;
    for _ in 0..runs.max(1) {
        hits += rays
            .par_iter()
            .filter(|ray| mesh.intersect(ray, f64::INFINITY).is_some())
            .count();
    }
    let seconds = start.elapsed().as_secs_f64();
    assert!(hits > 0, "the camera sees the knot");
    MeshBench {
        triangles: mesh.triangle_count(),
        build_ms,
        mrays_per_s: (rays.len() as f64 * f64::from(runs.max(1))) / seconds / 1e6,
        bytes_per_triangle: mesh.memory_bytes() as f64 / mesh.triangle_count() as f64,
    }
}

/// Rays from a pinhole camera at (0, 0, 4) looking down -z with a 60 degree vertical
/// field of view (the knot fills most of the frame), one through each pixel centre.
#[must_use]
pub fn camera_rays(width: u32, height: u32) -> Vec<Ray> {
    let origin = DVec3::new(0.0, 0.0, 4.0);
    let half_height = (30.0_f64).to_radians().tan();
    let half_width = half_height * f64::from(width) / f64::from(height);
    (0..height)
        .flat_map(|y| (0..width).map(move |x| (x, y)))
        .map(|(x, y)| {
            let u = (2.0 * (f64::from(x) + 0.5) / f64::from(width) - 1.0) * half_width;
            let v = (1.0 - 2.0 * (f64::from(y) + 0.5) / f64::from(height)) * half_height;
            Ray::new(origin, DVec3::new(u, v, -1.0).normalize())
        })
        .collect()
}

/// The editor's case of issue 36: a knot of about `triangles` triangles on a floor under
/// a point light, 800x600 at 4 samples, previewed by the real worker with the mesh built
/// once; the time from a material or light-colour edit to the first frame shown.
///
/// # Errors
/// When the scene cannot be rendered.
pub fn mesh_edit_latency(triangles: u32, runs: u32) -> Result<FirstFrameLatency, String> {
    let sides = 100;
    let segments = (triangles / (2 * sides)).max(3);
    let mut store = MeshStore::default();
    let knot = TriangleMesh::new(&torus_knot(segments, sides, 0.15, true));
    store.insert("knot.obj".to_owned(), std::sync::Arc::new(knot));
    let scene = crate::scene::parse_scene(KNOT_SCENE).map_err(|e| e.to_string())?;
    let request = PreviewRequest {
        meshes: std::sync::Arc::new(store),
        ..PreviewRequest::for_scene(1, scene)
    };
    first_frame_latency(request, runs)
}

/// The scene of [`mesh_edit_latency`]; the knot comes first, so the material edit is
/// its material's.
const KNOT_SCENE: &str = r#"Scene(
    camera: (position: (0.0, -3.5, 2.5), look_at: (0.0, 0.0, 0.0), up: (0.0, 0.0, 1.0),
             fov_deg: 50.0, width: 800, height: 600),
    render: (max_depth: 2, background: (0.05, 0.05, 0.08), samples_per_pixel: 4),
    materials: {
        "gold": (ambient: (0.08, 0.06, 0.02), diffuse: (0.64, 0.48, 0.16),
                 specular: (0.5, 0.5, 0.5), shininess: 40.0),
        "floor": (ambient: (0.1, 0.1, 0.1), diffuse: (0.5, 0.5, 0.5),
                  mirror: (0.2, 0.2, 0.2)),
    },
    objects: [
        (name: "knot", shape: Mesh(path: "knot.obj"), material: "gold"),
        (name: "floor", shape: Plane, transform: (translate: (0.0, 0.0, -0.8),
         scale: (6.0, 6.0, 1.0)), material: "floor"),
    ],
    lights: [
        Ambient(colour: (1.0, 1.0, 1.0)),
        Point(position: (-3.0, -4.0, 6.0), colour: (1.0, 1.0, 1.0), intensity: 60.0),
    ],
)"#;

#[cfg(test)]
mod tests {
    #[test]
    fn the_mesh_edit_latency_runs_on_a_small_knot_through_the_real_worker() {
        // A material edit and a light edit of a 2,000-triangle knot each reach a frame.
        let latency = super::mesh_edit_latency(2_000, 1).expect("the scene renders");
        for ms in [latency.material, latency.light_colour] {
            assert!(ms.is_finite() && ms > 0.0, "{ms}");
        }
    }
}
