//! Each scene of a class prepared once for all of its students' renders
//! ([`PreparedScene`]: raylab's picture split into channels, the conventions' trial
//! renders): made by the first of its pairs that is compared (never, when the cache holds
//! them all) and dropped when its last pair is done, so that a run holds a scene or two
//! at a time, not the class.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

use super::pair::LoadedScene;
use crate::compare::{CompareOptions, PreparedScene, prepare};
use crate::trace::RenderProgress;

/// One scene's preparation and how many of its pairs are still to do.
struct Slot {
    /// Not made yet (`None`), made (its result), or dropped after the last pair.
    prepared: Mutex<Option<Result<Arc<PreparedScene>, String>>>,
    /// Pairs of the scene not finished yet.
    left: AtomicUsize,
}

/// The scenes' preparations, shared by their pairs.
pub struct SharedScenes {
    slots: Vec<Slot>,
}

impl SharedScenes {
    /// Slots for scenes with `pairs[s]` pairs to run each.
    #[must_use]
    pub fn new(pairs: &[usize]) -> Self {
        Self {
            slots: pairs
                .iter()
                .map(|&n| Slot {
                    prepared: Mutex::new(None),
                    left: AtomicUsize::new(n),
                })
                .collect(),
        }
    }

    /// Scene `index` (read as `loaded`) prepared with `options`: made now if no pair made
    /// it before (the other pairs asking meanwhile wait for it), else the one made.
    ///
    /// # Errors
    /// Why the scene cannot be prepared (it does not compile), for each of its pairs.
    pub fn prepared(
        &self,
        index: usize,
        loaded: &LoadedScene,
        options: &CompareOptions,
    ) -> Result<Arc<PreparedScene>, String> {
        let mut slot = self.slots[index]
            .prepared
            .lock()
            .unwrap_or_else(|e| e.into_inner());
        slot.get_or_insert_with(|| {
            prepare(
                &loaded.scene,
                &loaded.meshes,
                options,
                &RenderProgress::default(),
            )
            .map(Arc::new)
            .map_err(|e| e.to_string())
        })
        .clone()
    }

    /// Says a pair of scene `index` is done; after its last, its preparation is dropped
    /// (pairs still holding it keep it until they finish).
    pub fn pair_done(&self, index: usize) {
        let slot = &self.slots[index];
        if slot.left.fetch_sub(1, Ordering::AcqRel) == 1 {
            let dropped = slot
                .prepared
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .take();
            drop(dropped);
        }
    }
}
