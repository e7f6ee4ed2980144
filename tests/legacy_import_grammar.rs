//! Property tests of the extended legacy grammar (issue 38): random object trees in both
//! CSG forms and groups import to the tree they describe; an `End` taken away or added
//! refuses the file; nesting past the importer's limit is an error; huge `FSAA` and
//! `Samples` are capped with a warning, never refused or passed on.

use proptest::prelude::*;
use raylab::scene::legacy::{MAX_NESTING, import_legacy};
use raylab::scene::{MAX_LIGHT_SAMPLES, MAX_SAMPLES_PER_PIXEL, Object, Shape, validate};

/// A random object tree, as the legacy text writes it.
#[derive(Clone, Debug)]
enum Node {
    Leaf(&'static str),
    Csg {
        form_2016: bool,
        op: &'static str,
        operands: Vec<Node>,
        transforms: Vec<&'static str>,
    },
    Group(Vec<Node>, Vec<&'static str>),
}

const LEAVES: &[&str] = &[
    "Sphere",
    "Cube",
    "Cone",
    "Cylinder",
    "Plane",
    "Octahedron",
    "Torus 0.5",
    "Tube 0.5",
];
const TRANSFORMS: &[&str] = &["Translate 0 1 0", "Rotate Y 30", "Scale 2", "Scale3 1 2 3"];

fn node() -> impl Strategy<Value = Node> {
    let leaf = prop::sample::select(LEAVES).prop_map(Node::Leaf);
    leaf.prop_recursive(6, 40, 3, |inner| {
        let transforms = prop::collection::vec(prop::sample::select(TRANSFORMS), 0..3);
        prop_oneof![
            (
                any::<bool>(),
                prop::sample::select(&["Union", "Intersection", "Difference"][..]),
                prop::collection::vec(inner.clone(), 2..=2),
                transforms.clone(),
            )
                .prop_map(|(form_2016, op, operands, transforms)| Node::Csg {
                    form_2016,
                    op,
                    operands,
                    transforms,
                }),
            (prop::collection::vec(inner, 0..4), transforms)
                .prop_map(|(children, transforms)| Node::Group(children, transforms)),
        ]
    })
}

/// The node as legacy text; node transforms go after the members (2016) or before them.
fn text(node: &Node, out: &mut String) {
    match node {
        Node::Leaf(kind) => out.push_str(&format!("Object {kind}\nEnd\n")),
        Node::Csg {
            form_2016,
            op,
            operands,
            transforms,
        } => {
            out.push_str(if *form_2016 { "Object CSG " } else { "CSG " });
            out.push_str(&format!("{op}\n"));
            if !form_2016 {
                transforms
                    .iter()
                    .for_each(|t| out.push_str(&format!("{t}\n")));
            }
            operands.iter().for_each(|o| text(o, out));
            if *form_2016 {
                transforms
                    .iter()
                    .for_each(|t| out.push_str(&format!("{t}\n")));
            }
            out.push_str("End\n");
        }
        Node::Group(children, transforms) => {
            out.push_str("ObjectGroup\n");
            children.iter().for_each(|c| text(c, out));
            transforms
                .iter()
                .for_each(|t| out.push_str(&format!("{t}\n")));
            out.push_str("End\n");
        }
    }
}

/// Whether the imported object has the generated tree's shape: the same kinds, members
/// and number of members, all the way down.
fn same_tree(node: &Node, object: &Object) -> bool {
    match (node, &object.shape) {
        (Node::Leaf(kind), shape) => kind.split(' ').next() == Some(shape.name()),
        (Node::Csg { operands, .. }, Shape::Csg { operands: got, .. })
        | (Node::Group(operands, _), Shape::Group { children: got }) => {
            operands.len() == got.len() && operands.iter().zip(got).all(|(n, o)| same_tree(n, o))
        }
        _ => false,
    }
}

fn config() -> ProptestConfig {
    ProptestConfig {
        cases: 256,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn random_trees_import_to_the_tree_they_describe(tree in node()) {
        let mut source = String::new();
        text(&tree, &mut source);
        let import = import_legacy(&source).map_err(|e| TestCaseError::fail(format!("{source}\n{e}")))?;
        validate(&import.scene).map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert_eq!(import.scene.objects.len(), 1);
        prop_assert!(same_tree(&tree, &import.scene.objects[0]), "{}\n{:?}", source, import.scene.objects[0]);
    }

    #[test]
    fn an_end_taken_away_or_added_refuses_the_file(tree in node(), pick in any::<usize>(), add in any::<bool>()) {
        let mut source = String::new();
        text(&tree, &mut source);
        let lines: Vec<&str> = source.lines().collect();
        let ends: Vec<usize> = (0..lines.len()).filter(|&i| lines[i] == "End").collect();
        let chosen = ends[pick % ends.len()];
        let broken: Vec<&str> = lines
            .iter()
            .enumerate()
            .flat_map(|(i, line)| match (i == chosen, add) {
                (false, _) => vec![*line],
                (true, false) => vec![],
                (true, true) => vec![*line, "End"],
            })
            .collect();
        let broken = broken.join("\n");
        prop_assert!(import_legacy(&broken).is_err(), "imported:\n{}", broken);
    }

    #[test]
    fn huge_fsaa_and_samples_are_capped_with_a_warning(
        fsaa in 1u64..1_000_000_000_000,
        samples in 1u64..1_000_000_000_000,
    ) {
        let source = format!(
            "Scene FSAA {fsaa} End\nLight PointLight Colour 1 1 1 Location 0 0 0 Radius 0.1\nSamples {samples}\nEnd"
        );
        let import = import_legacy(&source).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let per_axis = fsaa.min(256);
        prop_assert_eq!(u64::from(import.scene.render.samples_per_pixel), per_axis * per_axis);
        prop_assert!(import.scene.render.samples_per_pixel <= MAX_SAMPLES_PER_PIXEL);
        let raylab::scene::Light::Point { source: light, .. } = import.scene.lights[0] else {
            panic!("{:?}", import.scene.lights);
        };
        prop_assert_eq!(u64::from(light.samples), samples.min(u64::from(MAX_LIGHT_SAMPLES)));
        let capped = usize::from(fsaa > 256) + usize::from(samples > u64::from(MAX_LIGHT_SAMPLES));
        let warned = import.warnings.iter().filter(|w| w.contains("at most")).count();
        prop_assert_eq!(warned, capped, "{:?}", import.warnings);
    }

    #[test]
    fn nesting_deeper_than_the_limit_is_an_error_not_a_crash(extra in 1usize..2000) {
        let levels = MAX_NESTING + extra;
        let source = "Object CSG Union\n".repeat(levels) + "Object Sphere End\n" + &"End\n".repeat(levels);
        let errors = import_legacy(&source).expect_err("too deep");
        prop_assert_eq!(errors.0.len(), 1, "{}", errors);
        prop_assert_eq!(errors.0[0].line, MAX_NESTING + 1);
    }
}
