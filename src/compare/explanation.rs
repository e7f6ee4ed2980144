//! The verdicts: what an explanation says (term, light, object, factor, share), why
//! (its cause), where (its pixels), and how sure the numbers make it.

use serde::Serialize;

use super::bugs::{ClampBug, NormalBug, Part, SpecularBug};
use super::encoding::Encoding;
use super::spot_bugs::SpotBug;
use crate::scene::{ClampConvention, Conventions, Light, MirrorConvention, Quantise, Scene};

/// The term an explanation names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ExplainedTerm {
    /// `ka * ambient`.
    Ambient,
    /// A light's diffuse term.
    Diffuse,
    /// A light's specular term.
    Specular,
    /// Shadowing of a light.
    Shadows,
    /// The mirror term.
    Reflection,
    /// The transmission (refraction) term.
    Transmission,
    /// Which surface a pixel sees.
    Geometry,
    /// The colour of rays that hit nothing.
    Background,
    /// How linear colour became 8 bits.
    Encoding,
    /// How the whole picture combines and clamps colour (render.conventions).
    Conventions,
    /// The picture as a whole: another version of the scene.
    Scene,
}

impl ExplainedTerm {
    /// The name used in JSON and text.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            ExplainedTerm::Ambient => "ambient",
            ExplainedTerm::Diffuse => "diffuse",
            ExplainedTerm::Specular => "specular",
            ExplainedTerm::Shadows => "shadows",
            ExplainedTerm::Reflection => "reflection",
            ExplainedTerm::Transmission => "transmission",
            ExplainedTerm::Geometry => "geometry",
            ExplainedTerm::Background => "background",
            ExplainedTerm::Encoding => "encoding",
            ExplainedTerm::Conventions => "conventions",
            ExplainedTerm::Scene => "scene",
        }
    }
}

/// Why the pictures differ, as far as the numbers tell.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Cause {
    /// The term is scaled by `factor`.
    Factor,
    /// A wrong normal.
    Normal(NormalBug),
    /// A wrong specular lobe.
    Highlight(SpecularBug),
    /// Colour clamped too early.
    Clamp(ClampBug),
    /// A spot light computed wrongly (the explanation names the light).
    Spot(SpotBug),
    /// A part of an object (or all of it: `None`) is not there.
    Missing(Option<Part>),
    /// The 8-bit encoding differs.
    Encoding(Encoding),
    /// The other picture follows other course conventions (mirror blend, clamp of each
    /// ray) than the scene says.
    Conventions {
        /// The scene's.
        scene: Conventions,
        /// The other picture's.
        other: Conventions,
        /// The ray depth the other picture reaches, where it is the scene's `max_depth`
        /// exceeded (mirrors facing each other bouncing past the limit); `None` where it
        /// keeps the limit.
        depth: Option<u32>,
    },
    /// Pixels at an object's outline differ, no factor explains them.
    Silhouette,
    /// Shading varies across an object in a way no factor or known bug explains.
    Shading,
    /// The picture is of another version of the scene: outlines differ on several
    /// objects and nothing explains the bulk of the difference.
    DifferentScene {
        /// How many objects' outlines differ.
        objects: u32,
    },
}

impl Cause {
    /// The name used in JSON.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Cause::Factor => "factor",
            Cause::Normal(b) => b.name(),
            Cause::Highlight(b) => b.name(),
            Cause::Clamp(b) => b.name(),
            Cause::Spot(b) => b.name(),
            Cause::Missing(Some(Part::Back)) => "one-sided",
            Cause::Missing(_) => "missing",
            Cause::Encoding(Encoding::LinearTruncate) => "truncate",
            Cause::Encoding(e) => e.name(),
            Cause::Conventions { depth: Some(_), .. } => "no-depth-limit",
            Cause::Conventions { scene, other, .. } => {
                let names = super::conventions_fit::convention_names(scene, other);
                match names.as_slice() {
                    [one] => one,
                    ["mirror-blend", "clamp-each-ray"] => "mirror-blend-clamp-each-ray",
                    ["mirror-blend", "clamp-pixel"] => "mirror-blend-clamp-pixel",
                    ["mirror-add", "clamp-each-ray"] => "mirror-add-clamp-each-ray",
                    ["mirror-add", "clamp-pixel"] => "mirror-add-clamp-pixel",
                    _ => "conventions",
                }
            }
            Cause::Silhouette => "silhouette",
            Cause::Shading => "shading",
            Cause::DifferentScene { .. } => "different-scene",
        }
    }
}

