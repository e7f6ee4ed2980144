//! Tracing triangle meshes: watertightness (rays aimed exactly at shared edges and
//! vertices never slip through), interpolated normals, the hierarchy against brute
//! force, and meshes in a world (render, errors, spawned rays).

use glam::DVec3;
use raylab::bench::mesh::torus_knot;
use raylab::scene::{MeshData, parse_scene};
use raylab::trace::{MeshStore, Ray, TriangleMesh, World};

/// The top face z = 1 of [-1, 1]^2 as an n x n grid of quads (two triangles each,
/// alternating diagonals), vertices shared: every coordinate is exact in binary.
fn grid(n: u32) -> MeshData {
    let mut mesh = MeshData::default();
    for j in 0..=n {
        for i in 0..=n {
            let at = |k: u32| -1.0 + 2.0 * k as f32 / n as f32;
            mesh.positions.push([at(i), at(j), 1.0]);
        }
    }
    let v = |i: u32, j: u32| j * (n + 1) + i;
    for j in 0..n {
        for i in 0..n {
            let (a, b, c, d) = (v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1));
            if (i + j) % 2 == 0 {
                mesh.triangles.extend([[a, b, c], [a, c, d]]);
            } else {
                mesh.triangles.extend([[a, b, d], [b, c, d]]);
            }
        }
    }
    mesh
}

#[test]
fn rays_along_shared_edges_and_through_shared_vertices_of_a_grid_never_miss() {
    let n = 8;
    let mesh = TriangleMesh::new(&grid(n));
    let mut misses = Vec::new();
    // Every multiple of 1/16 in x and y: vertices, edge midpoints, diagonal points,
    // quad centres; the edge functions of the triangles there are exactly 0.
    for j in 1..(4 * n) {
        for i in 1..(4 * n) {
            let x = -1.0 + f64::from(i) / (2.0 * f64::from(n));
            let y = -1.0 + f64::from(j) / (2.0 * f64::from(n));
            for dir in [DVec3::NEG_Z, DVec3::new(0.0, 0.0, -3.0)] {
                let ray = Ray::new(DVec3::new(x, y, 3.0), dir);
                if mesh.intersect(&ray, f64::INFINITY).is_none() {
                    misses.push((x, y));
                }
            }
        }
    }
    assert!(
        misses.is_empty(),
        "{} rays slipped through: {:?}",
        misses.len(),
        &misses[..misses.len().min(5)]
    );
}

