//! The inspector: every field of the selected item (object, light, material, camera,
//! render settings). It edits a copy and pushes a command when the copy changed.

mod camera;
mod fields;
mod layout;
pub use fields::take_field_notice;
mod light;
mod limits;
mod material;
mod mesh;
mod object;
mod render_settings;
mod several;
mod tree_node;

use std::collections::BTreeMap;

use egui::Ui;

use crate::preview::MeshFacts;
use crate::scene::Scene;
use crate::ui::commands::{Command, Selection};

/// Shows the inspector for `selection`; `meshes` holds what the preview found in the
/// mesh files it has read. `focus_name` asks to put the keyboard in the name field (it
/// is reset once done).
pub fn inspector_ui(
    ui: &mut Ui,
    scene: &Scene,
    meshes: &BTreeMap<String, MeshFacts>,
    selection: &Selection,
    focus_name: &mut bool,
    commands: &mut Vec<Command>,
) {
    // Both ways: a row wider than the panel scrolls inside it rather than widening the
    // panel, so selecting something never moves the picture under the cursor.
    egui::ScrollArea::both()
        .auto_shrink([false, false])
        .show(ui, |ui| match selection {
            Selection::None => {
                ui.add_space(8.0);
                ui.weak("Select an object, light or material in the outliner or the viewport.");
            }
            Selection::Camera => camera::camera_ui(ui, &scene.camera, commands),
            Selection::Render => render_settings::render_ui(ui, &scene.render, commands),
            Selection::Object(index) => {
                if let Some(object) = scene.objects.get(*index) {
                    object::object_ui(ui, scene, &[*index], object, meshes, focus_name, commands);
                }
            }
            Selection::Part(path) => {
                if let Some(object) = crate::scene::tree::object_at(&scene.objects, path) {
                    object::object_ui(ui, scene, path, object, meshes, focus_name, commands);
                }
            }
            Selection::Several(paths) => several::several_ui(ui, scene, paths, commands),
            Selection::Light(index) => {
                if let Some(light) = scene.lights.get(*index) {
                    light::light_ui(ui, *index, light, commands);
                }
            }
            Selection::Material(name) => {
                if let Some(material) = scene.materials.get(name) {
                    material::material_ui(ui, name, material, focus_name, commands);
                }
            }
        });
}
