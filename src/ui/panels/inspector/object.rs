//! The object inspector: name, shape, material, transform, and the material's values
//! right below (what one tunes next).

use std::collections::BTreeMap;

use egui::Ui;

use super::fields::{number_row_ui, vec3_row_ui};
use super::layout::{grid_ui, heading_ui};
use super::limits::{self, Limits};
use super::material::material_rows_ui;
use super::mesh::mesh_rows_ui;
use super::tree_node::{breadcrumb_ui, csg_op_row_ui, tree_actions_ui};
use crate::preview::MeshFacts;
use crate::scene::tree::effective_material;
use crate::scene::*;
use crate::ui::commands::{Command, SceneEdit};

/// The inspector for the object or tree node at `path` (a top-level object's path is
/// its index alone).
pub(super) fn object_ui(
    ui: &mut Ui,
    scene: &Scene,
    path: &[usize],
    object: &Object,
    meshes: &BTreeMap<String, MeshFacts>,
    focus_name: &mut bool,
    commands: &mut Vec<Command>,
) {
    let nested = path.len() > 1;
    heading_ui(ui, if nested { "PART" } else { "OBJECT" }, &object.name);
    breadcrumb_ui(ui, scene, path, commands);
    let mut edited = object.clone();
    grid_ui(ui, "object", |ui| {
        ui.label("Name");
        name_field_ui(ui, path, &mut edited.name, focus_name);
        ui.end_row();

        ui.label("Shape");
        if edited.shape.is_unit_shape() {
            egui::ComboBox::from_id_salt("shape")
                .selected_text(edited.shape.name())
                .show_ui(ui, |ui| {
                    for shape in Shape::ALL {
                        let current = shape.same_kind(&edited.shape);
                        // Choosing the kind it already is keeps its parameter.
                        if ui.selectable_label(current, shape.name()).clicked() && !current {
                            edited.shape = shape;
                        }
                    }
                })
                .response
                .accessible_name("shape");
            ui.end_row();
            shape_parameter_ui(ui, &mut edited.shape);
        } else if let Shape::Mesh { path } = &edited.shape {
            ui.label("Mesh from a file");
            ui.end_row();
            mesh_rows_ui(ui, path, meshes.get(path));
        } else {
            // A tree or a mesh is more than a shape: switching it to a unit shape would
            // drop its operands, children or file in one click.
            ui.label(tree_or_mesh_summary(&edited.shape))
                .on_hover_text("Its parts are under it in the outliner");
            ui.end_row();
            csg_op_row_ui(ui, &mut edited.shape);
        }

        ui.label("Material");
        let inherited = effective_material(&scene.objects, &path[..path.len() - 1]);
        let inherit_label = format!("(inherit: {})", inherited.unwrap_or("none"));
        let shown = if edited.material.is_empty() {
            inherit_label.as_str()
        } else {
            edited.material.as_str()
        };
        egui::ComboBox::from_id_salt("material")
            .selected_text(shown)
            .show_ui(ui, |ui| {
                // Parts may show their parent's material; a top-level object needs one.
                if nested {
                    ui.selectable_value(&mut edited.material, String::new(), &inherit_label);
                }
                for name in scene.materials.keys() {
                    ui.selectable_value(&mut edited.material, name.clone(), name);
                }
            })
            .response
            .accessible_name("material");
        ui.end_row();
    });
    ui.add_space(6.0);
    ui.label(egui::RichText::new("Transform").strong());
    if nested {
        ui.weak("in its parent's space");
    }
    transform_ui(ui, &mut edited.transform);
    ui.add_space(4.0);
    tree_actions_ui(ui, &object.shape, commands);
    if edited != *object {
        let edit = match path {
            [index] => SceneEdit::SetObject(*index, edited),
            _ => SceneEdit::SetPart(path.to_vec(), edited),
        };
        commands.push(Command::Edit(edit));
    }
    // The material's values right here, since that is what one tunes next.
    let shown_material = effective_material(&scene.objects, path).unwrap_or_default();
    if let Some(material) = scene.materials.get(shown_material) {
        ui.add_space(6.0);
        if let [index] = path {
            shared_material_ui(ui, scene, *index, &object.material, commands);
        }
        let inherited = if object.material.is_empty() {
            " (inherited)"
        } else {
            ""
        };
        egui::CollapsingHeader::new(
            egui::RichText::new(format!(
                "Material \u{201c}{shown_material}\u{201d}{inherited}"
            ))
            .strong(),
        )
        .id_salt("object material")
        .default_open(true)
        .show(ui, |ui| {
            let mut edited = material.clone();
            grid_ui(ui, "object material", |ui| {
                material_rows_ui(ui, &mut edited)
            });
            if edited != *material {
                commands.push(Command::Edit(SceneEdit::SetMaterial(
                    shown_material.to_owned(),
                    edited,
                )));
            }
        });
    }
}