/// A small deterministic generator (xorshift), so the test needs no crate.
fn random_unit(state: &mut u64) -> DVec3 {
    let mut next = || {
        *state ^= *state << 13;
        *state ^= *state >> 7;
        *state ^= *state << 17;
        (*state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    loop {
        let v = DVec3::new(next(), next(), next());
        if v.length_squared() > 0.01 && v.length_squared() <= 1.0 {
            return v.normalize();
        }
    }
}

/// Whether every triangle of `data` with all of `corners` among its vertices faces a
/// ray along `dir` the same way, clearly: then the target is not on the silhouette seen
/// along the ray, and a ray aimed at it must cross the closed surface there. (At a
/// silhouette, a ray aimed at a vertex may rightly pass beside it by a rounding error.)
fn not_on_silhouette(data: &MeshData, corners: &[u32], dir: DVec3) -> bool {
    let corner = |i: u32| glam::Vec3::from_array(data.positions[i as usize]).as_dvec3();
    let mut signs = data
        .triangles
        .iter()
        .filter(|t| corners.iter().all(|c| t.contains(c)))
        .map(|t| {
            let [a, b, c] = t.map(corner);
            let n = (b - a).cross(c - a).normalize();
            let cos = n.dot(dir.normalize());
            if cos.abs() < 1e-3 { 0.0 } else { cos.signum() }
        });
    let first = signs.next().unwrap_or(0.0);
    first != 0.0 && signs.all(|s| s == first)
}

#[test]
fn rays_aimed_exactly_at_vertices_and_edges_of_a_closed_mesh_never_miss() {
    let data = torus_knot(60, 8, 0.2, false);
    let mesh = TriangleMesh::new(&data);
    let corner = |i: u32| glam::Vec3::from_array(data.positions[i as usize]).as_dvec3();
    let mut state = 0x9E37_79B9_7F4A_7C15_u64;
    let mut misses = Vec::new();
    let mut tried = 0;
    for &[ia, ib, ic] in &data.triangles {
        let [a, b, c] = [ia, ib, ic].map(corner);
        let targets = [
            (a, vec![ia]),
            (b, vec![ib]),
            (c, vec![ic]),
            ((a + b) * 0.5, vec![ia, ib]),
            ((b + c) * 0.5, vec![ib, ic]),
            ((c + a) * 0.5, vec![ic, ia]),
        ];
        for (target, corners) in targets {
            let origin = random_unit(&mut state) * 4.0;
            let ray = Ray::new(origin, target - origin);
            if !not_on_silhouette(&data, &corners, ray.dir) {
                continue;
            }
            tried += 1;
            // The target lies on the closed surface at t = 1: something is hit by then.
            match mesh.intersect(&ray, f64::INFINITY) {
                Some(hit) if hit.t <= 1.0 + 1e-9 => {}
                _ => misses.push(target),
            }
        }
    }
    assert!(tried > 4000, "{tried} rays");
    assert!(
        misses.is_empty(),
        "{} of {tried} rays slipped through, at {:?}",
        misses.len(),
        &misses[..misses.len().min(3)]
    );
}

#[test]
fn the_hierarchy_finds_the_same_hits_as_testing_every_triangle() {
    let data = torus_knot(90, 10, 0.25, false);
    let mesh = TriangleMesh::new(&data);
    let mut state = 7_u64;
    for _ in 0..500 {
        let origin = random_unit(&mut state) * 3.5;
        let target = random_unit(&mut state) * 1.2;
        let ray = Ray::new(origin, target - origin);
        let best = data.triangles.iter().filter_map(|t| {
            let single = MeshData {
                positions: t.map(|i| data.positions[i as usize]).to_vec(),
                triangles: vec![[0, 1, 2]],
                ..MeshData::default()
            };
            TriangleMesh::new(&single)
                .intersect(&ray, f64::INFINITY)
                .map(|h| h.t)
        });
        let brute = best.fold(f64::INFINITY, f64::min);
        let found = mesh
            .intersect(&ray, f64::INFINITY)
            .map_or(f64::INFINITY, |h| h.t);
        assert_eq!(found, brute, "ray {ray:?}");
        assert_eq!(mesh.occluded(&ray, f64::INFINITY), brute.is_finite());
    }
}

#[test]
fn vertex_normals_are_interpolated_with_the_barycentric_weights() {
    let mut data = MeshData {
        positions: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        triangles: vec![[0, 1, 2]],
        ..MeshData::default()
    };
    let normals = [
        DVec3::new(-0.2, -0.2, 1.0),
        DVec3::new(0.3, 0.0, 1.0),
        DVec3::new(0.0, 0.3, 1.0),
    ];
    data.normals = normals
        .iter()
        .map(|n| n.normalize().as_vec3().to_array())
        .collect();
    let mesh = TriangleMesh::new(&data);
    let (u, v) = (0.2, 0.5);
    let ray = Ray::new(DVec3::new(u, v, 2.0), DVec3::NEG_Z);
    let hit = mesh.intersect(&ray, f64::INFINITY).expect("hit");
    let n = |i: usize| glam::Vec3::from_array(data.normals[i]).as_dvec3();
    let expected = ((1.0 - u - v) * n(0) + u * n(1) + v * n(2)).normalize();
    assert!(
        (hit.n.normalize() - expected).length() < 1e-12,
        "{} vs {expected}",
        hit.n
    );
    let detail = mesh.triangle_hit(&ray, f64::INFINITY).expect("hit");
    assert_eq!(detail.triangle, 0);
    let [wa, wb, wc] = detail.weights;
    assert!((wa - 0.3).abs() < 1e-12 && (wb - u).abs() < 1e-12 && (wc - v).abs() < 1e-12);
    // Without normals the flat one comes back.
    data.normals.clear();
    let flat = TriangleMesh::new(&data)
        .intersect(&ray, f64::INFINITY)
        .expect("hit");
    assert!((flat.n.normalize() - DVec3::Z).length() < 1e-15);
}

const SCENE: &str = r#"Scene(
    camera: (position: (0.0, 0.0, 5.0), look_at: (0.0, 0.0, 0.0), fov_deg: 40.0, width: 64, height: 48),
    materials: { "m": (ambient: (0.2, 0.2, 0.2), diffuse: (0.6, 0.6, 0.6)) },
    objects: [ (name: "knot", shape: Mesh(path: "knot.obj"), material: "m") ],
    lights: [ Point(position: (0.0, 3.0, 6.0), colour: (1.0, 1.0, 1.0), intensity: 30.0) ],
)"#;

#[test]
fn a_world_needs_its_meshes_and_names_the_object_without_them() {
    let scene = parse_scene(SCENE).expect("parses");
    let message = World::new(&scene).expect_err("no meshes").to_string();
    assert!(
        message.contains("\"knot\"") && message.contains("knot.obj"),
        "{message}"
    );
    let mut data = std::collections::BTreeMap::new();
    data.insert("knot.obj".to_owned(), torus_knot(40, 8, 0.2, true));
    let world = World::with_meshes(&scene, &MeshStore::build(&data)).expect("compiles");
    // The knot passes (1.4, 0, 0), its tube (radius 0.2) tilted there: the top is a
    // little above z = 0.2.
    let ray = Ray::new(DVec3::new(1.4, 0.0, 5.0), DVec3::new(0.0, 0.0, -1.0));
    let hit = world
        .intersect(&ray, f64::INFINITY)
        .expect("the tube's top");
    assert!(hit.p.z > 0.18 && hit.p.z < 0.25, "{}", hit.p);
    let detail = world
        .triangle_hit(0, &ray, f64::INFINITY)
        .expect("a triangle");
    assert!((detail.t - hit.t).abs() < 1e-12);
}

#[test]
fn rays_spawned_from_a_mesh_do_not_hit_their_own_triangle() {
    let data = torus_knot(80, 12, 0.3, true);
    let mesh = TriangleMesh::new(&data);
    let mut state = 3_u64;
    let mut tested = 0;
    for _ in 0..2000 {
        let origin = random_unit(&mut state) * 3.0;
        let ray = Ray::new(origin, random_unit(&mut state) * 1.2 - origin);
        let Some(hit) = mesh.intersect(&ray, f64::INFINITY) else {
            continue;
        };
        // Leave on the ray's side, as the tracer's spawn does, in a random direction.
        let side = if hit.n.dot(ray.dir) < 0.0 {
            hit.n
        } else {
            -hit.n
        }
        .normalize();
        let mut dir = random_unit(&mut state);
        if dir.dot(side) < 0.0 {
            dir = -dir;
        }
        let offset = side.abs().dot(hit.p_error) * 2.0;
        let spawned = Ray::new(hit.p + side * offset, dir);
        if let Some(again) = mesh.intersect(&spawned, f64::INFINITY) {
            assert!(again.t * dir.length() > 1e-6, "self-hit at t = {}", again.t);
        }
        tested += 1;
    }
    assert!(tested > 500);
}

#[test]
fn a_material_edit_re_shades_a_mesh_scene_and_new_triangles_re_trace() {
    use raylab::trace::{RenderOptions, RenderProgress, RetraceReason, Reuse};
    let scene = parse_scene(SCENE).expect("parses");
    let mut data = std::collections::BTreeMap::new();
    data.insert("knot.obj".to_owned(), torus_knot(40, 8, 0.2, true));
    let store = MeshStore::build(&data);
    let world = World::with_meshes(&scene, &store).expect("compiles");
    let options = RenderOptions::from_scene(&scene);
    let first =
        raylab::trace::render_one_sample_cached(&world, &options, None, &RenderProgress::default())
            .expect("not cancelled");
    let mut edited = scene.clone();
    edited.materials.get_mut("m").expect("material").diffuse = DVec3::new(0.9, 0.1, 0.1);
    let same_meshes = World::with_meshes(&edited, &store).expect("compiles");
    let (w, h) = (options.width, options.height);
    assert!(first.cache.reuse(&same_meshes, w, h).is_reshade());
    let pass = raylab::trace::render_one_sample_cached(
        &same_meshes,
        &options,
        Some(&first.cache),
        &RenderProgress::default(),
    )
    .expect("not cancelled");
    assert!(
        pass.reused && pass.traced.total() == 0,
        "traced {:?}",
        pass.traced
    );
    // The same file read again is other triangles as far as the cache can tell.
    let rebuilt = World::with_meshes(&edited, &MeshStore::build(&data)).expect("compiles");
    assert_eq!(
        first.cache.reuse(&rebuilt, w, h),
        Reuse::Retrace(RetraceReason::Objects)
    );
}

#[test]
fn a_mesh_shadows_itself() {
    use raylab::trace::{RenderOptions, inspect_pixel};
    // One mesh: a floor square at z = 0 and a small square floating at z = 1. The light
    // (4, 0, 4) throws the small square's shadow on the floor over x in [-2, -0.67]. A
    // shadow ray leaves the floor on its outer side and still meets the same mesh.
    let square = |half: f32, z: f32| {
        [
            [-half, -half, z],
            [half, -half, z],
            [half, half, z],
            [-half, half, z],
        ]
    };
    let mut data = MeshData::default();
    data.positions.extend(square(2.0, 0.0));
    data.positions.extend(square(0.5, 1.0));
    data.triangles = vec![[0, 1, 2], [0, 2, 3], [4, 5, 6], [4, 6, 7]];
    let text = r#"Scene(
        camera: (position: (0.0, 0.0, 5.0), look_at: (0.0, 0.0, 0.0), fov_deg: 60.0, width: 64, height: 64),
        materials: { "m": (ambient: (0.1, 0.1, 0.1), diffuse: (0.8, 0.8, 0.8)) },
        objects: [ (name: "two squares", shape: Mesh(path: "squares.obj"), material: "m") ],
        lights: [ Point(position: (4.0, 0.0, 4.0), colour: (1.0, 1.0, 1.0), intensity: 30.0) ],
    )"#;
    let scene = parse_scene(text).expect("parses");
    let mut files = std::collections::BTreeMap::new();
    files.insert("squares.obj".to_owned(), data);
    let world = World::with_meshes(&scene, &MeshStore::build(&files)).expect("compiles");
    let options = RenderOptions::from_scene(&scene);
    // Pixel column 18 looks at x ~ -1.2 on the floor (in the shadow), column 50 at
    // x ~ +1.1 (lit).
    let outcome = |px: u32| {
        let report = inspect_pixel(&world, &options, px, 32);
        let hit = report.bounces[0].hit.expect("the floor");
        assert!(hit.p.z.abs() < 1e-9, "hit the floor, not {}", hit.p);
        report.bounces[0].light_outcomes()[0].1
    };
    assert_eq!(outcome(18), raylab::trace::LightOutcome::Shadowed(0));
    assert_eq!(outcome(50), raylab::trace::LightOutcome::Lit);
}

