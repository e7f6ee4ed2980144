//! CSG and groups in the tracer: analytic answers for the three operators, the hard
//! cases (shared faces, rays leaving CSG surfaces, grazes, empty results, deep trees)
//! and groups flattened with their tree paths.

use glam::DVec3;
use raylab::scene::{CsgOp, MAX_TREE_DEPTH, Object, Scene, Shape, Transform, Trs, examples};
use raylab::trace::{Ray, World, spawn_ray};

fn object(name: &str, shape: Shape, translate: DVec3, scale: f64, material: &str) -> Object {
    Object {
        name: name.to_owned(),
        shape,
        transform: Transform::Trs(Trs {
            translate,
            rotate_deg: DVec3::ZERO,
            scale: DVec3::splat(scale),
        }),
        material: material.to_owned(),
    }
}

fn csg(name: &str, op: CsgOp, operands: Vec<Object>) -> Object {
    object(
        name,
        Shape::Csg { op, operands },
        DVec3::ZERO,
        1.0,
        "red plastic",
    )
}

/// The default scene's materials and lights with only `objects`.
fn scene_of(objects: Vec<Object>) -> Scene {
    let mut scene = examples::default_scene();
    scene.objects = objects;
    scene
}

fn world_of(objects: Vec<Object>) -> World {
    World::new(&scene_of(objects)).expect("a valid scene")
}

fn material(world: &World, name: &str) -> usize {
    world.material_names.iter().position(|m| m == name).unwrap()
}

fn down_from(x: f64, y: f64, z: f64) -> Ray {
    Ray::new(DVec3::new(x, y, z), -DVec3::Z)
}

/// The unit sphere minus a sphere of radius 0.5 centred on its north pole.
fn bitten_sphere() -> World {
    world_of(vec![csg(
        "bitten",
        CsgOp::Difference,
        vec![
            object("body", Shape::Sphere, DVec3::ZERO, 1.0, ""),
            object("bite", Shape::Sphere, DVec3::Z, 0.5, "gold"),
        ],
    )])
}

#[test]
fn a_sphere_minus_a_sphere_has_a_hole_as_deep_as_the_bite() {
    let world = bitten_sphere();
    let hit = world
        .intersect(&down_from(0.0, 0.0, 5.0), f64::INFINITY)
        .unwrap();
    // The bite reaches down to z = 0.5 on the axis.
    assert!((hit.t - 4.5).abs() < 1e-12, "t = {}", hit.t);
    assert!((hit.p - DVec3::new(0.0, 0.0, 0.5)).length() < 1e-12);
    // The cut's normal is the bite's, turned inward: up, out of the result.
    assert!(
        (hit.n_outward - DVec3::Z).length() < 1e-12,
        "{}",
        hit.n_outward
    );
    assert_eq!(world.material_at(&hit), material(&world, "gold"));
    assert_eq!(
        world.objects[hit.object].csg.as_ref().unwrap().leaves[hit.part as usize].path,
        "bitten/bite"
    );
    // Off the bite the body shows, with the node's material inherited.
    let side = world
        .intersect(&down_from(0.0, 0.9, 5.0), f64::INFINITY)
        .unwrap();
    let z = (1.0f64 - 0.81).sqrt();
    assert!((side.p.z - z).abs() < 1e-12 && side.n_outward.z > 0.0);
    assert_eq!(world.material_at(&side), material(&world, "red plastic"));
    // From below, the body's south pole.
    let up = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
    let hit = world.intersect(&up, f64::INFINITY).unwrap();
    assert!((hit.t - 4.0).abs() < 1e-12 && (hit.n_outward + DVec3::Z).length() < 1e-12);
}

