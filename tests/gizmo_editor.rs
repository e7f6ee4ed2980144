//! The viewport's gizmos and camera navigation through egui_kittest, with no window:
//! pointer events on the picture drag handles, the scene follows by the expected world
//! amounts, and each gesture is one undo step. Navigation moves the view camera and
//! leaves the scene alone.

mod editor_harness;

use editor_harness::{click_at, editor_harness};
use egui::{Event, Key, Modifiers, PointerButton, Pos2, Rect, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use glam::DVec3;
use raylab::gizmo::spot::{rim_handle, rim_radial};
use raylab::gizmo::view::{bounding_sphere, world_per_pixel};
use raylab::scene::{Light, Scene, Transform, Trs};
use raylab::trace::PinholeCamera;
use raylab::ui::{EditorApp, EditorOptions, Selection, VIEWPORT_LABEL};

/// Length of the translate and scale arrows on screen, as the overlay draws them.
const ARROW_POINTS: f64 = 84.0;

fn harness() -> Harness<'static, EditorApp> {
    editor_harness(EditorOptions::default(), Vec2::new(1280.0, 800.0), 96)
}

fn select(harness: &mut Harness<'_, EditorApp>, label: &str) {
    harness.get_by_label(label).click();
    harness.run();
}

fn picture(harness: &Harness<'_, EditorApp>) -> Rect {
    harness.get_by_label(VIEWPORT_LABEL).rect()
}

