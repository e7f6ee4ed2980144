//! Export PNG: reads the scene's mesh files the way the preview does
//! ([`MeshCache::read`], from the scene file's folder) and renders in the background at
//! the scene's resolution and samples (editable in the window), either the full picture
//! or as the viewport shows it, then encodes and
//! writes the file atomically on the same background thread, so the window never waits
//! for the encoder or the disk. When the file cannot be written the render is kept, so it
//! can be saved elsewhere. A size that cannot fit in memory is refused before anything is
//! allocated.

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, PoisonError};
use std::time::{Duration, Instant};

use crate::preview::{BackgroundJob, MeshCache};
use crate::scene::{LoadWatch, MAX_IMAGE_SIDE, Scene};
use crate::trace::{Image, Isolation, MeshStore, RenderOptions, World, render};
use crate::ui::document::files::write_png;
use crate::ui::state::PreviewSettings;

/// What the viewport shows: its term switches and view, and the mute, solo and hide
/// switches; "as the viewport shows it" exports with all of them.
#[derive(Clone, Copy, Debug)]
pub struct ViewportLook<'a> {
    /// The toolbar's switches and view.
    pub settings: &'a PreviewSettings,
    /// The isolation switches.
    pub isolation: &'a Isolation,
}

/// Peak bytes an export needs per pixel: the sample sums (f64 RGB) and the tiles they are
/// gathered from, the averaged image (f32 RGB), and the 8-bit rows and encoded PNG.
pub const EXPORT_BYTES_PER_PIXEL: u64 = 24 + 24 + 12 + 3 + 3;

/// What an export job hands back: the image, and whether it reached the file.
struct Written {
    image: Image,
    written: Result<(), String>,
}

/// What a running export is doing, shown on its progress bar.
#[derive(Clone, Debug, PartialEq)]
pub enum ExportStage {
    /// Reading a mesh file (the path as the scene writes it), as the preview reads it.
    ReadingMesh {
        /// The mesh's path as the scene writes it.
        path: String,
        /// Fraction of the file read.
        fraction: f64,
    },
    /// Rendering (the job's own progress).
    Rendering,
}

impl std::fmt::Display for ExportStage {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::ReadingMesh { path, fraction } => write!(
                f,
                "reading the mesh \"{path}\" as the preview does: {:.0}%",
                fraction * 100.0
            ),
            Self::Rendering => f.write_str("rendering"),
        }
    }
}

/// The mesh file an export is reading (as the scene writes its path), and its progress.
type MeshReading = Arc<Mutex<Option<(String, Arc<LoadWatch>)>>>;

/// A render (or a write of the kept render) running on its own thread.
struct ExportJob {
    job: BackgroundJob<Result<Written, String>>,
    path: PathBuf,
    started: Instant,
    /// Whether the job renders (false: it only writes the kept render).
    renders: bool,
    /// The mesh file being read before the render starts, if any.
    reading: MeshReading,
}

/// The Export window's state.
#[derive(Default)]
pub struct ExportState {
    /// Whether the window is shown.
    pub open: bool,
    /// What to render: size and samples; the switches and view when `as_shown`.
    pub settings: Option<RenderOptions>,
    /// Export with the viewport's switches, solo and view instead of the full picture.
    pub as_shown: bool,
    /// Width and height keep `aspect` when one of them is edited.
    pub keep_aspect: bool,
    /// Width over height, as linked.
    pub aspect: f64,
    /// Where to write, as typed or picked.
    pub path: String,
    /// The document the file field was last proposed for: another document gets a
    /// fresh proposal; the same one keeps what the user typed or picked.
    proposed_for: Option<Option<PathBuf>>,
    /// The folder of the last file written: the next export is proposed there.
    pub last_folder: Option<PathBuf>,
    job: Option<ExportJob>,
    kept: Option<Image>,
    /// How the kept render's pixels become bytes (its scene's conventions).
    kept_quantise: crate::scene::Quantise,
    /// The outcome of the last export: a message, or an error.
    pub status: Option<Result<String, String>>,
    /// Bytes an export may use (tests set it; by default the memory available now).
    pub memory_budget: Option<u64>,
}

