//! The pixel inspector's window: the report laid out as text, bounce by bounce, with
//! every light of the scene and what it did. It opens beside the inspected pixel (not
//! over it), at its top for each new pixel, and the wheel scrolls it anywhere over it.

use egui::{Color32, Id, Pos2, Rect, RichText, Vec2};
use glam::DVec3;

use super::placement::Placement;
use super::{InspectedBounce, InspectedLight, InspectedPixel, PixelInspection};
use crate::trace::{BounceReport, Branch, LightRecord};
use crate::ui::commands::Command;
use crate::ui::state::RayPathSettings;

pub use crate::trace::switches_text;

/// Accessible name of the inspector window's final colour line.
pub const FINAL_COLOUR_LABEL: &str = "final colour";
/// The window's width and height, in points.
const WIDTH: f32 = 400.0;
const HEIGHT: f32 = 460.0;
/// The widest the user can make it; every line of the report fits in [`WIDTH`].
pub const MAX_WIDTH: f32 = WIDTH * 1.5;
/// Space between the inspected pixel and the window.
const GAP: f32 = 28.0;

/// Where the inspected pixel is on screen, and the screen the window stays on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelAnchor {
    /// The pixel's screen position.
    pub pos: Pos2,
    /// The viewport's rectangle (the window prefers to stay over it).
    pub viewport: Rect,
    /// The whole window's content (the inspector may cover side panels rather than
    /// the pixel).
    pub screen: Rect,
}

impl PixelAnchor {
    /// The top-left corner of a window of `size`: right of the pixel when it fits in
    /// the viewport, else left of it when that fits, else on the side with more room,
    /// never over the pixel while the screen has room beside it.
    pub(super) fn window_pos(&self, size: Vec2) -> Pos2 {
        let right = self.pos.x + GAP;
        let left = self.pos.x - GAP - size.x;
        let x = if right + size.x <= self.viewport.max.x {
            right
        } else if left >= self.viewport.min.x {
            left
        } else if self.screen.max.x - self.pos.x >= self.pos.x - self.screen.min.x {
            right.min(self.screen.max.x - size.x)
        } else {
            left.max(self.screen.min.x)
        };
        let y = (self.pos.y - 80.0).min(self.screen.max.y - size.y);
        Pos2::new(x, y.max(self.screen.min.y))
    }
}

/// What the window shows.
pub struct InspectorView<'a> {
    /// The inspected pixel.
    pub pixel: (u32, u32),
    /// Its newest inspection (`None` until the first one is traced).
    pub inspection: Option<&'a PixelInspection>,
    /// Whether that inspection describes the scene and switches as they are now.
    pub current: bool,
    /// The ray-path settings, for the pin button.
    pub ray_paths: &'a RayPathSettings,
    /// Where the pixel is on screen, if it is.
    pub anchor: Option<PixelAnchor>,
    /// Both pictures' values at the pixel, while a comparison is shown.
    pub compared: Option<crate::compare::PixelValues>,
}

/// The inspector window's id (its area's, in egui's memory).
#[must_use]
pub fn inspector_window_id() -> Id {
    Id::unique("raylab pixel inspector")
}

