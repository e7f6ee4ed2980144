//! A scene prepared for comparison: everything a comparison needs that depends on the
//! scene alone, made once and shared by every picture compared with it (a class's
//! students' renders of one scene). The split ([`Components`]) and raylab's picture are
//! made at once; the conventions' trial renders and the splits under adopted conventions
//! when a picture first needs them, then kept.
//!
//! What is kept lazily is made under a lock while other callers of the same part wait
//! (once_cell's `get_or_try_init`): sharing a [`PreparedScene`] between jobs of the
//! rayon pool that does the work could run a second job inside the first's wait on the
//! same thread and deadlock; share it between plain threads (as `raylab class` does).

use std::sync::{Arc, Mutex};

use once_cell::sync::OnceCell;

use super::catalogue::MISS;
use super::error::CompareError;
use super::fit::{ConventionTrials, SamplingSpread, convention_trials};
use super::report;
use super::split::{Components, render_components};
use crate::scene::{Conventions, Scene};
use crate::trace::{Image, MeshStore, RenderProgress, World};

/// A scene at a number of samples per pixel, ready to be compared with pictures
/// ([`super::compare_prepared`]).
pub struct PreparedScene {
    /// The scene as compared (under adopted conventions, for an adopted preparation).
    pub(super) scene: Scene,
    /// Its mesh objects' triangles.
    meshes: MeshStore,
    /// Samples per pixel of raylab's picture.
    pub(super) spp: u32,
    /// The scene compiled.
    pub(super) world: World,
    /// raylab's picture in channels.
    pub(super) components: Components,
    /// raylab's picture as the renderer's image.
    pub(super) raylab: Image,
    /// raylab's picture as the PNG's bytes.
    pub(super) raylab_rgb: Vec<[u8; 3]>,
    /// Whether each pixel lies on an outline of raylab's objects.
    pub(super) outline: Vec<bool>,
    /// The scene object each pixel shows, if any.
    pub(super) objects: Vec<Option<usize>>,
    /// How far each pixel's edges may blend (for pictures sampled otherwise).
    spread: OnceCell<SamplingSpread>,
    /// raylab's pictures under the course's other conventions.
    trials: OnceCell<ConventionTrials>,
    /// The scene prepared again under conventions (and a ray depth) a picture follows.
    adopted: Mutex<Vec<AdoptedSlot>>,
}

/// One adopted reading's preparation, made by the first picture that adopts it.
type AdoptedSlot = ((Conventions, u32), Arc<OnceCell<Arc<PreparedScene>>>);

impl PreparedScene {
    /// Compiles `scene` and splits raylab's picture of it at `spp` samples per pixel.
    ///
    /// # Errors
    /// [`CompareError::Scene`] when the scene does not compile, [`CompareError::Cancelled`]
    /// when `progress` cancels the split.
    pub fn new(
        scene: &Scene,
        meshes: &MeshStore,
        spp: u32,
        progress: &RenderProgress,
    ) -> Result<Self, CompareError> {
        let size = (scene.camera.width, scene.camera.height);
        let world =
            World::with_meshes(scene, meshes).map_err(|e| CompareError::Scene(e.to_string()))?;
        let components =
            render_components(scene, &world, size, spp, progress).ok_or(CompareError::Cancelled)?;
        Ok(Self::of_split(scene, meshes, spp, world, components))
    }

    /// `scene` (compiled as `world`) prepared around its split `components`.
    fn of_split(
        scene: &Scene,
        meshes: &MeshStore,
        spp: u32,
        world: World,
        components: Components,
    ) -> Self {
        let raylab = components.image();
        let raylab_rgb = report::rgb_of(&raylab);
        let outline = components.outline();
        let objects = (0..components.labels.len())
            .map(|p| components.object_label(p))
            .map(|l| (l != MISS).then_some(l as usize))
            .collect();
        Self {
            scene: scene.clone(),
            meshes: meshes.clone(),
            spp,
            world,
            components,
            raylab,
            raylab_rgb,
            outline,
            objects,
            spread: OnceCell::new(),
            trials: OnceCell::new(),
            adopted: Mutex::new(Vec::new()),
        }
    }

    /// The scene as prepared.
    #[must_use]
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// Samples per pixel of raylab's picture.
    #[must_use]
    pub fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    /// How far each pixel's edges may blend their sides, from raylab's picture.
    pub(super) fn spread(&self) -> &SamplingSpread {
        self.spread
            .get_or_init(|| SamplingSpread::of(&self.components.beauty, self.scene.camera.width))
    }

    /// raylab's pictures under the course's other conventions, rendered the first time
    /// they are asked for; `None` if cancelled (and then tried again when next asked).
    pub(super) fn trials(&self, progress: &RenderProgress) -> Option<&ConventionTrials> {
        self.trials
            .get_or_try_init(|| {
                convention_trials(&self.scene, &self.meshes, self.spp, progress).ok_or(())
            })
            .ok()
    }

    /// This scene prepared under `conventions` and `max_depth` instead of its own, made
    /// the first time a picture adopts them and kept for the next.
    ///
    /// # Errors
    /// As [`PreparedScene::new`] (a cancelled preparation is made again when next asked).
    pub(super) fn adopted(
        &self,
        conventions: Conventions,
        max_depth: u32,
        progress: &RenderProgress,
    ) -> Result<Arc<PreparedScene>, CompareError> {
        let key = (conventions, max_depth);
        let slot = {
            let mut adopted = self.adopted.lock().unwrap_or_else(|e| e.into_inner());
            if let Some((_, slot)) = adopted.iter().find(|(k, _)| *k == key) {
                Arc::clone(slot)
            } else {
                let slot = Arc::new(OnceCell::new());
                adopted.push((key, Arc::clone(&slot)));
                slot
            }
        };
        let prepared = slot.get_or_try_init(|| {
            let mut scene = self.scene.clone();
            scene.render.conventions = conventions;
            scene.render.max_depth = max_depth;
            // The same split, folded otherwise: its pixels that fold alike are kept.
            let world = World::with_meshes(&scene, &self.meshes)
                .map_err(|e| CompareError::Scene(e.to_string()))?;
            let components = self
                .components
                .split_again(&scene, &world, progress)
                .ok_or(CompareError::Cancelled)?;
            let prepared =
                PreparedScene::of_split(&scene, &self.meshes, self.spp, world, components);
            Ok(Arc::new(prepared))
        })?;
        Ok(Arc::clone(prepared))
    }
}
