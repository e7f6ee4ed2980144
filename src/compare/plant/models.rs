//! Planting bugs: raylab's picture of a scene as a tracer with some of the catalogue's
//! bugs would make it. The pictures come from the same models the diff fits: a bug that
//! is a channel of the split ([`crate::compare::split`]) is added at weight 1 (a term factor
//! scales its term), a convention or depth limit renders the scene under it, an encoding
//! writes the bytes its way, and the scene-level causes change the scene (an extra ball,
//! a moved camera). Several bugs at once add their changes, as the fit assumes.
//!
//! A bug is written as the diff names its cause, `CAUSE[@LIGHT|@OBJECT]`: `half-vector`,
//! `spot-no-cone@3` (light 3 of the scene's list), `missing-object@"red ball"` or
//! `missing-object@die/pip 1.1` (a name or tree path), and a term factor as
//! `TERM=FACTOR` (`diffuse=0@2`, `shadows=0`, `ambient=2@floor`). `light-off@L` is the
//! diffuse and specular terms of light L at 0.

use std::fmt;

use glam::DVec3;

use crate::compare::catalogue::{
    ClampBug, Kind, NormalBug, Part, ShadowBug, Slot, SpawnBug, SpecularBug, SpotBug,
};
use crate::compare::error::CompareError;
use crate::compare::fit::{Encoding, NO_LIMIT_DEPTH};
use crate::compare::other_image::OtherImage;
use crate::compare::split::{Components, render_components};
use crate::compare::verdict::{Cause, ExplainedTerm, Explanation, looped_lights};
use crate::scene::{
    ClampConvention, Light, MirrorConvention, Object, Quantise, Scene, Shape, Transform, Trs,
};
use crate::trace::{MeshStore, RenderOptions, RenderProgress, Term, World, render};

/// Where a planted bug acts.
#[derive(Clone, Debug, PartialEq)]
pub enum Site {
    /// Everywhere it can: every object, every light it concerns.
    Everywhere,
    /// One light, by its index in the scene's `lights` list.
    Light(usize),
    /// One node of the object trees, by its path of indices (`[object]` for an object).
    Node(Vec<usize>),
}

/// What a planted bug does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Plant {
    /// A term scaled by a factor (0: left out).
    Factor(Term, f64),
    /// A light's diffuse and specular terms left out.
    LightOff,
    /// A wrong shading normal.
    Normal(NormalBug),
    /// A wrong specular lobe.
    Highlight(SpecularBug),
    /// Colour clamped too early.
    Clamp(ClampBug),
    /// Shadows tested wrongly.
    ShadowTest(ShadowBug),
    /// Mirror rays started wrongly.
    Spawn(SpawnBug),
    /// A spot light computed wrongly.
    Spot(SpotBug),
    /// Planes hit only from the front.
    OneSided,
    /// A part of a shape never hit.
    MissingPart(Part),
    /// An object (or tree node) never hit.
    MissingObject,
    /// A ball drawn that the scene does not have.
    ExtraObject,
    /// The camera of another version of the scene.
    DifferentScene,
    /// Mirrors blended (`Blend`) or added (`Add`), against the scene's.
    Mirror(MirrorConvention),
    /// Colour clamped per ray (`EachRay`) or per pixel (`Pixel`), against the scene's.
    ClampAt(ClampConvention),
    /// Mirrors bouncing past the scene's depth limit.
    NoDepthLimit,
    /// The bytes written in another encoding.
    Encoding(Encoding),
}

/// One planted bug: what, and where.
#[derive(Clone, Debug, PartialEq)]
pub struct PlantedBug {
    /// What the bug does.
    pub plant: Plant,
    /// Where it acts.
    pub site: Site,
}

/// Every cause name `parse` knows, as `raylab render --help` lists them.
pub const CAUSE_NAMES: [&str; 34] = [
    "light-off",
    "normal-not-flipped",
    "normal-without-x",
    "normal-without-y",
    "normal-without-z",
    "normal-by-object-matrix",
    "reflected-vector-negated",
    "reflected-vector-n-minus-l",
    "half-vector",
    "no-max-before-power",
    "clamp-before-reflection",
    "clamp-every-ray",
    "truncate-each-ray",
    "spot-no-cone",
    "spot-no-falloff",
    "spot-angle-radians",
    "spot-full-angle",
    "spot-no-cone-no-falloff",
    "no-self-shadow",
    "shadow-acne",
    "shadow-beyond-light",
    "mirror-ray-wrong-side",
    "one-sided",
    "missing-caps",
    "missing-side",
    "missing-object",
    "extra-object",
    "different-scene",
    "mirror-blend",
    "mirror-add",
    "clamp-each-ray",
    "clamp-pixel",
    "no-depth-limit",
    "truncate",
];