/// Where a world point is on screen, seen through the camera the viewport shows.
fn screen(harness: &Harness<'_, EditorApp>, p_world: DVec3) -> Pos2 {
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
fn world_per_point(harness: &Harness<'_, EditorApp>, p_world: DVec3) -> f64 {
    let shown = harness.state().shown_camera();
    let h = f64::from(shown.height);
    world_per_pixel(&shown, p_world, h) * h / f64::from(picture(harness).height())
}

fn trs(scene: &Scene, index: usize) -> Trs {
    match scene.objects[index].transform {
        Transform::Trs(trs) => trs,
        Transform::Matrix(_) => panic!("expected translate/rotate/scale"),
    }
}

/// A primary-button drag from `from` to `to` in small steps, as a hand would.
fn drag(harness: &mut Harness<'_, EditorApp>, from: Pos2, to: Pos2, modifiers: Modifiers) {
    harness.event(Event::ModifiersChanged(modifiers));
    harness.event(Event::PointerMoved(from));
    harness.event(Event::PointerButton {
        pos: from,
        button: PointerButton::Primary,
        pressed: true,
        modifiers,
    });
    harness.step();
    for i in 1..=10 {
        harness.event(Event::PointerMoved(from + (to - from) * (i as f32 / 10.0)));
        harness.step();
    }
    harness.event(Event::PointerButton {
        pos: to,
        button: PointerButton::Primary,
        pressed: false,
        modifiers,
    });
    harness.event(Event::ModifiersChanged(Modifiers::NONE));
    harness.run();
}

fn undo(harness: &mut Harness<'_, EditorApp>) {
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run();
}

#[test]
fn dragging_the_x_arrow_moves_the_object_by_the_world_offset_under_the_cursor() {
    let mut harness = harness();
    select(&mut harness, "red ball");
    let before = harness.state().scene().clone();
    let origin = trs(&before, 1).translate;
    let length = ARROW_POINTS * world_per_point(&harness, origin);
    // Grab the x arrow at 70% of its length, let go where the point 1.25 units further
    // along x is drawn.
    let grab = origin + DVec3::X * length * 0.7;
    let from = screen(&harness, grab);
    let to = screen(&harness, grab + DVec3::X * 1.25);
    drag(&mut harness, from, to, Modifiers::NONE);

    let moved = trs(harness.state().scene(), 1).translate;
    assert!((moved.x - (origin.x + 1.25)).abs() < 2e-3, "{moved}");
    assert_eq!((moved.y, moved.z), (origin.y, origin.z), "only x changes");
    assert_eq!(harness.state().selection(), &Selection::Object(1));

    undo(&mut harness);
    assert_eq!(
        harness.state().scene(),
        &before,
        "one undo reverts the drag"
    );
}

#[test]
fn shift_snaps_a_plane_drag_to_whole_units() {
    let mut harness = harness();
    select(&mut harness, "blue box");
    let origin = trs(harness.state().scene(), 3).translate;
    let length = ARROW_POINTS * world_per_point(&harness, origin);
    // The ground-plane handle (normal y) sits at 0.39 of the arrow length along x and z.
    let grab = origin + DVec3::new(0.39, 0.0, 0.39) * length;
    let from = screen(&harness, grab);
    let to = screen(&harness, grab + DVec3::new(-1.3, 0.0, 0.8));
    drag(&mut harness, from, to, Modifiers::SHIFT);
    let moved = trs(harness.state().scene(), 3).translate;
    assert_eq!(moved.x, (origin.x - 1.3).round(), "{moved}");
    assert_eq!(moved.z, (origin.z + 0.8).round(), "{moved}");
    assert_eq!(moved.y, origin.y, "the plane handle keeps the height");
}

#[test]
fn the_scale_mode_button_and_a_scale_handle_drag() {
    let mut harness = harness();
    select(&mut harness, "mirror ball");
    harness.get_by_label("Scale").click();
    harness.run();
    let before = trs(harness.state().scene(), 2);
    let length = ARROW_POINTS * world_per_point(&harness, before.translate);
    // The x handle's square at the end of the arrow, dragged to 1.5 times as far out.
    let from = screen(&harness, before.translate + DVec3::X * length);
    let to = screen(&harness, before.translate + DVec3::X * length * 1.5);
    drag(&mut harness, from, to, Modifiers::NONE);
    let after = trs(harness.state().scene(), 2);
    assert!(
        (after.scale.x - before.scale.x * 1.5).abs() < 5e-3,
        "{}",
        after.scale
    );
    assert_eq!(after.scale.y, before.scale.y);
    assert_eq!(after.translate, before.translate);
}

#[test]
fn dragging_the_rim_handle_sets_the_spotlight_angle() {
    let mut harness = harness();
    select(&mut harness, "Spot light 4");
    assert_eq!(harness.state().selection(), &Selection::Light(3));
    let before = harness.state().scene().clone();
    let Light::Spot {
        position,
        direction,
        angle_deg,
        ..
    } = before.lights[3]
    else {
        panic!("light 4 is the spotlight");
    };
    let camera = &before.camera;
    let length = (camera.position - camera.look_at).length() * 0.3;
    let radial = rim_radial(direction, position - camera.position);
    let from = screen(
        &harness,
        rim_handle(position, direction, radial, angle_deg, length),
    );
    let to = screen(
        &harness,
        rim_handle(position, direction, radial, 35.0, length),
    );
    drag(&mut harness, from, to, Modifiers::NONE);
    let Light::Spot {
        angle_deg: after,
        position: p,
        direction: d,
        ..
    } = harness.state().scene().lights[3]
    else {
        panic!("still a spotlight");
    };
    assert!((after - 35.0).abs() < 0.05, "{after}");
    assert_eq!((p, d), (position, direction), "only the angle changes");
    undo(&mut harness);
    assert_eq!(harness.state().scene(), &before);
}

#[test]
fn dragging_the_tip_handle_re_aims_the_spotlight() {
    let mut harness = harness();
    select(&mut harness, "Spot light 4");
    let scene = harness.state().scene().clone();
    let Light::Spot {
        position,
        direction,
        ..
    } = scene.lights[3]
    else {
        panic!("light 4 is the spotlight");
    };
    let length = (scene.camera.position - scene.camera.look_at).length() * 0.3;
    let wanted = DVec3::new(-0.2, -1.0, 0.3).normalize();
    let from = screen(&harness, position + direction.normalize() * length);
    let to = screen(&harness, position + wanted * length);
    drag(&mut harness, from, to, Modifiers::NONE);
    let Light::Spot { direction: now, .. } = harness.state().scene().lights[3] else {
        panic!("still a spotlight");
    };
    assert!((now.normalize() - wanted).length() < 2e-3, "{now}");
    assert!(
        (now.length() - direction.length()).abs() < 1e-9,
        "length kept"
    );
}

#[test]
fn clicking_a_light_marker_selects_the_light() {
    let mut harness = harness();
    // The point light is out of the default view: frame it, then select the camera.
    select(&mut harness, "Point light 2");
    harness.key_press(Key::F);
    harness.run();
    select(&mut harness, "Camera");
    assert_eq!(harness.state().selection(), &Selection::Camera);
    let Light::Point { position, .. } = harness.state().scene().lights[1] else {
        panic!("light 2 is a point light");
    };
    let pos = screen(&harness, position);
    click_at(&mut harness, pos);
    assert_eq!(harness.state().selection(), &Selection::Light(1));
}

/// The view camera's pose, as a camera.
fn view_pose(harness: &Harness<'_, EditorApp>) -> raylab::scene::Camera {
    harness.state().view_camera().pose(1, 1)
}

#[test]
fn orbiting_on_empty_space_moves_the_view_and_a_click_still_picks() {
    let mut harness = harness();
    let before = harness.state().scene().clone();
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
        !harness.state().view_camera().through_scene_camera,
        "left camera view"
    );
    assert_ne!(orbited.position, before.camera.position, "the drag orbited");
    let distance = |c: &raylab::scene::Camera| (c.position - c.look_at).length();
    assert!((distance(&orbited) - distance(&before.camera)).abs() < 1e-9);
    assert_eq!(orbited.look_at, before.camera.look_at);
    assert_eq!(harness.state().scene(), &before, "the scene camera stays");
    assert!(!harness.state().is_dirty());
    undo(&mut harness);
    assert_eq!(
        view_pose(&harness),
        orbited,
        "looking around is no undo step"
    );

    // A click without a drag still picks the object under the cursor, seen from the view.
    let pos = screen(&harness, trs(&before, 3).translate);
    harness.event(Event::PointerMoved(pos));
    for pressed in [true, false] {
        harness.event(Event::PointerButton {
            pos,
            button: PointerButton::Primary,
            pressed,
            modifiers: Modifiers::NONE,
        });
    }
    harness.run();
    assert_eq!(harness.state().selection(), &Selection::Object(3));
    assert_eq!(harness.state().scene(), &before, "a click edits nothing");
}

