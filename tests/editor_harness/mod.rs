//! The editor under egui_kittest, shared by the UI tests: building a harness, clicking at
//! a screen point, a fresh folder per test.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

use egui::{Event, Modifiers, PointerButton, Pos2, Vec2};
use egui_kittest::Harness;
use raylab::ui::recent::RecentFiles;
use raylab::ui::{EditorApp, EditorOptions};

/// The editor in a `size` window, run until it settles (at most `max_steps` steps a run).
pub fn editor_harness(
    options: EditorOptions,
    size: Vec2,
    max_steps: u64,
) -> Harness<'static, EditorApp> {
    let app = EditorApp::new(options, RecentFiles::default());
    let mut harness = Harness::builder()
        .with_size(size)
        .with_max_steps(max_steps)
        .build_ui_state(|ui, app: &mut EditorApp| app.editor_ui(ui), app);
    harness.run();
    harness
}

/// A primary click (press and release) at `pos`.
pub fn click_at(harness: &mut Harness<'_, EditorApp>, pos: Pos2) {
    harness.event(Event::PointerMoved(pos));
    for pressed in [true, false] {
        harness.event(Event::PointerButton {
            pos,
            button: PointerButton::Primary,
            pressed,
            modifiers: Modifiers::NONE,
        });
    }
    harness.run_ok();
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
