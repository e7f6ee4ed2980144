//! Clicks on the picture, answered off the UI thread: the ray under the cursor (from the
//! camera the viewport shows) is cast in a probe job against the world of the scene,
//! and the answer selects the object it meets, or inspects the scene camera's pixel that
//! sees the point it meets (so a click in a free view inspects what the scene camera
//! shows there).

use std::sync::Arc;

use glam::DVec3;

use super::pixel_inspector::inspected_pixel;
use crate::preview::{Probe, WorldCache};
use crate::scene::Scene;
use crate::trace::{Isolation, PinholeCamera};
use crate::ui::commands::{Command, Selection};
use crate::ui::state::{PickPurpose, PickRequest};

/// What the ray met first.
#[derive(Clone, Debug, PartialEq)]
struct PickAnswer {
    /// The path of the scene node hit (see `World::node_path`).
    node: Option<Vec<usize>>,
    point: Option<DVec3>,
}

/// The pick jobs.
pub struct PickLink {
    probe: Probe<PickAnswer>,
    /// The newest click's tag and purpose; answers to older clicks are dropped.
    newest: Option<(u64, PickPurpose)>,
}

impl PickLink {
    /// A link whose jobs share `cache` and call `waker` when done.
    #[must_use]
    pub fn new(cache: Arc<WorldCache>, waker: Arc<dyn Fn() + Send + Sync>) -> Self {
        Self {
            probe: Probe::new(cache, waker),
            newest: None,
        }
    }

    /// Casts `request`'s ray into `scene` without what `isolation` leaves out (a hidden
    /// object cannot be picked), in a job.
    pub fn ask(&mut self, scene: &Scene, isolation: &Isolation, request: PickRequest) {
        let ray = request.ray;
        let tag = self.probe.ask(
            Arc::new(scene.clone()),
            isolation.clone(),
            Box::new(move |world| {
                let hit = world.intersect(&ray, f64::INFINITY);
                PickAnswer {
                    node: hit.as_ref().map(|h| world.node_path(h)),
                    point: hit.map(|h| h.p),
                }
            }),
        );
        self.newest = Some((tag, request.purpose));
    }

    /// The command a finished pick asks for, or the message of one that found nothing to
    /// inspect. `scene` gives the scene camera a point is seen through.
    pub fn poll(&mut self, scene: &Scene) -> Option<Result<Command, String>> {
        let mut outcome = None;
        while let Some((tag, result)) = self.probe.poll() {
            let Some((_, purpose)) = self.newest.filter(|(t, _)| *t == tag) else {
                continue;
            };
            self.newest = None;
            outcome = Some(result.and_then(|answer| command_for(scene, purpose, answer)));
        }
        outcome
    }

    /// Whether a pick is running or waiting.
    #[must_use]
    pub fn is_busy(&self) -> bool {
        self.probe.is_busy()
    }
}

fn command_for(scene: &Scene, purpose: PickPurpose, answer: PickAnswer) -> Result<Command, String> {
    match purpose {
        PickPurpose::Select => Ok(Command::Select(
            answer.node.map_or(Selection::None, Selection::node),
        )),
        PickPurpose::SelectParent => Ok(Command::Select(answer.node.map_or(
            Selection::None,
            |mut path| {
                if path.len() > 1 {
                    path.pop();
                }
                Selection::node(path)
            },
        ))),
        PickPurpose::Inspect => {
            let point = answer
                .point
                .ok_or("Nothing there to inspect: the ray meets no object")?;
            let camera = PinholeCamera::new(&scene.camera, scene.camera.width, scene.camera.height);
            camera
                .project(point)
                .and_then(|p| inspected_pixel(scene, p))
                .map(|pixel| Command::InspectPixel(Some(pixel)))
                .ok_or_else(|| "That point is outside the scene camera's picture".to_owned())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_seen_from_aside_inspects_the_scene_camera_pixel_that_sees_it() {
        let scene = crate::ui::files::default_scene();
        let camera = PinholeCamera::new(&scene.camera, scene.camera.width, scene.camera.height);
        let point = DVec3::new(0.2, 0.5, 0.1);
        let pixel = camera.project(point).unwrap();
        let answer = PickAnswer {
            node: Some(vec![1]),
            point: Some(point),
        };
        let expected = (pixel.x.floor() as u32, pixel.y.floor() as u32);
        assert_eq!(
            command_for(&scene, PickPurpose::Inspect, answer.clone()),
            Ok(Command::InspectPixel(Some(expected)))
        );
        assert_eq!(
            command_for(&scene, PickPurpose::Select, answer.clone()),
            Ok(Command::Select(Selection::Object(1)))
        );
        // A leaf of a tree is selected as a part; Shift+click takes the node holding it.
        let leaf = PickAnswer {
            node: Some(vec![2, 0, 3]),
            ..answer
        };
        assert_eq!(
            command_for(&scene, PickPurpose::Select, leaf.clone()),
            Ok(Command::Select(Selection::Part(vec![2, 0, 3])))
        );
        assert_eq!(
            command_for(&scene, PickPurpose::SelectParent, leaf),
            Ok(Command::Select(Selection::Part(vec![2, 0])))
        );
        let behind = PickAnswer {
            node: Some(vec![1]),
            point: Some(scene.camera.position * 2.0 - scene.camera.look_at),
        };
        assert!(command_for(&scene, PickPurpose::Inspect, behind).is_err());
    }
}
