//! Export PNG: renders in the background at the scene's resolution and samples (editable
//! in the window), with a progress bar and Cancel, and writes the file atomically. When
//! the file cannot be written the render is kept, so it can be saved elsewhere.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use egui::{DragValue, RichText, Ui};

use crate::preview::BackgroundJob;
use crate::scene::{MAX_IMAGE_SIDE, Scene};
use crate::trace::{Image, RenderOptions, World, render};
use crate::ui::document::files::{with_png_extension, write_png};

/// A render running on its own thread.
struct ExportJob {
    job: BackgroundJob<Image>,
    path: PathBuf,
    started: Instant,
}

/// The Export window's state.
#[derive(Default)]
pub struct ExportState {
    /// Whether the window is shown.
    pub open: bool,
    /// What to render: size and samples (the switches are always the full picture).
    pub settings: Option<RenderOptions>,
    /// Where to write, as typed or picked.
    pub path: String,
    job: Option<ExportJob>,
    kept: Option<Image>,
    /// The outcome of the last export: a message, or an error.
    pub status: Option<Result<String, String>>,
}

impl ExportState {
    /// Opens the window with the scene's size and samples; `default_path` fills an empty
    /// file field (e.g. the scene's file with `.png`).
    pub fn show(&mut self, scene: &Scene, default_path: Option<PathBuf>) {
        self.open = true;
        if self.path.trim().is_empty() {
            let path = default_path.unwrap_or_else(|| PathBuf::from("render.png"));
            self.path = path.display().to_string();
        }
        if self.job.is_none() {
            self.settings = Some(RenderOptions::from_scene(scene));
        }
    }

    /// Whether a render is running.
    #[must_use]
    pub fn is_running(&self) -> bool {
        self.job.is_some()
    }

    /// The finished render that could not be written, if any.
    #[must_use]
    pub fn kept_image(&self) -> Option<&Image> {
        self.kept.as_ref()
    }

    /// Starts rendering `scene` with the window's settings, to be written to `path`.
    /// `ctx` is repainted when the render ends.
    ///
    /// # Errors
    /// The scene cannot be rendered, or a render is already running.
    pub fn start(&mut self, scene: &Scene, path: &Path, ctx: &egui::Context) -> Result<(), String> {
        if self.job.is_some() {
            return Err("an export is already running".to_owned());
        }
        let options = self
            .settings
            .clone()
            .unwrap_or_else(|| RenderOptions::from_scene(scene));
        let world = World::new(scene).map_err(|e| format!("cannot render this scene: {e}"))?;
        let ctx = ctx.clone();
        let job = BackgroundJob::spawn(
            "export",
            move |progress| render(&world, &options, progress).map(|(image, _)| image),
            move || ctx.request_repaint(),
        )?;
        self.job = Some(ExportJob {
            job,
            path: path.to_owned(),
            started: Instant::now(),
        });
        self.status = None;
        Ok(())
    }

    /// Stops the running render at its next tile boundary.
    pub fn cancel(&self) {
        if let Some(job) = &self.job {
            job.job.cancel();
        }
    }

    /// Collects a finished render and writes it. Call every frame.
    pub fn poll(&mut self) {
        let Some(job) = &self.job else {
            return;
        };
        let Some(outcome) = job.job.try_result() else {
            return;
        };
        let elapsed = job.started.elapsed();
        let path = job.path.clone();
        self.job = None;
        match outcome {
            Ok(image) => self.write(image, &path, Some(elapsed)),
            Err(error) => self.status = Some(Err(error)),
        }
    }

    /// Writes the kept render to `path` (after a failed write).
    pub fn save_kept(&mut self, path: &Path) {
        if let Some(image) = self.kept.take() {
            self.write(image, path, None);
        }
    }

