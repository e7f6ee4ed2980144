//! The editor's looking state, apart from the scene: the view camera and the size a free
//! view renders at, the views remembered per file, the inspected and pinned pixels with
//! the ray-path settings, and the probes that pick and inspect off the UI thread.

use std::sync::Arc;

use crate::preview::WorldCache;
use crate::scene::Scene;
use crate::trace::{Isolation, TermSwitches};
use crate::ui::state::PickRequest;
use crate::ui::state::RayPathSettings;
use crate::ui::state::ViewCamera;
use crate::ui::viewport::pick_link::PickLink;
use crate::ui::viewport::pixel_inspector::link::InspectionLink;
use crate::ui::viewport::pixel_inspector::{PixelAnchor, PixelInspection};
use crate::ui::viewport::view_memory::ViewMemory;

/// The probes, started with the first frame (they repaint its context).
struct Probes {
    picks: PickLink,
    inspections: InspectionLink,
}

/// How the editor looks at the scene; none of it is part of the scene.
pub struct Looking {
    /// The view camera, or camera view.
    pub camera: ViewCamera,
    /// The size a free view renders at (the viewport's, from the last layout).
    pub free_size: (u32, u32),
    /// Views remembered per file.
    pub memory: ViewMemory,
    /// The inspected pixel of the scene camera's image.
    pub inspected: Option<(u32, u32)>,
    /// What the ray-path overlay draws, and the pinned pixels.
    pub ray_paths: RayPathSettings,
    /// Where the inspected pixel was on screen in the last layout.
    pub anchor: Option<PixelAnchor>,
    /// The scene as a free view renders it (the scene with the view camera), kept so it
    /// is copied only when the scene or the view changes.
    shown: Option<Scene>,
    probes: Option<Probes>,
}

impl Looking {
    /// Looking through `scene`'s camera, nothing inspected.
    pub(crate) fn new(scene: &Scene) -> Self {
        Self {
            camera: ViewCamera::through(&scene.camera),
            free_size: (scene.camera.width, scene.camera.height),
            memory: ViewMemory::default(),
            inspected: None,
            ray_paths: RayPathSettings::default(),
            anchor: None,
            shown: None,
            probes: None,
        }
    }

    /// A new document: camera view on its camera (or the view remembered for its file),
    /// nothing inspected or pinned.
    pub(crate) fn reset(&mut self, scene: &Scene, path: Option<&std::path::Path>) {
        self.camera = path
            .and_then(|p| self.memory.get(p).cloned())
            .unwrap_or_else(|| ViewCamera::through(&scene.camera));
        self.inspected = None;
        self.ray_paths.pinned.clear();
        self.anchor = None;
    }

    /// Starts the probes if they are not running; they repaint `ctx` when done.
    pub(crate) fn start(&mut self, ctx: &egui::Context) {
        if self.probes.is_none() {
            let cache = Arc::new(WorldCache::default());
            let ctx = ctx.clone();
            let waker: Arc<dyn Fn() + Send + Sync> = Arc::new(move || ctx.request_repaint());
            self.probes = Some(Probes {
                picks: PickLink::new(Arc::clone(&cache), Arc::clone(&waker)),
                inspections: InspectionLink::new(cache, waker),
            });
        }
    }

    /// The scene the preview renders: `scene` itself in camera view, else a copy with
    /// the view camera at the free size.
    pub(crate) fn shown_scene<'s>(&'s mut self, scene: &'s Scene) -> &'s Scene {
        if self.camera.through_scene_camera {
            return scene;
        }
        let camera = self.camera.shown(&scene.camera, self.free_size);
        let same_but_camera = self.shown.as_mut().is_some_and(|cached| {
            // Compared with the scene's own camera swapped in: no copy of the scene.
            let own = std::mem::replace(&mut cached.camera, scene.camera.clone());
            let same = *cached == *scene;
            cached.camera = own;
            same
        });
        let cached = match self.shown.take() {
            Some(mut cached) if same_but_camera => {
                cached.camera = camera;
                cached
            }
            _ => Scene {
                camera,
                ..scene.clone()
            },
        };
        self.shown.insert(cached)
    }

    /// Casts a click's ray off the UI thread, past the hidden objects.
    pub(crate) fn pick(&mut self, scene: &Scene, isolation: &Isolation, request: PickRequest) {
        if let Some(probes) = &mut self.probes {
            probes.picks.ask(scene, isolation, request);
        }
    }

    /// Takes finished answers: the command a pick asks for (or why it found nothing).
    pub(crate) fn poll(&mut self, scene: &Scene) -> Option<Result<crate::ui::Command, String>> {
        let probes = self.probes.as_mut()?;
        probes.inspections.poll();
        probes.picks.poll(scene)
    }

    /// Asks for the inspected and pinned pixels of `scene` with `switches` and
    /// `isolation` if they are not what was last asked.
    pub(crate) fn sync_inspections(
        &mut self,
        scene: &Scene,
        switches: TermSwitches,
        isolation: &Isolation,
    ) {
        let pixels = self
            .ray_paths
            .pixels(self.inspected, scene.camera.width, scene.camera.height);
        if let Some(probes) = &mut self.probes {
            probes.inspections.sync(scene, switches, isolation, pixels);
        }
    }

    /// Whether a probe is still working (the app keeps frames coming until it is done).
    pub fn is_busy(&self) -> bool {
        self.probes
            .as_ref()
            .is_some_and(|p| p.picks.is_busy() || p.inspections.is_busy())
    }

    /// The newest inspections of the inspected and pinned pixels.
    pub fn inspections(&self) -> &[PixelInspection] {
        self.probes.as_ref().map_or(&[], |p| p.inspections.all())
    }

    /// The newest inspection of the inspected pixel.
    pub fn inspection(&self) -> Option<&PixelInspection> {
        let pixel = self.inspected?;
        self.probes.as_ref()?.inspections.get(pixel)
    }

    /// Whether the inspections describe `scene` with `switches` and `isolation` as they
    /// are now.
    pub fn inspections_current(
        &self,
        scene: &Scene,
        switches: TermSwitches,
        isolation: &Isolation,
    ) -> bool {
        self.probes
            .as_ref()
            .is_some_and(|p| p.inspections.is_current(scene, switches, isolation))
    }
}
