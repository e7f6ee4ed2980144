//! The pixel inspector's window (its contents are laid out in `report_view.rs`). It
//! opens beside the inspected pixel (not over it), at its top for each new pixel, and the
//! wheel scrolls it anywhere over it.

use egui::{Color32, Id, Rect, RichText, Vec2};

use super::inspection::PixelInspection;
use super::placement::{PixelAnchor, Placement};
use super::report_view::pixel_ui;
use crate::ui::commands::Command;
use crate::ui::state::RayPathSettings;

pub use crate::trace::switches_text;

/// The window's width and height, in points.
const WIDTH: f32 = 400.0;
const HEIGHT: f32 = 460.0;
/// The widest the user can make it; every line of the report fits in [`WIDTH`].
pub const MAX_WIDTH: f32 = WIDTH * 1.5;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trace::{Term, TermSwitches};
    use egui::Pos2;

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
