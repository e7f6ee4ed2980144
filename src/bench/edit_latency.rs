//! Edit to first full-resolution frame, by kind of edit, through the real preview worker:
//! a material colour, a term switch, a light's colour, a light moved and an object moved.
//! The first three re-shade the worker's cached hits, a moved light re-casts its shadow
//! rays, and a moved object re-traces from the coarse passes on; the report puts each
//! beside `full_frame_1spp_ms`.

use std::time::{Duration, Instant};

use glam::DVec3;
use serde::Serialize;

use crate::preview::{Pass, PreviewRequest, PreviewWorker, median};
use crate::scene::{Light, LightSource, Scene, Transform};
use crate::trace::Term;

/// Median milliseconds from an edit's submit to its first full-resolution frame.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct EditLatency {
    /// The diffuse colour of the first object's material changed.
    pub material: f64,
    /// The specular term switched off or on.
    pub switch: f64,
    /// A light's colour changed.
    pub light_colour: f64,
    /// A light moved.
    pub light_move: f64,
    /// An object moved.
    pub geometry: f64,
}

/// The kinds of edit measured, in the report's order.
#[derive(Clone, Copy, Debug)]
enum EditKind {
    Material,
    Switch,
    LightColour,
    LightMove,
    Geometry,
}

/// Applies edit `kind` to `request`; `flip` alternates between two states so that every
/// submit is a real change. `Err` when the scene has nothing to edit that way.
fn apply(kind: EditKind, request: &mut PreviewRequest, flip: bool) -> Result<(), String> {
    let scene: &mut Scene = std::sync::Arc::make_mut(&mut request.scene);
    let sign = if flip { 1.0 } else { -1.0 };
    match kind {
        EditKind::Material => {
            // The first object's material (the default scene's floor, under half the
            // picture and in every mirror): a material edit re-shades only the pixels
            // whose rays meet it.
            let name = scene.objects.first().ok_or("no object")?.material.clone();
            let material = scene.materials.get_mut(&name).ok_or("no material")?;
            material.diffuse = if flip {
                DVec3::new(0.8, 0.3, 0.2)
            } else {
                DVec3::new(0.2, 0.5, 0.7)
            };
        }
        EditKind::Switch => request.options.switches.set(Term::Specular, !flip),
        EditKind::LightColour | EditKind::LightMove => {
            let light = scene
                .lights
                .iter_mut()
                .find(|l| !matches!(l, Light::Ambient { .. }))
                .ok_or("no light to edit")?;
            match (kind, light) {
                (
                    EditKind::LightColour,
                    Light::Point {
                        source: LightSource { colour, .. },
                        ..
                    }
                    | Light::Directional { colour, .. }
                    | Light::Spot {
                        source: LightSource { colour, .. },
                        ..
                    },
                ) => {
                    *colour = if flip {
                        DVec3::new(1.0, 0.6, 0.4)
                    } else {
                        DVec3::new(0.5, 0.8, 1.0)
                    };
                }
                (_, Light::Point { position, .. } | Light::Spot { position, .. }) => {
                    *position += DVec3::new(0.05, 0.0, 0.03) * sign;
                }
                (_, Light::Directional { direction, .. }) => {
                    *direction += DVec3::new(0.02, 0.0, 0.01) * sign;
                }
                (_, Light::Ambient { .. }) => unreachable!("ambient lights are skipped"),
            }
        }
        EditKind::Geometry => {
            let trs = scene
                .objects
                .iter_mut()
                .find_map(|o| match &mut o.transform {
                    Transform::Trs(trs) => Some(trs),
                    Transform::Matrix(_) => None,
                })
                .ok_or("no object with a translation to move")?;
            trs.translate.x += 0.01 * sign;
        }
    }
    Ok(())
}

/// Waits for the first frame of `generation` (the first full-resolution one, with
/// `full`) and returns when it came.
fn first_frame(
    worker: &mut PreviewWorker,
    generation: u64,
    full: bool,
    timeout: Duration,
) -> Result<Instant, String> {
    loop {
        let message = worker
            .recv_timeout(timeout)
            .ok_or("the preview worker did not answer")?;
        if message.generation != generation {
            continue;
        }
        let frame = message.result?;
        if !full || matches!(frame.pass, Pass::Full { .. }) {
            return Ok(Instant::now());
        }
    }
}