#[test]
fn a_closed_mesh_is_a_solid_with_alternating_crossings_and_an_open_one_is_not() {
    let knot = TriangleMesh::new(&torus_knot(60, 8, 0.2, false));
    assert!(knot.is_closed());
    assert!(
        !TriangleMesh::new(&grid(4)).is_closed(),
        "a sheet has a border"
    );
    // The pyramid's two groups repeat the base corners: matched by position, closed.
    let pyramid = raylab::scene::load_obj(
        &std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenes/pyramid.obj"),
    )
    .expect("loads");
    assert!(TriangleMesh::new(&pyramid).is_closed());
    // A ray straight down through the apex (a vertex of four triangles) and out through
    // the base's diagonal (an edge of two): one way in, one way out.
    let mesh = TriangleMesh::new(&pyramid);
    let mut out = Vec::new();
    mesh.crossings(&Ray::new(DVec3::new(0.0, 3.0, 0.0), DVec3::NEG_Y), &mut out);
    let ts: Vec<f64> = out.iter().map(|h| h.t).collect();
    assert_eq!(ts.len(), 2, "{ts:?}");
    assert!(
        (ts[0] - 1.6).abs() < 1e-6 && (ts[1] - 3.0).abs() < 1e-12,
        "{ts:?}"
    );
    assert!(out[0].n.dot(DVec3::NEG_Y) < 0.0 && out[1].n.dot(DVec3::NEG_Y) > 0.0);
    // Random rays through the knot cross it an even number of times from outside.
    let mut state = 11_u64;
    for _ in 0..300 {
        let origin = random_unit(&mut state) * 4.0;
        let ray = Ray::new(origin, random_unit(&mut state) * 1.2 - origin);
        knot.crossings(&ray, &mut out);
        assert_eq!(out.len() % 2, 0, "{ray:?}");
        let first = knot.intersect(&ray, f64::INFINITY).map(|h| h.t);
        assert_eq!(out.first().map(|h| h.t), first);
    }
}
