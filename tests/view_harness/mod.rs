//! Helpers for the view camera, ray-path and pixel inspector UI tests: the editor on a
//! small default scene saved to a file, waiting for the probes, projecting through the
//! camera the viewport shows, and drags.
#![allow(dead_code)]

#[path = "../editor_harness/mod.rs"]
pub mod editor_harness;

pub use editor_harness::step_until;

use std::path::PathBuf;

use egui::{Modifiers, PointerButton, Pos2, Rect, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use glam::DVec3;
use raylab::scene::{Scene, save_scene};
use raylab::trace::PinholeCamera;
use raylab::ui::files::default_scene;
use raylab::ui::gizmo::projection::ViewMapping;
use raylab::ui::recent::RecentFiles;
use raylab::ui::viewport::ray_paths::{ScreenSegment, screen_segments};
use raylab::ui::{EditorApp, EditorOptions, VIEWPORT_LABEL, ViewMemory};

/// The default scene, small: 160 x 120 at 4 samples a pixel.
pub fn small_scene() -> Scene {
    let mut scene = default_scene();
    scene.camera.width = 160;
    scene.camera.height = 120;
    scene.render.samples_per_pixel = 4;
    scene
}

/// `small_scene` saved in a fresh folder named after the test.
pub fn scene_file(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raylab-view-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("small.ron");
    save_scene(&small_scene(), &path).unwrap();
    path
}

/// The editor on `path`, with views remembered as `memory`, the preview on or off.
pub fn harness_on(path: PathBuf, preview: bool, memory: ViewMemory) -> Harness<'static, EditorApp> {
    let options = EditorOptions {
        scene: Some(path),
        preview,
        ..EditorOptions::default()
    };
    let app = EditorApp::new(options, RecentFiles::default()).with_view_memory(memory);
    let mut harness = Harness::builder()
        .with_size(Vec2::new(1280.0, 800.0))
        .with_max_steps(200)
        .build_ui_state(|ui, app: &mut EditorApp| app.editor_ui(ui), app);
    harness.run_ok();
    harness
}

/// The editor on a fresh copy of `small_scene`.
pub fn harness(name: &str, preview: bool) -> Harness<'static, EditorApp> {
    harness_on(scene_file(name), preview, ViewMemory::default())
}

/// Waits until picks and inspections are answered.
pub fn wait_for_probes(harness: &mut Harness<'_, EditorApp>) {
    step_until(harness, "the probes", |app| !app.is_probing());
}

/// The picture on screen.
pub fn picture(harness: &Harness<'_, EditorApp>) -> Rect {
    harness.get_by_label(VIEWPORT_LABEL).rect()
}

/// The mapping the viewport draws with.
pub fn view(harness: &Harness<'_, EditorApp>) -> ViewMapping {
    ViewMapping::new(&harness.state().shown_camera(), picture(harness))
}

/// Where a world point is on screen, through the camera the viewport shows.
pub fn screen(harness: &Harness<'_, EditorApp>, p_world: DVec3) -> Pos2 {
    view(harness)
        .project(p_world)
        .expect("in front of the camera")
}

/// Where scene object `index`'s origin is on screen.
pub fn object_on_screen(harness: &Harness<'_, EditorApp>, index: usize) -> Pos2 {
    let origin = harness.state().document().scene.objects[index]
        .transform
        .world_from_object()
        .translation;
    screen(harness, origin)
}

/// The scene camera's pixel that sees world point `p`.
pub fn scene_pixel(harness: &Harness<'_, EditorApp>, p: DVec3) -> (u32, u32) {
    let camera = &harness.state().document().scene.camera;
    let q = PinholeCamera::new(camera, camera.width, camera.height)
        .project(p)
        .unwrap();
    (q.x.floor() as u32, q.y.floor() as u32)
}

/// The ray-path segments as the viewport draws them now.
pub fn segments(harness: &Harness<'_, EditorApp>) -> Vec<ScreenSegment> {
    let app = harness.state();
    screen_segments(
        &view(harness),
        &app.document().scene,
        app.inspections(),
        &app.view().looking.ray_paths,
        app.view().looking.inspected,
    )
}

/// A primary click at `pos` with `modifiers`, then waits for the probes.
pub fn click(harness: &mut Harness<'_, EditorApp>, pos: Pos2, modifiers: Modifiers) {
    editor_harness::click_with(harness, pos, modifiers);
    wait_for_probes(harness);
}

/// A primary-button drag from `from` to `to` in small steps, as a hand would.
pub fn drag(harness: &mut Harness<'_, EditorApp>, from: Pos2, to: Pos2, modifiers: Modifiers) {
    editor_harness::press_drag_release(harness, PointerButton::Primary, (from, to), modifiers, 10);
    harness.run_ok();
}

/// Orbits the view by dragging across the sky near the picture's top.
pub fn orbit(harness: &mut Harness<'_, EditorApp>, by: Vec2) {
    let from = picture(harness).center_top() + Vec2::new(-150.0, 30.0);
    drag(harness, from, from + by, Modifiers::NONE);
}

/// Clicks a widget by its label, then settles.
pub fn press(harness: &mut Harness<'_, EditorApp>, label: &str) {
    harness.get_by_label(label).click();
    harness.run_ok();
    wait_for_probes(harness);
}

/// Clicks a toggle button by its label (some labels are also plain text elsewhere).
pub fn toggle(harness: &mut Harness<'_, EditorApp>, label: &str) {
    harness
        .get_by_role_and_label(egui::Role::Button, label)
        .click();
    harness.run_ok();
    wait_for_probes(harness);
}

/// Drags the pixel inspector window by its title to the screen's bottom-right corner,
/// over the side panel, clear of the ray-path controls along the picture's bottom-left
/// (a window over them would take their clicks).
pub fn move_inspector_away(harness: &mut Harness<'_, EditorApp>) {
    // The window's node spans the whole window: its title bar is along the top.
    let window = harness.get_by_label("Pixel inspector").rect();
    let title = window.center_top() + Vec2::new(0.0, 12.0);
    let screen = harness.ctx.content_rect();
    let to = Pos2::new(screen.max.x - window.width() / 2.0, screen.max.y - 10.0);
    drag(harness, title, to, Modifiers::NONE);
    let window = harness.get_by_label("Pixel inspector").rect();
    for control in ["primary rays", "shadow rays", "reflection rays", "normals"] {
        let button = harness
            .get_by_role_and_label(egui::Role::Button, control)
            .rect();
        assert!(
            !window.intersects(button),
            "the inspector {window:?} still covers {control:?} at {button:?}"
        );
    }
}
