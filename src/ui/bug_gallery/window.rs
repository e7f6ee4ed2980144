//! The Bug gallery window: progress with Cancel while the gallery renders, a notice with
//! Refresh once the scene has changed since, and the thumbnails in a scrolled grid of
//! fixed cells (raylab's own first), each captioned with its bug and what the bug is in
//! a tracer's code. Clicking one pushes [`Command::CompareWithGalleryPicture`].

use std::path::Path;
use std::time::Duration;

use egui::{Color32, ColorImage, RichText, TextureOptions, Ui, Vec2};

use super::state::{BugGallery, Thumbnail};
use crate::scene::Scene;
use crate::ui::commands::Command;

/// Accessible name of raylab's own picture's thumbnail.
pub const OWN_PICTURE_LABEL: &str = "Bug gallery picture: raylab (no bug)";

/// Width of a thumbnail, in points.
const THUMBNAIL_WIDTH: f32 = 200.0;

/// Room under each thumbnail for its caption, in points (the cells are all one size,
/// so the grid never moves as captions differ).
const CAPTION_HEIGHT: f32 = 64.0;

/// The accessible name of the thumbnail of the picture labelled `label` (the bug as
/// `raylab render --bug` takes it).
#[must_use]
pub fn thumbnail_label(label: &str) -> String {
    format!("Bug gallery picture: {label}")
}

/// Shows the window when open and polls the job. `folder` is the scene file's, where
/// its mesh files are.
pub fn bug_gallery_window(
    ctx: &egui::Context,
    gallery: &mut BugGallery,
    scene: &Scene,
    folder: Option<&Path>,
    commands: &mut Vec<Command>,
) {
    gallery.poll();
    if gallery.is_running() {
        ctx.request_repaint_after(Duration::from_millis(100));
    }
    if !gallery.open {
        return;
    }
    let mut open = true;
    let content = ctx.content_rect();
    egui::Window::new("Bug gallery")
        .open(&mut open)
        .collapsible(false)
        .resizable(true)
        .default_size([2.0 * THUMBNAIL_WIDTH + 80.0, 560.0])
        .pivot(egui::Align2::RIGHT_TOP)
        .default_pos(content.right_top() + Vec2::new(-250.0, 60.0))
        .show(ctx, |ui| window_ui(ui, gallery, scene, folder, commands));
    if !open {
        gallery.cancel();
        gallery.open = false;
    }
}

fn window_ui(
    ui: &mut Ui,
    gallery: &mut BugGallery,
    scene: &Scene,
    folder: Option<&Path>,
    commands: &mut Vec<Command>,
) {
    ui.label("This scene as a tracer with each known bug would render it. Click a picture to compare the scene with it and read what the diff says.");
    ui.add_space(4.0);
    status_ui(ui, gallery, scene, folder);
    ui.separator();
    let stale = gallery.is_stale(scene);
    egui::ScrollArea::vertical()
        .auto_shrink([false, false])
        .show(ui, |ui| grid_ui(ui, gallery, stale, commands));
}

/// One line, always there: progress and Cancel, the stale notice and Refresh, or the
/// error (so the grid below does not move when it changes).
fn status_ui(ui: &mut Ui, gallery: &mut BugGallery, scene: &Scene, folder: Option<&Path>) {
    ui.horizontal(|ui| {
        ui.set_min_height(24.0);
        if let Some(progress) = gallery.progress() {
            ui.spinner();
            let bugs = gallery.bugs_to_try().unwrap_or(0);
            ui.label(format!("Rendering the scene under {bugs} bugs…"));
            ui.add(
                egui::ProgressBar::new(progress as f32)
                    .desired_width(120.0)
                    .text("this picture"),
            );
            if ui.button("Cancel").clicked() {
                gallery.cancel();
            }
        } else if gallery.is_stale(scene) || gallery.thumbnails().is_empty() {
            let text = if gallery.thumbnails().is_empty() {
                "No gallery yet."
            } else {
                "The scene has changed since these pictures were made."
            };
            ui.label(RichText::new(text).color(Color32::from_rgb(255, 200, 120)));
            if ui.button("Refresh").clicked() {
                gallery.start(scene, folder, ui.ctx());
            }
        } else {
            let shown = gallery.thumbnails().len().saturating_sub(1);
            let left_out = gallery.left_out();
            let label = ui.weak(format!("{shown} bugs show in this scene."));
            if !left_out.is_empty() {
                label.on_hover_text(format!("Not in the gallery:\n{}", left_out.join("\n")));
            }
        }
    });
    if let Some(error) = gallery.error() {
        ui.label(RichText::new(error).color(Color32::from_rgb(255, 120, 110)));
    }
}