/// Shows the inspector window; closing it pushes [`Command::InspectPixel`]`(None)`.
pub fn pixel_inspector_ui(ctx: &egui::Context, view: &InspectorView, commands: &mut Vec<Command>) {
    let id = inspector_window_id();
    let screen = ctx.content_rect();
    let window = egui::Window::new("Pixel inspector")
        .id(id)
        .default_size([WIDTH, HEIGHT.min(screen.height() - 80.0)])
        // Wide content lines must not widen it over the pixel it sits beside; it never
        // runs past the bottom of the window (its content scrolls).
        .max_width(MAX_WIDTH)
        .max_height(screen.height() - 60.0)
        .constrain(true)
        .resizable(true);
    let placement = Placement::load(ctx, id);
    let before = ctx.memory(|m| m.area_rect(id));
    let (window, placed) = placement.place(
        ctx,
        window,
        view.pixel,
        view.anchor,
        Vec2::new(WIDTH, HEIGHT),
    );
    let window_rect = ctx.memory(|m| m.area_rect(id));
    let mut open = true;
    window.open(&mut open).show(ctx, |ui| {
        // A scroll position of its own per pixel: each new pixel opens at the top.
        egui::ScrollArea::vertical()
            .id_salt(("inspector scroll", view.pixel))
            .auto_shrink([true, false])
            .show(ui, |ui| {
                scroll_from_anywhere(ui, window_rect);
                contents_ui(ui, view, commands);
            });
    });
    // Moved this frame, and not by us: the user dragged it.
    let after = ctx.memory(|m| m.area_rect(id));
    if !placed
        && let (Some(before), Some(after)) = (before, after)
        && (after.min - before.min).length() > 0.5
    {
        Placement::moved_by_user(ctx, id);
    }
    if !open {
        Placement::forget(ctx, id);
        commands.push(Command::InspectPixel(None));
    }
}

/// The wheel over the window but outside the scroll area (its title bar) scrolls too.
fn scroll_from_anywhere(ui: &mut egui::Ui, window_rect: Option<Rect>) {
    // Through the context: `Ui::rect_contains_pointer` clips to the scroll area, which
    // would leave the title bar out.
    let over_window = window_rect.is_some_and(|r| ui.ctx().rect_contains_pointer(ui.layer_id(), r));
    let over_area = ui.rect_contains_pointer(ui.clip_rect());
    let delta = ui.input(|i| i.smooth_scroll_delta);
    if over_window && !over_area && delta != Vec2::ZERO {
        ui.scroll_with_delta(delta);
    }
}

fn contents_ui(ui: &mut egui::Ui, view: &InspectorView, commands: &mut Vec<Command>) {
    let (x, y) = view.pixel;
    ui.horizontal(|ui| {
        ui.label(RichText::new(format!("Pixel ({x}, {y})")).strong());
        let pinned = view.ray_paths.pinned.contains(&view.pixel);
        let text = if pinned { "Unpin" } else { "Pin" };
        if ui
            .button(text)
            .on_hover_text("Keep this pixel's rays drawn in the viewport")
            .clicked()
        {
            let mut settings = view.ray_paths.clone();
            settings.toggle_pin(view.pixel);
            commands.push(Command::SetRayPaths(settings));
        }
        if !view.current {
            ui.weak("updating…");
        }
    });
    let Some(inspection) = view.inspection else {
        ui.weak("Tracing…");
        return;
    };
    ui.weak(format!(
        "centre ray, beauty lighting · {}",
        switches_text(inspection.switches)
    ));
    ui.separator();
    if let Some(values) = &view.compared {
        super::compared::compared_ui(ui, values);
        ui.separator();
    }
    match &inspection.result {
        Ok(pixel) => pixel_ui(ui, pixel),
        Err(error) => {
            ui.colored_label(Color32::from_rgb(255, 120, 110), error);
        }
    }
}

fn pixel_ui(ui: &mut egui::Ui, pixel: &InspectedPixel) {
    for line in isolation_lines(pixel) {
        ui.label(RichText::new(line).color(crate::ui::style::ACCENT));
    }
    let report = &pixel.report;
    egui::Grid::new("final colour")
        .num_columns(2)
        .show(ui, |ui| {
            ui.label(FINAL_COLOUR_LABEL);
            ui.horizontal(|ui| {
                swatch_ui(ui, report.clamped);
                ui.monospace(colour_text(report.clamped));
            });
            ui.end_row();
            ui.label("before clamping");
            ui.monospace(colour_text(report.unclamped));
            ui.end_row();
        });
    for (index, (bounce, names)) in report.bounces.iter().zip(&pixel.bounces).enumerate() {
        egui::CollapsingHeader::new(RichText::new(bounce_title(bounce)).strong())
            .id_salt(("bounce", index))
            .default_open(true)
            .show(ui, |ui| bounce_ui(ui, index, bounce, names));
    }
}