#[test]
fn intersection_and_union_give_the_lens_and_the_pair() {
    let pair = || {
        vec![
            object("left", Shape::Sphere, DVec3::new(-0.5, 0.0, 0.0), 1.0, ""),
            object(
                "right",
                Shape::Sphere,
                DVec3::new(0.5, 0.0, 0.0),
                1.0,
                "gold",
            ),
        ]
    };
    let along_x = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
    let lens = world_of(vec![csg("lens", CsgOp::Intersection, pair())]);
    let hit = lens.intersect(&along_x, f64::INFINITY).unwrap();
    // Enters the right sphere (its left side at x = -0.5) first.
    assert!((hit.p.x + 0.5).abs() < 1e-12 && hit.n_outward.x < 0.0);
    assert_eq!(lens.material_at(&hit), material(&lens, "gold"));
    let pair_world = world_of(vec![csg("pair", CsgOp::Union, pair())]);
    let hit = pair_world.intersect(&along_x, f64::INFINITY).unwrap();
    assert!((hit.p.x + 1.5).abs() < 1e-12);
    // From inside the overlap, the union's exit is the right sphere's far side.
    let inside = Ray::new(DVec3::ZERO, DVec3::X);
    let exit = pair_world.intersect(&inside, f64::INFINITY).unwrap();
    assert!((exit.p.x - 1.5).abs() < 1e-12 && exit.n_outward.x > 0.0);
}

#[test]
fn a_cube_minus_a_cube_sharing_a_face_shows_no_skin_on_that_face() {
    // The cutter fills z in [0, 1] of the cube's middle: its top is the cube's top.
    let cutter = Object {
        transform: Transform::Trs(Trs {
            translate: DVec3::new(0.0, 0.0, 0.5),
            rotate_deg: DVec3::ZERO,
            scale: DVec3::new(0.5, 0.5, 0.5),
        }),
        ..object("slot", Shape::Cube, DVec3::ZERO, 1.0, "gold")
    };
    let world = world_of(vec![csg(
        "box",
        CsgOp::Difference,
        vec![object("block", Shape::Cube, DVec3::ZERO, 1.0, ""), cutter],
    )]);
    let hit = world
        .intersect(&down_from(0.1, 0.2, 5.0), f64::INFINITY)
        .unwrap();
    assert!(
        (hit.t - 5.0).abs() < 1e-12,
        "the slot's floor at z = 0, not t = {}",
        hit.t
    );
    assert_eq!(hit.n_outward, DVec3::Z);
    assert_eq!(world.material_at(&hit), material(&world, "gold"));
    // A shadow ray up the slot from its floor is clear; one from the floor sideways
    // meets the slot's wall.
    assert_eq!(
        world.occluder(&spawn_ray(&hit, DVec3::Z), f64::INFINITY),
        None
    );
    assert_eq!(
        world.occluder(&spawn_ray(&hit, DVec3::new(1.0, 0.0, 0.2)), f64::INFINITY),
        Some(0)
    );
    // Beside the slot the block's own top at z = 1.
    let beside = world
        .intersect(&down_from(0.75, 0.0, 5.0), f64::INFINITY)
        .unwrap();
    assert!((beside.t - 4.0).abs() < 1e-12);
}

#[test]
fn rays_leaving_csg_surfaces_do_not_meet_them_again() {
    let world = bitten_sphere();
    // Many camera-like rays; from each hit, shadow and mirror rays out of the solid.
    for i in 0..200 {
        let a = f64::from(i) * 0.0314;
        let origin = DVec3::new(3.0 * a.cos(), 3.0 * a.sin(), 2.0 + (a * 3.0).sin());
        let ray = Ray::new(origin, -origin + DVec3::new(0.1 * a.sin(), 0.0, 0.3));
        let Some(hit) = world.intersect(&ray, f64::INFINITY) else {
            continue;
        };
        let out = hit.n; // faces the ray: out of the solid
        let mirror = ray.dir - 2.0 * ray.dir.dot(out) / out.length_squared() * out;
        let leaving = spawn_ray(&hit, mirror);
        if let Some(again) = world.intersect(&leaving, f64::INFINITY) {
            // Only a genuine second surface (the bite's far rim), never the start.
            assert!(
                (again.p - hit.p).length() > 1e-6,
                "ray {i} met its own start at t = {}",
                again.t
            );
        }
    }
}

