//! The editor's layout as a person meets it: in an 800x500 window every toolbar control
//! is on screen between the side panels; a preview that is not the full picture says so;
//! a light marker under the gizmo mode buttons does not take their presses.

mod editor_harness;

use editor_harness::{editor_harness, harness, open_example, press_drag_release};
use egui::{Modifiers, PointerButton, Pos2, Rect, Vec2};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use glam::DVec2;
use raylab::scene::Light;
use raylab::trace::{PinholeCamera, Term, View};
use raylab::ui::{
    Command, EditorApp, EditorOptions, NOT_FULL_PICTURE, SceneEdit, Selection, VIEWPORT_LABEL,
};

/// Every control of the term toolbar and of the gizmo mode buttons.
const TOOLBAR_CONTROLS: [&str; 15] = [
    "ambient",
    "diffuse",
    "specular",
    "shadows",
    "reflection",
    "transmission",
    "solo",
    "view",
    "NaN guard",
    "Inspect",
    "Convergence",
    "Move",
    "Rotate",
    "Scale",
    "Frame",
];

#[test]
fn at_800_by_500_every_toolbar_control_is_on_screen_between_the_panels() {
    let size = Vec2::new(800.0, 500.0);
    let harness = editor_harness(EditorOptions::default(), size, 64);
    let left = harness.get_by_label("Camera").rect().max.x;
    let right = harness.get_by_label("INSPECTOR").rect().min.x;
    assert!(
        right - left > 300.0,
        "the side panels leave the viewport room"
    );
    let rects: Vec<(&str, Rect)> = TOOLBAR_CONTROLS
        .iter()
        .map(|label| (*label, harness.get_by_label(label).rect()))
        .collect();
    for (label, rect) in &rects {
        assert!(
            rect.min.x >= left && rect.max.x <= right && rect.max.y <= size.y,
            "{label} at {rect:?} is outside the viewport {left}..{right}"
        );
    }
    for (i, (a, ra)) in rects.iter().enumerate() {
        for (b, rb) in &rects[i + 1..] {
            assert!(!ra.intersects(*rb), "{a} {ra:?} overlaps {b} {rb:?}");
        }
    }
}

#[test]
fn at_the_default_window_size_the_toolbar_has_its_two_rows() {
    // 1280 x 800, the window `cargo run` opens: the six switches, solo and view on the
    // first row, the tools (the NaN guard among them) on the second.
    let harness = editor_harness(EditorOptions::default(), Vec2::new(1280.0, 800.0), 64);
    let row = |label: &str| harness.get_by_label(label).rect().center().y;
    for label in ["transmission", "solo", "view"] {
        assert_eq!(row(label), row("ambient"), "{label} on the first row");
    }
    for label in ["Convergence", "NaN guard"] {
        assert_eq!(row(label), row("Inspect"), "{label} on the second row");
    }
    assert!(row("Inspect") > row("ambient"));
}

#[test]
fn a_long_status_message_is_cut_short_and_never_runs_over_the_counts() {
    // An import's summary is long; in a 1000-point window it would cover the counts.
    let mut harness = editor_harness(EditorOptions::default(), Vec2::new(1000.0, 700.0), 64);
    let course = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/legacy/full.txt");
    harness.state_mut().push(Command::Open(course.into()));
    harness.run();
    harness.run();
    let message = harness
        .get_by_label_contains("read as the 2020 framework")
        .rect();
    let counts = harness.get_by_label("6 objects, 4 lights").rect();
    assert!(
        message.min.x > counts.max.x,
        "the message {message:?} runs over the counts {counts:?}"
    );
    assert!(message.max.x <= 1000.0, "{message:?} stays in the window");
}

#[test]
fn a_preview_that_is_not_the_full_picture_says_so_and_why() {
    let mut harness = harness();
    assert!(harness.query_by_label_contains(NOT_FULL_PICTURE).is_none());
    let mut settings = harness.state().view().preview_settings;
    settings.switches.set(Term::Diffuse, false);
    settings.view = View::Depth;
    harness
        .state_mut()
        .push(Command::SetPreviewSettings(settings));
    harness.run();
    let marker = harness.get_by_label_contains(NOT_FULL_PICTURE);
    // A label's text is its accessible value (kittest matches either).
    let node = marker.accesskit_node();
    let text = format!(
        "{} {}",
        node.label().unwrap_or_default(),
        node.value().unwrap_or_default()
    );
    assert!(
        text.contains("diffuse off") && text.contains("depth view"),
        "{text}"
    );
    let picture = harness.get_by_label(VIEWPORT_LABEL).rect();
    assert!(picture.contains_rect(marker.rect()), "over the picture");
}

/// Presses at `from`, moves to `to` in steps and releases, as a hand would.
fn drag(harness: &mut Harness<'_, EditorApp>, from: Pos2, to: Pos2) {
    press_drag_release(
        harness,
        PointerButton::Primary,
        (from, to),
        Modifiers::NONE,
        8,
    );
    harness.run();
}

