//! Shared by the gizmo tests: the editor at 1280x800, selecting by label, where world
//! points land on screen, and drags and undo as a hand makes them.
#![allow(dead_code)]

use crate::editor_harness::editor_harness;
use egui::{Key, Modifiers, PointerButton, Pos2, Rect, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use glam::DVec3;
use raylab::gizmo::view::world_per_pixel;
use raylab::scene::{Scene, Transform, Trs};
use raylab::trace::PinholeCamera;
use raylab::ui::{EditorApp, EditorOptions, VIEWPORT_LABEL};

/// Length of the translate and scale arrows on screen, as the overlay draws them.
pub const ARROW_POINTS: f64 = 84.0;

pub fn harness() -> Harness<'static, EditorApp> {
    editor_harness(EditorOptions::default(), Vec2::new(1280.0, 800.0), 96)
}

pub fn select(harness: &mut Harness<'_, EditorApp>, label: &str) {
    harness.get_by_label(label).click();
    harness.run();
}

pub fn picture(harness: &Harness<'_, EditorApp>) -> Rect {
    harness.get_by_label(VIEWPORT_LABEL).rect()
}

/// Where a world point is on screen, seen through the camera the viewport shows.
pub fn screen(harness: &Harness<'_, EditorApp>, p_world: DVec3) -> Pos2 {
    let shown = harness.state().shown_camera();
    let picture = picture(harness);
    let (w, h) = (shown.width, shown.height);
    let p = PinholeCamera::new(&shown, w, h)
        .project(p_world)
        .expect("in front of the camera");
    Pos2::new(
        picture.min.x + (p.x / f64::from(w)) as f32 * picture.width(),
        picture.min.y + (p.y / f64::from(h)) as f32 * picture.height(),
    )
}

/// World units per screen point at `p_world`.
pub fn world_per_point(harness: &Harness<'_, EditorApp>, p_world: DVec3) -> f64 {
    let shown = harness.state().shown_camera();
    let h = f64::from(shown.height);
    world_per_pixel(&shown, p_world, h) * h / f64::from(picture(harness).height())
}

pub fn trs(scene: &Scene, index: usize) -> Trs {
    match scene.objects[index].transform {
        Transform::Trs(trs) => trs,
        Transform::Matrix(_) => panic!("expected translate/rotate/scale"),
    }
}

/// A primary-button drag from `from` to `to` in small steps, as a hand would.
pub fn drag(harness: &mut Harness<'_, EditorApp>, from: Pos2, to: Pos2, modifiers: Modifiers) {
    crate::editor_harness::press_drag_release(
        harness,
        PointerButton::Primary,
        (from, to),
        modifiers,
        10,
    );
    harness.run();
}

pub fn undo(harness: &mut Harness<'_, EditorApp>) {
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
}
