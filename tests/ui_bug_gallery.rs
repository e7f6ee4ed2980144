//! File > Bug gallery under egui_kittest: the gallery of the open scene renders in the
//! background, its thumbnails are found by their bugs' labels, clicking one compares the
//! scene with that picture (the diff names the bug), and an edit marks the gallery stale
//! until Refresh renders it again.

mod editor_harness;

use std::path::PathBuf;

use egui::Vec2;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use raylab::compare::plant::{gallery_scene, parse_bugs};
use raylab::ui::bug_gallery::{OWN_PICTURE_LABEL, thumbnail_label};
use raylab::ui::compare::{OtherSource, explanation_label};
use raylab::ui::{Command, EditorApp, EditorOptions, SceneEdit};

use editor_harness::{editor_harness, step_until};

const LAB: &str = "tests/compare/lab.ron";

fn harness() -> Harness<'static, EditorApp> {
    editor_harness(
        EditorOptions {
            scene: Some(PathBuf::from(LAB)),
            ..EditorOptions::default()
        },
        Vec2::new(1280.0, 860.0),
        64,
    )
}

/// File > Bug gallery…, then waits for the gallery.
fn open_gallery(harness: &mut Harness<'_, EditorApp>) {
    harness.get_by_label("File").click();
    harness.run();
    harness.get_by_label("Bug gallery…").click();
    // The spinner repaints while the gallery renders: step, not run.
    harness.step();
    step_until(harness, "the bug gallery", |app| {
        !app.tools().bug_gallery.is_running()
    });
    assert_eq!(harness.state().tools().bug_gallery.error(), None);
}

#[test]
fn clicking_a_gallery_picture_compares_the_scene_with_it_and_the_diff_names_its_bug() {
    let mut harness = harness();
    open_gallery(&mut harness);
    let labels: Vec<String> = harness
        .state()
        .tools()
        .bug_gallery
        .thumbnails()
        .iter()
        .map(|t| t.label.clone())
        .collect();
    assert_eq!(labels[0], "raylab (no bug)");
    assert!(labels.contains(&"shadows=0".to_owned()), "{labels:?}");
    // Every picture is there to find by its bug, raylab's own first.
    harness.get_by_label(OWN_PICTURE_LABEL);
    for label in &labels {
        harness.get_by_label(&thumbnail_label(label));
    }

    // It is further down than the window shows: scrolled to, then clicked.
    harness
        .get_by_label(&thumbnail_label("shadows=0"))
        .scroll_to_me();
    harness.run();
    harness.get_by_label(&thumbnail_label("shadows=0")).click();
    harness.run();
    step_until(&mut harness, "the comparison", |app| {
        !app.tools().compare.is_running()
    });
    let app = harness.state();
    assert_eq!(app.tools().compare.error(), None);
    let compared = app
        .tools()
        .compare
        .compared()
        .expect("the comparison is shown");
    assert_eq!(
        compared.source,
        OtherSource::Planted("shadows=0".to_owned())
    );
    let scaled = gallery_scene(app.document().scene.clone(), None);
    let planted = parse_bugs("shadows=0", &scaled).unwrap();
    let top = compared
        .comparison
        .explanations
        .first()
        .expect("an explanation")
        .clone();
    assert!(
        planted[0].is_named_by(&top),
        "the top explanation does not name the planted bug: {top:?}"
    );
    // The explanation is in the view, where a student reads it.
    let scene = app.document().scene.clone();
    harness.get_by_label(&explanation_label(0, &top, &scene));
    harness.get_by_label_contains("bug gallery: shadows=0");
}

#[test]
fn an_edit_marks_the_gallery_stale_until_refresh_renders_it_again() {
    let mut harness = harness();
    open_gallery(&mut harness);
    let before = harness.state().tools().bug_gallery.thumbnails()[0]
        .picture
        .clone();
    assert!(
        !harness
            .get_by_label(OWN_PICTURE_LABEL)
            .accesskit_node()
            .is_disabled()
    );

    let mut camera = harness.state().document().scene.camera.clone();
    camera.fov_deg += 10.0;
    harness
        .state_mut()
        .push(Command::Edit(SceneEdit::SetCamera(camera)));
    harness.run();
    // The pictures of the older scene cannot be compared, and say so.
    assert!(
        harness
            .state()
            .tools()
            .bug_gallery
            .is_stale(&harness.state().document().scene)
    );
    assert!(
        harness
            .get_by_label(OWN_PICTURE_LABEL)
            .accesskit_node()
            .is_disabled()
    );
    harness.get_by_label_contains("The scene has changed since");

    harness.get_by_label("Refresh").click();
    harness.step();
    step_until(&mut harness, "the refreshed gallery", |app| {
        !app.tools().bug_gallery.is_running()
    });
    let app = harness.state();
    assert!(!app.tools().bug_gallery.is_stale(&app.document().scene));
    assert_ne!(app.tools().bug_gallery.thumbnails()[0].picture, before);
    assert!(
        !harness
            .get_by_label(OWN_PICTURE_LABEL)
            .accesskit_node()
            .is_disabled()
    );
}