/// Moves the default scene's point light to where the picture shows it at `screen`
/// (6 units along the camera ray there); returns its index and the light placed.
fn put_point_light_at(harness: &mut Harness<'_, EditorApp>, screen: Pos2) -> (usize, Light) {
    let picture = harness.get_by_label(VIEWPORT_LABEL).rect();
    let scene = harness.state().document().scene.clone();
    let (w, h) = (scene.camera.width, scene.camera.height);
    let image_point = DVec2::new(
        f64::from((screen.x - picture.min.x) / picture.width()) * f64::from(w),
        f64::from((screen.y - picture.min.y) / picture.height()) * f64::from(h),
    );
    let ray = PinholeCamera::new(&scene.camera, w, h).ray(image_point);
    let index = scene
        .lights
        .iter()
        .position(|l| matches!(l, Light::Point { .. }))
        .expect("the default scene has a point light");
    let mut light = scene.lights[index].clone();
    if let Light::Point { position, .. } = &mut light {
        *position = ray.at(6.0);
    }
    harness
        .state_mut()
        .push(Command::Edit(SceneEdit::SetLight(index, light.clone())));
    harness.run();
    (index, light)
}

#[test]
fn a_light_marker_under_the_gizmo_buttons_does_not_take_their_presses() {
    let mut harness = harness();
    let rotate = harness.get_by_label("Rotate").rect().center();
    // Put the point light where it is drawn right under the Rotate button.
    put_point_light_at(&mut harness, rotate);
    let placed = harness.state().document().scene.clone();

    harness.get_by_label("Rotate").click();
    harness.run();
    assert_eq!(
        &harness.state().document().selection,
        &Selection::None,
        "no light picked"
    );
    drag(&mut harness, rotate, rotate + Vec2::new(60.0, 25.0));
    assert_eq!(
        &harness.state().document().scene,
        &placed,
        "a press on the button neither drags the light nor orbits the camera"
    );
}

#[test]
fn a_lights_mute_and_solo_buttons_stay_on_top_of_the_not_the_full_picture_marker() {
    let mut harness = harness();
    let mut settings = harness.state().view().preview_settings;
    settings.switches.set(Term::Diffuse, false);
    harness
        .state_mut()
        .push(Command::SetPreviewSettings(settings));
    harness.run();
    let marker = harness.get_by_label_contains(NOT_FULL_PICTURE).rect();
    // Put the point light so that its M button (drawn 9 points right of and 22 points
    // above the marker dot) lands in the middle of the amber marker.
    let (index, _) = put_point_light_at(&mut harness, marker.center() + Vec2::new(-19.0, 13.0));
    harness
        .state_mut()
        .push(Command::Select(Selection::Light(index)));
    harness.run();
    let mute = harness
        .get_all_by_label_contains("(marker)")
        .find(|node| {
            node.accesskit_node()
                .label()
                .is_some_and(|l| l.starts_with("mute "))
        })
        .expect("the selected light's M button");
    assert!(
        marker.contains(mute.rect().center()),
        "the M button {:?} lies under the marker {marker:?}",
        mute.rect()
    );
    mute.click();
    harness.run();
    let muted = &harness.state().view().isolation.muted_lights;
    assert!(muted.contains(&index), "the click reached the M button");
}

/// The inspector's left edge and the viewport's picture, where a person sees them.
fn layout_marks(harness: &Harness<'_, EditorApp>) -> (f32, Rect) {
    let inspector = harness.get_by_label("INSPECTOR").rect().min.x;
    let picture = harness.get_by_label(VIEWPORT_LABEL).rect();
    (inspector, picture)
}

#[test]
fn selecting_anything_keeps_the_inspector_width_and_the_picture_still() {
    for size in [Vec2::new(1280.0, 800.0), Vec2::new(900.0, 600.0)] {
        let mut harness = editor_harness(EditorOptions::default(), size, 64);
        open_example(&mut harness, "more_shapes.ron");
        let before = layout_marks(&harness);
        let scene = harness.state().document().scene.clone();
        let mut selections = vec![Selection::Camera, Selection::Render];
        selections.extend((0..scene.objects.len()).map(Selection::Object));
        selections.extend((0..scene.lights.len()).map(Selection::Light));
        selections.extend(scene.materials.keys().cloned().map(Selection::Material));
        for selection in selections {
            harness.state_mut().push(Command::Select(selection.clone()));
            harness.run();
            let now = layout_marks(&harness);
            assert_eq!(
                now.0, before.0,
                "{size:?}: the inspector moved for {selection:?}"
            );
            assert_eq!(
                now.1, before.1,
                "{size:?}: the picture moved for {selection:?}"
            );
        }
    }
}