impl Plant {
    /// The cause as the diff names it (`factor` for a term factor).
    #[must_use]
    pub fn name(self) -> String {
        match self {
            Plant::Factor(term, f) => format!("{}={f}", term.name()),
            Plant::LightOff => "light-off".to_owned(),
            Plant::Normal(b) => b.name().to_owned(),
            Plant::Highlight(b) => b.name().to_owned(),
            Plant::Clamp(b) => b.name().to_owned(),
            Plant::ShadowTest(b) => b.name().to_owned(),
            Plant::Spawn(b) => b.name().to_owned(),
            Plant::Spot(b) => b.name().to_owned(),
            Plant::OneSided => "one-sided".to_owned(),
            Plant::MissingPart(Part::Caps) => "missing-caps".to_owned(),
            Plant::MissingPart(Part::Side) => "missing-side".to_owned(),
            Plant::MissingPart(Part::Front) => "missing-front".to_owned(),
            Plant::MissingPart(Part::Back) => "one-sided".to_owned(),
            Plant::MissingPart(Part::Whole) | Plant::MissingObject => "missing-object".to_owned(),
            Plant::ExtraObject => "extra-object".to_owned(),
            Plant::DifferentScene => "different-scene".to_owned(),
            Plant::Mirror(MirrorConvention::Blend) => "mirror-blend".to_owned(),
            Plant::Mirror(MirrorConvention::Add) => "mirror-add".to_owned(),
            Plant::ClampAt(ClampConvention::EachRay) => "clamp-each-ray".to_owned(),
            Plant::ClampAt(ClampConvention::Pixel) => "clamp-pixel".to_owned(),
            Plant::NoDepthLimit => "no-depth-limit".to_owned(),
            Plant::Encoding(Encoding::LinearTruncate) => "truncate".to_owned(),
            Plant::Encoding(e) => e.name().to_owned(),
        }
    }

    /// The plant a cause name stands for, without its site.
    fn from_name(name: &str) -> Option<Self> {
        if let Some((term, factor)) = name.split_once('=') {
            let term = term.parse::<Term>().ok()?;
            let factor = factor
                .parse::<f64>()
                .ok()
                .filter(|f| f.is_finite() && *f >= 0.0)?;
            return Some(Plant::Factor(term, factor));
        }
        let by_name = |list: &[Plant]| list.iter().copied().find(|p| p.name() == name);
        let normal = NormalBug::ALL.map(Plant::Normal);
        let highlight = SpecularBug::ALL.map(Plant::Highlight);
        let clamp = ClampBug::ALL.map(Plant::Clamp);
        let spot = SpotBug::ALL.map(Plant::Spot);
        let shadow = ShadowBug::ALL.map(Plant::ShadowTest);
        let spawn = SpawnBug::ALL.map(Plant::Spawn);
        let other = [
            Plant::LightOff,
            Plant::OneSided,
            Plant::MissingPart(Part::Caps),
            Plant::MissingPart(Part::Side),
            Plant::MissingPart(Part::Front),
            Plant::MissingObject,
            Plant::ExtraObject,
            Plant::DifferentScene,
            Plant::Mirror(MirrorConvention::Blend),
            Plant::Mirror(MirrorConvention::Add),
            Plant::ClampAt(ClampConvention::EachRay),
            Plant::ClampAt(ClampConvention::Pixel),
            Plant::NoDepthLimit,
            Plant::Encoding(Encoding::LinearTruncate),
            Plant::Encoding(Encoding::LinearRound),
            Plant::Encoding(Encoding::Srgb),
        ];
        by_name(&normal)
            .or_else(|| by_name(&highlight))
            .or_else(|| by_name(&clamp))
            .or_else(|| by_name(&spot))
            .or_else(|| by_name(&shadow))
            .or_else(|| by_name(&spawn))
            .or_else(|| by_name(&other))
    }

