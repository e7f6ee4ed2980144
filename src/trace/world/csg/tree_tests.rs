//! The CSG example's trees (a lens, a die with 21 pips, a hollow cube with windows) and a
//! three-way Intersection (a cone, a sphere and a rotated cube), against the same trees
//! run without their early exits or closed form: the same answers for rays from
//! anywhere, with any `t_max`, and for rays leaving their own surfaces, as shadow and
//! mirror rays do (where the exits skip the most).

use glam::DVec3;
use proptest::prelude::*;

use super::tree::{CsgTree, Step};
use crate::scene::{Shape, parse_scene};
use crate::trace::ray::Ray;
use crate::trace::shapes::MeshStore;

/// A cone, a sphere and a rotated cube intersected: three leaves in closed form.
const THREE_WAY: &str = r#"Scene(format: 1,
    camera: (position: (0.0, 0.0, 5.0), look_at: (0.0, 0.0, 0.0), up: (0.0, 1.0, 0.0), fov_deg: 40.0, width: 8, height: 8),
    materials: {"m": ()}, lights: [],
    objects: [(name: "cut cone", material: "m", shape: Csg(op: Intersection, operands: [
        (name: "cone", shape: Cone, transform: (translate: (0.0, 0.0, -1.0), scale: (1.5, 1.5, 2.0))),
        (name: "ball", shape: Sphere, transform: (scale: (1.2, 1.2, 1.2))),
        (name: "box", shape: Cube, transform: (rotate_deg: (30.0, 20.0, 10.0), scale: (0.9, 0.9, 0.9))),
    ]))],
)"#;

/// The CSG example's top-level CSG nodes, compiled, and [`THREE_WAY`]'s.
fn example_trees() -> Vec<CsgTree> {
    let mut trees = csg_trees(include_str!("../../../../scenes/csg.ron"));
    assert_eq!(trees.len(), 3, "the lens, the die and the hollow cube");
    trees.extend(csg_trees(THREE_WAY));
    trees
}

fn csg_trees(text: &str) -> Vec<CsgTree> {
    let scene = parse_scene(text).expect("the example");
    scene
        .objects
        .iter()
        .filter_map(|object| match &object.shape {
            Shape::Csg { op, operands } => Some(
                CsgTree::build(
                    *op,
                    operands,
                    "m",
                    &object.name,
                    &|_| Some(0),
                    &MeshStore::default(),
                )
                .expect("the example compiles"),
            ),
            _ => None,
        })
        .collect()
}

#[test]
fn intersections_of_convex_primitives_take_the_closed_form() {
    let closed: Vec<bool> = example_trees().iter().map(|t| t.closed_form).collect();
    // The lens and the three-way Intersection; not the die nor the hollow cube.
    assert_eq!(closed, [true, false, false, true]);
}

/// The tree without its SkipIfEmpty steps: every operand evaluated in full.
fn without_early_exits(tree: &CsgTree) -> CsgTree {
    let kept: Vec<usize> = (0..tree.steps.len())
        .filter(|&i| !matches!(tree.steps[i], Step::SkipIfEmpty { .. }))
        .collect();
    // A jump to old step `i` lands on the first kept step at or after it.
    let moved = |i: u32| kept.partition_point(|&k| k < i as usize) as u32;
    let mut plain = tree.clone();
    plain.closed_form = false;
    plain.steps = kept
        .iter()
        .map(|&i| match tree.steps[i] {
            Step::SkipIfMissed {
                bounds,
                lists,
                skip_to,
            } => Step::SkipIfMissed {
                bounds,
                lists,
                skip_to: moved(skip_to),
            },
            step => step,
        })
        .collect();
    plain
}

fn vector(range: f64) -> impl Strategy<Value = DVec3> {
    (-range..range, -range..range, -range..range).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn same_answers(
    tree: &CsgTree,
    plain: &CsgTree,
    ray: &Ray,
    t_max: f64,
) -> Result<(), TestCaseError> {
    let (hit, expected) = (tree.intersect(ray, t_max), plain.intersect(ray, t_max));
    prop_assert_eq!(hit, expected, "intersect {:?} {}", ray, t_max);
    prop_assert_eq!(
        tree.occluded(ray, t_max),
        plain.occluded(ray, t_max),
        "occluded"
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]
    #[test]
    fn early_exits_change_no_answer(
        origin in vector(2.5),
        dir in vector(1.0).prop_filter("a direction", |d| d.length() > 0.1),
        out in vector(1.0).prop_filter("a direction", |d| d.length() > 0.1),
        t_max in prop_oneof![Just(f64::INFINITY), 0.05..6.0],
    ) {
        for tree in example_trees() {
            let plain = without_early_exits(&tree);
            let ray = Ray::new(origin, dir);
            same_answers(&tree, &plain, &ray, t_max)?;
            // A ray leaving the surface this one meets, outward or inward, from just off it.
            if let Some(hit) = plain.intersect(&ray, f64::INFINITY) {
                // Ranges that end just past or just short of the surface.
                for scale in [0.999, 1.001] {
                    same_answers(&tree, &plain, &ray, hit.hit.t * scale)?;
                }
                let n = hit.hit.n;
                let side = if out.dot(n) >= 0.0 { 1.0 } else { -1.0 };
                let leaving = Ray::new(hit.hit.p + n * side * 1e-9, out);
                same_answers(&tree, &plain, &leaving, t_max)?;
            }
        }
    }
}
