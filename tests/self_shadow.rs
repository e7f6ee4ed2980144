//! Shapes that are not convex shadow themselves: a torus or a tube lit across its hole
//! has its far inner side in the shadow of its near side. (A shadow ray leaving a convex
//! solid outward may skip the solid; leaving a torus or a tube it must not.)

use raylab::scene::parse_scene;
use raylab::trace::{LightOutcome, RenderOptions, World, inspect_pixel};

/// A camera inside the hole of `shape` (axis z), looking at the inner side at x = -0.75
/// (which faces +x), and a directional light shining from +x through the hole.
fn scene(shape: &str) -> String {
    format!(
        r#"Scene(
    camera: (position: (0.3, 0.0, 0.0), look_at: (-1.0, 0.0, 0.0), up: (0.0, 0.0, 1.0),
             fov_deg: 20.0, width: 33, height: 33),
    materials: {{ "m": (ambient: (0.1, 0.1, 0.1), diffuse: (0.8, 0.8, 0.8)) }},
    objects: [ (name: "ring", shape: {shape}, material: "m") ],
    lights: [ Directional(direction: (-1.0, 0.0, 0.0), colour: (1.0, 1.0, 1.0)) ],
)"#
    )
}

fn outcome(shape: &str) -> LightOutcome {
    let scene = parse_scene(&scene(shape)).expect("parses");
    let world = World::new(&scene).expect("compiles");
    let report = inspect_pixel(&world, &RenderOptions::from_scene(&scene), 16, 16);
    let hit = report.bounces[0].hit.expect("the inner side");
    assert!((hit.p.x + 0.75).abs() < 0.05, "hit at {}", hit.p);
    report.bounces[0].light_outcomes()[0].1
}

#[test]
fn a_torus_and_a_tube_shadow_their_own_far_side() {
    for shape in ["Torus(minor: 0.25)", "Tube(inner: 0.75)"] {
        assert!(
            matches!(outcome(shape), LightOutcome::Shadowed(_)),
            "{shape}: {:?}",
            outcome(shape)
        );
    }
}
