//! The inspector's page layout: a heading naming what is shown, and the two-column grid
//! its rows go in.

use egui::Ui;

/// The page's heading: the kind of thing shown, small, then its name.
pub(super) fn heading_ui(ui: &mut Ui, kind: &str, title: &str) {
    ui.add_space(4.0);
    ui.horizontal(|ui| {
        ui.label(egui::RichText::new(kind).small().weak());
        ui.heading(title);
    });
    ui.separator();
}

/// A two-column grid of labelled rows.
pub(super) fn grid_ui(ui: &mut Ui, id: &str, rows: impl FnOnce(&mut Ui)) {
    egui::Grid::new(id)
        .num_columns(2)
        .spacing([12.0, 6.0])
        .min_col_width(72.0)
        .show(ui, rows);
}
