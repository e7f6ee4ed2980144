//! The pixel inspector: every number behind one pixel, for the ray through its centre,
//! as the tracer's own shading code recorded it ([`inspect_pixel`]). The numbers are the
//! tracer's [`PixelReport`] itself; this model only adds the names of the objects,
//! materials and lights its indices point at, and of the lights and objects the
//! isolation switches leave out (shown as such, not as missing), so the window lays out
//! text.

mod window;

use crate::scene::Scene;
use crate::trace::{
    Isolation, PixelReport, RenderOptions, TermSwitches, View, World, inspect_pixel,
};
use crate::ui::panels::outliner::light_label;

pub use window::{
    FINAL_COLOUR_LABEL, isolation_lines, pixel_inspector_ui, shadow_text, switches_text,
};

/// One pixel inspected in one scene with one set of switches.
#[derive(Clone, Debug)]
pub struct PixelInspection {
    /// The pixel, in the scene camera's pixel grid.
    pub pixel: (u32, u32),
    /// The switches it was traced with.
    pub switches: TermSwitches,
    /// The lights and objects left out when it was traced.
    pub isolation: Isolation,
    /// The scene it was traced in (to notice edits).
    pub scene: Scene,
    /// The tracer's record with names resolved, or why the scene cannot be traced.
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
    /// Names for each of the bounce's lights, same order.
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

/// The names of one light's part.
#[derive(Clone, Debug, PartialEq)]
pub struct InspectedLight {
    /// "Point light 2": the kind and the outliner's number.
    pub label: String,
    /// The blocking object's name, if the shadow ray was blocked.
    pub blocked_by: Option<String>,
}

impl PixelInspection {
    /// Traces pixel `pixel` of `scene` at its own resolution with `switches` and
    /// `isolation`.
    #[must_use]
    pub fn new(
        scene: &Scene,
        switches: TermSwitches,
        isolation: &Isolation,
        pixel: (u32, u32),
    ) -> Self {
        let result = World::isolated(scene, isolation)
            .map_err(|e| e.to_string())
            .and_then(|world| {
                let (width, height) = (scene.camera.width, scene.camera.height);
                if pixel.0 >= width || pixel.1 >= height {
                    return Err(format!(
                        "pixel {pixel:?} is outside the {width} x {height} image"
                    ));
                }
                let options = RenderOptions {
                    switches,
                    view: View::Beauty,
                    isolation: isolation.clone(),
                    ..RenderOptions::from_scene(scene)
                };
                let report = inspect_pixel(&world, &options, pixel.0, pixel.1);
                Ok(resolve(scene, isolation, report))
            });
        Self {
            pixel,
            switches,
            isolation: isolation.clone(),
            scene: scene.clone(),
            result,
        }
    }

    /// Whether this inspection still describes `scene` with `switches` and `isolation`.
    #[must_use]
    pub fn is_current(&self, scene: &Scene, switches: TermSwitches, isolation: &Isolation) -> bool {
        self.switches == switches && self.isolation == *isolation && self.scene == *scene
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

/// Names for the (scene) indices of a report, and for what `isolation` leaves out.
fn resolve(scene: &Scene, isolation: &Isolation, report: PixelReport) -> InspectedPixel {
    let object_name = |i: usize| scene.objects.get(i).map_or("?", |o| o.name.as_str());
    let label = |i: usize| {
        scene
            .lights
            .get(i)
            .map_or_else(|| format!("light {}", i + 1), |light| light_label(light, i))
    };
    let bounces = report
        .bounces
        .iter()
        .map(|b| InspectedBounce {
            hit: b.hit.map(|hit| InspectedHit {
                object: object_name(hit.object).to_owned(),
                material: scene
                    .objects
                    .get(hit.object)
                    .map(|o| o.material.clone())
                    .unwrap_or_default(),
            }),
            lights: b
                .lights
                .iter()
                .map(|l| InspectedLight {
                    label: label(l.scene_index),
                    blocked_by: l.blocked_by.map(|i| object_name(i).to_owned()),
                })
                .collect(),
        })
        .collect();
    InspectedPixel {
        report,
        bounces,
        lights_off: (0..scene.lights.len())
            .filter(|&i| !isolation.is_light_lit(i))
            .map(label)
            .collect(),
        hidden_objects: isolation
            .hidden_objects
            .iter()
            .map(|&i| object_name(i).to_owned())
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_resolve_every_index_of_the_report() {
        let scene = crate::ui::files::default_scene();
        let mut mirrors = 0;
        let mut blocked = 0;
        for y in (0..scene.camera.height).step_by(37) {
            for x in (0..scene.camera.width).step_by(41) {
                let inspection =
                    PixelInspection::new(&scene, TermSwitches::ALL_ON, &Isolation::NONE, (x, y));
                let pixel = inspection.result.unwrap();
                assert_eq!(pixel.bounces.len(), pixel.report.bounces.len());
                for (bounce, names) in pixel.report.bounces.iter().zip(&pixel.bounces) {
                    assert_eq!(bounce.hit.is_some(), names.hit.is_some());
                    if let Some(hit) = &names.hit {
                        assert!(scene.objects.iter().any(|o| o.name == hit.object));
                        assert!(scene.materials.contains_key(&hit.material));
                    }
                    assert_eq!(bounce.lights.len(), names.lights.len());
                    for (light, light_names) in bounce.lights.iter().zip(&names.lights) {
                        assert!(light_names.label.contains("light"), "{}", light_names.label);
                        assert_eq!(light.blocked_by.is_some(), light_names.blocked_by.is_some());
                        blocked += usize::from(light.blocked_by.is_some());
                    }
                }
                mirrors += usize::from(pixel.bounces.len() > 1);
            }
        }
        assert!(mirrors > 0 && blocked > 0, "{mirrors} {blocked}");
    }

    #[test]
    fn a_pixel_outside_the_image_or_a_broken_scene_is_an_error_not_a_panic() {
        let mut scene = crate::ui::files::default_scene();
        let none = Isolation::NONE;
        let outside = PixelInspection::new(&scene, TermSwitches::ALL_ON, &none, (10_000, 0));
        assert!(outside.result.unwrap_err().contains("outside"));
        scene.objects[0].material = "missing".to_owned();
        let broken = PixelInspection::new(&scene, TermSwitches::ALL_ON, &none, (1, 1));
        assert!(broken.result.is_err());
    }
}