impl ExportState {
    /// Opens the window with the scene's size and samples. For another `document` than
    /// last time (its file, or the course file it was imported from), or an empty file
    /// field, the field gets `NAME.png` (the document's name) in the last export's
    /// folder, else the user's pictures or home folder; never beside the scene (a shipped
    /// example's folder is nobody's output folder).
    pub fn show(&mut self, scene: &Scene, document: Option<&Path>) {
        self.open = true;
        let document = document.map(Path::to_owned);
        let fresh = self.proposed_for.as_ref() != Some(&document) || self.path.trim().is_empty();
        if fresh && self.job.is_none() {
            let name = document
                .as_deref()
                .and_then(Path::file_stem)
                .map_or_else(|| "render".into(), |s| s.to_string_lossy());
            let file = format!("{name}.png");
            let folder = self.last_folder.clone().or_else(pictures_or_home);
            let path = folder.map_or_else(|| PathBuf::from(&file), |f| f.join(&file));
            self.path = path.display().to_string();
            self.proposed_for = Some(document);
        }
        if self.job.is_none() {
            self.settings = Some(RenderOptions::from_scene(scene));
            self.keep_aspect = true;
            self.aspect = f64::from(scene.camera.width) / f64::from(scene.camera.height.max(1));
        }
    }

    /// Whether a render or a write is running.
    #[must_use]
    pub fn is_running(&self) -> bool {
        self.job.is_some()
    }

    /// Whether the running job renders (its progress means something).
    #[must_use]
    pub fn is_rendering(&self) -> bool {
        self.job.as_ref().is_some_and(|j| j.renders)
    }

    /// The finished render that could not be written, if any.
    #[must_use]
    pub fn kept_image(&self) -> Option<&Image> {
        self.kept.as_ref()
    }

    /// What the export renders: the window's size and samples, with the full picture's
    /// switches, or the viewport's when `as_shown`.
    #[must_use]
    pub fn options(&self, scene: &Scene, shown: ViewportLook<'_>) -> RenderOptions {
        let sized = self
            .settings
            .clone()
            .unwrap_or_else(|| RenderOptions::from_scene(scene));
        let looks = if self.as_shown {
            RenderOptions {
                isolation: shown.isolation.clone(),
                ..shown.settings.render_options(scene)
            }
        } else {
            RenderOptions::from_scene(scene)
        };
        RenderOptions {
            width: sized.width,
            height: sized.height,
            samples_per_pixel: sized.samples_per_pixel,
            ..looks
        }
    }

    /// Starts rendering `scene` with the window's settings, to be written to `path`. Its
    /// mesh files are read first, on the job's thread, from `folder` (the scene file's)
    /// exactly as the preview reads them.
    /// `ctx` is repainted when the job ends.
    ///
    /// # Errors
    /// The image would not fit in memory, or a job is already running. (A scene that
    /// cannot be rendered, or a mesh that cannot be read, ends the job with its error.)
    pub fn start(
        &mut self,
        scene: &Scene,
        folder: Option<&Path>,
        shown: ViewportLook<'_>,
        path: &Path,
        ctx: &egui::Context,
    ) -> Result<(), String> {
        if self.job.is_some() {
            return Err("an export is already running".to_owned());
        }
        let options = self.options(scene, shown);
        let budget = self.memory_budget.or_else(available_memory_bytes);
        check_export_memory(options.width, options.height, budget)?;
        let target = path.to_owned();
        let ctx = ctx.clone();
        let quantise = scene.render.conventions.quantise;
        self.kept_quantise = quantise;
        let scene = scene.clone();
        let folder = folder.map(Path::to_path_buf);
        let reading = MeshReading::default();
        let job_reading = Arc::clone(&reading);
        let job = BackgroundJob::spawn(
            "export",
            move |progress| {
                let meshes = read_meshes(&scene, folder.as_deref(), &job_reading);
                let world = meshes
                    .and_then(|meshes| {
                        World::isolated_with_meshes(&scene, &options.isolation, &meshes)
                            .map_err(|e| e.to_string())
                    })
                    .map_err(|e| format!("cannot render this scene: {e}"));
                let world = match world {
                    Ok(world) => world,
                    // A read cancelled with the export ends as the render's cancel does.
                    Err(_) if progress.is_cancelled() => return None,
                    Err(error) => return Some(Err(error)),
                };
                let (image, _) = render(&world, &options, progress)?;
                let written = write_png(&image, &target, quantise);
                Some(Ok(Written { image, written }))
            },
            move || ctx.request_repaint(),
        )?;
        self.run(job, path, true);
        if let Some(running) = &mut self.job {
            running.reading = reading;
        }
        Ok(())
    }