    /// The bug in a tracer's code, in a few words (the catalogue's column, shortened for a
    /// caption).
    #[must_use]
    pub fn in_code(self) -> &'static str {
        match self {
            Plant::Factor(..) => "a term scaled or left out",
            Plant::LightOff => "a light skipped in the loop over lights",
            Plant::Normal(NormalBug::NotFlipped) => "n not turned to face the ray",
            Plant::Normal(NormalBug::DropX | NormalBug::DropY | NormalBug::DropZ) => {
                "a normal built from two of its three components"
            }
            Plant::Normal(NormalBug::ObjectMatrix) => "n = M n, not (M^-1)^T n",
            Plant::Highlight(SpecularBug::NegatedReflection) => "r = l - 2(n.l)n",
            Plant::Highlight(SpecularBug::NMinusL) => "r = 2(n.l)(n - l)",
            Plant::Highlight(SpecularBug::HalfVector) => "Blinn's (n.h)^s for Phong's (r.v)^s",
            Plant::Highlight(SpecularBug::NoMaxBeforePower) => "pow(r.v, s) before max(0, .)",
            Plant::Clamp(ClampBug::LocalBeforeReflection) => {
                "local colour clamped before the mirror"
            }
            Plant::Clamp(ClampBug::EveryRay) => "each reflected colour clamped",
            Plant::Clamp(ClampBug::TruncateEachRay) => "each reflected colour kept as bytes",
            Plant::Spot(SpotBug::NoCone) => "the spot's cone test missing",
            Plant::Spot(SpotBug::NoFalloff) => "the spot's strength not divided by d^2",
            Plant::Spot(SpotBug::AngleRadians) => "cos(angle) with degrees as radians",
            Plant::Spot(SpotBug::FullAngle) => "the half angle halved",
            Plant::Spot(SpotBug::NoConeNoFalloff) => "neither the cone test nor / d^2",
            Plant::ShadowTest(ShadowBug::NoSelfShadow) => "the shadow ray skips its own object",
            Plant::ShadowTest(ShadowBug::Acne) => "the shadow ray starts on the surface",
            Plant::ShadowTest(ShadowBug::BeyondLight) => "any hit on the shadow ray counts",
            Plant::Spawn(SpawnBug::MirrorWrongSide) => "the mirror ray starts at p - eps n",
            Plant::OneSided | Plant::MissingPart(Part::Back) => "a plane hit only when d.n < 0",
            Plant::MissingPart(_) => "one part of a shape never hit",
            Plant::MissingObject => "an object never hit",
            Plant::ExtraObject => "an object drawn that is not in the scene",
            Plant::DifferentScene => "another version of the scene file",
            Plant::Mirror(MirrorConvention::Blend) => "(1 - km) local + km reflected",
            Plant::Mirror(MirrorConvention::Add) => "local + km reflected",
            Plant::ClampAt(ClampConvention::EachRay) => "clip() of every ray's colour",
            Plant::ClampAt(ClampConvention::Pixel) => "only the pixel clamped",
            Plant::NoDepthLimit => "recursion without rayDepth",
            Plant::Encoding(Encoding::LinearTruncate) => "int(255 c)",
            Plant::Encoding(Encoding::LinearRound) => "round(255 c)",
            Plant::Encoding(Encoding::Srgb) => "the sRGB curve written",
        }
    }

    /// Whether the bug is of one light (its site is a light), of the objects, or of the
    /// whole picture.
    fn scope(self) -> Scope {
        match self {
            Plant::LightOff | Plant::Spot(_) => Scope::Light,
            Plant::Factor(Term::Ambient | Term::Reflection | Term::Transmission, _)
            | Plant::Normal(_)
            | Plant::Highlight(_)
            | Plant::Clamp(_)
            | Plant::ShadowTest(_)
            | Plant::Spawn(_)
            | Plant::OneSided
            | Plant::MissingPart(_)
            | Plant::MissingObject => Scope::Object,
            Plant::Factor(_, _) => Scope::LightOrObject,
            _ => Scope::Picture,
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Scope {
    Light,
    Object,
    LightOrObject,
    Picture,
}

impl fmt::Display for PlantedBug {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.plant.name())?;
        match &self.site {
            Site::Everywhere => Ok(()),
            Site::Light(l) => write!(f, "@{l}"),
            Site::Node(path) => write!(
                f,
                "@{}",
                path.iter()
                    .map(ToString::to_string)
                    .collect::<Vec<_>>()
                    .join(".")
            ),
        }
    }
}

impl PlantedBug {
    /// The bug as a reader names it: `spot-no-cone@3`, `half-vector@red ball`.
    #[must_use]
    pub fn label(&self, scene: &Scene) -> String {
        match &self.site {
            Site::Node(path) => format!(
                "{}@{}",
                self.plant.name(),
                crate::scene::tree::path_name(&scene.objects, path)
            ),
            _ => self.to_string(),
        }
    }
}

