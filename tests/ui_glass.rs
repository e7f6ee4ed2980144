//! Glass and sphere lights in the editor: the material inspector edits `transmission` and
//! `ior` (held to the validator's range), the light inspector a Point or Spot light's
//! radius and shadow rays, and the toolbar switches the transmission term.

mod editor_harness;

use egui_kittest::kittest::Queryable;
use glam::DVec3;
use raylab::scene::{Light, LightSource};
use raylab::trace::Term;
use raylab::ui::{Command, Selection};

#[test]
fn the_material_inspector_edits_transmission_and_ior_in_one_undo_step_each() {
    let mut harness = editor_harness::harness_on_example("glass.ron");
    harness
        .state_mut()
        .push(Command::Select(Selection::Material("glass".to_owned())));
    harness.run();
    harness.get_by_label("ior").set_value_accesskit(1.33);
    harness.run();
    assert_eq!(
        harness.state().document().scene.materials["glass"].ior,
        1.33
    );
    // Out of range: held to the validator's largest index.
    harness.get_by_label("ior").set_value_accesskit(1e6);
    harness.run();
    assert_eq!(
        harness.state().document().scene.materials["glass"].ior,
        raylab::scene::MAX_IOR
    );
    harness.state_mut().push(Command::Undo);
    harness.run();
    assert_eq!(
        harness.state().document().scene.materials["glass"].ior,
        1.33
    );
    harness
        .get_by_label("transmission r")
        .set_value_accesskit(0.5);
    harness.run();
    let glass = &harness.state().document().scene.materials["glass"];
    assert_eq!(glass.transmission, DVec3::new(0.5, 0.95, 0.94));
}

#[test]
fn the_light_inspector_edits_a_point_lights_radius_and_shadow_rays() {
    let mut harness = editor_harness::harness_on_example("glass.ron");
    harness
        .state_mut()
        .push(Command::Select(Selection::Light(1)));
    harness.run();
    harness.get_by_label("radius").set_value_accesskit(0.3);
    harness.run();
    harness.get_by_label("shadow rays").set_value_accesskit(8.0);
    harness.run();
    let Light::Point {
        source: LightSource {
            radius, samples, ..
        },
        ..
    } = harness.state().document().scene.lights[1]
    else {
        panic!("light 1 of glass.ron is a point light");
    };
    assert_eq!((radius, samples), (0.3, 8));
    // A directional light has no sphere: no such rows.
    harness
        .state_mut()
        .push(Command::Select(Selection::Light(2)));
    harness.run();
    assert!(harness.query_by_label("radius").is_none());
}

#[test]
fn the_toolbar_switches_the_transmission_term() {
    let mut harness = editor_harness::harness_on_example("glass.ron");
    assert!(
        harness
            .state()
            .view()
            .preview_settings
            .switches
            .is_on(Term::Transmission)
    );
    harness.get_by_label("transmission").click();
    harness.run();
    assert!(
        !harness
            .state()
            .view()
            .preview_settings
            .switches
            .is_on(Term::Transmission)
    );
}
