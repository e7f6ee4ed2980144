//! `raylab inspect SCENE --pixel X,Y [--json]`: every ray behind one pixel's centre
//! sample, from the tracer's own recorder (the record the editor's pixel inspector and
//! ray-path overlay show), as a readable tree or as JSON with fixed fields. It takes
//! `raylab render`'s isolation flags: muted lights and hidden objects are left out of the
//! trace and named as such in the output.

use std::path::PathBuf;

use clap::Args;
use serde::Serialize;

use super::inspect_tree::{lights_off, object_name, tree_text};
use super::isolation::IsolationArgs;
use crate::scene::Scene;
use crate::trace::{
    Isolation, PixelReport, RayKind, RenderOptions, Term, TermSwitches, View, World, traced_rays,
    try_inspect_pixel,
};

/// Arguments of `raylab inspect`.
#[derive(Debug, Args)]
pub struct InspectArgs {
    /// The scene file: RON, or a course `.txt` scene (told by its content, imported on the fly).
    pub scene: PathBuf,
    /// The pixel, as X,Y in the scene camera's image (0,0 is the top-left pixel).
    #[arg(long, value_parser = parse_pixel, value_name = "X,Y")]
    pub pixel: (u32, u32),
    /// Print JSON instead of a tree.
    #[arg(long)]
    pub json: bool,
    /// The term switches the pixel is traced with.
    #[command(flatten)]
    pub terms: TermArgs,
    /// Lights muted or solo, objects hidden.
    #[command(flatten)]
    pub isolation: IsolationArgs,
    /// The course's conventions, over the scene's.
    #[command(flatten)]
    pub conventions: super::ConventionArgs,
}

/// The term switches, as `raylab render` takes them.
#[derive(Debug, Default, Args)]
pub struct TermArgs {
    /// Terms to switch off, comma-separated: ambient,diffuse,specular,shadows,reflection,
    /// transmission.
    #[arg(long, value_delimiter = ',')]
    pub off: Vec<Term>,
    /// Show one term alone.
    #[arg(long)]
    pub solo: Option<Term>,
}

impl TermArgs {
    /// The switches these arguments ask for.
    #[must_use]
    pub fn switches(&self) -> TermSwitches {
        let mut switches = TermSwitches::ALL_ON;
        for term in &self.off {
            switches.set(*term, false);
        }
        switches.with_solo(self.solo)
    }
}

/// "12,40" to (12, 40).
fn parse_pixel(text: &str) -> Result<(u32, u32), String> {
    let wanted = || format!("`{text}` is not a pixel: write X,Y with whole numbers, e.g. 120,45");
    let (x, y) = text.split_once(',').ok_or_else(wanted)?;
    let x = x.trim().parse().map_err(|_| wanted())?;
    let y = y.trim().parse().map_err(|_| wanted())?;
    Ok((x, y))
}

/// Runs `raylab inspect`, printing to stdout.
///
/// # Errors
/// A message naming what went wrong: the file, the scene, or a pixel outside the image.
pub fn run(args: &InspectArgs) -> Result<(), String> {
    let scene = super::load_any_scene(&args.scene)?;
    print!("{}", inspect_text(&scene, args)?);
    Ok(())
}

/// What `raylab inspect` prints for `scene`.
///
/// # Errors
/// The scene's validation message, an isolation flag naming a light or object the scene
/// does not have, or a pixel outside the image.
pub fn inspect_text(scene: &Scene, args: &InspectArgs) -> Result<String, String> {
    let pruned = args.isolation.without_hidden_children(scene)?;
    let scene = &args.conventions.applied(pruned);
    let isolation = args.isolation.isolation(scene)?;
    let meshes = crate::cli::load_meshes(scene, &args.scene)?;
    let world =
        World::isolated_with_meshes(scene, &isolation, &meshes).map_err(|e| e.to_string())?;
    let options = RenderOptions {
        switches: args.terms.switches(),
        view: View::Beauty,
        isolation,
        ..RenderOptions::from_scene(scene)
    };
    let (x, y) = args.pixel;
    let report = try_inspect_pixel(&world, &options, x, y).map_err(|e| e.to_string())?;
    if args.json {
        let json =
            serde_json::to_string_pretty(&JsonReport::new(scene, &options.isolation, &report))
                .map_err(|e| format!("cannot write JSON: {e}"))?;
        Ok(json + "\n")
    } else {
        Ok(tree_text(scene, &options, &report))
    }
}