impl PlantedBug {
    /// Whether explanation `e` names this bug: its cause (a term factor: its term and
    /// which side of 1), and its light or object where the bug was planted on one (the
    /// node itself, a part of it, or the node holding it).
    #[must_use]
    pub fn is_named_by(&self, e: &Explanation) -> bool {
        let cause_fits = match self.plant {
            Plant::Factor(term, factor) => {
                // A light missing holds its diffuse and specular terms missing.
                let light_missing = e.term == ExplainedTerm::Light
                    && matches!(term, Term::Diffuse | Term::Specular)
                    && factor < 1.0;
                e.cause == Cause::Factor
                    && (e.term.name() == term.name() || light_missing)
                    && (e.factor < 1.0) == (factor < 1.0)
            }
            Plant::LightOff => {
                e.cause == Cause::Factor
                    && matches!(
                        e.term,
                        ExplainedTerm::Light | ExplainedTerm::Term(Term::Diffuse | Term::Specular)
                    )
                    && e.factor < 0.5
            }
            Plant::Normal(b) => e.cause == Cause::Normal(b),
            Plant::Highlight(b) => e.cause == Cause::Highlight(b),
            Plant::Clamp(b) => {
                e.cause == Cause::Clamp(b)
                    || (b == ClampBug::EveryRay
                        && matches!(e.cause, Cause::Conventions { .. })
                        && e.cause.name().contains("clamp-each-ray"))
            }
            Plant::ShadowTest(b) => e.cause == Cause::ShadowTest(b),
            Plant::Spawn(b) => e.cause == Cause::Spawn(b),
            Plant::Spot(b) => e.cause == Cause::Spot(b),
            Plant::OneSided | Plant::MissingPart(Part::Back) => e.cause.name() == "one-sided",
            Plant::MissingPart(part) => e.cause == Cause::Missing(Some(part)),
            Plant::MissingObject => e.cause.name() == "missing-object",
            Plant::ExtraObject => e.cause.name() == "extra-object",
            Plant::DifferentScene => e.cause.name() == "different-scene",
            // Every ray's colour clamped is one picture whether it is read as the
            // course's convention or as the bug that clamps each reflected ray (the
            // camera ray's clamp is the pixel's): either name is right.
            Plant::ClampAt(ClampConvention::EachRay)
                if e.cause == Cause::Clamp(ClampBug::EveryRay) =>
            {
                true
            }
            Plant::Mirror(_) | Plant::ClampAt(_) | Plant::NoDepthLimit => {
                matches!(e.cause, Cause::Conventions { .. })
                    && e.cause.name().contains(self.plant.name().as_str())
            }
            Plant::Encoding(encoding) => e.cause == Cause::Encoding(encoding),
        };
        cause_fits
            && match &self.site {
                Site::Everywhere => true,
                Site::Light(l) => e.light == Some(*l),
                // The node, a deeper part of it, or the node holding it.
                Site::Node(path) => {
                    let n = e.node.len().min(path.len());
                    n > 0 && e.node[..n] == path[..n]
                }
            }
    }
}

/// Reads a comma-separated list of bugs, `CAUSE[@LIGHT|@OBJECT]` each, for `scene`
/// (light indices, object names and tree paths are looked up in it).
///
/// # Errors
/// A message naming the unknown cause, light or object, or a site the cause cannot
/// have.
pub fn parse_bugs(spec: &str, scene: &Scene) -> Result<Vec<PlantedBug>, String> {
    spec.split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|one| parse_bug(one, scene))
        .collect()
}

fn parse_bug(text: &str, scene: &Scene) -> Result<PlantedBug, String> {
    let (name, site) = match text.split_once('@') {
        Some((name, site)) => (name.trim(), Some(site.trim().trim_matches('"'))),
        None => (text, None),
    };
    if let Some(bug) = loop_bug(name, scene) {
        return match site {
            None => bug,
            Some(site) => Err(format!(
                "{name}@{site}: {name} says itself which light or object it concerns"
            )),
        };
    }
    let plant = Plant::from_name(name).ok_or_else(|| {
        format!(
            "unknown bug {name:?}: one of {}, {}, or TERM=FACTOR (ambient, diffuse, specular, \
             shadows, reflection, transmission)",
            CAUSE_NAMES.join(", "),
            LOOP_BUG_NAMES.join(", ")
        )
    })?;
    let scope = plant.scope();
    let site = match site {
        None => Site::Everywhere,
        Some(site) => {
            let light = site
                .parse::<usize>()
                .ok()
                .filter(|&l| l < scene.lights.len());
            match scope {
                Scope::Light | Scope::LightOrObject if light.is_some() => {
                    Site::Light(light.unwrap_or_default())
                }
                Scope::Light => {
                    return Err(format!(
                        "{name}@{site}: {name} is a light's bug; give a light's index \
                         (0 to {})",
                        scene.lights.len().saturating_sub(1)
                    ));
                }
                Scope::Object | Scope::LightOrObject => Site::Node(
                    node_path(scene, site)
                        .ok_or_else(|| format!("{name}@{site}: no object {site:?} in the scene"))?,
                ),
                Scope::Picture => {
                    return Err(format!(
                        "{name}@{site}: {name} concerns the whole picture, not one light or object"
                    ));
                }
            }
        }
    };
    Ok(PlantedBug { plant, site })
}

