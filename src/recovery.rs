//! Crash recovery for the editor: unsaved edits are written every few seconds to a
//! recovery file in the platform's data folder (atomically), one file per running
//! editor. The next start finds the files of editors that are no longer running and
//! offers to restore the newest. No egui here: the editor decides when to call these.
//!
//! Whether an editor still runs is not guessed from a process id (ids are reused, and a
//! dead but unreaped process still has one): each editor holds an exclusive lock on its
//! own `.lock` file from its first write on, and the operating system releases that lock
//! when the process ends, however it ends. A recovery file whose lock can be taken is an
//! orphan.

use std::fs::{File, OpenOptions, TryLockError};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{SystemTime, UNIX_EPOCH};

use serde::{Deserialize, Serialize};

use crate::scene::{Scene, read_text_file, write_atomically};

/// What a recovery file holds: the scene and where it came from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Recovery {
    /// The file the scene was opened from or last saved to, if any.
    pub source: Option<PathBuf>,
    /// When it was written, seconds since the Unix epoch.
    pub saved_at_unix: u64,
    /// The unsaved scene.
    pub scene: Scene,
}

/// The recovery files of one folder, and this editor's own. Clones share the lock.
#[derive(Clone, Debug)]
pub struct RecoveryStore {
    folder: PathBuf,
    /// This editor's id, unique among editors ever started: `<pid>-<start ns>-<n>`.
    id: String,
    /// The lock that says "this editor is running", taken at the first write.
    lock: Arc<Mutex<Option<HeldLock>>>,
}

/// A recovery file left by an editor that is no longer running.
#[derive(Clone, Debug, PartialEq)]
pub struct Orphan {
    /// The file.
    pub path: PathBuf,
    /// What it holds.
    pub recovery: Recovery,
}

/// An exclusive lock on a file, released (and the file removed) when dropped; the
/// operating system releases it when the process dies.
#[derive(Debug)]
struct HeldLock {
    file: File,
    path: PathBuf,
}

impl Drop for HeldLock {
    fn drop(&mut self) {
        let _ = self.file.unlock();
        let _ = std::fs::remove_file(&self.path);
    }
}

const PREFIX: &str = "recovery-";
const SUFFIX: &str = ".ron";
const LOCK_SUFFIX: &str = ".lock";

/// Editors started by this process so far (tests start several).
static STARTED: AtomicU64 = AtomicU64::new(0);

impl RecoveryStore {
    /// Recovery files in `folder`; this editor gets a fresh id.
    #[must_use]
    pub fn new(folder: PathBuf) -> Self {
        let started_ns = SystemTime::now()
            .duration_since(UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos());
        let n = STARTED.fetch_add(1, Ordering::Relaxed);
        Self {
            folder,
            id: format!("{}-{started_ns}-{n}", std::process::id()),
            lock: Arc::default(),
        }
    }

    /// This editor's recovery file.
    #[must_use]
    pub fn own_path(&self) -> PathBuf {
        self.folder.join(format!("{PREFIX}{}{SUFFIX}", self.id))
    }

    fn lock_path(&self, id: &str) -> PathBuf {
        self.folder.join(format!("{PREFIX}{id}{LOCK_SUFFIX}"))
    }

    /// Writes the unsaved scene, atomically (taking this editor's lock first).
    ///
    /// # Errors
    /// The I/O error (the editor shows it and keeps going).
    pub fn save(&self, scene: &Scene, source: Option<&Path>) -> std::io::Result<()> {
        std::fs::create_dir_all(&self.folder)?;
        self.hold_lock()?;
        let recovery = Recovery {
            source: source.map(Path::to_owned),
            saved_at_unix: SystemTime::now()
                .duration_since(UNIX_EPOCH)
                .map_or(0, |d| d.as_secs()),
            scene: scene.clone(),
        };
        let text = ron::ser::to_string_pretty(&recovery, ron::ser::PrettyConfig::new())
            .map_err(std::io::Error::other)?;
        write_atomically(&self.own_path(), text.as_bytes())
    }

    /// Takes this editor's lock unless it holds it already.
    fn hold_lock(&self) -> std::io::Result<()> {
        let mut held = self.lock.lock().unwrap_or_else(|e| e.into_inner());
        if held.is_some() {
            return Ok(());
        }
        let path = self.lock_path(&self.id);
        let file = OpenOptions::new()
            .create(true)
            .truncate(false)
            .write(true)
            .open(&path)?;
        file.try_lock().map_err(|e| match e {
            TryLockError::WouldBlock => {
                std::io::Error::other(format!("{} is locked by another editor", path.display()))
            }
            TryLockError::Error(e) => e,
        })?;
        *held = Some(HeldLock { file, path });
        Ok(())
    }

