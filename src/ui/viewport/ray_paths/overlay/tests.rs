//! The ray-path overlay's hover card on trees: a ray names the leaf it met.

use super::*;
use crate::gizmo::ray_paths::{SegmentKind, SegmentLengths, path_segments};
use crate::trace::{TermSwitches, World};

/// The CSG example, and every `step`-th pixel of it (each way) inspected, lazily.
fn csg_pixels(step: usize) -> (Scene, impl Iterator<Item = PixelInspection>) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/csg.ron");
    let scene = crate::scene::load_scene(&path).unwrap();
    let world = World::new(&scene).unwrap();
    let (w, h) = (scene.camera.width, scene.camera.height);
    let inspected = scene.clone();
    let pixels = (0..h)
        .step_by(step)
        .flat_map(move |y| (0..w).step_by(step).map(move |x| (x, y)))
        .map(move |pixel| PixelInspection::traced(&world, &inspected, TermSwitches::ALL_ON, pixel));
    (scene, pixels)
}

#[test]
fn a_ray_that_meets_a_tree_names_the_leaf_it_hit() {
    // A pixel whose camera ray meets a pip's cut in the die.
    let (scene, mut pixels) = csg_pixels(3);
    let inspection = pixels
        .find(|i| {
            i.result.as_ref().is_ok_and(|r| {
                r.report.bounces[0]
                    .surface
                    .as_ref()
                    .is_some_and(|s| s.path.starts_with("die/pip"))
            })
        })
        .expect("the die's pips are in the picture");
    let report = &inspection.result.as_ref().unwrap().report;
    let leaf = report.bounces[0].surface.as_ref().unwrap().path.clone();
    let lengths = SegmentLengths {
        run_off: 1.0,
        normal: 0.1,
    };
    let camera_ray = path_segments(report, &scene.lights, lengths)
        .into_iter()
        .find(|s| matches!(s.kind, SegmentKind::Ray(RayKind::Primary)))
        .expect("the camera ray");
    let segment = ScreenSegment {
        pixel: inspection.pixel,
        inspected: true,
        segment: camera_ray,
        from: Pos2::ZERO,
        to: Pos2::ZERO,
    };
    let lines = hover_lines(&segment, &scene, std::slice::from_ref(&inspection));
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with(&format!("hits {leaf} at t"))),
        "{lines:?}"
    );
}

#[test]
fn a_shadow_ray_names_the_leaf_that_blocked_it_in_the_card_and_the_inspector() {
    // A pixel of the floor in the die's shadow.
    let (scene, mut pixels) = csg_pixels(4);
    let (inspection, light) = pixels
        .find_map(|i| {
            let bounce = &i.result.as_ref().ok()?.bounces[0];
            let light = bounce
                .lights
                .iter()
                .find(|l| l.outcome.starts_with("shadowed by die/"))?
                .scene_index;
            Some((i, light))
        })
        .expect("the die shadows the floor");
    let result = inspection.result.as_ref().unwrap();
    let (.., surface) = (result.report.bounces[0].blocker_hits.iter())
        .find(|(l, ..)| *l == light)
        .expect("the blocker's hit");
    let leaf = surface.path.clone();
    assert!(
        leaf.starts_with("die/") && leaf.len() > "die/".len(),
        "{leaf}"
    );
    let outcome = result.bounces[0]
        .lights
        .iter()
        .find(|l| l.scene_index == light);
    assert_eq!(outcome.unwrap().outcome, format!("shadowed by {leaf}"));
    let lengths = SegmentLengths {
        run_off: 1.0,
        normal: 0.1,
    };
    let shadow = path_segments(&result.report, &scene.lights, lengths)
        .into_iter()
        .find(|s| matches!(s.kind, SegmentKind::Ray(RayKind::Shadow)) && s.light == Some(light))
        .expect("the blocked shadow ray");
    let segment = ScreenSegment {
        pixel: inspection.pixel,
        inspected: true,
        segment: shadow,
        from: Pos2::ZERO,
        to: Pos2::ZERO,
    };
    let lines = hover_lines(&segment, &scene, std::slice::from_ref(&inspection));
    let blocked = format!("blocked by {leaf} at t");
    assert!(lines.iter().any(|l| l.starts_with(&blocked)), "{lines:?}");
}