/// The bugs of a tracer's loops, as the catalogue models them: the last light or object
/// skipped (a loop that stops one short) is that light off or that object missing; the
/// ambient added once per light is the ambient term times the number of other lights.
fn loop_bug(name: &str, scene: &Scene) -> Option<Result<PlantedBug, String>> {
    let bug = match name {
        "last-light-skipped" => match scene.lights.len() {
            0 => Err("last-light-skipped: the scene has no light".to_owned()),
            n => Ok(PlantedBug {
                plant: Plant::LightOff,
                site: Site::Light(n - 1),
            }),
        },
        "last-object-skipped" => match scene.objects.len() {
            0 => Err("last-object-skipped: the scene has no object".to_owned()),
            n => Ok(PlantedBug {
                plant: Plant::MissingObject,
                site: Site::Node(vec![n - 1]),
            }),
        },
        "ambient-per-light" => match looped_lights(scene) {
            0 | 1 => Err(
                "ambient-per-light: the scene needs two lights or more beside the ambient for it to show"
                    .to_owned(),
            ),
            n => Ok(PlantedBug {
                plant: Plant::Factor(Term::Ambient, n as f64),
                site: Site::Everywhere,
            }),
        },
        _ => return None,
    };
    Some(bug)
}

/// The cause names of the loop bugs, planted as other causes (see [`parse_bugs`]).
pub const LOOP_BUG_NAMES: [&str; 3] = [
    "last-light-skipped",
    "last-object-skipped",
    "ambient-per-light",
];

/// The path of the node named `name` (an object's name, or a tree path `a/b`).
fn node_path(scene: &Scene, name: &str) -> Option<Vec<usize>> {
    fn find(objects: &[Object], names: &[&str], path: &mut Vec<usize>) -> bool {
        let Some((first, rest)) = names.split_first() else {
            return true;
        };
        for (i, object) in objects.iter().enumerate() {
            if object.name != *first {
                continue;
            }
            path.push(i);
            if find(object.shape.children(), rest, path) {
                return true;
            }
            path.pop();
        }
        false
    }
    let names: Vec<&str> = name.split('/').collect();
    let mut path = Vec::new();
    find(&scene.objects, &names, &mut path).then_some(path)
}

/// raylab's picture of `scene` (at its camera's size, `spp` samples per pixel) as a
/// tracer with `bugs` would write it, with the meshes of `meshes`.
///
/// # Errors
/// [`CompareError::Scene`] when the scene (or the changed one) does not compile, or a
/// bug cannot be planted in it (a site it does not have, a node the diff does not try
/// as missing), and [`CompareError::Cancelled`].
pub fn plant(
    scene: &Scene,
    meshes: &MeshStore,
    bugs: &[PlantedBug],
    spp: u32,
    progress: &RenderProgress,
) -> Result<OtherImage, CompareError> {
    if bugs.iter().any(|b| b.plant == Plant::NoDepthLimit) && has_glass(scene) {
        // Every glass hit splits a ray in two: 2^48 rays a pixel.
        return Err(CompareError::Scene(
            "no-depth-limit is not planted in a scene with glass: its ray trees would grow \
             as 2^depth"
                .to_owned(),
        ));
    }
    let changed = changed_scene(scene, bugs);
    let world =
        World::with_meshes(&changed, meshes).map_err(|e| CompareError::Scene(e.to_string()))?;
    let channel_bugs: Vec<&PlantedBug> = bugs.iter().filter(|b| is_channel_bug(b.plant)).collect();
    let picture: Vec<[f64; 3]> = if channel_bugs.is_empty() {
        let options = RenderOptions {
            samples_per_pixel: spp.max(1),
            ..RenderOptions::from_scene(&changed)
        };
        let (image, _) = render(&world, &options, progress).ok_or(CompareError::Cancelled)?;
        image
            .pixels
            .iter()
            .map(|p| p.as_dvec3().to_array())
            .collect()
    } else {
        let size = (changed.camera.width, changed.camera.height);
        let components = render_components(&changed, &world, size, spp, progress)
            .ok_or(CompareError::Cancelled)?;
        let weights = channel_weights(&components, &world, &channel_bugs)?;
        with_channels(&components, &weights)
    };
    let encoding = bugs
        .iter()
        .rev()
        .find_map(|b| match b.plant {
            Plant::Encoding(e) => Some(e),
            _ => None,
        })
        .unwrap_or_else(|| own_encoding(scene));
    Ok(encoded(&changed, &picture, encoding))
}

/// Whether any material of `scene` transmits.
#[must_use]
pub fn has_glass(scene: &Scene) -> bool {
    scene
        .materials
        .values()
        .any(|m| m.transmission != DVec3::ZERO)
}

/// Whether the bug is a channel of the split, added to raylab's picture.
fn is_channel_bug(plant: Plant) -> bool {
    matches!(
        plant,
        Plant::Factor(..)
            | Plant::LightOff
            | Plant::Normal(_)
            | Plant::Highlight(_)
            | Plant::Clamp(_)
            | Plant::ShadowTest(_)
            | Plant::Spawn(_)
            | Plant::Spot(_)
            | Plant::OneSided
            | Plant::MissingPart(_)
            | Plant::MissingObject
    )
}