    /// Removes this editor's recovery file (after a save, or on a clean exit).
    pub fn clear(&self) {
        let _ = std::fs::remove_file(self.own_path());
    }

    /// Recovery files of editors no longer running, newest first. Unreadable files are
    /// skipped (and left for the user to look at).
    #[must_use]
    pub fn orphans(&self) -> Vec<Orphan> {
        let Ok(entries) = std::fs::read_dir(&self.folder) else {
            return Vec::new();
        };
        let mut orphans: Vec<Orphan> = entries
            .filter_map(|entry| entry.ok().map(|e| e.path()))
            .filter(|path| {
                recovery_id(path).is_some_and(|id| id != self.id && !self.is_running(id))
            })
            .filter_map(|path| {
                let text = read_text_file(&path).ok()?;
                let recovery: Recovery = ron::from_str(&text).ok()?;
                Some(Orphan { path, recovery })
            })
            .collect();
        orphans.sort_by_key(|o| std::cmp::Reverse(o.recovery.saved_at_unix));
        orphans
    }

    /// Whether the editor `id` still holds its lock. Only a lock held elsewhere counts:
    /// a missing or unreadable lock file means the file is offered rather than lost.
    fn is_running(&self, id: &str) -> bool {
        let Ok(file) = File::open(self.lock_path(id)) else {
            return false;
        };
        match file.try_lock_shared() {
            Ok(()) => {
                let _ = file.unlock();
                false
            }
            Err(TryLockError::WouldBlock) => true,
            Err(TryLockError::Error(_)) => false,
        }
    }

    /// Deletes an orphan once it has been restored or declined.
    pub fn discard(orphan: &Orphan) {
        let _ = std::fs::remove_file(&orphan.path);
    }
}

/// The editor id in a recovery file's name.
fn recovery_id(path: &Path) -> Option<&str> {
    let name = path.file_name()?.to_str()?;
    name.strip_prefix(PREFIX)?.strip_suffix(SUFFIX)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn folder(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("raylab-recovery-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    #[test]
    fn a_running_editors_file_is_not_offered_until_its_lock_is_released() {
        let dir = folder("offer");
        let mut scene = Scene::empty();
        scene.render.max_depth = 2;
        // Another editor of this very process: its process id is ours, so only the
        // lock can tell whether it runs.
        let other = RecoveryStore::new(dir.clone());
        other.save(&scene, Some(Path::new("/tmp/a.ron"))).unwrap();
        let me = RecoveryStore::new(dir.clone());
        me.save(&Scene::empty(), None).unwrap();
        assert!(me.orphans().is_empty(), "the other editor still runs");

        // It ends without clearing its file, as a crash would: the lock goes with it.
        drop(other);
        let orphans = me.orphans();
        assert_eq!(orphans.len(), 1);
        assert_eq!(orphans[0].recovery.scene, scene);
        assert_eq!(
            orphans[0].recovery.source.as_deref(),
            Some(Path::new("/tmp/a.ron"))
        );
        // Our own file is not an orphan for us, and clearing removes it.
        me.clear();
        assert!(!me.own_path().exists());
        RecoveryStore::discard(&orphans[0]);
        assert!(me.orphans().is_empty());
    }

    #[test]
    fn a_file_without_a_lock_is_offered_whatever_its_process_id() {
        let dir = folder("pid");
        std::fs::create_dir_all(&dir).unwrap();
        let recovery = Recovery {
            source: None,
            saved_at_unix: 1,
            scene: Scene::empty(),
        };
        let text = ron::ser::to_string(&recovery).unwrap();
        // Named after a process id that runs (ours), as the pid-era files were.
        let name = format!("{PREFIX}{}{SUFFIX}", std::process::id());
        std::fs::write(dir.join(name), text).unwrap();
        assert_eq!(RecoveryStore::new(dir).orphans().len(), 1);
    }

    #[test]
    fn garbage_in_the_folder_is_ignored() {
        let dir = folder("garbage");
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("recovery-999999999.ron"), "not a recovery file").unwrap();
        std::fs::write(dir.join("notes.txt"), "hello").unwrap();
        assert!(RecoveryStore::new(dir).orphans().is_empty());
    }
}
