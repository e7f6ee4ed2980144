//! The contract's optional section: more shapes, object trees, transmission, sphere
//! lights and the course conventions. Each loads as written, saves back to an equal
//! scene, leaves old files unchanged, and each bad value is refused by name.

use raylab::scene::{
    ClampConvention, Conventions, CsgOp, Light, LightSource, MirrorConvention, Quantise, Scene,
    Shape, parse_scene, scene_to_ron,
};

const TREES: &str = r#"
Scene(
    render: (conventions: (mirror: Blend, clamp: EachRay, quantise: Truncate)),
    materials: {
        "glass": (diffuse: (0.05, 0.05, 0.05), specular: (0.9, 0.9, 0.9), shininess: 200.0,
                  mirror: (0.05, 0.05, 0.05), transmission: (0.9, 0.9, 0.9), ior: 1.5),
        "snow": (diffuse: (0.9, 0.9, 0.9)),
    },
    objects: [
        (
            name: "lens",
            shape: Csg(op: Intersection, operands: [
                (shape: Sphere, transform: (translate: (0.0, 0.0, -0.6)), material: "glass"),
                (shape: Sphere, transform: (translate: (0.0, 0.0, 0.6))),
            ]),
            transform: (scale: (1.0, 1.0, 0.5)),
            material: "glass",
        ),
        (
            name: "snowman",
            shape: Group(children: [
                (name: "body", shape: Torus(minor: 0.25), material: "snow"),
                (name: "hat", shape: Tube(inner: 0.5), material: "snow"),
                (name: "nose", shape: Octahedron, material: "snow"),
                (name: "teapot", shape: Mesh(path: "teapot.obj"), material: "snow"),
            ]),
            transform: (translate: (2.0, 0.0, 0.0)),
        ),
    ],
    lights: [
        Point(position: (0.0, 4.0, 0.0), colour: (1.0, 1.0, 1.0), intensity: 20.0,
              radius: 0.2, samples: 16),
        Spot(position: (0.0, 5.0, 0.0), direction: (0.0, -1.0, 0.0), angle_deg: 20.0,
             colour: (1.0, 1.0, 1.0), radius: 0.5),
    ],
)
"#;

fn scene() -> Scene {
    parse_scene(TREES).expect("the contract's tree example loads")
}

