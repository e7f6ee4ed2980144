//! The outliner: camera, render settings, objects, materials and lights as a list to
//! select from, with add, duplicate, delete and rename.

use egui::{RichText, Ui};

use crate::scene::{Light, Scene, Shape};
use crate::ui::commands::{Command, LightKind, SceneEdit, Selection};

/// Shows the outliner.
pub fn outliner_ui(ui: &mut Ui, scene: &Scene, selection: &Selection, commands: &mut Vec<Command>) {
    egui::ScrollArea::vertical()
        .auto_shrink([false, false])
        .show(ui, |ui| {
            section_ui(ui, "Scene", None, |ui| {
                item_ui(
                    ui,
                    "Camera",
                    "◉",
                    selection == &Selection::Camera,
                    Selection::Camera,
                    commands,
                );
                item_ui(
                    ui,
                    "Render settings",
                    "≡",
                    selection == &Selection::Render,
                    Selection::Render,
                    commands,
                );
            });
            section_ui(ui, "Objects", Some(scene.objects.len()), |ui| {
                for (index, object) in scene.objects.iter().enumerate() {
                    let selected = selection == &Selection::Object(index);
                    let response = item_ui(
                        ui,
                        &object.name,
                        shape_icon(object.shape),
                        selected,
                        Selection::Object(index),
                        commands,
                    );
                    item_menu(&response, Selection::Object(index), commands);
                }
                ui.menu_button("+ Add object", |ui| {
                    for shape in Shape::ALL {
                        if ui.button(shape.name()).clicked() {
                            commands.push(Command::Edit(SceneEdit::AddObject(shape)));
                        }
                    }
                });
            });
            section_ui(ui, "Materials", Some(scene.materials.len()), |ui| {
                for name in scene.materials.keys() {
                    let selection_here = Selection::Material(name.clone());
                    let selected = selection == &selection_here;
                    let response =
                        item_ui(ui, name, "◆", selected, selection_here.clone(), commands);
                    item_menu(&response, selection_here, commands);
                }
                if ui.button("+ Add material").clicked() {
                    commands.push(Command::Edit(SceneEdit::AddMaterial));
                }
            });
            section_ui(ui, "Lights", Some(scene.lights.len()), |ui| {
                for (index, light) in scene.lights.iter().enumerate() {
                    let selected = selection == &Selection::Light(index);
                    let label = light_label(light, index);
                    let response = item_ui(
                        ui,
                        &label,
                        light_icon(light),
                        selected,
                        Selection::Light(index),
                        commands,
                    );
                    item_menu(&response, Selection::Light(index), commands);
                }
                ui.menu_button("+ Add light", |ui| {
                    for kind in LightKind::ALL {
                        if ui.button(format!("{} light", kind.name())).clicked() {
                            commands.push(Command::Edit(SceneEdit::AddLight(kind)));
                        }
                    }
                });
            });
        });
}

/// The outliner's name of a light: "Point light 2" (its place in the list, from 1).
#[must_use]
pub fn light_label(light: &Light, index: usize) -> String {
    format!("{} light {}", light.kind_name(), index + 1)
}

fn shape_icon(shape: Shape) -> &'static str {
    match shape {
        Shape::Sphere => "●",
        Shape::Plane => "▭",
        Shape::Cube => "■",
        Shape::Cylinder => "▮",
        Shape::Cone => "▲",
    }
}

fn light_icon(light: &Light) -> &'static str {
    match light {
        Light::Ambient { .. } => "◌",
        Light::Point { .. } => "⊙",
        Light::Directional { .. } => "↓",
        Light::Spot { .. } => "△",
    }
}

fn section_ui(ui: &mut Ui, title: &str, count: Option<usize>, body: impl FnOnce(&mut Ui)) {
    let header = match count {
        Some(n) => format!("{title}  ({n})"),
        None => title.to_owned(),
    };
    egui::CollapsingHeader::new(RichText::new(header).strong())
        .id_salt(title)
        .default_open(true)
        .show(ui, body);
}

/// A selectable row; its accessible name is the item's name alone.
fn item_ui(
    ui: &mut Ui,
    name: &str,
    icon: &str,
    selected: bool,
    target: Selection,
    commands: &mut Vec<Command>,
) -> egui::Response {
    let text = format!("{icon}  {name}");
    let response = ui
        .add(
            egui::Button::selectable(selected, text)
                .min_size(egui::vec2(ui.available_width(), 0.0)),
        )
        .accessible_name(name);
    if response.clicked() && !selected {
        commands.push(Command::Select(target));
    }
    response
}

/// Right-click menu of an item: rename (objects, materials), duplicate, delete.
fn item_menu(response: &egui::Response, target: Selection, commands: &mut Vec<Command>) {
    response.context_menu(|ui| {
        let renamable = matches!(target, Selection::Object(_) | Selection::Material(_));
        if renamable && ui.button("Rename").clicked() {
            commands.push(Command::Select(target.clone()));
            commands.push(Command::FocusName);
        }
        if ui.button("Duplicate").clicked() {
            commands.push(Command::Select(target.clone()));
            commands.push(Command::Edit(SceneEdit::DuplicateSelected));
        }
        if ui.button("Delete").clicked() {
            commands.push(Command::Select(target.clone()));
            commands.push(Command::Edit(SceneEdit::DeleteSelected));
        }
    });
}
