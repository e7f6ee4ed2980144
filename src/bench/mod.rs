//! `raylab bench`: throughput, speed against error, and the cost of double precision.
//! Everything here calls the same tracer as the editor and the command line.

pub mod class;
pub mod convergence;
pub mod crossover;
pub mod diff;
pub mod diff_accuracy;
pub mod edit_latency;
pub mod mesh;
pub mod plot;
pub mod precision;
pub mod random_scene;
pub mod throughput;

use std::collections::BTreeMap;

use serde::Serialize;

pub use convergence::{CurveChecks, CurvePoint, convergence_curves, curve_checks};
pub use crossover::{CrossoverPoint, bvh_crossover};
pub use edit_latency::{EditLatency, FirstFrameLatency, edit_latency};
pub use precision::{PrecisionCost, precision_cost};
pub use throughput::{SceneThroughput, scene_throughput};

/// Everything one `raylab bench` run measured.
#[derive(Clone, Debug, Serialize)]
pub struct BenchReport {
    /// Whether this was a `--quick` run.
    pub quick: bool,
    /// Worker threads rayon used.
    pub threads: usize,
    /// Throughput of the default scene at 1 sample per pixel, millions of rays per second.
    pub throughput_mrays_per_s: f64,
    /// Time of a full 800x600 frame of the default scene at 1 sample per pixel.
    pub full_frame_1spp_ms: f64,
    /// Edit to first coarse preview frame, through the preview worker.
    pub first_preview_ms: Option<f64>,
    /// Edit to first full-resolution preview frame, through the preview worker.
    pub first_full_preview_ms: Option<f64>,
    /// Edit submitted midway through the last pass to the first frame of the edit, by the
    /// scene's samples per pixel ("16", "4096"), through the preview worker.
    pub restart_latency_ms: BTreeMap<String, f64>,
    /// Edit to first full-resolution frame by kind of edit, default scene at 800x600,
    /// through the preview worker: material, switch and light colour edits re-shade
    /// cached hits, a moved light re-casts its shadow rays, geometry re-traces.
    pub edit_to_full_frame_ms: EditLatency,
    /// The same for `glass.ron` (where the measured scenes include it) with its glass
    /// ball first, so that the material edited is the glass: its trees of rays are
    /// re-shaded from the cache as a chain is.
    pub glass_edit_to_full_frame_ms: Option<EditLatency>,
    /// Per example scene.
    pub scenes: Vec<SceneThroughput>,
    /// Error against time for the default scene, per strategy.
    pub curve: Vec<CurvePoint>,
    /// The same curve for the sphere-light example (`soft_spot.ron`), where one exists
    /// among the measured scenes. Printed, not in `--json` (no issue has named a key).
    #[serde(skip)]
    pub sphere_light_curve: Vec<CurvePoint>,
    /// The curve's progressive passes against uniform sampling, and the preview's error
    /// estimate against the true error.
    pub curve_checks: CurveChecks,
    /// The intersection kernel in f32 and f64.
    pub precision: PrecisionCost,
    /// Flat list against BVH for growing object counts.
    pub bvh_crossover: Vec<CrossoverPoint>,
    /// `raylab diff` of a 500x500 scene with 5 objects and 3 lights, best time.
    pub diff_500_ms: f64,
    /// `raylab diff` of a 1280x720 course scene with mirrors at 4 samples a pixel (like
    /// the public corpus's slowest pair) against a mirror-blending tracer's picture, best
    /// time.
    pub diff_1280x720_ms: f64,
    /// `raylab class` on a generated class (the example scenes at 400x300 with planted
    /// bugs; 6 students x 10 scenes, a quick run 3 x 4), every pair compared, per minute.
    pub class_pairs_per_minute: f64,
    /// Of bugs planted alone in example and random scenes never tuned on (see
    /// `bench::diff_accuracy::report_accuracy`), the share the diff names first.
    pub diff_top1: f64,
    /// The same, named in the top two.
    pub diff_top2: f64,
    /// Of correct pictures (raylab's own at 1, 2 and 4 samples per pixel), the share in
    /// which the diff claims a bug.
    pub diff_false_verdicts: f64,
    /// Triangles of the generated torus knot of the mesh section.
    pub mesh_triangles: usize,
    /// Best time to build the knot's hierarchy, all cores.
    pub mesh_build_ms: f64,
    /// Primary rays per second through the knot, all cores, millions.
    pub mesh_mrays_per_s: f64,
    /// Memory of the built knot per triangle.
    pub mesh_bytes_per_triangle: f64,
    /// Median ms from a material or light-colour edit of the knot on a floor to the
    /// preview's first frame. Printed, not in `--json` (no issue has named a key).
    #[serde(skip)]
    pub mesh_edit_first_frame_ms: Option<FirstFrameLatency>,
}
