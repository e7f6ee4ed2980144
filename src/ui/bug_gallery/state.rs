//! The Bug gallery's state: the job that renders the gallery off the UI thread (with
//! progress and cancel), the gallery it made, and the scene it was made of, so that an
//! edit marks it stale instead of letting it show pictures of an older scene.

use std::path::{Path, PathBuf};

use egui::TextureHandle;

use super::meshes::read_meshes;
use crate::compare::OtherImage;
use crate::compare::plant::{gallery, gallery_bugs, gallery_scene};
use crate::scene::Scene;
use crate::trace::{MeshStore, RenderProgress};
use crate::ui::compare::PictureToCompare;
use crate::ui::scene_job::SceneJob;

/// Samples per pixel of the gallery's pictures: one, as the course's tracers render.
pub const GALLERY_SAMPLES: u32 = 1;

/// One picture of the gallery, raylab's own first.
pub struct Thumbnail {
    /// The bug as `raylab render --bug` takes it (raylab's own: "raylab (no bug)").
    pub label: String,
    /// What the bug is in a tracer's code.
    pub in_code: String,
    /// The share of pixels the bug changes (none for raylab's own).
    pub changed_share: Option<f64>,
    /// The picture, at the gallery's size.
    pub picture: OtherImage,
    /// Its texture, made when first shown.
    pub(super) texture: Option<TextureHandle>,
}

/// What a finished job made.
struct Made {
    /// The scene at the gallery's size.
    scaled: Scene,
    meshes: MeshStore,
    thumbnails: Vec<Thumbnail>,
    left_out: Vec<String>,
}

/// A gallery being rendered, tagged with how many bugs it tries.
type Running = SceneJob<Made, usize>;

/// A gallery made, and the editor's scene it shows.
struct Shown {
    made: Made,
    scene: Scene,
}

/// Everything the editor keeps about the Bug gallery.
#[derive(Default)]
pub struct BugGallery {
    /// Whether the window is open.
    pub open: bool,
    running: Option<Running>,
    shown: Option<Shown>,
    error: Option<String>,
}

impl BugGallery {
    /// Opens the window; renders the gallery unless one of this very scene is shown or
    /// being made.
    pub fn show(&mut self, scene: &Scene, folder: Option<&Path>, ctx: &egui::Context) {
        self.open = true;
        let current = |s: &Scene| s == scene;
        let up_to_date = self.running.as_ref().is_some_and(|r| current(r.scene()))
            || self.shown.as_ref().is_some_and(|s| current(&s.scene));
        if !up_to_date {
            self.start(scene, folder, ctx);
        }
    }

    /// Renders the gallery of `scene` (its mesh files in `folder`) on a thread of its
    /// own; a gallery being made is cancelled. The pictures shown stay until it ends.
    pub fn start(&mut self, scene: &Scene, folder: Option<&Path>, ctx: &egui::Context) {
        self.running = None;
        self.error = None;
        let (thread_scene, folder) = (scene.clone(), folder.map(Path::to_owned));
        let bugs = gallery_bugs(&gallery_scene(scene.clone(), None)).len();
        let work = move |progress: &RenderProgress| {
            let made = make(&thread_scene, folder, progress);
            (!progress.is_cancelled()).then_some(made)
        };
        match SceneJob::spawn("bug gallery", scene, bugs, work, ctx) {
            Ok(job) => self.running = Some(job),
            Err(error) => self.error = Some(error),
        }
    }

    /// Takes the outcome of a finished job.
    pub fn poll(&mut self) {
        let Some((outcome, scene, _)) = SceneJob::take_finished(&mut self.running) else {
            return;
        };
        match outcome {
            Ok(made) => self.shown = Some(Shown { made, scene }),
            Err(error) => self.error = Some(format!("No gallery: {error}")),
        }
    }

    /// Asks the gallery being made to stop (its end is reported as an error).
    pub fn cancel(&self) {
        if let Some(running) = &self.running {
            running.cancel();
        }
    }

    /// Whether a gallery is being made.
    #[must_use]
    pub fn is_running(&self) -> bool {
        self.running.is_some()
    }

    /// Fraction done of the picture being rendered now, `None` when nothing runs.
    #[must_use]
    pub fn progress(&self) -> Option<f64> {
        self.running.as_ref().map(SceneJob::fraction)
    }

    /// How many bugs the gallery being made tries (each one picture, if it shows).
    #[must_use]
    pub fn bugs_to_try(&self) -> Option<usize> {
        self.running.as_ref().map(|r| *r.tag())
    }

    /// Why the last gallery could not be made.
    #[must_use]
    pub fn error(&self) -> Option<&str> {
        self.error.as_deref()
    }

    /// The pictures shown, raylab's own first (empty before the first gallery).
    #[must_use]
    pub fn thumbnails(&self) -> &[Thumbnail] {
        self.shown.as_ref().map_or(&[], |s| &s.made.thumbnails)
    }

    /// The pictures shown, to make their textures.
    pub(super) fn thumbnails_mut(&mut self) -> &mut [Thumbnail] {
        self.shown
            .as_mut()
            .map_or(&mut [], |s| &mut s.made.thumbnails)
    }

    /// Bugs that could not be planted in the scene shown, each with why.
    #[must_use]
    pub fn left_out(&self) -> &[String] {
        self.shown.as_ref().map_or(&[], |s| &s.made.left_out)
    }

    /// Whether the pictures shown are of another scene than `scene` (it was edited).
    #[must_use]
    pub fn is_stale(&self, scene: &Scene) -> bool {
        self.shown.as_ref().is_some_and(|s| s.scene != *scene)
    }

    /// Picture `index` (0: raylab's own) with what comparing it with its scene needs.
    #[must_use]
    pub fn picture_to_compare(&self, index: usize) -> Option<PictureToCompare> {
        let shown = self.shown.as_ref()?;
        let thumbnail = shown.made.thumbnails.get(index)?;
        Some(PictureToCompare {
            compared_scene: shown.made.scaled.clone(),
            editor_scene: shown.scene.clone(),
            meshes: shown.made.meshes.clone(),
            picture: thumbnail.picture.clone(),
            samples_per_pixel: GALLERY_SAMPLES,
            label: thumbnail.label.clone(),
        })
    }
}

/// The gallery of `scene`: its meshes read, the scene at the gallery's size, the pictures.
fn make(scene: &Scene, folder: Option<PathBuf>, progress: &RenderProgress) -> Result<Made, String> {
    let meshes = read_meshes(scene, folder.as_deref())?;
    let scaled = gallery_scene(scene.clone(), None);
    let found = gallery(&scaled, &meshes, GALLERY_SAMPLES, progress)?;
    let own = Thumbnail {
        label: "raylab (no bug)".to_owned(),
        in_code: "the scene as the contract renders it".to_owned(),
        changed_share: None,
        picture: found.own,
        texture: None,
    };
    let bugs = found.pictures.into_iter().map(|p| Thumbnail {
        label: p.label,
        in_code: p.in_code.to_owned(),
        changed_share: Some(p.changed_share),
        picture: p.picture,
        texture: None,
    });
    Ok(Made {
        scaled,
        meshes,
        thumbnails: std::iter::once(own).chain(bugs).collect(),
        left_out: found.left_out,
    })
}
