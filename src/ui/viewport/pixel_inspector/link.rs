//! The pixel inspector's tracing, off the UI thread: the inspected pixel, its row or
//! column and the pinned pixels are traced in a probe job whenever the scene, the
//! switches, the isolation switches or the pixels change (at most one job at a time, the newest state next), and
//! the newest answer is kept for the window and the ray-path overlay.

use std::sync::Arc;

use super::inspection::PixelInspection;
use crate::preview::{Probe, WorldCache};
use crate::scene::Scene;
use crate::trace::{Isolation, TermSwitches};

/// What a question or an answer is about.
#[derive(Clone, Debug, PartialEq)]
struct About {
    scene: Arc<Scene>,
    switches: TermSwitches,
    isolation: Isolation,
    pixels: Vec<(u32, u32)>,
}

impl About {
    fn is(&self, scene: &Scene, switches: TermSwitches, isolation: &Isolation) -> bool {
        self.switches == switches && self.isolation == *isolation && *self.scene == *scene
    }
}

/// The jobs tracing the inspected pixels, and their newest answer.
pub struct InspectionLink {
    probe: Probe<Vec<PixelInspection>>,
    /// The questions not answered yet, oldest first, with their tags.
    asked: Vec<(u64, About)>,
    /// The newest answer and what it is about.
    answer: Option<(About, Vec<PixelInspection>)>,
}

impl InspectionLink {
    /// A link whose jobs share `cache` and call `waker` when done.
    #[must_use]
    pub fn new(cache: Arc<WorldCache>, waker: Arc<dyn Fn() + Send + Sync>) -> Self {
        Self {
            probe: Probe::new(cache, waker),
            asked: Vec::new(),
            answer: None,
        }
    }

    /// Asks for `pixels` of `scene` with `switches` and `isolation`, unless that is what
    /// the newest question was about. No pixels: forget everything.
    pub fn sync(
        &mut self,
        scene: &Scene,
        switches: TermSwitches,
        isolation: &Isolation,
        pixels: Vec<(u32, u32)>,
    ) {
        if pixels.is_empty() {
            self.asked.clear();
            self.answer = None;
            return;
        }
        let newest = self
            .asked
            .last()
            .map(|(_, about)| about)
            .or(self.answer.as_ref().map(|(about, _)| about));
        if newest
            .is_some_and(|about| about.is(scene, switches, isolation) && about.pixels == pixels)
        {
            return;
        }
        // The scene snapshot is shared with the last question when only pixels changed.
        let snapshot = match newest {
            Some(about) if *about.scene == *scene => Arc::clone(&about.scene),
            _ => Arc::new(scene.clone()),
        };
        let about = About {
            scene: Arc::clone(&snapshot),
            switches,
            isolation: isolation.clone(),
            pixels: pixels.clone(),
        };
        let job_scene = Arc::clone(&snapshot);
        let tag = self.probe.ask(
            snapshot,
            isolation.clone(),
            Box::new(move |world| {
                pixels
                    .iter()
                    .map(|p| PixelInspection::traced(world, &job_scene, switches, *p))
                    .collect()
            }),
        );
        self.asked.push((tag, about));
    }

    /// Takes a finished answer. A scene that cannot be traced answers every pixel with
    /// its message.
    pub fn poll(&mut self) {
        while let Some((tag, result)) = self.probe.poll() {
            let Some(at) = self.asked.iter().position(|(t, _)| *t == tag) else {
                continue;
            };
            let about = self.asked[at].1.clone();
            // Questions older than this one were replaced before they ran.
            self.asked.drain(..=at);
            let inspections = match result {
                Ok(inspections) => inspections,
                Err(error) => about
                    .pixels
                    .iter()
                    .map(|p| PixelInspection {
                        pixel: *p,
                        switches: about.switches,
                        isolation: about.isolation.clone(),
                        result: Err(error.clone()),
                    })
                    .collect(),
            };
            self.answer = Some((about, inspections));
        }
    }

    /// The newest inspection of `pixel`, current or not.
    #[must_use]
    pub fn get(&self, pixel: (u32, u32)) -> Option<&PixelInspection> {
        self.all().iter().find(|i| i.pixel == pixel)
    }

    /// Every inspection of the newest answer.
    #[must_use]
    pub fn all(&self) -> &[PixelInspection] {
        self.answer.as_ref().map_or(&[], |(_, all)| all.as_slice())
    }

    /// Whether the newest answer describes `scene` with `switches` and `isolation` (else
    /// it is shown while a newer one is traced).
    #[must_use]
    pub fn is_current(&self, scene: &Scene, switches: TermSwitches, isolation: &Isolation) -> bool {
        self.answer
            .as_ref()
            .is_some_and(|(about, _)| about.is(scene, switches, isolation))
    }

    /// Whether a job is running or waiting.
    #[must_use]
    pub fn is_busy(&self) -> bool {
        self.probe.is_busy()
    }
}
