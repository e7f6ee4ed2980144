//! Closed meshes as CSG operands: a mesh cube behaves as the unit cube does in the same
//! tree (same surfaces, same cut material, rays leaving its surfaces), and an open mesh
//! is refused by its tree path.

use std::collections::BTreeMap;

use glam::DVec3;
use raylab::scene::{CsgOp, MeshData, Object, Scene, Shape, Transform, Trs, examples};
use raylab::trace::{MeshStore, Ray, World, spawn_ray};

/// The cube [-1, 1]^3 as 12 outward-facing triangles.
fn cube_mesh() -> MeshData {
    let mut mesh = MeshData::default();
    for z in [-1.0, 1.0] {
        for y in [-1.0, 1.0] {
            for x in [-1.0, 1.0] {
                mesh.positions.push([x, y, z]);
            }
        }
    }
    // Vertex k has x = bit 0, y = bit 1, z = bit 2; each face is wound outward.
    let faces: [[u32; 4]; 6] = [
        [0, 2, 3, 1], // z = -1
        [4, 5, 7, 6], // z = +1
        [0, 1, 5, 4], // y = -1
        [2, 6, 7, 3], // y = +1
        [0, 4, 6, 2], // x = -1
        [1, 3, 7, 5], // x = +1
    ];
    for [a, b, c, d] in faces {
        mesh.triangles.extend([[a, b, c], [a, c, d]]);
    }
    mesh
}

/// The same cube's top face alone: an open surface.
fn open_mesh() -> MeshData {
    let mut mesh = cube_mesh();
    mesh.triangles.truncate(4);
    mesh
}

fn object(name: &str, shape: Shape, translate: DVec3, scale: f64, material: &str) -> Object {
    Object {
        name: name.to_owned(),
        shape,
        transform: Transform::Trs(Trs {
            translate,
            rotate_deg: DVec3::new(10.0, 20.0, 30.0),
            scale: DVec3::splat(scale),
        }),
        material: material.to_owned(),
    }
}

/// A cube (of `body`'s shape) minus a sphere at one corner, in the default scene.
fn bitten_cube(body: Shape) -> Scene {
    let mut scene = examples::default_scene();
    scene.objects = vec![Object {
        name: "bitten".to_owned(),
        shape: Shape::Csg {
            op: CsgOp::Difference,
            operands: vec![
                object("body", body, DVec3::ZERO, 1.0, ""),
                object("bite", Shape::Sphere, DVec3::splat(0.8), 0.9, "gold"),
            ],
        },
        transform: Transform::Trs(Trs {
            translate: DVec3::new(0.0, 0.0, 1.0),
            rotate_deg: DVec3::ZERO,
            scale: DVec3::ONE,
        }),
        material: "red plastic".to_owned(),
    }];
    scene
}

fn meshes(data: MeshData) -> MeshStore {
    let mut files = BTreeMap::new();
    files.insert("cube.obj".to_owned(), data);
    MeshStore::build(&files)
}

fn mesh_shape() -> Shape {
    Shape::Mesh {
        path: "cube.obj".to_owned(),
    }
}

/// Rays from a ring of points around the node, aimed near its centre.
fn rays() -> Vec<Ray> {
    let mut rays = Vec::new();
    for i in 0..24 {
        for j in 0..12 {
            let (a, b) = (f64::from(i) * 0.2618, f64::from(j) * 0.25 - 1.4);
            let from = DVec3::new(a.cos() * b.cos(), a.sin() * b.cos(), b.sin()) * 6.0
                + DVec3::new(0.0, 0.0, 1.0);
            let at = DVec3::new(0.3 * (a * 3.0).sin(), 0.3 * (b * 5.0).cos(), 1.2);
            rays.push(Ray::new(from, at - from));
        }
    }
    rays
}

#[test]
fn a_closed_mesh_operand_cuts_and_is_cut_like_the_unit_cube_it_copies() {
    let unit = World::new(&bitten_cube(Shape::Cube)).expect("compiles");
    let mesh = World::with_meshes(&bitten_cube(mesh_shape()), &meshes(cube_mesh()))
        .expect("a closed mesh is a solid");
    let mut hits = 0;
    let mut cuts = 0;
    for ray in rays() {
        let (a, b) = (
            unit.intersect(&ray, f64::INFINITY),
            mesh.intersect(&ray, f64::INFINITY),
        );
        match (a, b) {
            (None, None) => {}
            (Some(a), Some(b)) => {
                hits += 1;
                assert!((a.t - b.t).abs() < 1e-9, "t {} against {}", a.t, b.t);
                assert!(a.n_outward.dot(b.n_outward) > 1.0 - 1e-9);
                assert_eq!(unit.material_at(&a), mesh.material_at(&b));
                cuts += usize::from(a.part == 1);
                // A ray leaving the surface outward meets the node again exactly when
                // the unit cube's does (the cut is concave), and a ray sent inward
                // leaves through the far side at the same place.
                for dir in [b.n_outward, -b.n_outward + 0.1 * ray.dir] {
                    let (ua, mb) = (
                        unit.intersect(&spawn_ray(&a, dir), f64::INFINITY),
                        mesh.intersect(&spawn_ray(&b, dir), f64::INFINITY),
                    );
                    assert_eq!(ua.is_some(), mb.is_some(), "leaving along {dir}");
                    if let (Some(ua), Some(mb)) = (ua, mb) {
                        assert!((ua.t - mb.t).abs() < 1e-9);
                    }
                }
            }
            (a, b) => panic!("unit cube {a:?}, mesh cube {b:?} along {ray:?}"),
        }
    }
    assert!(hits > 100 && cuts > 5, "{hits} hits, {cuts} on the bite");
}

#[test]
fn an_open_mesh_is_refused_as_an_operand_by_its_tree_path() {
    let error = World::with_meshes(&bitten_cube(mesh_shape()), &meshes(open_mesh()))
        .expect_err("an open surface has no inside");
    let message = error.to_string();
    assert!(
        message.contains("\"bitten/body\"") && message.contains("not closed"),
        "{message}"
    );
}
