//! The ray-path overlay's hover card on trees: a ray names the leaf it met.

use super::*;
use crate::gizmo::ray_paths::{SegmentKind, SegmentLengths, path_segments};
use crate::trace::{TermSwitches, World};

#[test]
fn a_ray_that_meets_a_tree_names_the_leaf_it_hit() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/csg.ron");
    let scene = crate::scene::load_scene(&path).unwrap();
    let world = World::new(&scene).unwrap();
    // A pixel whose camera ray meets a pip's cut in the die.
    let (w, h) = (scene.camera.width, scene.camera.height);
    let inspection = (0..h)
        .step_by(3)
        .flat_map(|y| (0..w).step_by(3).map(move |x| (x, y)))
        .map(|pixel| PixelInspection::traced(&world, &scene, TermSwitches::ALL_ON, pixel))
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
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/csg.ron");
    let scene = crate::scene::load_scene(&path).unwrap();
    let world = World::new(&scene).unwrap();
    // A pixel of the floor in the die's shadow.
    let (w, h) = (scene.camera.width, scene.camera.height);
    let (inspection, light) = (0..h)
        .step_by(4)
        .flat_map(|y| (0..w).step_by(4).map(move |x| (x, y)))
        .map(|pixel| PixelInspection::traced(&world, &scene, TermSwitches::ALL_ON, pixel))
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