    fn write(&mut self, image: Image, path: &Path, elapsed: Option<Duration>) {
        match write_png(&image, path) {
            Ok(()) => {
                let time =
                    elapsed.map_or_else(String::new, |t| format!(" in {:.1} s", t.as_secs_f64()));
                self.status = Some(Ok(format!(
                    "Exported {} ({}×{}){time}",
                    path.display(),
                    image.width,
                    image.height
                )));
                self.kept = None;
            }
            Err(error) => {
                self.status = Some(Err(format!(
                    "{error}. The render is kept: choose another file."
                )));
                self.kept = Some(image);
            }
        }
    }

    /// Fraction of the running render done.
    #[must_use]
    pub fn progress(&self) -> Option<f64> {
        self.job.as_ref().map(|j| j.job.fraction())
    }
}

/// Shows the Export PNG window (when open).
pub fn export_window(ctx: &egui::Context, state: &mut ExportState, scene: &Scene) {
    let mut open = state.open;
    egui::Window::new("Export PNG")
        .open(&mut open)
        .resizable(false)
        .collapsible(false)
        .default_width(360.0)
        .pivot(egui::Align2::CENTER_CENTER)
        .default_pos(ctx.content_rect().center())
        .show(ctx, |ui| export_ui(ui, state, scene));
    state.open = open || state.is_running();
    state.poll();
    if state.is_running() {
        ctx.request_repaint_after(Duration::from_millis(100));
    }
}

fn export_ui(ui: &mut Ui, state: &mut ExportState, scene: &Scene) {
    let mut settings = state
        .settings
        .clone()
        .unwrap_or_else(|| RenderOptions::from_scene(scene));
    let running = state.is_running();
    ui.add_enabled_ui(!running, |ui| {
        egui::Grid::new("export settings")
            .num_columns(2)
            .spacing([12.0, 6.0])
            .show(ui, |ui| {
                ui.label("Width");
                ui.add(DragValue::new(&mut settings.width).range(1..=MAX_IMAGE_SIDE))
                    .accessible_name("export width");
                ui.end_row();
                ui.label("Height");
                ui.add(DragValue::new(&mut settings.height).range(1..=MAX_IMAGE_SIDE))
                    .accessible_name("export height");
                ui.end_row();
                ui.label("Samples");
                ui.add(DragValue::new(&mut settings.samples_per_pixel).range(1..=65536))
                    .accessible_name("export samples");
                ui.end_row();
                ui.label("File");
                ui.horizontal(|ui| {
                    ui.add(egui::TextEdit::singleline(&mut state.path).desired_width(220.0))
                        .accessible_name("export path");
                    if ui.button("Browse…").clicked()
                        && let Some(path) = rfd::FileDialog::new()
                            .add_filter("PNG image", &["png"])
                            .set_file_name("render.png")
                            .save_file()
                    {
                        state.path = with_png_extension(path).display().to_string();
                    }
                });
                ui.end_row();
            });
    });
    state.settings = Some(settings);
    ui.add_space(6.0);
    if let Some(progress) = state.progress() {
        ui.horizontal(|ui| {
            ui.add(
                egui::ProgressBar::new(progress as f32)
                    .show_percentage()
                    .desired_width(260.0),
            );
            if ui.button("Cancel").clicked() {
                state.cancel();
            }
        });
    } else {
        ui.horizontal(|ui| {
            let path = PathBuf::from(state.path.trim());
            let has_path = !state.path.trim().is_empty();
            if ui
                .add_enabled(has_path, egui::Button::new("Render and save"))
                .clicked()
            {
                let path = with_png_extension(path.clone());
                if let Err(error) = state.start(scene, &path, ui.ctx()) {
                    state.status = Some(Err(error));
                }
            }
            if state.kept_image().is_some()
                && ui
                    .add_enabled(has_path, egui::Button::new("Save kept render"))
                    .clicked()
            {
                state.save_kept(&with_png_extension(path));
            }
        });
    }
    match &state.status {
        Some(Ok(message)) => {
            ui.label(RichText::new(message).color(egui::Color32::from_rgb(140, 200, 140)));
        }
        Some(Err(error)) => {
            ui.label(RichText::new(error).color(egui::Color32::from_rgb(255, 120, 110)));
        }
        None => {}
    }
}
