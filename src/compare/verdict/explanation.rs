//! The verdicts: what an explanation says (term, light, object, factor, share), why
//! (its cause), where (its pixels), and how sure the numbers make it.

use serde::Serialize;

use crate::compare::catalogue::SpotBug;
use crate::compare::catalogue::{ClampBug, NormalBug, Part, ShadowBug, SpawnBug, SpecularBug};
use crate::compare::catalogue::{Node, Nodes};
use crate::compare::extras::PixelBox;
use crate::compare::extras::ShapeGuess;
use crate::compare::fit::Encoding;
use crate::scene::Conventions;
use crate::trace::Term;

/// The term an explanation names: one of the lighting model's, or what lies outside it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ExplainedTerm {
    /// A term of the lighting model (ambient, a light's diffuse or specular, shadows,
    /// reflection, transmission).
    Term(Term),
    /// A light's diffuse and specular terms together: the light itself (a light the
    /// other picture lacks).
    Light,
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
            ExplainedTerm::Term(term) => term.name(),
            ExplainedTerm::Light => "light",
            ExplainedTerm::Geometry => "geometry",
            ExplainedTerm::Background => "background",
            ExplainedTerm::Encoding => "encoding",
            ExplainedTerm::Conventions => "conventions",
            ExplainedTerm::Scene => "scene",
        }
    }
}

/// As its [`ExplainedTerm::name`].
impl Serialize for ExplainedTerm {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.name())
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
    /// Shadows tested wrongly.
    ShadowTest(ShadowBug),
    /// Mirror rays started wrongly.
    Spawn(SpawnBug),
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
    /// The other picture draws an object where raylab sees the background or another
    /// object (the explanation's `bbox` says where), shaped like this.
    ExtraObject(ShapeGuess),
    /// Pixels at an object's outline differ, no factor explains them.
    Silhouette,
    /// Shading varies across an object in a way no factor or known bug explains.
    Shading,
    /// Pixels along edges differ as another renderer's sampling (anti-aliasing) would
    /// make them: not a bug.
    Sampling,
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
            Cause::ShadowTest(b) => b.name(),
            Cause::Spawn(b) => b.name(),
            Cause::Spot(b) => b.name(),
            Cause::Missing(Some(Part::Back)) => "one-sided",
            Cause::Missing(Some(Part::Whole) | None) => "missing-object",
            Cause::Missing(Some(_)) => "missing-part",
            Cause::ExtraObject(_) => "extra-object",
            Cause::Encoding(Encoding::LinearTruncate) => "truncate",
            Cause::Encoding(e) => e.name(),
            Cause::Conventions { depth: Some(_), .. } => "no-depth-limit",
            Cause::Conventions { scene, other, .. } => {
                let names = crate::compare::fit::convention_names(scene, other);
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
            Cause::Sampling => "sampling",
            Cause::DifferentScene { .. } => "different-scene",
        }
    }
}

/// The confidence from which a verdict is called "high": calibrated on the accuracy
/// benchmark's tuning seeds (`raylab bench --diff-accuracy 6 --tuning`, docs/COMPARE.md),
/// where 95.3% of the claims at or above it named a planted bug (94.1% from 0.7).
pub const HIGH_CONFIDENCE: f64 = 0.9;

/// One explanation of (part of) the difference.
#[derive(Clone, Debug, PartialEq)]
pub struct Explanation {
    /// The term.
    pub term: ExplainedTerm,
    /// Index of the light in the scene's light list, or `None` (every light, or none).
    pub light: Option<usize>,
    /// Index of the object in the scene, or `None` (every object, or none).
    pub object: Option<usize>,
    /// The name of the node named: the object's, or a tree path (`"die/pip 1.1"`).
    pub object_name: Option<String>,
    /// The tree path of the node named: the object's index, then child and operand
    /// indices down to it (`[object]` for a whole object), as the editor selects it;
    /// empty when no object is named.
    pub node: Vec<usize>,
    /// The fitted scale of raylab's component in the other image: 1 as raylab, 0 missing.
    pub factor: f64,
    /// Share of the squared difference this explains (0 to 1).
    pub share: f64,
    /// The pixels it concerns, ascending row-major indices.
    pub pixels: Vec<u32>,
    /// Why.
    pub cause: Cause,
    /// For an object missing or extra: the bounding box of its pixels (for a missing
    /// one, where raylab draws it).
    pub bbox: Option<PixelBox>,
    /// Other readings that fit the same pixels as well (the less specific, or another
    /// story), each a short phrase.
    pub fits_as_well: Vec<String>,
    /// How sure the numbers make it, 0 to 1.
    pub confidence: f64,
    /// One sentence for a reader.
    pub summary: String,
}

impl Explanation {
    /// "high", "medium" or "low". "high" starts at [`HIGH_CONFIDENCE`].
    #[must_use]
    pub fn sureness(&self) -> &'static str {
        if self.confidence >= HIGH_CONFIDENCE {
            "high"
        } else if self.confidence >= 0.4 {
            "medium"
        } else {
            "low"
        }
    }

    /// Names node `node` of `nodes` (or none): its object, its name and its path.
    pub fn name_node(&mut self, nodes: &Nodes, node: Option<usize>) {
        let node = node.map(|n| &nodes.nodes[n]);
        self.object = node.map(Node::object);
        self.object_name = node.map(|n| n.name.clone());
        self.node = node.map_or_else(Vec::new, |n| n.path.clone());
    }

    /// Whether pixel `p` is among the explanation's pixels.
    #[must_use]
    pub fn covers(&self, p: u32) -> bool {
        self.pixels.binary_search(&p).is_ok()
    }
}
