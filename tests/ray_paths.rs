//! The ray-path overlay's geometry comes from the tracer's record: segments end where
//! the recorded rays stopped, stubs point at the lights without a shadow ray, and the
//! projection onto the viewport round-trips (the ray through a drawn point passes
//! through the world point), from the scene camera and from a view camera off to the side.

mod common;
mod known_scenes;

use egui::{Pos2, Rect, Vec2};
use glam::DVec3;
use known_scenes::mirror_scene;
use raylab::gizmo::ray_paths::{SegmentEnd, SegmentKind, SegmentLengths, path_segments};
use raylab::scene::{Camera, Scene};
use raylab::trace::{
    LightOutcome, LightSkip, PixelReport, RayKind, RenderOptions, TermSwitches, World,
    inspect_pixel,
};
use raylab::ui::gizmo::projection::ViewMapping;
use raylab::ui::state::RayPathSettings;
use raylab::ui::viewport::pixel_inspector::PixelInspection;
use raylab::ui::viewport::ray_paths::screen_segments;

const LENGTHS: SegmentLengths = SegmentLengths {
    run_off: 50.0,
    normal: 0.5,
};

fn report(scene: &Scene, pixel: (u32, u32)) -> PixelReport {
    let world = World::new(scene).unwrap();
    inspect_pixel(&world, &RenderOptions::from_scene(scene), pixel.0, pixel.1)
}

fn near(a: DVec3, b: DVec3) -> bool {
    (a - b).length() < 1e-9
}

#[test]
fn segments_end_where_the_recorded_rays_stopped() {
    let scene = mirror_scene();
    let segments = path_segments(&report(&scene, (16, 16)), &scene.lights, LENGTHS);
    let find = |kind: SegmentKind, depth: u32| {
        segments
            .iter()
            .find(|s| s.kind == kind && s.depth == depth)
            .unwrap_or_else(|| panic!("no {kind:?} at depth {depth}: {segments:?}"))
    };
    let primary = find(SegmentKind::Ray(RayKind::Primary), 0);
    assert!(near(primary.from, scene.camera.position) && near(primary.to, DVec3::ZERO));
    assert_eq!((primary.end, primary.object), (SegmentEnd::Hit, Some(0)));

    let shadow = find(SegmentKind::Ray(RayKind::Shadow), 0);
    assert!(
        near(shadow.to, DVec3::new(0.0, 0.0, 7.0)),
        "{:?}",
        shadow.to
    );
    assert_eq!(shadow.end, SegmentEnd::Blocked);
    assert_eq!(
        (shadow.object, shadow.light),
        (Some(1), Some(1)),
        "the target blocks light 1"
    );

    let bounce = find(SegmentKind::Ray(RayKind::Reflection), 1);
    assert!(near(bounce.to, DVec3::new(0.0, 0.0, 7.0)));
    assert_eq!((bounce.end, bounce.object), (SegmentEnd::Hit, Some(1)));

    let normal = find(SegmentKind::Normal, 0);
    assert!(near(normal.from, DVec3::ZERO) && near(normal.to, DVec3::Z * 0.5));

    // The spotlight, outside its cone, gets a stub towards it from each hit; the point
    // light is behind the target's lit-side-away surface.
    let cone = find(
        SegmentKind::Unreached(LightOutcome::Skipped(LightSkip::OutsideSpotCone)),
        0,
    );
    assert_eq!(cone.light, Some(2));
    assert!(
        near(cone.to, DVec3::Z),
        "a stub of twice the normal towards (0, 0, 3)"
    );
    let behind = find(SegmentKind::Unreached(LightOutcome::BehindSurface), 1);
    assert_eq!(behind.light, Some(1));
    assert!(
        near(behind.from, DVec3::new(0.0, 0.0, 7.0)) && near(behind.to, DVec3::new(0.0, 0.0, 8.0))
    );
    assert_eq!(
        segments.len(),
        8,
        "3 rays, 2 normals, 3 stubs: {segments:?}"
    );

    // A miss runs off along its direction.
    let miss = path_segments(&report(&scene, (0, 0)), &scene.lights, LENGTHS);
    assert_eq!(miss.len(), 1);
    assert_eq!(miss[0].end, SegmentEnd::RunsOff);
    assert!(((miss[0].to - miss[0].from).length() - 50.0).abs() < 1e-9);
}

