//! The pixel inspector: every number behind one pixel, for the ray through its centre,
//! as the tracer's own shading code recorded it ([`inspect_pixel`]). The data model
//! ([`PixelInspection`]) resolves indices to names so the window only lays out text.

use egui::{Color32, RichText};
use glam::DVec3;

use super::commands::Command;
use super::outliner::light_label;
use crate::scene::Scene;
use crate::trace::{BounceReport, PixelReport, Term, TermSwitches, World, inspect_pixel};

/// One pixel inspected in one scene with one set of switches.
#[derive(Clone, Debug)]
pub struct PixelInspection {
    /// The pixel, in the scene camera's pixel grid.
    pub pixel: (u32, u32),
    /// The switches it was traced with.
    pub switches: TermSwitches,
    /// The scene it was traced in (to notice edits).
    pub scene: Scene,
    /// The chain of rays with names resolved, or why the scene cannot be traced.
    pub result: Result<InspectedPixel, String>,
}

/// The numbers of [`PixelReport`] with names for objects, materials and lights.
#[derive(Clone, Debug, PartialEq)]
pub struct InspectedPixel {
    /// The camera ray, then each mirror bounce.
    pub bounces: Vec<InspectedBounce>,
    /// The colour before clamping.
    pub unclamped: DVec3,
    /// The colour written, clamped to [0, 1].
    pub clamped: DVec3,
}

/// One ray of the chain.
#[derive(Clone, Debug, PartialEq)]
pub struct InspectedBounce {
    /// 0 for the camera ray.
    pub depth: u32,
    /// What it hit, or `None` for a miss.
    pub hit: Option<InspectedHit>,
    /// The colour of a miss.
    pub background: DVec3,
    /// The ambient term.
    pub ambient: DVec3,
    /// The lights that can reach the point.
    pub lights: Vec<InspectedLight>,
    /// `(km, reflected colour)` when a mirror ray was cast.
    pub reflection: Option<(DVec3, DVec3)>,
    /// The colour this ray returned.
    pub colour: DVec3,
}

/// A surface hit.
#[derive(Clone, Debug, PartialEq)]
pub struct InspectedHit {
    /// The object's name.
    pub object: String,
    /// Its material's name.
    pub material: String,
    /// Ray parameter.
    pub t: f64,
    /// The hit point (world).
    pub p: DVec3,
    /// The shading normal (facing the ray).
    pub n: DVec3,
}

/// One light's part.
#[derive(Clone, Debug, PartialEq)]
pub struct InspectedLight {
    /// "Point light 2": the kind and the outliner's number.
    pub label: String,
    /// Strength arriving at the point, before visibility.
    pub strength: DVec3,
    /// n.l.
    pub n_dot_l: f64,
    /// Whether a shadow ray was cast.
    pub shadow_ray_cast: bool,
    /// The blocking object's name, if the shadow ray was blocked.
    pub blocked_by: Option<String>,
    /// Diffuse contribution.
    pub diffuse: DVec3,
    /// Specular contribution.
    pub specular: DVec3,
}

impl InspectedBounce {
    /// The sum of the listed terms: ambient + each light's diffuse and specular + km x
    /// reflected for a hit, the background for a miss. Equals `colour`.
    #[must_use]
    pub fn sum_of_terms(&self) -> DVec3 {
        if self.hit.is_none() {
            return self.background;
        }
        let local: DVec3 = self.lights.iter().map(|l| l.diffuse + l.specular).sum();
        let mirror = self.reflection.map_or(DVec3::ZERO, |(km, c)| km * c);
        self.ambient + local + mirror
    }
}

impl PixelInspection {
    /// Traces pixel `pixel` of `scene` at its own resolution with `switches`.
    #[must_use]
    pub fn new(scene: &Scene, switches: TermSwitches, pixel: (u32, u32)) -> Self {
        let result = World::new(scene)
            .map_err(|e| e.to_string())
            .and_then(|world| {
                let (width, height) = (scene.camera.width, scene.camera.height);
                if pixel.0 >= width || pixel.1 >= height {
                    return Err(format!(
                        "pixel {pixel:?} is outside the {width} x {height} image"
                    ));
                }
                let options = crate::trace::RenderOptions {
                    switches,
                    view: crate::trace::View::Beauty,
                    ..crate::trace::RenderOptions::from_scene(scene)
                };
                let report = inspect_pixel(&world, &options, pixel.0, pixel.1);
                Ok(resolve(&world, scene, &report))
            });
        Self {
            pixel,
            switches,
            scene: scene.clone(),
            result,
        }
    }