    fn run(&mut self, job: BackgroundJob<Result<Written, String>>, path: &Path, renders: bool) {
        self.job = Some(ExportJob {
            job,
            path: path.to_owned(),
            started: Instant::now(),
            renders,
            reading: MeshReading::default(),
        });
        self.status = None;
    }

    /// What the running export is doing: reading a mesh file or rendering.
    #[must_use]
    pub fn stage(&self) -> Option<ExportStage> {
        let job = self.job.as_ref()?;
        let reading = job.reading.lock().unwrap_or_else(PoisonError::into_inner);
        Some(match &*reading {
            Some((path, watch)) => ExportStage::ReadingMesh {
                path: path.clone(),
                fraction: watch.fraction(),
            },
            None => ExportStage::Rendering,
        })
    }

    /// Stops the running render at its next tile boundary (or the mesh file being read).
    pub fn cancel(&self) {
        if let Some(job) = &self.job {
            job.job.cancel();
            let reading = job.reading.lock().unwrap_or_else(PoisonError::into_inner);
            if let Some((_, watch)) = &*reading {
                watch.cancel();
            }
        }
    }

    /// Collects a finished job. Call every frame.
    pub fn poll(&mut self) {
        let Some(job) = &self.job else {
            return;
        };
        let Some(outcome) = job.job.try_result() else {
            return;
        };
        let elapsed = job.renders.then(|| job.started.elapsed());
        let path = job.path.clone();
        self.job = None;
        match outcome {
            Ok(Ok(Written { image, written })) => self.finish(image, written, &path, elapsed),
            Ok(Err(error)) | Err(error) => self.status = Some(Err(error)),
        }
    }

    /// Writes the kept render to `path` (after a failed write), in the background.
    ///
    /// # Errors
    /// The thread cannot start, or a job is already running.
    pub fn save_kept(&mut self, path: &Path, ctx: &egui::Context) -> Result<(), String> {
        if self.job.is_some() {
            return Err("an export is already running".to_owned());
        }
        let Some(image) = self.kept.take() else {
            return Ok(());
        };
        let target = path.to_owned();
        let ctx = ctx.clone();
        let quantise = self.kept_quantise;
        let job = BackgroundJob::spawn(
            "export",
            move |_| {
                let written = write_png(&image, &target, quantise);
                Some(Ok(Written { image, written }))
            },
            move || ctx.request_repaint(),
        )?;
        self.run(job, path, false);
        Ok(())
    }