#[test]
fn a_graze_and_an_empty_difference_are_no_surface() {
    // Tangent to the body at x = 1, away from the bite: the regularised solid has no
    // surface there, and both queries agree.
    let world = bitten_sphere();
    let graze = Ray::new(DVec3::new(1.0, -5.0, 0.0), DVec3::Y);
    assert_eq!(
        world.intersect(&graze, f64::INFINITY).is_some(),
        world.occluder(&graze, f64::INFINITY).is_some()
    );
    let empty = world_of(vec![csg(
        "nothing",
        CsgOp::Difference,
        vec![
            object("a", Shape::Sphere, DVec3::ZERO, 1.0, ""),
            object("b", Shape::Sphere, DVec3::ZERO, 1.0, ""),
        ],
    )]);
    for ray in [
        down_from(0.0, 0.0, 5.0),
        down_from(0.5, 0.3, 5.0),
        Ray::new(DVec3::ZERO, DVec3::X),
    ] {
        assert!(empty.intersect(&ray, f64::INFINITY).is_none());
        assert!(empty.occluder(&ray, f64::INFINITY).is_none());
    }
}

/// `levels` nested Unions around one sphere.
fn nested(levels: usize) -> Object {
    let mut node = object("ball", Shape::Sphere, DVec3::ZERO, 1.0, "");
    for level in 0..levels {
        node = csg(&format!("level {level}"), CsgOp::Union, vec![node]);
    }
    node
}

#[test]
fn a_tree_a_thousand_levels_deep_renders_on_a_small_stack() {
    // 256 KiB: a recursive walk of 1,000 levels would not fit.
    let handle = std::thread::Builder::new()
        .stack_size(256 * 1024)
        .spawn(|| {
            let world = world_of(vec![nested(MAX_TREE_DEPTH)]);
            let hit = world
                .intersect(&down_from(0.0, 0.0, 5.0), f64::INFINITY)
                .unwrap();
            assert!((hit.t - 4.0).abs() < 1e-12);
            let deeper = scene_of(vec![nested(MAX_TREE_DEPTH + 1)]);
            let message = World::new(&deeper).unwrap_err().to_string();
            assert!(message.contains("1000 levels"), "{message}");
            std::mem::forget(deeper); // dropping is the test's business, not the tracer's
        })
        .unwrap();
    handle.join().unwrap();
}

#[test]
fn groups_flatten_with_placement_inherited_materials_and_paths() {
    let snowman = Object {
        name: "snowman".to_owned(),
        shape: Shape::Group {
            children: vec![
                object("body", Shape::Sphere, DVec3::ZERO, 1.0, ""),
                object(
                    "head",
                    Shape::Sphere,
                    DVec3::new(0.0, 0.0, 1.5),
                    0.5,
                    "gold",
                ),
            ],
        },
        transform: Transform::Trs(Trs {
            translate: DVec3::new(2.0, 0.0, 0.0),
            rotate_deg: DVec3::ZERO,
            scale: DVec3::ONE,
        }),
        material: "blue satin".to_owned(),
    };
    let ball = object(
        "ball",
        Shape::Sphere,
        DVec3::new(-3.0, 0.0, 0.0),
        1.0,
        "red plastic",
    );
    let world = world_of(vec![ball, snowman]);
    let names: Vec<&str> = world.objects.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["ball", "snowman/body", "snowman/head"]);
    assert_eq!(world.object_scene_index, [0, 1, 1]);
    let head = world
        .intersect(&down_from(2.0, 0.0, 5.0), f64::INFINITY)
        .unwrap();
    assert!((head.p.z - 2.0).abs() < 1e-12, "world = parent * child");
    assert_eq!(world.material_at(&head), material(&world, "gold"));
    let body = world
        .intersect(&down_from(2.9, 0.0, 5.0), f64::INFINITY)
        .unwrap();
    assert_eq!(world.material_at(&body), material(&world, "blue satin"));
    assert_eq!(world.scene_object(body.object), 1);
}

