//! A small scene of trees for the tree module's tests: a ball, a die (a Difference of a
//! body and a group of two pips, one with its own material), and a lamp with no material.

use glam::DVec3;

use crate::scene::{CsgOp, Object, Scene, Shape, Transform, Trs};

/// A sphere called `name` at `x` on the x axis, showing `material` (empty: inherited).
pub(super) fn leaf(name: &str, x: f64, material: &str) -> Object {
    Object {
        name: name.to_owned(),
        shape: Shape::Sphere,
        transform: Transform::Trs(Trs {
            translate: DVec3::new(x, 0.0, 0.0),
            ..Trs::default()
        }),
        material: material.to_owned(),
    }
}

/// `[ball, die [body, pips [pip 1, pip 2]], lamp]`; the die is moved, turned and scaled.
pub(super) fn die_scene() -> Scene {
    let pips = Object {
        name: "pips".to_owned(),
        shape: Shape::Group {
            children: vec![leaf("pip 1", 1.0, "black"), leaf("pip 2", 2.0, "")],
        },
        transform: Transform::Trs(Trs {
            translate: DVec3::new(0.0, 0.0, 1.0),
            ..Trs::default()
        }),
        material: String::new(),
    };
    let die = Object {
        name: "die".to_owned(),
        shape: Shape::Csg {
            op: CsgOp::Difference,
            operands: vec![leaf("body", 0.0, ""), pips],
        },
        transform: Transform::Trs(Trs {
            translate: DVec3::new(0.0, 5.0, 0.0),
            rotate_deg: DVec3::new(0.0, 30.0, 0.0),
            scale: DVec3::new(2.0, 1.0, 1.0),
        }),
        material: "ivory".to_owned(),
    };
    let mut scene = Scene::empty();
    scene.objects = vec![leaf("ball", -3.0, "red"), die, leaf("lamp", 7.0, "")];
    scene
}

/// Every node's name, in walk order.
pub(super) fn names(scene: &Scene) -> Vec<String> {
    scene.nodes().map(|n| n.object.name.clone()).collect()
}

/// Every leaf's name and where it is in the world, in walk order.
pub(super) fn leaf_placements(scene: &Scene) -> Vec<(String, glam::DAffine3)> {
    let mut out = Vec::new();
    let mut work: Vec<(glam::DAffine3, &Object)> = scene
        .objects
        .iter()
        .rev()
        .map(|o| (glam::DAffine3::IDENTITY, o))
        .collect();
    while let Some((parent, object)) = work.pop() {
        let world = parent * object.transform.world_from_object();
        if object.shape.children().is_empty() {
            out.push((object.name.clone(), world));
        }
        work.extend(object.shape.children().iter().rev().map(|c| (world, c)));
    }
    out
}