    /// Whether this inspection still describes `scene` with `switches`.
    #[must_use]
    pub fn is_current(&self, scene: &Scene, switches: TermSwitches) -> bool {
        self.switches == switches && self.scene == *scene
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

/// Names for the indices of a report.
fn resolve(world: &World, scene: &Scene, report: &PixelReport) -> InspectedPixel {
    let object_name = |i: usize| world.objects.get(i).map_or("?", |o| o.name.as_str());
    let bounce = |b: &BounceReport| InspectedBounce {
        depth: b.depth,
        hit: b.hit.map(|hit| InspectedHit {
            object: object_name(hit.object).to_owned(),
            material: world
                .objects
                .get(hit.object)
                .and_then(|o| world.material_names.get(o.material))
                .cloned()
                .unwrap_or_default(),
            t: hit.t,
            p: hit.p,
            n: hit.n,
        }),
        background: b.background,
        ambient: b.ambient,
        lights: b
            .lights
            .iter()
            .map(|l| InspectedLight {
                label: scene.lights.get(l.scene_index).map_or_else(
                    || format!("light {}", l.scene_index + 1),
                    |light| light_label(light, l.scene_index),
                ),
                strength: l.strength,
                n_dot_l: l.n_dot_l,
                shadow_ray_cast: l.shadow_ray_cast,
                blocked_by: l.blocked_by.map(|i| object_name(i).to_owned()),
                diffuse: l.diffuse,
                specular: l.specular,
            })
            .collect(),
        reflection: b.reflection,
        colour: b.colour,
    };
    InspectedPixel {
        bounces: report.bounces.iter().map(bounce).collect(),
        unclamped: report.unclamped,
        clamped: report.clamped,
    }
}

/// Accessible name of the inspector window's final colour line.
pub const FINAL_COLOUR_LABEL: &str = "final colour";

/// Shows the inspector window; closing it pushes [`Command::InspectPixel`]`(None)`.
pub fn pixel_inspector_ui(
    ctx: &egui::Context,
    inspection: &PixelInspection,
    commands: &mut Vec<Command>,
) {
    let mut open = true;
    // Over the right of the picture, below the toolbar, clear of the side panels.
    let corner = ctx.content_rect().right_top() + egui::vec2(-800.0, 110.0);
    egui::Window::new("Pixel inspector")
        .open(&mut open)
        .default_pos(corner.max(egui::pos2(0.0, 0.0)))
        .default_width(420.0)
        .resizable(true)
        .show(ctx, |ui| {
            let (x, y) = inspection.pixel;
            ui.label(RichText::new(format!("Pixel ({x}, {y})")).strong());
            ui.weak(format!(
                "centre ray, beauty lighting · {}",
                switches_text(inspection.switches)
            ));
            ui.separator();
            match &inspection.result {
                Ok(pixel) => pixel_ui(ui, pixel),
                Err(error) => {
                    ui.colored_label(Color32::from_rgb(255, 120, 110), error);
                }
            }
        });
    if !open {
        commands.push(Command::InspectPixel(None));
    }
}

/// "all terms on", or "off: diffuse, shadows · solo specular".
#[must_use]
pub fn switches_text(switches: TermSwitches) -> String {
    let off: Vec<&str> = Term::ALL
        .into_iter()
        .filter(|t| !switches.is_on(*t))
        .map(Term::name)
        .collect();
    let mut parts = Vec::new();
    if !off.is_empty() {
        parts.push(format!("off: {}", off.join(", ")));
    }
    if let Some(solo) = switches.solo {
        parts.push(format!("solo {solo}"));
    }
    if parts.is_empty() {
        "all terms on".to_owned()
    } else {
        parts.join(" · ")
    }
}

fn pixel_ui(ui: &mut egui::Ui, pixel: &InspectedPixel) {
    egui::ScrollArea::vertical()
        .max_height(380.0)
        .show(ui, |ui| {
            for bounce in &pixel.bounces {
                let title = match bounce.depth {
                    0 => "Camera ray".to_owned(),
                    d => format!("Reflection, depth {d}"),
                };
                egui::CollapsingHeader::new(RichText::new(title).strong())
                    .id_salt(("bounce", bounce.depth))
                    .default_open(true)
                    .show(ui, |ui| bounce_ui(ui, bounce));
            }
        });
    ui.separator();
    egui::Grid::new("final colour")
        .num_columns(2)
        .show(ui, |ui| {
            ui.label("before clamping");
            ui.monospace(colour_text(pixel.unclamped));
            ui.end_row();
            ui.label(FINAL_COLOUR_LABEL);
            ui.horizontal(|ui| {
                swatch_ui(ui, pixel.clamped);
                ui.monospace(colour_text(pixel.clamped));
            });
            ui.end_row();
        });
}

fn bounce_ui(ui: &mut egui::Ui, bounce: &InspectedBounce) {
    let Some(hit) = &bounce.hit else {
        egui::Grid::new(("miss", bounce.depth))
            .num_columns(2)
            .show(ui, |ui| {
                ui.label("hit");
                ui.label("nothing (background)");
                ui.end_row();
                ui.label("colour");
                ui.monospace(colour_text(bounce.colour));
                ui.end_row();
            });
        return;
    };
    egui::Grid::new(("hit", bounce.depth))
        .num_columns(2)
        .show(ui, |ui| {
            ui.label("hit");
            ui.label(RichText::new(&hit.object).strong());
            ui.end_row();
            ui.label("material");
            ui.label(&hit.material);
            ui.end_row();
            ui.label("t");
            ui.monospace(format!("{:.6}", hit.t));
            ui.end_row();
            ui.label("point");
            ui.monospace(vector_text(hit.p));
            ui.end_row();
            ui.label("normal");
            ui.monospace(vector_text(hit.n));
            ui.end_row();
            ui.label("ambient");
            ui.monospace(colour_text(bounce.ambient));
            ui.end_row();
        });
    for light in &bounce.lights {
        light_ui(ui, light, bounce.depth);
    }
    if bounce.lights.is_empty() {
        ui.weak("no light reaches this point");
    }
    egui::Grid::new(("result", bounce.depth))
        .num_columns(2)
        .show(ui, |ui| {
            ui.label("reflection");
            match bounce.reflection {
                Some((km, reflected)) => ui.monospace(format!(
                    "km {} × {} = {}",
                    colour_text(km),
                    colour_text(reflected),
                    colour_text(km * reflected)
                )),
                None => ui.weak("no mirror ray"),
            };
            ui.end_row();
            ui.label("colour");
            ui.monospace(colour_text(bounce.colour));
            ui.end_row();
        });
}

fn light_ui(ui: &mut egui::Ui, light: &InspectedLight, depth: u32) {
    ui.label(RichText::new(&light.label).underline());
    egui::Grid::new(("light", depth, &light.label))
        .num_columns(2)
        .show(ui, |ui| {
            ui.label("strength");
            ui.monospace(colour_text(light.strength));
            ui.end_row();
            ui.label("n·l");
            ui.monospace(format!("{:.4}", light.n_dot_l));
            ui.end_row();
            ui.label("shadow ray");
            ui.label(shadow_text(light));
            ui.end_row();
            ui.label("diffuse");
            ui.monospace(colour_text(light.diffuse));
            ui.end_row();
            ui.label("specular");
            ui.monospace(colour_text(light.specular));
            ui.end_row();
        });
}

/// "blocked by red ball", "cast, reaches the light", "not cast".
#[must_use]
pub fn shadow_text(light: &InspectedLight) -> String {
    match (&light.blocked_by, light.shadow_ray_cast) {
        (Some(blocker), _) => format!("blocked by {blocker}"),
        (None, true) => "cast, reaches the light".to_owned(),
        (None, false) => "not cast".to_owned(),
    }
}

fn swatch_ui(ui: &mut egui::Ui, colour: DVec3) {
    let (rect, _) = ui.allocate_exact_size(egui::vec2(14.0, 14.0), egui::Sense::hover());
    let [r, g, b] = colour
        .as_vec3()
        .to_array()
        .map(crate::trace::image::encode_linear);
    ui.painter()
        .rect_filled(rect, 2.0, Color32::from_rgb(r, g, b));
}

fn colour_text(c: DVec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", c.x, c.y, c.z)
}

fn vector_text(v: DVec3) -> String {
    format!("({:.4}, {:.4}, {:.4})", v.x, v.y, v.z)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_listed_terms_add_up_to_each_colour_and_names_are_resolved() {
        let scene = super::super::files::default_scene();
        let mut mirrors = 0;
        let mut blocked = 0;
        for y in (0..scene.camera.height).step_by(37) {
            for x in (0..scene.camera.width).step_by(41) {
                let inspection = PixelInspection::new(&scene, TermSwitches::ALL_ON, (x, y));
                let pixel = inspection.result.unwrap();
                for bounce in &pixel.bounces {
                    assert!((bounce.sum_of_terms() - bounce.colour).abs().max_element() < 1e-12);
                    if let Some(hit) = &bounce.hit {
                        assert!(scene.objects.iter().any(|o| o.name == hit.object));
                        assert!(scene.materials.contains_key(&hit.material));
                    }
                    for light in &bounce.lights {
                        assert!(light.label.contains("light"), "{}", light.label);
                        if light.blocked_by.is_some() {
                            blocked += 1;
                        }
                    }
                }
                mirrors += usize::from(pixel.bounces.len() > 1);
                assert_eq!(pixel.bounces[0].colour, pixel.unclamped);
            }
        }
        assert!(mirrors > 0 && blocked > 0, "{mirrors} {blocked}");
    }

    #[test]
    fn a_pixel_outside_the_image_or_a_broken_scene_is_an_error_not_a_panic() {
        let mut scene = super::super::files::default_scene();
        let outside = PixelInspection::new(&scene, TermSwitches::ALL_ON, (10_000, 0));
        assert!(outside.result.unwrap_err().contains("outside"));
        scene.objects[0].material = "missing".to_owned();
        let broken = PixelInspection::new(&scene, TermSwitches::ALL_ON, (1, 1));
        assert!(broken.result.is_err());
    }

    #[test]
    fn switches_read_as_on_the_command_line() {
        let mut switches = TermSwitches::ALL_ON;
        assert_eq!(switches_text(switches), "all terms on");
        switches.set(Term::Diffuse, false);
        switches.set(Term::Shadows, false);
        assert_eq!(
            switches_text(switches.with_solo(Some(Term::Specular))),
            "off: diffuse, shadows · solo specular"
        );
    }
}
