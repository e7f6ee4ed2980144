//! The editor's look: dark, quiet panels around a dominant viewport, one warm accent.

use egui::{Color32, CornerRadius, Stroke, Theme, Visuals};

/// The accent colour (selection, focus).
pub const ACCENT: Color32 = Color32::from_rgb(255, 170, 60);

/// Sets the fonts, the dark theme, spacing and colours. Fonts apply from the next pass.
pub fn apply_style(ctx: &egui::Context) {
    // The outliner's icons are geometric shapes that Hack has and Ubuntu-Light lacks.
    let mut fonts = egui::FontDefinitions::default();
    if let Some(family) = fonts.families.get_mut(&egui::FontFamily::Proportional) {
        family.push("Hack".to_owned());
    }
    ctx.set_fonts(fonts);
    ctx.set_theme(Theme::Dark);
    let mut visuals = Visuals::dark();
    visuals.panel_fill = Color32::from_gray(30);
    visuals.window_fill = Color32::from_gray(34);
    visuals.extreme_bg_color = Color32::from_gray(20);
    visuals.faint_bg_color = Color32::from_gray(36);
    visuals.selection.bg_fill = Color32::from_rgb(128, 78, 24);
    visuals.selection.stroke = Stroke::new(1.0, Color32::from_rgb(255, 236, 214));
    visuals.widgets.noninteractive.bg_stroke = Stroke::new(1.0, Color32::from_gray(48));
    visuals.widgets.inactive.corner_radius = CornerRadius::same(3);
    visuals.widgets.hovered.corner_radius = CornerRadius::same(3);
    visuals.widgets.active.corner_radius = CornerRadius::same(3);
    visuals.window_corner_radius = CornerRadius::same(6);
    ctx.set_visuals_of(Theme::Dark, visuals);
    ctx.style_mut_of(Theme::Dark, |style| {
        style.spacing.item_spacing = egui::vec2(8.0, 5.0);
        style.spacing.button_padding = egui::vec2(7.0, 3.0);
        style.spacing.interact_size.y = 22.0;
        style.spacing.indent = 14.0;
    });
}
