//! Typing into the inspector's number fields key by key: while typing, the text is the
//! user's (never rewritten, never judged); the field takes or refuses what was typed
//! when the edit ends (Return, Tab). Every kind of field: a scale, an angle, a colour
//! channel, an index of refraction, a radius and a whole number of samples.

mod editor_harness;

use editor_harness::harness;
use egui::{Event, Key, Modifiers};
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use raylab::scene::{Light, LightKind, LightSource, Scene, Transform};
use raylab::ui::{Command, EditorApp, SceneEdit};

/// A key to press in a field.
#[derive(Clone, Copy)]
enum Stroke {
    Char(char),
    Backspace,
}

/// The keys of `text`, one by one.
fn chars(text: &str) -> Vec<Stroke> {
    text.chars().map(Stroke::Char).collect()
}

/// What a field shows now (its text while it is being typed into).
fn field_text(harness: &Harness<'_, EditorApp>, label: &str) -> String {
    harness
        .get_by_label(label)
        .accesskit_node()
        .value()
        .unwrap_or_default()
}

/// Whether the status line says something about a typed value.
fn has_field_notice(harness: &Harness<'_, EditorApp>) -> bool {
    [
        "is not a number",
        "is not taken here",
        "is outside what",
        "not a finite",
    ]
    .iter()
    .any(|words| harness.query_by_label_contains(words).is_some())
}

/// Clicks the field `label`, selects all (Ctrl+A) and presses `strokes` one frame each,
/// checking after each that the field shows exactly what was typed, that nothing was
/// said about it and that `value` has not moved; then ends the edit with `end`.
fn type_keys(
    harness: &mut Harness<'_, EditorApp>,
    label: &str,
    strokes: &[Stroke],
    end: Key,
    value: impl Fn(&Scene) -> f64,
) {
    let before = value(&harness.state().document().scene);
    harness.get_by_label(label).click();
    harness.run();
    harness.key_press_modifiers(Modifiers::COMMAND, Key::A);
    harness.run();
    let mut typed = field_text(harness, label);
    let mut selected_all = true;
    for stroke in strokes {
        match *stroke {
            Stroke::Char(c) => {
                harness.event(Event::Text(c.to_string()));
                if selected_all {
                    typed.clear();
                }
                typed.push(c);
            }
            Stroke::Backspace => {
                harness.key_press(Key::Backspace);
                if selected_all {
                    typed.clear();
                } else {
                    typed.pop();
                }
            }
        }
        selected_all = false;
        harness.run();
        assert_eq!(
            field_text(harness, label),
            typed,
            "{label}: the text is the user's"
        );
        assert!(
            !has_field_notice(harness),
            "{label}: nothing is judged while typing {typed:?}"
        );
        assert_eq!(
            value(&harness.state().document().scene),
            before,
            "{label}: typing {typed:?}"
        );
    }
    harness.key_press(end);
    harness.run();
}

