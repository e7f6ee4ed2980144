//! The outliner: camera, render settings, objects, materials and lights as a list to
//! select from, with add, duplicate, delete and rename; a hide toggle on each object and
//! mute and solo toggles on each light (editor state, not scene edits).

mod row;
mod tree;

use egui::{RichText, Ui};

use crate::scene::{Light, Scene, Shape};
use crate::trace::Isolation;
use crate::ui::commands::{Command, LightKind, SceneEdit, Selection};
use crate::ui::state::{IsolationToggle, light_label};

use row::{
    HIDE_ICON, Row, item_menu, item_ui, last_selection_id, reveal_id, row_ui, shape_icon, toggle_ui,
};
use tree::{Shown, node_row_ui, node_ui};

/// Shows the outliner.
pub fn outliner_ui(
    ui: &mut Ui,
    scene: &Scene,
    selection: &Selection,
    isolation: &Isolation,
    commands: &mut Vec<Command>,
) {
    // A selection made elsewhere (a pick in the viewport) scrolls its row into view.
    let last = ui.data(|d| d.get_temp::<Selection>(last_selection_id()));
    let reveal = last.as_ref() != Some(selection);
    ui.data_mut(|d| {
        d.insert_temp(last_selection_id(), selection.clone());
        d.insert_temp(reveal_id(), reveal);
    });
    egui::ScrollArea::vertical()
        .auto_shrink([false, false])
        .show(ui, |ui| {
            section_ui(ui, "Scene", None, |ui| {
                item_ui(
                    ui,
                    &Row::plain("Camera", "◉"),
                    selection == &Selection::Camera,
                    Selection::Camera,
                    commands,
                );
                item_ui(
                    ui,
                    &Row::plain("Render settings", "≡"),
                    selection == &Selection::Render,
                    Selection::Render,
                    commands,
                );
            });
            section_ui(ui, "Objects", Some(scene.objects.len()), |ui| {
                for (index, object) in scene.objects.iter().enumerate() {
                    let shown = isolation.is_object_shown(index);
                    let row = Row {
                        name: &object.name,
                        icon: shape_icon(&object.shape),
                        greyed: !shown,
                    };
                    node_ui(
                        ui,
                        object,
                        &[index],
                        "",
                        Shown {
                            selection,
                            isolation,
                        },
                        commands,
                        &mut |ui, commands| {
                            row_ui(
                                ui,
                                commands,
                                |ui, commands| hide_toggle_ui(ui, index, object, shown, commands),
                                |ui, commands| {
                                    let response =
                                        node_row_ui(ui, &row, &[index], selection, commands);
                                    item_menu(&response, Selection::Object(index), commands);
                                },
                            );
                        },
                    );
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
                    let row = Row::plain(name, "◆");
                    let response = item_ui(ui, &row, selected, selection_here.clone(), commands);
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
                    let row = Row {
                        name: &label,
                        icon: light_icon(light),
                        greyed: !isolation.is_light_lit(index),
                    };
                    row_ui(
                        ui,
                        commands,
                        |ui, commands| light_toggles_ui(ui, index, &label, isolation, commands),
                        |ui, commands| {
                            let response =
                                item_ui(ui, &row, selected, Selection::Light(index), commands);
                            item_menu(&response, Selection::Light(index), commands);
                        },
                    );
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

/// An object's hide toggle, for a right-to-left layout.
fn hide_toggle_ui(
    ui: &mut Ui,
    index: usize,
    object: &crate::scene::Object,
    shown: bool,
    commands: &mut Vec<Command>,
) {
    let hide = toggle_ui(ui, !shown, HIDE_ICON, &format!("hide {}", object.name)).on_hover_text(
        if shown {
            "Hide: leave it out of the render (no shadow, no reflection)"
        } else {
            "Hidden: click to show it again"
        },
    );
    if hide.clicked() {
        commands.push(Command::Isolate(IsolationToggle::Hide(index)));
    }
}

/// A light's mute and solo toggles, for a right-to-left layout; Ctrl- or Shift-click on
/// solo adds to the solo lights.
fn light_toggles_ui(
    ui: &mut Ui,
    index: usize,
    label: &str,
    isolation: &Isolation,
    commands: &mut Vec<Command>,
) {
    // Laid out right to left: solo is the rightmost, mute left of it.
    let solo = isolation.solo_lights.contains(&index);
    let clicked = toggle_ui(ui, solo, "S", &format!("solo {label}"))
        .on_hover_text(
            "Solo: render as if this were the only light (Ctrl- or Shift-click: several)",
        )
        .clicked();
    if clicked {
        let add = ui.input(|i| i.modifiers.command || i.modifiers.shift);
        commands.push(Command::Isolate(IsolationToggle::Solo {
            light: index,
            add,
        }));
    }
    let muted = isolation.muted_lights.contains(&index);
    if toggle_ui(ui, muted, "M", &format!("mute {label}"))
        .on_hover_text("Mute: render without this light")
        .clicked()
    {
        commands.push(Command::Isolate(IsolationToggle::Mute(index)));
    }
}