/// The thumbnails in rows of as many as fit.
fn grid_ui(ui: &mut Ui, gallery: &mut BugGallery, stale: bool, commands: &mut Vec<Command>) {
    let ctx = ui.ctx().clone();
    let spacing = ui.spacing().item_spacing.x;
    let columns = ((ui.available_width() + spacing) / (THUMBNAIL_WIDTH + spacing))
        .floor()
        .max(1.0) as usize;
    let thumbnails = gallery.thumbnails_mut();
    for (row, chunk) in thumbnails.chunks_mut(columns).enumerate() {
        ui.horizontal_top(|ui| {
            for (column, thumbnail) in chunk.iter_mut().enumerate() {
                let index = row * columns + column;
                if thumbnail_ui(ui, &ctx, thumbnail, stale) {
                    commands.push(Command::CompareWithGalleryPicture(index));
                }
            }
        });
        ui.add_space(6.0);
    }
}

/// One cell: the picture (a button, disabled while stale) and its caption. True when
/// clicked.
fn thumbnail_ui(ui: &mut Ui, ctx: &egui::Context, thumbnail: &mut Thumbnail, stale: bool) -> bool {
    let picture = &thumbnail.picture;
    let texture = thumbnail.texture.get_or_insert_with(|| {
        let size = [picture.width as usize, picture.height as usize];
        let pixels = picture
            .rgb
            .iter()
            .map(|&[r, g, b]| Color32::from_rgb(r, g, b));
        ctx.load_texture(
            format!("bug gallery {}", thumbnail.label),
            ColorImage::new(size, pixels.collect()),
            TextureOptions::LINEAR,
        )
    });
    let aspect = picture.height as f32 / picture.width.max(1) as f32;
    let size = Vec2::new(THUMBNAIL_WIDTH, THUMBNAIL_WIDTH * aspect);
    let (label, in_code, share) = (
        &thumbnail.label,
        &thumbnail.in_code,
        thumbnail.changed_share,
    );
    ui.vertical(|ui| {
        ui.set_width(THUMBNAIL_WIDTH);
        let image = egui::Image::new((texture.id(), size));
        let hover = if stale {
            "The scene has changed since: Refresh first".to_owned()
        } else {
            format!("Compare the scene with this picture ({label})")
        };
        let clicked = ui
            .add_enabled(!stale, egui::Button::image(image).frame(false))
            .on_hover_text(&hover)
            .on_disabled_hover_text(&hover)
            .accessible_name(thumbnail_label(label))
            .clicked();
        ui.allocate_ui(Vec2::new(THUMBNAIL_WIDTH, CAPTION_HEIGHT), |ui| {
            ui.set_min_size(Vec2::new(THUMBNAIL_WIDTH, CAPTION_HEIGHT));
            ui.add(egui::Label::new(RichText::new(label).strong()).truncate());
            let line = match share {
                Some(share) => format!("{in_code} · {:.1}% of pixels", 100.0 * share),
                None => in_code.clone(),
            };
            ui.add(egui::Label::new(RichText::new(line).small().weak()).wrap());
        });
        clicked
    })
    .inner
}
