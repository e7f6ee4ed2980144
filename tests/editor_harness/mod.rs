//! The editor under egui_kittest, shared by the UI tests: building a harness, clicking at
//! a screen point, waiting for background work, a fresh folder per test.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use egui::{Event, Modifiers, PointerButton, Pos2, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use raylab::ui::recent::RecentFiles;
use raylab::ui::{EditorApp, EditorOptions, Selection};

/// The editor with `options` in a 1280x800 window.
pub fn harness_with(options: EditorOptions) -> Harness<'static, EditorApp> {
    editor_harness(options, Vec2::new(1280.0, 800.0), 64)
}

/// The editor with `options` in a 1280x800 window, without kittest's check that every
/// widget has an accessible name: egui_file's path and file name fields have none, and
/// they are that crate's widgets, not ours.
pub fn harness_with_file_dialog(options: EditorOptions) -> Harness<'static, EditorApp> {
    build(options, Vec2::new(1280.0, 800.0), 64, false)
}

/// The editor on the default scene in a 1280x800 window, preview off.
pub fn harness() -> Harness<'static, EditorApp> {
    harness_with(EditorOptions::default())
}

/// An editor with `scenes/NAME` open.
pub fn harness_on_example(name: &str) -> Harness<'static, EditorApp> {
    let mut harness = harness();
    open_example(&mut harness, name);
    harness
}

/// Opens `scenes/NAME` in the editor.
pub fn open_example(harness: &mut Harness<'_, EditorApp>, name: &str) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name);
    harness.state_mut().push(raylab::ui::Command::Open(path));
    harness.run();
}

/// Clicks the default scene's "red ball" in the outliner.
pub fn select_red_ball(harness: &mut Harness<'_, EditorApp>) {
    harness.get_by_label("red ball").click();
    harness.run();
    assert_eq!(&harness.state().document().selection, &Selection::Object(1));
}

/// Steps the harness until `done` holds, sleeping between steps (bounded).
pub fn step_until(
    harness: &mut Harness<'_, EditorApp>,
    what: &str,
    done: impl Fn(&EditorApp) -> bool,
) {
    let deadline = Instant::now() + Duration::from_secs(120);
    while !done(harness.state()) {
        assert!(Instant::now() < deadline, "timed out waiting for {what}");
        std::thread::sleep(Duration::from_millis(20));
        harness.step();
    }
    harness.run_ok();
}

/// The editor in a `size` window, run until it settles (at most `max_steps` steps a run).
pub fn editor_harness(
    options: EditorOptions,
    size: Vec2,
    max_steps: u64,
) -> Harness<'static, EditorApp> {
    build(options, size, max_steps, true)
}

fn build(
    options: EditorOptions,
    size: Vec2,
    max_steps: u64,
    accessibility_check: bool,
) -> Harness<'static, EditorApp> {
    let app = EditorApp::new(options, RecentFiles::default());
    let mut harness = Harness::builder()
        .with_size(size)
        .with_max_steps(max_steps)
        .with_accessibility_check(accessibility_check)
        .build_ui_state(|ui, app: &mut EditorApp| app.editor_ui(ui), app);
    harness.run();
    harness
}

/// A primary click (press and release) at `pos`.
pub fn click_at(harness: &mut Harness<'_, EditorApp>, pos: Pos2) {
    click_with(harness, pos, Modifiers::NONE);
}

/// A primary click at `pos` with `modifiers` held (and released after).
pub fn click_with(harness: &mut Harness<'_, EditorApp>, pos: Pos2, modifiers: Modifiers) {
    harness.event(Event::ModifiersChanged(modifiers));
    harness.event(Event::PointerMoved(pos));
    for pressed in [true, false] {
        harness.event(Event::PointerButton {
            pos,
            button: PointerButton::Primary,
            pressed,
            modifiers,
        });
    }
    harness.run_ok();
    if modifiers != Modifiers::NONE {
        harness.event(Event::ModifiersChanged(Modifiers::NONE));
        harness.run_ok();
    }
}

/// Waits until the final frame of the newest preview request is on screen.
pub fn wait_for_final(harness: &mut Harness<'_, EditorApp>) {
    step_until(harness, "the final frame", |app| {
        app.preview().is_some_and(|p| {
            p.shown()
                .is_some_and(|s| s.is_final && s.generation == p.generation())
        })
    });
}

/// Asks the window to close, as the window manager's close button does.
pub fn close_window(harness: &mut Harness<'_, EditorApp>) {
    harness
        .input_mut()
        .viewports
        .entry(egui::ViewportId::ROOT)
        .or_default()
        .events
        .push(egui::ViewportEvent::Close);
    harness.run();
}

/// A fresh folder under the system's temporary folder.
pub fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raylab-ui-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A file dropped on the window, as the native integration hands it over.
#[derive(Debug)]
struct DroppedPath(PathBuf);

impl egui::DroppedFile for DroppedPath {
    fn path(&self) -> &Path {
        &self.0
    }
    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

/// Drops the file at `path` on the window and runs the frames that follow.
pub fn drop_file(harness: &mut Harness<'_, EditorApp>, path: &Path) {
    harness
        .input_mut()
        .dropped_files
        .push(std::sync::Arc::new(DroppedPath(path.to_owned())));
    harness.run();
}

/// A `button` drag from `from` to `to` in `steps` small moves with `modifiers` held, as a
/// hand would; the caller runs the frames that follow.
pub fn press_drag_release(
    harness: &mut Harness<'_, EditorApp>,
    button: PointerButton,
    (from, to): (Pos2, Pos2),
    modifiers: Modifiers,
    steps: u32,
) {
    harness.event(Event::ModifiersChanged(modifiers));
    harness.event(Event::PointerMoved(from));
    harness.event(Event::PointerButton {
        pos: from,
        button,
        pressed: true,
        modifiers,
    });
    harness.step();
    for i in 1..=steps {
        harness.event(Event::PointerMoved(
            from + (to - from) * (i as f32 / steps as f32),
        ));
        harness.step();
    }
    harness.event(Event::PointerButton {
        pos: to,
        button,
        pressed: false,
        modifiers,
    });
    harness.event(Event::ModifiersChanged(Modifiers::NONE));
}