/// The object's name. Every keystroke renames, except to nothing: an object needs a
/// name (the outliner would show a blank row), so an emptied field keeps its text only
/// while it is being typed in, and on leaving it the name stays as it was, said in the
/// status line.
fn name_field_ui(ui: &mut Ui, path: &[usize], name: &mut String, focus_name: &mut bool) {
    let id = ui.make_persistent_id(("object name being typed", path));
    let mut text = ui
        .data(|d| d.get_temp::<String>(id))
        .unwrap_or_else(|| name.clone());
    let response = ui
        .add(egui::TextEdit::singleline(&mut text).desired_width(f32::INFINITY))
        .accessible_name("object name");
    if std::mem::take(focus_name) {
        response.request_focus();
    }
    if text.trim().is_empty() {
        if !response.has_focus() {
            ui.data_mut(|d| d.remove::<String>(id));
            if response.lost_focus() {
                super::fields::leave_notice(
                    ui.ctx(),
                    format!("An object needs a name: it stays \u{201c}{name}\u{201d}"),
                );
            }
        } else {
            ui.data_mut(|d| d.insert_temp(id, text));
        }
    } else {
        ui.data_mut(|d| d.remove::<String>(id));
        *name = text;
    }
}

/// The torus's and the tube's parameter, as a field on its own row.
fn shape_parameter_ui(ui: &mut Ui, shape: &mut Shape) {
    match shape {
        Shape::Torus { minor } => {
            number_row_ui(ui, "minor radius", minor, 0.005, limits::TORUS_MINOR);
        }
        Shape::Tube { inner } => {
            number_row_ui(ui, "inner radius", inner, 0.005, limits::TUBE_INNER);
        }
        _ => {}
    }
}

pub(super) fn transform_ui(ui: &mut Ui, transform: &mut Transform) {
    match transform {
        Transform::Trs(trs) => {
            grid_ui(ui, "trs", |ui| {
                vec3_row_ui(ui, "translate", &mut trs.translate, 0.01, Limits::ANY);
                vec3_row_ui(ui, "rotate", &mut trs.rotate_deg, 0.5, Limits::ANY);
                vec3_row_ui(ui, "scale", &mut trs.scale, 0.01, Limits::NONZERO);
            });
        }
        Transform::Matrix(rows) => {
            ui.weak("A general matrix (read-only): rows of the object-to-world transform.");
            egui::Grid::new("matrix")
                .spacing([10.0, 4.0])
                .show(ui, |ui| {
                    for row in rows.iter() {
                        for value in row {
                            ui.monospace(format!("{value:>8.3}"));
                        }
                        ui.end_row();
                    }
                });
            if ui
                .button("Reset to translate/rotate/scale")
                .on_hover_text("Keeps position, rotation and scale; drops any shear")
                .clicked()
            {
                *transform = Transform::Trs(Trs::nearest(&transform.world_from_object()));
            }
        }
    }
}

/// Where the material is shared, says so (an edit here changes every object using it)
/// and offers this object a copy of its own.
fn shared_material_ui(
    ui: &mut Ui,
    scene: &Scene,
    index: usize,
    material: &str,
    commands: &mut Vec<Command>,
) {
    let users = crate::ui::commands::material_users(scene, material);
    if users < 2 {
        return;
    }
    ui.horizontal(|ui| {
        ui.label(
            egui::RichText::new(format!(
                "\u{201c}{material}\u{201d} is shared by {users} objects"
            ))
            .color(crate::ui::style::ACCENT),
        );
        if ui
            .button("Make unique")
            .on_hover_text("Give this object its own copy, so edits below change only it")
            .clicked()
        {
            commands.push(Command::Edit(SceneEdit::MakeMaterialUnique(index)));
        }
    });
}

/// What a tree or mesh object holds, in a few words.
fn tree_or_mesh_summary(shape: &Shape) -> String {
    match shape {
        Shape::Csg { op, operands } => format!("Csg {} of {}", op.name(), operands.len()),
        Shape::Group { children } => format!("Group of {}", children.len()),
        Shape::Mesh { path } => format!("Mesh {path}"),
        other => other.name().to_owned(),
    }
}
