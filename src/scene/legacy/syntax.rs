//! The legacy file as typed blocks: what the parser produces and the converter reads.
//! Every item keeps the line and token it came from, for error messages.

use glam::DVec3;

use crate::scene::{CsgOp, LightKind, Shape};

/// Where an item came from: the 1-based line and the token that names it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct At {
    /// 1-based line.
    pub line: usize,
    /// The token, as written.
    pub token: String,
}

/// A value and where it came from.
#[derive(Clone, Debug, PartialEq)]
pub struct Item<T> {
    /// The parsed value.
    pub value: T,
    /// The keyword that introduced it.
    pub at: At,
}

/// A coordinate axis of `Rotate`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    /// Rotate about X.
    X,
    /// Rotate about Y.
    Y,
    /// Rotate about Z.
    Z,
}

/// One transform keyword; a sequence of them is applied in file order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TransformStep {
    /// `Translate x y z`.
    Translate(DVec3),
    /// `Rotate X|Y|Z deg`.
    Rotate {
        /// The axis.
        axis: Axis,
        /// The angle in degrees (counter-clockwise looking down the axis).
        angle_deg: f64,
    },
    /// `Scale s`: uniform.
    Scale(f64),
    /// `Scale3 sx sy sz`.
    Scale3(DVec3),
}

/// One material keyword, in a Material block or overriding an object's copy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SurfaceEdit {
    /// `Colour R G B`: sets ambient and diffuse.
    Colour(DVec3),
    /// `Ambient R G B`.
    Ambient(DVec3),
    /// `Diffuse R G B`.
    Diffuse(DVec3),
    /// `Specular R G B EXP`.
    Specular {
        /// Specular colour.
        colour: DVec3,
        /// Phong exponent.
        exponent: f64,
    },
    /// `Mirror R G B`.
    Mirror(DVec3),
    /// `Opacity a`, in [0, 1]: the transmission is 1 - a (grey).
    Opacity(f64),
    /// `RefractiveIndex n`: the index of refraction inside.
    RefractiveIndex(f64),
}

/// One keyword of the Scene block.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneSetting {
    /// `renderSize W H`.
    RenderSize {
        /// Width in pixels.
        width: u32,
        /// Height in pixels.
        height: u32,
    },
    /// `backgroundColour R G B`.
    Background(DVec3),
    /// `ambientLight R G B` (older files).
    AmbientLight(DVec3),
    /// `rayDepth N`: a whole number >= 0 as written, which may exceed what raylab renders.
    RayDepth(f64),
    /// `filename NAME`: the legacy output image; not used by the import.
    Filename(String),
    /// `Supersampling` (4) or `FSAA N` (N * N), already capped to what raylab renders.
    SamplesPerPixel(u32),
    /// `scaleResolution s`: the size so far times `s`, truncated.
    ScaleResolution(f64),
}

/// One keyword of a Light block.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightSetting {
    /// `Colour R G B`.
    Colour(DVec3),
    /// `Location x y z`.
    Location(DVec3),
    /// `Direction x y z`.
    Direction(DVec3),
    /// `Angle deg`.
    Angle(f64),
    /// `Radius r`: a sphere light of radius r.
    Radius(f64),
    /// `Samples N`: shadow rays per shading point, already capped.
    Samples(u32),
}

/// What an Object block draws.
#[derive(Clone, Debug, PartialEq)]
pub enum ObjectKind {
    /// One of the unit shapes without parameters (`Shape::ALL`).
    Shape(Shape),
    /// `Torus R`: the legacy unit torus (minor radius 0.5) scaled by R.
    Torus(f64),
    /// `Tube R`: the hole's radius is sqrt(R / 2).
    Tube(f64),
    /// `Mesh PATH`: the path as written.
    Mesh(String),
    /// `Object CSG OP` or a top-level `CSG OP` block.
    Csg {
        /// How the operands combine.
        op: CsgOp,
        /// Which of the two ways it was written.
        form: CsgForm,
        /// The operands, in file order.
        operands: Vec<ObjectNode>,
    },
    /// `ObjectGroup ... End`.
    Group(Vec<ObjectNode>),
    /// A kind that draws nothing here (an unknown kind, `Parabaloid`); warned already.
    Skipped,
}

/// The two ways students write CSG.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CsgForm {
    /// `Object CSG OP` (the 2016 framework): operands first, the node's keywords after.
    Object2016,
    /// `CSG OP ... End` as a block of its own (students' addition to the 2020 one).
    TopLevel,
}

/// An object and everything below it.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectNode {
    /// What it draws.
    pub kind: ObjectKind,
    /// Its own keywords, in file order (for a tree node, wherever they sit among its
    /// operands or children).
    pub settings: Vec<Item<ObjectSetting>>,
    /// The name from a comment on the line right before it, if any.
    pub name: Option<String>,
    /// The token that names its kind, for messages.
    pub at: At,
}

/// One keyword of an Object block.
#[derive(Clone, Debug, PartialEq)]
pub enum ObjectSetting {
    /// `Material NAME`: copy a material defined earlier.
    Material(String),
    /// An override of the object's copy of its material.
    Surface(SurfaceEdit),
    /// A transform step.
    Transform(TransformStep),
}

/// A block's contents.
#[derive(Clone, Debug, PartialEq)]
pub enum Block {
    /// `Scene ... End`.
    Scene(Vec<Item<SceneSetting>>),
    /// `Camera PinholeCamera F ... End`.
    Camera {
        /// Distance of the 2-unit-wide image plane.
        focal_length: f64,
        /// The camera's placement, in file order.
        transforms: Vec<Item<TransformStep>>,
    },
    /// `Light KIND ... End`.
    Light {
        /// Which kind.
        kind: LightKind,
        /// Its keywords, in file order.
        settings: Vec<Item<LightSetting>>,
        /// Keywords that had an error and so are missing from `settings`, as written;
        /// their absence is not reported a second time.
        broken: Vec<String>,
    },
    /// `Material NAME ... End`.
    Material {
        /// The name (case-sensitive).
        name: String,
        /// Its keywords, in file order.
        edits: Vec<Item<SurfaceEdit>>,
    },
    /// `Object SHAPE ... End`, `CSG ... End` or `ObjectGroup ... End`.
    Object(ObjectNode),
}

/// A parsed block and the token that names it (`Scene`, the camera type, the light
/// kind, the material name or the shape).
#[derive(Clone, Debug, PartialEq)]
pub struct ParsedBlock {
    /// The contents.
    pub block: Block,
    /// The naming token.
    pub at: At,
}
