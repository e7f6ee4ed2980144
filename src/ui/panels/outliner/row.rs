//! One row of the outliner: its look (name, icon, greyed), the selectable button as wide
//! as the space left, the small toggles at its end, and its right-click menu.

use egui::{Align, Layout, RichText, Ui};

use crate::scene::Shape;
use crate::ui::commands::{Command, SceneEdit, Selection};

/// Least width of one isolation toggle at the end of a row.
const TOGGLE_WIDTH: f32 = 22.0;

/// The hide toggle's text.
pub(super) const HIDE_ICON: &str = "H";

/// The icon of an object row: the shape it is.
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

/// Where the outliner keeps the selection it showed last frame.
pub(super) fn last_selection_id() -> egui::Id {
    egui::Id::unique("outliner last selection")
}

/// Where the outliner says, for this frame, that the selected row should scroll into view.
pub(super) fn reveal_id() -> egui::Id {
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

/// A small on/off toggle at the end of a row, named for screen readers and tests.
pub(super) fn toggle_ui(ui: &mut Ui, on: bool, text: &str, name: &str) -> egui::Response {
    ui.add(egui::Button::selectable(on, text).min_size(egui::vec2(TOGGLE_WIDTH, 0.0)))
        .accessible_name(name)
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
