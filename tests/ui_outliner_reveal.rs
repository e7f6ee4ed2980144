//! A selection made outside the outliner (a pick in the viewport, which sends the same
//! select command) scrolls the outliner to the picked row.

mod editor_harness;

use editor_harness::harness;
use egui_kittest::kittest::Queryable;
use raylab::scene::Shape;
use raylab::ui::{Command, SceneEdit, Selection};

#[test]
fn a_pick_scrolls_the_outliner_to_the_picked_row() {
    let mut harness = harness();
    for _ in 0..60 {
        harness
            .state_mut()
            .push(Command::Edit(SceneEdit::AddObject(Shape::Sphere)));
    }
    harness.run();
    // Back at the top of the list (the new objects scrolled it down).
    harness.state_mut().push(Command::Select(Selection::Camera));
    harness.run();
    let last = harness.state().document().scene.objects.len() - 1;
    let name = harness.state().document().scene.objects[last].name.clone();
    let window = harness.ctx.content_rect();
    // The outliner's row (the inspector, on the right, may name the object too).
    let row_rect = |harness: &egui_kittest::Harness<'_, raylab::ui::EditorApp>| {
        harness
            .query_all_by_label(&name)
            .map(|node| node.rect())
            .min_by(|a, b| a.min.x.total_cmp(&b.min.x))
            .expect("the row")
    };
    assert!(
        !window.contains_rect(row_rect(&harness)),
        "the row starts out of view"
    );
    harness
        .state_mut()
        .push(Command::Select(Selection::Object(last)));
    harness.run();
    let row = row_rect(&harness);
    assert!(
        window.contains_rect(row),
        "{name} at {row:?}, window {window:?}"
    );
}