/// Scene text with `levels` nested one-operand Unions around a sphere.
fn nested_text(levels: usize) -> String {
    let mut object = "(name: \"ball\", shape: Sphere, material: \"m\")".to_owned();
    for level in 0..levels {
        object = format!("(name: \"l{level}\", shape: Csg(op: Union, operands: [{object}]))");
    }
    format!(
        "Scene(format: 1, camera: (position: (0.0, 0.0, 5.0), look_at: (0.0, 0.0, 0.0), \
         up: (0.0, 1.0, 0.0), fov_deg: 40.0, width: 8, height: 6), \
         materials: {{\"m\": (diffuse: (0.5, 0.5, 0.5))}}, lights: [], objects: [{object}])"
    )
}

#[test]
fn a_file_a_thousand_levels_deep_loads_and_deeper_ones_are_clear_errors() {
    // On a 1 MiB stack: the parser's stack grows on the heap, not the thread's.
    let handle = std::thread::Builder::new()
        .stack_size(1024 * 1024)
        .spawn(|| {
            let deepest = raylab::scene::parse_scene(&nested_text(MAX_TREE_DEPTH))
                .expect("a tree of the deepest depth validation takes loads");
            let hit = World::new(&deepest)
                .unwrap()
                .intersect(&down_from(0.0, 0.0, 5.0), f64::INFINITY);
            assert!(hit.is_some_and(|hit| (hit.t - 4.0).abs() < 1e-12));
            std::mem::forget(deepest);
            let error = raylab::scene::parse_scene(&nested_text(MAX_TREE_DEPTH + 1))
                .unwrap_err()
                .to_string();
            assert!(error.contains("1000 levels"), "{error}");
            let error = raylab::scene::parse_scene(&nested_text(10 * MAX_TREE_DEPTH))
                .unwrap_err()
                .to_string();
            assert!(
                error.contains("objects nested more than 1000 levels deep")
                    && !error.contains("recursion_limit"),
                "in the scene's words, not the parser's: {error}"
            );
        })
        .unwrap();
    handle.join().unwrap();
}

#[test]
fn hiding_a_group_hides_its_members_and_ids_stay_the_scenes() {
    let group = |name: &str, x: f64| Object {
        name: name.to_owned(),
        shape: Shape::Group {
            children: vec![
                object("a", Shape::Sphere, DVec3::new(x, 0.0, 0.0), 0.5, ""),
                object("b", Shape::Sphere, DVec3::new(x, 2.0, 0.0), 0.5, ""),
            ],
        },
        transform: Transform::default(),
        material: "gold".to_owned(),
    };
    let scene = scene_of(vec![
        group("left", -2.0),
        group("middle", 0.0),
        group("right", 2.0),
    ]);
    let isolation = raylab::trace::Isolation {
        hidden_objects: [1].into_iter().collect(),
        ..raylab::trace::Isolation::NONE
    };
    let world = World::isolated(&scene, &isolation).unwrap();
    assert_eq!(world.object_scene_index, [0, 0, 2, 2]);
    assert!(
        world
            .intersect(&down_from(0.0, 0.0, 5.0), f64::INFINITY)
            .is_none()
    );
    let right = world
        .intersect(&down_from(2.0, 2.0, 5.0), f64::INFINITY)
        .unwrap();
    assert_eq!(world.scene_object(right.object), 2);
    assert_eq!(world.objects[right.object].name, "right/b");
}

#[test]
fn each_world_object_can_be_taken_out_of_its_tree() {
    let snowman = Object {
        name: "snowman".to_owned(),
        shape: Shape::Group {
            children: vec![
                object("body", Shape::Sphere, DVec3::ZERO, 1.0, ""),
                csg(
                    "hat",
                    CsgOp::Union,
                    vec![object("brim", Shape::Cube, DVec3::Z, 0.5, "")],
                ),
            ],
        },
        transform: Transform::default(),
        material: "gold".to_owned(),
    };
    let scene = scene_of(vec![
        object("ball", Shape::Sphere, DVec3::X * 5.0, 1.0, "gold"),
        snowman,
    ]);
    let world = World::new(&scene).unwrap();
    for index in 0..world.objects.len() {
        let without = raylab::trace::scene_without_world_object(&scene, index).unwrap();
        let names: Vec<String> = World::new(&without)
            .unwrap()
            .objects
            .iter()
            .map(|o| o.name.clone())
            .collect();
        let mut expected: Vec<String> = world.objects.iter().map(|o| o.name.clone()).collect();
        expected.remove(index);
        assert_eq!(names, expected);
    }
    assert!(raylab::trace::scene_without_world_object(&scene, world.objects.len()).is_none());
}

