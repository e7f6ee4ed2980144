//! The state of a comparison in the editor: the job that runs it off the UI thread, its
//! outcome (the comparison, or an error for the user), and how it is being looked at.
//! A comparison with a file reads the scene's mesh files on the job's thread the way the
//! preview and Export PNG do ([`MeshCache::read`], from the scene file's folder).

use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::compare::{
    CompareError, CompareOptions, Comparison, OtherImage, PixelValues, compare_with_meshes,
};
use crate::preview::MeshCache;
use crate::scene::{LoadWatch, Scene};
use crate::trace::{MeshStore, RenderProgress};
use crate::ui::scene_job::SceneJob;

use super::mode::{CompareMode, Side};
use super::textures::CompareTextures;
use super::view::ZoomView;

/// A comparison that ran: what was compared and what was found.
pub struct Compared {
    /// The comparison's result.
    pub comparison: Comparison,
    /// Where the other picture came from.
    pub source: OtherSource,
    /// The scene as it was compared (to notice later edits).
    pub scene: Scene,
    /// Its pictures on the GPU, made when first shown.
    pub textures: Option<CompareTextures>,
}

/// Where the other picture of a comparison came from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum OtherSource {
    /// A file (PNG or PPM): it can be compared again after an edit.
    File(PathBuf),
    /// A picture made in the editor (a Bug gallery picture), named by its bug.
    Planted(String),
}

impl OtherSource {
    /// A short name for the toolbar.
    #[must_use]
    pub fn name(&self) -> String {
        match self {
            Self::File(path) => path.file_name().map_or_else(
                || path.display().to_string(),
                |n| n.to_string_lossy().into_owned(),
            ),
            Self::Planted(label) => format!("bug gallery: {label}"),
        }
    }
}

/// A picture made in the editor, to compare with a scene (a Bug gallery picture).
pub struct PictureToCompare {
    /// The scene at the picture's size, as compared.
    pub compared_scene: Scene,
    /// The editor's scene the picture was made of (a later edit makes the result stale).
    pub editor_scene: Scene,
    /// The scene's meshes.
    pub meshes: MeshStore,
    /// The picture.
    pub picture: OtherImage,
    /// Its samples per pixel: raylab's side is rendered with as many.
    pub samples_per_pixel: u32,
    /// What the toolbar calls it.
    pub label: String,
}

/// A running comparison, tagged with where its other picture came from.
type Running = SceneJob<Comparison, OtherSource>;

/// A comparison's failure as the job reports it: the message for the user, none when
/// it was cancelled.
fn failure(error: CompareError) -> Option<String> {
    match error {
        CompareError::Cancelled => None,
        error => Some(error.to_string()),
    }
}

/// Everything the editor keeps about comparing with another image.
#[derive(Default)]
pub struct CompareSession {
    /// Whether the Compare with Image window is open.
    pub window_open: bool,
    /// The path in the window's field.
    pub path_text: String,
    /// How the pictures are shown.
    pub mode: CompareMode,
    /// Zoom and pan, shared by both pictures.
    pub view: ZoomView,
    /// Where the swipe line is, 0 (left) to 1 (right) across the picture.
    pub swipe: f32,
    /// Which picture the flip mode shows.
    pub flip_side: Side,
    /// Whether the flip mode flips by itself.
    pub auto_flip: bool,
    running: Option<Running>,
    compared: Option<Compared>,
    error: Option<String>,
    highlighted: Option<usize>,
}

impl CompareSession {
    /// Opens the window where a file is chosen.
    pub fn show_window(&mut self) {
        self.window_open = true;
    }

    /// Starts comparing `scene` with the picture at `path` on a thread of its own (a
    /// running comparison is cancelled); its mesh files are read there first, from
    /// `folder` (the scene file's; none: never saved). The window opens to show progress
    /// and errors.
    pub fn start(
        &mut self,
        scene: &Scene,
        folder: Option<&Path>,
        path: &Path,
        ctx: &egui::Context,
    ) {
        self.path_text = path.display().to_string();
        let (thread_scene, thread_path) = (scene.clone(), path.to_owned());
        let folder = folder.map(Path::to_path_buf);
        let work = move |progress: &_| {
            let other = OtherImage::load(&thread_path).map_err(|e| Some(e.to_string()))?;
            let meshes = MeshCache::default()
                .read(
                    &thread_scene,
                    folder.as_deref(),
                    &MeshStore::default(),
                    &mut |_| Arc::new(LoadWatch::default()),
                )
                .map_err(|e| Some(format!("the scene cannot be rendered: {e}")))?;
            compare_with_meshes(
                &thread_scene,
                &meshes,
                &other,
                &CompareOptions::default(),
                progress,
            )
            .map_err(failure)
        };
        self.spawn(OtherSource::File(path.to_owned()), scene, work, ctx);
    }