/// A preview worker that has shown `request` and is refining it (as after a user's
/// pause), for edits to be timed against.
fn settled_worker(request: &PreviewRequest, timeout: Duration) -> Result<PreviewWorker, String> {
    let mut worker = PreviewWorker::spawn(Box::new(|| {}));
    worker.submit(request.clone());
    first_frame(&mut worker, request.generation, true, timeout)?;
    if request.scene.render.samples_per_pixel > 1 {
        // The worker keeps the rays of the one-sample pass once that pass is shown,
        // before the first anti-aliasing pass: the edits start when the picture is
        // refining, as after a user's pause.
        first_frame(&mut worker, request.generation, true, timeout)?;
    }
    Ok(worker)
}

/// The median over `runs` edits of `kind` of the time from the submit to the first
/// frame (the first full-resolution one, with `full`).
fn time_edits(
    worker: &mut PreviewWorker,
    request: &mut PreviewRequest,
    kind: EditKind,
    runs: u32,
    full: bool,
    timeout: Duration,
) -> Result<f64, String> {
    let mut times = Vec::new();
    for run in 0..runs.max(1) {
        apply(kind, request, run % 2 == 0)?;
        request.generation += 1;
        let submitted = Instant::now();
        worker.submit(request.clone());
        let at = first_frame(worker, request.generation, full, timeout)?;
        times.push(at - submitted);
    }
    Ok(median(times).as_secs_f64() * 1e3)
}

/// Median milliseconds from an edit's submit to its first frame of any pass, for the
/// edits that re-shade (a material's colour, a light's colour).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct FirstFrameLatency {
    /// The diffuse colour of the first object's material changed.
    pub material: f64,
    /// A light's colour changed.
    pub light_colour: f64,
}

/// For `request` (its scene, options and meshes): per re-shading edit, the median over
/// `runs` edits of the time from the submit to the first frame shown.
///
/// # Errors
/// When the scene cannot be rendered or has no light to edit.
pub fn first_frame_latency(
    mut request: PreviewRequest,
    runs: u32,
) -> Result<FirstFrameLatency, String> {
    let timeout = Duration::from_secs(120);
    let mut worker = settled_worker(&request, timeout)?;
    let mut measure = |kind| time_edits(&mut worker, &mut request, kind, runs, false, timeout);
    Ok(FirstFrameLatency {
        material: measure(EditKind::Material)?,
        light_colour: measure(EditKind::LightColour)?,
    })
}

/// For `scene` at its own size and samples: per kind of edit, the median over `runs`
/// edits of the time from the submit to the first full-resolution frame. One worker
/// runs them all, each edit made while the previous one's anti-aliasing passes run, as
/// a user's would be.
///
/// # Errors
/// When the scene cannot be rendered or has nothing to edit of some kind.
pub fn edit_latency(scene: &Scene, runs: u32) -> Result<EditLatency, String> {
    let timeout = Duration::from_secs(120);
    let mut request = PreviewRequest::for_scene(1, scene.clone());
    let mut worker = settled_worker(&request, timeout)?;
    let mut measure = |kind| time_edits(&mut worker, &mut request, kind, runs, true, timeout);
    Ok(EditLatency {
        material: measure(EditKind::Material)?,
        switch: measure(EditKind::Switch)?,
        light_colour: measure(EditKind::LightColour)?,
        light_move: measure(EditKind::LightMove)?,
        geometry: measure(EditKind::Geometry)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kind_of_edit_changes_the_scene_and_a_scene_without_lights_is_an_error() {
        let scene = crate::scene::examples::default_scene();
        for kind in [
            EditKind::Material,
            EditKind::Switch,
            EditKind::LightColour,
            EditKind::LightMove,
            EditKind::Geometry,
        ] {
            // As the benchmark goes: flip, unflip, flip again, each a change.
            let mut before = PreviewRequest::for_scene(1, scene.clone());
            for flip in [true, false, true] {
                let mut after = before.clone();
                apply(kind, &mut after, flip).unwrap();
                let changed = after.scene != before.scene || after.options != before.options;
                assert!(changed, "{kind:?} {flip}");
                before = after;
            }
        }
        let mut dark = scene;
        dark.lights.clear();
        let mut request = PreviewRequest::for_scene(1, dark);
        assert!(apply(EditKind::LightMove, &mut request, true).is_err());
    }
}
