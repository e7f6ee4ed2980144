//! Showing is not editing: every inspector panel opened on a scene at the edges of the
//! contract (mirrored and tiny scales, rotations past a turn, huge and tiny Phong
//! exponents and zero, the most samples, the deepest mirrors, HDR colours, spots wider
//! than a hemisphere) leaves the scene
//! bit-identical, with no undo step and no modified mark.

mod editor_harness;

use editor_harness::{editor_harness, temp_dir};
use egui::Vec2;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use raylab::scene::load_scene;
use raylab::ui::{Command, EditorApp, EditorOptions, Selection};

/// Values the validator takes and the old fields clamped on display.
const EDGE_SCENE: &str = r#"Scene(
    camera: (position: (0.0, 2.0, 9.0), look_at: (0.0, 0.5, -0.0), up: (0.0, 1.0, 0.0),
             fov_deg: 0.25, width: 16384, height: 1),
    render: (max_depth: 10000, background: (4.0, 0.0, 1e-9), samples_per_pixel: 65536),
    materials: {
        "sharp": (ambient: (3.0, 0.0, 0.0), diffuse: (0.0, 1e-7, 0.5), specular: (20.0, 1.0, 1.0),
                  shininess: 1000000.0, mirror: (1.0, 1.0, 1.0)),
        "dull": (diffuse: (0.5, 0.5, 0.5), shininess: 0.000001),
        "flat": (specular: (1.0, 1.0, 1.0), shininess: 0.0),
    },
    objects: [
        (name: "mirrored", shape: Cube, material: "sharp",
         transform: (translate: (-0.0, 1e9, -1e-9), rotate_deg: (720.0, -1080.5, 359.999),
                     scale: (-1.0, 0.00000001, -200000.0))),
        (name: "tilted", shape: Cone, material: "dull",
         transform: Matrix(((0.0, -2.0, 0.0, 1.0), (1.0, 0.0, 0.0, 2.0), (0.0, 0.0, -0.5, -3.0)))),
    ],
    lights: [
        Ambient(colour: (2.0, 2.0, 2.0), intensity: 0.0),
        Point(position: (1e12, -4.0, 3.0), colour: (5.0, 0.25, 100.0), intensity: 1000000.0),
        Directional(direction: (0.001, -1.0, 0.0), colour: (1.5, 1.0, 0.0)),
        Spot(position: (0.0, 5.0, 0.0), direction: (0.0, -1.0, 0.0), angle_deg: 180.0,
             colour: (40.0, 30.0, 20.0), intensity: 7.5),
        Spot(position: (0.0, 5.0, 0.0), direction: (0.0, -1.0, 0.0), angle_deg: 0.0001,
             colour: (0.0, 0.0, 0.0)),
        Spot(position: (0.0, 5.0, 0.0), direction: (0.0, -1.0, 0.0), angle_deg: 135.0,
             colour: (1.0, 1.0, 1.0)),
    ],
)
"#;

/// Every outliner row's label, in outliner order (a name may repeat: object and material).
fn outliner_labels(app: &EditorApp) -> Vec<String> {
    let scene = &app.document().scene;
    let mut labels: Vec<String> = vec!["Camera".into(), "Render settings".into()];
    labels.extend(scene.objects.iter().map(|o| o.name.clone()));
    labels.extend(scene.materials.keys().cloned());
    labels.extend(
        scene
            .lights
            .iter()
            .enumerate()
            .map(|(i, l)| raylab::ui::light_label(l, i)),
    );
    labels
}

/// Opens each colour swatch of the panel on show and closes it again.
fn open_every_swatch(harness: &mut Harness<'_, EditorApp>) {
    let swatches: Vec<String> = harness
        .query_all_by_label_contains(" colour")
        .filter_map(|node| node.accesskit_node().label())
        .filter(|label| label.ends_with(" colour"))
        .collect();
    for swatch in swatches {
        harness.get_by_label(&swatch).click();
        harness.run();
        harness.key_press(egui::Key::Escape);
        harness.run();
    }
}

#[test]
fn opening_every_panel_on_a_scene_at_the_contracts_edges_changes_nothing() {
    let dir = temp_dir("showing");
    let path = dir.join("edges.ron");
    std::fs::write(&path, EDGE_SCENE).unwrap();
    let loaded = load_scene(&path).expect("the edge scene is valid");
    let bits = format!("{loaded:?}");
    let mut harness = editor_harness(EditorOptions::default(), Vec2::new(1280.0, 800.0), 64);
    harness.state_mut().push(Command::Open(path));
    harness.run();
    assert_eq!(format!("{:?}", &harness.state().document().scene), bits);

    let labels = outliner_labels(harness.state());
    for (position, label) in labels.iter().enumerate() {
        // "floor"-like names can be both an object and a material: take this occurrence.
        let earlier = labels[..position].iter().filter(|l| *l == label).count();
        harness
            .get_all_by_role_and_label(egui::Role::Button, label)
            .nth(earlier)
            .unwrap_or_else(|| panic!("an outliner row {label}"))
            .click();
        harness.run();
        assert_ne!(
            &harness.state().document().selection,
            &Selection::None,
            "{label}"
        );
        open_every_swatch(&mut harness);
        let app = harness.state();
        assert_eq!(
            format!("{:?}", &app.document().scene),
            bits,
            "showing {label} edited the scene"
        );
        assert!(
            !app.document().can_undo(),
            "showing {label} left an undo step"
        );
        assert!(
            !app.document().is_dirty(),
            "showing {label} marked the scene modified"
        );
        assert!(!app.title().contains('*'), "{}", app.title());
    }
}

