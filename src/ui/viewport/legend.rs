//! A legend for the debug views, in the picture's bottom-right corner: what the depth
//! view's greys, the object-id view's colours, the normal view's hues and the shadow
//! mask's greys mean. The lit picture needs none.

use egui::{Align2, Color32, Rect, RichText, Vec2};

use crate::scene::Scene;
use crate::trace::{View, encode_linear, object_id_colour};

/// Objects listed by the object-id legend; the rest are counted.
const LISTED_OBJECTS: usize = 8;

/// The legend of `view` over `picture`.
pub fn view_legend_ui(ui: &egui::Ui, picture: Rect, view: View, scene: &Scene) {
    if view == View::Beauty || picture.width() < 160.0 {
        return;
    }
    egui::Area::new(egui::Id::unique("raylab view legend"))
        .order(egui::Order::Middle)
        .pivot(Align2::RIGHT_BOTTOM)
        .fixed_pos(picture.right_bottom() - Vec2::splat(8.0))
        .interactable(false)
        .show(ui.ctx(), |ui| {
            egui::Frame::new()
                .fill(Color32::from_black_alpha(170))
                .inner_margin(6.0)
                .corner_radius(4.0)
                .show(ui, |ui| {
                    ui.set_max_width(picture.width().min(260.0));
                    ui.spacing_mut().item_spacing.y = 1.0;
                    legend_lines(ui, view, scene);
                });
        });
}

fn legend_lines(ui: &mut egui::Ui, view: View, scene: &Scene) {
    let small = |text: &str| {
        RichText::new(text.to_owned())
            .small()
            .color(Color32::from_gray(220))
    };
    match view {
        View::Beauty => {}
        View::Depth => {
            ui.horizontal(|ui| {
                ui.label(small("depth: near"));
                let (rect, _) = ui.allocate_exact_size(Vec2::new(70.0, 10.0), egui::Sense::hover());
                for i in 0..14 {
                    let grey = 1.0 - (1.0 - 0.15) * i as f32 / 13.0;
                    let x = rect.min.x + rect.width() * i as f32 / 14.0;
                    let cell = Rect::from_min_size(
                        egui::pos2(x, rect.min.y),
                        Vec2::new(rect.width() / 14.0 + 0.5, rect.height()),
                    );
                    ui.painter()
                        .rect_filled(cell, 0.0, Color32::from_gray(encode_linear(grey)));
                }
                ui.label(small("far"));
            });
            ui.label(small(
                "the distances the camera sees, white to dark grey; black: no hit",
            ));
        }
        View::ObjectId => {
            ui.label(small("object id: a flat colour per object"));
            for (index, object) in scene.objects.iter().enumerate().take(LISTED_OBJECTS) {
                let [r, g, b] = object_id_colour(index)
                    .as_vec3()
                    .to_array()
                    .map(encode_linear);
                ui.horizontal(|ui| {
                    let (rect, _) = ui.allocate_exact_size(Vec2::splat(10.0), egui::Sense::hover());
                    ui.painter()
                        .rect_filled(rect, 2.0, Color32::from_rgb(r, g, b));
                    ui.label(small(&object.name));
                });
            }
            let more = scene.objects.len().saturating_sub(LISTED_OBJECTS);
            if more > 0 {
                ui.label(small(&format!(
                    "and {more} more (a group's members share its colour)"
                )));
            }
        }
        View::Normal => {
            ui.label(small("normal: (n + 1) / 2 as colour, facing the ray"));
            ui.label(small(
                "+x red, +y green, +z blue; (0.5, 0.5, 0.5) is no normal",
            ));
        }
        View::ShadowMask => {
            ui.label(small(
                "shadow mask: the share of facing lights reaching each point",
            ));
            ui.label(small(
                "white: all of them; black: none (or no light faces it)",
            ));
        }
    }
}