fn error_with(from: &str, to: &str) -> String {
    assert!(
        TREES.contains(from),
        "test bug: {from:?} not in the example"
    );
    match parse_scene(&TREES.replacen(from, to, 1)) {
        Ok(_) => panic!("expected an error after replacing {from:?} with {to:?}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn trees_shapes_glass_sphere_lights_and_conventions_load_as_written() {
    let scene = scene();
    assert_eq!(
        scene.render.conventions,
        Conventions {
            mirror: MirrorConvention::Blend,
            clamp: ClampConvention::EachRay,
            quantise: Quantise::Truncate,
        }
    );
    let glass = &scene.materials["glass"];
    assert_eq!(glass.ior, 1.5);
    assert_eq!(glass.transmission.x, 0.9);
    assert_eq!(scene.materials["snow"].ior, 1.0, "ior defaults to 1");
    let Shape::Csg { op, operands } = &scene.objects[0].shape else {
        panic!("lens is a Csg: {:?}", scene.objects[0].shape);
    };
    assert_eq!(*op, CsgOp::Intersection);
    assert_eq!(
        operands[1].material, "",
        "an operand may leave its material out"
    );
    let children = scene.objects[1].shape.children();
    let shapes: Vec<&Shape> = children.iter().map(|c| &c.shape).collect();
    assert_eq!(
        shapes,
        [
            &Shape::Torus { minor: 0.25 },
            &Shape::Tube { inner: 0.5 },
            &Shape::Octahedron,
            &Shape::Mesh {
                path: "teapot.obj".into()
            },
        ]
    );
    assert_eq!(scene.lights[0].sphere(), Some((0.2, 16)));
    assert_eq!(
        scene.lights[1].sphere(),
        Some((0.5, 1)),
        "samples default to 1"
    );
}

#[test]
fn unnamed_children_are_numbered_among_their_siblings() {
    let scene = scene();
    let operands = scene.objects[0].shape.children();
    assert_eq!(operands[0].name, "Sphere 0");
    assert_eq!(operands[1].name, "Sphere 1");
}

#[test]
fn a_tree_scene_saves_and_loads_back_equal() {
    let scene = scene();
    let text = scene_to_ron(&scene);
    assert_eq!(parse_scene(&text).expect("reloads"), scene, "{text}");
}

#[test]
fn defaults_of_the_new_fields_are_not_written() {
    let mut scene = scene();
    scene.render.conventions = Conventions::default();
    scene.lights.truncate(1);
    if let Light::Point {
        source: LightSource {
            radius, samples, ..
        },
        ..
    } = &mut scene.lights[0]
    {
        *radius = 0.0;
        *samples = 1;
    }
    scene.materials.get_mut("glass").unwrap().ior = 1.0;
    scene.materials.get_mut("glass").unwrap().transmission = glam::DVec3::ZERO;
    let text = scene_to_ron(&scene);
    for field in ["conventions", "radius", "samples", "ior", "transmission"] {
        let written = format!("{field}:");
        assert!(
            !text.contains(&written),
            "{field} written at its default:\n{text}"
        );
    }
}

#[test]
fn bad_shape_parameters_are_refused_naming_the_object() {
    let e = error_with("Torus(minor: 0.25)", "Torus(minor: 0.0)");
    assert!(e.contains("\"snowman/body\"") && e.contains("minor"), "{e}");
    let e = error_with("Torus(minor: 0.25)", "Torus(minor: inf)");
    assert!(e.contains("minor"), "{e}");
    for inner in ["1.0", "0.0", "-0.5", "NaN"] {
        let e = error_with("Tube(inner: 0.5)", &format!("Tube(inner: {inner})"));
        assert!(
            e.contains("\"snowman/hat\"") && e.contains("inner"),
            "{inner}: {e}"
        );
    }
    let e = error_with("Mesh(path: \"teapot.obj\")", "Mesh(path: \"\")");
    assert!(e.contains("Mesh path is empty"), "{e}");
}

#[test]
fn an_empty_csg_and_a_leaf_without_material_are_refused() {
    let empty = TREES.replace(
        r#"(shape: Sphere, transform: (translate: (0.0, 0.0, -0.6)), material: "glass"),
                (shape: Sphere, transform: (translate: (0.0, 0.0, 0.6))),"#,
        "",
    );
    let e = parse_scene(&empty).unwrap_err().to_string();
    assert!(e.contains("\"lens\"") && e.contains("no operands"), "{e}");
    let e = error_with(
        r#"(name: "nose", shape: Octahedron, material: "snow")"#,
        r#"(name: "nose", shape: Octahedron)"#,
    );
    assert!(
        e.contains("\"snowman/nose\"") && e.contains("no material"),
        "{e}"
    );
}

#[test]
fn bad_glass_and_sphere_lights_are_refused_by_name() {
    for ior in ["0.0", "-1.5", "1e300", "NaN"] {
        let e = error_with("ior: 1.5", &format!("ior: {ior}"));
        assert!(
            e.contains("material \"glass\"") && e.contains("ior"),
            "{ior}: {e}"
        );
    }
    let e = error_with(
        "transmission: (0.9, 0.9, 0.9)",
        "transmission: (-0.1, 0.9, 0.9)",
    );
    assert!(e.contains("transmission"), "{e}");
    let e = error_with("radius: 0.2", "radius: -0.2");
    assert!(e.contains("lights[0]") && e.contains("radius"), "{e}");
    for samples in ["0", "1000000000"] {
        let e = error_with("samples: 16", &format!("samples: {samples}"));
        assert!(e.contains("samples"), "{samples}: {e}");
    }
}

#[test]
fn a_deep_tree_is_refused_past_the_limit_without_overflowing() {
    // Built in memory: the checks walk the tree with a work list.
    let leaf = scene().objects[1].shape.children()[0].clone();
    let mut object = leaf;
    for level in 0..=raylab::scene::MAX_TREE_DEPTH {
        object = raylab::scene::Object {
            name: format!("g{level}"),
            shape: Shape::Group {
                children: vec![object],
            },
            transform: Default::default(),
            material: String::new(),
        };
    }
    let mut deep = scene();
    deep.objects = vec![object];
    let e = raylab::scene::validate(&deep).unwrap_err().to_string();
    assert!(e.contains("levels deep"), "{e}");
}
