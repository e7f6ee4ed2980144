//! The outliner: camera, render settings, objects, materials and lights as a list to
//! select from, with add, duplicate, delete and rename; a hide toggle on each object and
//! mute and solo toggles on each light (editor state, not scene edits).

use egui::{Align, Layout, RichText, Ui};

use crate::scene::{Light, Scene, Shape};
use crate::trace::Isolation;
use crate::ui::commands::{Command, LightKind, SceneEdit, Selection};
use crate::ui::state::{IsolationToggle, light_label};

use super::outliner_tree::{Shown, node_row_ui, node_ui};

/// Least width of one isolation toggle at the end of a row.
const TOGGLE_WIDTH: f32 = 22.0;

/// The hide toggle's text.
pub(super) const HIDE_ICON: &str = "H";

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

pub(super) fn shape_icon(shape: &Shape) -> &'static str {
    match shape {
        Shape::Sphere => "●",
        Shape::Plane => "▭",
        Shape::Cube => "■",
        Shape::Cylinder => "▮",
        Shape::Cone => "▲",
        Shape::Torus { .. } => "◎",
        Shape::Tube { .. } => "◘",
        Shape::Octahedron => "◆",
        Shape::Mesh { .. } => "△",
        Shape::Csg { .. } => "⊖",
        Shape::Group { .. } => "▤",
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

/// The look of a row: its name, icon and whether it is greyed (hidden, muted, not solo).
pub(super) struct Row<'a> {
    pub(super) name: &'a str,
    pub(super) icon: &'a str,
    pub(super) greyed: bool,
}

impl<'a> Row<'a> {
    /// A row that is never greyed.
    pub(super) fn plain(name: &'a str, icon: &'a str) -> Self {
        Self {
            name,
            icon,
            greyed: false,
        }
    }
}

/// One line of the outliner: `toggles` at its right end (laid out first, right to left,
/// so they always fit the panel) and `item` filling the width left of them.
pub(super) fn row_ui(
    ui: &mut Ui,
    commands: &mut Vec<Command>,
    toggles: impl FnOnce(&mut Ui, &mut Vec<Command>),
    item: impl FnOnce(&mut Ui, &mut Vec<Command>),
) {
    let size = egui::vec2(ui.available_width(), ui.spacing().interact_size.y);
    ui.allocate_ui_with_layout(size, Layout::right_to_left(Align::Center), |ui| {
        toggles(ui, commands);
        ui.with_layout(Layout::left_to_right(Align::Center), |ui| {
            item(ui, commands)
        });
    });
}

fn last_selection_id() -> egui::Id {
    egui::Id::unique("outliner last selection")
}

/// Where the outliner says, for this frame, that the selected row should scroll into view.
fn reveal_id() -> egui::Id {
    egui::Id::unique("outliner reveal selection")
}

/// A selectable row as wide as the space left; its accessible name is the item's name
/// alone.
pub(super) fn item_ui(
    ui: &mut Ui,
    row: &Row,
    selected: bool,
    target: Selection,
    commands: &mut Vec<Command>,
) -> egui::Response {
    let response = item_button(ui, row, selected, egui::Sense::click());
    if response.clicked() && !selected {
        commands.push(Command::Select(target));
    }
    response
}

/// The selectable button of a row, as wide as the space left, sensing `sense`; its
/// accessible name is the item's name alone.
pub(super) fn item_button(
    ui: &mut Ui,
    row: &Row,
    selected: bool,
    sense: egui::Sense,
) -> egui::Response {
    let text = format!("{}  {}", row.icon, row.name);
    let text = if row.greyed {
        RichText::new(text).weak().italics()
    } else {
        RichText::new(text)
    };
    let width = ui.available_width().max(40.0);
    let response = ui
        // The growing atom after the text keeps the name at the left of the wide button.
        .add(
            egui::Button::selectable(selected, (text, egui::Atom::grow()))
                .min_size(egui::vec2(width, 0.0))
                .sense(sense),
        )
        .accessible_name(row.name);
    if selected
        && ui
            .data(|d| d.get_temp::<bool>(reveal_id()))
            .unwrap_or(false)
    {
        // Only as far as needed: a row already in view does not move.
        response.scroll_to_me(None);
    }
    response
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

/// A small on/off toggle at the end of a row, named for screen readers and tests.
pub(super) fn toggle_ui(ui: &mut Ui, on: bool, text: &str, name: &str) -> egui::Response {
    ui.add(egui::Button::selectable(on, text).min_size(egui::vec2(TOGGLE_WIDTH, 0.0)))
        .accessible_name(name)
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

/// Right-click menu of an item: rename (objects, materials), duplicate, delete.
pub(super) fn item_menu(response: &egui::Response, target: Selection, commands: &mut Vec<Command>) {
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