    fn finish(
        &mut self,
        image: Image,
        written: Result<(), String>,
        path: &Path,
        elapsed: Option<Duration>,
    ) {
        match written {
            Ok(()) => {
                self.last_folder = path
                    .parent()
                    .filter(|f| !f.as_os_str().is_empty())
                    .map(Path::to_owned);
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

    /// Sets the width (or the height, `height_edited`), the other side following the
    /// linked aspect ratio when `keep_aspect` is on.
    pub fn resize(&mut self, width: u32, height: u32, height_edited: bool) {
        let Some(settings) = &mut self.settings else {
            return;
        };
        let side = |x: f64| (x.round() as u32).clamp(1, MAX_IMAGE_SIDE);
        (settings.width, settings.height) = match (self.keep_aspect, height_edited) {
            (false, _) => (width, height),
            (true, false) => (width, side(f64::from(width) / self.aspect)),
            (true, true) => (side(f64::from(height) * self.aspect), height),
        };
    }
}

/// The meshes `scene` refers to, read from `folder` by the preview's [`MeshCache`], each
/// file announced in `reading` while it is read.
fn read_meshes(
    scene: &Scene,
    folder: Option<&Path>,
    reading: &MeshReading,
) -> Result<MeshStore, String> {
    let mut announce = |path: &str| {
        let watch = Arc::new(LoadWatch::default());
        *reading.lock().unwrap_or_else(PoisonError::into_inner) =
            Some((path.to_owned(), Arc::clone(&watch)));
        watch
    };
    let meshes = MeshCache::default().read(scene, folder, &MeshStore::default(), &mut announce);
    *reading.lock().unwrap_or_else(PoisonError::into_inner) = None;
    meshes
}

/// Refuses a `width` x `height` export that needs more than `budget` bytes (none: no
/// limit known), with the numbers in the message.
///
/// # Errors
/// The message for the user.
pub fn check_export_memory(width: u32, height: u32, budget: Option<u64>) -> Result<(), String> {
    let needed = u64::from(width) * u64::from(height) * EXPORT_BYTES_PER_PIXEL;
    match budget {
        Some(budget) if needed > budget => Err(format!(
            "a {width}×{height} export needs about {:.1} GB of memory and {:.1} GB is \
             available: choose a smaller size",
            needed as f64 / 1e9,
            budget as f64 / 1e9
        )),
        _ => Ok(()),
    }
}

/// The user's pictures folder (`$XDG_PICTURES_DIR`, else `~/Pictures` where it exists),
/// else the home folder; `None` without a home.
#[must_use]
pub fn pictures_or_home() -> Option<PathBuf> {
    let home = std::env::var_os("HOME").map(PathBuf::from);
    let pictures = std::env::var_os("XDG_PICTURES_DIR")
        .map(PathBuf::from)
        .or_else(|| home.as_ref().map(|h| h.join("Pictures")));
    pictures.filter(|p| p.is_dir()).or(home)
}

/// Memory the system can give now (Linux: `MemAvailable`); `None` where unknown.
#[must_use]
pub fn available_memory_bytes() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

#[cfg(test)]
mod tests {
    use super::*;

    static FULL_PICTURE: Isolation = Isolation::NONE;

    fn look(settings: &PreviewSettings) -> ViewportLook<'_> {
        ViewportLook {
            settings,
            isolation: &FULL_PICTURE,
        }
    }

    #[test]
    fn an_export_too_large_for_memory_is_refused_before_it_starts() {
        assert!(check_export_memory(800, 600, Some(1 << 30)).is_ok());
        let error = check_export_memory(16384, 16384, Some(8_000_000_000)).unwrap_err();
        assert!(
            error.contains("16384×16384") && error.contains("8.0 GB"),
            "{error}"
        );
        assert!(
            check_export_memory(16384, 16384, None).is_ok(),
            "no limit known"
        );

        let scene = crate::scene::examples::default_scene();
        let mut state = ExportState::default();
        state.show(&scene, None);
        state.memory_budget = Some(1000);
        let ctx = egui::Context::default();
        let shown = PreviewSettings::default();
        let error = state
            .start(&scene, None, look(&shown), Path::new("never.png"), &ctx)
            .unwrap_err();
        assert!(error.contains("memory"), "{error}");
        assert!(!state.is_running(), "nothing started");
    }

    #[test]
    fn width_and_height_keep_the_aspect_ratio_unless_unlinked() {
        let scene = crate::scene::examples::default_scene();
        let mut state = ExportState::default();
        state.show(&scene, None);
        state.aspect = 2.0;
        state.resize(401, 10, false);
        let size = |s: &ExportState| s.settings.as_ref().map(|o| (o.width, o.height));
        assert_eq!(size(&state), Some((401, 201)));
        state.resize(10, 50, true);
        assert_eq!(size(&state), Some((100, 50)));
        state.keep_aspect = false;
        state.resize(30, 50, true);
        assert_eq!(size(&state), Some((30, 50)));
    }

    #[test]
    fn as_shown_takes_the_viewports_switches_and_view() {
        let scene = crate::scene::examples::default_scene();
        let mut shown = PreviewSettings::default();
        shown.switches.set(crate::trace::Term::Diffuse, false);
        shown.view = crate::trace::View::Depth;
        let mut state = ExportState::default();
        state.show(&scene, None);
        assert_eq!(
            state.options(&scene, look(&shown)).view,
            crate::trace::View::Beauty
        );
        state.as_shown = true;
        let options = state.options(&scene, look(&shown));
        assert_eq!(
            (options.switches, options.view),
            (shown.switches, shown.view)
        );
        let muted = Isolation {
            muted_lights: [0].into(),
            ..Isolation::NONE
        };
        let look = ViewportLook {
            settings: &shown,
            isolation: &muted,
        };
        assert_eq!(state.options(&scene, look).isolation, muted, "as shown");
        state.as_shown = false;
        assert_eq!(state.options(&scene, look).isolation, Isolation::NONE);
        assert_eq!(options.width, scene.camera.width);
    }
}
