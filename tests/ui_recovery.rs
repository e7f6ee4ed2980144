//! Crash recovery through the editor, with no window: unsaved work of an editor that
//! died is offered and restored, edits reach the recovery file, and an autosave that
//! fails says so.

mod editor_harness;

use editor_harness::{harness_with, temp_dir};
use egui::Key;
use egui_kittest::kittest::Queryable;
use raylab::ui::files::default_scene;
use raylab::ui::{Command, EditorOptions};

#[test]
fn unsaved_work_of_a_killed_editor_is_offered_and_restored() {
    use raylab::recovery::RecoveryStore;
    let dir = temp_dir("recovery");
    // An editor that died left its unsaved scene; its lock went with it.
    let mut lost = default_scene();
    lost.objects[0].name = "edited before the crash".to_owned();
    RecoveryStore::new(dir.clone()).save(&lost, None).unwrap();
    let mut harness = harness_with(EditorOptions {
        recovery: Some(RecoveryStore::new(dir.clone())),
        ..EditorOptions::default()
    });
    assert!(harness.state().has_restore_offer());
    harness.get_by_label("Restore").click();
    harness.run();
    assert!(!harness.state().has_restore_offer());
    assert_eq!(&harness.state().document().scene, &lost);
    assert!(
        harness.state().document().is_dirty(),
        "restored edits are unsaved"
    );
    // The offer was used up: a new editor in the same folder offers nothing.
    assert!(RecoveryStore::new(dir).orphans().is_empty());
}

#[test]
fn unsaved_edits_reach_the_recovery_file_and_leave_it_on_save() {
    use raylab::recovery::RecoveryStore;
    let dir = temp_dir("autosave");
    let store = RecoveryStore::new(dir.clone());
    let own = store.own_path();
    let mut harness = harness_with(EditorOptions {
        recovery: Some(store),
        ..EditorOptions::default()
    });
    assert!(!own.exists());
    harness.get_by_label("red ball").click();
    harness.run();
    harness.key_press(Key::Delete);
    harness.run();
    assert!(harness.state().document().is_dirty());
    assert!(own.exists(), "the unsaved edit was written at once");
    harness
        .state_mut()
        .push(Command::SaveAs(dir.join("saved.ron")));
    harness.run();
    harness.run();
    assert!(!harness.state().document().is_dirty());
    assert!(!own.exists(), "nothing left to recover after a save");
}

#[test]
fn an_autosave_that_fails_says_so_in_the_status_bar() {
    use raylab::recovery::RecoveryStore;
    let dir = temp_dir("autosave-fails");
    // The recovery folder cannot be made: a file stands where its parent should be.
    let blocker = dir.join("not a folder");
    std::fs::write(&blocker, "x").unwrap();
    let mut harness = harness_with(EditorOptions {
        recovery: Some(RecoveryStore::new(blocker.join("recovery"))),
        ..EditorOptions::default()
    });
    assert_eq!(harness.state().autosave_error(), None);
    harness.get_by_label("red ball").click();
    harness.run();
    harness.key_press(Key::Delete);
    harness.run();
    let error = harness
        .state()
        .autosave_error()
        .expect("the failure is kept");
    assert!(error.contains("autosave failed"), "{error}");
    harness.get_by_label_contains("autosave failed");
}
