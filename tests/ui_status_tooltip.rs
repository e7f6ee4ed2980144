//! A status-bar message too long for the bar shows its whole text in one tooltip, not two.

mod editor_harness;

use editor_harness::editor_harness;
use egui::Vec2;
use egui_kittest::kittest::Queryable;
use raylab::ui::{Command, EditorOptions};

#[test]
fn a_cut_short_status_message_has_one_tooltip() {
    let mut harness = editor_harness(EditorOptions::default(), Vec2::new(900.0, 700.0), 64);
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/legacy/full.txt");
    harness.state_mut().push(Command::ImportLegacy(path));
    harness.run();
    harness.get_by_label_contains("(not saved yet)").hover();
    for _ in 0..60 {
        harness.step();
    }
    harness.run();
    let shown = harness
        .query_all_by_label_contains("(not saved yet)")
        .count();
    assert_eq!(shown, 2, "the message and one tooltip with its whole text");
}
