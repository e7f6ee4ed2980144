//! The view camera of each scene file, remembered across runs in eframe's storage (never
//! in the scene file): opening a file again brings back the view it was left with.

use std::collections::BTreeMap;
use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::ui::state::ViewCamera;
use crate::ui::stored::Stored;

/// How many files' views are kept; the least recently stored go first.
const MAX_FILES: usize = 64;

/// Views by file, with the order they were stored in.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ViewMemory {
    views: BTreeMap<String, (u64, ViewCamera)>,
    counter: u64,
}

impl Stored for ViewMemory {
    const KEY: &'static str = "raylab.view_cameras";
}

impl ViewMemory {
    /// The view last remembered for `path`, if it is usable.
    #[must_use]
    pub fn get(&self, path: &Path) -> Option<&ViewCamera> {
        self.views
            .get(&key(path))
            .map(|(_, view)| view)
            .filter(|view| view.is_usable())
    }

    /// Remembers `view` for `path`, forgetting the oldest file beyond [`MAX_FILES`].
    pub fn remember(&mut self, path: &Path, view: &ViewCamera) {
        self.counter += 1;
        self.views.insert(key(path), (self.counter, view.clone()));
        while self.views.len() > MAX_FILES {
            let oldest = self
                .views
                .iter()
                .min_by_key(|(_, (stamp, _))| *stamp)
                .map(|(name, _)| name.clone());
            match oldest {
                Some(name) => self.views.remove(&name),
                None => break,
            };
        }
    }
}

fn key(path: &Path) -> String {
    std::path::absolute(path)
        .unwrap_or_else(|_| path.to_owned())
        .to_string_lossy()
        .into_owned()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ui::test_storage::MapStorage;

    #[test]
    fn views_survive_storage_per_file_and_the_oldest_go_first() {
        let scene = crate::ui::document::files::default_scene();
        let mut view = ViewCamera::free(&scene.camera);
        view.position.x += 3.0;
        let mut memory = ViewMemory::default();
        memory.remember(Path::new("a.ron"), &view);
        let mut storage = MapStorage::default();
        memory.save(&mut storage);
        let loaded = ViewMemory::load(Some(&storage));
        assert_eq!(loaded.get(Path::new("a.ron")), Some(&view));
        assert_eq!(loaded.get(Path::new("b.ron")), None);
        for i in 0..MAX_FILES + 5 {
            memory.remember(Path::new(&format!("f{i}.ron")), &view);
        }
        assert_eq!(memory.views.len(), MAX_FILES);
        assert_eq!(memory.get(Path::new("a.ron")), None, "the oldest went");
        assert!(
            memory
                .get(Path::new(&format!("f{}.ron", MAX_FILES + 4)))
                .is_some()
        );
    }
}
