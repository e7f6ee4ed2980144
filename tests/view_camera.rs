//! The view camera, through egui_kittest: looking around never edits the scene and the
//! viewport renders the view at its own size; camera view shows the scene camera and its
//! final frame equals `raylab render`; "set scene camera from view" is one undo step;
//! the scene camera's frustum is selectable and movable; the view is remembered per file.

mod view_harness;

use egui::{Key, Modifiers, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use glam::DVec3;
use raylab::preview::Pass;
use raylab::trace::{RenderOptions, RenderProgress, World, render};
use raylab::ui::state::free_render_size;
use raylab::ui::{CAMERA_VIEW_LABEL, EditorApp, Selection, ViewMemory};
use view_harness::editor_harness::wait_for_final;
use view_harness::{click, drag, harness, harness_on, orbit, picture, scene_file, screen, view};

fn undo(harness: &mut Harness<'_, EditorApp>) {
    harness.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    harness.run_ok();
}

#[test]
fn orbiting_leaves_the_scene_unmodified_and_renders_the_view_at_the_viewport_size() {
    let mut harness = harness("orbit", true);
    let before = harness.state().document().scene.clone();
    assert!(
        harness.state().view().looking.camera.through_scene_camera,
        "files open in camera view"
    );
    orbit(&mut harness, Vec2::new(120.0, 20.0));
    let app = harness.state();
    assert!(!app.view().looking.camera.through_scene_camera);
    assert_ne!(app.view().looking.camera.position, before.camera.position);
    assert_eq!(
        &app.document().scene,
        &before,
        "the scene camera did not move"
    );
    assert!(
        !app.document().is_dirty() && !app.title().contains('*'),
        "{}",
        app.title()
    );

    // The preview renders the view camera at the viewport's size, not the scene's.
    let options = app.preview().unwrap().submitted_options().unwrap();
    let shown = app.shown_camera();
    assert_eq!((options.width, options.height), (shown.width, shown.height));
    let area = picture(&harness);
    let expected = free_render_size(area.width(), area.height(), 1.0);
    let (dw, dh) = (
        options.width.abs_diff(expected.0),
        options.height.abs_diff(expected.1),
    );
    assert!(dw <= 1 && dh <= 1, "{options:?} for a picture of {area:?}");
    assert_ne!(
        (options.width, options.height),
        (before.camera.width, before.camera.height)
    );

    undo(&mut harness);
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "nothing to undo"
    );
    assert!(
        !harness.state().view().looking.camera.through_scene_camera,
        "the view stays"
    );
}

#[test]
fn camera_view_shows_the_scene_camera_and_its_final_frame_equals_render() {
    let mut harness = harness("camera-view", true);
    orbit(&mut harness, Vec2::new(-90.0, 10.0));
    harness.key_press(Key::Num0);
    harness.run_ok();
    assert!(harness.state().view().looking.camera.through_scene_camera);
    let scene = harness.state().document().scene.clone();
    assert_eq!(harness.state().shown_camera(), scene.camera);
    wait_for_final(&mut harness);
    let frame = harness.state().preview().unwrap().frame().unwrap();
    assert_eq!(
        frame.pass,
        Pass::Full {
            samples: 4,
            target: 4
        }
    );
    let world = World::new(&scene).unwrap();
    let (image, _) = render(
        &world,
        &RenderOptions::from_scene(&scene),
        &RenderProgress::default(),
    )
    .unwrap();
    assert!(
        frame.image.pixels == image.pixels,
        "the preview differs from raylab render"
    );

    // The button goes back to the view camera where it was.
    harness.get_by_label(CAMERA_VIEW_LABEL).click();
    harness.run_ok();
    assert!(!harness.state().view().looking.camera.through_scene_camera);
}

