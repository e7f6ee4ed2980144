//! The ray-path overlay in the editor, through egui_kittest: an inspected pixel's rays
//! are drawn from the record, a pin keeps a pixel's rays, row mode traces a row,
//! hovering a segment shows its numbers, and each ray kind can be switched off.

mod view_harness;

use egui::{Modifiers, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use raylab::gizmo::ray_paths::SegmentKind;
use raylab::trace::RayKind;
use raylab::ui::EditorApp;
use raylab::ui::state::{MAX_SPAN_PIXELS, RaySpan};
use raylab::ui::viewport::ray_paths::ScreenSegment;
use view_harness::{
    click, harness, move_inspector_away, object_on_screen, orbit, picture, press, scene_pixel,
    segments, toggle,
};

/// Inspects the pixel over scene object `index` (in camera view); returns the pixel.
fn inspect_object(harness: &mut Harness<'_, EditorApp>, index: usize) -> (u32, u32) {
    let origin = harness.state().document().scene.objects[index]
        .transform
        .world_from_object()
        .translation;
    let pixel = scene_pixel(harness, origin);
    let pos = object_on_screen(harness, index);
    click(harness, pos, Modifiers::ALT);
    assert_eq!(harness.state().view().looking.inspected, Some(pixel));
    // As a person would: the inspector window out of the way of the picture.
    move_inspector_away(harness);
    pixel
}

fn drawn_pixels(segments: &[ScreenSegment]) -> Vec<(u32, u32)> {
    let mut pixels: Vec<_> = segments.iter().map(|s| s.pixel).collect();
    pixels.dedup();
    pixels
}

#[test]
fn a_pin_keeps_a_pixels_rays_and_row_mode_traces_the_row() {
    let mut harness = harness("pins", false);
    let ball = inspect_object(&mut harness, 1);
    assert_eq!(drawn_pixels(&segments(&harness)), vec![ball]);
    press(&mut harness, "Pin");
    assert_eq!(harness.state().view().looking.ray_paths.pinned, vec![ball]);
    harness.get_by_label("Unpin");

    let boxed = inspect_object(&mut harness, 3);
    let drawn = drawn_pixels(&segments(&harness));
    assert!(drawn.contains(&ball) && drawn.contains(&boxed), "{drawn:?}");
    assert!(
        segments(&harness)
            .iter()
            .all(|s| s.inspected == (s.pixel == boxed)),
        "the pinned pixel is drawn fainter"
    );

    press(&mut harness, "rays of the row");
    assert_eq!(harness.state().view().looking.ray_paths.span, RaySpan::Row);
    let traced: Vec<(u32, u32)> = harness
        .state()
        .inspections()
        .iter()
        .map(|i| i.pixel)
        .collect();
    let row = traced.iter().filter(|p| p.1 == boxed.1).count();
    assert!(
        row > MAX_SPAN_PIXELS as usize / 2 && row <= MAX_SPAN_PIXELS as usize + 1,
        "{row}"
    );
    assert!(traced.contains(&ball), "pins stay");

    press(&mut harness, "Clear pins");
    assert!(harness.state().view().looking.ray_paths.pinned.is_empty());
    assert!(
        !harness.state().document().scene.objects.is_empty()
            && !harness.state().document().is_dirty()
    );
}

/// Which end of a segment a point is measured from.
#[derive(Clone, Copy)]
enum End {
    Start,
    Finish,
}

/// A point `pixels` screen points from one end of the longest drawn segment of `kind` of
/// the inspected pixel, checked to be on the picture (a shadow ray to a sun ends far off
/// screen, and a camera ray may start off it, so a fraction of the length would miss).
fn point_on(
    harness: &Harness<'_, EditorApp>,
    kind: SegmentKind,
    end: End,
    pixels: f32,
) -> egui::Pos2 {
    let all = segments(harness);
    let segment = all
        .iter()
        .filter(|s| s.inspected && s.segment.kind == kind)
        .max_by(|a, b| a.from.distance(a.to).total_cmp(&b.from.distance(b.to)))
        .unwrap_or_else(|| panic!("no {kind:?} drawn"));
    let (from, to) = match end {
        End::Start => (segment.from, segment.to),
        End::Finish => (segment.to, segment.from),
    };
    let point = from + (to - from).normalized() * pixels;
    assert!(
        picture(harness).contains(point),
        "{point:?} is off the picture {:?}",
        picture(harness)
    );
    point
}

fn hover(harness: &mut Harness<'_, EditorApp>, pos: egui::Pos2) {
    harness.event(egui::Event::PointerMoved(pos));
    harness.run_ok();
}

#[test]
fn hovering_a_segment_shows_its_numbers_and_each_kind_can_be_hidden() {
    let mut harness = harness("hover", false);
    let ball = inspect_object(&mut harness, 1);
    // Look at the rays from the side: the camera ray is a line, not a point.
    orbit(&mut harness, Vec2::new(140.0, 30.0));
    assert!(!harness.state().view().looking.camera.through_scene_camera);

    // Near its hit: the camera ray starts at the scene camera, maybe off the picture.
    let primary = point_on(
        &harness,
        SegmentKind::Ray(RayKind::Primary),
        End::Finish,
        60.0,
    );
    hover(&mut harness, primary);
    let (x, y) = ball;
    harness.get_by_label(&format!("primary ray · pixel ({x}, {y}) · depth 0"));
    harness.get_by_label_contains("hits red ball at t");
    let camera = harness.state().document().scene.camera.position;
    let origin = format!("origin ({:.4}, {:.4}, {:.4})", camera.x, camera.y, camera.z);
    harness.get_by_label(&origin);

    let shadow = point_on(
        &harness,
        SegmentKind::Ray(RayKind::Shadow),
        End::Start,
        100.0,
    );
    hover(&mut harness, shadow);
    harness.get_by_label_contains("shadow ray · pixel");
    harness.get_by_label_contains("towards");

    toggle(&mut harness, "shadow rays");
    assert!(!harness.state().view().looking.ray_paths.shadow);
    assert!(
        segments(&harness).iter().all(|s| !matches!(
            s.segment.kind,
            SegmentKind::Ray(RayKind::Shadow) | SegmentKind::Unreached(_)
        )),
        "no shadow rays drawn"
    );
    hover(&mut harness, shadow);
    assert!(
        harness
            .query_by_label_contains("shadow ray · pixel")
            .is_none()
    );

    toggle(&mut harness, "primary rays");
    toggle(&mut harness, "normals");
    assert!(
        segments(&harness)
            .iter()
            .all(|s| s.segment.kind == SegmentKind::Ray(RayKind::Reflection)),
        "only the mirror rays are left"
    );
    toggle(&mut harness, "shadow rays");
    assert!(harness.state().view().looking.ray_paths.shadow);
    assert_eq!(
        harness.state().document().scene.camera.position,
        camera,
        "looking is not editing"
    );

    // A muted light's absence is said on the hover card, as in the inspector window.
    toggle(&mut harness, "primary rays");
    press(&mut harness, "mute Point light 2");
    let off = "off (muted or not solo): Point light 2";
    assert_eq!(
        harness.query_all_by_label(off).count(),
        1,
        "the window's line"
    );
    let primary = point_on(
        &harness,
        SegmentKind::Ray(RayKind::Primary),
        End::Finish,
        60.0,
    );
    hover(&mut harness, primary);
    assert_eq!(harness.query_all_by_label(off).count(), 2, "and the card's");
}