/// "Camera ray", "Reflection, depth 2", "Refraction, depth 1 (from ray 1)", or
/// "Total internal reflection, depth 3 (from ray 2)": rays number from 1 in the order the
/// window lists them, named where a tree makes the parent ambiguous.
fn bounce_title(bounce: &BounceReport) -> String {
    let Some((parent, branch)) = bounce.from else {
        return "Camera ray".to_owned();
    };
    let what = match branch {
        Branch::Mirror => "Reflection",
        Branch::Refracted => "Refraction",
        Branch::InternallyReflected => "Total internal reflection",
    };
    let depth = bounce.depth;
    if parent + 1 == depth as usize {
        format!("{what}, depth {depth}")
    } else {
        format!("{what}, depth {depth} (from ray {})", parent + 1)
    }
}

fn bounce_ui(ui: &mut egui::Ui, index: usize, bounce: &BounceReport, names: &InspectedBounce) {
    let (Some(hit), Some(hit_names)) = (&bounce.hit, &names.hit) else {
        egui::Grid::new(("miss", index))
            .num_columns(2)
            .show(ui, |ui| {
                ui.label("hit");
                ui.label("nothing (background)");
                ui.end_row();
                number_row_ui(ui, "colour", colour_text(bounce.colour));
            });
        return;
    };
    egui::Grid::new(("hit", index))
        .num_columns(2)
        .show(ui, |ui| {
            ui.label("hit");
            ui.label(RichText::new(&hit_names.object).strong());
            ui.end_row();
            ui.label("material");
            ui.label(&hit_names.material);
            ui.end_row();
            number_row_ui(ui, "t", format!("{:.6}", hit.t));
            number_row_ui(ui, "point", vector_text(hit.p));
            number_row_ui(ui, "normal", vector_text(hit.n));
            number_row_ui(ui, "ambient", colour_text(bounce.ambient));
        });
    for light in &names.lights {
        light_ui(ui, light, index);
    }
    if names.lights.is_empty() {
        ui.weak("the scene has no lights");
    }
    egui::Grid::new(("result", index))
        .num_columns(2)
        .show(ui, |ui| {
            // One colour per row: all three on one line would widen the window over
            // the pixel it sits beside.
            match bounce.reflection {
                Some((km, reflected)) => {
                    number_row_ui(ui, "mirror km", colour_text(km));
                    number_row_ui(ui, "reflected", colour_text(reflected));
                    number_row_ui(ui, "km × reflected", colour_text(km * reflected));
                }
                None => {
                    ui.label("reflection");
                    ui.weak("no mirror ray");
                    ui.end_row();
                }
            }
            if let Some((kt, transmitted)) = bounce.transmission {
                number_row_ui(ui, "transmission kt", colour_text(kt));
                number_row_ui(ui, "transmitted", colour_text(transmitted));
                number_row_ui(ui, "kt × transmitted", colour_text(kt * transmitted));
            }
            if let Some(unclamped) = bounce.unclamped {
                number_row_ui(ui, "before each-ray clamp", colour_text(unclamped));
            }
            number_row_ui(ui, "colour", colour_text(bounce.colour));
        });
}

/// One light: its name, what it did (green when it added light), and the numbers.
fn light_ui(ui: &mut egui::Ui, light: &InspectedLight, bounce: usize) {
    ui.horizontal(|ui| {
        ui.label(RichText::new(&light.label).underline());
        let colour = if light.adds_light {
            Color32::from_rgb(140, 220, 140)
        } else {
            Color32::from_gray(160)
        };
        ui.label(RichText::new(&light.outcome).color(colour));
    });
    let Some(record) = &light.record else {
        return;
    };
    egui::Grid::new(("light", bounce, light.scene_index))
        .num_columns(2)
        .show(ui, |ui| {
            number_row_ui(ui, "strength", colour_text(record.strength));
            number_row_ui(ui, "n·l", format!("{:.4}", record.n_dot_l));
            ui.label("shadow ray");
            ui.label(shadow_text(record));
            ui.end_row();
            number_row_ui(ui, "diffuse", colour_text(record.diffuse));
            number_row_ui(ui, "specular", colour_text(record.specular));
        });
}