/// The scene as the picture-wide bugs change it: conventions, depth, an extra ball, a
/// moved camera. Added objects go last, so every other node keeps its path.
fn changed_scene(scene: &Scene, bugs: &[PlantedBug]) -> Scene {
    let mut changed = scene.clone();
    for bug in bugs {
        match bug.plant {
            Plant::Mirror(m) => changed.render.conventions.mirror = m,
            Plant::ClampAt(c) => changed.render.conventions.clamp = c,
            Plant::NoDepthLimit => {
                changed.render.max_depth = changed.render.max_depth.max(NO_LIMIT_DEPTH);
            }
            Plant::ExtraObject => changed.objects.push(extra_ball(scene)),
            Plant::DifferentScene => changed.camera = moved_camera(scene),
            _ => {}
        }
    }
    changed
}

/// A ball a third of the way from what the camera looks at towards the camera, an
/// eighth of the picture's height across, in the first material of the scene.
fn extra_ball(scene: &Scene) -> Object {
    let camera = &scene.camera;
    let centre = camera.look_at + (camera.position - camera.look_at) / 3.0;
    let distance = (camera.position - centre).length();
    let radius = distance * (camera.fov_deg.to_radians() / 2.0).tan() / 8.0;
    Object {
        name: "extra ball".to_owned(),
        shape: Shape::Sphere,
        transform: Transform::Trs(Trs {
            translate: centre,
            rotate_deg: DVec3::ZERO,
            scale: DVec3::splat(radius),
        }),
        material: scene.materials.keys().next().cloned().unwrap_or_default(),
    }
}

/// The camera turned by 2 degrees about what it looks at (around its up axis): the
/// picture of a scene file whose camera was moved a little.
fn moved_camera(scene: &Scene) -> crate::scene::Camera {
    let mut camera = scene.camera.clone();
    let turn = glam::DQuat::from_axis_angle(camera.up.normalize_or(DVec3::Y), 2f64.to_radians());
    camera.position = camera.look_at + turn * (camera.position - camera.look_at);
    camera
}

/// Per channel, the weight the bugs add it with (0: not at all).
fn channel_weights(
    components: &Components,
    world: &World,
    bugs: &[&PlantedBug],
) -> Result<Vec<f64>, CompareError> {
    let space = components.space;
    let mut weights = vec![0.0; space.count()];
    let lights_of = |site: &Site| -> Result<Vec<usize>, CompareError> {
        match site {
            Site::Light(scene_index) => world
                .light_scene_index
                .iter()
                .position(|s| s == scene_index)
                .map(|l| vec![l])
                .ok_or_else(|| {
                    CompareError::Scene(format!("light {scene_index} is not a lit light"))
                }),
            _ => Ok((0..space.lights).collect()),
        }
    };
    let leaves_of = |site: &Site| -> Result<std::ops::Range<usize>, CompareError> {
        match site {
            Site::Node(path) => components
                .nodes
                .nodes
                .iter()
                .find(|n| &n.path == path)
                .map(|n| n.leaves.clone())
                .ok_or_else(|| CompareError::Scene(format!("no node {path:?} in the scene"))),
            _ => Ok(0..space.objects),
        }
    };
    let add = |weights: &mut Vec<f64>, kind: Kind, leaves: std::ops::Range<usize>, weight: f64| {
        for leaf in leaves {
            weights[space.id(kind, Some(leaf)) as usize] += weight;
        }
    };
    for bug in bugs {
        let light_site = matches!(bug.site, Site::Light(_));
        let leaves = if light_site {
            0..space.objects
        } else {
            leaves_of(&bug.site)?
        };
        match bug.plant {
            Plant::Factor(term, factor) => {
                let lights = lights_of(&bug.site)?;
                let per_light = |kind: fn(usize) -> Kind| lights.iter().map(move |&l| kind(l));
                let kinds: Vec<(Kind, f64)> = match term {
                    Term::Ambient => vec![(Kind::Ambient, factor - 1.0)],
                    Term::Reflection => vec![(Kind::Reflection, factor - 1.0)],
                    Term::Transmission => vec![(Kind::Transmission, factor - 1.0)],
                    Term::Diffuse => per_light(Kind::Diffuse)
                        .map(|k| (k, factor - 1.0))
                        .collect(),
                    Term::Specular => per_light(Kind::Specular)
                        .map(|k| (k, factor - 1.0))
                        .collect(),
                    // The shadows' factor is the part of the light they take away.
                    Term::Shadows => per_light(Kind::Shadow).map(|k| (k, 1.0 - factor)).collect(),
                };
                for (kind, weight) in kinds {
                    add(&mut weights, kind, leaves.clone(), weight);
                }
            }
            Plant::LightOff => {
                for l in lights_of(&bug.site)? {
                    add(&mut weights, Kind::Diffuse(l), leaves.clone(), -1.0);
                    add(&mut weights, Kind::Specular(l), leaves.clone(), -1.0);
                }
            }
            Plant::Normal(b) => add(&mut weights, Kind::Normal(b), leaves, 1.0),
            Plant::Highlight(b) => add(&mut weights, Kind::Highlight(b), leaves, 1.0),
            Plant::Clamp(b) => add(&mut weights, Kind::Clamp(b), leaves, 1.0),
            Plant::ShadowTest(b) => add(&mut weights, Kind::ShadowTest(b), leaves, 1.0),
            Plant::Spawn(b) => add(&mut weights, Kind::Spawn(b), leaves, 1.0),
            Plant::Spot(b) => {
                for l in lights_of(&bug.site)? {
                    add(&mut weights, Kind::Spot(b, l), leaves.clone(), 1.0);
                }
            }
            Plant::OneSided => add(&mut weights, Kind::Missing(Part::Back), leaves, 1.0),
            Plant::MissingPart(part) => add(&mut weights, Kind::Missing(part), leaves, 1.0),
            Plant::MissingObject => missing_node(components, &bug.site, &mut weights)?,
            _ => {}
        }
    }
    Ok(weights)
}

