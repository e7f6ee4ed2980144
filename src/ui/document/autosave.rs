//! No lost work: while the scene has unsaved changes, it is written every few seconds to
//! this editor's recovery file (atomically, in the platform's data folder). A clean exit,
//! a save or discarding the changes removes it; after a crash or a kill the next start
//! finds it and offers to restore it.

use std::path::Path;
use std::time::{Duration, Instant};

use egui::{Align2, RichText};

use crate::recovery::{Orphan, RecoveryStore};
use crate::scene::Scene;

/// How often unsaved changes are written to the recovery file.
pub const AUTOSAVE_INTERVAL: Duration = Duration::from_secs(3);

/// The user's answer to the restore offer.
#[derive(Clone, Debug, PartialEq)]
pub enum RestoreAnswer {
    /// Open the recovered scene (and the file it belonged to).
    Restore(Box<Scene>, Option<std::path::PathBuf>),
    /// Throw the recovered scene away.
    Discard,
}

/// The autosave timer and the restore offer.
#[derive(Debug, Default)]
pub struct Autosave {
    store: Option<RecoveryStore>,
    /// The scene last written, so an unchanged scene is not written again.
    written: Option<Scene>,
    last_write: Option<Instant>,
    offer: Option<Orphan>,
    /// The last write error, shown once in the status bar.
    pub error: Option<String>,
}

impl Autosave {
    /// Autosave into `store` (none: autosave off), offering the newest recovery file of
    /// an editor that is no longer running.
    #[must_use]
    pub fn new(store: Option<RecoveryStore>) -> Self {
        let offer = store.as_ref().and_then(|s| s.orphans().into_iter().next());
        Self {
            store,
            offer,
            ..Self::default()
        }
    }

    /// Whether a restore offer is waiting for an answer.
    #[must_use]
    pub fn has_offer(&self) -> bool {
        self.offer.is_some()
    }

    /// Once per frame: writes the scene if it has unsaved changes that are not yet in the
    /// recovery file and the interval has passed; removes the file when nothing is unsaved.
    /// Returns when it wants to be called again.
    pub fn tick(
        &mut self,
        scene: &Scene,
        dirty: bool,
        source: Option<&Path>,
        now: Instant,
    ) -> Option<Duration> {
        let store = self.store.as_ref()?;
        if !dirty {
            if self.written.take().is_some() {
                store.clear();
            }
            return None;
        }
        if self.written.as_ref() == Some(scene) {
            return None;
        }
        let due = self.last_write.map_or(now, |t| t + AUTOSAVE_INTERVAL);
        if now < due {
            return Some(due - now);
        }
        match store.save(scene, source) {
            Ok(()) => {
                self.written = Some(scene.clone());
                self.error = None;
            }
            Err(e) => self.error = Some(format!("autosave failed: {e}")),
        }
        self.last_write = Some(now);
        None
    }

    /// Removes this editor's recovery file (clean exit, or changes knowingly discarded).
    pub fn clear(&mut self) {
        if let Some(store) = &self.store {
            store.clear();
        }
        self.written = None;
    }

    /// The restore offer, answered with the same call as a click would make.
    pub fn answer(&mut self, restore: bool) -> Option<RestoreAnswer> {
        let orphan = self.offer.take()?;
        RecoveryStore::discard(&orphan);
        Some(if restore {
            RestoreAnswer::Restore(Box::new(orphan.recovery.scene), orphan.recovery.source)
        } else {
            RestoreAnswer::Discard
        })
    }

    /// The restore offer as a modal window; the answer once given.
    pub fn offer_ui(&mut self, ctx: &egui::Context) -> Option<RestoreAnswer> {
        let orphan = self.offer.as_ref()?;
        let from = orphan.recovery.source.as_ref().map_or_else(
            || "an unsaved scene".to_owned(),
            |p| p.display().to_string(),
        );
        let mut choice = None;
        egui::Window::new("Restore unsaved work?")
            .collapsible(false)
            .resizable(false)
            .anchor(Align2::CENTER_CENTER, [0.0, 0.0])
            .show(ctx, |ui| {
                ui.label(format!(
                    "raylab did not close cleanly last time. Unsaved changes to {from} were kept."
                ));
                ui.label(RichText::new("Restore them, or discard them for good.").weak());
                ui.horizontal(|ui| {
                    if ui.button("Restore").clicked() {
                        choice = Some(true);
                    }
                    if ui.button("Discard").clicked() {
                        choice = Some(false);
                    }
                });
            });
        choice.and_then(|restore| self.answer(restore))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn store(name: &str) -> RecoveryStore {
        let dir =
            std::env::temp_dir().join(format!("raylab-autosave-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        RecoveryStore::new(dir)
    }

    #[test]
    fn writes_unsaved_changes_at_most_every_interval_and_clears_when_clean() {
        let store = store("timer");
        let path = store.own_path();
        let mut autosave = Autosave::new(Some(store));
        let start = Instant::now();
        let mut scene = Scene::empty();
        assert_eq!(autosave.tick(&scene, false, None, start), None);
        assert!(!path.exists());
        scene.render.max_depth = 1;
        autosave.tick(&scene, true, None, start);
        assert!(path.exists(), "first unsaved change written at once");
        scene.render.max_depth = 2;
        let wait = autosave.tick(&scene, true, None, start + Duration::from_secs(1));
        assert_eq!(wait, Some(AUTOSAVE_INTERVAL - Duration::from_secs(1)));
        autosave.tick(&scene, true, None, start + AUTOSAVE_INTERVAL);
        let written = std::fs::read_to_string(&path).unwrap();
        assert!(written.contains("max_depth: 2"), "{written}");
        // Saved: the recovery file goes.
        autosave.tick(&scene, false, None, start + AUTOSAVE_INTERVAL * 2);
        assert!(!path.exists());
    }
}
