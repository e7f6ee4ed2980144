//! Crash recovery for the editor: unsaved edits are written every few seconds to a
//! recovery file in the platform's data folder (atomically), one file per running
//! editor. The next start finds the files of editors that are no longer running and
//! offers to restore the newest. No egui here: the editor decides when to call these.

use std::path::{Path, PathBuf};
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

/// The recovery files of one folder, and this process's own.
#[derive(Clone, Debug)]
pub struct RecoveryStore {
    folder: PathBuf,
    pid: u32,
}

/// A recovery file left by an editor that is no longer running.
#[derive(Clone, Debug, PartialEq)]
pub struct Orphan {
    /// The file.
    pub path: PathBuf,
    /// What it holds.
    pub recovery: Recovery,
}

const PREFIX: &str = "recovery-";
const SUFFIX: &str = ".ron";

impl RecoveryStore {
    /// Recovery files in `folder`, this process writing `recovery-<pid>.ron`.
    #[must_use]
    pub fn new(folder: PathBuf) -> Self {
        Self {
            folder,
            pid: std::process::id(),
        }
    }

    /// The same store as another process id would see it (for tests).
    #[must_use]
    pub fn with_pid(folder: PathBuf, pid: u32) -> Self {
        Self { folder, pid }
    }

    /// This process's recovery file.
    #[must_use]
    pub fn own_path(&self) -> PathBuf {
        self.folder.join(format!("{PREFIX}{}{SUFFIX}", self.pid))
    }

    /// Writes the unsaved scene, atomically.
    ///
    /// # Errors
    /// The I/O error (the editor shows it and keeps going).
    pub fn save(&self, scene: &Scene, source: Option<&Path>) -> std::io::Result<()> {
        std::fs::create_dir_all(&self.folder)?;
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

    /// Removes this process's recovery file (after a save, or on a clean exit).
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
                recovery_pid(path).is_some_and(|pid| pid != self.pid && !process_is_running(pid))
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

    /// Deletes an orphan once it has been restored or declined.
    pub fn discard(orphan: &Orphan) {
        let _ = std::fs::remove_file(&orphan.path);
    }
}

/// The process id in a recovery file's name.
fn recovery_pid(path: &Path) -> Option<u32> {
    let name = path.file_name()?.to_str()?;
    name.strip_prefix(PREFIX)?
        .strip_suffix(SUFFIX)?
        .parse()
        .ok()
}

/// Whether a process with this id is running (Linux: `/proc/<pid>`; elsewhere assume
/// not, so a recovery file is offered rather than lost).
fn process_is_running(pid: u32) -> bool {
    cfg!(target_os = "linux") && Path::new(&format!("/proc/{pid}")).exists()
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
    fn a_dead_editors_file_is_offered_and_a_live_ones_is_not() {
        let dir = folder("offer");
        let mut scene = Scene::empty();
        scene.render.max_depth = 2;
        // A pid that cannot be running (above the kernel's pid_max).
        let dead = RecoveryStore::with_pid(dir.clone(), u32::MAX - 1);
        dead.save(&scene, Some(Path::new("/tmp/a.ron"))).unwrap();
        let me = RecoveryStore::new(dir.clone());
        me.save(&Scene::empty(), None).unwrap();
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
    fn garbage_in_the_folder_is_ignored() {
        let dir = folder("garbage");
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("recovery-999999999.ron"), "not a recovery file").unwrap();
        std::fs::write(dir.join("notes.txt"), "hello").unwrap();
        assert!(RecoveryStore::new(dir).orphans().is_empty());
    }
}