/// The channels of a node left out, as the diff tries it: what is seen without it, and
/// the light its shadows took away.
fn missing_node(
    components: &Components,
    site: &Site,
    weights: &mut [f64],
) -> Result<(), CompareError> {
    let Site::Node(path) = site else {
        return Err(CompareError::Scene(
            "missing-object needs an object: missing-object@NAME".to_owned(),
        ));
    };
    let space = components.space;
    let tried = components
        .tried
        .iter()
        .find(|t| &components.nodes.nodes[t.node].path == path)
        .ok_or_else(|| {
            CompareError::Scene(format!(
                "node {path:?} is not among the nodes the diff tries as missing"
            ))
        })?;
    match tried.slot {
        Slot::Leaf(leaf) => {
            for part in Part::ALL {
                weights[space.id(Kind::Missing(part), Some(leaf)) as usize] += 1.0;
            }
            weights[space.id(Kind::ShadowCast, Some(leaf)) as usize] += 1.0;
        }
        Slot::Inner(slot) => {
            weights[space.id(Kind::NodeMissing, Some(slot)) as usize] += 1.0;
            weights[space.id(Kind::NodeShadowCast, Some(slot)) as usize] += 1.0;
        }
    }
    Ok(())
}

/// raylab's picture with each channel added at its weight.
fn with_channels(components: &Components, weights: &[f64]) -> Vec<[f64; 3]> {
    (0..components.beauty.len())
        .map(|p| {
            let mut colour = components.beauty[p];
            for entry in components.pixel(p) {
                let w = weights[entry.channel as usize];
                if w != 0.0 {
                    for (c, v) in colour.iter_mut().zip(entry.value) {
                        *c += w * f64::from(v);
                    }
                }
            }
            colour
        })
        .collect()
}

/// Each of `bugs` planted alone in `scene` (one picture each, in order): the bugs that
/// are channels of the split share one split of the scene, the others render their own
/// scene. A bug that cannot be planted gives its error in its place.
///
/// # Errors
/// [`CompareError::Scene`] when the scene does not compile, and
/// [`CompareError::Cancelled`].
pub fn plant_each(
    scene: &Scene,
    meshes: &MeshStore,
    bugs: &[PlantedBug],
    spp: u32,
    progress: &RenderProgress,
) -> Result<Vec<Result<OtherImage, CompareError>>, CompareError> {
    let world =
        World::with_meshes(scene, meshes).map_err(|e| CompareError::Scene(e.to_string()))?;
    let shared = bugs.iter().any(|b| is_channel_bug(b.plant));
    let components = if shared {
        let size = (scene.camera.width, scene.camera.height);
        Some(render_components(scene, &world, size, spp, progress).ok_or(CompareError::Cancelled)?)
    } else {
        None
    };
    let own = own_encoding(scene);
    let mut pictures = Vec::with_capacity(bugs.len());
    for bug in bugs {
        if progress.is_cancelled() {
            return Err(CompareError::Cancelled);
        }
        let picture = match &components {
            Some(components) if is_channel_bug(bug.plant) => {
                channel_weights(components, &world, &[bug]).map(|weights| {
                    let picture = with_channels(components, &weights);
                    encoded(scene, &picture, own)
                })
            }
            _ => plant(scene, meshes, std::slice::from_ref(bug), spp, progress),
        };
        pictures.push(picture);
    }
    Ok(pictures)
}

/// The encoding the scene writes its bytes with.
fn own_encoding(scene: &Scene) -> Encoding {
    match scene.render.conventions.quantise {
        Quantise::Round => Encoding::LinearRound,
        Quantise::Truncate => Encoding::LinearTruncate,
    }
}

/// `picture` (linear, at the scene's size) written as bytes by `encoding`.
fn encoded(scene: &Scene, picture: &[[f64; 3]], encoding: Encoding) -> OtherImage {
    let rgb = picture
        .iter()
        .map(|p| p.map(|c| encoding.encode(c)))
        .collect();
    OtherImage::new(scene.camera.width, scene.camera.height, rgb)
}