#[test]
fn shift_drag_pans_and_the_wheel_zooms_the_view() {
    let mut harness = harness();
    let before = harness.state().scene().clone();
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
    assert_eq!(harness.state().scene(), &before, "the scene camera stays");
    assert!(!harness.state().is_dirty());
}

#[test]
fn f_frames_the_selection() {
    let mut harness = harness();
    select(&mut harness, "blue box");
    let before = harness.state().scene().clone();
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
        harness.state().scene(),
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
    let before = trs(harness.state().scene(), 2);
    let radius = 72.0 * world_per_point(&harness, before.translate);
    // The y ring (about world y for zero angles), grabbed between +x and +z where no
    // other ring passes, turned a quarter towards -z.
    let c = before.translate;
    let s = 0.5f64.sqrt();
    let from = screen(&harness, c + DVec3::new(s, 0.0, s) * radius);
    let to = screen(&harness, c + DVec3::new(s, 0.0, -s) * radius);
    drag(&mut harness, from, to, Modifiers::NONE);
    let after = trs(harness.state().scene(), 2);
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
    assert!((trs(harness.state().scene(), 2).translate.x - (c.x + 0.5)).abs() < 2e-3);
}

#[test]
fn a_middle_drag_pans_even_over_a_handle() {
    let mut harness = harness();
    select(&mut harness, "red ball");
    let before = harness.state().scene().clone();
    let origin = trs(&before, 1).translate;
    let length = ARROW_POINTS * world_per_point(&harness, origin);
    let from = screen(&harness, origin + DVec3::X * length * 0.7);
    let to = from + Vec2::new(-30.0, 25.0);
    harness.event(Event::PointerMoved(from));
    harness.event(Event::PointerButton {
        pos: from,
        button: PointerButton::Middle,
        pressed: true,
        modifiers: Modifiers::NONE,
    });
    harness.step();
    for i in 1..=6 {
        harness.event(Event::PointerMoved(from + (to - from) * (i as f32 / 6.0)));
        harness.step();
    }
    harness.event(Event::PointerButton {
        pos: to,
        button: PointerButton::Middle,
        pressed: false,
        modifiers: Modifiers::NONE,
    });
    harness.run();
    assert_eq!(
        harness.state().scene(),
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
    let before = harness.state().scene().clone();
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
    let after = harness.state().scene();
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
