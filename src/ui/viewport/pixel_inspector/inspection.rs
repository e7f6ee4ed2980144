//! One pixel inspected: the tracer's report with the names of the objects, materials and
//! lights its indices point at, and of what the isolation switches leave out.

use crate::scene::{Light, Scene};
use crate::trace::{
    Isolation, LightRecord, PixelReport, RenderOptions, TermSwitches, View, World,
    try_inspect_pixel,
};
use crate::ui::state::light_label;

/// One pixel inspected in one scene with one set of switches.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelInspection {
    /// The pixel, in the scene camera's pixel grid.
    pub pixel: (u32, u32),
    /// The switches it was traced with.
    pub switches: TermSwitches,
    /// The lights and objects left out when it was traced.
    pub isolation: Isolation,
    /// The tracer's record with names resolved, or why the pixel cannot be traced.
    pub result: Result<InspectedPixel, String>,
}

/// The tracer's [`PixelReport`] and the names its indices stand for.
#[derive(Clone, Debug, PartialEq)]
pub struct InspectedPixel {
    /// The numbers, as the tracer recorded them.
    pub report: PixelReport,
    /// Names for each of `report.bounces`, same order.
    pub bounces: Vec<InspectedBounce>,
    /// The lights that do not shine (muted, or not solo while others are), by label.
    pub lights_off: Vec<String>,
    /// The objects left out, by name.
    pub hidden_objects: Vec<String>,
}

/// The names behind one ray of the chain.
#[derive(Clone, Debug, PartialEq)]
pub struct InspectedBounce {
    /// What it hit, or `None` for a miss.
    pub hit: Option<InspectedHit>,
    /// Every light of the scene, in its order, with what it did at the hit (empty for a
    /// miss).
    pub lights: Vec<InspectedLight>,
}

/// The names of a surface hit.
#[derive(Clone, Debug, PartialEq)]
pub struct InspectedHit {
    /// The object's name.
    pub object: String,
    /// Its material's name.
    pub material: String,
}

/// One light's part at a hit, named.
#[derive(Clone, Debug, PartialEq)]
pub struct InspectedLight {
    /// Index of the light in the scene's list.
    pub scene_index: usize,
    /// "Point light 2": the kind and the outliner's number.
    pub label: String,
    /// What it did, in words: "lit", "behind the surface", "shadowed by red ball"...
    pub outcome: String,
    /// Whether it added light.
    pub adds_light: bool,
    /// The shader's numbers, for a light it sampled.
    pub record: Option<LightRecord>,
}

impl PixelInspection {
    /// Traces pixel `pixel` of `scene` (compiled as `world`, with `world.isolation`) at
    /// its own resolution with `switches`. Runs off the UI thread, in
    /// [`link::InspectionLink`]'s jobs.
    #[must_use]
    pub fn traced(world: &World, scene: &Scene, switches: TermSwitches, pixel: (u32, u32)) -> Self {
        let options = RenderOptions {
            switches,
            view: View::Beauty,
            isolation: world.isolation.clone(),
            ..RenderOptions::from_scene(scene)
        };
        let result = try_inspect_pixel(world, &options, pixel.0, pixel.1)
            .map(|report| resolve(scene, &world.isolation, report))
            .map_err(|e| e.to_string());
        Self {
            pixel,
            switches,
            isolation: world.isolation.clone(),
            result,
        }
    }
}

/// The pixel of the scene camera's image at `image_point` (in its pixels, fractional),
/// or `None` outside the image.
#[must_use]
pub fn inspected_pixel(scene: &Scene, image_point: glam::DVec2) -> Option<(u32, u32)> {
    let (width, height) = (scene.camera.width, scene.camera.height);
    let inside = image_point.x >= 0.0
        && image_point.y >= 0.0
        && image_point.x < f64::from(width)
        && image_point.y < f64::from(height);
    inside.then(|| {
        let x = (image_point.x.floor() as u32).min(width.saturating_sub(1));
        let y = (image_point.y.floor() as u32).min(height.saturating_sub(1));
        (x, y)
    })
}

/// Outcome text of a light the isolation switches turn off.
pub const LIGHT_OFF_OUTCOME: &str = "off (muted or not solo)";