/// The JSON form: the fixed fields, plus the unclamped colour and the lights.
#[derive(Serialize)]
struct JsonReport {
    pixel: [u32; 2],
    colour: [f64; 3],
    unclamped: [f64; 3],
    rays: Vec<JsonRay>,
    lights: Vec<JsonLight>,
    /// Indices of the lights the isolation flags switch off (muted, or not solo).
    lights_off: Vec<usize>,
    /// Names of the objects the isolation flags leave out.
    hidden_objects: Vec<String>,
}

#[derive(Serialize)]
struct JsonRay {
    kind: &'static str,
    depth: u32,
    origin: [f64; 3],
    direction: [f64; 3],
    t: Option<f64>,
    t_max: Option<f64>,
    hit: Option<JsonHit>,
    light: Option<usize>,
    blocked_by: Option<String>,
}

#[derive(Serialize)]
struct JsonHit {
    object: String,
    point: [f64; 3],
    normal: [f64; 3],
}

/// What one light did at one hit point.
#[derive(Serialize)]
struct JsonLight {
    depth: u32,
    light: usize,
    outcome: String,
    n_dot_l: Option<f64>,
    diffuse: [f64; 3],
    specular: [f64; 3],
}

impl JsonReport {
    fn new(scene: &Scene, isolation: &Isolation, report: &PixelReport) -> Self {
        let name = |i: usize| object_name(scene, i);
        let rays = traced_rays(report)
            .iter()
            .map(|ray| JsonRay {
                kind: ray.kind.name(),
                depth: ray.depth,
                origin: ray.origin.to_array(),
                direction: ray.direction.to_array(),
                t: ray.t,
                t_max: ray.t_max,
                hit: ray.hit.map(|hit| JsonHit {
                    object: (ray.kind != RayKind::Shadow)
                        .then(|| report.bounces.get(ray.depth as usize))
                        .flatten()
                        .and_then(|b| b.surface.as_ref())
                        .map_or_else(|| name(hit.object), |s| s.path.clone()),
                    point: hit.point.to_array(),
                    normal: hit.normal.to_array(),
                }),
                light: ray.light,
                blocked_by: ray.blocked_by.map(name),
            })
            .collect();
        let lights = report
            .bounces
            .iter()
            .flat_map(|bounce| {
                bounce
                    .light_outcomes()
                    .into_iter()
                    .map(move |(light, outcome, record)| JsonLight {
                        depth: bounce.depth,
                        light,
                        outcome: outcome.text(&name),
                        n_dot_l: record.map(|r| r.n_dot_l),
                        diffuse: record.map_or([0.0; 3], |r| r.diffuse.to_array()),
                        specular: record.map_or([0.0; 3], |r| r.specular.to_array()),
                    })
            })
            .collect();
        Self {
            pixel: [report.pixel.0, report.pixel.1],
            colour: report.clamped.to_array(),
            unclamped: report.unclamped.to_array(),
            rays,
            lights,
            lights_off: lights_off(scene, isolation),
            hidden_objects: isolation
                .hidden_objects
                .iter()
                .map(|&i| object_name(scene, i))
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pixel_is_two_whole_numbers() {
        assert_eq!(parse_pixel("12,40"), Ok((12, 40)));
        assert_eq!(parse_pixel(" 3 , 4 "), Ok((3, 4)));
        for bad in ["12", "a,b", "-1,2", "1,2,3"] {
            assert!(parse_pixel(bad).unwrap_err().contains("X,Y"), "{bad}");
        }
    }
}
