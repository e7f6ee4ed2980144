//! The isolation switches remembered per scene file across runs, in eframe's storage
//! (editor state, never in the scene file): opening a file brings back what was muted,
//! solo and hidden in it. Unnamed scenes (the default scene, a new one) start with the
//! full picture.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::trace::Isolation;
use crate::ui::stored::Stored;

/// How many files are remembered; the least recently used is forgotten first.
pub const MAX_REMEMBERED_FILES: usize = 64;

/// The switches of one file, as stored: scene indices.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
struct StoredIsolation {
    muted_lights: Vec<usize>,
    solo_lights: Vec<usize>,
    hidden_objects: Vec<usize>,
    #[serde(default)]
    hidden_parts: Vec<Vec<usize>>,
}

impl StoredIsolation {
    fn new(isolation: &Isolation) -> Self {
        Self {
            muted_lights: isolation.muted_lights.iter().copied().collect(),
            solo_lights: isolation.solo_lights.iter().copied().collect(),
            hidden_objects: isolation.hidden_objects.iter().copied().collect(),
            hidden_parts: isolation.hidden_parts.iter().cloned().collect(),
        }
    }

    fn isolation(&self) -> Isolation {
        Isolation {
            muted_lights: self.muted_lights.iter().copied().collect(),
            solo_lights: self.solo_lights.iter().copied().collect(),
            hidden_objects: self.hidden_objects.iter().copied().collect(),
            hidden_parts: self.hidden_parts.iter().cloned().collect(),
        }
    }
}

/// The switches of each file that has some, most recently used first.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct IsolationMemory {
    files: Vec<(String, StoredIsolation)>,
}

impl Stored for IsolationMemory {
    const KEY: &'static str = "raylab.isolation";
}

impl IsolationMemory {
    /// The switches last remembered for `path`; the full picture for a file not known.
    #[must_use]
    pub fn recall(&self, path: &Path) -> Isolation {
        let key = key(path);
        self.files
            .iter()
            .find(|(file, _)| *file == key)
            .map_or(Isolation::NONE, |(_, stored)| stored.isolation())
    }

    /// Remembers `isolation` for `path` (the full picture is remembered by forgetting).
    pub fn remember(&mut self, path: &Path, isolation: &Isolation) {
        let key = key(path);
        self.files.retain(|(file, _)| *file != key);
        if !isolation.is_none() {
            self.files.insert(0, (key, StoredIsolation::new(isolation)));
            self.files.truncate(MAX_REMEMBERED_FILES);
        }
    }
}

fn key(path: &Path) -> String {
    path.to_string_lossy().into_owned()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ui::test_storage::MapStorage;
    use std::collections::BTreeSet;

    #[test]
    fn switches_survive_storage_per_file_and_the_oldest_files_are_forgotten() {
        let a = Path::new("/scenes/a.ron");
        let b = Path::new("/scenes/b.ron");
        let isolation = Isolation {
            muted_lights: BTreeSet::from([1, 2]),
            solo_lights: BTreeSet::from([3]),
            hidden_objects: BTreeSet::from([0]),
            hidden_parts: BTreeSet::new(),
        };
        let mut memory = IsolationMemory::default();
        memory.remember(a, &isolation);
        let mut storage = MapStorage::default();
        memory.save(&mut storage);
        let loaded = IsolationMemory::load(Some(&storage));
        assert_eq!(loaded.recall(a), isolation);
        assert_eq!(loaded.recall(b), Isolation::NONE);
        assert_eq!(IsolationMemory::load(None), IsolationMemory::default());

        let mut memory = loaded;
        memory.remember(a, &Isolation::NONE);
        assert_eq!(
            memory,
            IsolationMemory::default(),
            "the full picture is not stored"
        );
        for n in 0..=MAX_REMEMBERED_FILES {
            memory.remember(Path::new(&format!("/scenes/{n}.ron")), &isolation);
        }
        assert_eq!(memory.recall(Path::new("/scenes/0.ron")), Isolation::NONE);
        assert_eq!(memory.recall(Path::new("/scenes/1.ron")), isolation);
    }
}
