//! Work on a copy of the editor's scene off the UI thread (the Bug gallery's pictures, a
//! comparison): a [`BackgroundJob`] kept with the scene it was started for, so that its
//! outcome can be told from a later edit, and with what else its window shows while it
//! runs. Started, polled, watched and cancelled the same way by each window.

use crate::preview::BackgroundJob;
use crate::scene::Scene;
use crate::trace::RenderProgress;

/// A job making a `T` for the editor's scene as it was when the job started; `Tag` is
/// what the caller keeps with it (where the picture came from, how many bugs it tries).
pub struct SceneJob<T, Tag> {
    job: BackgroundJob<Result<T, String>>,
    scene: Scene,
    tag: Tag,
}

impl<T: Send + 'static, Tag> SceneJob<T, Tag> {
    /// Starts `work` on a thread named after `what`; a repaint of `ctx` is asked for when
    /// it ends. `work` returns `None` when it saw the cancel flag, or its outcome: the
    /// `T`, or the message for the user.
    ///
    /// # Errors
    /// When the operating system cannot start a thread.
    pub fn spawn(
        what: &str,
        scene: &Scene,
        tag: Tag,
        work: impl FnOnce(&RenderProgress) -> Option<Result<T, String>> + Send + 'static,
        ctx: &egui::Context,
    ) -> Result<Self, String> {
        let repaint = ctx.clone();
        let job = BackgroundJob::spawn(what, work, move || repaint.request_repaint())?;
        Ok(Self {
            job,
            scene: scene.clone(),
            tag,
        })
    }
}

impl<T, Tag> SceneJob<T, Tag> {
    /// Takes the job out of `slot` once it has ended: its outcome (a crash or a cancel
    /// is an error too), the scene it was started for, and its tag. `None`, and the job
    /// stays, while it runs.
    pub fn take_finished(slot: &mut Option<Self>) -> Option<(Result<T, String>, Scene, Tag)> {
        let outcome = slot.as_ref()?.job.try_result()?;
        let Self { scene, tag, .. } = slot.take()?;
        Some((outcome.and_then(|made| made), scene, tag))
    }

    /// The editor's scene the job was started for.
    #[must_use]
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// What the caller keeps with the job.
    #[must_use]
    pub fn tag(&self) -> &Tag {
        &self.tag
    }

    /// Fraction done, 0 to 1.
    #[must_use]
    pub fn fraction(&self) -> f64 {
        self.job.fraction()
    }

    /// Asks the work to stop at its next check (its end is then reported as an error).
    pub fn cancel(&self) {
        self.job.cancel();
    }
}