/// A camera off to the side of the mirror scene, seeing the camera ray and the bounce.
fn side_camera() -> Camera {
    Camera {
        position: DVec3::new(9.0, 3.0, 4.0),
        look_at: DVec3::new(0.0, 0.0, 3.5),
        up: DVec3::Y,
        fov_deg: 60.0,
        width: 640,
        height: 400,
    }
}

fn inspections(scene: &Scene, pixels: &[(u32, u32)]) -> Vec<PixelInspection> {
    let world = World::new(scene).unwrap();
    pixels
        .iter()
        .map(|p| PixelInspection::traced(&world, scene, TermSwitches::ALL_ON, *p))
        .collect()
}

#[test]
fn drawn_segments_round_trip_through_the_view_camera() {
    let scene = mirror_scene();
    let picture = Rect::from_min_size(Pos2::new(40.0, 30.0), Vec2::new(640.0, 400.0));
    let view = ViewMapping::new(&side_camera(), picture);
    let all = inspections(&scene, &[(16, 16), (0, 0)]);
    let settings = RayPathSettings::default();
    let drawn = screen_segments(&view, &scene, &all, &settings, Some((16, 16)));
    assert!(
        drawn.iter().any(|s| s.pixel == (0, 0) && !s.inspected),
        "the second pixel too"
    );
    for s in &drawn {
        for (world, screen) in [(s.segment.from, s.from), (s.segment.to, s.to)] {
            let ray = view.ray(screen);
            let offset = world - ray.origin;
            let miss = (offset - ray.dir * offset.dot(ray.dir)).length();
            assert!(
                miss < 1e-4 * offset.length(),
                "{:?}: {miss}",
                s.segment.kind
            );
        }
    }
    let kinds = |d: &[raylab::ui::viewport::ray_paths::ScreenSegment]| {
        d.iter().map(|s| s.segment.kind).collect::<Vec<_>>()
    };
    assert!(kinds(&drawn).contains(&SegmentKind::Ray(RayKind::Shadow)));
    // Each kind can be switched off.
    let no_shadows = RayPathSettings {
        shadow: false,
        normals: false,
        ..RayPathSettings::default()
    };
    let fewer = screen_segments(&view, &scene, &all, &no_shadows, Some((16, 16)));
    assert!(
        kinds(&fewer)
            .iter()
            .all(|k| matches!(k, SegmentKind::Ray(RayKind::Primary | RayKind::Reflection)))
    );
    assert_eq!(
        fewer.len(),
        drawn
            .iter()
            .filter(|s| matches!(
                s.segment.kind,
                SegmentKind::Ray(RayKind::Primary | RayKind::Reflection)
            ))
            .count()
    );
}

#[test]
fn through_the_scene_camera_a_camera_ray_collapses_to_its_pixel() {
    let scene = mirror_scene();
    let picture = Rect::from_min_size(Pos2::new(0.0, 0.0), Vec2::new(330.0, 330.0));
    let view = ViewMapping::new(&scene.camera, picture);
    let all = inspections(&scene, &[(16, 16), (3, 29)]);
    let drawn = screen_segments(&view, &scene, &all, &RayPathSettings::default(), None);
    for pixel in [(16u32, 16u32), (3, 29)] {
        let primary = drawn
            .iter()
            .find(|s| s.pixel == pixel && s.segment.kind == SegmentKind::Ray(RayKind::Primary))
            .expect("drawn");
        // 10 points a pixel: the pixel's centre.
        let centre = Pos2::new(pixel.0 as f32 * 10.0 + 5.0, pixel.1 as f32 * 10.0 + 5.0);
        assert!(primary.to.distance(centre) < 1e-3, "{:?}", primary.to);
    }
}