/// One field: its label, how to show it, how to read its value, and what each typed
/// text leaves in it (`None`: the field keeps its value).
struct FieldCase {
    label: &'static str,
    show: fn(&mut Harness<'_, EditorApp>),
    value: fn(&Scene) -> f64,
    /// After `0.3`, `.3`, `-0.5`, `1e-3`.
    expected: [Option<f64>; 4],
}

fn red_ball(harness: &mut Harness<'_, EditorApp>) {
    harness.get_by_label("red ball").click();
    harness.run();
}

fn red_plastic(harness: &mut Harness<'_, EditorApp>) {
    harness.get_by_label("red plastic").click();
    harness.run();
}

fn new_spot(harness: &mut Harness<'_, EditorApp>) {
    harness
        .state_mut()
        .push(Command::Edit(SceneEdit::AddLight(LightKind::Spot)));
    harness.run();
}

fn render_settings(harness: &mut Harness<'_, EditorApp>) {
    harness.get_by_label("Render settings").click();
    harness.run();
}

fn scale_x(scene: &Scene) -> f64 {
    match scene.objects[1].transform {
        Transform::Trs(trs) => trs.scale.x,
        Transform::Matrix(_) => f64::NAN,
    }
}

fn spot(scene: &Scene) -> (f64, f64) {
    match scene.lights.last() {
        Some(Light::Spot {
            angle_deg,
            source: LightSource { radius, .. },
            ..
        }) => (*angle_deg, *radius),
        other => panic!("expected the new spot light: {other:?}"),
    }
}

fn cases() -> Vec<FieldCase> {
    vec![
        FieldCase {
            label: "scale x",
            show: red_ball,
            value: scale_x,
            expected: [Some(0.3), Some(0.3), Some(-0.5), Some(0.001)],
        },
        FieldCase {
            label: "angle",
            show: new_spot,
            value: |scene| spot(scene).0,
            // An angle of 0 (where -0.5 is held) is refused: no cone.
            expected: [Some(0.3), Some(0.3), None, Some(0.001)],
        },
        FieldCase {
            label: "diffuse r",
            show: red_plastic,
            value: |scene| scene.materials["red plastic"].diffuse.x,
            expected: [Some(0.3), Some(0.3), Some(0.0), Some(0.001)],
        },
        FieldCase {
            label: "ior",
            show: red_plastic,
            value: |scene| scene.materials["red plastic"].ior,
            expected: [Some(0.3), Some(0.3), None, Some(0.001)],
        },
        FieldCase {
            label: "radius",
            show: new_spot,
            value: |scene| spot(scene).1,
            expected: [Some(0.3), Some(0.3), Some(0.0), Some(0.001)],
        },
        FieldCase {
            label: "samples",
            show: render_settings,
            value: |scene| f64::from(scene.render.samples_per_pixel),
            // A whole number of at least 1.
            expected: [Some(1.0), Some(1.0), Some(1.0), Some(1.0)],
        },
    ]
}

#[test]
fn every_kind_of_number_field_takes_what_was_typed_when_the_edit_ends() {
    for case in cases() {
        for (text, expected) in ["0.3", ".3", "-0.5", "1e-3"].iter().zip(case.expected) {
            let mut harness = harness();
            (case.show)(&mut harness);
            let before = (case.value)(&harness.state().document().scene);
            type_keys(
                &mut harness,
                case.label,
                &chars(text),
                Key::Enter,
                case.value,
            );
            let after = (case.value)(&harness.state().document().scene);
            assert_eq!(
                after,
                expected.unwrap_or(before),
                "{} after typing {text} and Return",
                case.label
            );
            if expected.is_none() {
                assert!(
                    harness
                        .query_by_label_contains("is not taken here")
                        .is_some(),
                    "{}: a refused {text} is said in the status line",
                    case.label
                );
            }
        }
    }
}

#[test]
fn backspace_over_the_whole_text_then_return_keeps_the_value_and_says_why() {
    for case in cases() {
        let mut harness = harness();
        (case.show)(&mut harness);
        let before = (case.value)(&harness.state().document().scene);
        // Click, Ctrl+A, then backspace over everything: an empty field.
        let strokes = [Stroke::Backspace; 3];
        type_keys(&mut harness, case.label, &strokes, Key::Enter, case.value);
        assert_eq!(
            (case.value)(&harness.state().document().scene),
            before,
            "{}",
            case.label
        );
        assert!(
            harness.query_by_label_contains("is not a number").is_some(),
            "{}: the empty text is refused when the edit ends, and said",
            case.label
        );
    }
}

#[test]
fn tab_ends_the_edit_as_return_does() {
    let mut harness = harness();
    red_ball(&mut harness);
    type_keys(&mut harness, "scale x", &chars("0.3"), Key::Tab, scale_x);
    assert_eq!(scale_x(&harness.state().document().scene), 0.3);
}
