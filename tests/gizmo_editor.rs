//! The viewport's gizmos and camera navigation through egui_kittest, with no window:
//! pointer events on the picture drag handles, the scene follows by the expected world
//! amounts, and each gesture is one undo step. Navigation moves the view camera and
//! leaves the scene alone.

mod editor_harness;
mod gizmo_harness;

use editor_harness::click_at;
use egui::{Key, Modifiers};
use egui_kittest::kittest::Queryable;
use gizmo_harness::*;
use glam::DVec3;
use raylab::gizmo::spot::{rim_handle, rim_radial};
use raylab::scene::Light;
use raylab::ui::Selection;

#[test]
fn dragging_the_x_arrow_moves_the_object_by_the_world_offset_under_the_cursor() {
    let mut harness = harness();
    select(&mut harness, "red ball");
    let before = harness.state().document().scene.clone();
    let origin = trs(&before, 1).translate;
    let length = ARROW_POINTS * world_per_point(&harness, origin);
    // Grab the x arrow at 70% of its length, let go where the point 1.25 units further
    // along x is drawn.
    let grab = origin + DVec3::X * length * 0.7;
    let from = screen(&harness, grab);
    let to = screen(&harness, grab + DVec3::X * 1.25);
    drag(&mut harness, from, to, Modifiers::NONE);

    let moved = trs(&harness.state().document().scene, 1).translate;
    assert!((moved.x - (origin.x + 1.25)).abs() < 2e-3, "{moved}");
    assert_eq!((moved.y, moved.z), (origin.y, origin.z), "only x changes");
    assert_eq!(&harness.state().document().selection, &Selection::Object(1));

    undo(&mut harness);
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "one undo reverts the drag"
    );
}

#[test]
fn shift_snaps_a_plane_drag_to_whole_units() {
    let mut harness = harness();
    select(&mut harness, "blue box");
    let origin = trs(&harness.state().document().scene, 3).translate;
    let length = ARROW_POINTS * world_per_point(&harness, origin);
    // The ground-plane handle (normal y) sits at 0.39 of the arrow length along x and z.
    let grab = origin + DVec3::new(0.39, 0.0, 0.39) * length;
    let from = screen(&harness, grab);
    let to = screen(&harness, grab + DVec3::new(-1.3, 0.0, 0.8));
    drag(&mut harness, from, to, Modifiers::SHIFT);
    let moved = trs(&harness.state().document().scene, 3).translate;
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
    let before = trs(&harness.state().document().scene, 2);
    let length = ARROW_POINTS * world_per_point(&harness, before.translate);
    // The x handle's square at the end of the arrow, dragged to 1.5 times as far out.
    let from = screen(&harness, before.translate + DVec3::X * length);
    let to = screen(&harness, before.translate + DVec3::X * length * 1.5);
    drag(&mut harness, from, to, Modifiers::NONE);
    let after = trs(&harness.state().document().scene, 2);
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
    assert_eq!(&harness.state().document().selection, &Selection::Light(3));
    let before = harness.state().document().scene.clone();
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
    } = harness.state().document().scene.lights[3]
    else {
        panic!("still a spotlight");
    };
    assert!((after - 35.0).abs() < 0.05, "{after}");
    assert_eq!((p, d), (position, direction), "only the angle changes");
    undo(&mut harness);
    assert_eq!(&harness.state().document().scene, &before);
}

#[test]
fn dragging_the_tip_handle_re_aims_the_spotlight() {
    let mut harness = harness();
    select(&mut harness, "Spot light 4");
    let scene = harness.state().document().scene.clone();
    let Light::Spot {
        position,
        direction,
        ..
    } = scene.lights[3]
    else {
        panic!("light 4 is the spotlight");
    };
    let length = (scene.camera.position - scene.camera.look_at).length() * 0.3;
    // Grab the tip and let go over a point of the plane through it that faces the eye,
    // well off the sphere the tip sits on between drags: the light aims through it.
    let start_tip = position + direction.normalize() * length;
    let (u, v) = (scene.camera.position - start_tip)
        .normalize()
        .any_orthonormal_pair();
    let target = start_tip + length * (1.5 * u - 0.8 * v);
    let wanted = (target - position).normalize();
    let from = screen(&harness, start_tip);
    let to = screen(&harness, target);
    drag(&mut harness, from, to, Modifiers::NONE);
    let Light::Spot { direction: now, .. } = harness.state().document().scene.lights[3] else {
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
    assert_eq!(&harness.state().document().selection, &Selection::Camera);
    let Light::Point { position, .. } = harness.state().document().scene.lights[1] else {
        panic!("light 2 is a point light");
    };
    let pos = screen(&harness, position);
    click_at(&mut harness, pos);
    assert_eq!(&harness.state().document().selection, &Selection::Light(1));
}

#[test]
fn an_arrow_that_runs_past_the_pictures_top_edge_is_drawn_and_grabbed_in_the_margin() {
    let mut harness = harness();
    select(&mut harness, "red ball");
    // Put the ball 6 pixels below the picture's top edge, at the camera's own distance:
    // its y arrow (84 points long) runs up into the margin above the picture.
    let shown = harness.state().shown_camera();
    let camera = raylab::trace::PinholeCamera::new(&shown, shown.width, shown.height);
    let ray = camera.ray(glam::DVec2::new(f64::from(shown.width) * 0.5, 6.0));
    let distance = (shown.look_at - shown.position).length();
    let place = ray.origin + ray.dir.normalize() * distance;
    for (axis, value) in ["x", "y", "z"].iter().zip(place.to_array()) {
        harness
            .get_by_label(&format!("translate {axis}"))
            .set_value_accesskit(value);
        harness.run();
    }
    let origin = trs(&harness.state().document().scene, 1).translate;
    let length = ARROW_POINTS * world_per_point(&harness, origin);
    let grab = screen(&harness, origin + DVec3::Y * length * 0.8);
    let top = picture(&harness).min.y;
    assert!(
        grab.y < top - 20.0,
        "the grab point {grab:?} is above the picture ({top})"
    );
    drag(
        &mut harness,
        grab,
        grab + egui::vec2(0.0, 30.0),
        Modifiers::NONE,
    );
    let moved = trs(&harness.state().document().scene, 1).translate;
    assert!(
        moved.y < origin.y - 1e-3,
        "dragged down from the margin: {moved} from {origin}"
    );
    assert_eq!((moved.x, moved.z), (origin.x, origin.z), "only y changes");
}