/// What a light's shadow rays found: "blocked", "12 of 16 reach the light (vis 0.75)".
fn shadow_text(record: &LightRecord) -> String {
    let (fraction, rays) = record.visibility;
    if !record.shadow_ray_cast {
        return if record.n_dot_l <= 0.0 {
            "not cast (light behind the surface)"
        } else {
            "not cast (shadows off)"
        }
        .to_owned();
    }
    if rays > 1 {
        let reach = (fraction * f64::from(rays)).round();
        return format!("{reach} of {rays} reach the light (vis {fraction:.3})");
    }
    if record.blocked_by.is_some() {
        "blocked".to_owned()
    } else {
        "cast, reaches the light".to_owned()
    }
}

/// What the isolation switches leave out of every bounce, one line each:
/// "off (muted or not solo): Point light 2" and "hidden (rays pass through): red ball".
#[must_use]
pub fn isolation_lines(pixel: &InspectedPixel) -> Vec<String> {
    let mut lines = Vec::new();
    if !pixel.lights_off.is_empty() {
        lines.push(format!(
            "off (muted or not solo): {}",
            pixel.lights_off.join(", ")
        ));
    }
    if !pixel.hidden_objects.is_empty() {
        lines.push(format!(
            "hidden (rays pass through): {}",
            pixel.hidden_objects.join(", ")
        ));
    }
    lines
}

/// One grid row: a label and a number in monospace.
fn number_row_ui(ui: &mut egui::Ui, label: &str, value: String) {
    ui.label(label);
    ui.monospace(value);
    ui.end_row();
}

fn swatch_ui(ui: &mut egui::Ui, colour: DVec3) {
    let (rect, _) = ui.allocate_exact_size(egui::vec2(14.0, 14.0), egui::Sense::hover());
    let [r, g, b] = colour.as_vec3().to_array().map(crate::trace::encode_linear);
    ui.painter()
        .rect_filled(rect, 2.0, Color32::from_rgb(r, g, b));
}

fn colour_text(c: DVec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", c.x, c.y, c.z)
}

fn vector_text(v: DVec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", v.x, v.y, v.z)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::{Term, TermSwitches};

    #[test]
    fn switches_read_as_on_the_command_line() {
        let mut switches = TermSwitches::ALL_ON;
        assert_eq!(switches_text(switches), "all terms on");
        switches.set(Term::Diffuse, false);
        switches.set(Term::Shadows, false);
        assert_eq!(
            switches_text(switches.with_solo(Some(Term::Specular))),
            "off: diffuse, shadows · solo specular"
        );
    }

    #[test]
    fn the_window_sits_beside_the_pixel_on_the_side_with_room() {
        let viewport = Rect::from_min_size(Pos2::new(200.0, 80.0), Vec2::new(800.0, 600.0));
        let screen = Rect::from_min_size(Pos2::ZERO, Vec2::new(1280.0, 800.0));
        let size = Vec2::new(WIDTH, HEIGHT);
        let at = |x: f32| PixelAnchor {
            pos: Pos2::new(x, 300.0),
            viewport,
            screen,
        };
        assert!(
            at(300.0).window_pos(size).x > 300.0,
            "right of a pixel on the left"
        );
        assert!(
            at(900.0).window_pos(size).x + WIDTH < 900.0,
            "left of a pixel on the right"
        );
        // In the middle of a viewport too narrow for either side: over a side panel.
        let narrow = Rect::from_min_size(Pos2::new(230.0, 80.0), Vec2::new(700.0, 600.0));
        let middle = PixelAnchor {
            viewport: narrow,
            ..at(600.0)
        };
        for anchor in [at(300.0), at(900.0), middle] {
            let window = Rect::from_min_size(anchor.window_pos(size), size);
            assert!(
                !window.contains(anchor.pos),
                "not over the pixel: {window:?}"
            );
            assert!(screen.contains_rect(window), "on screen: {window:?}");
        }
    }
}