#[test]
fn a_field_takes_values_beyond_its_drag_range_and_refuses_what_the_validator_refuses() {
    let mut harness = editor_harness(EditorOptions::default(), Vec2::new(1280.0, 800.0), 64);
    harness.get_by_label("red ball").click();
    harness.run();
    harness.get_by_label("scale x").set_value_accesskit(-2.5);
    harness.get_by_label("rotate z").set_value_accesskit(725.0);
    harness.run();
    let transform = harness.state().document().scene.objects[1].transform;
    let raylab::scene::Transform::Trs(trs) = transform else {
        panic!("expected translate/rotate/scale");
    };
    assert_eq!(trs.scale.x, -2.5, "a mirror is a negative scale");
    assert_eq!(trs.rotate_deg.z, 725.0);

    // A zero scale would make the transform singular: the field keeps its value.
    harness.get_by_label("scale x").set_value_accesskit(0.0);
    harness.run();
    let raylab::scene::Transform::Trs(trs) = harness.state().document().scene.objects[1].transform
    else {
        panic!("expected translate/rotate/scale");
    };
    assert_eq!(trs.scale.x, -2.5);

    harness.get_by_label("Render settings").click();
    harness.run();
    harness.get_by_label("samples").set_value_accesskit(65536.0);
    harness.run();
    assert_eq!(
        harness.state().document().scene.render.samples_per_pixel,
        65536
    );
    harness
        .get_by_label("max depth")
        .set_value_accesskit(f64::from(raylab::scene::MAX_DEPTH));
    harness.run();
    assert_eq!(
        harness.state().document().scene.render.max_depth,
        raylab::scene::MAX_DEPTH
    );

    // The widest spot the contract takes, and a Phong exponent of 0.
    harness
        .state_mut()
        .push(Command::Edit(raylab::ui::SceneEdit::AddLight(
            raylab::scene::LightKind::Spot,
        )));
    harness.run();
    harness.get_by_label("angle").set_value_accesskit(150.0);
    harness.run();
    let spot = harness
        .state()
        .document()
        .scene
        .lights
        .last()
        .unwrap()
        .clone();
    assert!(
        matches!(spot, raylab::scene::Light::Spot { angle_deg, .. } if angle_deg == 150.0),
        "{spot:?}"
    );
    harness.get_by_label("red plastic").click();
    harness.run();
    harness.get_by_label("shininess").set_value_accesskit(0.0);
    harness.run();
    assert_eq!(
        harness.state().document().scene.materials["red plastic"].shininess,
        0.0
    );
    raylab::scene::validate(&harness.state().document().scene).unwrap();
}

/// Types `text` into the number field `label` as a person does: click (the field turns
/// into a text box), select all, type, Enter.
fn type_into(harness: &mut Harness<'_, EditorApp>, label: &str, text: &str) {
    harness.get_by_label(label).click();
    harness.run();
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    harness.get_by_label(label).type_text(text);
    harness.run();
    harness.key_press(egui::Key::Enter);
    harness.run();
}

#[test]
fn a_typed_value_the_field_does_not_take_is_said_in_the_status_line() {
    let mut harness = editor_harness(EditorOptions::default(), Vec2::new(1280.0, 800.0), 64);
    harness.get_by_label("red ball").click();
    harness.run();
    let before = harness.state().document().scene.clone();
    type_into(&mut harness, "scale x", "nan");
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "NaN is not taken"
    );
    // The status line says so.
    harness.get_by_label_contains("is not a finite number: the field keeps");
    type_into(&mut harness, "scale x", "0");
    harness.get_by_label_contains("0 is not taken here (not 0)");
    assert_eq!(
        &harness.state().document().scene,
        &before,
        "a zero scale is not taken"
    );
}

#[test]
fn a_notice_about_a_typed_value_goes_with_the_undo_of_that_value() {
    let mut harness = editor_harness(EditorOptions::default(), Vec2::new(1280.0, 800.0), 64);
    harness.get_by_label("red ball").click();
    harness.run();
    type_into(&mut harness, "translate x", "1e30");
    harness.get_by_label_contains("is taken, but it is far beyond");
    harness.state_mut().push(raylab::ui::Command::Undo);
    harness.run();
    assert!(
        harness
            .query_by_label_contains("is taken, but it is far beyond")
            .is_none(),
        "the notice spoke of the value the undo took away"
    );
}
