//! raylab's binned-SAH mesh hierarchy against obvhs's PLOC builders (BVH2 and the wide
//! CWBVH) on the 1,000,000-triangle knot of `raylab bench`: best build time of 3 on all
//! cores, and primary rays through each (800x600, the bench's camera) per second on one
//! thread. raylab traverses in f64 with watertight triangles; obvhs in f32 with its own
//! triangle test, so its rays are cheaper per test by design.

use std::time::{Duration, Instant};

use glam::Vec3A;
use obvhs::{
    BvhBuildParams,
    bvh2::builder::build_bvh2_from_tris,
    cwbvh::builder::build_cwbvh_from_tris,
    ray::{Ray, RayHit},
    triangle::Triangle,
};
use raylab::bench::mesh::{camera_rays, torus_knot};
use raylab::trace::TriangleMesh;

fn best_of<T>(runs: u32, mut f: impl FnMut() -> T) -> (T, f64) {
    let mut best = f64::INFINITY;
    let mut out = None;
    for _ in 0..runs {
        let start = Instant::now();
        out = Some(f());
        best = best.min(start.elapsed().as_secs_f64() * 1e3);
    }
    (out.expect("ran"), best)
}

fn main() {
    let data = torus_knot(5000, 100, 0.15, false);
    let rays = camera_rays(800, 600);
    let one_thread = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    println!(
        "{} triangles, {} rays, {} threads for builds",
        data.triangles.len(),
        rays.len(),
        rayon::current_num_threads()
    );

    let (mesh, ms) = best_of(3, || TriangleMesh::new(&data));
    let (hits, trace) = best_of(3, || {
        one_thread.install(|| {
            rays.iter()
                .filter(|r| mesh.intersect(r, f64::INFINITY).is_some())
                .count()
        })
    });
    println!(
        "raylab binned SAH (8 bins): build {ms:.0} ms, {:.2} Mrays/s one thread, {hits} hits, {:.1} bytes/triangle",
        rays.len() as f64 / trace / 1e3,
        mesh.memory_bytes() as f64 / data.triangles.len() as f64
    );

    let tris: Vec<Triangle> = data
        .triangles
        .iter()
        .map(|t| {
            let [v0, v1, v2] = t.map(|i| Vec3A::from_array(data.positions[i as usize]));
            Triangle { v0, v1, v2 }
        })
        .collect();
    let obvhs_rays: Vec<Ray> = rays
        .iter()
        .map(|r| Ray::new_inf(r.origin.as_vec3a(), r.dir.as_vec3a()))
        .collect();
    for (name, params) in [
        ("fast_build", BvhBuildParams::fast_build()),
        ("medium_build", BvhBuildParams::medium_build()),
    ] {
        let (bvh, ms) = best_of(3, || {
            build_bvh2_from_tris(&tris, params, &mut Duration::default())
        });
        let (hits, trace) = best_of(3, || {
            obvhs_rays
                .iter()
                .filter(|&&ray| {
                    let mut hit = RayHit::none();
                    bvh.ray_traverse(ray, &mut hit, |ray, id| {
                        tris[bvh.primitive_indices[id] as usize].intersect(ray)
                    })
                })
                .count()
        });
        println!(
            "obvhs BVH2 PLOC {name}: build {ms:.0} ms, {:.2} Mrays/s one thread, {hits} hits",
            obvhs_rays.len() as f64 / trace / 1e3
        );
        let (wide, ms) = best_of(3, || {
            build_cwbvh_from_tris(&tris, params, &mut Duration::default())
        });
        let (hits, trace) = best_of(3, || {
            obvhs_rays
                .iter()
                .filter(|&&ray| {
                    let mut hit = RayHit::none();
                    wide.ray_traverse(ray, &mut hit, |ray, id| {
                        tris[wide.primitive_indices[id] as usize].intersect(ray)
                    })
                })
                .count()
        });
        println!(
            "obvhs CWBVH {name}: build {ms:.0} ms, {:.2} Mrays/s one thread, {hits} hits",
            obvhs_rays.len() as f64 / trace / 1e3
        );
    }
}
