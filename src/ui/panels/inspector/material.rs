//! The material inspector: its name (a key, renamed when the field is left) and values.

use egui::Ui;

use super::fields::{colour_row_ui, number_row_ui};
use super::layout::{grid_ui, heading_ui};
use super::limits::{IOR, SHININESS};
use crate::scene::*;
use crate::ui::commands::{Command, SceneEdit};

pub(super) fn material_ui(
    ui: &mut Ui,
    name: &str,
    material: &Material,
    focus_name: &mut bool,
    commands: &mut Vec<Command>,
) {
    heading_ui(ui, "MATERIAL", name);
    let mut edited = material.clone();
    grid_ui(ui, "material", |ui| {
        ui.label("Name");
        // The name is a key: edit a buffer, rename when the field is left.
        let id = ui.make_persistent_id(("material name", name));
        let mut buffer = ui
            .data_mut(|d| d.get_temp::<String>(id))
            .unwrap_or_else(|| name.to_owned());
        let response = ui
            .add(egui::TextEdit::singleline(&mut buffer).desired_width(f32::INFINITY))
            .accessible_name("material name");
        if std::mem::take(focus_name) {
            response.request_focus();
        }
        if response.lost_focus() {
            ui.data_mut(|d| d.remove::<String>(id));
            if buffer != name {
                commands.push(Command::Edit(SceneEdit::RenameMaterial {
                    from: name.to_owned(),
                    to: buffer,
                }));
            }
        } else if response.has_focus() {
            ui.data_mut(|d| d.insert_temp(id, buffer));
        }
        ui.end_row();
        material_rows_ui(ui, &mut edited);
    });
    if edited != *material {
        commands.push(Command::Edit(SceneEdit::SetMaterial(
            name.to_owned(),
            edited,
        )));
    }
}

/// The rows of a material's values.
pub(super) fn material_rows_ui(ui: &mut Ui, material: &mut Material) {
    colour_row_ui(ui, "ambient", &mut material.ambient);
    colour_row_ui(ui, "diffuse", &mut material.diffuse);
    colour_row_ui(ui, "specular", &mut material.specular);
    number_row_ui(ui, "shininess", &mut material.shininess, 0.5, SHININESS);
    colour_row_ui(ui, "mirror", &mut material.mirror);
    colour_row_ui(ui, "transmission", &mut material.transmission);
    number_row_ui(ui, "ior", &mut material.ior, 0.01, IOR);
}
