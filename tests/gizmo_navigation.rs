//! Camera navigation in the viewport through egui_kittest, with no window: orbit, pan,
//! zoom and F move the view camera (never the scene), the gizmo modes switch by key, and
//! a drag survives a middle button or a delete under it.

mod editor_harness;
mod gizmo_harness;

use egui::{Event, Key, Modifiers, PointerButton, Vec2};
use egui_kittest::Harness;
use gizmo_harness::*;
use glam::DVec3;
use raylab::gizmo::view::bounding_sphere;
use raylab::ui::{EditorApp, Selection};

/// The view camera's pose, as a camera.
fn view_pose(harness: &Harness<'_, EditorApp>) -> raylab::scene::Camera {
    harness.state().view().looking.camera.pose(1, 1)
}

#[test]
fn orbiting_on_empty_space_moves_the_view_and_a_click_still_picks() {
    let mut harness = harness();
    let before = harness.state().document().scene.clone();
    let picture = picture(&harness);
    // Near the top of the picture: sky, no handle.
    let from = picture.center_top() + Vec2::new(-150.0, 30.0);
    drag(
        &mut harness,
        from,
        from + Vec2::new(120.0, 20.0),
        Modifiers::NONE,
    );
    let orbited = view_pose(&harness);
    assert!(
        !harness.state().view().looking.camera.through_scene_camera,
        "left camera view"
    );
    assert_ne!(orbited.position, before.camera.position, "the drag orbited");
    let distance = |c: &raylab::scene::Camera| (c.position - c.look_at).length();
    assert!((distance(&orbited) - distance(&before.camera)).abs() < 1e-9);
    assert_eq!(orbited.look_at, before.camera.look_at);
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "the scene camera stays"
    );
    assert!(!harness.state().document().is_dirty());
    undo(&mut harness);
    assert_eq!(
        view_pose(&harness),
        orbited,
        "looking around is no undo step"
    );

    // A click without a drag still picks the object under the cursor, seen from the view.
    let pos = screen(&harness, trs(&before, 3).translate);
    editor_harness::click_at(&mut harness, pos);
    assert_eq!(&harness.state().document().selection, &Selection::Object(3));
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "a click edits nothing"
    );
}

#[test]
fn shift_drag_pans_and_the_wheel_zooms_the_view() {
    let mut harness = harness();
    let before = harness.state().document().scene.clone();
    let picture = picture(&harness);
    let from = picture.center_top() + Vec2::new(-150.0, 30.0);
    drag(
        &mut harness,
        from,
        from + Vec2::new(40.0, 0.0),
        Modifiers::SHIFT,
    );
    let panned = view_pose(&harness);
    let shift = panned.look_at - before.camera.look_at;
    assert!(shift.length() > 0.0, "panned");
    assert!(
        ((panned.position - before.camera.position) - shift).length() < 1e-9,
        "eye and target move together"
    );

    let zoom_from = view_pose(&harness);
    let picture = self::picture(&harness);
    harness.event(Event::PointerMoved(picture.center()));
    for _ in 0..3 {
        harness.event(Event::MouseWheel {
            unit: egui::MouseWheelUnit::Line,
            delta: Vec2::new(0.0, 1.0),
            phase: egui::TouchPhase::Move,
            source: egui::MouseWheelSource::Wheel,
            modifiers: Modifiers::NONE,
        });
        harness.step();
    }
    harness.run();
    let zoomed = view_pose(&harness);
    let distance = |c: &raylab::scene::Camera| (c.position - c.look_at).length();
    let expected = distance(&zoom_from) * 0.9f64.powi(3);
    assert!(
        (distance(&zoomed) - expected).abs() < 1e-9,
        "three steps in"
    );
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "the scene camera stays"
    );
    assert!(!harness.state().document().is_dirty());
}

#[test]
fn f_frames_the_selection() {
    let mut harness = harness();
    select(&mut harness, "blue box");
    let before = harness.state().document().scene.clone();
    harness.key_press(Key::F);
    harness.run();
    let camera = view_pose(&harness);
    let (centre, radius) = bounding_sphere(&before.objects[3]);
    assert!(
        (camera.look_at - centre).length() < 1e-12,
        "{}",
        camera.look_at
    );
    // The same view direction, close enough for the box to fill the view.
    let direction = |c: &raylab::scene::Camera| (c.position - c.look_at).normalize();
    assert!((direction(&camera) - direction(&before.camera)).length() < 1e-9);
    assert!((camera.position - camera.look_at).length() < radius * 5.0);
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "framing moves the view only"
    );
}