#[test]
fn only_intersections_of_primitives_count_as_convex() {
    let lens = world_of(vec![csg(
        "lens",
        CsgOp::Intersection,
        vec![
            object("front", Shape::Sphere, DVec3::Z * 0.5, 1.0, ""),
            object("back", Shape::Sphere, -DVec3::Z * 0.5, 1.0, ""),
        ],
    )]);
    assert!(!lens.objects[0].can_meet_itself());
    assert!(bitten_sphere().objects[0].can_meet_itself());
    // A shadow ray leaving the bite's floor sideways meets the rim: not convex.
    let world = bitten_sphere();
    let floor = world
        .intersect(&down_from(0.0, 0.0, 5.0), f64::INFINITY)
        .unwrap();
    let sideways = spawn_ray(&floor, DVec3::new(1.0, 0.0, 0.3));
    assert_eq!(world.occluder(&sideways, f64::INFINITY), Some(0));
}

#[test]
fn a_hit_names_the_path_of_the_leaf_it_lies_on_through_groups_and_csg_nodes() {
    let group = object(
        "g",
        Shape::Group {
            children: vec![
                object("a", Shape::Sphere, DVec3::new(-3.0, 0.0, 0.0), 1.0, ""),
                csg(
                    "c",
                    CsgOp::Union,
                    vec![
                        object("box", Shape::Cube, DVec3::ZERO, 0.8, ""),
                        object(
                            "ball",
                            Shape::Sphere,
                            DVec3::new(3.0, 0.0, 0.0),
                            1.0,
                            "gold",
                        ),
                    ],
                ),
            ],
        },
        DVec3::ZERO,
        1.0,
        "red plastic",
    );
    let lone = object(
        "lone",
        Shape::Sphere,
        DVec3::new(0.0, 6.0, 0.0),
        1.0,
        "gold",
    );
    let world = world_of(vec![lone, group]);
    let path_at = |x: f64, y: f64| {
        let hit = world
            .intersect(&down_from(x, y, 10.0), f64::INFINITY)
            .unwrap();
        world.node_path(&hit)
    };
    assert_eq!(path_at(0.0, 6.0), vec![0]);
    assert_eq!(path_at(-3.0, 0.0), vec![1, 0]);
    assert_eq!(path_at(0.0, 0.0), vec![1, 1, 0]);
    assert_eq!(path_at(3.0, 0.0), vec![1, 1, 1]);
}

#[test]
fn every_hit_on_the_csg_example_names_by_index_the_leaf_its_name_path_names() {
    use raylab::scene::tree::path_name;
    use raylab::trace::PinholeCamera;
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/csg.ron");
    let scene = raylab::scene::load_scene(&path).unwrap();
    let world = World::new(&scene).unwrap();
    let camera = PinholeCamera::new(&scene.camera, 160, 120);
    let mut leaves = std::collections::BTreeSet::new();
    for y in 0..120 {
        for x in 0..160 {
            let ray = camera.ray(glam::DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5));
            let Some(hit) = world.intersect(&ray, f64::INFINITY) else {
                continue;
            };
            let object = &world.objects[hit.object];
            let expected = match &object.csg {
                Some(tree) => tree.leaves[hit.part as usize].path.clone(),
                None => object.name.clone(),
            };
            let by_index = path_name(&scene.objects, &world.node_path(&hit));
            assert_eq!(by_index, expected, "pixel ({x}, {y})");
            leaves.insert(by_index);
        }
    }
    // The pips cut in chunks (tested as one box first) are named right too.
    assert!(
        leaves.iter().filter(|l| l.contains("pip")).count() >= 5,
        "{leaves:?}"
    );
}