/// At the usual window sizes (a narrower inspector than its default still scrolls
/// sideways rather than widening: see the test above).
#[test]
fn every_inspector_field_fits_inside_the_panel() {
    for size in [Vec2::new(1280.0, 800.0), Vec2::new(1100.0, 700.0)] {
        let mut harness = editor_harness(EditorOptions::default(), size, 64);
        open_example(&mut harness, "more_shapes.ron");
        for selection in [Selection::Object(6), Selection::Render, Selection::Light(2)] {
            harness.state_mut().push(Command::Select(selection.clone()));
            harness.run();
            let labels: Vec<String> = [
                "ambient",
                "diffuse",
                "background",
                "colour",
                "translate",
                "position",
            ]
            .iter()
            .flat_map(|l| ["r", "g", "b", "x", "y", "z"].map(|c| format!("{l} {c}")))
            .collect();
            for label in &labels {
                for node in harness.query_all_by_label(label) {
                    let rect = node.rect();
                    assert!(
                        rect.max.x <= size.x - 4.0,
                        "{size:?} {selection:?}: {label} ends at {} beyond the window",
                        rect.max.x
                    );
                }
            }
        }
    }
}

#[test]
fn a_huge_typed_value_shows_in_the_fields_width_and_moves_nothing() {
    let mut harness = editor_harness(EditorOptions::default(), Vec2::new(1280.0, 800.0), 64);
    harness
        .state_mut()
        .push(Command::Select(Selection::Object(1)));
    harness.run();
    let before = layout_marks(&harness);
    let field = harness.get_by_label("translate x").rect();
    harness
        .get_by_label("translate x")
        .set_value_accesskit(1e30);
    harness.run();
    harness.run();
    assert_eq!(layout_marks(&harness), before, "the layout moved");
    let after = harness.get_by_label("translate x").rect();
    assert_eq!(after.width(), field.width(), "the field changed width");
    // Typed, it is also taken with a warning: see ui_showing.rs.
    // Selecting something else leaves the layout as it was, too.
    harness.state_mut().push(Command::Select(Selection::Render));
    harness.run();
    assert_eq!(layout_marks(&harness), before);
}

#[test]
fn the_debug_views_carry_a_legend_and_the_lit_picture_none() {
    let mut harness = harness();
    harness.run();
    assert!(harness.query_by_label_contains("depth: near").is_none());
    let first = harness.state().document().scene.objects[0].name.clone();
    let named_before = harness.get_all_by_label(&first).count();
    for (view, line) in [
        (View::Depth, "depth: near"),
        (View::ObjectId, "object id: a flat colour per object"),
        (View::Normal, "+x red, +y green, +z blue"),
        (View::ShadowMask, "shadow mask: the share of facing lights"),
    ] {
        harness.get_by_label("view").click();
        harness.run();
        let label = format!("view {}", raylab::ui::state::view_label(view));
        harness.get_by_label(&label).click();
        harness.run();
        assert_eq!(harness.state().view().preview_settings.view, view);
        harness.get_by_label_contains(line);
    }
    // The object-id legend names the scene's objects.
    harness.get_by_label("view").click();
    harness.run();
    harness.get_by_label("view object id").click();
    harness.run();
    assert_eq!(harness.get_all_by_label(&first).count(), named_before + 1);
}

#[test]
fn isolating_a_light_or_switching_a_solo_keeps_the_toolbar_rows_and_the_picture() {
    use raylab::ui::state::IsolationToggle;
    for size in [Vec2::new(1280.0, 800.0), Vec2::new(1000.0, 700.0)] {
        let mut harness = editor_harness(EditorOptions::default(), size, 64);
        harness.run();
        let before = layout_marks(&harness);
        let steps = [
            Command::Isolate(IsolationToggle::Solo {
                light: 1,
                add: false,
            }),
            Command::Isolate(IsolationToggle::Mute(2)),
            Command::Isolate(IsolationToggle::Hide(0)),
            Command::Isolate(IsolationToggle::ShowAll),
        ];
        for step in steps {
            let what = format!("{step:?}");
            harness.state_mut().push(step);
            harness.run();
            harness.run();
            assert_eq!(
                layout_marks(&harness),
                before,
                "{size:?}: the picture moved after {what}"
            );
        }
    }
}

#[test]
fn an_error_or_warning_banner_floats_and_moves_nothing() {
    let mut harness = editor_harness(EditorOptions::default(), Vec2::new(1280.0, 800.0), 64);
    harness.run();
    let before = layout_marks(&harness);
    let outliner_top = harness.get_by_label("Camera").rect();
    // A failed open: an error banner.
    harness
        .state_mut()
        .push(Command::Open("/no/such/scene.ron".into()));
    harness.run();
    harness.run();
    assert!(harness.state().error().is_some());
    harness.get_by_label("Dismiss");
    assert_eq!(
        layout_marks(&harness),
        before,
        "the error banner moved the picture"
    );
    assert_eq!(
        harness.get_by_label("Camera").rect(),
        outliner_top,
        "nor the outliner"
    );
    harness.get_by_label("Dismiss").click();
    harness.run();
    assert!(harness.state().error().is_none());
    assert_eq!(layout_marks(&harness), before);
}
