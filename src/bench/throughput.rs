//! Rays per second on whole frames at one sample per pixel, all cores.

use std::time::Instant;

use serde::Serialize;

use crate::scene::Scene;
use crate::trace::{RenderOptions, RenderProgress, World, render};

/// Throughput of one scene.
#[derive(Clone, Debug, Serialize)]
pub struct SceneThroughput {
    /// File name of the scene.
    pub scene: String,
    /// Frame size.
    pub width: u32,
    /// Frame size.
    pub height: u32,
    /// Best time of the runs, milliseconds.
    pub frame_ms: f64,
    /// Primary rays per frame.
    pub primary_rays: u64,
    /// Shadow rays per frame.
    pub shadow_rays: u64,
    /// Mirror rays per frame.
    pub reflection_rays: u64,
    /// Transmitted rays per frame (refracted or internally reflected).
    pub transmission_rays: u64,
    /// All rays per second, millions.
    pub mrays_per_s: f64,
}

/// Renders `scene` (called `name` in the report) at `width` x `height`, 1 sample per
/// pixel, `runs` times and keeps the best time.
///
/// # Errors
/// The scene cannot be rendered.
pub fn scene_throughput(
    name: &str,
    scene: &Scene,
    width: u32,
    height: u32,
    runs: u32,
) -> Result<SceneThroughput, String> {
    let world = World::new(scene).map_err(|e| format!("{name}: {e}"))?;
    let options = RenderOptions {
        width,
        height,
        samples_per_pixel: 1,
        ..RenderOptions::from_scene(scene)
    };
    let mut best = f64::INFINITY;
    let mut rays = crate::trace::RayCounts::default();
    for _ in 0..runs.max(1) {
        let started = Instant::now();
        let (_, counts) =
            render(&world, &options, &RenderProgress::default()).ok_or("cancelled")?;
        best = best.min(started.elapsed().as_secs_f64());
        rays = counts;
    }
    Ok(SceneThroughput {
        scene: name.to_owned(),
        width,
        height,
        frame_ms: best * 1e3,
        primary_rays: rays.primary,
        shadow_rays: rays.shadow,
        reflection_rays: rays.reflection,
        transmission_rays: rays.transmission,
        mrays_per_s: rays.total() as f64 / best / 1e6,
    })
}