/// One explanation of (part of) the difference.
#[derive(Clone, Debug, PartialEq)]
pub struct Explanation {
    /// The term.
    pub term: ExplainedTerm,
    /// Index of the light in the scene's light list, or `None` (every light, or none).
    pub light: Option<usize>,
    /// Index of the object in the scene, or `None` (every object, or none).
    pub object: Option<usize>,
    /// The object's name.
    pub object_name: Option<String>,
    /// The fitted scale of raylab's component in the other image: 1 as raylab, 0 missing.
    pub factor: f64,
    /// Share of the squared difference this explains (0 to 1).
    pub share: f64,
    /// The pixels it concerns, ascending row-major indices.
    pub pixels: Vec<u32>,
    /// Why.
    pub cause: Cause,
    /// How sure the numbers make it, 0 to 1.
    pub confidence: f64,
    /// One sentence for a reader.
    pub summary: String,
}

impl Explanation {
    /// "high", "medium" or "low".
    #[must_use]
    pub fn sureness(&self) -> &'static str {
        if self.confidence >= 0.7 {
            "high"
        } else if self.confidence >= 0.4 {
            "medium"
        } else {
            "low"
        }
    }

    /// Whether pixel `p` is among the explanation's pixels.
    #[must_use]
    pub fn covers(&self, p: u32) -> bool {
        self.pixels.binary_search(&p).is_ok()
    }
}

fn light_name(scene: &Scene, light: usize) -> String {
    let kind = scene.lights.get(light).map_or("?", Light::kind_name);
    format!("light {light} ({kind})")
}

fn on_object(name: Option<&str>) -> String {
    name.map_or_else(String::new, |n| format!(" on '{n}'"))
}