/// The bugs the gallery shows for `scene`: every cause of the catalogue that the scene
/// has something for, each everywhere it can act (a light's bug on every light that
/// has it; a left-out light and a missing object on the first of each).
#[must_use]
pub fn gallery_bugs(scene: &Scene) -> Vec<PlantedBug> {
    let everywhere = |plant| PlantedBug {
        plant,
        site: Site::Everywhere,
    };
    let mut bugs = Vec::new();
    let lit: Vec<usize> = (0..scene.lights.len())
        .filter(|&l| !matches!(scene.lights[l], Light::Ambient { .. }))
        .collect();
    if let Some(&first) = lit.first() {
        bugs.push(PlantedBug {
            plant: Plant::LightOff,
            site: Site::Light(first),
        });
    }
    bugs.extend(
        [
            Plant::Factor(Term::Ambient, 0.0),
            Plant::Factor(Term::Specular, 0.0),
            Plant::Factor(Term::Shadows, 0.0),
            Plant::Factor(Term::Reflection, 0.0),
            Plant::Factor(Term::Transmission, 0.0),
        ]
        .map(everywhere),
    );
    bugs.extend(NormalBug::ALL.map(|b| everywhere(Plant::Normal(b))));
    bugs.extend(SpecularBug::ALL.map(|b| everywhere(Plant::Highlight(b))));
    bugs.extend(ClampBug::ALL.map(|b| everywhere(Plant::Clamp(b))));
    bugs.extend(ShadowBug::ALL.map(|b| everywhere(Plant::ShadowTest(b))));
    bugs.extend(SpawnBug::ALL.map(|b| everywhere(Plant::Spawn(b))));
    if lit
        .iter()
        .any(|&l| matches!(scene.lights[l], Light::Spot { .. }))
    {
        bugs.extend(SpotBug::ALL.map(|b| everywhere(Plant::Spot(b))));
    }
    bugs.extend(
        [
            Plant::OneSided,
            Plant::MissingPart(Part::Caps),
            Plant::MissingPart(Part::Side),
        ]
        .map(everywhere),
    );
    if !scene.objects.is_empty() {
        bugs.push(PlantedBug {
            plant: Plant::MissingObject,
            site: Site::Node(vec![scene.objects.len() - 1]),
        });
    }
    if !has_glass(scene) {
        bugs.push(everywhere(Plant::NoDepthLimit));
    }
    bugs.extend(
        [
            Plant::ExtraObject,
            Plant::DifferentScene,
            Plant::Mirror(match scene.render.conventions.mirror {
                MirrorConvention::Add => MirrorConvention::Blend,
                MirrorConvention::Blend => MirrorConvention::Add,
            }),
            Plant::ClampAt(match scene.render.conventions.clamp {
                ClampConvention::Pixel => ClampConvention::EachRay,
                ClampConvention::EachRay => ClampConvention::Pixel,
            }),
            Plant::Encoding(match scene.render.conventions.quantise {
                Quantise::Round => Encoding::LinearTruncate,
                Quantise::Truncate => Encoding::LinearRound,
            }),
            Plant::Encoding(Encoding::Srgb),
        ]
        .map(everywhere),
    );
    bugs
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene() -> Scene {
        crate::scene::examples::default_scene()
    }

    #[test]
    fn names_read_back_as_the_same_bug() {
        let scene = scene();
        for bug in gallery_bugs(&scene) {
            // As a reader writes it: objects by name.
            let text = bug.label(&scene);
            let read = parse_bugs(&text, &scene).unwrap_or_else(|e| panic!("{text}: {e}"));
            assert_eq!(read, vec![bug], "{text}");
        }
        let bugs = parse_bugs("diffuse=0.5@1, half-vector@red ball,truncate", &scene).unwrap();
        assert_eq!(bugs[0].plant, Plant::Factor(Term::Diffuse, 0.5));
        assert_eq!(bugs[0].site, Site::Light(1));
        assert_eq!(bugs[1].site, Site::Node(vec![1]));
        assert_eq!(bugs[2].plant, Plant::Encoding(Encoding::LinearTruncate));
    }

    #[test]
    fn a_wrong_site_is_refused_by_name() {
        let scene = scene();
        let e = parse_bugs("spot-no-cone@floor", &scene).unwrap_err();
        assert!(e.contains("a light's bug"), "{e}");
        let e = parse_bugs("half-vector@nothing", &scene).unwrap_err();
        assert!(e.contains("no object \"nothing\""), "{e}");
        let e = parse_bugs("mirror-blend@0", &scene).unwrap_err();
        assert!(e.contains("whole picture"), "{e}");
        let e = parse_bugs("purple", &scene).unwrap_err();
        assert!(e.contains("unknown bug \"purple\""), "{e}");
    }
}
