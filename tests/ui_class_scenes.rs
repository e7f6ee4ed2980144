//! Going through a class's course scenes: an untouched import is no unsaved change, the
//! window title names the file it came from, and File > Open Next / Previous in Folder
//! (Page Down / Page Up) step through the folder's scenes with no question asked.

mod editor_harness;

use std::path::{Path, PathBuf};

use editor_harness::{harness, temp_dir};
use egui::Key;
use egui_kittest::kittest::Queryable;
use raylab::ui::{Command, SceneEdit};

/// A folder with two course scenes and a RON scene, by name: a.txt, b.txt, c.ron.
fn class_folder() -> PathBuf {
    let dir = temp_dir("class-scenes");
    let legacy = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/legacy");
    std::fs::copy(legacy.join("lit_sphere.txt"), dir.join("a.txt")).unwrap();
    std::fs::copy(legacy.join("mirror.txt"), dir.join("b.txt")).unwrap();
    let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    std::fs::copy(scenes.join("shapes.ron"), dir.join("c.ron")).unwrap();
    dir
}

#[test]
fn an_untouched_import_is_no_change_and_the_title_names_its_file() {
    let dir = class_folder();
    let mut harness = harness();
    harness.state_mut().push(Command::Open(dir.join("a.txt")));
    harness.run();
    assert!(!harness.state().document().is_dirty(), "nothing was edited");
    assert_eq!(harness.state().title(), "a.txt (imported) — raylab");
    // Opening another asks nothing.
    harness.state_mut().push(Command::Open(dir.join("c.ron")));
    harness.run();
    assert!(harness.state().pending_discard().is_none());
    assert_eq!(harness.state().path(), Some(dir.join("c.ron").as_path()));
    // Import Legacy gives the same.
    harness
        .state_mut()
        .push(Command::ImportLegacy(dir.join("b.txt")));
    harness.run();
    assert!(!harness.state().document().is_dirty());
    assert_eq!(harness.state().title(), "b.txt (imported) — raylab");
    // An edit is a change, marked and asked about.
    harness
        .state_mut()
        .push(Command::Edit(SceneEdit::AddMaterial));
    harness.run();
    assert_eq!(harness.state().title(), "b.txt (imported)* — raylab");
    harness.state_mut().push(Command::Open(dir.join("a.txt")));
    harness.run();
    assert!(
        harness.state().pending_discard().is_some(),
        "the edit is asked about"
    );
}

#[test]
fn page_down_and_page_up_step_through_the_folder_with_no_question() {
    let dir = class_folder();
    let mut harness = harness();
    harness.state_mut().push(Command::Open(dir.join("a.txt")));
    harness.run();
    harness.key_press(Key::PageDown);
    harness.run();
    assert!(harness.state().pending_discard().is_none(), "no question");
    assert_eq!(harness.state().title(), "b.txt (imported) — raylab");
    harness.key_press(Key::PageDown);
    harness.run();
    assert_eq!(harness.state().path(), Some(dir.join("c.ron").as_path()));
    harness.key_press(Key::PageDown);
    harness.run();
    assert_eq!(
        harness.state().path(),
        Some(dir.join("c.ron").as_path()),
        "the last one stays"
    );
    harness.get_by_label_contains("is the last scene in its folder");
    harness.key_press(Key::PageUp);
    harness.run();
    assert_eq!(harness.state().title(), "b.txt (imported) — raylab");

    // The same from the File menu.
    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label("Open Previous in Folder").click();
    harness.run();
    assert_eq!(harness.state().title(), "a.txt (imported) — raylab");
    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label("Open Next in Folder").click();
    harness.run();
    assert_eq!(harness.state().title(), "b.txt (imported) — raylab");
}