#[test]
fn w_e_r_switch_the_gizmo_and_rings_rotate() {
    let mut harness = harness();
    select(&mut harness, "mirror ball");
    harness.key_press(Key::E);
    harness.run();
    let before = trs(&harness.state().document().scene, 2);
    let radius = 72.0 * world_per_point(&harness, before.translate);
    // The y ring (about world y for zero angles), grabbed between +x and +z where no
    // other ring passes, turned a quarter towards -z.
    let c = before.translate;
    let s = 0.5f64.sqrt();
    let from = screen(&harness, c + DVec3::new(s, 0.0, s) * radius);
    let to = screen(&harness, c + DVec3::new(s, 0.0, -s) * radius);
    drag(&mut harness, from, to, Modifiers::NONE);
    let after = trs(&harness.state().document().scene, 2);
    assert!(
        (after.rotate_deg.y - 90.0).abs() < 0.1,
        "{}",
        after.rotate_deg
    );
    assert_eq!((after.rotate_deg.x, after.rotate_deg.z), (0.0, 0.0));
    harness.key_press(Key::W);
    harness.run();
    // Back in move mode, the x arrow works again.
    let length = ARROW_POINTS * world_per_point(&harness, c);
    let grab = c + DVec3::X * length * 0.7;
    let (from, to) = (
        screen(&harness, grab),
        screen(&harness, grab + DVec3::X * 0.5),
    );
    drag(&mut harness, from, to, Modifiers::NONE);
    assert!((trs(&harness.state().document().scene, 2).translate.x - (c.x + 0.5)).abs() < 2e-3);
}

#[test]
fn a_middle_drag_pans_even_over_a_handle() {
    let mut harness = harness();
    select(&mut harness, "red ball");
    let before = harness.state().document().scene.clone();
    let origin = trs(&before, 1).translate;
    let length = ARROW_POINTS * world_per_point(&harness, origin);
    let from = screen(&harness, origin + DVec3::X * length * 0.7);
    let to = from + Vec2::new(-30.0, 25.0);
    editor_harness::press_drag_release(
        &mut harness,
        PointerButton::Middle,
        (from, to),
        Modifiers::NONE,
        6,
    );
    harness.run();
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "the object and the camera stay"
    );
    let after = view_pose(&harness);
    let shift = after.look_at - before.camera.look_at;
    assert!(shift.length() > 0.0, "panned");
    assert!(((after.position - before.camera.position) - shift).length() < 1e-9);
}

#[test]
fn deleting_the_selection_mid_drag_ends_the_drag_without_editing_another_object() {
    let mut harness = harness();
    select(&mut harness, "red ball");
    let before = harness.state().document().scene.clone();
    let origin = trs(&before, 1).translate;
    let grab = origin + DVec3::X * ARROW_POINTS * world_per_point(&harness, origin) * 0.7;
    let (from, to) = (
        screen(&harness, grab),
        screen(&harness, grab + DVec3::X * 1.25),
    );
    harness.event(Event::PointerMoved(from));
    harness.event(Event::PointerButton {
        pos: from,
        button: PointerButton::Primary,
        pressed: true,
        modifiers: Modifiers::NONE,
    });
    harness.step();
    for i in 1..=10 {
        if i == 5 {
            // Delete the dragged object halfway: "mirror ball" takes its index.
            harness.key_press(Key::Delete);
        }
        harness.event(Event::PointerMoved(from + (to - from) * (i as f32 / 10.0)));
        harness.step();
    }
    harness.event(Event::PointerButton {
        pos: to,
        button: PointerButton::Primary,
        pressed: false,
        modifiers: Modifiers::NONE,
    });
    harness.run();
    let after = &harness.state().document().scene;
    assert_eq!(
        after.objects.len(),
        before.objects.len() - 1,
        "the red ball was deleted"
    );
    assert_eq!(
        after.objects[1], before.objects[2],
        "the object now at its index was not dragged"
    );
}