/// The sentence for an explanation whose other fields are set.
#[must_use]
pub fn summary(e: &Explanation, scene: &Scene) -> String {
    let object = e.object_name.as_deref();
    let light = e.light.map(|l| light_name(scene, l));
    let f = e.factor;
    let weight = 1.0 - f;
    let term = e.term.name();
    match e.cause {
        Cause::Factor if e.term == ExplainedTerm::Shadows => {
            let whose = light.map_or("Shadows".to_owned(), |l| format!("Shadows of {l}"));
            if f < 0.1 {
                format!(
                    "{whose}{} are missing: shadowed places are lit in the other image (shadow factor {f:.2}).",
                    on_object(object)
                )
            } else {
                format!(
                    "{whose}{} take away {f:.2} of the light raylab's take away.",
                    on_object(object)
                )
            }
        }
        Cause::Factor => {
            let subject = match (&light, object) {
                (Some(l), Some(o)) => format!("The {term} of {l} on '{o}'"),
                (Some(l), None) => format!("The {term} of {l}"),
                (None, Some(o)) => format!("The {term} of '{o}'"),
                (None, None) => format!("The {term} term"),
            };
            if f < 0.05 {
                format!("{subject} is missing in the other image (factor {f:.2}).")
            } else {
                format!("{subject} is {f:.2} times raylab's in the other image.")
            }
        }
        Cause::Normal(bug) => match object {
            Some(o) => format!(
                "'{o}' is shaded as if {} (the bug's picture fits with weight {weight:.2}).",
                bug.describe()
            ),
            None => format!(
                "Every object is shaded as if {} (weight {weight:.2}).",
                bug.describe()
            ),
        },
        Cause::Highlight(bug) => format!(
            "Highlights{} look as if {} (weight {weight:.2}).",
            on_object(object),
            bug.describe()
        ),
        Cause::Clamp(bug) => format!(
            "Reflections{} are darker where they exceed 1: {} (weight {weight:.2}).",
            on_object(object).replace(" on ", " in "),
            bug.describe()
        ),
        Cause::Spot(bug) => format!(
            "{} lights the other image as if {} (weight {weight:.2}; explains {:.1}% of the difference).",
            capitalised(light.as_deref().unwrap_or("a spot light")),
            bug.describe(),
            100.0 * e.share
        ),
        Cause::Missing(part) => {
            let o = object.unwrap_or("an object");
            match part {
                Some(Part::Back) => format!(
                    "'{o}' is invisible from behind in the other image: a one-sided plane (weight {weight:.2})."
                ),
                Some(Part::Whole) | None => format!(
                    "'{o}' is missing in the other image: what lies behind it shows instead (weight {weight:.2})."
                ),
                Some(p) => format!(
                    "{} of '{o}' are missing in the other image: what lies behind shows instead (weight {weight:.2}).",
                    capitalised(p.describe())
                ),
            }
        }
        Cause::Conventions {
            depth: Some(depth), ..
        } => format!(
            "The other image's rays bounce past the scene's ray depth ({}): its mirrors facing each other go on to depth {depth} or more, as a tracer without a depth limit does.",
            scene.render.max_depth
        ),
        Cause::Conventions { other, .. } => {
            let mirror = match other.mirror {
                MirrorConvention::Blend => "blends mirrors as (1 - km) local + km reflected",
                MirrorConvention::Add => "adds mirrors as local + km reflected",
            };
            let clamp = match other.clamp {
                ClampConvention::EachRay => "clamps each ray's colour to [0, 1]",
                ClampConvention::Pixel => "clamps only the pixel",
            };
            format!(
                "The other image follows other conventions than the scene: it {mirror} and {clamp} (render.conventions: (mirror: {:?}, clamp: {:?})).",
                other.mirror, other.clamp
            )
        }
        Cause::Encoding(encoding) => {
            let scene_writes = match scene.render.conventions.quantise {
                Quantise::Round => "round(255 c)",
                Quantise::Truncate => "floor(255 c), as the scene's conventions say",
            };
            match encoding {
                Encoding::LinearTruncate => format!(
                    "The other image truncates to 8 bits, floor(255 c), where raylab writes {scene_writes}."
                ),
                Encoding::LinearRound => format!(
                    "The other image rounds to 8 bits, round(255 c), where raylab writes {scene_writes}."
                ),
                other => format!(
                    "The other image is written as {}, raylab's as linear {scene_writes}.",
                    other.name()
                ),
            }
        }
        Cause::Silhouette => format!(
            "The outline of {} differs over {} pixels: the shape is elsewhere, another size, or hit where it should not be.",
            object.map_or("the objects".to_owned(), |o| format!("'{o}'")),
            e.pixels.len()
        ),
        Cause::Shading => format!(
            "Shading varies across {} in a way no factor or known bug explains; it follows the {term} term, as a wrong normal or reflected vector would.",
            object.map_or("the picture".to_owned(), |o| format!("'{o}'"))
        ),
        Cause::DifferentScene { objects } => format!(
            "The picture looks like another version of this scene: the outlines of {objects} objects differ and no factor or known bug explains most of the difference. Was it rendered from an older scene file (the camera or objects moved)? The verdicts below are weak until the two agree."
        ),
    }
}

fn capitalised(text: &str) -> String {
    let mut chars = text.chars();
    chars
        .next()
        .map_or_else(String::new, |c| c.to_uppercase().chain(chars).collect())
}