#[test]
fn setting_the_scene_camera_from_the_view_is_one_undo_step() {
    let mut harness = harness("set-camera", false);
    let before = harness.state().document().scene.clone();
    orbit(&mut harness, Vec2::new(100.0, -15.0));
    let view = harness.state().view().looking.camera.clone();
    harness.key_press_modifiers(Modifiers::COMMAND | Modifiers::ALT, Key::Num0);
    harness.run_ok();
    let camera = harness.state().document().scene.camera.clone();
    assert_eq!(
        (camera.position, camera.look_at),
        (view.position, view.look_at)
    );
    assert_eq!(
        (camera.width, camera.height),
        (before.camera.width, before.camera.height)
    );
    assert!(harness.state().document().is_dirty());
    assert!(
        harness.state().view().looking.camera.through_scene_camera,
        "looking through it now"
    );
    undo(&mut harness);
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "one undo restores the camera"
    );
}

#[test]
fn the_scene_camera_is_drawn_from_the_view_selectable_and_movable() {
    let mut harness = harness("frustum", false);
    let before = harness.state().document().scene.clone();
    // Step back and to the side so the scene camera is in view.
    orbit(&mut harness, Vec2::new(210.0, 20.0));
    let centre = picture(&harness).center();
    for _ in 0..10 {
        harness.event(egui::Event::MouseWheel {
            unit: egui::MouseWheelUnit::Line,
            delta: Vec2::new(0.0, -1.0),
            phase: egui::TouchPhase::Move,
            source: egui::MouseWheelSource::Wheel,
            modifiers: Modifiers::NONE,
        });
        harness.event(egui::Event::PointerMoved(centre));
        harness.step();
    }
    harness.run_ok();
    let eye = before.camera.position;
    assert!(
        picture(&harness).contains(screen(&harness, eye)),
        "the eye is in view"
    );
    let at = screen(&harness, eye);
    click(&mut harness, at, Modifiers::NONE);
    assert_eq!(&harness.state().document().selection, &Selection::Camera);

    // The move gizmo at the eye: drag the x arrow by one world unit.
    let length = 84.0 * view(&harness).world_per_point(eye);
    let grab = eye + DVec3::X * length * 0.7;
    let (from, to) = (screen(&harness, grab), screen(&harness, grab + DVec3::X));
    drag(&mut harness, from, to, Modifiers::NONE);
    let moved = harness.state().document().scene.camera.clone();
    assert!(
        (moved.position - (eye + DVec3::X)).length() < 5e-3,
        "{}",
        moved.position
    );
    assert!(
        ((moved.look_at - before.camera.look_at) - (moved.position - eye)).length() < 1e-9,
        "the camera keeps its aim"
    );
    undo(&mut harness);
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "one undo for the drag"
    );
}

#[test]
fn the_view_is_remembered_per_file() {
    let path = scene_file("memory");
    let mut harness = harness_on(path.clone(), false, ViewMemory::default());
    orbit(&mut harness, Vec2::new(60.0, 25.0));
    let view = harness.state().view().looking.camera.clone();
    let memory = harness.state().view_memory();
    assert_eq!(memory.get(&path), Some(&view));
    let reopened = harness_on(path, false, memory.clone());
    assert_eq!(
        &reopened.state().view().looking.camera,
        &view,
        "the same file, the same view"
    );
    let other = harness_on(scene_file("memory-other"), false, memory);
    assert!(
        other.state().view().looking.camera.through_scene_camera,
        "another file: camera view"
    );
    // Nothing of the view is in the scene file.
    assert_eq!(
        &reopened.state().document().scene,
        &other.state().document().scene
    );
}

#[test]
fn leaving_camera_view_starts_from_where_the_scene_camera_is_now() {
    let mut harness = harness("leave_camera_view", false);
    // The scene camera moves (an edit) while camera view is on...
    let mut camera = harness.state().document().scene.camera.clone();
    camera.position += glam::DVec3::new(2.0, 1.0, -1.5);
    harness
        .state_mut()
        .push(raylab::ui::Command::Edit(raylab::ui::SceneEdit::SetCamera(
            camera.clone(),
        )));
    harness.run();
    // ... then the user leaves camera view: the free view starts there.
    harness
        .state_mut()
        .push(raylab::ui::Command::ToggleCameraView);
    harness.run();
    let view = &harness.state().view().looking.camera;
    assert!(!view.through_scene_camera);
    assert_eq!(
        (view.position, view.look_at, view.fov_deg),
        (camera.position, camera.look_at, camera.fov_deg)
    );
}