    /// Starts comparing a picture made in the editor with its scene, as [`Self::start`]
    /// does a file's; no file is written.
    pub fn start_picture(&mut self, request: PictureToCompare, ctx: &egui::Context) {
        let source = OtherSource::Planted(request.label);
        let PictureToCompare {
            compared_scene,
            editor_scene,
            meshes,
            picture,
            samples_per_pixel,
            ..
        } = request;
        let options = CompareOptions {
            samples_per_pixel: Some(samples_per_pixel),
        };
        let work = move |progress: &_| {
            compare_with_meshes(&compared_scene, &meshes, &picture, &options, progress)
                .map_err(failure)
        };
        self.spawn(source, &editor_scene, work, ctx);
    }

    /// Runs `work` on a thread of its own; `scene` is kept to notice later edits. The
    /// work fails with the message for the user, or with none when it was cancelled.
    fn spawn(
        &mut self,
        source: OtherSource,
        scene: &Scene,
        work: impl FnOnce(&RenderProgress) -> Result<Comparison, Option<String>> + Send + 'static,
        ctx: &egui::Context,
    ) {
        self.running = None;
        self.error = None;
        self.window_open = true;
        let work = move |progress: &RenderProgress| match work(progress) {
            Ok(comparison) => Some(Ok(comparison)),
            Err(None) => None,
            Err(Some(error)) => Some(Err(error)),
        };
        match SceneJob::spawn("comparison", scene, source, work, ctx) {
            Ok(job) => self.running = Some(job),
            Err(error) => self.error = Some(error),
        }
    }

    /// Takes the outcome of a finished job: the comparison is shown, an error is kept
    /// for the window (which stays open to show it).
    pub fn poll(&mut self) {
        let Some((outcome, scene, source)) = SceneJob::take_finished(&mut self.running) else {
            return;
        };
        match outcome {
            Ok(comparison) => {
                self.compared = Some(Compared {
                    comparison,
                    source,
                    scene,
                    textures: None,
                });
                self.highlighted = None;
                self.view = ZoomView::default();
                self.swipe = 0.5;
                self.window_open = false;
            }
            Err(error) => {
                self.error = Some(format!("Cannot compare: {error}"));
                self.window_open = true;
            }
        }
    }

    /// Asks the running comparison to stop (its end is reported as an error).
    pub fn cancel(&self) {
        if let Some(running) = &self.running {
            running.cancel();
        }
    }

    /// Fraction done of the running comparison, `None` when none runs.
    #[must_use]
    pub fn progress(&self) -> Option<f64> {
        self.running.as_ref().map(SceneJob::fraction)
    }

    /// Whether a comparison is running.
    #[must_use]
    pub fn is_running(&self) -> bool {
        self.running.is_some()
    }

    /// Why the last comparison could not be made.
    #[must_use]
    pub fn error(&self) -> Option<&str> {
        self.error.as_deref()
    }

    /// The comparison being shown.
    #[must_use]
    pub fn compared(&self) -> Option<&Compared> {
        self.compared.as_ref()
    }

    /// The comparison being shown, to make its textures.
    pub fn compared_mut(&mut self) -> Option<&mut Compared> {
        self.compared.as_mut()
    }

    /// The comparison's result, when one is shown.
    #[must_use]
    pub fn comparison(&self) -> Option<&Comparison> {
        self.compared.as_ref().map(|c| &c.comparison)
    }

    /// Whether the viewport shows the comparison instead of the live preview.
    #[must_use]
    pub fn is_showing(&self) -> bool {
        self.compared.is_some()
    }

    /// Back to the live preview.
    pub fn close(&mut self) {
        self.compared = None;
        self.highlighted = None;
    }

    /// The explanation whose pixels are highlighted.
    #[must_use]
    pub fn highlighted(&self) -> Option<usize> {
        self.highlighted
    }

    /// Highlights explanation `index` (`None`: nothing).
    pub fn highlight(&mut self, index: Option<usize>) {
        let count = self.comparison().map_or(0, |c| c.explanations.len());
        self.highlighted = index.filter(|&i| i < count);
    }

    /// The highlighted explanation's pixels (row-major indices), empty when none.
    #[must_use]
    pub fn highlighted_pixels(&self) -> &[u32] {
        match (self.comparison(), self.highlighted) {
            (Some(c), Some(i)) => c.explanations.get(i).map_or(&[], |e| &e.pixels),
            _ => &[],
        }
    }

    /// Both pictures' values at `pixel`, when a comparison is shown and holds it.
    #[must_use]
    pub fn pixel_values(&self, pixel: (u32, u32)) -> Option<PixelValues> {
        let c = self.comparison()?;
        (pixel.0 < c.width && pixel.1 < c.height).then(|| c.pixel(pixel.0, pixel.1))
    }

    /// Whether `scene` differs from the scene that was compared.
    #[must_use]
    pub fn is_stale(&self, scene: &Scene) -> bool {
        self.compared.as_ref().is_some_and(|c| c.scene != *scene)
    }
}
