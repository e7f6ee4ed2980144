//! Recently opened and saved files, remembered across runs in eframe's storage (editor
//! state, never part of a scene file).

use std::path::{Path, PathBuf};

use crate::ui::stored::Stored;
use serde::{Deserialize, Serialize};

/// How many files are remembered.
pub const MAX_RECENT: usize = 10;

/// Most recent first, no duplicates. A file that failed to open stays, marked, so a
/// file on an unplugged drive or a share that is down is still there next time.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct RecentFiles {
    paths: Vec<PathBuf>,
    /// The files whose last open failed.
    #[serde(default)]
    failed: Vec<PathBuf>,
}

impl Stored for RecentFiles {
    const KEY: &'static str = "raylab.recent_files";
}

impl RecentFiles {
    /// Moves (or adds) `path` to the front: it opened or was saved, so it is no longer
    /// marked as failed.
    pub fn push(&mut self, path: &Path) {
        let path = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_owned());
        self.paths.retain(|p| *p != path);
        self.failed.retain(|p| *p != path);
        self.paths.insert(0, path);
        self.paths.truncate(MAX_RECENT);
    }

    /// Marks `path` (as listed, or as given) as failing to open; it stays in the list.
    pub fn mark_failed(&mut self, path: &Path) {
        let listed = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_owned());
        for candidate in [path.to_owned(), listed] {
            if self.paths.contains(&candidate) && !self.failed.contains(&candidate) {
                self.failed.push(candidate);
            }
        }
    }

    /// Whether the last open of `path` failed.
    #[must_use]
    pub fn has_failed(&self, path: &Path) -> bool {
        self.failed.iter().any(|p| p == path)
    }

    /// The files, most recent first.
    #[must_use]
    pub fn paths(&self) -> &[PathBuf] {
        &self.paths
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::ui::test_storage::MapStorage;

    #[test]
    fn the_list_survives_a_restart_through_storage() {
        let mut storage = MapStorage::default();
        assert_eq!(RecentFiles::load(Some(&storage)), RecentFiles::default());
        let mut recent = RecentFiles::default();
        recent.push(Path::new("/nonexistent/a.ron"));
        recent.push(Path::new("/nonexistent/b.ron"));
        recent.save(&mut storage);
        assert_eq!(RecentFiles::load(Some(&storage)), recent);
        assert_eq!(RecentFiles::load(None), RecentFiles::default());
    }

    #[test]
    fn newest_first_without_duplicates_and_bounded() {
        let mut recent = RecentFiles::default();
        for i in 0..12 {
            recent.push(Path::new(&format!("/nonexistent/{i}.ron")));
        }
        recent.push(Path::new("/nonexistent/5.ron"));
        assert_eq!(recent.paths().len(), MAX_RECENT);
        assert_eq!(recent.paths()[0], Path::new("/nonexistent/5.ron"));
        assert_eq!(
            recent
                .paths()
                .iter()
                .filter(|p| p.ends_with("5.ron"))
                .count(),
            1
        );
    }

    #[test]
    fn a_file_that_failed_to_open_stays_marked_until_it_opens() {
        let mut recent = RecentFiles::default();
        let path = Path::new("/nonexistent/gone.ron");
        recent.push(path);
        recent.mark_failed(path);
        assert_eq!(recent.paths(), [path]);
        assert!(recent.has_failed(path));
        let mut storage = MapStorage::default();
        recent.save(&mut storage);
        assert!(RecentFiles::load(Some(&storage)).has_failed(path));
        recent.push(path);
        assert!(!recent.has_failed(path));
    }
}