/// Names for the (scene) indices of a report, and for what `isolation` leaves out.
fn resolve(scene: &Scene, isolation: &Isolation, report: PixelReport) -> InspectedPixel {
    let object_name = |i: usize| {
        scene
            .objects
            .get(i)
            .map_or_else(|| format!("object {i}"), |o| o.name.clone())
    };
    let bounces = report
        .bounces
        .iter()
        .map(|b| {
            let Some(hit) = b.hit else {
                return InspectedBounce {
                    hit: None,
                    lights: Vec::new(),
                };
            };
            let outcomes = b.light_outcomes();
            let lights = scene
                .lights
                .iter()
                .enumerate()
                .filter_map(|(index, light)| {
                    let label = light_label(light, index);
                    if !isolation.is_light_lit(index) {
                        return Some(InspectedLight {
                            scene_index: index,
                            label,
                            outcome: LIGHT_OFF_OUTCOME.to_owned(),
                            adds_light: false,
                            record: None,
                        });
                    }
                    if matches!(light, Light::Ambient { .. }) {
                        return Some(InspectedLight {
                            scene_index: index,
                            label,
                            outcome: "in the ambient term (ka × its colour)".to_owned(),
                            adds_light: b.ambient != glam::DVec3::ZERO,
                            record: None,
                        });
                    }
                    let (_, outcome, record) = outcomes.iter().find(|(i, ..)| *i == index)?;
                    // A blocker in a tree is named by the leaf the shadow ray met.
                    let blocker_name = |blocker: usize| {
                        b.blocker_hits
                            .iter()
                            .find(|(light, ..)| *light == index)
                            .map_or_else(|| object_name(blocker), |(.., s)| s.path.clone())
                    };
                    Some(InspectedLight {
                        scene_index: index,
                        label,
                        outcome: outcome.text(&blocker_name),
                        adds_light: outcome.adds_light(),
                        record: record.copied(),
                    })
                })
                .collect();
            InspectedBounce {
                hit: Some(InspectedHit {
                    object: object_name(hit.object),
                    material: scene
                        .objects
                        .get(hit.object)
                        .map(|o| o.material.clone())
                        .unwrap_or_default(),
                }),
                lights,
            }
        })
        .collect();
    InspectedPixel {
        report,
        bounces,
        lights_off: (0..scene.lights.len())
            .filter(|&i| !isolation.is_light_lit(i))
            .map(|i| light_label(&scene.lights[i], i))
            .collect(),
        hidden_objects: isolation
            .hidden_objects
            .iter()
            .map(|&i| object_name(i))
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_light_of_the_scene_is_listed_with_what_it_did() {
        let scene = crate::ui::files::default_scene();
        let world = World::new(&scene).unwrap();
        let mut mirrors = 0;
        let mut shadowed = 0;
        let mut behind = 0;
        for y in (0..scene.camera.height).step_by(37) {
            for x in (0..scene.camera.width).step_by(41) {
                let inspection =
                    PixelInspection::traced(&world, &scene, TermSwitches::ALL_ON, (x, y));
                let pixel = inspection.result.unwrap();
                assert_eq!(pixel.bounces.len(), pixel.report.bounces.len());
                for (bounce, names) in pixel.report.bounces.iter().zip(&pixel.bounces) {
                    assert_eq!(bounce.hit.is_some(), names.hit.is_some());
                    let Some(hit) = &names.hit else {
                        continue;
                    };
                    assert!(scene.objects.iter().any(|o| o.name == hit.object));
                    assert!(scene.materials.contains_key(&hit.material));
                    let listed: Vec<usize> = names.lights.iter().map(|l| l.scene_index).collect();
                    assert_eq!(listed, (0..scene.lights.len()).collect::<Vec<_>>());
                    for light in &names.lights {
                        if let Some(record) = &light.record {
                            if let Some(blocker) = record.blocked_by {
                                let name = &scene.objects[blocker].name;
                                assert_eq!(light.outcome, format!("shadowed by {name}"));
                                shadowed += 1;
                            }
                            if record.n_dot_l <= 0.0 {
                                assert_eq!(light.outcome, "behind the surface");
                                behind += 1;
                            }
                            assert_eq!(light.adds_light, light.outcome == "lit");
                        }
                    }
                }
                mirrors += usize::from(pixel.bounces.len() > 1);
            }
        }
        assert!(
            mirrors > 0 && shadowed > 0 && behind > 0,
            "{mirrors} {shadowed} {behind}"
        );
    }

    #[test]
    fn a_pixel_outside_the_image_is_an_error_not_a_panic() {
        let scene = crate::ui::files::default_scene();
        let world = World::new(&scene).unwrap();
        let outside = PixelInspection::traced(&world, &scene, TermSwitches::ALL_ON, (10_000, 0));
        assert!(
            outside
                .result
                .unwrap_err()
                .contains("outside the 800 x 600 image")
        );
    }
}
